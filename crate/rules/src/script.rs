//! A compiled rule: the slot's function of one script, in its own sandboxed engine, called by the
//! model through [`kumiki_model::slot::Script`].

use std::rc::Rc;

use kumiki_model::rng::Rng;
use kumiki_model::slot::{Script, SlotInfo, Stop};
use kumiki_model::Error;
use rhai::debugger::{DebuggerCommand, DebuggerEvent};
use rhai::{CallFnOptions, Dynamic, Engine, EvalAltResult, ParseError, ParseErrorType, Scope, AST};
use serde_json::Value;

use crate::caps;
use crate::convert;
use crate::sandbox::{self, State};

pub(crate) struct Compiled {
    engine: Engine,
    ast: AST,
    info: SlotInfo,
    state: Rc<State>,
}

/// Reads `source` as the script of slot `info`: it must parse within the caps, hold nothing but
/// functions, and define the slot's function with one parameter.
pub(crate) fn compile(info: SlotInfo, source: &str) -> Result<Compiled, Error> {
    let field = format!("rules.{}", info.name);
    let max = kumiki_model::slot::MAX_SOURCE_BYTES;
    if source.len() > max {
        return Err(Error::field(
            field,
            format!(
                "{} bytes is too long; a rule's script holds at most {max}",
                source.len()
            ),
        ));
    }
    let state = Rc::new(State::default());
    let engine = sandbox::engine(&state);
    let ast = engine
        .compile(source)
        .map_err(|e| Error::field(&field, parse_error(&e)))?;
    if let Some(stmt) = ast.statements().first() {
        return Err(Error::field(
            &field,
            format!(
                "{}: a rule's script holds only functions; this statement outside them would never run",
                line(stmt.position()).unwrap_or_else(|| "the top".into())
            ),
        ));
    }
    if !ast
        .iter_functions()
        .any(|f| f.name == info.name && f.params.len() == 1)
    {
        return Err(Error::field(
            &field,
            format!(
                "the script defines no function {}(input) of one parameter, which the slot calls",
                info.name
            ),
        ));
    }
    Ok(Compiled {
        engine,
        ast,
        info,
        state,
    })
}

impl Script for Compiled {
    fn call(&self, input: Value, rng: Option<&mut Rng>) -> Result<Value, Stop> {
        let lent = rng.as_deref().cloned();
        let spent = self.state.spent.get();
        let result = self.run(&self.engine, &self.state, &input, lent.clone());
        let state = &self.state;
        state.spent.set(spent + state.running.get());
        let back = state.rng.borrow_mut().take();
        if let (Some(rng), Some(back)) = (rng, back) {
            *rng = back;
        }
        let answer = result.map_err(|e| self.stop(e, &input, lent, spent))?;
        convert::to_value(&answer).map_err(|what| {
            Stop(format!(
                "rule '{}' answered {what}; it must answer {}",
                self.info.name, self.info.output
            ))
        })
    }

    fn begin_step(&self) {
        self.state.spent.set(0);
    }
}

impl Compiled {
    /// One call of the slot's function on `engine`, whose state lends it `rng`.
    fn run(
        &self,
        engine: &Engine,
        state: &State,
        input: &Value,
        rng: Option<Rng>,
    ) -> Result<Dynamic, Box<EvalAltResult>> {
        *state.rng.borrow_mut() = rng;
        state.running.set(0);
        let options = CallFnOptions::new().eval_ast(false).rewind_scope(true);
        engine.call_fn_with_options::<Dynamic>(
            options,
            &mut Scope::new(),
            &self.ast,
            self.info.name,
            (convert::to_dynamic(input),),
        )
    }

