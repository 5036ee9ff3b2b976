//! The goal language of classroom exercises: a small expression over a run's outcome, checked by
//! replaying the run, never by `eval`.
//!
//! ```text
//! completed and steps <= 800
//! metrics.collisions < 20 or not completed
//! scenario.robots <= 5 and metrics.built >= 0.9
//! ```
//!
//! - Values are numbers and true/false.
//! - Names: `completed` (true/false), `steps`, `metrics.NAME` (a metric of the model), and
//!   `scenario.PATH` (a number or true/false in the scenario, by dotted path: `scenario.robots`,
//!   `scenario.stages.0.robots`).
//! - Operators, loosest first: `or`; `and`; `not`; the comparisons `<`, `<=`, `>`, `>=`, `==`,
//!   `!=`; `+` and `-`; `*` and `/`; unary `-`. Parentheses group. `&&`, `||` and `!` are accepted
//!   for `and`, `or` and `not`; `≤`, `≥` and `≠` for their ASCII forms.
//!
//! A goal is parsed and type-checked once ([`Goal::parse`]); [`Goal::check`] evaluates it on an
//! outcome and says in words why it is met or not.

use serde_json::Value;

use crate::error::{Error, Result};

mod parse;

use super::lookup_path;
use parse::type_of;

/// The longest goal, in characters.
pub const MAX_GOAL_CHARS: usize = 1000;

/// A parsed, type-checked goal.
#[derive(Clone, Debug, PartialEq)]
pub struct Goal {
    text: String,
    expr: Expr,
}

#[derive(Clone, Debug, PartialEq)]
enum Expr {
    Number(f64),
    Bool(bool),
    Name(Name),
    Neg(Box<Expr>),
    Not(Box<Expr>),
    Arith(Box<Expr>, ArithOp, Box<Expr>),
    Compare(Box<Expr>, CmpOp, Box<Expr>),
    And(Vec<Expr>),
    Or(Vec<Expr>),
}

