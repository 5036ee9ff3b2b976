//! `kumiki soak` through the real binary: it picks the model's largest preset, goes on with the
//! next seed when a run finishes, and samples memory that a short soak already shows flat.

use std::process::Command;

#[test]
fn a_short_soak_samples_flat_memory() {
    let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args([
            "soak", "--model", "amas", "--steps", "3000", "--every", "500",
        ])
        .output()
        .expect("the kumiki binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        row["preset"], "amas-fig25",
        "the first AMAS preset of 28 × 28 cells"
    );
    assert_eq!(row["steps"], 3000);
    assert!(
        row["runs"].as_u64().unwrap() > 1,
        "finished runs are followed by the next seed"
    );
    let live: Vec<u64> = row["samples"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["live_bytes"].as_u64().unwrap())
        .collect();
    assert_eq!(live.len(), 6);
    let (first, most) = (live[0], *live.iter().max().unwrap());
    assert!(
        most < first + first / 5,
        "live heap bytes at each sample: {live:?}"
    );
}
