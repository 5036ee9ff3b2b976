//! `kumiki`: the command-line face of the core. See `kumiki help`.

mod bench;
mod pool;
mod reproduce;

#[global_allocator]
static ALLOC: bench::Counting = bench::Counting;

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use kumiki_core::experiment::{self, Experiment, Row, PROGRAM_VERSION};
use kumiki_core::scenario::{parse_override, MAX_SEED};
use kumiki_core::{hash, link, presets, Run, Scenario};

const HELP: &str = "\
kumiki: self-assembling and self-reconfiguring modular robots, from the command line

USAGE
  kumiki presets                       one built-in scenario name per line
  kumiki experiments                   one built-in experiment name per line
  kumiki show SCENARIO                 print the scenario as JSON
  kumiki link SCENARIO [--base URL]    print a share link that opens the scenario in the page
  kumiki run SCENARIO [--seed S | --seeds N] [--max-steps M] [--set PATH=VALUE]...
                      [--format json|csv] [--jobs J]
  kumiki sweep EXPERIMENT [--format json|csv] [--jobs J]
  kumiki bench WORKLOAD.json... [--jobs J]
                                       time workloads (see tests/bench); one JSON line each
  kumiki reproduce [--model M] [--check] [--root DIR] [--jobs J]
                                       run every model's paper experiments and write
                                       docs/reproduction.md and .json under DIR (default .);
                                       --check compares instead; --model M prints one model's part
  kumiki queries                       the models' helper calls: MODEL NAME and what each does
  kumiki query MODEL NAME [ARGS]       a model's helper call; ARGS is JSON text or a JSON file,
                                       e.g. kumiki query cubes3d derive '{\"shape\": \"##\\n##\\n\"}'
  kumiki help | --version

SCENARIO is a JSON file, a share link (or its #k1... part), or a preset name.
EXPERIMENT is an experiment JSON file or a built-in experiment name.
--seeds N runs seeds 1..N; --set overrides any scenario field by its dotted path, the value read
as JSON when it parses (5, true, [1,2]) and as text otherwise. Runs of many seeds use every core
(--jobs to choose). Output: one JSON object per run and line, or CSV with a header.";

/// A usage error (exit code 2) or a failure of the run itself (exit code 1).
pub enum Failure {
    Usage(String),
    Run(String),
}

impl<E: std::fmt::Display> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure::Run(e.to_string())
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match dispatch(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            eprintln!("kumiki: {msg}\n(see 'kumiki help')");
            ExitCode::from(2)
        }
        Err(Failure::Run(msg)) => {
            eprintln!("kumiki: {msg}");
            ExitCode::from(1)
        }
    }
}

fn dispatch(args: &[String]) -> Result<(), Failure> {
    let Some(command) = args.first() else {
        println!("{HELP}");
        return Ok(());
    };
    let rest = &args[1..];
    match command.as_str() {
        "help" | "--help" | "-h" => {
            println!("{HELP}");
            Ok(())
        }
        "--version" | "version" => {
            println!("{PROGRAM_VERSION}");
            Ok(())
        }
        "presets" => {
            no_more(rest)?;
            let mut out = std::io::stdout().lock();
            for name in presets::names() {
                writeln!(out, "{name}")?;
            }
            Ok(())
        }
        "experiments" => {
            no_more(rest)?;
            let mut out = std::io::stdout().lock();
            for name in presets::experiment_names() {
                writeln!(out, "{name}")?;
            }
            Ok(())
        }
        "show" => {
            let (target, _) = one_positional(rest, "show", &[])?;
            println!("{}", load_scenario(&target)?.to_json_pretty());
            Ok(())
        }
        "link" => {
            let (target, opts) = one_positional(rest, "link", &["--base"])?;
            let scenario = load_scenario(&target)?;
            let base = opts
                .get("--base")
                .cloned()
                .unwrap_or_else(|| "http://localhost:8080/".into());
            println!("{base}#{}", link::encode(&scenario));
            Ok(())
        }
        "run" => run(rest),
        "sweep" => sweep(rest),
        "bench" => bench(rest),
        "reproduce" => {
            let check = rest.iter().any(|a| a == "--check");
            let rest: Vec<String> = rest.iter().filter(|a| *a != "--check").cloned().collect();
            let (positional, opts) = parse_options(&rest, &["--model", "--root", "--jobs"])?;
            no_more(&positional)?;
            let model = opts.get("--model").map(String::as_str);
            let mode = match (model, check) {
                (Some(_), true) => {
                    return Err(Failure::Usage(
                        "--check covers every model; drop --model".into(),
                    ))
                }
                (Some(_), false) => reproduce::Mode::Print,
                (None, true) => reproduce::Mode::Check,
                (None, false) => reproduce::Mode::Write,
            };
            let root = opts.get("--root").map_or(".", String::as_str);
            reproduce::run(model, mode, std::path::Path::new(root), threads(&opts)?)
        }
        "queries" => {
            no_more(rest)?;
            let mut out = std::io::stdout().lock();
            for q in kumiki_core::models::QUERIES {
                writeln!(out, "{} {}\t{}", q.model, q.name, q.description)?;
            }
            Ok(())
        }
        "query" => query(rest),
        other => Err(Failure::Usage(format!("unknown command '{other}'"))),
    }
}

