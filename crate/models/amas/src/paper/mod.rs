//! The claims of Terada & Murata's text about their results, beside Kumiki's figures for them
//! (the reproduction report, `docs/reproduction.md`). Every verdict is computed from the runs.

mod appendix;
mod bridge;
mod disturbances;
mod figures;

use serde_json::{json, Value};

use appendix::figb1_findings;
use bridge::bridge_findings;
use disturbances::fig27_findings;
use figures::{fig23_findings, fig24_findings};
use kumiki_model::report::{Finding, Paper, Results, Stats, Verdict};

pub const PAPER: Paper = Paper {
    model: "amas",
    citation: "Y. Terada and S. Murata, \"Automatic Modular Assembly System and its Distributed \
               Control\", IJRR 27(3–4), 2008",
    experiments: &[
        "amas-fig23",
        "amas-fig23-corner",
        "amas-fig23-turned",
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

/// Figure 23's rows of one shape ("L" or "T") and field, a rule and a number of robots.
fn fig23(r: &Results, shape: &str, field: &str, rule: &str, robots: u32, metric: &str) -> Stats {
    r.stats(
        "amas-fig23",
        &[
            ("scenario", json!(format!("{shape}, {field} field"))),
            ("collision", json!(rule)),
            ("robots", json!(robots)),
        ],
        metric,
    )
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
