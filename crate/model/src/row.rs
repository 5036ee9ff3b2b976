//! The records a run leaves: its [`Outcome`], and the [`Row`] of an experiment traced to its
//! parameters, scenario and program, with the [`Trace`] of metrics sampled along the way. The
//! papers' findings ([`crate::report`]) read them.

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::model::Metrics;

/// The version of this program, carried by every row.
pub const PROGRAM_VERSION: &str = concat!("kumiki ", env!("CARGO_PKG_VERSION"));

/// The summary of a run, as the CLI prints it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Outcome {
    pub scenario: String,
    pub seed: u64,
    pub completed: bool,
    pub steps: u64,
    pub hash: String,
    pub metrics: Metrics,
}

/// A metric sampled during a run: `step[i]` and `values[name][i]`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Trace {
    pub step: Vec<u64>,
    pub values: Map<String, Value>,
}

/// The result of one run, traceable to its scenario and program.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Row {
    pub scenario: String,
    pub seed: u64,
    pub completed: bool,
    pub steps: u64,
    pub hash: String,
    pub metrics: Metrics,
    pub params: Map<String, Value>,
    pub scenario_hash: String,
    pub version: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trace: Option<Trace>,
}

impl Row {
    /// The row of a finished run, traced to its parameters, scenario and program.
    pub fn from_outcome(
        outcome: Outcome,
        params: Map<String, Value>,
        scenario_hash: String,
        trace: Option<Trace>,
    ) -> Row {
        Row {
            scenario: outcome.scenario,
            seed: outcome.seed,
            completed: outcome.completed,
            steps: outcome.steps,
            hash: outcome.hash,
            metrics: outcome.metrics,
            params,
            scenario_hash,
            version: PROGRAM_VERSION.to_string(),
            trace,
        }
    }
}

impl Trace {
    /// Records `names` of `metrics` at `step`, once per step.
    pub fn sample(&mut self, step: u64, metrics: &Metrics, names: &[String]) {
        if self.step.last() == Some(&step) {
            return;
        }
        self.step.push(step);
        for name in names {
            let v = metrics.get(name).cloned().unwrap_or(Value::Null);
            match self
                .values
                .entry(name.clone())
                .or_insert_with(|| Value::Array(Vec::new()))
            {
                Value::Array(list) => list.push(v),
                _ => unreachable!("trace values are lists"),
            }
        }
    }
}
