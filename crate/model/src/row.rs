//! The records a run leaves: its [`Outcome`], and the [`Row`] of an experiment traced to its
//! parameters, scenario and program, with the [`Trace`] of metrics sampled along the way. The
//! papers' findings ([`crate::report`]) read them.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::model::Metrics;

/// The version of this program, carried by every row.
pub const PROGRAM_VERSION: &str = concat!("kumiki ", env!("CARGO_PKG_VERSION"));

/// The summary of a run, as the CLI prints it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct Outcome {
    /// The scenario's name.
    pub scenario: String,
    pub seed: u64,
    /// The run reached its goal.
    pub completed: bool,
    pub steps: u64,
    /// The state hash at the end, in hex.
    pub hash: String,
    #[schemars(with = "crate::model::MetricValues")]
    pub metrics: Metrics,
    /// Why the run stopped before its end: a rule's script went past a cap or failed (the
    /// message names the rule, the line and the cap). Absent for a run that was not stopped.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stopped: Option<String>,
}

/// A metric sampled during a run: `step[i]` and `values[name][i]`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct Trace {
    pub step: Vec<u64>,
    /// Each traced metric's values, one per sampled step (null where it was missing).
    #[schemars(with = "std::collections::BTreeMap<String, Vec<crate::model::Metric>>")]
    pub values: Map<String, Value>,
}

/// The result of one run, traceable to its scenario and program: its [`Outcome`] (which it
/// dereferences to) and where it came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct Row {
    #[serde(flatten)]
    pub outcome: Outcome,
    /// The experiment's overrides of this run, by dotted path.
    pub params: Map<String, Value>,
    /// The hash of the scenario without its seed: every seed of one configuration shares it.
    pub scenario_hash: String,
    /// The program that ran it.
    pub version: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trace: Option<Trace>,
}

impl std::ops::Deref for Row {
    type Target = Outcome;

    fn deref(&self) -> &Outcome {
        &self.outcome
    }
}

impl std::ops::DerefMut for Row {
    fn deref_mut(&mut self) -> &mut Outcome {
        &mut self.outcome
    }
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
            outcome,
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