#[derive(Clone, Debug, PartialEq)]
enum Name {
    Completed,
    Steps,
    Metric(String),
    Scenario(String),
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum ArithOp {
    Add,
    Sub,
    Mul,
    Div,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum CmpOp {
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Type {
    Number,
    Bool,
    /// A scenario or metric value whose kind is known only when the run is checked.
    Any,
}

/// What a goal is checked against: a run's outcome and its scenario.
pub struct Outcome<'a> {
    pub completed: bool,
    pub steps: u64,
    pub metrics: &'a serde_json::Map<String, Value>,
    /// The whole scenario as JSON.
    pub scenario: &'a Value,
}

/// Whether a goal is met, and why, in words.
#[derive(Clone, Debug, PartialEq, serde::Serialize, schemars::JsonSchema)]
pub struct Check {
    pub met: bool,
    pub because: String,
}

impl Goal {
    /// Parses and type-checks a goal. Errors name the column and say what was expected.
    pub fn parse(text: &str) -> Result<Goal> {
        let chars = text.chars().count();
        if chars > MAX_GOAL_CHARS {
            return Err(Error::field(
                "",
                format!("{chars} characters is too long; a goal has at most {MAX_GOAL_CHARS}"),
            ));
        }
        let expr = parse::expression(text)?;
        if type_of(&expr) == Type::Number {
            return Err(Error::field(
                "",
                "the goal is a number, not a condition; compare it, as in 'steps <= 800'",
            ));
        }
        Ok(Goal {
            text: text.trim().to_string(),
            expr,
        })
    }

    /// The goal as written.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The metric names and scenario paths the goal reads.
    pub fn names(&self) -> Vec<String> {
        let mut out = Vec::new();
        collect_names(&self.expr, &mut out);
        kumiki_model::sort::sort(&mut out);
        out.dedup();
        out
    }

    /// The goal in words, for students: `completed and metrics.collisions < 40` reads
    /// "Completed, and collisions below 40."
    pub fn words(&self) -> String {
        let text = words(&self.expr, false);
        let mut chars = text.chars();
        match chars.next() {
            Some(first) => format!("{}{}.", first.to_uppercase(), chars.as_str()),
            None => String::new(),
        }
    }

    /// Evaluates the goal on an outcome.
    pub fn check(&self, outcome: &Outcome) -> Check {
        match eval(&self.expr, outcome) {
            Ok(Val::Bool(met)) => Check {
                met,
                because: explain(&self.expr, outcome, met),
            },
            Ok(Val::Number(v)) => Check {
                met: false,
                because: format!(
                    "the goal gives the number {} rather than true or false",
                    show(v)
                ),
            },
            Err(why) => Check {
                met: false,
                because: why,
            },
        }
    }
}

fn collect_names(e: &Expr, out: &mut Vec<String>) {
    match e {
        Expr::Name(n) => out.push(name_text(n)),
        Expr::Neg(a) | Expr::Not(a) => collect_names(a, out),
        Expr::Arith(a, _, b) | Expr::Compare(a, _, b) => {
            collect_names(a, out);
            collect_names(b, out);
        }
        Expr::And(parts) | Expr::Or(parts) => parts.iter().for_each(|p| collect_names(p, out)),
        Expr::Number(_) | Expr::Bool(_) => {}
    }
}

fn name_text(n: &Name) -> String {
    match n {
        Name::Completed => "completed".into(),
        Name::Steps => "steps".into(),
        Name::Metric(m) => format!("metrics.{m}"),
        Name::Scenario(p) => format!("scenario.{p}"),
    }
}

// ---- evaluation -------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug, PartialEq)]
enum Val {
    Number(f64),
    Bool(bool),
}

fn lookup(n: &Name, o: &Outcome) -> std::result::Result<Val, String> {
    let from_json = |v: Option<&Value>, what: String| match v {
        Some(Value::Number(x)) => x.as_f64().map(Val::Number).ok_or(what),
        Some(Value::Bool(b)) => Ok(Val::Bool(*b)),
        Some(_) => Err(format!("{what} is neither a number nor true/false")),
        None => Err(format!("{what} does not exist")),
    };
    match n {
        Name::Completed => Ok(Val::Bool(o.completed)),
        Name::Steps => Ok(Val::Number(o.steps as f64)),
        Name::Metric(m) => from_json(o.metrics.get(m), format!("the metric '{m}'")),
        Name::Scenario(p) => from_json(lookup_path(o.scenario, p), format!("the scenario's '{p}'")),
    }
}

fn eval(e: &Expr, o: &Outcome) -> std::result::Result<Val, String> {
    let num = |e: &Expr| match eval(e, o)? {
        Val::Number(v) => Ok(v),
        Val::Bool(_) => Err(format!(
            "{} is true or false where a number is needed",
            describe(e)
        )),
    };
    let boolean = |e: &Expr| match eval(e, o)? {
        Val::Bool(b) => Ok(b),
        Val::Number(_) => Err(format!(
            "{} is a number where true or false is needed",
            describe(e)
        )),
    };
    Ok(match e {
        Expr::Number(v) => Val::Number(*v),
        Expr::Bool(b) => Val::Bool(*b),
        Expr::Name(n) => lookup(n, o)?,
        Expr::Neg(a) => Val::Number(-num(a)?),
        Expr::Not(a) => Val::Bool(!boolean(a)?),
        Expr::Arith(a, op, b) => {
            let (x, y) = (num(a)?, num(b)?);
            Val::Number(match op {
                ArithOp::Add => x + y,
                ArithOp::Sub => x - y,
                ArithOp::Mul => x * y,
                ArithOp::Div => x / y,
            })
        }
        Expr::Compare(a, op, b) => {
            let (x, y) = (eval(a, o)?, eval(b, o)?);
            Val::Bool(match (x, y) {
                (Val::Number(x), Val::Number(y)) => match op {
                    CmpOp::Lt => x < y,
                    CmpOp::Le => x <= y,
                    CmpOp::Gt => x > y,
                    CmpOp::Ge => x >= y,
                    CmpOp::Eq => x == y,
                    CmpOp::Ne => x != y,
                },
                (Val::Bool(x), Val::Bool(y)) if matches!(op, CmpOp::Eq | CmpOp::Ne) => {
                    (x == y) == (*op == CmpOp::Eq)
                }
                _ => {
                    return Err(format!(
                        "{} compares a number with true or false",
                        describe(e)
                    ))
                }
            })
        }
        Expr::And(parts) => {
            let mut all = true;
            for p in parts {
                all &= boolean(p)?;
            }
            Val::Bool(all)
        }
        Expr::Or(parts) => {
            let mut any = false;
            for p in parts {
                any |= boolean(p)?;
            }
            Val::Bool(any)
        }
    })
}

/// Why the goal came out as `met`: the parts that decided it, with their values.
fn explain(e: &Expr, o: &Outcome, met: bool) -> String {
    match e {
        // Met: every part held. Not met: the parts that failed.
        Expr::And(parts) if !met => parts
            .iter()
            .filter(|p| eval(p, o) == Ok(Val::Bool(false)))
            .map(|p| explain(p, o, false))
            .collect::<Vec<_>>()
            .join("; and "),
        // Met: the parts that held. Not met: every part failed.
        Expr::Or(parts) if met => parts
            .iter()
            .filter(|p| eval(p, o) == Ok(Val::Bool(true)))
            .map(|p| explain(p, o, true))
            .collect::<Vec<_>>()
            .join("; and "),
        Expr::And(parts) | Expr::Or(parts) => parts
            .iter()
            .map(|p| explain(p, o, met))
            .collect::<Vec<_>>()
            .join("; "),
        Expr::Not(inner) => explain(inner, o, !met),
        Expr::Name(Name::Completed) => match met {
            true => "the run completed".into(),
            false => "the run did not complete".into(),
        },
        Expr::Compare(a, op, b) => {
            let side = |x: &Expr| match (x, eval(x, o)) {
                (Expr::Number(_), _) => describe(x),
                (_, Ok(Val::Number(v))) => format!("{} is {}", describe(x), show(v)),
                (_, Ok(Val::Bool(v))) => format!("{} is {v}", describe(x)),
                (_, Err(why)) => why,
            };
            let holds = eval(e, o) == Ok(Val::Bool(true));
            let sym = match op {
                CmpOp::Lt => "<",
                CmpOp::Le => "≤",
                CmpOp::Gt => ">",
                CmpOp::Ge => "≥",
                CmpOp::Eq => "=",
                CmpOp::Ne => "≠",
            };
            let (left, right) = (side(a), side(b));
            let needed = format!("{sym} {}", right_value(b, o));
            match holds {
                true => format!("{left}, {needed} as required"),
                false if matches!(**b, Expr::Number(_)) => {
                    format!("{left}, but it must be {needed}")
                }
                false => format!("{left} and {right}, but the first must be {sym} the second"),
            }
        }
        other => match eval(other, o) {
            Ok(Val::Bool(v)) => format!("{} is {v}", describe(other)),
            Ok(Val::Number(v)) => format!("{} is {}", describe(other), show(v)),
            Err(why) => why,
        },
    }
}

fn right_value(b: &Expr, o: &Outcome) -> String {
    match eval(b, o) {
        Ok(Val::Number(v)) => show(v),
        Ok(Val::Bool(v)) => v.to_string(),
        Err(_) => describe(b),
    }
}

/// An expression written back, for messages.
fn describe(e: &Expr) -> String {
    match e {
        Expr::Number(v) => show(*v),
        Expr::Bool(b) => b.to_string(),
        Expr::Name(n) => name_text(n),
        Expr::Neg(a) => format!("-{}", describe(a)),
        Expr::Not(a) => format!("not {}", describe(a)),
        Expr::Arith(a, op, b) => {
            let sym = match op {
                ArithOp::Add => "+",
                ArithOp::Sub => "-",
                ArithOp::Mul => "*",
                ArithOp::Div => "/",
            };
            format!("({} {sym} {})", describe(a), describe(b))
        }
        Expr::Compare(a, _, b) => format!("{} compared with {}", describe(a), describe(b)),
        Expr::And(p) => p.iter().map(describe).collect::<Vec<_>>().join(" and "),
        Expr::Or(p) => p.iter().map(describe).collect::<Vec<_>>().join(" or "),
    }
}

/// An expression in words; `nested` puts a list of alternatives or conditions in parentheses.
fn words(e: &Expr, nested: bool) -> String {
    let noun = |x: &Expr| match x {
        Expr::Name(Name::Steps) => "steps".to_string(),
        Expr::Name(Name::Metric(m)) => m.replace('_', " "),
        Expr::Name(Name::Scenario(p)) => format!("the scenario's {}", p.replace('_', " ")),
        other => describe(other),
    };
    let group = |text: String| match nested {
        true => format!("({text})"),
        false => text,
    };
    match e {
        Expr::Name(Name::Completed) => "completed".into(),
        Expr::Bool(true) => "always met".into(),
        Expr::Bool(false) => "never met".into(),
        Expr::Not(inner) => match **inner {
            Expr::Name(Name::Completed) => "not completed".into(),
            _ => format!("not {}", words(inner, true)),
        },
        Expr::And(parts) => {
            let all: Vec<String> = parts.iter().map(|p| words(p, true)).collect();
            group(all.join(", and "))
        }
        Expr::Or(parts) => {
            let any: Vec<String> = parts.iter().map(|p| words(p, true)).collect();
            group(any.join(", or "))
        }
        Expr::Compare(a, op, b) => {
            let phrase = match (op, &**b) {
                (CmpOp::Eq, Expr::Bool(_)) => "is",
                (CmpOp::Ne, Expr::Bool(_)) => "is not",
                (CmpOp::Lt, _) => "below",
                (CmpOp::Le, _) => "at most",
                (CmpOp::Gt, _) => "above",
                (CmpOp::Ge, _) => "at least",
                (CmpOp::Eq, _) => "equal to",
                (CmpOp::Ne, _) => "other than",
            };
            format!("{} {phrase} {}", noun(a), noun(b))
        }
        other => noun(other),
    }
}

/// A number as a person writes it: whole numbers without a fraction, others to 4 significant
/// digits.
fn show(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn outcome<'a>(
        completed: bool,
        steps: u64,
        metrics: &'a serde_json::Map<String, Value>,
        scenario: &'a Value,
    ) -> Outcome<'a> {
        Outcome {
            completed,
            steps,
            metrics,
            scenario,
        }
    }

