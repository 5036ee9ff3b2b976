//! `kumiki sweep` with the richer design (a range, a Latin-hypercube sample, a stop condition),
//! three conditions summarised with Kruskal-Wallis and Holm, and figures written as PDF.

use std::path::PathBuf;
use std::process::Command;

use serde_json::Value;

fn stdout(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs");
    assert!(
        out.status.success(),
        "kumiki {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const DESIGNED: &str = r#"{"version": 1, "name": "designed", "scenarios": ["amas-L"],
  "grid": {"max_steps": {"start": 200, "step": 100, "end": 300}},
  "sample": {"method": "latin", "count": 3, "seed": 2,
             "ranges": {"robots": {"min": 1, "max": 6, "integer": true}}},
  "seeds": 2, "stop": "metrics.placed >= 12",
  "plot": [{"kind": "summary", "group": ["params.robots"]},
           {"kind": "lines", "x": "params.robots", "y": "steps"}]}"#;

#[test]
fn a_designed_sweep_runs_its_points_stops_and_compares_three_conditions() {
    let dir = scratch("designed");
    let file = dir.join("designed.json");
    std::fs::write(&file, DESIGNED).unwrap();
    let file = file.to_str().unwrap();
    let rows: Vec<Value> = stdout(&["sweep", file])
        .lines()
        .skip(1)
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    // Two grid values × three sampled points × two seeds.
    assert_eq!(rows.len(), 12);
    let robots: std::collections::BTreeSet<u64> = rows
        .iter()
        .map(|r| r["params"]["robots"].as_u64().unwrap())
        .collect();
    assert_eq!(robots.len(), 3, "three Latin-hypercube points: {robots:?}");
    for r in &rows {
        let stopped = r["metrics"]["placed"].as_u64().unwrap() >= 12;
        let at_end = r["steps"] == r["params"]["max_steps"];
        assert!(stopped || at_end, "{r}");
    }
    let again: Vec<Value> = stdout(&["sweep", file, "--jobs", "1"])
        .lines()
        .skip(1)
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(again, rows, "the same points and rows on one thread");
    let summary: Vec<Value> = stdout(&["sweep", file, "--summary"])
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let kw: Vec<&Value> = summary
        .iter()
        .filter(|l| l.get("kruskal_wallis").is_some())
        .collect();
    assert_eq!(kw.len(), 1);
    assert_eq!(kw[0]["kruskal_wallis"]["df"], 2);
    let pairs: Vec<&Value> = summary
        .iter()
        .filter(|l| l.get("comparison").is_some())
        .collect();
    assert_eq!(pairs.len(), 3);
    assert!(pairs.iter().all(|p| p["direction"] == "first minus second"
        && p["p_holm"].as_f64().unwrap() >= p["comparison"]["p"].as_f64().unwrap()));
    stdout(&[
        "sweep",
        file,
        "--plot",
        "pdf",
        "--plot-dir",
        dir.to_str().unwrap(),
    ]);
    for i in 1..=2 {
        let pdf = std::fs::read(dir.join(format!("designed-{i}.pdf"))).unwrap();
        assert!(pdf.starts_with(b"%PDF-1.4") && pdf.ends_with(b"%%EOF\n"));
    }
}