fn no_more(rest: &[String]) -> Result<(), Failure> {
    match rest.first() {
        None => Ok(()),
        Some(extra) => Err(Failure::Usage(format!("unexpected argument '{extra}'"))),
    }
}

/// Parsed flags: single-valued options plus repeated `--set`.
struct Options {
    single: std::collections::BTreeMap<String, String>,
    sets: Vec<String>,
}

impl Options {
    fn get(&self, key: &str) -> Option<&String> {
        self.single.get(key)
    }
}

fn parse_options(rest: &[String], allowed: &[&str]) -> Result<(Vec<String>, Options), Failure> {
    let mut positional = Vec::new();
    let mut opts = Options {
        single: Default::default(),
        sets: Vec::new(),
    };
    let mut i = 0;
    while i < rest.len() {
        let arg = &rest[i];
        if let Some(flag) = arg.strip_prefix("--").map(|_| arg.as_str()) {
            let (name, inline) = match flag.split_once('=') {
                Some((n, v)) if n != "--set" => (n.to_string(), Some(v.to_string())),
                _ => (flag.to_string(), None),
            };
            if !allowed.contains(&name.as_str()) {
                return Err(Failure::Usage(format!("unknown option '{name}'")));
            }
            let value = match inline {
                Some(v) => v,
                None => {
                    i += 1;
                    rest.get(i)
                        .cloned()
                        .ok_or_else(|| Failure::Usage(format!("{name} needs a value")))?
                }
            };
            if name == "--set" {
                opts.sets.push(value);
            } else if opts.single.insert(name.clone(), value).is_some() {
                return Err(Failure::Usage(format!("{name} given twice")));
            }
        } else {
            positional.push(arg.clone());
        }
        i += 1;
    }
    Ok((positional, opts))
}

fn one_positional(
    rest: &[String],
    command: &str,
    allowed: &[&str],
) -> Result<(String, Options), Failure> {
    let (positional, opts) = parse_options(rest, allowed)?;
    match positional.as_slice() {
        [one] => Ok((one.clone(), opts)),
        [] => Err(Failure::Usage(format!("{command} needs a scenario"))),
        [_, extra, ..] => Err(Failure::Usage(format!("unexpected argument '{extra}'"))),
    }
}

/// A scenario from a file, a link or a preset name, in that order.
fn load_scenario(target: &str) -> Result<Scenario, Failure> {
    let path = std::path::Path::new(target);
    if path.is_file() {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{target}: {e}"))?;
        return Scenario::from_json(&text).map_err(|e| Failure::Run(format!("{target}: {e}")));
    }
    if target.contains('#') || target.starts_with(link::PREFIX) {
        return Ok(link::decode(target)?);
    }
    if presets::names().any(|n| n == target) {
        return Ok(presets::scenario(target)?);
    }
    Err(Failure::Run(format!(
        "'{target}' is not a file, a share link or a preset (see 'kumiki presets')"
    )))
}

fn parse_number(flag: &str, text: &str, max: u64) -> Result<u64, Failure> {
    match text.parse::<u64>() {
        Ok(n) if n <= max => Ok(n),
        _ => Err(Failure::Usage(format!(
            "{flag} expects a whole number from 0 to {max}, not '{text}'"
        ))),
    }
}

fn threads(opts: &Options) -> Result<usize, Failure> {
    match opts.get("--jobs") {
        Some(j) => Ok(parse_number("--jobs", j, 256)?.max(1) as usize),
        None => Ok(std::thread::available_parallelism().map_or(1, usize::from)),
    }
}

fn format(opts: &Options) -> Result<bool, Failure> {
    match opts.get("--format").map(String::as_str) {
        None | Some("json") => Ok(false),
        Some("csv") => Ok(true),
        Some(other) => Err(Failure::Usage(format!(
            "--format is json or csv, not '{other}'"
        ))),
    }
}

