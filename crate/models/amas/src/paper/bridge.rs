//! The bridge built in stages.

use super::*;

/// The bridge raised one row per stage: the thinnest staging, nothing of the block cut off.
const ROW_BY_ROW: &str = "bridge raised one row per stage";

/// A thinner reading of figure 33: a deck 3 thick on piers 3 wide.
const THIN_ONE: &str = "bridge, deck 3 thick on piers 3 wide, one stage";
const THIN_STAGED: &str = "bridge, deck 3 thick on piers 3 wide, staged";

pub(super) fn bridge_findings(r: &Results, out: &mut Vec<Finding>) {
    let values = |scenario: &str, metric: &str| {
        r.values("amas-bridge", &[("scenario", json!(scenario))], metric)
    };
    let stat = |scenario: &str, metric: &str| Stats::of(&values(scenario, metric));
    let single = values("amas-bridge-single", "steps");
    let staged = values("amas-bridge-staged", "steps");
    let o = Ordering::new(&staged, &single, true, Size::Any);
    let thin_o = Ordering::new(
        &values(THIN_STAGED, "steps"),
        &values(THIN_ONE, "steps"),
        true,
        Size::Any,
    );
    // The work against the bound through the final shape, which both builds end with.
    let work =
        |scenario: &str| stat(scenario, "total_steps").mean / stat(scenario, "path_bound").mean;
    let build = |scenario: &str| {
        format!(
            "{} (work {:.2} × the path bound {:.0}; relays {:.0}, collisions {:.0})",
            stat(scenario, "steps").describe(0),
            work(scenario),
            stat(scenario, "path_bound").mean,
            stat(scenario, "relays").mean,
            stat(scenario, "collisions").mean,
        )
    };
    out.push(Finding::new(
        "§6.4, fig. 33",
        "The 35×15 bridge, five robots, discrete field with module relay, ten trials: assembly \
         using disassembly and reassembly takes fewer steps than normal assembly in one stage \
         (which lets the deck overhang).",
        format!(
            "deck 5 thick on piers 5 wide: one stage {}; staged in three targets {} (modules from \
             the conveyor {:.0}, dismantled and reused {:.0}); {}. Raised one row per stage: {}. \
             Deck 3 thick on piers 3 wide: one stage {}; staged, raised by the deck's thickness \
             (five targets), {}; {}",
            build("amas-bridge-single"),
            build("amas-bridge-staged"),
            stat("amas-bridge-staged", "picked").mean,
            stat("amas-bridge-staged", "dismantled").mean,
            o.describe(),
            build(ROW_BY_ROW),
            build(THIN_ONE),
            build(THIN_STAGED),
            thin_o.describe(),
        ),
        r.rows("amas-bridge").len(),
        o.verdict(),
        "Holds if the staged bridge takes fewer steps than the one-stage bridge, significantly \
         (the deck 5 thick on piers 5 wide, three targets: a block 5 rows high, the deck raised \
         to rows 5–9 on piers, then to rows 0–4; figure 32 and figure 33 are not in the text). \
         The work of each build is set against the bound through the final shape (footnote 2 \
         with distances through the bridge), which both builds end with: the one-stage run \
         stays close to it, so its deck leaves the robots room to pass. A thinner deck on \
         narrower piers, which figure 33 could show as well, is run both ways beside it, with \
         the same staging raised by the deck's own thickness. Section 6 gives the schedule: \
         stages follow one another, and within a stage dismantled modules go straight to the \
         growth front, as in Kumiki; the staged runs lose their time in the dismantling \
         stages (crate/models/amas/README.md, interpretations 28 and 31: one-wide remnants of \
         the dismantled block raised five rows at a time, robots queueing at one end of the \
         deck raised one row at a time).",
    ));
}
