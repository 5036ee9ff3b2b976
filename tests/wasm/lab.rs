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
