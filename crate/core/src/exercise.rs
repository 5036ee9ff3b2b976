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

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};

/// Length limits of an exercise's texts, in characters.
pub const MAX_TITLE_CHARS: usize = 100;
pub const MAX_INSTRUCTIONS_CHARS: usize = 10_000;
pub const MAX_HINTS: usize = 10;
pub const MAX_HINT_CHARS: usize = 1000;

/// The longest goal, in characters.
pub const MAX_GOAL_CHARS: usize = 1000;
/// The deepest nesting of parentheses and operators.
const MAX_DEPTH: usize = 32;

/// A scenario's `exercise` section: what a teacher asks, which fields students may not change,
/// and the goal a run must meet.
///
/// ```json
/// "exercise": {
///   "title": "Fewer collisions",
///   "instructions": "Change the collision rule so that the L is built with *fewer* collisions.",
///   "locked": { "robots": 10, "target": "..." },
///   "goal": "completed and metrics.collisions < 20",
///   "hints": ["Section 4.2 compares three rules."]
/// }
/// ```
/// `locked` maps dotted scenario paths to the teacher's values: the page shows those fields
/// read-only, and `kumiki check` reports a hand-in whose values differ.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// The exercise's title.
    #[schemars(length(max = MAX_TITLE_CHARS))]
    pub title: String,
    /// What the student is asked to do.
    #[serde(default)]
    #[schemars(length(max = MAX_INSTRUCTIONS_CHARS))]
    pub instructions: String,
    /// Dotted scenario paths and the teacher's values: fields students may not change.
    #[serde(default)]
    pub locked: BTreeMap<String, Value>,
    /// A condition on the run's outcome, such as `completed and steps <= 800`.
    #[schemars(length(max = MAX_GOAL_CHARS))]
    pub goal: String,
    /// Hints shown one at a time.
    #[serde(default)]
    #[schemars(length(max = MAX_HINTS), inner(length(max = MAX_HINT_CHARS)))]
    pub hints: Vec<String>,
}

impl Exercise {
    /// Reads and checks an exercise section; `doc` is the whole scenario, in which every locked
    /// path must name a field.
    pub fn from_value(value: Value, doc: &Value) -> Result<Exercise> {
        let exercise: Exercise = crate::error::from_value(value)?;
        let long = |path: &str, text: &str, max: usize| {
            let n = text.chars().count();
            match n > max {
                true => Err(Error::field(
                    path,
                    format!("{n} characters is too long; at most {max}"),
                )),
                false => Ok(()),
            }
        };
        long("title", &exercise.title, MAX_TITLE_CHARS)?;
        long(
            "instructions",
            &exercise.instructions,
            MAX_INSTRUCTIONS_CHARS,
        )?;
        if exercise.hints.len() > MAX_HINTS {
            return Err(Error::field(
                "hints",
                format!(
                    "{} hints are too many; at most {MAX_HINTS}",
                    exercise.hints.len()
                ),
            ));
        }
        for (i, hint) in exercise.hints.iter().enumerate() {
            long(&format!("hints[{i}]"), hint, MAX_HINT_CHARS)?;
        }
        Goal::parse(&exercise.goal).map_err(|e| e.within("goal"))?;
        for path in exercise.locked.keys() {
            if path == "exercise" || path.starts_with("exercise.") {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "the exercise itself cannot be locked; it is never editable by students",
                ));
            }
            if lookup_path(doc, path).is_none() {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "no such field in this scenario",
                ));
            }
        }
        Ok(exercise)
    }

    /// The goal, parsed (it was checked when the exercise was read).
    pub fn goal(&self) -> Goal {
        Goal::parse(&self.goal).expect("the goal was checked when the exercise was read")
    }

    /// The locked fields whose value in `doc` is not the teacher's: (path, teacher's, found).
    pub fn locked_changes(&self, doc: &Value) -> Vec<(String, Value, Value)> {
        self.locked
            .iter()
            .filter_map(|(path, want)| {
                let got = lookup_path(doc, path).cloned().unwrap_or(Value::Null);
                (got != *want).then(|| (path.clone(), want.clone(), got))
            })
            .collect()
    }
}