    fn metrics() -> serde_json::Map<String, Value> {
        json!({"collisions": 12, "built": 0.75, "stage": 1})
            .as_object()
            .unwrap()
            .clone()
    }

    #[test]
    fn goals_read_in_words() {
        let words = |t: &str| Goal::parse(t).unwrap().words();
        assert_eq!(
            words("completed and metrics.collisions < 40"),
            "Completed, and collisions below 40."
        );
        assert_eq!(
            words("completed and steps <= 300 and scenario.robots <= 6"),
            "Completed, and steps at most 300, and the scenario's robots at most 6."
        );
        assert_eq!(
            words("metrics.span >= 10 or not completed"),
            "Span at least 10, or not completed."
        );
        assert_eq!(
            words("completed and (steps < 200 or scenario.adaptation == true)"),
            "Completed, and (steps below 200, or the scenario's adaptation is true)."
        );
    }

    #[test]
    fn goals_check_outcomes_and_say_why() {
        let m = metrics();
        let s = json!({"robots": 6, "stages": [{"robots": 3}], "field": "discrete"});
        let o = outcome(true, 912, &m, &s);
        let check = |text: &str| Goal::parse(text).unwrap().check(&o);

        let c = check("completed and steps <= 800");
        assert!(!c.met);
        assert_eq!(c.because, "steps is 912, but it must be ≤ 800");

        let c = check("completed && metrics.collisions < 20");
        assert!(c.met, "{}", c.because);
        assert_eq!(
            c.because,
            "the run completed; metrics.collisions is 12, < 20 as required"
        );

        let c = check("scenario.robots <= 5 or metrics.built >= 0.9");
        assert!(!c.met);
        assert_eq!(
            c.because,
            "scenario.robots is 6, but it must be ≤ 5; metrics.built is 0.75, but it must be ≥ 0.9"
        );

        assert!(check("scenario.stages.0.robots == 3").met);
        assert!(check("not (steps > 1000) and -steps < 0").met);
        assert!(check("steps / 2 + 1 == 457").met);
        assert!(check("steps ≥ 900 and steps ≠ 1").met);
        assert!(!check("not completed").met);
        assert_eq!(check("not completed").because, "the run completed");

        let c = check("metrics.nothing > 1");
        assert!(!c.met);
        assert!(
            c.because.contains("the metric 'nothing' does not exist"),
            "{}",
            c.because
        );
        let c = check("scenario.field > 1");
        assert!(!c.met);
        assert!(
            c.because.contains("neither a number nor true/false"),
            "{}",
            c.because
        );
    }

