//! The lab module's handles as JavaScript sees them, run in headless Node.
#![cfg(target_arch = "wasm32")]

use kumiki_lab::ExperimentRunner;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn experiment_jobs_run_in_wasm() {
    let runner = ExperimentRunner::new("amas-fig23").unwrap();
    assert!(runner.job_count() > 0);
    assert!(runner.run(0).is_ok());
}

/// A sweep cancelled part way: its export says so and lists only the seeds it ran; its figures
/// come as SVG and PDF.
#[wasm_bindgen_test]
fn a_partial_sweep_exports_as_partial_and_figures_come_as_pdf() {
    let experiment = r#"{"version": 1, "name": "w", "scenarios": ["chobie-load5"], "seeds": [3, 4],
        "sample": {"count": 2, "seed": 1, "ranges": {"max_steps": {"min": 5, "max": 9, "integer": true}}}}"#;
    let runner = ExperimentRunner::new(experiment).unwrap();
    assert_eq!(runner.job_count(), 4);
    let rows = format!("[{}]", runner.run(0).unwrap());
    let csv =
        kumiki_lab::experiment_export(experiment, &rows, "csv", "2024-01-01T00:00:00Z").unwrap();
    assert!(csv.contains("# partial: 1 of 4 runs"), "{csv}");
    assert!(csv.contains("# seeds: 3\n"), "{csv}");
    let pdf = kumiki_lab::experiment_figure_pdf(experiment, &rows, 0).unwrap();
    assert!(pdf.starts_with(b"%PDF-1.4"));
}

/// A class read from a form's export, its exercise found, and each row graded in wasm, whole or
/// in slices, with the table's CSV: the calls the Grade view's workers make.
#[wasm_bindgen_test]
fn a_class_is_read_and_graded_in_wasm() {
    use kumiki_lab::{class_exercise, grade_row, grades_csv, read_handins, RowReplay};
    use serde_json::Value;
    let read = |v: wasm_bindgen::JsValue| -> Value { serde_wasm_bindgen::from_value(v).unwrap() };
    let lesson = kumiki_core::lessons::scenario("lesson-amas-robots").unwrap();
    let solved = lesson.with_override("robots", 5.into()).unwrap();
    let links = [&lesson, &solved].map(|s| format!("#{}", kumiki_core::link::encode(s)));
    let csv = format!(
        "Name,Link,Why?\nAda,{},\"two\nlines\"\nGrace,{},one\n",
        links[0], links[1]
    );
    let rows = read(read_handins(csv.as_bytes()).unwrap());
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 2, "the answer's line break stays in its row");
    assert_eq!(rows[1]["student"], "Grace");
    let class = read(class_exercise(None, links.to_vec()).unwrap());
    let teacher = class["teacher"].as_str().unwrap();
    let graded: Vec<Value> = rows
        .iter()
        .map(|r| read(grade_row(&r.to_string(), teacher).unwrap()))
        .collect();
    assert_eq!(graded[0]["met"], false);
    assert_eq!(graded[1]["met"], true);
    let mut replay = RowReplay::new(&rows[1].to_string(), teacher).unwrap();
    assert_eq!(replay.row(), 2);
    while !replay.advance(10.0) {}
    assert_eq!(read(replay.finish(false).unwrap()), graded[1]);
    let table = grades_csv(&serde_json::to_string(&graded).unwrap(), teacher).unwrap();
    assert!(
        table.starts_with("handin,student,name,met,points,"),
        "{table}"
    );
    assert_eq!(table.lines().count(), 3);
}