/// A graded hand-in: the student's scenario replayed to its end and judged by its exercise.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Grade {
    pub name: String,
    pub met: bool,
    pub because: String,
    pub completed: bool,
    pub steps: u64,
    pub hash: String,
    /// Locked fields the hand-in changed: "robots: 5 → 7".
    pub locked_edited: Vec<String>,
    /// Every field that differs from the teacher's exercise, when it is known (the name, which
    /// Hand in sets, left out).
    pub changed: Vec<String>,
    /// The hand-in's exercise section is not the teacher's (its goal or locks were edited).
    pub exercise_edited: bool,
    /// The metrics the goal reads, at the end of the replayed run (the page's Grade view shows
    /// them; `kumiki check` leaves them out).
    #[serde(skip)]
    pub goal_metrics: BTreeMap<String, Value>,
}

/// Replays a hand-in and judges it by the exercise it carries, or by `original`'s when the
/// teacher's exercise is given: the hand-in then may not have edited the exercise itself, and
/// every field that differs from the original is listed. A hand-in with no exercise is an error.
pub fn grade(handin: &crate::Scenario, original: Option<&crate::Scenario>) -> Result<Grade> {
    let exercise = match original {
        Some(o) => o.exercise.as_ref().ok_or_else(|| {
            Error::field("exercise", "the teacher's scenario has no exercise section")
        })?,
        None => handin
            .exercise
            .as_ref()
            .ok_or_else(|| Error::field("exercise", "this scenario is not an exercise hand-in"))?,
    };
    let mut run = crate::Run::new(handin.clone())?;
    run.run_to_end();
    let outcome = run.outcome();
    let doc = handin.to_value();
    let check = exercise.goal().check(&Outcome {
        completed: outcome.completed,
        steps: outcome.steps,
        metrics: &outcome.metrics,
        scenario: &doc,
    });
    let locked_edited = crate::grading::locked_edits(exercise, &doc);
    let (changed, exercise_edited) = match original {
        // The name is left out: Hand in writes the student's name into it.
        Some(o) => (
            differences(&o.to_value(), &doc)
                .into_iter()
                .filter(|p| !p.starts_with("exercise") && p != "name")
                .collect(),
            handin.exercise.as_ref() != Some(exercise),
        ),
        None => (Vec::new(), false),
    };
    let mut because = check.because;
    if !locked_edited.is_empty() {
        because = format!(
            "the hand-in changed locked fields ({}); {because}",
            locked_edited.join(", ")
        );
    }
    if exercise_edited {
        because = format!("the hand-in edited the exercise itself; {because}");
    }
    let goal_metrics = exercise
        .goal()
        .names()
        .iter()
        .filter_map(|n| n.strip_prefix("metrics."))
        .filter_map(|m| Some((m.to_string(), outcome.metrics.get(m)?.clone())))
        .collect();
    Ok(Grade {
        goal_metrics,
        name: handin.name.clone(),
        met: check.met && !exercise_edited && locked_edited.is_empty(),
        because,
        completed: outcome.completed,
        steps: outcome.steps,
        hash: outcome.hash,
        locked_edited,
        changed,
        exercise_edited,
    })
}

/// The value at a dotted path (`stages.0.robots`) of a JSON document.
pub fn lookup_path<'a>(doc: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.').try_fold(doc, |here, seg| match here {
        Value::Object(map) => map.get(seg),
        Value::Array(items) => seg.parse::<usize>().ok().and_then(|i| items.get(i)),
        _ => None,
    })
}

