//! `kumiki`: the command-line face of the core. See `kumiki help`.

mod bench;
mod check;
mod pool;
mod reproduce;
mod runs;
mod shard;
mod soak;

// Counts only while `kumiki bench` or `kumiki soak` measures; see `bench::Counting` for why it is
// installed.
#[global_allocator]
static ALLOC: bench::Counting = bench::Counting;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand, ValueEnum};
use kumiki_core::experiment::PROGRAM_VERSION;
use kumiki_core::{lessons, link, presets, Limits};
use serde_json::Value;

use runs::{load_scenario, run, sweep, RunArgs, SweepArgs};

const AFTER_HELP: &str = "\
SCENARIO is a JSON file, a share link (or its #k1... part), a preset name or a lesson name.
EXPERIMENT is an experiment JSON file or a built-in experiment name.
Runs of many seeds and sweeps use every core (--jobs to choose). Output: one JSON object per run
and line, or CSV with a header. --shard I/N runs part of them (see docs/cluster.md); kumiki merge
puts the parts back together.
Every metric's unit and meaning: kumiki help metrics.";

/// The note under `run` and `sweep`'s help: what their metrics mean is one command away.
const METRICS_POINTER: &str =
    "Each metric in the output is explained, with its unit, by kumiki help metrics.";

#[derive(Parser)]
#[command(
    name = "kumiki",
    version,
    about = "kumiki: self-assembling and self-reconfiguring modular robots, from the command line",
    after_help = AFTER_HELP
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// One built-in scenario name per line
    Presets,
    /// One built-in experiment name per line
    Experiments,
    /// The built-in lessons (classroom exercises): name, model, paper section and title, one a line
    Lessons,
    /// Print the scenario as JSON
    Show {
        /// A JSON file, a share link, a preset or a lesson name
        scenario: String,
        #[command(flatten)]
        size: Size,
    },
    /// Print a share link that opens the scenario in the page
    Link {
        /// A JSON file, a share link, a preset or a lesson name
        scenario: String,
        /// The page's address; without it, the KUMIKI_BASE environment variable, or else
        /// http://localhost:8080/ (what `npm start` serves). The base used is said on stderr.
        #[arg(long, value_name = "URL")]
        base: Option<String>,
        #[command(flatten)]
        size: Size,
    },
    /// Run a scenario for one seed or many
    #[command(after_help = METRICS_POINTER)]
    Run(RunArgs),
    /// Run an experiment: scenarios x grid x seeds, one row per run
    #[command(after_help = METRICS_POINTER)]
    Sweep(SweepArgs),
    /// Put the outputs of --shard runs back into one, in the unsharded order
    Merge {
        /// The shards' outputs, in any order
        #[arg(required = true, value_name = "FILES")]
        files: Vec<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Json)]
        format: Format,
    },
    /// Time workloads (see tests/bench); one JSON line each
    Bench {
        #[arg(required = true, value_name = "WORKLOAD.json")]
        files: Vec<PathBuf>,
        #[command(flatten)]
        jobs: Jobs,
    },
    /// Run each model's largest preset for many steps and sample its memory; one JSON line each
    Soak {
        /// Steps per model (a run that finishes is followed by the next seed)
        #[arg(long, value_name = "N", default_value_t = 1_000_000,
              value_parser = clap::value_parser!(u64).range(1..))]
        steps: u64,
        /// Steps between memory samples
        #[arg(long, value_name = "N", default_value_t = 10_000,
              value_parser = clap::value_parser!(u64).range(1..))]
        every: u64,
        /// Soak this model only
        #[arg(long, value_name = "M")]
        model: Option<String>,
    },
    /// Run every model's paper experiments and write docs/reproduction.md and .json under DIR
    Reproduce {
        /// Print this model's part as Markdown instead of writing the report
        #[arg(long, value_name = "M", conflicts_with = "check")]
        model: Option<String>,
        /// Compare the report under DIR with what the experiments give now; fail if it differs
        #[arg(long)]
        check: bool,
        /// The repository root the report lives under
        #[arg(long, value_name = "DIR", default_value = ".")]
        root: PathBuf,
        #[command(flatten)]
        jobs: Jobs,
    },
    /// Every metric a model reports: model, name, unit and meaning, tab-separated, one a line
    Metrics {
        /// Only this model's metrics
        model: Option<String>,
        /// One JSON object per metric and line instead
        #[arg(long)]
        json: bool,
    },
    /// Write the JSON Schemas of scenarios and experiments (DIR/docs/schema), the TypeScript types
    /// generated from them and from the records the core hands the page (DIR/web/*.gen.ts), the
    /// metric tables (DIR/docs/metrics.md) and the limits table of DIR/docs/scenario-format.md
    Schema {
        /// Compare the schemas under DIR with what this build derives; fail if they differ
        #[arg(long)]
        check: bool,
        /// The repository root the schemas live under
        #[arg(long, value_name = "DIR", default_value = ".")]
        root: PathBuf,
    },
    /// Grade classroom hand-ins: replay each link within the exercise's budget and judge it by
    /// the teacher's exercise
    Check {
        /// Hand-in links (or scenario files)
        #[arg(value_name = "LINK")]
        links: Vec<String>,
        /// A file of hand-ins: links one a line, a form's CSV or text export (comma, semicolon or
        /// tab), or a workbook (.xlsx, .ods, .xls)
        #[arg(long, value_name = "FILE")]
        file: Option<PathBuf>,
        /// The exercise as the teacher made it (a link, file or lesson): hand-ins are judged by
        /// its goal, locks and allowed disturbances, and every field they changed is listed.
        /// Without it, the exercise most hand-ins carry is the class's; one that differs fails
        #[arg(long, value_name = "EXERCISE")]
        exercise: Option<String>,
        #[arg(long, value_enum, default_value_t = check::CheckFormat::Json)]
        format: check::CheckFormat,
        /// Exit with status 1 when a hand-in does not meet the goal or cannot be graded
        #[arg(long)]
        strict: bool,
        #[command(flatten)]
        jobs: Jobs,
        #[command(flatten)]
        size: Size,
    },
    /// The models' rule slots (MODEL SLOT and what it decides, one a line), or with MODEL and
    /// SLOT the paper's rule as a script, to start one's own from (docs/rules.md)
    Rules {
        model: Option<String>,
        slot: Option<String>,
    },
    /// The models' helper calls: MODEL NAME and what each does
    Queries,
    /// A model's helper call, e.g. kumiki query cubes3d derive '{"shape": "##\n##\n"}'
    Query {
        model: String,
        name: String,
        /// JSON text or a JSON file
        args: Option<String>,
    },
    /// Print the program version
    #[command(hide = true)]
    Version,
}

