//! The range a number in a model's description may take, stated once ([`Bounded::BOUNDS`]): the
//! description's check reads it ([`check`]) and so does its JSON Schema ([`in_schema`], a schemars
//! transform), so the page's form and an editor's schema offer exactly what the check accepts.
//!
//! ```ignore
//! impl Bounded for Spec {
//!     const BOUNDS: &'static [Bound<Spec>] = &[
//!         Bound::new("diffusion", |s: &Spec| Some(s.diffusion))
//!             .above(0.0)
//!             .at_most(0.25)
//!             .why("larger values make equation 1 unstable"),
//!         Bound::new("supply_rows", |s: &Spec| Some(s.supply_rows.into()))
//!             .at_least(1.0)
//!             .up_to(|l| l.amas.supply_rows.into()),
//!     ];
//! }
//! ```
//!
//! with `#[schemars(transform = bounds::in_schema::<Spec>)]` on the description.

use crate::error::{Error, Result};
use crate::limits::Limits;

/// A description whose numbers have ranges: every model's [`Spec`](crate::model::Spec), and any
/// record inside one.
pub trait Bounded: Sized + 'static {
    /// Each bounded key with its range.
    const BOUNDS: &'static [Bound<Self>];
}

/// The low end of a range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Low {
    None,
    AtLeast(f64),
    /// Greater than, not equal.
    Above(f64),
}

/// The high end of a range.
#[derive(Clone, Copy, Debug)]
pub enum High {
    None,
    AtMost(f64),
    /// At most a size limit: the one the description is checked within, the page's
    /// ([`Limits::PAGE`]) in the schema.
    Limit(fn(&Limits) -> f64),
}

/// The range of one key of a description `S`: a number, or a list's length.
pub struct Bound<S> {
    /// The key as the scenario writes it.
    pub key: &'static str,
    /// The key's value (a list's length), or `None` when it is left out.
    pub value: fn(&S) -> Option<f64>,
    /// The key is a list, and its length is bounded.
    pub list: bool,
    pub low: Low,
    pub high: High,
    /// What the number counts, named after the range in messages ("steps", "cells").
    pub unit: &'static str,
    /// The rule in words, said instead of the range ("at least one robot is needed").
    pub says: &'static str,
    /// Why the range is what it is, said after it.
    pub why: &'static str,
}

impl<S> Bound<S> {
    /// A number with no range yet.
    pub const fn new(key: &'static str, value: fn(&S) -> Option<f64>) -> Bound<S> {
        Bound {
            key,
            value,
            list: false,
            low: Low::None,
            high: High::None,
            unit: "",
            says: "",
            why: "",
        }
    }

    /// A list whose length (given by `value`) has no range yet.
    pub const fn length(key: &'static str, value: fn(&S) -> Option<f64>) -> Bound<S> {
        let mut bound = Bound::new(key, value);
        bound.list = true;
        bound
    }

    pub const fn at_least(mut self, v: f64) -> Self {
        self.low = Low::AtLeast(v);
        self
    }

    pub const fn above(mut self, v: f64) -> Self {
        self.low = Low::Above(v);
        self
    }

    pub const fn at_most(mut self, v: f64) -> Self {
        self.high = High::AtMost(v);
        self
    }

    /// At most the size limit `limit` reads.
    pub const fn up_to(mut self, limit: fn(&Limits) -> f64) -> Self {
        self.high = High::Limit(limit);
        self
    }

    pub const fn unit(mut self, unit: &'static str) -> Self {
        self.unit = unit;
        self
    }

    pub const fn says(mut self, rule: &'static str) -> Self {
        self.says = rule;
        self
    }

    pub const fn why(mut self, reason: &'static str) -> Self {
        self.why = reason;
        self
    }

    /// The greatest value within `limits`, if there is one.
    pub fn high(&self, limits: &Limits) -> Option<f64> {
        match self.high {
            High::None => None,
            High::AtMost(v) => Some(v),
            High::Limit(limit) => Some(limit(limits)),
        }
    }

    /// Whether `v` is in the range within `limits`.
    pub fn holds(&self, v: f64, limits: &Limits) -> bool {
        let low = match self.low {
            Low::None => true,
            Low::AtLeast(a) => v >= a,
            Low::Above(a) => v > a,
        };
        v.is_finite() && low && self.high(limits).is_none_or(|b| v <= b)
    }

