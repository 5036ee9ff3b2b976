//! `kumiki run` and `kumiki sweep`: their options, scenarios and experiments loaded from files,
//! links and names, their jobs run on the thread pool, and their rows written as JSON lines or
//! CSV.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use kumiki_core::experiment::{Experiment, Row};
use kumiki_core::export::{self, Provenance};
use kumiki_core::scenario::{parse_override, MAX_SEED, MAX_STEPS};
use kumiki_core::{hash, lessons, link, presets, Limits, Run, Scenario};
use serde_json::Value;

use crate::shard::{self, Shard, Tag};
use crate::{pool, Failure, Format, Jobs, PlotFormat, Size};

#[derive(Args)]
pub(crate) struct RunArgs {
    /// A JSON file, a share link, a preset or a lesson name
    scenario: String,
    /// Run this seed instead of the scenario's; `random` draws a fresh one from the system's
    /// entropy, printed on stderr and recorded in the output
    #[arg(long, value_name = "S|random", value_parser = parse_seed)]
    seed: Option<SeedArg>,
    /// Run seeds 1..N
    #[arg(long, value_name = "N", conflicts_with = "seed",
          value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    seeds: Option<u64>,
    /// Stop every run after at most M steps
    #[arg(long, value_name = "M", value_parser = clap::value_parser!(u64).range(1..=MAX_STEPS))]
    max_steps: Option<u64>,
    /// Override a scenario field by its dotted path; VALUE is read as JSON when it parses
    /// (5, true, [1,2]) and as text otherwise
    #[arg(long = "set", value_name = "PATH=VALUE", value_parser = parse_set)]
    sets: Vec<(String, Value)>,
    /// Put the script in FILE in the model's rule slot SLOT, in place of the paper's rule (see
    /// kumiki rules and docs/rules.md)
    #[arg(long = "rule", value_name = "SLOT=FILE", value_parser = parse_rule)]
    rules: Vec<(String, PathBuf)>,
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,
    #[command(flatten)]
    jobs: Jobs,
    /// Run only shard I of N (I from 0) of the seeds, as JSON lines for kumiki merge
    #[arg(long, value_name = "I/N", requires = "seeds")]
    shard: Option<Shard>,
    #[command(flatten)]
    size: Size,
}

#[derive(Args)]
pub(crate) struct SweepArgs {
    /// An experiment JSON file or a built-in experiment name
    experiment: String,
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,
    /// Also draw the experiment's plots: one EXPERIMENT-N.svg (or .pdf) per plot, in --plot-dir
    #[arg(long, value_enum, value_name = "FORMAT")]
    plot: Option<PlotFormat>,
    /// Where --plot writes its files
    #[arg(long, value_name = "DIR", default_value = ".")]
    plot_dir: PathBuf,
    /// Print per condition n, mean, sd, median, IQR and 95% interval, then the comparisons (for
    /// three or more conditions the Kruskal-Wallis test, and every pair, first minus second, by
    /// effect sizes and the Mann-Whitney U test, Holm-corrected) as JSON lines instead of the rows
    #[arg(long, conflicts_with = "shard")]
    summary: bool,
    /// Also write the traced metrics in long form (run, step, metric, unit, value) as CSV to FILE
    #[arg(long, value_name = "FILE", conflicts_with = "shard")]
    traces: Option<PathBuf>,
    #[command(flatten)]
    jobs: Jobs,
    /// Run only shard I of N (I from 0) of the jobs, as JSON lines for kumiki merge
    #[arg(long, value_name = "I/N")]
    shard: Option<Shard>,
    #[command(flatten)]
    size: Size,
}

/// `--seed`: a seed a scenario accepts, or `random` for a fresh one.
#[derive(Clone, Copy)]
enum SeedArg {
    Fixed(u64),
    Random,
}

fn parse_seed(text: &str) -> Result<SeedArg, String> {
    if text == "random" {
        return Ok(SeedArg::Random);
    }
    match text.parse::<u64>() {
        Ok(seed) if seed <= MAX_SEED => Ok(SeedArg::Fixed(seed)),
        _ => Err(format!(
            "'{text}' is not a seed: give a whole number from 0 to {MAX_SEED}, or 'random'"
        )),
    }
}

fn parse_set(text: &str) -> Result<(String, Value), String> {
    parse_override(text).map_err(|e| e.to_string())
}

fn parse_rule(text: &str) -> Result<(String, PathBuf), String> {
    match text.split_once('=') {
        Some((slot, file)) if !slot.is_empty() && !file.is_empty() => {
            Ok((slot.to_string(), PathBuf::from(file)))
        }
        _ => Err(format!("'{text}' is not SLOT=FILE")),
    }
}