#[derive(Args)]
struct Jobs {
    /// Threads to use (default: every core)
    #[arg(long = "jobs", value_name = "J", value_parser = clap::value_parser!(u64).range(1..=256))]
    jobs: Option<u64>,
}

impl Jobs {
    fn threads(&self) -> usize {
        match self.jobs {
            Some(j) => j as usize,
            None => std::thread::available_parallelism().map_or(1, usize::from),
        }
    }
}

#[derive(Args)]
struct Size {
    /// Accept scenarios beyond what the page draws, up to the core's large limits (see
    /// docs/scenario-format.md)
    #[arg(long)]
    allow_large: bool,
}

impl Size {
    fn limits(&self) -> &'static Limits {
        match self.allow_large {
            true => &Limits::LARGE,
            false => &Limits::PAGE,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum PlotFormat {
    Svg,
    Pdf,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    Json,
    Csv,
}

/// A usage error clap cannot see (exit code 2) or a failure of the run itself (exit code 1).
pub enum Failure {
    Usage(String),
    Run(String),
}

impl<E: std::fmt::Display> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure::Run(e.to_string())
    }
}

/// Usage errors, clap's and ours, print the same way: one line naming the problem and a pointer
/// to the help.
fn usage_error(message: &str) -> ExitCode {
    eprintln!("kumiki: {message}\n(see 'kumiki help')");
    ExitCode::from(2)
}

/// The long help of `kumiki metrics` (`kumiki help metrics`, `kumiki metrics --help`): every
/// model's metrics with their units and meanings, from the same tables as the page's metric cards
/// and docs/metrics.md.
fn metrics_help() -> String {
    let mut text = String::from("What each metric means, by model (unit in brackets):\n");
    for m in kumiki_core::models::MODELS {
        text.push_str(&format!("\n{}\n", m.name));
        for info in m.metrics {
            text.push_str(&format!(
                "  {} [{}]\n      {}\n",
                info.name, info.unit, info.about
            ));
        }
    }
    text
}

/// The command line's definition, with the help texts made from the core's tables.
fn cli_definition() -> clap::Command {
    Cli::command().mut_subcommand("metrics", |c| c.after_long_help(metrics_help()))
}