    /// The rule, in words: "must be from 1 to 1000 steps (why)".
    pub fn rule(&self, limits: &Limits) -> String {
        let unit = match self.unit {
            "" => String::new(),
            unit => format!(" {unit}"),
        };
        let verb = if self.list { "must hold" } else { "must be" };
        let rule = match (self.says, self.low, self.high(limits)) {
            (says, _, _) if !says.is_empty() => says.to_string(),
            (_, Low::AtLeast(a), Some(b)) => format!("{verb} from {a} to {b}{unit}"),
            (_, Low::Above(a), Some(b)) => format!("{verb} above {a} and at most {b}{unit}"),
            (_, Low::AtLeast(a), None) => format!("{verb} at least {a}{unit}"),
            (_, Low::Above(a), None) => format!("{verb} above {a}{unit}"),
            (_, Low::None, Some(b)) => format!("{verb} at most {b}{unit}"),
            (_, Low::None, None) => format!("{verb} a number{unit}"),
        };
        match self.why {
            "" => rule,
            why => format!("{rule} ({why})"),
        }
    }
}

/// Checks each of `S`'s bounded keys of `description` within `limits`, naming the first out of
/// range with its rule.
pub fn check<S: Bounded>(description: &S, limits: &Limits) -> Result<()> {
    for bound in S::BOUNDS {
        if let Some(v) = (bound.value)(description) {
            if !bound.holds(v, limits) {
                return Err(Error::field(bound.key, bound.rule(limits)));
            }
        }
    }
    Ok(())
}

/// Writes each of `S`'s ranges into its JSON Schema (a schemars transform: put
/// `#[schemars(transform = in_schema::<S>)]` on `S`): `minimum`, `exclusiveMinimum` and `maximum`
/// on a number, `minItems` and `maxItems` on a list, the page's limits for a size limit.
///
/// # Panics
/// When a bound names a key the schema does not have: a misspelt key fails every schema test.
pub fn in_schema<S: Bounded>(schema: &mut schemars::Schema) {
    use serde_json::{json, Value};
    let Some(Value::Object(properties)) = schema.get_mut("properties") else {
        unreachable!("a bounded description is an object")
    };
    for bound in S::BOUNDS {
        let Some(Value::Object(property)) = properties.get_mut(bound.key) else {
            panic!("bounded key '{}' is not in the schema", bound.key)
        };
        let (min, exclusive, max) = match bound.list {
            true => ("minItems", "minItems", "maxItems"),
            false => ("minimum", "exclusiveMinimum", "maximum"),
        };
        // Whole on a list's length or an integer key, as schemars writes their ranges.
        let whole = bound.list
            || property.get("type") == Some(&json!("integer"))
            || property
                .get("type")
                .and_then(Value::as_array)
                .is_some_and(|t| t.contains(&json!("integer")));
        let number = |v: f64| match whole {
            true => json!(v as i64),
            false => json!(v),
        };
        match bound.low {
            Low::None => {}
            Low::AtLeast(a) => {
                property.insert(min.into(), number(a));
            }
            Low::Above(a) => {
                property.remove(min);
                property.insert(exclusive.into(), number(a));
            }
        }
        if let Some(b) = bound.high(&Limits::PAGE) {
            property.insert(max.into(), number(b));
        }
    }
}

/// [`check`] for a list of records inside a description (`targets[i]`).
pub fn check_each<S: Bounded>(key: &str, records: &[S], limits: &Limits) -> Result<()> {
    for (i, record) in records.iter().enumerate() {
        check(record, limits).map_err(|e| e.within(&format!("{key}[{i}]")))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Probe {
        n: f64,
        rate: Option<f64>,
    }

    impl Bounded for Probe {
        const BOUNDS: &'static [Bound<Probe>] = &[
            Bound::new("n", |p: &Probe| Some(p.n))
                .at_least(1.0)
                .up_to(|l| l.shape_cells as f64)
                .unit("steps"),
            Bound::new("rate", |p: &Probe| p.rate)
                .above(0.0)
                .at_most(0.25)
                .why("larger values are unstable"),
        ];
    }

    #[test]
    fn a_bound_checks_its_range_and_says_its_rule() {
        let ok = Probe { n: 3.0, rate: None };
        assert!(check(&ok, &Limits::PAGE).is_ok());
        let low = Probe { n: 0.0, rate: None };
        let cells = Limits::PAGE.shape_cells;
        assert_eq!(
            check(&low, &Limits::PAGE).unwrap_err().to_string(),
            format!("n: must be from 1 to {cells} steps")
        );
        let zero = Probe {
            n: 1.0,
            rate: Some(0.0),
        };
        assert_eq!(
            check(&zero, &Limits::PAGE).unwrap_err().to_string(),
            "rate: must be above 0 and at most 0.25 (larger values are unstable)"
        );
        let nan = Probe {
            n: f64::NAN,
            rate: None,
        };
        assert!(check(&nan, &Limits::PAGE).is_err());
    }
}
