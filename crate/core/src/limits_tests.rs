//! The limits ([`kumiki_model::limits`], re-exported as [`crate::limits`], and each model's own,
//! found through the registry) at work on whole scenarios, read under the page's and the large
//! limits, and as the table the documentation gives.

use crate::limits::Limits;
use crate::presets;
use serde_json::{json, Value};

/// `preset` with `key` set to `value`, read under the page's limits and under the large
/// ones: the page's error, and whether the large limits accept it.
fn under_both(preset: &str, key: &str, value: Value) -> (String, bool) {
    let mut doc = presets::scenario(preset).unwrap().to_value();
    doc[key] = value;
    let page = crate::Scenario::from_value_within(doc.clone(), &Limits::PAGE)
        .expect_err("over the page's limit")
        .to_string();
    let large = crate::Scenario::from_value_within(doc, &Limits::LARGE);
    (page, large.is_ok())
}

#[test]
fn an_amas_target_wider_than_the_page_allows_is_refused_by_size_and_limit() {
    let wide = format!("{}\n", "#".repeat(5000));
    let (page, large) = under_both("amas-L", "target", json!(wide));
    assert_eq!(
        page,
        "target: 5000×2 cells (with the supply rows) exceeds the limit of 4096×4096"
    );
    assert!(large);
}

#[test]
fn a_chobie_world_wider_than_the_page_allows_is_refused_by_size_and_limit() {
    let world = format!("{}\n{}\n", "#".repeat(3000), "=".repeat(3000));
    let (page, large) = under_both("chobie-crawl3", "world", json!(world));
    assert_eq!(
        page,
        "world: the world is 3000×2 cells (extend included); at most 2048 a side"
    );
    assert!(large);
}

#[test]
fn a_cubes3d_space_larger_than_the_page_allows_is_refused_by_size_and_limit() {
    let mut doc = presets::scenario("cubes-box12-ladder").unwrap().to_value();
    doc["shape"] = json!(format!("{}\n", "#".repeat(600)));
    doc["targets"] = json!([{"shape": format!("{}\n", "#".repeat(600))}]);
    let page = crate::Scenario::from_value_within(doc.clone(), &Limits::PAGE)
        .unwrap_err()
        .to_string();
    assert!(
        page.starts_with("shape: the space the shapes need with margin")
            && page.contains("(620×")
            && page.ends_with("exceeds the limit of 512 per side and 4194304 cells"),
        "{page}"
    );
    assert!(crate::Scenario::from_value_within(doc, &Limits::LARGE).is_ok());
}

#[test]
fn a_fracta_start_wider_than_the_page_allows_is_refused_by_size_and_limit() {
    let row = "# ".repeat(1100);
    let (page, large) = under_both("fracta-triangle10", "start", json!(row));
    assert!(
        page.starts_with("start: 11")
            && page.ends_with("cells with the margin exceeds the limit of 1024×1024"),
        "{page}"
    );
    assert!(large);
}

#[test]
fn a_scenario_keeps_its_limits_through_overrides() {
    let large = presets::scenario("amas-L")
        .unwrap()
        .with_limits(&Limits::LARGE)
        .unwrap();
    let wide = json!(format!("{}\n", "#".repeat(5000)));
    assert!(large.with_override("target", wide.clone()).is_ok());
    let page = presets::scenario("amas-L").unwrap();
    assert!(page.with_override("target", wide).is_err());
}

#[test]
fn the_table_has_a_row_for_every_limit() {
    // Each model's test checks that its rows read every field of its limits (every_limit_has_a_row);
    // the table holds the shared bound and every row of every registered model, in registry order.
    let table = crate::models::limits_markdown();
    let mut want = vec!["every".to_string()];
    for m in crate::models::MODELS {
        assert!(
            !m.limits.lines().is_empty(),
            "{} declares no limits",
            m.name
        );
        want.extend(m.limits.lines().iter().map(|_| format!("`{}`", m.name)));
    }
    let models: Vec<String> = table
        .lines()
        .skip(2)
        .map(|l| {
            l.split(" | ")
                .next()
                .unwrap()
                .trim_start_matches("| ")
                .to_string()
        })
        .collect();
    assert_eq!(models, want);
}

#[test]
fn the_table_writes_powers_of_two_and_groups_thousands() {
    let table = crate::models::limits_markdown();
    assert!(table.contains("| every | cells a shape text spans (width × height × layers; rows padded to the widest) | 2^24 | 2^28 |"), "{table}");
    assert!(
        table.contains("| `chobie` | robots | 5000 | 50 000 |"),
        "{table}"
    );
    assert!(
        table.contains("| `cubes3d` | units | 100 000 | 1 000 000 |"),
        "{table}"
    );
}

#[test]
fn large_allows_at_least_what_the_page_allows() {
    let shared = crate::limits::TableLine::shape_cells();
    let lines = crate::models::MODELS.iter().flat_map(|m| m.limits.lines());
    for line in std::iter::once(shared).chain(lines) {
        assert!(line.large >= line.page, "{}", line.what);
    }
}
