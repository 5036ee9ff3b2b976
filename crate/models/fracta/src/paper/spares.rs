//! Section 3.3's spares: where figure 5's spare sits (the figure is not in the text), run both
//! ways, and "up to three spares".

use super::*;

/// The depth of the breadth-first search of the fewest repair motions.
const SEARCH_LIMIT: usize = 6;

/// The ten positions a fault is given to.
const UNITS: [u64; 10] = [0, 1, 2, 3, 4, 6, 7, 8, 9, 10];

pub(super) fn findings(r: &Results) -> Vec<Finding> {
    vec![place(r), three(r)]
}

/// One reading's figures: assembly, repair, the fewest motions per position.
fn figures(r: &Results, spare: Spare) -> String {
    let asm = scenario(spare.assembly());
    let done = r.values("fracta-assembly", &asm, "completed");
    let steps = r.stats("fracta-assembly", &asm, "convergence_steps");
    let rep = scenario(spare.repair());
    let repaired = r.values("fracta-repair", &rep, "completed");
    let repair = r.stats("fracta-repair", &rep, "repair_steps");
    let fewest: Vec<Option<usize>> = UNITS
        .iter()
        .map(|&u| search::fewest_repair_motions(spare, u, SEARCH_LIMIT))
        .collect();
    let medians: Vec<String> = UNITS
        .iter()
        .map(|&u| {
            let filter = [
                ("scenario", json!(spare.repair())),
                ("disturbances.0.unit", json!(u)),
            ];
            fmt(r.stats("fracta-repair", &filter, "repair_steps").median, 0)
        })
        .collect();
    let known: Vec<f64> = fewest.iter().flatten().map(|&n| n as f64).collect();
    format!(
        "assembly {} (median {} steps, mean {}); repair {} (median {}, mean {}; medians by \
         faulty unit 0–10 without 5: {}); fewest motions to repair each position {} (mean {})",
        ratio(&done),
        fmt(steps.median, 0),
        fmt(steps.mean, 1),
        ratio(&repaired),
        fmt(repair.median, 0),
        fmt(repair.mean, 1),
        medians.join(", "),
        fewest
            .iter()
            .map(|f| f.map_or("?".into(), |n| n.to_string()))
            .collect::<Vec<_>>()
            .join(", "),
        if known.len() == UNITS.len() {
            fmt(known.iter().sum::<f64>() / known.len() as f64, 1)
        } else {
            "n/a".into()
        }
    )
}

fn place(r: &Results) -> Finding {
    let [edge, corner] = Spare::BOTH.map(|s| figures(r, s));
    let runs = r.rows("fracta-assembly").len() + r.rows("fracta-repair").len();
    Finding::new(
        "§3.3, fig. 5",
        "Figure 5 gives the triangle first priority and the shape with a spare unit second; \
         the figure is not in the text, so where the spare sits is read from the text.",
        format!("spare in the middle of an edge: {edge}. Beside a corner: {corner}"),
        runs,
        Verdict::NotStated,
        "Both readings' statements are derived from their shapes (`kumiki query fracta derive`), \
         and for each the triangle with its spare is the only 11-cell polyhex in which every \
         unit matches a statement (an enumeration of all 1 716 033, in the tests). The text \
         favours the middle of an edge: 3.3 says \"up to three spares can be included by \
         slightly modifying the description\", and a triangle has three places in the middle \
         of an edge, one per edge, where beside its corners it has six, which would hold up to \
         six. Figure 4's words (\"all the movable type o units have the difference 0 with \
         proper neighbors {K, K}\") fit one 11-unit shape under either reading, and section \
         4's one experiment a position fits both. So Kumiki's presets put the spare in the \
         middle of an edge (crate/models/fracta/README.md, interpretation 15), and the rows \
         of this section are that reading's; the corner's runs are beside them here and in \
         the repair summary. The fewest motions are a breadth-first search over the model's \
         own motions from the 10 units a cut-off leaves.",
    )
}

fn three(r: &Results) -> Finding {
    let [edge, corner] = [
        "fracta-triangle10-3spares",
        "fracta-triangle10-3spares-corner",
    ]
    .map(|name| {
        let f = scenario(name);
        (
            r.values("fracta-spares", &f, "completed"),
            r.stats("fracta-spares", &f, "convergence_steps"),
        )
    });
    Finding::new(
        "§3.3",
        "Up to three spares can be included by slightly modifying the description.",
        format!(
            "a spare in the middle of each edge: {} assembled, {} steps; a spare beside each \
             corner: {} assembled, {} steps",
            ratio(&edge.0),
            edge.1.describe(0),
            ratio(&corner.0),
            corner.1.describe(0)
        ),
        edge.0.len() + corner.0.len(),
        Verdict::of_most(count(&edge.0), edge.0.len()),
        &format!(
            "fracta-spares: 13 units from two lines of 7 and 6, 100 seeds each, capped at \
             10 000 steps. The description is the triangle's, then the statements each further \
             spare adds (priorities 2 to 4, derived from the shapes). The text says three \
             spares can be included, so the verdict asks that most runs assemble with three. \
             Edge: {} Corner: {}",
            failures(r, "fracta-spares", &scenario("fracta-triangle10-3spares")),
            failures(
                r,
                "fracta-spares",
                &scenario("fracta-triangle10-3spares-corner")
            )
        ),
    )
}