/// A scenario from a file, a link, a preset name or a lesson name, in that order, held to
/// `limits`.
pub(crate) fn load_scenario(target: &str, limits: &'static Limits) -> Result<Scenario, Failure> {
    let path = Path::new(target);
    if path.is_file() {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{target}: {e}"))?;
        return Scenario::from_json_within(&text, limits)
            .map_err(|e| Failure::Run(format!("{target}: {e}")));
    }
    if target.contains('#') || target.starts_with(link::PREFIX) {
        let opened = link::open_within(target, limits)?;
        if opened.version_differs() {
            let when = match opened.made_with < opened.current {
                true => "an earlier",
                false => "a newer",
            };
            eprintln!(
                "kumiki: this link was made with {when} Kumiki ({} behaviour version {}, this one runs {}); results may differ",
                opened.scenario.model(), opened.made_with, opened.current
            );
        }
        return Ok(opened.scenario);
    }
    if presets::names().any(|n| n == target) {
        return Ok(presets::scenario(target)?.with_limits(limits)?);
    }
    if lessons::names().any(|n| n == target) {
        return Ok(lessons::scenario(target)?.with_limits(limits)?);
    }
    Err(Failure::Run(format!(
        "'{target}' is not a file, a share link, a preset or a lesson (see 'kumiki presets' and 'kumiki lessons')"
    )))
}

pub(crate) fn run(args: RunArgs, out: &mut impl Write) -> Result<(), Failure> {
    let mut scenario = load_scenario(&args.scenario, args.size.limits())?;
    let mut params = serde_json::Map::new();
    if !args.sets.is_empty() {
        scenario = scenario.with_overrides(&args.sets)?;
        params.extend(args.sets.iter().cloned());
    }
    for (slot, file) in &args.rules {
        let source = std::fs::read_to_string(file)
            .map_err(|e| format!("--rule {slot}={}: {e}", file.display()))?;
        scenario = scenario.with_override(&format!("rules.{slot}"), source.into())?;
    }
    if let Some(m) = args.max_steps {
        scenario = scenario.with_override("max_steps", m.into())?;
    }
    let seeds: Vec<u64> = match (args.seed, args.seeds) {
        (Some(SeedArg::Fixed(s)), _) => vec![s],
        (Some(SeedArg::Random), _) => {
            let seed = kumiki_seed::fresh_seed()
                .map_err(|e| format!("no random seed could be drawn: {e}"))?;
            eprintln!("kumiki: drew seed {seed}; --seed {seed} runs it again");
            vec![seed]
        }
        (None, Some(n)) => (1..=n).collect(),
        (None, None) => vec![scenario.seed],
    };
    // A scenario that compares two runs (its `compare` section) runs both, the first run's row
    // first; the second's is named with its label ("lesson-amas-compare (tokens only)") and its
    // parameters name the setting it changes.
    let mut runs = vec![(scenario.clone(), params.clone())];
    if let (Some(compare), Some(mut second)) = (&scenario.compare, scenario.compared()?) {
        let (_, label) = compare.labels(&scenario.to_value());
        second.name = format!("{} ({label})", second.name);
        let mut params = params.clone();
        params.insert(compare.path.clone(), compare.value.clone());
        runs.push((second, params));
    }
    let runs: Vec<(Scenario, serde_json::Map<String, Value>, String)> = runs
        .into_iter()
        .map(|(s, p)| {
            let h = hash::hex(s.hash_without_seed());
            (s, p, h)
        })
        .collect();
    let output = Output {
        command: shard::Command::Run,
        source: scenario.name.clone(),
        format: args.format,
        shard: args.shard,
        threads: args.jobs.threads(),
        progress: args.seeds.is_some(),
        provenance: None,
        quiet: false,
    };
    output.emit(seeds.len() * runs.len(), out, false, |i| {
        let (scenario, params, scenario_hash) = &runs[i % runs.len()];
        let mut s = scenario.clone();
        s.seed = seeds[i / runs.len()];
        let mut run = Run::new(s).expect("the scenario was validated");
        run.run_to_end();
        Ok(Row::from_outcome(
            run.outcome(),
            params.clone(),
            scenario_hash.clone(),
            None,
        ))
    })?;
    Ok(())
}

