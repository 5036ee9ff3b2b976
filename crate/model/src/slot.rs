//! Rule slots: the decisions a model lets a user's script take in place of its paper's rule.
//!
//! A slot is one decision a unit takes from what it senses locally: CHOBIE II's robot deciding
//! whether it leads, and in which form. Each slot is a type implementing [`Slot`]: its typed
//! input (what the unit senses), its typed output (its decision), its documentation
//! ([`SlotInfo`], with the paper's rule written as a script) and the paper's rule in Rust, the
//! built-in. A model holds a [`Rule`] for each of its slots and asks it for every decision; the
//! rule answers with the built-in, or with a [`Script`] put in its place when the scenario carries
//! one (`rules: { slot: source }`).
//!
//! The model crates never see the script engine: a [`Script`] is this trait, implemented by the
//! engine's crate (`kumiki-rules`), and the core puts one in a model through
//! [`Model::install`](crate::model::Model::install). Inputs and outputs cross to the script as
//! JSON values (serde), so a slot is its two types, its [`SlotInfo`] and one function.

use std::marker::PhantomData;
use std::rc::Rc;

use schemars::JsonSchema;
use serde::de::DeserializeOwned;
#[cfg(feature = "scripts")]
use serde::Deserialize;
use serde::Serialize;
use serde_json::Value;

use crate::rng::Rng;

/// The longest script a scenario's `rules` may hold for one slot, in bytes of UTF-8: a rule is a
/// few dozen lines (the paper's CHOBIE II rule is under 1 KiB), and a link carries it.
pub const MAX_SOURCE_BYTES: usize = 16 * 1024;

/// One field of a slot's input, documented for the editor and docs/rules.md.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[schemars(rename = "SlotField")]
pub struct Field {
    /// Its name in the script (`robot.first`).
    pub name: &'static str,
    /// Its type in the script's words: `bool`, `int`, `float`, `string`, or a map or list of them.
    pub kind: &'static str,
    pub about: &'static str,
}

/// What a slot is, for the reader of a scenario, the editor and docs/rules.md.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
pub struct SlotInfo {
    /// The slot's key in a scenario's `rules`, and the name of the function its script defines.
    pub name: &'static str,
    pub title: &'static str,
    /// What the decision is, where in a step it is taken, and who takes it.
    pub about: &'static str,
    /// The fields of the one argument the function is called with, a map.
    pub input: &'static [Field],
    /// What the function returns, in words: the values it may take.
    pub output: &'static str,
    /// The paper's rule written as a script: the built-in's source, and the editor's starting
    /// text. It gives the built-in's state hashes step by step (a test holds it to that).
    pub paper: &'static str,
    /// The script may draw from the model's seeded generator (`random()`, `random_int(n)`).
    pub random: bool,
}

/// A slot: its input and output types, its documentation, and the paper's rule in Rust.
pub trait Slot: 'static {
    /// What the deciding unit senses, as the script receives it (one map).
    type Input: Serialize;
    /// The decision, read from the script's answer.
    type Output: DeserializeOwned;
    const INFO: SlotInfo;
    /// The paper's rule, the built-in: what [`SlotInfo::paper`] computes. `rng` is the model's
    /// generator when the slot has one ([`SlotInfo::random`]).
    fn paper(input: &Self::Input, rng: Option<&mut Rng>) -> Self::Output;
}

/// Why a script stopped the run: the message names the rule, the line and the cap or the error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stop(pub String);

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// A compiled script in a slot, as the engine gives it. Calls are deterministic: the same input
/// and generator give the same answer on every target.
pub trait Script {
    /// Calls the slot's function on one input (the slot's input as JSON), drawing from `rng`
    /// when the slot has one. An error stops the run.
    fn call(&self, input: Value, rng: Option<&mut Rng>) -> Result<Value, Stop>;
    /// A new step begins: the budget of operations a step may spend in the script starts again.
    fn begin_step(&self);
}

/// What a model holds for one of its slots: the paper's rule, or a script in its place. A copy
/// (a keyframe of the run) shares the script. Without the `scripts` feature (the page's
/// first-load module, which has no engine) it is always the paper's rule.
pub struct Rule<S> {
    #[cfg(feature = "scripts")]
    script: Option<Rc<dyn Script>>,
    slot: PhantomData<fn() -> S>,
}

impl<S> Clone for Rule<S> {
    fn clone(&self) -> Self {
        Rule {
            #[cfg(feature = "scripts")]
            script: self.script.clone(),
            slot: PhantomData,
        }
    }
}