/// The dotted paths at which two documents differ, down to the values that differ (lists of
/// different lengths count as one difference).
pub fn differences(a: &Value, b: &Value) -> Vec<String> {
    fn walk(a: &Value, b: &Value, at: &str, out: &mut Vec<String>) {
        let join = |k: &str| {
            if at.is_empty() {
                k.to_string()
            } else {
                format!("{at}.{k}")
            }
        };
        match (a, b) {
            (Value::Object(x), Value::Object(y)) => {
                let mut keys: Vec<&String> = x.keys().chain(y.keys()).collect();
                keys.sort();
                keys.dedup();
                for k in keys {
                    match (x.get(k), y.get(k)) {
                        (Some(p), Some(q)) => walk(p, q, &join(k), out),
                        _ => out.push(join(k)),
                    }
                }
            }
            (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
                for (i, (p, q)) in x.iter().zip(y).enumerate() {
                    walk(p, q, &join(&i.to_string()), out);
                }
            }
            (p, q) if p != q => out.push(at.to_string()),
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(a, b, "", &mut out);
    out
}

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
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
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
        let tokens = lex(text)?;
        let mut p = Parser {
            tokens,
            at: 0,
            depth: 0,
        };
        if p.tokens.len() == 1 {
            return Err(Error::field(
                "",
                "the goal is empty; write a condition such as 'completed and steps <= 800'",
            ));
        }
        let expr = p.or()?;
        if let Some(t) = p.peek_token() {
            return Err(t.error(format!(
                "expected 'and', 'or' or the end, found {}",
                t.kind.show()
            )));
        }
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
        out.sort();
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

// ---- lexing -----------------------------------------------------------------------------------

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Number(f64),
    Ident(String),
    Op(&'static str),
    Open,
    Close,
    End,
}

impl Kind {
    fn show(&self) -> String {
        match self {
            Kind::Number(v) => format!("the number {}", show(*v)),
            Kind::Ident(s) => format!("'{s}'"),
            Kind::Op(o) => format!("'{o}'"),
            Kind::Open => "'('".into(),
            Kind::Close => "')'".into(),
            Kind::End => "the end".into(),
        }
    }
}

#[derive(Clone, Debug)]
struct Token {
    kind: Kind,
    /// 1-based character column.
    column: usize,
}

impl Token {
    fn error(&self, reason: String) -> Error {
        Error::field("", format!("column {}: {reason}", self.column))
    }
}

fn lex(text: &str) -> Result<Vec<Token>> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let column = i + 1;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        let two: String = chars[i..(i + 2).min(chars.len())].iter().collect();
        let op = match two.as_str() {
            "<=" => Some(("<=", 2)),
            ">=" => Some((">=", 2)),
            "==" => Some(("==", 2)),
            "!=" => Some(("!=", 2)),
            "&&" => Some(("and", 2)),
            "||" => Some(("or", 2)),
            _ => match c {
                '<' => Some(("<", 1)),
                '>' => Some((">", 1)),
                '≤' => Some(("<=", 1)),
                '≥' => Some((">=", 1)),
                '≠' => Some(("!=", 1)),
                '+' => Some(("+", 1)),
                '-' => Some(("-", 1)),
                '*' => Some(("*", 1)),
                '/' => Some(("/", 1)),
                '!' => Some(("not", 1)),
                '=' => {
                    return Err(Error::field(
                        "",
                        format!("column {column}: '=' alone is not a comparison; write '=='"),
                    ))
                }
                _ => None,
            },
        };
        if let Some((op, len)) = op {
            out.push(Token {
                kind: Kind::Op(op),
                column,
            });
            i += len;
        } else if c == '(' || c == ')' {
            out.push(Token {
                kind: if c == '(' { Kind::Open } else { Kind::Close },
                column,
            });
            i += 1;
        } else if c.is_ascii_digit()
            || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
        {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
                let mut j = i + 1;
                if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
                    j += 1;
                }
                if j < chars.len() && chars[j].is_ascii_digit() {
                    i = j;
                    while i < chars.len() && chars[i].is_ascii_digit() {
                        i += 1;
                    }
                }
            }
            let word: String = chars[start..i].iter().collect();
            let v: f64 = word.parse().map_err(|_| {
                Error::field("", format!("column {column}: '{word}' is not a number"))
            })?;
            out.push(Token {
                kind: Kind::Number(v),
                column,
            });
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len()
                && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == '.')
            {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let kind = match word.as_str() {
                "and" => Kind::Op("and"),
                "or" => Kind::Op("or"),
                "not" => Kind::Op("not"),
                _ => Kind::Ident(word),
            };
            out.push(Token { kind, column });
        } else {
            return Err(Error::field(
                "",
                format!("column {column}: '{c}' has no meaning in a goal"),
            ));
        }
    }
    out.push(Token {
        kind: Kind::End,
        column: chars.len() + 1,
    });
    Ok(out)
}

