//! The claims of Terada & Murata's text about their results, beside Kumiki's figures for them
//! (the reproduction report, `docs/reproduction.md`). Every verdict is computed from the runs.

mod appendix;
mod bridge;
mod disturbances;
mod figures;
mod labour;

use serde_json::json;

use appendix::figb1_findings;
use bridge::bridge_findings;
use disturbances::fig27_findings;
use figures::fig23_findings;
use kumiki_model::report::{Finding, Ordering, Paper, Results, Size, Stats, Verdict};
use labour::fig24_findings;

pub const PAPER: Paper = Paper {
    model: "amas",
    citation: "Y. Terada and S. Murata, \"Automatic Modular Assembly System and its Distributed \
               Control\", IJRR 27(3–4), 2008",
    experiments: &[
        "amas-fig23",
        "amas-fig23-foot",
        "amas-fig24",
        "amas-fig27",
        "amas-fig27-rules",
        "amas-fig27-supply",
        "amas-bridge",
        "amas-figB1",
    ],
    findings,
};

const FIELDS: [(&str, &str); 2] = [("continuous", "continuous"), ("discrete", "discrete")];

/// Figure 22's two readings: the shapes standing on their stems (`amas-fig23`, the primary
/// reading, where the traffic turns the corners) and on their foot or crossbar
/// (`amas-fig23-foot`).
const READINGS: [(&str, &str); 2] = [
    ("amas-fig23", "on their stems"),
    ("amas-fig23-foot", "on their foot"),
];

/// The values of figure 23's runs of one reading (experiment), shape ("L" or "T"), field, rule
/// and number of robots.
fn fig23_values(
    r: &Results,
    experiment: &str,
    shape: &str,
    field: &str,
    rule: &str,
    robots: u32,
    metric: &str,
) -> Vec<f64> {
    r.values(
        experiment,
        &[
            ("scenario", json!(format!("{shape}, {field} field"))),
            ("collision", json!(rule)),
            ("robots", json!(robots)),
        ],
        metric,
    )
}

/// [`Stats`] of [`fig23_values`].
fn fig23(
    r: &Results,
    experiment: &str,
    shape: &str,
    field: &str,
    rule: &str,
    robots: u32,
    metric: &str,
) -> Stats {
    Stats::of(&fig23_values(
        r, experiment, shape, field, rule, robots, metric,
    ))
}

/// The weakest of several verdicts on the parts of one claim: holds only when every part
/// holds, differs when any part differs.
fn weakest(verdicts: impl IntoIterator<Item = Verdict>) -> Verdict {
    let rank = |v: Verdict| match v {
        Verdict::Holds | Verdict::NotStated => 2,
        Verdict::Partial => 1,
        Verdict::Differs => 0,
    };
    verdicts
        .into_iter()
        .min_by_key(|&v| rank(v))
        .unwrap_or(Verdict::Differs)
}

/// "median 850 (IQR 820–880)".
fn median(s: &Stats) -> String {
    format!("{:.0} ({:.0}–{:.0})", s.median, s.q1, s.q3)
}

fn findings(r: &Results) -> Vec<Finding> {
    let mut out = Vec::new();
    fig23_findings(r, &mut out);
    fig24_findings(r, &mut out);
    fig27_findings(r, &mut out);
    bridge_findings(r, &mut out);
    figb1_findings(r, &mut out);
    out
}