    #[test]
    fn bad_goals_are_refused_with_the_column_and_the_rule() {
        let err = |text: &str| Goal::parse(text).unwrap_err().to_string();
        assert_eq!(
            err(""),
            "the goal is empty; write a condition such as 'completed and steps <= 800'"
        );
        assert_eq!(
            err("steps = 800"),
            "column 7: '=' alone is not a comparison; write '=='"
        );
        assert_eq!(
            err("steps <= "),
            "column 10: expected a number, a name or '(', found the end"
        );
        assert_eq!(
            err("steps"),
            "the goal is a number, not a condition; compare it, as in 'steps <= 800'"
        );
        assert_eq!(
            err("completed < 3"),
            "column 11: the left side of a comparison needs a number, but is true or false"
        );
        assert_eq!(
            err("steps and completed"),
            "column 7: the left side of 'and' needs true or false, but is a number"
        );
        assert_eq!(err("1 < steps < 9"), "column 11: comparisons do not chain; join them with 'and', as in 'steps > 10 and steps < 90'");
        assert_eq!(err("robots <= 5"), "column 1: 'robots' is not a name a goal knows; use completed, steps, metrics.NAME or scenario.PATH");
        assert_eq!(err("(steps > 3"), "column 11: expected ')', found the end");
        assert_eq!(
            err("steps > 3 $"),
            "column 11: '$' has no meaning in a goal"
        );
        assert!(err(&"(".repeat(100)).contains("nests deeper than 32"));
        assert!(err(&"x".repeat(MAX_GOAL_CHARS + 1)).contains("too long"));
        assert!(err(&format!("{}completed", "not ".repeat(40))).contains("nests deeper"));
    }

    #[test]
    fn names_lists_what_the_goal_reads() {
        let g = Goal::parse("completed and metrics.collisions < scenario.robots * 2 and steps > 0")
            .unwrap();
        assert_eq!(
            g.names(),
            vec![
                "completed",
                "metrics.collisions",
                "scenario.robots",
                "steps"
            ]
        );
        assert_eq!(
            g.text(),
            "completed and metrics.collisions < scenario.robots * 2 and steps > 0"
        );
    }
}
