//! Helper calls for editors and the CLI: the crawl forms of figure 7, reconstructed, and the world
//! text split into the two layers the page paints (robots, terrain) and merged back.

use serde_json::{json, Value};

use kumiki_model::error::{Error, Result};

/// The largest crawl drawn by the query.
pub const MAX_CRAWL: u64 = 4001;

/// The world text of crawl form `form` (1 to 4) for `robots` = 2k + 1 robots: form 1 is a lower
/// tier of k + 1 robots with k robots on its left above; each form's single leader turns it into
/// the next, and form 4 turns into form 1 one cell to the right.
pub fn crawl_world(robots: u64, form: u64, margin: u64) -> String {
    let k = (robots - 1) / 2;
    // (upper tier start, upper length, lower tier start, lower length) per form.
    let (us, ul, ls, ll) = match form {
        1 => (0, k, 0, k + 1),
        2 => (1, k, 0, k + 1),
        3 => (0, k + 1, 1, k),
        _ => (1, k + 1, 1, k),
    };
    let w = (k + 2 + margin) as usize;
    let row = |start: u64, len: u64| {
        let mut s = String::with_capacity(w);
        for x in 0..w as u64 {
            s.push(if x >= start && x < start + len {
                '#'
            } else {
                '.'
            });
        }
        s
    };
    format!(
        "{}\n{}\n{}\n{}\n",
        ".".repeat(w),
        row(us, ul),
        row(ls, ll),
        "=".repeat(w)
    )
}

/// `{"robots": n, "form": f, "margin": m}` → `{"world": text}`.
pub fn crawl(args: &Value) -> Result<Value> {
    let n = args
        .get("robots")
        .and_then(Value::as_u64)
        .ok_or_else(|| Error::field("robots", "give the number of robots, an odd number ≥ 3"))?;
    if n < 3 || n % 2 == 0 || n > MAX_CRAWL {
        return Err(Error::field(
            "robots",
            format!("the crawl forms need an odd number of robots from 3 to {MAX_CRAWL}"),
        ));
    }
    let form = args.get("form").map_or(Some(1), Value::as_u64).unwrap_or(0);
    if !(1..=4).contains(&form) {
        return Err(Error::field("form", "a crawl form is 1, 2, 3 or 4"));
    }
    let margin = args
        .get("margin")
        .map_or(Some(10), Value::as_u64)
        .unwrap_or(u64::MAX);
    if margin > 1000 {
        return Err(Error::field("margin", "from 0 to 1000 empty columns"));
    }
    Ok(json!({ "world": crawl_world(n, form, margin) }))
}

/// The text of a string argument.
fn text<'a>(args: &'a Value, key: &str) -> Result<&'a str> {
    args.get(key)
        .and_then(Value::as_str)
        .ok_or_else(|| Error::field(key, "give it as text"))
}

/// The lines of a text as the page's painters read it: a final newline ends the last line rather
/// than starting an empty one.
fn lines(text: &str) -> Vec<&str> {
    text.strip_suffix('\n')
        .unwrap_or(text)
        .split('\n')
        .collect()
}

/// `{"world": text}` → `{"robots": shape, "terrain": shape}`: the world's robots (`#`) and its
/// terrain (`=`) each as a square shape, `#` where the layer has something and `.` elsewhere,
/// aligned at the top-left as the world is. Any text is split, a world that would not run too.
pub fn layers(args: &Value) -> Result<Value> {
    let world = lines(text(args, "world")?);
    let layer = |mark: char| -> String {
        let rows: Vec<String> = world
            .iter()
            .map(|line| {
                line.chars()
                    .map(|c| if c == mark { '#' } else { '.' })
                    .collect()
            })
            .collect();
        rows.join("\n")
    };
    Ok(json!({ "robots": layer('#'), "terrain": layer('=') }))
}

/// `{"robots": shape, "terrain": shape}` → `{"world": text}`: the two layers, aligned at the
/// top-left, merged into world text (`#` a robot, `=` terrain, `.` empty). A cell that is both a
/// robot and terrain is refused by its row and column.
pub fn merge(args: &Value) -> Result<Value> {
    let robots = lines(text(args, "robots")?);
    let terrain = lines(text(args, "terrain")?);
    let mut rows = Vec::with_capacity(robots.len().max(terrain.len()));
    for y in 0..robots.len().max(terrain.len()) {
        let a: Vec<char> = robots.get(y).map_or(Vec::new(), |l| l.chars().collect());
        let b: Vec<char> = terrain.get(y).map_or(Vec::new(), |l| l.chars().collect());
        let mut row = String::with_capacity(a.len().max(b.len()));
        for x in 0..a.len().max(b.len()) {
            let robot = a.get(x) == Some(&'#');
            let ground = b.get(x) == Some(&'#');
            if robot && ground {
                return Err(Error::field(
                    "",
                    format!(
                        "row {}, column {} is both a robot and terrain",
                        y + 1,
                        x + 1
                    ),
                ));
            }
            row.push(match (robot, ground) {
                (true, _) => '#',
                (_, true) => '=',
                _ => '.',
            });
        }
        rows.push(row);
    }
    Ok(json!({ "world": format!("{}\n", rows.join("\n").trim_end_matches('\n')) }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use kumiki_core::presets;

    /// Every preset's world splits into its two layers and merges back into the same text.
    #[test]
    fn worlds_split_into_layers_and_merge_back() {
        let mut seen = 0;
        for name in presets::names() {
            let doc = presets::scenario(name).unwrap().to_value();
            let Some(world) = doc.get("world").and_then(Value::as_str) else {
                continue;
            };
            let parts = layers(&json!({ "world": world })).unwrap();
            assert!(!parts["robots"].as_str().unwrap().contains('='), "{name}");
            let merged = merge(&parts).unwrap();
            assert_eq!(merged["world"], world, "{name}");
            seen += 1;
        }
        assert!(seen > 0, "no preset has a world");
        let parts = layers(&json!({"world": ".#.\n===\n"})).unwrap();
        assert_eq!(parts, json!({"robots": ".#.\n...", "terrain": "...\n###"}));
    }

    /// A cell painted in both layers is refused by its row and column; ragged layers align at
    /// the top-left.
    #[test]
    fn a_cell_in_both_layers_is_refused_where_it_is() {
        let clash = merge(&json!({"robots": "..\n.#", "terrain": "..\n##"})).unwrap_err();
        assert_eq!(
            clash.to_string(),
            "row 2, column 2 is both a robot and terrain"
        );
        let merged = merge(&json!({"robots": "#", "terrain": ".\n###\n"})).unwrap();
        assert_eq!(merged["world"], "#\n===\n");
        assert!(merge(&json!({"robots": "#"})).is_err());
    }
}
