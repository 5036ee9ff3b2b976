//! The tables of models and lessons in hand-written pages, written from the registry by `kumiki
//! schema` (see [`super::spliced`]).

use crate::error::{Error, Result};
use crate::models::{MODELS, PAPERS};
use crate::presets;
use crate::run::Run;

/// The README's table of models: each model in gallery order, its paper's citation with the
/// quoted titles in italics, the lattice its first preset lays out, and its page, the `README.md`
/// of its crate.
pub fn models_markdown() -> Result<String> {
    let mut out =
        String::from("| model | paper | lattice | documentation |\n| --- | --- | --- | --- |\n");
    for (m, paper) in MODELS.iter().zip(PAPERS) {
        let preset = presets::names()
            .find(|n| presets::scenario(n).is_ok_and(|s| s.model() == m.name))
            .ok_or_else(|| Error::field("model", format!("model '{}' has no preset", m.name)))?;
        let lattice = Run::new(presets::scenario(preset)?)?
            .model()
            .layout()
            .lattice;
        let lattice = serde_json::to_value(lattice).map_err(|e| Error::json(&e))?;
        let page = format!("crate/models/{}/README.md", m.name);
        out.push_str(&format!(
            "| `{}` | {} | {} | [{page}]({page}) |\n",
            m.name,
            italic_titles(paper.citation),
            lattice.as_str().unwrap_or_default(),
        ));
    }
    Ok(out)
}

/// A citation with each quoted title (`"..."`) in italics (`*...*`).
fn italic_titles(citation: &str) -> String {
    citation
        .split('"')
        .enumerate()
        .map(|(i, part)| match i % 2 {
            1 => format!("*{part}*"),
            _ => part.to_string(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn titles_in_quotes_are_set_in_italics() {
        assert_eq!(
            italic_titles("A. B and C. D, \"One\"; and section 2 of E, \"Two\", 1999"),
            "A. B and C. D, *One*; and section 2 of E, *Two*, 1999"
        );
    }

    /// Each paper's citation names its title in quotes, as the table sets it in italics.
    #[test]
    fn every_citation_quotes_its_title() {
        for paper in PAPERS {
            assert!(
                paper.citation.matches('"').count() >= 2
                    && paper.citation.matches('"').count() % 2 == 0,
                "{}: its citation quotes its title: {}",
                paper.model,
                paper.citation
            );
        }
    }
}
