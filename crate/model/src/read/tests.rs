use super::{read, read_tagged};
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::collections::BTreeMap;

#[derive(Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Doc {
    name: String,
    count: u32,
    #[serde(default)]
    small: u8,
    signed: i64,
    ratio: f64,
    flag: bool,
    letter: Option<char>,
    cells: Vec<[i32; 3]>,
    pair: (u16, String),
    wrapped: Wrapped,
    unit: Unit,
    nothing: (),
    kind: Kind,
    tagged: Vec<Tagged>,
    adjacent: Adjacent,
    either: Option<Either>,
    table: BTreeMap<String, Vec<f32>>,
    #[serde(flatten)]
    rest: Rest,
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
struct Wrapped(u64);

#[derive(Debug, PartialEq, Serialize, Deserialize)]
struct Unit;

#[derive(Debug, PartialEq, Serialize, Deserialize)]
enum Kind {
    Plain,
    Newtype(u32),
    Tuple(i8, i8),
    Struct { at: [u8; 2], note: Option<String> },
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
enum Tagged {
    Fault { unit: u32 },
    Move { cells: Vec<i32> },
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "t", content = "c")]
enum Adjacent {
    A(String),
    B { x: i32 },
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
enum Either {
    Number(f64),
    Names(Vec<String>),
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
struct Rest {
    extra: Option<i32>,
}

fn valid() -> Value {
    json!({
        "name": "a", "count": 3, "small": 1, "signed": -4, "ratio": 0.5, "flag": true,
        "letter": "q", "cells": [[1, 2, 3], [4, 5, 6]], "pair": [7, "b"], "wrapped": 9,
        "unit": null, "nothing": null, "kind": {"Struct": {"at": [1, 2], "note": null}},
        "tagged": [{"kind": "fault", "unit": 2}, {"kind": "move", "cells": [1]}],
        "adjacent": {"t": "B", "c": {"x": -1}}, "either": ["x", "y"],
        "table": {"k": [1.5, 2.0]}, "extra": 5
    })
}

/// Every document one change away from `root`: each place replaced by each kind of value,
/// each key removed, an unknown key added to each object and an item to each list.
fn neighbours(root: &Value) -> Vec<Value> {
    let kinds = [
        json!(null),
        json!(true),
        json!("x"),
        json!("Plain"),
        json!("fault"),
        json!(-3),
        json!(2),
        json!(1.5),
        json!(1e12),
        json!(5_000_000_000u64),
        json!([]),
        json!([1, 2, 3]),
        json!(["A", "B"]),
        json!({}),
        json!({"a": 1}),
        json!({"Newtype": 4}),
        json!({"Tuple": [1, 2]}),
        json!({"Plain": null}),
    ];
    fn places(v: &Value, at: &mut Vec<Value>, all: &mut Vec<Vec<Value>>) {
        all.push(at.clone());
        match v {
            Value::Object(m) => m.iter().for_each(|(k, c)| {
                at.push(json!(k));
                places(c, at, all);
                at.pop();
            }),
            Value::Array(a) => a.iter().enumerate().for_each(|(i, c)| {
                at.push(json!(i));
                places(c, at, all);
                at.pop();
            }),
            _ => {}
        }
    }
    fn place<'a>(root: &'a mut Value, at: &[Value]) -> &'a mut Value {
        at.iter().fold(root, |v, step| match step {
            Value::String(k) => &mut v[k.as_str()],
            _ => &mut v[step.as_u64().unwrap() as usize],
        })
    }
    let mut all = Vec::new();
    places(root, &mut Vec::new(), &mut all);
    let mut out = Vec::new();
    for at in &all {
        for kind in &kinds {
            let mut doc = root.clone();
            *place(&mut doc, at) = kind.clone();
            out.push(doc);
        }
        let mut doc = root.clone();
        match place(&mut doc, at) {
            Value::Object(m) => {
                m.insert("bogus".into(), json!(1));
            }
            Value::Array(a) => a.push(json!(7)),
            _ => continue,
        }
        out.push(doc);
        if let Some((last, parent)) = at.split_last() {
            let mut doc = root.clone();
            match (place(&mut doc, parent), last) {
                (Value::Object(m), Value::String(k)) => drop(m.remove(k)),
                (Value::Array(a), i) => drop(a.remove(i.as_u64().unwrap() as usize)),
                _ => unreachable!(),
            }
            out.push(doc);
        }
    }
    out
}

