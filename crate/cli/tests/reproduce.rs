//! `kumiki reproduce` writes the report, `--check` accepts it as written and refuses it once
//! changed.

use std::process::Command;

fn kumiki(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

#[test]
fn check_accepts_the_written_report_and_refuses_a_changed_one() {
    let root = std::env::temp_dir().join(format!("kumiki-reproduce-{}", std::process::id()));
    std::fs::create_dir_all(root.join("docs")).unwrap();
    let root_arg = root.to_str().unwrap();

    let write = kumiki(&["reproduce", "--root", root_arg]);
    assert!(write.status.success(), "{}", String::from_utf8_lossy(&write.stderr));
    let md = std::fs::read_to_string(root.join("docs/reproduction.md")).unwrap();
    assert!(md.starts_with("# Reproduction report"));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root.join("docs/reproduction.json")).unwrap())
            .unwrap();
    assert!(json["models"].is_object());

    let check = kumiki(&["reproduce", "--check", "--root", root_arg]);
    assert!(check.status.success(), "{}", String::from_utf8_lossy(&check.stderr));

    std::fs::write(root.join("docs/reproduction.md"), md + "\nedited by hand\n").unwrap();
    let stale = kumiki(&["reproduce", "--check", "--root", root_arg]);
    assert_eq!(stale.status.code(), Some(1));
    let err = String::from_utf8_lossy(&stale.stderr);
    assert!(err.contains("docs/reproduction.md") && err.contains("npm run reproduce"), "{err}");

    let both = kumiki(&["reproduce", "--check", "--model", "amas"]);
    assert_eq!(both.status.code(), Some(2));
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn an_unknown_model_is_named() {
    let out = kumiki(&["reproduce", "--model", "no-such"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no-such"));
}