// ---- parsing ----------------------------------------------------------------------------------

struct Parser {
    tokens: Vec<Token>,
    at: usize,
    depth: usize,
}

impl Parser {
    fn peek(&self) -> &Kind {
        &self.tokens[self.at].kind
    }

    /// The next token, unless it is the end.
    fn peek_token(&self) -> Option<&Token> {
        let t = &self.tokens[self.at];
        (t.kind != Kind::End).then_some(t)
    }

    fn next(&mut self) -> Token {
        let t = self.tokens[self.at].clone();
        if t.kind != Kind::End {
            self.at += 1;
        }
        t
    }

    fn is_op(&self, op: &str) -> bool {
        matches!(self.peek(), Kind::Op(o) if *o == op)
    }

    fn deeper(&mut self) -> Result<()> {
        self.depth += 1;
        match self.depth > MAX_DEPTH {
            true => Err(self.tokens[self.at]
                .error(format!("the goal nests deeper than {MAX_DEPTH} levels"))),
            false => Ok(()),
        }
    }

    fn or(&mut self) -> Result<Expr> {
        self.deeper()?;
        let mut parts = vec![self.and()?];
        while self.is_op("or") {
            let t = self.next();
            let rhs = self.and()?;
            for (side, e) in [("left", &parts[parts.len() - 1]), ("right", &rhs)] {
                need(e, Type::Bool, &t, &format!("the {side} side of 'or'"))?;
            }
            parts.push(rhs);
        }
        self.depth -= 1;
        Ok(if parts.len() == 1 {
            parts.pop().unwrap()
        } else {
            Expr::Or(parts)
        })
    }

    fn and(&mut self) -> Result<Expr> {
        let mut parts = vec![self.not()?];
        while self.is_op("and") {
            let t = self.next();
            let rhs = self.not()?;
            for (side, e) in [("left", &parts[parts.len() - 1]), ("right", &rhs)] {
                need(e, Type::Bool, &t, &format!("the {side} side of 'and'"))?;
            }
            parts.push(rhs);
        }
        Ok(if parts.len() == 1 {
            parts.pop().unwrap()
        } else {
            Expr::And(parts)
        })
    }

    fn not(&mut self) -> Result<Expr> {
        if self.is_op("not") {
            let t = self.next();
            self.deeper()?;
            let inner = self.not()?;
            self.depth -= 1;
            need(&inner, Type::Bool, &t, "'not'")?;
            return Ok(Expr::Not(Box::new(inner)));
        }
        self.compare()
    }

    fn compare(&mut self) -> Result<Expr> {
        let lhs = self.sum()?;
        let op = match self.peek() {
            Kind::Op("<") => CmpOp::Lt,
            Kind::Op("<=") => CmpOp::Le,
            Kind::Op(">") => CmpOp::Gt,
            Kind::Op(">=") => CmpOp::Ge,
            Kind::Op("==") => CmpOp::Eq,
            Kind::Op("!=") => CmpOp::Ne,
            _ => return Ok(lhs),
        };
        let t = self.next();
        let rhs = self.sum()?;
        if !matches!(op, CmpOp::Eq | CmpOp::Ne) {
            need(&lhs, Type::Number, &t, "the left side of a comparison")?;
            need(&rhs, Type::Number, &t, "the right side of a comparison")?;
        } else {
            let (a, b) = (type_of(&lhs), type_of(&rhs));
            if a != Type::Any && b != Type::Any && a != b {
                return Err(t.error(
                    "'==' and '!=' compare a number with a number, or true/false with true/false"
                        .into(),
                ));
            }
        }
        if matches!(self.peek(), Kind::Op("<" | "<=" | ">" | ">=" | "==" | "!=")) {
            return Err(self.tokens[self.at].error(
                "comparisons do not chain; join them with 'and', as in 'steps > 10 and steps < 90'"
                    .into(),
            ));
        }
        Ok(Expr::Compare(Box::new(lhs), op, Box::new(rhs)))
    }

