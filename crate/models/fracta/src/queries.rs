//! Helper calls for editors and the CLI (see `models::query`).

use super::*;

fn text<'a>(args: &'a Value, key: &str) -> Result<&'a str> {
    args.get(key)
        .and_then(Value::as_str)
        .ok_or_else(|| Error::field(key, "expected text"))
}

/// `derive`: the statements of one or more hex shapes (`{"shape": text}`) separated by lines
/// holding `---`: the first shape gives priority 1, the next the statements it adds at
/// priority 2, and so on. Answers `{"goal": text}`.
pub fn derive(args: &Value) -> Result<Value> {
    let input = text(args, "shape")?;
    let mut shapes = Vec::new();
    for (i, block) in input.split("\n---").enumerate() {
        let block = block.trim_start_matches('-');
        let g = shape::parse_hex(block).map_err(|e| match e {
            Error::Field { reason, .. } if input.contains("---") => {
                Error::field("shape", format!("shape {}: {reason}", i + 1))
            }
            other => other.within("shape"),
        })?;
        shapes.push(g);
    }
    let goal = derive::derive(&shapes).map_err(|e| Error::field("shape", e))?;
    Ok(json!({ "goal": goal.text() }))
}

/// `check`: parses `{"goal": text}` and answers it in normal form (sorted, canonical names),
/// or an error naming the line and the problem.
pub fn check(args: &Value) -> Result<Value> {
    let goal = Goal::parse(text(args, "goal")?).map_err(|e| Error::field("goal", e))?;
    Ok(json!({ "goal": goal.text() }))
}

/// `types`: the connection types: code, name, ASCII spelling, bonds, movable, colour.
pub fn types(_args: &Value) -> Result<Value> {
    let t: &Types = super::types();
    let list: Vec<Value> = t
        .info
        .iter()
        .enumerate()
        .skip(1)
        .map(|(c, i)| {
            json!({
                "code": c, "name": i.name, "ascii": i.ascii, "aliases": i.aliases,
                "bonds": i.bonds, "movable": i.movable, "color": i.color,
                "from_paper": i.paper, "description": i.description,
            })
        })
        .collect();
    Ok(json!({ "types": list }))
}
