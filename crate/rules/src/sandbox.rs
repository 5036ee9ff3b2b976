//! The engine a rule script runs in: Rhai without I/O, clock, `eval` or modules, with every cap of
//! [`crate::caps`], maths from the model's portable functions and randomness from the model's
//! seeded generator only.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use kumiki_model::math;
use kumiki_model::rng::Rng;
use rhai::packages::{
    ArithmeticPackage, BasicArrayPackage, BasicFnPackage, BasicIteratorPackage, BasicMapPackage,
    BasicStringPackage, BitFieldPackage, LogicPackage, MoreStringPackage, Package,
};
use rhai::{Dynamic, Engine, EvalAltResult, Position, FLOAT, INT};

use crate::caps;

/// What a script's engine shares with the script between and during calls.
#[derive(Default)]
pub(crate) struct State {
    /// The model's generator, lent for the length of a call (when the slot has one).
    pub rng: RefCell<Option<Rng>>,
    /// Operations spent by the step's finished calls.
    pub spent: Cell<u64>,
    /// Operations of the call under way, as last reported.
    pub running: Cell<u64>,
}

/// Symbols a rule may not use: `eval` runs text as code, and `**` raises a float to a power with
/// the platform's `powf`, which may differ natively and in wasm in the last bit (`pow(x, y)` is
/// the portable one).
const DISABLED: [&str; 3] = ["eval", "**", "**="];

type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// A sandboxed engine sharing `state` with its script.
pub(crate) fn engine(state: &Rc<State>) -> Engine {
    let mut engine = Engine::new_raw();
    // The standard library less its I/O-free but unwanted parts: no `sleep`, `exit`, `timestamp`
    // or reflection (LanguageCorePackage, BasicTimePackage), no platform maths
    // (BasicMathPackage: its `sin`, `exp`, ... call the system's libm natively), no BLOBs.
    engine.register_global_module(ArithmeticPackage::new().as_shared_module());
    engine.register_global_module(BasicStringPackage::new().as_shared_module());
    engine.register_global_module(BasicIteratorPackage::new().as_shared_module());
    engine.register_global_module(BasicFnPackage::new().as_shared_module());
    engine.register_global_module(LogicPackage::new().as_shared_module());
    engine.register_global_module(BitFieldPackage::new().as_shared_module());
    engine.register_global_module(BasicArrayPackage::new().as_shared_module());
    engine.register_global_module(BasicMapPackage::new().as_shared_module());
    engine.register_global_module(MoreStringPackage::new().as_shared_module());
    for symbol in DISABLED {
        engine.disable_symbol(symbol);
    }
    engine.on_print(|_| {});
    engine.on_debug(|_, _, _| {});
    engine.set_strict_variables(true);
    engine.set_max_call_levels(caps::CALL_DEPTH);
    engine.set_max_expr_depths(caps::EXPRESSION_DEPTH, caps::FUNCTION_EXPRESSION_DEPTH);
    engine.set_max_string_size(caps::STRING_BYTES);
    engine.set_max_array_size(caps::ARRAY_ITEMS);
    engine.set_max_map_size(caps::MAP_ENTRIES);
    engine.set_max_variables(caps::VARIABLES);
    engine.set_max_functions(caps::FUNCTIONS);
    let counter = Rc::clone(state);
    engine.on_progress(move |ops| {
        counter.running.set(ops);
        if ops > caps::OPERATIONS_PER_CALL {
            Some(caps::PER_CALL.into())
        } else if counter.spent.get() + ops > caps::OPERATIONS_PER_STEP {
            Some(caps::PER_STEP.into())
        } else {
            None
        }
    });
    maths(&mut engine);
    randomness(&mut engine, state);
    engine
}

/// The portable maths: `exp`, `ln`, `ln_1p` and `pow` through `kumiki_model::math` (one libm on
/// every target), and the operations IEEE 754 rounds exactly everywhere.
fn maths(engine: &mut Engine) {
    engine.register_fn("exp", math::exp);
    engine.register_fn("exp", |x: INT| math::exp(x as FLOAT));
    engine.register_fn("ln", math::ln);
    engine.register_fn("ln", |x: INT| math::ln(x as FLOAT));
    engine.register_fn("ln_1p", math::ln_1p);
    engine.register_fn("pow", math::pow);
    engine.register_fn("pow", |x: FLOAT, y: INT| math::pow(x, y as FLOAT));
    engine.register_fn("pow", |x: INT, y: FLOAT| math::pow(x as FLOAT, y));
    engine.register_fn("pow", |x: INT, y: INT| math::pow(x as FLOAT, y as FLOAT));
    engine.register_fn("sqrt", |x: FLOAT| x.sqrt());
    engine.register_fn("sqrt", |x: INT| (x as FLOAT).sqrt());
    engine.register_fn("floor", |x: FLOAT| x.floor());
    engine.register_fn("ceiling", |x: FLOAT| x.ceil());
    engine.register_fn("round", |x: FLOAT| x.round());
    engine.register_fn("to_float", |x: INT| x as FLOAT);
    engine.register_fn("to_float", |x: FLOAT| x);
    engine.register_fn("to_int", |x: INT| x);
    engine.register_fn("to_int", to_int);
    engine.register_fn("is_nan", |x: FLOAT| x.is_nan());
    engine.register_fn("is_finite", |x: FLOAT| x.is_finite());
    engine.register_fn("PI", || std::f64::consts::PI);
    engine.register_fn("E", || std::f64::consts::E);
}

/// A float's whole part as an integer; an error where it has none.
fn to_int(x: FLOAT) -> Fallible<INT> {
    let whole = x.trunc();
    if whole.is_finite() && (INT::MIN as FLOAT..=INT::MAX as FLOAT).contains(&whole) {
        Ok(whole as INT)
    } else {
        Err(runtime(format!(
            "{x} has no whole number part that fits an integer"
        )))
    }
}

/// `random()`, uniform in [0, 1), and `random_int(n)`, uniform in 0..n, from the model's seeded
/// generator, lent to the script for the length of a call.
fn randomness(engine: &mut Engine, state: &Rc<State>) {
    let lent = Rc::clone(state);
    engine.register_fn("random", move || -> Fallible<FLOAT> {
        draw(&lent, |rng| Ok(rng.unit()))
    });
    let lent = Rc::clone(state);
    engine.register_fn("random_int", move |n: INT| -> Fallible<INT> {
        let below = u32::try_from(n)
            .ok()
            .filter(|&n| n > 0)
            .ok_or_else(|| runtime(format!("random_int({n}): n must be from 1 to {}", u32::MAX)))?;
        draw(&lent, |rng| Ok(INT::from(rng.below(below))))
    });
}

fn draw<T>(state: &State, f: impl FnOnce(&mut Rng) -> Fallible<T>) -> Fallible<T> {
    match state.rng.borrow_mut().as_mut() {
        Some(rng) => f(rng),
        None => Err(runtime(
            "this slot draws no random numbers: its model decides it without chance".into(),
        )),
    }
}

fn runtime(message: String) -> Box<EvalAltResult> {
    EvalAltResult::ErrorRuntime(Dynamic::from(message), Position::NONE).into()
}