    /// The message of an error that stopped a call: the rule, the line, and the cap or the error.
    fn stop(
        &self,
        mut err: Box<EvalAltResult>,
        input: &Value,
        rng: Option<Rng>,
        spent: u64,
    ) -> Stop {
        let inner = innermost(&mut err);
        // The engine moves a cap's error to the start of each call it leaves; the call, replayed
        // the same way while stepping, shows where it was.
        let pos = match inner.is_system_exception() {
            true => self.locate(input, rng, spent),
            false => inner.position(),
        };
        let at = line(pos).map_or(String::new(), |l| format!(" at {l}"));
        inner.clear_position();
        let what = match &*inner {
            EvalAltResult::ErrorTerminated(token, _) if token.to_string() == caps::PER_CALL => {
                format!(
                    "more than {} operations in one call (the cap per call)",
                    caps::OPERATIONS_PER_CALL
                )
            }
            EvalAltResult::ErrorTerminated(..) => format!(
                "more than {} operations in one step, its calls together (the cap per step)",
                caps::OPERATIONS_PER_STEP
            ),
            EvalAltResult::ErrorStackOverflow(_) => format!(
                "calls nested more than {} deep (the cap on call depth)",
                caps::CALL_DEPTH
            ),
            EvalAltResult::ErrorTooManyVariables(_) => format!(
                "more than {} variables alive at once (the cap on variables)",
                caps::VARIABLES
            ),
            EvalAltResult::ErrorDataTooLarge(what, _) => too_large(what),
            EvalAltResult::ErrorRuntime(value, _) => value.to_string(),
            other => other.to_string(),
        };
        Stop(format!("rule '{}' stopped{at}: {what}", self.info.name))
    }

    /// Where a call that a cap stopped was when it stopped: the call again, from the same input,
    /// generator and step budget, in an engine that notes the position of every step it takes.
    fn locate(&self, input: &Value, rng: Option<Rng>, spent: u64) -> rhai::Position {
        let state = Rc::new(State::default());
        state.spent.set(spent);
        let mut engine = sandbox::engine(&state);
        let last = Rc::new(std::cell::Cell::new(rhai::Position::NONE));
        let seen = Rc::clone(&last);
        #[allow(deprecated)] // "not deprecated, but considered volatile": Rhai is pinned exactly
        engine.register_debugger(
            |_, debugger| debugger,
            move |_, event, _, _, pos| {
                if matches!(event, DebuggerEvent::Step) && !pos.is_none() {
                    seen.set(pos);
                }
                Ok(DebuggerCommand::StepInto)
            },
        );
        let _ = self.run(&engine, &state, input, rng);
        last.get()
    }
}

/// The error where it happened, inside the calls that led to it.
fn innermost(err: &mut EvalAltResult) -> &mut EvalAltResult {
    match err {
        EvalAltResult::ErrorInFunctionCall(_, _, inner, _) => innermost(inner),
        other => other,
    }
}

/// The cap a value went past, by the engine's name for it.
fn too_large(what: &str) -> String {
    match what {
        "Length of string" => format!(
            "a string longer than {} bytes (the cap on string size)",
            caps::STRING_BYTES
        ),
        "Size of object map" => format!(
            "a map of more than {} entries, those of the maps in it counted (the cap on map size)",
            caps::MAP_ENTRIES
        ),
        _ => format!(
            "an array of more than {} items, those of the arrays in it counted (the cap on array size)",
            caps::ARRAY_ITEMS
        ),
    }
}

fn parse_error(e: &ParseError) -> String {
    let what = match e.err_type() {
        ParseErrorType::ExprTooDeep => format!(
            "expressions nested more than {} deep, {} inside a function (the cap on expression depth)",
            caps::EXPRESSION_DEPTH,
            caps::FUNCTION_EXPRESSION_DEPTH
        ),
        ParseErrorType::TooManyFunctions => format!(
            "more than {} functions (the cap on functions)",
            caps::FUNCTIONS
        ),
        other if other.to_string().contains("'eval'") => {
            "eval is not available to a rule: a rule's code is its script".into()
        }
        other => other.to_string(),
    };
    match line(e.position()) {
        Some(at) => format!("{at}: {what}"),
        None => what,
    }
}

/// "line L, column C" of a position, or none.
fn line(pos: rhai::Position) -> Option<String> {
    let l = pos.line()?;
    Some(match pos.position() {
        Some(c) => format!("line {l}, column {c}"),
        None => format!("line {l}"),
    })
}
