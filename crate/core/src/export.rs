//! Exports of an experiment's rows that say how they were made: a provenance header (program
//! and commit, each model's behaviour version, the experiment as read, its seeds and the time),
//! then the rows, as JSON lines or as CSV whose columns name their units, and traced metrics in
//! long form. The page and `kumiki sweep` call these same functions, so the same sweep gives the
//! same bytes (the time aside, which each passes in).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::experiment::{Experiment, Row, PROGRAM_VERSION};
use crate::models;
pub use crate::plot::figure::Partial;

/// The commit this program was built from (see build.rs).
pub const COMMIT: &str = env!("KUMIKI_COMMIT");

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// "kumiki 0.1.0".
    pub program: String,
    pub commit: String,
    /// The behaviour version of each model the experiment runs (see `ModelEntry::model_version`).
    pub models: BTreeMap<String, u32>,
    /// The seeds every grid point ran; of a partial sweep, the seeds of the runs it has.
    pub seeds: Vec<u64>,
    /// When the sweep ran, as the caller gave it (RFC 3339, UTC).
    pub time: String,
    /// The experiment as it was read, every scenario included.
    pub experiment: Value,
    /// Set when the rows are only some of the experiment's runs (a cancelled sweep).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub partial: Option<Partial>,
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
            partial: None,
        }
    }

    /// The provenance of `rows` of `e`: when they are fewer than its runs (a cancelled sweep),
    /// marked partial, with only the seeds of the runs it has.
    pub fn of_rows(e: &Experiment, time: &str, rows: &[Row]) -> Provenance {
        let mut p = Provenance::of(e, time);
        let of = e.job_count();
        if rows.len() < of {
            p.seeds.retain(|s| rows.iter().any(|r| r.seed == *s));
            p.partial = Some(Partial {
                runs: rows.len(),
                of,
            });
        }
        p
    }

    /// The provenance as `# ` comment lines, for the top of a CSV file.
    pub fn comment(&self) -> String {
        let models: Vec<String> = self
            .models
            .iter()
            .map(|(m, v)| format!("{m} behaviour version {v}"))
            .collect();
        let partial = self.partial.map_or(String::new(), |p| {
            format!(
                "# {}: the sweep was cancelled; seeds are those run\n",
                p.words()
            )
        });
        format!(
            "# {} (commit {})\n{partial}# models: {}\n# seeds: {}\n# time: {}\n# experiment: {}\n",
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
    p.comment() + to_csv(rows).as_str()
}

/// The traced metrics in long form: one line per run, step and metric, with the metric's unit.
pub fn trace_csv(p: &Provenance, rows: &[Row]) -> String {
    let mut params: Vec<&String> = rows.iter().flat_map(|r| r.params.keys()).collect();
    kumiki_model::sort::sort(&mut params);
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

/// Rows as CSV: fixed columns, then `params.*` and `metrics.*` columns in sorted order; a
/// column of a quantity with a unit names it in brackets (`metrics.total_steps [robot steps]`).
pub fn to_csv(rows: &[Row]) -> String {
    let mut params: Vec<&String> = rows.iter().flat_map(|r| r.params.keys()).collect();
    kumiki_model::sort::sort(&mut params);
    params.dedup();
    let mut metrics: Vec<&String> = rows.iter().flat_map(|r| r.metrics.keys()).collect();
    kumiki_model::sort::sort(&mut metrics);
    metrics.dedup();
    let mut out = String::from("scenario,seed,completed,steps [steps],hash,scenario_hash,version");
    for p in &params {
        out.push_str(&format!(",{}", csv_field(&format!("params.{p}"))));
    }
    for m in &metrics {
        let column = match metric_unit(m) {
            Some(unit) => format!("metrics.{m} [{unit}]"),
            None => format!("metrics.{m}"),
        };
        out.push_str(&format!(",{}", csv_field(&column)));
    }
    // Why a rule's script stopped a run: a column only when one did, so other exports keep theirs.
    let stopped = rows.iter().any(|r| r.stopped.is_some());
    if stopped {
        out.push_str(",stopped");
    }
    out.push('\n');
    for r in rows {
        out.push_str(&format!(
            "{},{},{},{},{},{},{}",
            csv_text(&r.scenario),
            r.seed,
            r.completed,
            r.steps,
            r.hash,
            r.scenario_hash,
            csv_field(&r.version)
        ));
        for p in &params {
            out.push(',');
            out.push_str(&csv_value(r.params.get(*p)));
        }
        for m in &metrics {
            out.push(',');
            out.push_str(&csv_value(r.metrics.get(*m)));
        }
        if stopped {
            out.push(',');
            out.push_str(&csv_text(r.stopped.as_deref().unwrap_or_default()));
        }
        out.push('\n');
    }
    out
}

/// A parameter's or metric's value as a CSV cell: empty when missing, text guarded, numbers as
/// JSON writes them.
pub(crate) fn csv_value(v: Option<&Value>) -> String {
    match v {
        None | Some(Value::Null) => String::new(),
        Some(Value::String(s)) => csv_text(s),
        Some(other) => csv_field(&other.to_string()),
    }
}

/// Text from a scenario (a name, a parameter's text value) as a CSV cell. A cell that starts
/// with `=`, `+`, `-`, `@`, a tab or a carriage return is read as a formula by spreadsheets, so
/// such text gets a leading `'` (OWASP's advice); numbers never pass through here.
pub fn csv_text(s: &str) -> String {
    match s.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        true => csv_field(&format!("'{s}")),
        false => csv_field(s),
    }
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::Outcome;

    fn row(scenario: &str, param: Value, metric: Value) -> Row {
        Row {
            outcome: Outcome {
                scenario: scenario.into(),
                seed: 1,
                completed: true,
                steps: 5,
                hash: "00".into(),
                metrics: [("m".to_string(), metric)].into_iter().collect(),
                stopped: None,
            },
            params: [("p".to_string(), param)].into_iter().collect(),
            scenario_hash: "11".into(),
            version: "kumiki 0".into(),
            trace: None,
        }
    }

    #[test]
    fn csv_text_that_a_spreadsheet_would_run_is_neutralised_but_numbers_are_not() {
        let csv = to_csv(&[
            row(
                "=HYPERLINK(\"x\")",
                Value::from("@SUM(A1)"),
                Value::from(-1.5),
            ),
            row("+1", Value::from("-2"), Value::from(3)),
            row("plain, name", Value::from("ok"), Value::from(-7)),
        ]);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "scenario,seed,completed,steps [steps],hash,scenario_hash,version,params.p,metrics.m"
        );
        assert_eq!(
            lines[1],
            "\"'=HYPERLINK(\"\"x\"\")\",1,true,5,00,11,kumiki 0,'@SUM(A1),-1.5"
        );
        assert_eq!(lines[2], "'+1,1,true,5,00,11,kumiki 0,'-2,3");
        assert_eq!(lines[3], "\"plain, name\",1,true,5,00,11,kumiki 0,ok,-7");
    }
}
