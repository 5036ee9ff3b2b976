//! Section 6: the motion toward the light (figures 13 and 14), under the readings the text leaves
//! open: the ground plane, the light's priority and the clock of equation 8.

use serde_json::{json, Value};

use kumiki_model::report::{self, Finding, Ordering, Results, Size, Stats, Verdict};

use super::{figures, traced_values};

/// The length of the runs.
const END: u64 = 1000;
/// The window the displacement is reported per.
const WINDOW: u64 = 100;

/// The motion of the runs of one condition.
struct Motion {
    /// Each run's displacement at the end, and their statistics.
    ends: Vec<f64>,
    end: Stats,
    /// Mean gain in each hundred-step window.
    per_window: Vec<f64>,
    /// Each run's gain in the first and the second half.
    first: Vec<f64>,
    second: Vec<f64>,
    /// Runs that end nearer the light than they began.
    ahead: usize,
    toward: f64,
    away: f64,
    moves: f64,
    switches: f64,
}

fn motion(results: &Results, exp: &str, filter: &[(&str, Value)]) -> Motion {
    let at = |step: u64| traced_values(results, exp, filter, "displacement", step);
    let mean = |v: &[f64]| Stats::of(v).mean;
    let gain = |a: &[f64], b: &[f64]| -> Vec<f64> { b.iter().zip(a).map(|(b, a)| b - a).collect() };
    let points: Vec<Vec<f64>> = (0..=END / WINDOW).map(|k| at(k * WINDOW)).collect();
    let per_window = points
        .windows(2)
        .map(|w| mean(&gain(&w[0], &w[1])))
        .collect();
    let (start, half, end) = (at(0), at(END / 2), at(END));
    let per_run = |metric: &str| results.stats(exp, filter, metric).mean;
    Motion {
        end: Stats::of(&end),
        per_window,
        first: gain(&start, &half),
        second: gain(&half, &end),
        ahead: end.iter().filter(|&&d| d > 0.0).count(),
        ends: end,
        toward: per_run("moves_toward"),
        away: per_run("moves_away"),
        moves: per_run("moves"),
        switches: per_run("switches"),
    }
}

impl Motion {
    /// The second half's gain against the first's: a decline claimed, of at least medium size.
    fn decline(&self) -> Ordering {
        Ordering::new(&self.first, &self.second, false, Size::Medium)
    }

    /// "A consistent motion to the source": every run ends nearer the light, every hundred-step
    /// window gains on average, and the second half gains not less than the first by a
    /// significant effect of medium size or more. Differs when at most half the runs end nearer
    /// the light or still move toward it in the second half (the motion stops); partial
    /// otherwise.
    fn consistent(&self) -> Verdict {
        let n = self.end.n;
        let moving = self.second.iter().filter(|&&g| g > 0.0).count();
        let steady = self.per_window.iter().all(|&g| g > 0.0) && !self.declines();
        match (Verdict::of_all(self.ahead, n), Verdict::of_most(moving, n)) {
            (Verdict::Holds, Verdict::Holds) if steady => Verdict::Holds,
            (Verdict::Differs, _) | (_, Verdict::Differs | Verdict::Partial) => Verdict::Differs,
            _ => Verdict::Partial,
        }
    }

    /// Whether the second half gains less than the first by a significant effect of medium
    /// size or more.
    fn declines(&self) -> bool {
        self.decline().verdict() == Verdict::Holds
    }

    /// The figures of a row.
    fn describe(&self) -> String {
        let windows: Vec<String> = self.per_window.iter().map(|g| report::fmt(*g, 2)).collect();
        format!(
            "centre of mass along the light after {END} steps: {}; {}/{} runs end nearer the light, {} still move toward it in the second half; gain per hundred steps: {}; first half {}, second half {} ({}: {}); per run {} moves toward the light, {} away, {} across; {} target switches per run",
            self.end.describe(2),
            self.ahead,
            self.end.n,
            self.second.iter().filter(|&&g| g > 0.0).count(),
            windows.join(", "),
            Stats::of(&self.first).short(2),
            Stats::of(&self.second).short(2),
            figures(&self.decline()),
            if self.declines() { "a decline of medium size or more" } else { "no decline of medium size or more" },
            report::fmt(self.toward, 0),
            report::fmt(self.away, 0),
            report::fmt(self.moves - self.toward - self.away, 0),
            report::fmt(self.switches, 0),
        )
    }
}

const CONSISTENT: &str = "Holds when every run ends nearer the light, every hundred-step window gains on average, and the second half of the run gains not less than the first by a significant effect of medium size or more (Cohen's d ≥ 0.5 and rank-biserial ≥ 0.3, Mann-Whitney U on the runs' gains): \"consistent\" read as steady, a small slowing allowed. Differs when at most half the runs end nearer the light or still gain in the second half (the motion stops); partial in between. Each move toward the light takes the centre of mass an eighth of a cell nearer.";

