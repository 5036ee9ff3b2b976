//! The goal language's lexer and parser: text to a type-checked [`Expr`].

use super::{show, ArithOp, CmpOp, Expr, Name, Type};
use crate::error::{Error, Result};

/// The deepest nesting of parentheses and operators.
const MAX_DEPTH: usize = 32;

/// The value of a number the lexer found (digits with '.'s, then perhaps an exponent), as
/// `str::parse::<f64>` reads it: correctly rounded, ".5" and "5." taken, too large infinite. Read
/// by the JSON reader the module links anyway, not the standard library's, whose tables would add
/// 18 KB gzipped to the page's wasm; so it is first written as JSON writes a number (no '.' at
/// either end, no leading zeros). None when it has two '.'s.
fn number(word: &str) -> Option<f64> {
    let (mantissa, exponent) = word.split_at(word.find(['e', 'E']).unwrap_or(word.len()));
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if frac.contains('.') {
        return None;
    }
    let int = match int.trim_start_matches('0') {
        "" => "0",
        digits => digits,
    };
    let point = if frac.is_empty() { "" } else { "." };
    // Written as JSON, the only number the reader refuses is one out of the range of f64.
    Some(serde_json::from_str(&format!("{int}{point}{frac}{exponent}")).unwrap_or(f64::INFINITY))
}

/// Parses `text` into an expression, or says at which column and why not.
pub(super) fn expression(text: &str) -> Result<Expr> {
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
    Ok(expr)
}

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
            let v = number(&word).ok_or_else(|| {
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

pub(super) fn type_of(e: &Expr) -> Type {
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

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_read_as_the_standard_library_reads_them() {
        let words = [
            "0",
            "7",
            "300",
            "007",
            "0.5",
            ".5",
            "5.",
            "1.e5",
            "2.5E-3",
            "1e+05",
            "00.10",
            "0.1",
            "0.30000000000000004",
            "123456789012345678901234567890",
            "9007199254740993",
            "2.2250738585072011e-308",
            "4.9e-324",
            "1e-400",
            "1.7976931348623157e308",
            "1e400",
            "0.000000000000000000000000000000000000001",
        ];
        for word in words {
            let std: f64 = word.parse().unwrap();
            assert_eq!(
                number(word).map(f64::to_bits),
                Some(std.to_bits()),
                "{word}"
            );
        }
        assert_eq!(number("1.2.3"), None);
        assert!("1.2.3".parse::<f64>().is_err());
    }
}
