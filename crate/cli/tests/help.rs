//! The help explains the metrics from the one table of each model's metrics.rs: `kumiki help
//! metrics` (and `kumiki metrics --help`) gives every metric's unit and meaning, the same words
//! `kumiki metrics` prints and the page's metric cards show, and `run` and `sweep` point to it.

use std::process::Command;

fn kumiki(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs");
    assert!(out.status.success(), "kumiki {args:?} fails");
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn help_explains_every_metric_from_the_table() {
    let table = kumiki(&["metrics"]);
    let rows: Vec<Vec<&str>> = table.lines().map(|l| l.split('\t').collect()).collect();
    assert!(rows.len() > 40, "every model's metrics are listed");
    for args in [&["help", "metrics"][..], &["metrics", "--help"]] {
        let help = kumiki(args);
        for row in &rows {
            let [model, name, unit, about] = row[..] else {
                panic!("a metrics line has four fields: {row:?}")
            };
            let entry = format!("  {name} [{unit}]\n      {about}\n");
            let section = help
                .split("\n\n")
                .find(|s| s.starts_with(&format!("{model}\n")))
                .unwrap_or_else(|| panic!("kumiki {args:?} has a section for {model}"));
            assert!(
                format!("{section}\n").contains(&entry),
                "kumiki {args:?} explains {model}'s {name}"
            );
        }
    }
    // The short help stays short.
    assert!(!kumiki(&["metrics", "-h"]).contains(rows[0][3]));
    for command in ["run", "sweep"] {
        assert!(kumiki(&["help", command]).contains("kumiki help metrics"));
    }
    assert!(kumiki(&["--help"]).contains("kumiki help metrics"));
}