pub(super) fn findings(results: &Results) -> Vec<Finding> {
    let fig14 = |ground: &str| motion(results, "cubes-fig14", &[("ground", json!(ground))]);
    let reading = |clock: &str, priority: &str| {
        motion(
            results,
            "cubes-light-readings",
            &[("clock", json!(clock)), ("priority", json!(priority))],
        )
    };
    let (anchor, fixed) = (fig14("anchor"), fig14("fixed"));
    let frozen = results
        .values("cubes-fig14", &[("ground", json!("fixed"))], "movable")
        .iter()
        .filter(|&&v| v == 0.0)
        .count();
    let run_clock = reading("run", "positions");
    let (on_units, none) = (reading("target", "units"), reading("target", "none"));
    let preset = reading("target", "positions");
    let clocks = Ordering::new(&preset.ends, &run_clock.ends, false, Size::Any);
    let over_none = Ordering::new(&preset.ends, &none.ends, false, Size::Large);
    let over_units = Ordering::new(&preset.ends, &on_units.ends, false, Size::Any);
    vec![
        Finding {
            section: "§6, figs. 13 and 14".into(),
            claim: "\"The group of units makes a consistent motion to the source\" (ground read as 'anchor': the plane holds the units touching it like a bond, let go when a unit is carried away, and the structure stays fixed to it).".into(),
            kumiki: anchor.describe(),
            runs: anchor.end.n,
            verdict: anchor.consistent(),
            note: format!("{CONSISTENT} The preset's readings: the light's priority on each unit's reachable positions, and each unit's clock of equation 8 restarting when it switches target (crate/models/cubes3d/README.md, interpretations 11, 15 and 18)."),
        },
        Finding {
            section: "§6, figs. 13 and 14".into(),
            claim: "\"The group of units makes a consistent motion to the source\" (ground read as 'fixed': units touching the plane never move).".into(),
            kumiki: format!("{}; no unit may move at step {END} in {frozen}/{} runs", fixed.describe(), fixed.end.n),
            runs: fixed.end.n,
            verdict: fixed.consistent(),
            note: format!("{CONSISTENT} Read so, every unit that comes down to the plane is fixed for good, the back units of the cube's bottom layer never leave, and the structure freezes once its upper units have come down. The text rules this reading out: for units that may not move it says \"set non-movable\" (the four lit units when the target switches to the ladder), and two of those four touch the plane, so they would be non-movable already; \"fixed to it by some connecting mechanism\" names a connection. See crate/models/cubes3d/README.md, interpretation 15."),
        },
        Finding {
            section: "§6 with §4.2, eq. 8".into(),
            claim: "\"The group of units makes a consistent motion to the source\", with T of equation 8 on one clock for the whole run (not reset when a unit switches target; the reading of model version 4).".into(),
            kumiki: format!("{}; with the clock restarting at each switch (the preset) the structure ends farther toward the light, {} against {} ({})", run_clock.describe(), preset.end.short(2), run_clock.end.short(2), figures(&clocks)),
            runs: run_clock.end.n,
            verdict: run_clock.consistent(),
            note: format!("{CONSISTENT} Section 6 has each unit run \"the self-reconfiguration process (i)–(iii) described in Section 4 with the current target structure\", a new problem at each switch, and the model restarts each unit's clock when it switches (the preset). On one clock T falls to C / ln 1001 = 0.72 by step 1000 and the motion slows as the structure cools; the runs of cubes-light-readings, the priority on positions."),
        },
        Finding {
            section: "§6".into(),
            claim: "\"The units assign a higher moving priority to reachable positions approaching the light source such that the whole structure can move toward the light source.\"".into(),
            kumiki: format!(
                "displacement after {END} steps with the priority on each unit's positions {}, without a priority {} ({}); with the priority on which unit's chosen move goes first (model version 4) {} (positions against units: {})",
                preset.end.short(2),
                none.end.short(2),
                over_none.describe(),
                on_units.end.short(2),
                figures(&over_units),
            ),
            runs: preset.end.n + none.end.n + on_units.end.n,
            verdict: over_none.verdict(),
            note: "A unit that can reach a position nearer the light chooses by its rule among staying and those positions only; one that cannot chooses among all its positions (crate/models/cubes3d/README.md, interpretation 18). Holds when the structure moves farther with the priority than without it by a large effect; without it the light only holds the four lit units at the switch to the ladder. The clock restarts at each switch in all three; the runs of cubes-light-readings.".into(),
        },
        Finding {
            section: "§6, fig. 14".into(),
            claim: "The paper reports how far the structure moved toward the source in 1000 steps, and calls the velocity rather slow.".into(),
            kumiki: format!("{} cells (ground as anchor)", anchor.end.describe(2)),
            runs: anchor.end.n,
            verdict: Verdict::NotStated,
            note: "Kumiki's own figure; no comparison is judged.".into(),
        },
    ]
}