    fn sum(&mut self) -> Result<Expr> {
        let mut lhs = self.term()?;
        loop {
            let op = match self.peek() {
                Kind::Op("+") => ArithOp::Add,
                Kind::Op("-") => ArithOp::Sub,
                _ => return Ok(lhs),
            };
            let t = self.next();
            let rhs = self.term()?;
            need(&lhs, Type::Number, &t, "arithmetic")?;
            need(&rhs, Type::Number, &t, "arithmetic")?;
            lhs = Expr::Arith(Box::new(lhs), op, Box::new(rhs));
        }
    }

    fn term(&mut self) -> Result<Expr> {
        let mut lhs = self.unary()?;
        loop {
            let op = match self.peek() {
                Kind::Op("*") => ArithOp::Mul,
                Kind::Op("/") => ArithOp::Div,
                _ => return Ok(lhs),
            };
            let t = self.next();
            let rhs = self.unary()?;
            need(&lhs, Type::Number, &t, "arithmetic")?;
            need(&rhs, Type::Number, &t, "arithmetic")?;
            lhs = Expr::Arith(Box::new(lhs), op, Box::new(rhs));
        }
    }

    fn unary(&mut self) -> Result<Expr> {
        if self.is_op("-") {
            let t = self.next();
            self.deeper()?;
            let inner = self.unary()?;
            self.depth -= 1;
            need(&inner, Type::Number, &t, "'-'")?;
            return Ok(Expr::Neg(Box::new(inner)));
        }
        self.atom()
    }

    fn atom(&mut self) -> Result<Expr> {
        let t = self.next();
        match &t.kind {
            Kind::Number(v) => Ok(Expr::Number(*v)),
            Kind::Open => {
                let inner = self.or()?;
                let close = self.next();
                match &close.kind {
                    Kind::Close => Ok(inner),
                    other => Err(close.error(format!("expected ')', found {}", other.show()))),
                }
            }
            Kind::Ident(word) => match word.as_str() {
                "true" => Ok(Expr::Bool(true)),
                "false" => Ok(Expr::Bool(false)),
                "completed" => Ok(Expr::Name(Name::Completed)),
                "steps" => Ok(Expr::Name(Name::Steps)),
                _ => {
                    if let Some(m) = word.strip_prefix("metrics.").filter(|m| !m.is_empty()) {
                        Ok(Expr::Name(Name::Metric(m.to_string())))
                    } else if let Some(p) = word.strip_prefix("scenario.").filter(|p| !p.is_empty())
                    {
                        Ok(Expr::Name(Name::Scenario(p.to_string())))
                    } else {
                        Err(t.error(format!(
                            "'{word}' is not a name a goal knows; use completed, steps, metrics.NAME or scenario.PATH"
                        )))
                    }
                }
            },
            other => Err(t.error(format!(
                "expected a number, a name or '(', found {}",
                other.show()
            ))),
        }
    }
}

fn type_of(e: &Expr) -> Type {
    match e {
        Expr::Number(_) | Expr::Neg(_) | Expr::Arith(..) => Type::Number,
        Expr::Bool(_) | Expr::Not(_) | Expr::Compare(..) | Expr::And(_) | Expr::Or(_) => Type::Bool,
        Expr::Name(Name::Completed) => Type::Bool,
        Expr::Name(Name::Steps) => Type::Number,
        Expr::Name(_) => Type::Any,
    }
}

