//! Every registered model's documentation, found through the registry: its page, the `README.md`
//! of its crate, in ODD form, and its row in the README's table of models.

use std::path::Path;

use super::MODELS;

/// The repository's root, two folders above the core's crate.
fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// The sections of the ODD form (Grimm et al.) every model page has, with the interpretations
/// made where its paper is silent.
const SECTIONS: [&str; 8] = [
    "## Purpose",
    "## Entities, state variables and scales",
    "## Process overview and scheduling",
    "## Stochasticity",
    "## Initialisation",
    "## Input",
    "## Submodels",
    "## Interpretations",
];

#[test]
fn every_model_has_its_page_in_odd_form_and_its_readme_row() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    for m in MODELS {
        let page = format!("crate/models/{}/README.md", m.name);
        let text = std::fs::read_to_string(root().join(&page))
            .unwrap_or_else(|e| panic!("{}: {page} is its documentation: {e}", m.name));
        let mut from = 0;
        for section in SECTIONS {
            let at = text[from..]
                .lines()
                .position(|l| l == section)
                .unwrap_or_else(|| panic!("{page}: no '{section}' after the sections before it"));
            from += text[from..]
                .lines()
                .take(at + 1)
                .map(|l| l.len() + 1)
                .sum::<usize>();
        }
        let row = format!("| `{}` |", m.name);
        assert!(
            readme
                .lines()
                .any(|l| l.starts_with(&row) && l.contains(&format!("]({page})"))),
            "README.md: the table of models has no row for {} linking {page}",
            m.name
        );
    }
}
