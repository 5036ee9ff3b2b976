//! `kumiki bench` through the real binary: a workload's bare steps, and the same steps through the
//! Playback the page's Sim plays, whose keyframes and ratio it reports.

use std::process::Command;

#[test]
fn a_workload_is_timed_bare_and_played_as_the_page_plays_it() {
    let workload = std::env::temp_dir().join(format!("kumiki-bench-{}.json", std::process::id()));
    std::fs::write(
        &workload,
        r#"{"name": "tiny", "scenario": "amas-square28", "set": {"max_steps": 100000000},
            "warmup": 10, "steps": 400, "repeats": 3}"#,
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .arg("bench")
        .arg(&workload)
        .output()
        .expect("the kumiki binary runs");
    std::fs::remove_file(&workload).unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let bare = row["steps_per_second"].as_f64().unwrap();
    let played = row["playback_steps_per_second"].as_f64().unwrap();
    let ratio = row["playback_over_bare"].as_f64().unwrap();
    assert!(bare > 0.0 && played > 0.0, "{row}");
    // The median of the repeats' ratios, played over bare.
    assert!(ratio > 0.0 && ratio.is_finite(), "{row}");
    // Keyframes 16 steps apart or, when copies cost more than their share of the time (a busy
    // machine), a power of two further.
    let every = row["keyframes"]["every"].as_u64().unwrap();
    assert!(every >= 16 && every.is_power_of_two(), "{row}");
    assert!(row["keyframes"]["kept"].as_u64().unwrap() >= 1, "{row}");
}
