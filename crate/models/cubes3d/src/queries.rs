//! Helper calls for the editors and the CLI (see the core's `models::query`).

use serde_json::{json, Value};

use super::typelist::{self, TypeList};
use kumiki_model::error::{Error, Result};
use kumiki_model::shape;

fn described(lists: Vec<TypeList>, units: usize) -> Value {
    json!({
        "type_lists": typelist::to_text(&lists),
        "count": lists.len(),
        "units": units,
    })
}

/// The `derive` query: the unique type-list description of a shape, given as cubic-lattice text
/// (`{"shape": "##\n##\n---\n##\n##\n"}`) or as unit coordinates (`{"units": [[0, 0, 0], ...]}`).
/// Answers `{"type_lists": text, "count": n, "units": n}`.
pub fn query_derive(args: &Value) -> Result<Value> {
    if let Some(text) = args.get("shape") {
        let text = text
            .as_str()
            .ok_or_else(|| Error::field("shape", "expected text"))?;
        let g = shape::parse_cubic(text).map_err(|e| e.within("shape"))?;
        let units = typelist::grid_units(&g);
        let lists = typelist::describe(&units).map_err(|e| e.within("shape"))?;
        Ok(described(lists, units.len()))
    } else if let Some(list) = args.get("units") {
        let units: Vec<(i32, i32, i32)> =
            kumiki_model::error::from_value::<Vec<[i32; 3]>>(list.clone())
                .map_err(|e| e.within("units"))?
                .into_iter()
                .map(|[x, y, z]| (x, y, z))
                .collect();
        let max_units = crate::limits::LIMITS.page.units;
        if units.len() > max_units {
            return Err(Error::field("units", format!("at most {max_units} units")));
        }
        let lists = typelist::describe(&units).map_err(|e| e.within("units"))?;
        Ok(described(lists, units.len()))
    } else {
        Err(Error::field("", "derive needs \"shape\" or \"units\""))
    }
}

/// The `check` query: parses `{"type_lists": text}` and answers it in normal form with its count,
/// or an error naming the line and the problem.
pub fn query_check(args: &Value) -> Result<Value> {
    let text = args
        .get("type_lists")
        .and_then(Value::as_str)
        .ok_or_else(|| Error::field("type_lists", "expected text"))?;
    let lists = typelist::parse(text).map_err(|e| e.within("type_lists"))?;
    Ok(json!({ "type_lists": typelist::to_text(&lists), "count": lists.len() }))
}