fn main() -> ExitCode {
    let parsed = cli_definition()
        .try_get_matches()
        .and_then(|matches| Cli::from_arg_matches(&matches));
    let cli = match parsed {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // One line that names the problem, like every other error of this program: clap's
            // message up to its first blank line (the usage and tips follow it), on one line.
            let text = e.to_string();
            let message: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty())
                .map(str::trim)
                .collect();
            return usage_error(message.join(" ").trim_start_matches("error: "));
        }
    };
    match dispatch(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => usage_error(&msg),
        Err(Failure::Run(msg)) => {
            eprintln!("kumiki: {msg}");
            ExitCode::from(1)
        }
    }
}

/// `kumiki rules [MODEL [SLOT]]`: the slots, one a line (MODEL SLOT, title), or a slot's paper
/// rule as a script.
fn rules(model: Option<&str>, slot: Option<&str>, out: &mut impl Write) -> Result<(), Failure> {
    if let Some(model) = model {
        kumiki_core::models::entry(model)?;
    }
    let slots: Vec<_> = kumiki_core::rules::slots()
        .into_iter()
        .filter(|d| model.is_none_or(|m| d.model == m))
        .collect();
    match slot {
        None => {
            for d in &slots {
                writeln!(out, "{} {}\t{}", d.model, d.slot.name, d.slot.title)?;
            }
        }
        Some(name) => {
            let doc = slots.iter().find(|d| d.slot.name == name).ok_or_else(|| {
                let known: Vec<&str> = slots.iter().map(|d| d.slot.name).collect();
                Failure::Usage(format!(
                    "{} has no rule slot '{name}'; its slots: {}",
                    model.unwrap_or_default(),
                    known.join(", ")
                ))
            })?;
            write!(out, "{}", doc.slot.paper)?;
        }
    }
    Ok(())
}

/// Where `kumiki link`'s links open when neither `--base` nor `KUMIKI_BASE` says.
const DEFAULT_BASE: &str = "http://localhost:8080/";