pub(crate) fn sweep(args: SweepArgs, out: &mut impl Write) -> Result<(), Failure> {
    let target = &args.experiment;
    let path = Path::new(target);
    let experiment = if path.is_file() {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{target}: {e}"))?;
        Experiment::from_json_within(&text, args.size.limits())
            .map_err(|e| Failure::Run(format!("{target}: {e}")))?
    } else {
        Experiment::named_or_json_within(target, args.size.limits())?
    };
    let jobs = experiment.jobs();
    let provenance = Provenance::of(&experiment, &now_utc());
    let keep = args.plot.is_some() || args.summary || args.traces.is_some();
    let output = Output {
        command: shard::Command::Sweep,
        source: experiment.name.clone(),
        format: args.format,
        shard: args.shard,
        threads: args.jobs.threads(),
        progress: true,
        provenance: Some(provenance.clone()),
        quiet: args.summary,
    };
    let rows = output.emit(jobs.len(), out, keep, |i| {
        experiment.run_job(&jobs[i]).map_err(|e| e.to_string())
    })?;
    let figures = kumiki_core::plot::figure::figures_of(&experiment, &rows);
    if args.summary {
        for line in kumiki_core::plot::figure::summary_lines(&figures) {
            writeln!(out, "{line}")?;
        }
    }
    if let Some(format) = args.plot {
        std::fs::create_dir_all(&args.plot_dir)
            .map_err(|e| format!("{}: {e}", args.plot_dir.display()))?;
        for (i, f) in figures.iter().enumerate() {
            let (ext, bytes) = match format {
                PlotFormat::Svg => ("svg", kumiki_core::plot::svg::svg(f).into_bytes()),
                PlotFormat::Pdf => (
                    "pdf",
                    kumiki_core::plot::pdf::pdf(&kumiki_core::plot::svg::layout(f)),
                ),
            };
            let path = args
                .plot_dir
                .join(format!("{}-{}.{ext}", experiment.name, i + 1));
            std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))?;
            eprintln!("kumiki: wrote {}", path.display());
        }
    }
    if let Some(path) = &args.traces {
        std::fs::write(path, export::trace_csv(&provenance, &rows))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

/// Now as RFC 3339 UTC to the second, or the time `SOURCE_DATE_EPOCH` gives (the
/// reproducible-builds convention), so a rerun can write the same bytes.
fn now_utc() -> String {
    let secs = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.trim().parse::<i64>().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs() as i64)
        });
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // Howard Hinnant's civil_from_days.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

/// How the rows of `run` and `sweep` are computed and written.
struct Output {
    command: shard::Command,
    source: String,
    format: Format,
    shard: Option<Shard>,
    threads: usize,
    /// Whether a progress bar is worth showing (when stderr is a terminal).
    progress: bool,
    /// Written before the rows (a sweep's): a JSON line, or CSV comment lines.
    provenance: Option<Provenance>,
    /// Write no rows (`--summary` prints its statistics instead).
    quiet: bool,
}

impl Output {
    /// Runs jobs `0..total` (or this shard's share) on the thread pool and writes their rows in
    /// job order: JSON lines as they come, CSV at the end (its columns depend on every row).
    fn emit(
        &self,
        total: usize,
        out: &mut impl Write,
        keep: bool,
        work: impl Fn(usize) -> Result<Row, String> + Sync,
    ) -> Result<Vec<Row>, Failure> {
        if self.shard.is_some() && self.format == Format::Csv {
            return Err(Failure::Run(
                "a shard is written as JSON lines; give --format csv to kumiki merge instead"
                    .into(),
            ));
        }
        let indices: Vec<usize> = match self.shard {
            Some(s) => s.jobs(total),
            None => (0..total).collect(),
        };
        let bar = match self.progress {
            true => progress_bar(&self.source, indices.len()),
            false => ProgressBar::hidden(),
        };
        let mut rows: Vec<Row> = Vec::new();
        if let (Some(p), false) = (&self.provenance, self.quiet || self.format == Format::Csv) {
            writeln!(out, "{}", serde_json::json!({ "provenance": p }))?;
        }
        pool::run_ordered(
            indices.len(),
            self.threads,
            |k| work(indices[k]),
            |k, row| -> Result<(), Failure> {
                let row = row?;
                bar.inc(1);
                if let Some(why) = &row.stopped {
                    bar.suspend(|| {
                        eprintln!("kumiki: {} (seed {}): {why}", row.scenario, row.seed)
                    });
                }
                if keep {
                    rows.push(row.clone());
                }
                if self.quiet {
                    return Ok(());
                }
                match (self.shard, self.format) {
                    (Some(_), _) => {
                        let tag = Tag {
                            command: self.command,
                            source: self.source.clone(),
                            job: indices[k],
                            jobs: total,
                        };
                        writeln!(out, "{}", shard::shard_line(tag, row))?;
                    }
                    (None, Format::Json) => {
                        writeln!(out, "{}", shard::json_line(self.command, &row))?
                    }
                    (None, Format::Csv) if !keep => rows.push(row),
                    (None, Format::Csv) => {}
                }
                Ok(())
            },
        )?;
        bar.finish_and_clear();
        if self.format == Format::Csv && !self.quiet {
            let text = match &self.provenance {
                Some(p) => export::csv(p, &rows),
                None => export::to_csv(&rows),
            };
            write!(out, "{text}")?;
        }
        Ok(rows)
    }
}

/// A progress bar over `total` runs on stderr, or a hidden one when stderr is not a terminal (a
/// log file or a pipe gets no bar).
pub fn progress_bar(prefix: &str, total: usize) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    ProgressBar::new(total as u64)
        .with_prefix(prefix.to_string())
        .with_style(
            ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} runs, {eta} left")
                .expect("the template is valid")
                .progress_chars("#>."),
        )
}