#[test]
fn reads_as_serde_path_to_error_over_serde_json_did() {
    let docs = neighbours(&valid());
    assert!(docs.len() > 800, "{} documents", docs.len());
    let (mut oks, mut errors) = (0, 0);
    for doc in std::iter::once(valid()).chain(docs) {
        let ours = read::<Doc>(&doc).map_err(|(e, path)| format!("{path}: {e}"));
        let theirs = serde_path_to_error::deserialize::<_, Doc>(doc.clone())
            .map_err(|e| format!("{}: {}", e.path(), e.inner()));
        assert_eq!(ours, theirs, "{doc}");
        match ours {
            Ok(_) => oks += 1,
            Err(_) => errors += 1,
        }
    }
    // Both kinds of outcome are compared, many times each.
    assert!(oks > 50 && errors > 500, "{oks} read, {errors} refused");
}

#[test]
fn paths_are_written_as_serde_path_to_error_writes_them() {
    let mut doc = valid();
    doc["cells"][1][2] = json!("x");
    let (_, path) = read::<Doc>(&doc).unwrap_err();
    assert_eq!(path, "cells[1][2]");
    let mut doc = valid();
    doc["kind"] = json!({"Struct": {"at": [1, 300]}});
    assert_eq!(read::<Doc>(&doc).unwrap_err().1, "kind.Struct.at[1]");
    assert_eq!(read::<Doc>(&json!(3)).unwrap_err().1, ".");
}

/// An action's kinds, as the models declare them: externally tagged for the reader, which takes
/// the tag out of the object, and internally tagged below for serde to compare with.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
enum Act {
    Load { cells: Vec<u64>, force: f64 },
    Move(Which),
    Switch,
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
enum Internal {
    Load { cells: Vec<u64>, force: f64 },
    Move(Which),
    Switch,
}

#[derive(Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
struct Which {
    #[serde(default)]
    count: Option<u32>,
    #[serde(default)]
    cells: Option<Vec<u32>>,
}

#[test]
fn a_tagged_object_reads_as_serde_reads_it_internally_tagged_with_the_field_named() {
    let valid = [
        json!({"kind": "load", "cells": [1, 2], "force": 3.5}),
        json!({"kind": "move", "count": 2}),
        json!({"cells": [4], "kind": "move"}),
        json!({"kind": "switch"}),
    ];
    let (mut oks, mut errors, mut deeper) = (0, 0, 0);
    for doc in valid
        .iter()
        .flat_map(|v| std::iter::once(v.clone()).chain(neighbours(v)))
    {
        let Value::Object(map) = &doc else { continue };
        let mut rest = map.clone();
        let kind = rest.remove("kind");
        let rest = Value::Object(rest);
        let ours = read_tagged::<Act>("kind", kind.as_ref(), &rest);
        let theirs = serde_path_to_error::deserialize::<_, Internal>(doc.clone());
        match (ours, theirs) {
            (Ok(a), Ok(b)) => {
                let same = match (a, b) {
                    (Act::Load { cells, force }, Internal::Load { cells: c, force: f }) => {
                        cells == c && force == f
                    }
                    (Act::Move(w), Internal::Move(v)) => w == v,
                    (Act::Switch, Internal::Switch) => true,
                    _ => false,
                };
                assert!(same, "{doc}");
                oks += 1;
            }
            (Err((a, at)), Err(b)) => {
                assert_eq!(a.to_string(), b.inner().to_string(), "{doc}");
                // serde buffers the object and loses the place inside it; the reader keeps it.
                let before = b.path().to_string();
                assert!(
                    before == "." || at == before,
                    "{doc}: {at} against {before}"
                );
                deeper += usize::from(at != before);
                errors += 1;
            }
            (a, b) => panic!("{doc}: {a:?} against {b:?}"),
        }
    }
    assert!(
        oks >= 4 && errors > 100 && deeper > 20,
        "{oks} {errors} {deeper}"
    );
}
