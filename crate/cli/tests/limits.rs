//! `--allow-large`: a scenario beyond the page's limits is refused by name, size and limit, and
//! accepted (and run) under the large limits.

use std::process::{Command, Output};

fn kumiki(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

#[test]
fn allow_large_accepts_what_the_page_refuses() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("limits");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("wide.json");
    let scenario = serde_json::json!({
        "version": 1, "model": "amas", "name": "wide", "robots": 2, "max_steps": 3,
        "target": format!("{}\n", "#".repeat(5000)),
    });
    std::fs::write(&file, scenario.to_string()).unwrap();
    let file = file.to_str().unwrap();

    let refused = kumiki(&["run", file]);
    assert!(!refused.status.success());
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(
        message
            .contains("target: 5000×2 cells (with the supply rows) exceeds the limit of 4096×4096"),
        "{message}"
    );

    let accepted = kumiki(&["run", file, "--allow-large"]);
    assert!(
        accepted.status.success(),
        "{}",
        String::from_utf8_lossy(&accepted.stderr)
    );
    let row: serde_json::Value = serde_json::from_slice(&accepted.stdout).unwrap();
    assert_eq!(row["steps"], 3);
}
