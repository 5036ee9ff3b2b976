//! Exports of an experiment's rows that say how they were made: a provenance header (program
//! and commit, each model's behaviour version, the experiment as read, its seeds and the time),
//! then the rows, as JSON lines or as CSV whose columns name their units, and traced metrics in
//! long form. The page and `kumiki sweep` call these same functions, so the same sweep gives the
//! same bytes (the time aside, which each passes in).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::experiment::{csv_text, csv_value, to_csv, Experiment, Row, PROGRAM_VERSION};
use crate::models;

/// The commit this program was built from (see build.rs).
pub const COMMIT: &str = env!("KUMIKI_COMMIT");

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// "kumiki 0.1.0".
    pub program: String,
    pub commit: String,
    /// The behaviour version of each model the experiment runs (see `ModelEntry::model_version`).
    pub models: BTreeMap<String, u32>,
    /// The seeds every grid point ran.
    pub seeds: Vec<u64>,
    /// When the sweep ran, as the caller gave it (RFC 3339, UTC).
    pub time: String,
    /// The experiment as it was read, every scenario included.
    pub experiment: Value,
}

impl Provenance {
    pub fn of(e: &Experiment, time: &str) -> Provenance {
        Provenance {
            program: PROGRAM_VERSION.into(),
            commit: COMMIT.into(),
            models: e
                .scenarios
                .iter()
                .filter_map(|s| models::entry(s.model()).ok())
                .map(|m| (m.name.to_string(), m.model_version))
                .collect(),
            seeds: e.seeds.clone(),
            time: time.into(),
            experiment: e.definition.clone(),
        }
    }

    /// The provenance as `# ` comment lines, for the top of a CSV file.
    pub fn comment(&self) -> String {
        let models: Vec<String> = self
            .models
            .iter()
            .map(|(m, v)| format!("{m} behaviour version {v}"))
            .collect();
        format!(
            "# {} (commit {})\n# models: {}\n# seeds: {}\n# time: {}\n# experiment: {}\n",
            self.program,
            self.commit,
            models.join(", "),
            self.seeds
                .iter()
                .map(u64::to_string)
                .collect::<Vec<_>>()
                .join(" "),
            self.time,
            self.experiment
        )
    }
}

/// The unit of a metric, from the first model's table that has it.
pub fn metric_unit(name: &str) -> Option<&'static str> {
    models::MODELS
        .iter()
        .find_map(|m| models::metric_info(m.name, name))
        .map(|i| i.unit)
}

/// JSON lines: `{"provenance": ...}`, then one row per line as `kumiki sweep` writes it.
pub fn json_lines(p: &Provenance, rows: &[Row]) -> String {
    let mut out = serde_json::json!({ "provenance": p }).to_string();
    out.push('\n');
    for r in rows {
        out.push_str(&serde_json::to_string(r).expect("rows serialise"));
        out.push('\n');
    }
    out
}

/// CSV with the provenance as comment lines first (spreadsheets and `pandas.read_csv(...,
/// comment="#")` skip them).
pub fn csv(p: &Provenance, rows: &[Row]) -> String {
    p.comment() + &to_csv(rows)
}

/// The traced metrics in long form: one line per run, step and metric, with the metric's unit.
pub fn trace_csv(p: &Provenance, rows: &[Row]) -> String {
    let mut params: Vec<&String> = rows.iter().flat_map(|r| r.params.keys()).collect();
    params.sort();
    params.dedup();
    let mut out = p.comment();
    out.push_str("scenario,seed");
    for k in &params {
        out.push_str(&format!(",{}", csv_text(&format!("params.{k}"))));
    }
    out.push_str(",step [steps],metric,unit,value\n");
    for r in rows {
        let Some(t) = &r.trace else { continue };
        let lead: String = std::iter::once(csv_text(&r.scenario))
            .chain(std::iter::once(r.seed.to_string()))
            .chain(params.iter().map(|k| csv_value(r.params.get(*k))))
            .collect::<Vec<_>>()
            .join(",");
        for (name, values) in &t.values {
            let unit = metric_unit(name).unwrap_or("");
            for (i, step) in t.step.iter().enumerate() {
                let v = match values.get(i) {
                    None | Some(Value::Null) => String::new(),
                    Some(v) => v.to_string(),
                };
                out.push_str(&format!(
                    "{lead},{step},{},{},{v}\n",
                    csv_text(name),
                    csv_text(unit)
                ));
            }
        }
    }
    out
}