fn dispatch(command: Option<Command>) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    match command {
        None => {
            write!(out, "{}", cli_definition().render_help())?;
        }
        Some(Command::Version) => writeln!(out, "{PROGRAM_VERSION}")?,
        Some(Command::Presets) => {
            for name in presets::names() {
                writeln!(out, "{name}")?;
            }
        }
        Some(Command::Lessons) => {
            for l in lessons::list()? {
                writeln!(out, "{}\t{}\t{}\t{}", l.name, l.model, l.section, l.title)?;
            }
        }
        Some(Command::Experiments) => {
            for name in presets::experiment_names() {
                writeln!(out, "{name}")?;
            }
        }
        Some(Command::Show { scenario, size }) => {
            let scenario = load_scenario(&scenario, size.limits())?;
            writeln!(out, "{}", scenario.to_json_pretty())?;
        }
        Some(Command::Link {
            scenario,
            base,
            size,
        }) => {
            let scenario = load_scenario(&scenario, size.limits())?;
            let (base, from) = match (base, std::env::var("KUMIKI_BASE")) {
                (Some(b), _) => (b, "--base"),
                (None, Ok(b)) if !b.trim().is_empty() => (b.trim().to_string(), "KUMIKI_BASE"),
                _ => (
                    DEFAULT_BASE.to_string(),
                    "the default; set KUMIKI_BASE or --base",
                ),
            };
            eprintln!("kumiki: links open {base} ({from})");
            writeln!(out, "{base}#{}", link::encode(&scenario))?;
        }
        Some(Command::Run(args)) => run(args, &mut out)?,
        Some(Command::Sweep(args)) => sweep(args, &mut out)?,
        Some(Command::Merge { files, format }) => {
            let texts = files
                .iter()
                .map(|f| {
                    std::fs::read_to_string(f)
                        .map(|t| (f.display().to_string(), t))
                        .map_err(|e| format!("{}: {e}", f.display()))
                })
                .collect::<Result<Vec<_>, _>>()?;
            let (command, provenance, rows) = shard::merge(&texts)?;
            write!(
                out,
                "{}",
                shard::write(command, provenance.as_ref(), &rows, format == Format::Csv)
            )?;
        }
        Some(Command::Bench { files, jobs }) => {
            bench::start_counting();
            let workloads = files
                .iter()
                .map(|f| bench::load(f))
                .collect::<Result<Vec<_>, _>>()?;
            for w in &workloads {
                writeln!(out, "{}", bench::measure(w, jobs.threads()))?;
            }
        }
        Some(Command::Soak {
            steps,
            every,
            model,
        }) => {
            bench::start_counting();
            for model in soak::models(model.as_deref())? {
                writeln!(out, "{}", soak::soak(model, steps, every)?)?;
            }
        }
        Some(Command::Reproduce {
            model,
            check,
            root,
            jobs,
        }) => {
            let mode = match (&model, check) {
                (Some(_), _) => reproduce::Mode::Print,
                (None, true) => reproduce::Mode::Check,
                (None, false) => reproduce::Mode::Write,
            };
            reproduce::run(model.as_deref(), mode, &root, jobs.threads())?;
        }
        Some(Command::Check {
            links,
            file,
            exercise,
            format,
            strict,
            jobs,
            size,
        }) => {
            let limits = size.limits();
            let handins = check::handins(links, file.as_deref())?;
            let given = exercise
                .as_deref()
                .map(|e| load_scenario(e, limits))
                .transpose()?;
            let teacher = check::teacher(given.as_ref(), &handins)?;
            eprintln!("kumiki: graded by {}", teacher.describe());
            let tally = check::run(&handins, &teacher, format, jobs.threads(), limits, &mut out)?;
            eprintln!("kumiki: {tally}");
            if strict && !tally.all_met() {
                return Err(Failure::Run(format!("--strict: {tally}")));
            }
        }
        Some(Command::Metrics { model, json }) => {
            let models: Vec<&str> = match &model {
                Some(m) => vec![kumiki_core::models::entry(m)?.name],
                None => kumiki_core::models::MODELS.iter().map(|m| m.name).collect(),
            };
            for m in models {
                for info in kumiki_core::models::metric_table(m)? {
                    match json {
                        true => writeln!(
                            out,
                            "{}",
                            serde_json::json!({"model": m, "name": info.name, "unit": info.unit, "about": info.about})
                        )?,
                        false => {
                            writeln!(out, "{m}\t{}\t{}\t{}", info.name, info.unit, info.about)?
                        }
                    }
                }
            }
        }
        Some(Command::Schema { check, root }) => schema(check, &root)?,
        Some(Command::Rules { model, slot }) => rules(model.as_deref(), slot.as_deref(), &mut out)?,
        Some(Command::Queries) => {
            for (model, q) in kumiki_core::models::queries() {
                writeln!(out, "{model} {}\t{}", q.name, q.description)?;
            }
        }
        Some(Command::Query { model, name, args }) => {
            let text = match args {
                None => "{}".to_string(),
                Some(a) if Path::new(&a).is_file() => {
                    std::fs::read_to_string(&a).map_err(|e| format!("{a}: {e}"))?
                }
                Some(a) => a,
            };
            let args: Value = serde_json::from_str(&text).map_err(|e| format!("ARGS: {e}"))?;
            writeln!(out, "{}", kumiki_core::models::query(&model, &name, &args)?)?;
        }
    }
    Ok(())
}

/// Writes `docs/schema/`, the TypeScript types and the generated parts of the docs under `root`,
/// or with `check` says whether they are current.
fn schema(check: bool, root: &Path) -> Result<(), Failure> {
    let mut files = kumiki_core::schema::files();
    for (path, marker, part) in kumiki_core::schema::spliced()? {
        let doc = std::fs::read_to_string(root.join(path)).map_err(|e| format!("{path}: {e}"))?;
        let text = kumiki_core::schema::splice(&doc, marker, &part).ok_or_else(|| {
            format!(
                "{path}: the <!-- {marker}:begin --> and <!-- {marker}:end --> lines are missing"
            )
        })?;
        files.push((path.to_string(), text));
    }
    if check {
        let stale: Vec<String> = files
            .iter()
            .filter(|(path, text)| {
                std::fs::read_to_string(root.join(path)).ok().as_ref() != Some(text)
            })
            .map(|(path, _)| path.clone())
            .collect();
        return match stale.is_empty() {
            true => {
                eprintln!("the schemas are current");
                Ok(())
            }
            false => Err(Failure::Run(format!(
                "{} {} not what this build derives: run 'kumiki schema' and commit the result",
                stale.join(" and "),
                if stale.len() == 1 { "is" } else { "are" }
            ))),
        };
    }
    for (path, text) in files {
        let path = root.join(path);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        }
        std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}
