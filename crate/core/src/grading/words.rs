//! What an exercise holds a scenario to, in words a teacher reads: a locked field a scenario
//! changed (a shape as the cells removed and added, not as two texts), a goal's name the model
//! does not know, with the nearest one it does, and a student's name as a table shows it.

use serde_json::Value;

use crate::exercise::{lookup_path, Goal};

/// The most cell coordinates a shape change lists before "…".
const MAX_CELLS_LISTED: usize = 5;

/// A locked field changed from the teacher's value, in words: `robots: 5 → 7`, or for a shape
/// `target: 4 cells removed at (3, 5), (4, 5), …`.
pub fn change_text(path: &str, want: &Value, got: &Value) -> String {
    match (want, got) {
        (Value::String(a), Value::String(b)) if a.contains('\n') || b.contains('\n') => {
            format!("{path}: {}", shape_change(a, b))
        }
        (want, Value::Null) => format!("{path}: {want} → left out"),
        _ => format!("{path}: {want} → {got}"),
    }
}

/// The cells of a shape's text by position: (column, row, layer), counted from 0 at the text's
/// top left (layers, separated by `---`, from the ground up), and the character there. Hex rows
/// separate their cells with spaces, so a column is a cell's place in its row, not a character's.
fn cells(text: &str) -> Vec<((usize, usize, usize), char)> {
    let mut out = Vec::new();
    for (layer, block) in text.split("\n---").enumerate() {
        let rows = block.lines().filter(|l| l.trim() != "---");
        for (row, line) in rows.filter(|l| !l.trim().is_empty()).enumerate() {
            let line = line.trim_end();
            let marks: Vec<char> = match line.contains(' ') {
                true => line
                    .split_whitespace()
                    .filter_map(|t| t.chars().next())
                    .collect(),
                false => line.chars().collect(),
            };
            for (column, c) in marks.into_iter().enumerate() {
                out.push(((column, row, layer), c));
            }
        }
    }
    out
}

/// How shape `b` differs from shape `a`: cells removed, added, and changed in kind.
pub fn shape_change(a: &str, b: &str) -> String {
    use std::collections::BTreeMap;
    let layered = a.contains("\n---") || b.contains("\n---");
    let (a, b): (BTreeMap<_, _>, BTreeMap<_, _>) = (
        cells(a).into_iter().collect(),
        cells(b).into_iter().collect(),
    );
    let filled =
        |m: &BTreeMap<(usize, usize, usize), char>, at| m.get(at).is_some_and(|&c| c != '.');
    let mut places: Vec<&(usize, usize, usize)> = a.keys().chain(b.keys()).collect();
    // Reading order: layer, row, column.
    kumiki_model::sort::sort_by_key(&mut places, |&&(c, r, l)| (l, r, c));
    places.dedup();
    let (mut removed, mut added, mut changed) = (Vec::new(), Vec::new(), Vec::new());
    for at in places {
        match (filled(&a, at), filled(&b, at)) {
            (true, false) => removed.push(*at),
            (false, true) => added.push(*at),
            (true, true) if a.get(at) != b.get(at) => changed.push(*at),
            _ => {}
        }
    }
    let list = |what: &str, at: &[(usize, usize, usize)]| {
        let shown: Vec<String> = at
            .iter()
            .take(MAX_CELLS_LISTED)
            .map(|&(c, r, l)| match layered {
                true => format!("({c}, {r}, {l})"),
                false => format!("({c}, {r})"),
            })
            .collect();
        let more = if at.len() > MAX_CELLS_LISTED {
            ", …"
        } else {
            ""
        };
        let cells = if at.len() == 1 { "cell" } else { "cells" };
        format!("{} {cells} {what} at {}{more}", at.len(), shown.join(", "))
    };
    let parts: Vec<String> = [
        ("removed", &removed),
        ("added", &added),
        ("changed", &changed),
    ]
    .into_iter()
    .filter(|(_, at)| !at.is_empty())
    .map(|(what, at)| list(what, at))
    .collect();
    match parts.is_empty() {
        true => "the same cells, written differently".into(),
        false => parts.join("; "),
    }
}

/// The first name in `goal` that `metrics` (the model's metric names) or `doc` (the scenario)
/// does not have, with the nearest known name when one is close: the teacher's editor says so as
/// they type.
pub fn unknown_name(goal: &Goal, metrics: &[String], doc: &Value) -> Option<String> {
    for name in goal.names() {
        if let Some(metric) = name.strip_prefix("metrics.") {
            if !metrics.iter().any(|m| m == metric) {
                let near = nearest(metric, metrics.iter().map(String::as_str));
                return Some(format!(
                    "this model has no metric '{metric}'{}",
                    suggestion("metrics.", near)
                ));
            }
        } else if let Some(path) = name.strip_prefix("scenario.") {
            match lookup_path(doc, path) {
                Some(Value::Number(_) | Value::Bool(_)) => {}
                Some(_) => {
                    return Some(format!(
                        "the scenario's '{path}' is neither a number nor true/false"
                    ))
                }
                None => {
                    let keys = doc
                        .as_object()
                        .map(|m| m.keys().map(String::as_str).collect::<Vec<_>>())
                        .unwrap_or_default();
                    let near = nearest(path, keys.into_iter());
                    return Some(format!(
                        "the scenario has no field '{path}'{}",
                        suggestion("scenario.", near)
                    ));
                }
            }
        }
    }
    None
}

