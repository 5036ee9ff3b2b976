//! A slot's input and output as they cross: JSON values (the contract's form) to the script's
//! values and back.

use rhai::{Array, Dynamic, Map, FLOAT, INT};
use serde_json::{Number, Value};

/// The script's value of a JSON value: null is `()`, a whole number an integer, any other number
/// a float.
pub(crate) fn to_dynamic(value: &Value) -> Dynamic {
    match value {
        Value::Null => Dynamic::UNIT,
        Value::Bool(b) => (*b).into(),
        Value::Number(n) => match n.as_i64() {
            Some(i) => i.into(),
            None => n.as_f64().unwrap_or(FLOAT::NAN).into(),
        },
        Value::String(s) => s.as_str().into(),
        Value::Array(items) => {
            let array: Array = items.iter().map(to_dynamic).collect();
            array.into()
        }
        Value::Object(entries) => {
            let map: Map = entries
                .iter()
                .map(|(k, v)| (k.as_str().into(), to_dynamic(v)))
                .collect();
            map.into()
        }
    }
}

/// The JSON value of a script's answer; an error naming the type it cannot be.
pub(crate) fn to_value(value: &Dynamic) -> Result<Value, String> {
    if value.is_unit() {
        return Ok(Value::Null);
    }
    if let Some(b) = value.clone().try_cast::<bool>() {
        return Ok(b.into());
    }
    if let Some(i) = value.clone().try_cast::<INT>() {
        return Ok(i.into());
    }
    if let Some(x) = value.clone().try_cast::<FLOAT>() {
        return Number::from_f64(x)
            .map(Value::Number)
            .ok_or_else(|| format!("the number {x}, which is not finite"));
    }
    if value.is_string() || value.is_char() {
        return Ok(Value::String(value.to_string()));
    }
    if value.is_array() {
        let items = value.read_lock::<Array>().expect("an array reads as one");
        return items
            .iter()
            .map(to_value)
            .collect::<Result<_, _>>()
            .map(Value::Array);
    }
    if value.is_map() {
        let map = value.read_lock::<Map>().expect("a map reads as one");
        return map
            .iter()
            .map(|(k, v)| Ok((k.to_string(), to_value(v)?)))
            .collect::<Result<_, String>>()
            .map(Value::Object);
    }
    Err(format!("a value of type {}", value.type_name()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn values_cross_both_ways_unchanged() {
        let v = json!({"a": [1, 2.5, true, null, "x"], "b": {"c": -3}});
        assert_eq!(to_value(&to_dynamic(&v)).unwrap(), v);
        // Floats stay floats, whole numbers integers.
        assert!(to_dynamic(&json!(2.0)).is::<FLOAT>());
        assert!(to_dynamic(&json!(2)).is::<INT>());
    }

    #[test]
    fn an_answer_that_is_not_json_is_named() {
        assert_eq!(
            to_value(&Dynamic::from(FLOAT::INFINITY)).unwrap_err(),
            "the number inf, which is not finite"
        );
        let f = Dynamic::from(rhai::FnPtr::new("f").unwrap());
        assert_eq!(to_value(&f).unwrap_err(), "a value of type Fn");
    }
}