fn need(e: &Expr, want: Type, at: &Token, role: &str) -> Result<()> {
    let got = type_of(e);
    if got == Type::Any || got == want {
        return Ok(());
    }
    let (want, got) = match want {
        Type::Number => ("a number", "true or false"),
        _ => ("true or false", "a number"),
    };
    Err(at.error(format!("{role} needs {want}, but is {got}")))
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

    fn exercise_doc(exercise: Value) -> Value {
        let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
        doc["exercise"] = exercise;
        doc
    }

    #[test]
    fn an_exercise_travels_in_the_scenario_and_its_link() {
        let doc = exercise_doc(json!({
            "title": "Fewer collisions",
            "instructions": "Change *one* thing.",
            "locked": {"robots": 5, "field": "continuous"},
            "goal": "completed and metrics.collisions < 20",
            "hints": ["Section 4.2."]
        }));
        let s = crate::Scenario::from_value(doc).unwrap();
        let e = s.exercise.clone().unwrap();
        assert_eq!(e.title, "Fewer collisions");
        assert_eq!(e.goal().names(), vec!["completed", "metrics.collisions"]);
        let back = crate::link::decode(&crate::link::encode(&s)).unwrap();
        assert_eq!(back, s);
        assert!(e.locked_changes(&s.to_value()).is_empty());
        let edited = s.with_override("robots", json!(7)).unwrap();
        assert_eq!(
            e.locked_changes(&edited.to_value()),
            vec![("robots".to_string(), json!(5), json!(7))]
        );
        assert_eq!(
            differences(&s.to_value(), &edited.to_value()),
            vec!["robots"]
        );
    }

    #[test]
    fn grading_replays_the_hand_in_and_reports_what_changed() {
        let doc = exercise_doc(json!({
            "title": "Build it",
            "locked": {"robots": 5},
            "goal": "completed and steps <= 100000"
        }));
        let teacher = crate::Scenario::from_value(doc).unwrap();
        let fair = teacher.with_override("collision", json!("relay")).unwrap();
        let g = grade(&fair, Some(&teacher)).unwrap();
        assert!(g.met, "{}", g.because);
        assert!(g.completed && g.steps > 0 && g.hash.len() == 16);
        assert_eq!(g.changed, vec!["collision"]);
        assert!(g.locked_edited.is_empty() && !g.exercise_edited);
        // The same run as replaying the link by hand.
        let mut run = crate::Run::new(fair.clone()).unwrap();
        run.run_to_end();
        assert_eq!(g.hash, run.outcome().hash);

        let tampered = teacher.with_override("robots", json!(9)).unwrap();
        let g = grade(&tampered, None).unwrap();
        assert_eq!(g.locked_edited, vec!["robots: 5 → 9"]);
        assert!(!g.met);
        assert!(
            g.because
                .starts_with("the hand-in changed locked fields (robots: 5 → 9); "),
            "{}",
            g.because
        );

        let mut cheat = fair.clone();
        cheat.exercise.as_mut().unwrap().goal = "true".into();
        let g = grade(&cheat, Some(&teacher)).unwrap();
        assert!(g.exercise_edited && !g.met);
        assert!(g
            .because
            .starts_with("the hand-in edited the exercise itself"));

        let plain = crate::presets::scenario("amas-L").unwrap();
        assert!(grade(&plain, None)
            .unwrap_err()
            .to_string()
            .contains("not an exercise"));
    }

    #[test]
    fn bad_exercises_name_the_field() {
        let err = |exercise: Value| {
            crate::Scenario::from_value(exercise_doc(exercise))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err(json!({"title": "t", "goal": "steps = 3"})),
            "exercise.goal: column 7: '=' alone is not a comparison; write '=='"
        );
        assert_eq!(
            err(json!({"title": "t", "goal": "completed", "locked": {"robot": 5}})),
            "exercise.locked.robot: no such field in this scenario"
        );
        assert_eq!(
            err(json!({"title": "t", "goal": "completed", "locked": {"exercise.goal": 1}})),
            "exercise.locked.exercise.goal: the exercise itself cannot be locked; it is never editable by students"
        );
        assert!(err(json!({"goal": "completed"})).starts_with("exercise: 'title' is required"));
        assert!(err(json!({"title": "t", "goal": "completed", "extra": 1}))
            .contains("unknown field 'extra'"));
        assert!(
            err(json!({"title": "t", "goal": "completed", "hints": vec!["h"; 11]}))
                .contains("at most 10")
        );
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
