//! `--shard I/N` and `kumiki merge`: a long sweep split over the tasks of a cluster job array
//! (SLURM `--array`, a Kubernetes Indexed Job) and put back together.
//!
//! Shard `I` of `N` (counting from 0, like `$SLURM_ARRAY_TASK_ID` with `--array=0-(N-1)` and
//! `$JOB_COMPLETION_INDEX`) takes the jobs whose index leaves remainder `I` when divided by `N`:
//! experiments list their jobs grid point by grid point, so dealing them out like cards gives every
//! shard a share of the slow and the fast points. A shard writes JSON lines: each row as the
//! command writes it in full (an experiment row, with `params`, `scenario_hash` and `version`),
//! plus a `shard` object that says where the row goes. `kumiki merge` checks that every job is
//! there exactly once and writes the rows in the unsharded order and format, byte for byte.

use std::collections::BTreeMap;
use std::str::FromStr;

use kumiki_core::experiment::Row;
use kumiki_core::export::{self, Provenance};
use kumiki_core::Outcome;
use serde::{Deserialize, Serialize};

/// Which part of the jobs this process runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(text: &str) -> Result<Shard, String> {
        let bad = || format!("'{text}' is not I/N with 0 <= I < N (for example 0/4 to 3/4)");
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let index: usize = i.trim().parse().map_err(|_| bad())?;
        let count: usize = n.trim().parse().map_err(|_| bad())?;
        if count == 0 || index >= count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }
}

impl Shard {
    /// The indices of the jobs, among `total`, that this shard runs.
    pub fn jobs(self, total: usize) -> Vec<usize> {
        (self.index..total).step_by(self.count).collect()
    }
}

/// What the unsharded command writes as its JSON lines: `run` writes each run's outcome, `sweep`
/// the whole experiment row.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Command {
    Run,
    Sweep,
}

impl Command {
    fn name(self) -> &'static str {
        match self {
            Command::Run => "run",
            Command::Sweep => "sweep",
        }
    }
}

/// Where a row of a shard belongs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tag {
    pub command: Command,
    /// The scenario (`run`) or experiment (`sweep`) name, so shards of different runs do not mix.
    pub source: String,
    /// The row's place in the unsharded output, from 0.
    pub job: usize,
    /// How many rows the unsharded output has.
    pub jobs: usize,
}

#[derive(Serialize, Deserialize)]
struct Line {
    shard: Tag,
    #[serde(flatten)]
    row: Row,
}

/// One row of a shard's output, without the newline.
pub fn shard_line(tag: Tag, row: Row) -> String {
    serde_json::to_string(&Line { shard: tag, row }).expect("rows serialise")
}

/// One row as the unsharded command writes it in JSON, without the newline.
pub fn json_line(command: Command, row: &Row) -> String {
    match command {
        Command::Sweep => serde_json::to_string(row),
        Command::Run => serde_json::to_string(&Outcome {
            scenario: row.scenario.clone(),
            seed: row.seed,
            completed: row.completed,
            steps: row.steps,
            hash: row.hash.clone(),
            metrics: row.metrics.clone(),
            stopped: row.stopped.clone(),
        }),
    }
    .expect("rows serialise")
}

/// A sweep shard's first line: the provenance of the sweep.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Header {
    provenance: Provenance,
}

/// Rows in the unsharded order, and a sweep's provenance, from the text of shard files (name,
/// text), in any order. Shards of one sweep must agree on the provenance, the time aside (each
/// task starts at its own time); the merged output carries the earliest.
pub fn merge(
    files: &[(String, String)],
) -> Result<(Command, Option<Provenance>, Vec<Row>), String> {
    let mut first: Option<(String, Tag)> = None;
    let mut rows: BTreeMap<usize, Row> = BTreeMap::new();
    let mut version: Option<String> = None;
    let mut provenance: Option<(String, Provenance)> = None;
    for (name, text) in files {
        for (n, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let at = format!("{name}:{}", n + 1);
            if let Ok(Header { provenance: p }) = serde_json::from_str(line) {
                match &mut provenance {
                    None => provenance = Some((at, p)),
                    Some((where_, one)) => {
                        let same = Provenance {
                            time: one.time.clone(),
                            ..p.clone()
                        };
                        if same != *one {
                            return Err(format!(
                                "{at}: a different sweep (program, models or experiment) from {where_}"
                            ));
                        }
                        if p.time < one.time {
                            one.time = p.time;
                        }
                    }
                }
                continue;
            }
            let Line { shard, row } = serde_json::from_str(line).map_err(|e| {
                format!("{at}: not a row of a shard ({e}); shards are written by --shard I/N")
            })?;
            match &first {
                None => first = Some((at.clone(), shard.clone())),
                Some((where_, one)) => {
                    if (one.command, &one.source, one.jobs)
                        != (shard.command, &shard.source, shard.jobs)
                    {
                        return Err(format!(
                            "{at}: from `{} {}` with {} jobs, but {where_} is from `{} {}` with {} jobs",
                            shard.command.name(),
                            shard.source,
                            shard.jobs,
                            one.command.name(),
                            one.source,
                            one.jobs
                        ));
                    }
                }
            }
            if let Some(v) = &version {
                if *v != row.version {
                    return Err(format!(
                        "{at}: made by {} but earlier rows by {v}; shards must come from one program",
                        row.version
                    ));
                }
            } else {
                version = Some(row.version.clone());
            }
            if shard.job >= shard.jobs {
                return Err(format!("{at}: job {} of only {}", shard.job, shard.jobs));
            }
            if rows.insert(shard.job, row).is_some() {
                return Err(format!(
                    "{at}: job {} appears twice (a shard given twice?)",
                    shard.job
                ));
            }
        }
    }
    let Some((_, tag)) = first else {
        return Err("the shards hold no rows".into());
    };
    let missing: Vec<String> = (0..tag.jobs)
        .filter(|j| !rows.contains_key(j))
        .map(|j| j.to_string())
        .collect();
    if !missing.is_empty() {
        let shown = missing
            .iter()
            .take(10)
            .cloned()
            .collect::<Vec<_>>()
            .join(", ");
        let more = if missing.len() > 10 { ", ..." } else { "" };
        return Err(format!(
            "{} of {} jobs are missing (jobs {shown}{more}); is a shard missing or cut short?",
            missing.len(),
            tag.jobs
        ));
    }
    Ok((
        tag.command,
        provenance.map(|(_, p)| p),
        rows.into_values().collect(),
    ))
}

/// The merged rows written the way the unsharded command writes them.
pub fn write(command: Command, provenance: Option<&Provenance>, rows: &[Row], csv: bool) -> String {
    match (csv, provenance) {
        (true, Some(p)) => export::csv(p, rows),
        (true, None) => export::to_csv(rows),
        (false, Some(p)) if command == Command::Sweep => export::json_lines(p, rows),
        (false, _) => rows.iter().map(|r| json_line(command, r) + "\n").collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_deal_jobs_round_robin() {
        assert_eq!("1/4".parse(), Ok(Shard { index: 1, count: 4 }));
        for bad in ["4/4", "0/0", "1", "-1/3", "a/b", "1/4/5"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
        let s = Shard { index: 1, count: 4 };
        assert_eq!(s.jobs(10), vec![1, 5, 9]);
        assert_eq!(Shard { index: 3, count: 4 }.jobs(3), Vec::<usize>::new());
        let mut all: Vec<usize> = (0..4)
            .flat_map(|i| Shard { index: i, count: 4 }.jobs(10))
            .collect();
        all.sort();
        assert_eq!(all, (0..10).collect::<Vec<_>>());
    }
}
