//! `--shard I/N` and `kumiki merge`, through the real binary: the merged shards are the unsharded
//! output byte for byte, in JSON and in CSV, for `sweep` and `run --seeds`.

use std::path::PathBuf;
use std::process::{Command, Output};

fn kumiki(args: &[&str]) -> Output {
    // A fixed time, so the provenance of every shard and of the whole sweep is the same.
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .env("SOURCE_DATE_EPOCH", "1700000000")
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

fn stdout(args: &[&str]) -> String {
    let out = kumiki(args);
    assert!(
        out.status.success(),
        "kumiki {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// A scratch folder for this test binary's files.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs every shard of `args`, writes each output to a file, and returns the files in reverse
/// order, so merge cannot lean on the order it is given.
fn shard_files(dir: &std::path::Path, args: &[&str], count: usize) -> Vec<String> {
    let mut files = Vec::new();
    for i in 0..count {
        let shard = format!("{i}/{count}");
        let mut all = args.to_vec();
        all.extend(["--shard", &shard]);
        let text = stdout(&all);
        let file = dir.join(format!("shard-{i}.jsonl"));
        std::fs::write(&file, text).unwrap();
        files.push(file.display().to_string());
    }
    files.reverse();
    files
}

fn merge(files: &[String], format: &str) -> Output {
    let mut args = vec!["merge", "--format", format];
    args.extend(files.iter().map(String::as_str));
    kumiki(&args)
}

fn assert_merges_to_unsharded(dir: &std::path::Path, args: &[&str], count: usize) {
    let files = shard_files(dir, args, count);
    for format in ["json", "csv"] {
        let mut whole = args.to_vec();
        whole.extend(["--format", format]);
        let unsharded = stdout(&whole);
        assert!(unsharded.lines().count() > count, "too few rows to test");
        let merged = merge(&files, format);
        assert!(
            merged.status.success(),
            "{}",
            String::from_utf8_lossy(&merged.stderr)
        );
        assert_eq!(
            String::from_utf8(merged.stdout).unwrap(),
            unsharded,
            "{args:?} in {format}"
        );
    }
}

#[test]
fn merged_sweep_shards_equal_the_unsharded_sweep() {
    let dir = scratch("sweep");
    // Two scenarios, a grid, a trace and more jobs than shards, dealt unevenly (12 over 5).
    let experiment = dir.join("small.json");
    std::fs::write(
        &experiment,
        r#"{"version": 1, "name": "small", "scenarios": ["amas-L", "amas-T"],
            "grid": {"robots": [1, 3]}, "set": {"max_steps": 60}, "seeds": 3,
            "trace": {"every": 20, "metrics": ["built"]}}"#,
    )
    .unwrap();
    let path = experiment.display().to_string();
    assert_merges_to_unsharded(&dir, &["sweep", &path, "--jobs", "2"], 5);
}

#[test]
fn merged_run_shards_equal_the_unsharded_run() {
    let dir = scratch("run");
    let args = [
        "run",
        "fracta-hexagon7",
        "--seeds",
        "7",
        "--set",
        "max_steps=40",
    ];
    assert_merges_to_unsharded(&dir, &args, 3);
}

#[test]
fn merge_refuses_missing_repeated_and_mixed_shards() {
    let dir = scratch("refuse");
    let files = shard_files(
        &dir,
        &["run", "amas-L", "--seeds", "4", "--max-steps", "5"],
        2,
    );
    let stderr = |out: Output| {
        assert_eq!(out.status.code(), Some(1));
        String::from_utf8(out.stderr).unwrap()
    };
    let missing = stderr(merge(&files[..1], "json"));
    assert!(missing.contains("2 of 4 jobs are missing"), "{missing}");
    let twice = stderr(merge(&[files[0].clone(), files[0].clone()], "json"));
    assert!(twice.contains("appears twice"), "{twice}");
    let other = dir.join("other.jsonl");
    std::fs::write(
        &other,
        stdout(&[
            "run",
            "amas-T",
            "--seeds",
            "4",
            "--max-steps",
            "5",
            "--shard",
            "0/2",
        ]),
    )
    .unwrap();
    let mixed = stderr(merge(
        &[files[0].clone(), other.display().to_string()],
        "json",
    ));
    assert!(
        mixed.contains("amas-T") && mixed.contains("amas-L"),
        "{mixed}"
    );
    let plain = dir.join("plain.jsonl");
    std::fs::write(&plain, stdout(&["run", "amas-L", "--max-steps", "5"])).unwrap();
    let not_a_shard = stderr(merge(&[plain.display().to_string()], "json"));
    assert!(
        not_a_shard.contains("not a row of a shard"),
        "{not_a_shard}"
    );
}

#[test]
fn usage_errors_are_one_line_and_exit_2() {
    for args in [
        &["run", "amas-L", "--seed", "1", "--seeds", "3"][..],
        &["run", "amas-L", "--shard", "0/2"],
        &["sweep", "amas-fig23", "--shard", "2/2"],
        &["run", "amas-L", "--format", "xml"],
        &["frobnicate"],
    ] {
        let out = kumiki(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 2, "{args:?}: {err}");
        assert!(lines[0].starts_with("kumiki: "), "{err}");
        assert_eq!(lines[1], "(see 'kumiki help')");
    }
    let out = kumiki(&["run", "amas-L", "--set", "robots=0"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "kumiki: robots: at least one robot is needed\n"
    );
}

#[test]
fn run_writes_the_documented_json_line() {
    let line = stdout(&["run", "amas-L", "--seed", "3", "--max-steps", "20"]);
    assert!(
        line.starts_with(r#"{"scenario":"amas-L","seed":3,"completed":false,"steps":20,"hash":""#),
        "{line}"
    );
    assert!(line.contains(r#","metrics":{"#) && !line.contains("scenario_hash"));
    assert_eq!(line.lines().count(), 1);
}

#[test]
fn a_random_seed_is_recorded_and_replays() {
    let out = kumiki(&["run", "amas-L", "--seed", "random", "--max-steps", "30"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let seed = row["seed"]
        .as_u64()
        .expect("the row records the seed drawn");
    assert!(seed < 1 << 53);
    let note = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        note,
        format!("kumiki: drew seed {seed}; --seed {seed} runs it again\n")
    );
    let again = stdout(&[
        "run",
        "amas-L",
        "--seed",
        &seed.to_string(),
        "--max-steps",
        "30",
    ]);
    let replay: serde_json::Value = serde_json::from_str(&again).unwrap();
    assert_eq!(
        replay["hash"], row["hash"],
        "seed {seed} replays the same run"
    );
}

#[test]
fn a_seed_that_is_neither_a_number_nor_random_is_refused() {
    let out = kumiki(&["run", "amas-L", "--seed", "lucky"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("'lucky' is not a seed"));
}
