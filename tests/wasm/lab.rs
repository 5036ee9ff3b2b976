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