fn suggestion(prefix: &str, near: Option<&str>) -> String {
    near.map(|n| format!("; did you mean '{prefix}{n}'?"))
        .unwrap_or_else(|| match prefix {
            "metrics." => "; the metrics are listed under the view".into(),
            _ => String::new(),
        })
}

/// The candidate closest to `word` by edit distance, when it is within a third of its length
/// (at least 1, at most 3 edits).
fn nearest<'a>(word: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    crate::error::nearest_within(word, candidates, (word.chars().count() / 3).clamp(1, 3))
}

/// A student's name as one line of a table or a terminal shows it: control characters and
/// bidirectional overrides and isolates dropped (a name with a right-to-left override cannot make
/// `Ali\u{202e}gnp.exe` read "Aliexe.png"), cut to `max` characters with "…", and "(no name)"
/// when nothing is left. The full name stays in the grade's data.
pub fn shown_name(name: &str, max: usize) -> String {
    let clean: String = name
        .chars()
        .map(|c| if c.is_whitespace() { ' ' } else { c })
        .filter(|&c| !c.is_control() && !is_bidi_control(c))
        .collect();
    let clean = clean.trim();
    match clean.chars().count() {
        0 => "(no name)".into(),
        n if n > max => format!(
            "{}…",
            clean
                .chars()
                .take(max.saturating_sub(1))
                .collect::<String>()
                .trim_end()
        ),
        _ => clean.to_string(),
    }
}

/// The characters that change the direction of text around them: embeddings, overrides,
/// isolates and marks.
fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{200e}' | '\u{200f}' | '\u{061c}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_shape_change_lists_the_cells_removed_and_added_capped() {
        let a = "####....\n####....\n########\n";
        let b = "####....\n##......\n#####...\n";
        assert_eq!(
            shape_change(a, b),
            "5 cells removed at (2, 1), (3, 1), (5, 2), (6, 2), (7, 2)"
        );
        let c = "########\n####....\n########\n";
        assert_eq!(
            shape_change(a, c),
            "4 cells added at (4, 0), (5, 0), (6, 0), (7, 0)"
        );
        let many = "........\n........\n........\n";
        assert_eq!(
            shape_change(a, many),
            "16 cells removed at (0, 0), (1, 0), (2, 0), (3, 0), (0, 1), …"
        );
        assert_eq!(shape_change(a, a), "the same cells, written differently");
    }

    #[test]
    fn hex_rows_count_cells_and_layers_count_from_the_ground() {
        let hex = "# # #\n # # #\n";
        let hex2 = "# . #\n # # #\n";
        assert_eq!(shape_change(hex, hex2), "1 cell removed at (1, 0)");
        let cube = "##\n##\n---\n##\n##\n";
        let cube2 = "##\n##\n---\n##\n#.\n";
        assert_eq!(shape_change(cube, cube2), "1 cell removed at (1, 1, 1)");
    }

    #[test]
    fn change_texts_name_the_field_and_the_teachers_value_first() {
        assert_eq!(change_text("robots", &json!(5), &json!(7)), "robots: 5 → 7");
        assert_eq!(
            change_text("target", &json!("##\n"), &json!("#.\n")),
            "target: 1 cell removed at (1, 0)"
        );
        assert_eq!(
            change_text("seed", &json!(1), &Value::Null),
            "seed: 1 → left out"
        );
    }

    #[test]
    fn names_are_shown_without_direction_tricks_and_cut() {
        assert_eq!(shown_name("Ali\u{202e}gnp.exe", 40), "Alignp.exe");
        assert_eq!(shown_name("  \u{2067}\u{2069} ", 40), "(no name)");
        assert_eq!(shown_name("Ada\nLovelace", 40), "Ada Lovelace");
        assert_eq!(
            shown_name(&"x".repeat(100_000), 10),
            format!("{}…", "x".repeat(9))
        );
    }

    #[test]
    fn misspelt_names_are_found_with_a_suggestion() {
        let metrics = vec!["collisions".to_string(), "placed".to_string()];
        let doc = json!({"robots": 5, "field": "continuous"});
        let goal = |t: &str| Goal::parse(t).unwrap();
        assert_eq!(
            unknown_name(
                &goal("completed and metrics.collisions < 40"),
                &metrics,
                &doc
            ),
            None
        );
        assert_eq!(
            unknown_name(&goal("metrics.colisions < 40"), &metrics, &doc).unwrap(),
            "this model has no metric 'colisions'; did you mean 'metrics.collisions'?"
        );
        assert_eq!(
            unknown_name(&goal("metrics.speed < 4"), &metrics, &doc).unwrap(),
            "this model has no metric 'speed'; the metrics are listed under the view"
        );
        assert_eq!(
            unknown_name(&goal("scenario.robot <= 6"), &metrics, &doc).unwrap(),
            "the scenario has no field 'robot'; did you mean 'scenario.robots'?"
        );
        assert_eq!(
            unknown_name(&goal("scenario.field == 1"), &metrics, &doc).unwrap(),
            "the scenario's 'field' is neither a number nor true/false"
        );
    }
}