impl<S> Default for Rule<S> {
    fn default() -> Self {
        Rule {
            #[cfg(feature = "scripts")]
            script: None,
            slot: PhantomData,
        }
    }
}

impl<S> std::fmt::Debug for Rule<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.scripted() {
            true => f.write_str("Rule(script)"),
            false => f.write_str("Rule(paper)"),
        }
    }
}

impl<S> Rule<S> {
    /// The paper's rule.
    pub fn paper() -> Self {
        Rule::default()
    }

    /// Puts `script` in place of the paper's rule. Only a build with the engine makes scripts,
    /// and it has the `scripts` feature (the core's `rules` feature turns both on).
    pub fn install(&mut self, script: Rc<dyn Script>) {
        #[cfg(feature = "scripts")]
        {
            self.script = Some(script);
        }
        #[cfg(not(feature = "scripts"))]
        {
            let _ = script;
            unreachable!("a script in a build without the contract's scripts feature")
        }
    }

    pub fn scripted(&self) -> bool {
        #[cfg(feature = "scripts")]
        return self.script.is_some();
        #[cfg(not(feature = "scripts"))]
        false
    }
}

impl<S: Slot> Rule<S> {
    /// The decision for `input`: the built-in's, or the script's read as the slot's output.
    #[inline]
    pub fn decide(&self, input: &S::Input, rng: Option<&mut Rng>) -> Result<S::Output, Stop> {
        #[cfg(feature = "scripts")]
        if let Some(script) = &self.script {
            return ask::<S>(script.as_ref(), input, rng);
        }
        Ok(S::paper(input, rng))
    }
}

/// `script`'s decision for `input`, read as the slot's output.
#[cfg(feature = "scripts")]
fn ask<S: Slot>(
    script: &dyn Script,
    input: &S::Input,
    rng: Option<&mut Rng>,
) -> Result<S::Output, Stop> {
    let value = serde_json::to_value(input).expect("a slot's input serialises");
    let answer = script.call(value, rng)?;
    S::Output::deserialize(&answer).map_err(|_| {
        let info = S::INFO;
        Stop(format!(
            "rule '{}' answered {}; it must answer {}",
            info.name,
            cut(&answer.to_string(), 80),
            info.output
        ))
    })
}

/// `text` cut to about `max` characters.
#[cfg(feature = "scripts")]
fn cut(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        Some((at, _)) => format!("{}…", &text[..at]),
        None => text.to_string(),
    }
}

#[cfg(all(test, feature = "scripts"))]
mod tests {
    use super::*;
    use std::cell::Cell;

    struct Double;

    #[derive(Serialize)]
    struct In {
        x: i64,
    }

    #[derive(Deserialize, Debug, PartialEq)]
    struct Out(i64);

    impl Slot for Double {
        type Input = In;
        type Output = Out;
        const INFO: SlotInfo = SlotInfo {
            name: "double",
            title: "Twice x",
            about: "A test slot.",
            input: &[],
            output: "an integer",
            paper: "fn double(input) { input.x * 2 }",
            random: false,
        };
        fn paper(input: &In, _: Option<&mut Rng>) -> Out {
            Out(input.x * 2)
        }
    }

    /// A script that answers what it is given to answer, and counts its calls.
    struct Fixed(Value, Cell<u32>);

    impl Script for Fixed {
        fn call(&self, input: Value, _: Option<&mut Rng>) -> Result<Value, Stop> {
            assert_eq!(input, serde_json::json!({"x": 4}));
            self.1.set(self.1.get() + 1);
            Ok(self.0.clone())
        }
        fn begin_step(&self) {}
    }

    #[test]
    fn a_rule_answers_with_the_paper_until_a_script_is_installed() {
        let mut rule = Rule::<Double>::paper();
        assert_eq!(rule.decide(&In { x: 4 }, None), Ok(Out(8)));
        let script = Rc::new(Fixed(serde_json::json!(9), Cell::new(0)));
        rule.install(script.clone());
        assert!(rule.scripted());
        assert_eq!(rule.clone().decide(&In { x: 4 }, None), Ok(Out(9)));
        assert_eq!(script.1.get(), 1);
    }

    #[test]
    fn an_answer_of_the_wrong_type_stops_the_run_naming_the_rule_and_the_output() {
        let mut rule = Rule::<Double>::paper();
        rule.install(Rc::new(Fixed(serde_json::json!("nine"), Cell::new(0))));
        let stop = rule.decide(&In { x: 4 }, None).unwrap_err();
        assert_eq!(
            stop.0,
            "rule 'double' answered \"nine\"; it must answer an integer"
        );
    }
}