fn run(rest: &[String]) -> Result<(), Failure> {
    let (target, opts) = one_positional(
        rest,
        "run",
        &[
            "--seed",
            "--seeds",
            "--max-steps",
            "--set",
            "--format",
            "--jobs",
        ],
    )?;
    let csv = format(&opts)?;
    let mut scenario = load_scenario(&target)?;
    let mut params = serde_json::Map::new();
    let overrides = opts
        .sets
        .iter()
        .map(|s| parse_override(s))
        .collect::<Result<Vec<_>, _>>()?;
    if !overrides.is_empty() {
        scenario = scenario.with_overrides(&overrides)?;
        for (path, value) in overrides {
            params.insert(path, value);
        }
    }
    if let Some(m) = opts.get("--max-steps") {
        let m = parse_number("--max-steps", m, kumiki_core::scenario::MAX_STEPS)?;
        scenario = scenario.with_override("max_steps", m.into())?;
    }
    let seeds: Vec<u64> = match (opts.get("--seed"), opts.get("--seeds")) {
        (Some(_), Some(_)) => {
            return Err(Failure::Usage("give --seed or --seeds, not both".into()))
        }
        (Some(s), None) => vec![parse_number("--seed", s, MAX_SEED)?],
        (None, Some(n)) => (1..=parse_number("--seeds", n, 1_000_000)?.max(1)).collect(),
        (None, None) => vec![scenario.seed],
    };
    let scenario_hash = hash::hex(scenario.hash_without_seed());
    let jobs = threads(&opts)?;
    let mut rows: Vec<Row> = Vec::new();
    let mut out = std::io::stdout().lock();
    pool::run_ordered(
        seeds.len(),
        jobs,
        |i| {
            let mut s = scenario.clone();
            s.seed = seeds[i];
            let mut run = Run::new(s).expect("the scenario was validated");
            run.run_to_end();
            run.outcome()
        },
        |_, outcome| {
            if csv {
                rows.push(Row {
                    scenario: outcome.scenario,
                    seed: outcome.seed,
                    completed: outcome.completed,
                    steps: outcome.steps,
                    hash: outcome.hash,
                    metrics: outcome.metrics,
                    params: params.clone(),
                    scenario_hash: scenario_hash.clone(),
                    version: PROGRAM_VERSION.into(),
                    trace: None,
                });
                Ok(())
            } else {
                writeln!(
                    out,
                    "{}",
                    serde_json::to_string(&outcome).expect("rows serialise")
                )
            }
        },
    )?;
    if csv {
        write!(out, "{}", experiment::to_csv(&rows))?;
    }
    Ok(())
}

fn sweep(rest: &[String]) -> Result<(), Failure> {
    let (target, opts) = one_positional(rest, "sweep", &["--format", "--jobs"])?;
    let csv = format(&opts)?;
    let path = std::path::Path::new(&target);
    let experiment = if path.is_file() {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{target}: {e}"))?;
        Experiment::from_json(&text).map_err(|e| Failure::Run(format!("{target}: {e}")))?
    } else {
        Experiment::named_or_json(&target)?
    };
    let jobs = experiment.jobs();
    let total = jobs.len();
    let progress = std::io::stderr().is_terminal();
    let mut rows: Vec<Row> = Vec::with_capacity(if csv { total } else { 0 });
    let mut out = std::io::stdout().lock();
    let mut done = 0usize;
    pool::run_ordered(
        total,
        threads(&opts)?,
        |i| experiment.run_job(&jobs[i]),
        |_, row| {
            let row = row.map_err(|e| std::io::Error::other(e.to_string()))?;
            done += 1;
            if progress {
                let width = 30;
                let filled = done * width / total.max(1);
                eprint!(
                    "\r{} [{}{}] {done}/{total}",
                    experiment.name,
                    "#".repeat(filled),
                    ".".repeat(width - filled)
                );
                if done == total {
                    eprintln!();
                }
            }
            if csv {
                rows.push(row);
                Ok(())
            } else {
                writeln!(
                    out,
                    "{}",
                    serde_json::to_string(&row).expect("rows serialise")
                )
            }
        },
    )?;
    if csv {
        write!(out, "{}", experiment::to_csv(&rows))?;
    }
    Ok(())
}

fn query(rest: &[String]) -> Result<(), Failure> {
    let (positional, _) = parse_options(rest, &[])?;
    let (model, name, args) = match positional.as_slice() {
        [m, n] => (m, n, "{}".to_string()),
        [m, n, a] => {
            let path = std::path::Path::new(a);
            let text = if path.is_file() {
                std::fs::read_to_string(path).map_err(|e| format!("{a}: {e}"))?
            } else {
                a.clone()
            };
            (m, n, text)
        }
        [_, _, _, extra, ..] => {
            return Err(Failure::Usage(format!("unexpected argument '{extra}'")))
        }
        _ => {
            return Err(Failure::Usage(
                "query needs a model and a query name".into(),
            ))
        }
    };
    let args: serde_json::Value =
        serde_json::from_str(&args).map_err(|e| Failure::Usage(format!("ARGS: {e}")))?;
    let answer = kumiki_core::models::query(model, name, &args)?;
    println!("{answer}");
    Ok(())
}

fn bench(rest: &[String]) -> Result<(), Failure> {
    let (files, opts) = parse_options(rest, &["--jobs"])?;
    if files.is_empty() {
        return Err(Failure::Usage(
            "bench needs workload files (tests/bench/*.json)".into(),
        ));
    }
    let workloads = files
        .iter()
        .map(|f| bench::load(std::path::Path::new(f)))
        .collect::<Result<Vec<_>, _>>()?;
    let threads = threads(&opts)?;
    let mut out = std::io::stdout().lock();
    for w in &workloads {
        writeln!(out, "{}", bench::measure(w, threads))?;
    }
    Ok(())
}
