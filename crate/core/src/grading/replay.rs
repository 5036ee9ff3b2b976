//! One hand-in graded ([`Replay`]): its rules judged first (the class's exercise, the locked
//! fields, the disturbances), then, when it kept to them, its run replayed within the exercise's
//! budget and judged. A grader steps it in slices ([`Replay::advance`]) so that it can say which
//! row is running and how far it is, and stop it at a time budget; [`grade`] does it all with a
//! clock. `kumiki check` and the page's grading workers both grade this way.

use std::collections::BTreeMap;

use serde_json::Value;

use super::{locked_edits, Grade, Teacher};
use crate::error::Result;
use crate::exercise::{listed, Exercise, Outcome, Verdict};
use crate::{Run, Scenario};

/// The most steps one slice of [`grade`] takes before it reads the clock again.
const MAX_SLICE: u64 = 4096;
/// A slice shorter than this, in seconds, doubles the next one.
const SLICE_SECONDS: f64 = 0.01;

/// A hand-in being graded.
pub struct Replay {
    /// The grade, with everything but the run's end filled in.
    grade: Grade,
    exercise: Exercise,
    /// The hand-in's scenario as JSON, which the goal's `scenario.` names read.
    doc: Value,
    /// Why it is not replayed: the rules it broke, in words; empty when it kept to them.
    broken: Vec<String>,
    /// Its run; `None` when it broke a rule (nothing to judge).
    run: Option<Run>,
}

impl Replay {
    /// Judges `handin`'s rules by the class's exercise and, when it kept to them, builds its run
    /// (the one part of a replay that cannot be stopped half-way).
    pub fn start(handin: Scenario, teacher: &Teacher) -> Result<Replay> {
        let exercise = teacher.exercise().clone();
        let doc = handin.to_value();
        let differs = teacher.exercise_differences(handin.exercise.as_ref());
        let locked_edited = locked_edits(&exercise, &doc);
        let disturbances = exercise.disturbance_problems(listed(&doc));
        let mut broken = Vec::new();
        if let Some(paths) = &differs {
            broken.push(format!(
                "its exercise is not the class's ({} differ{})",
                paths.join(", "),
                if paths.len() == 1 { "s" } else { "" }
            ));
        }
        if !locked_edited.is_empty() {
            broken.push(format!(
                "it changed locked fields ({})",
                locked_edited.join(", ")
            ));
        }
        if !disturbances.is_empty() {
            broken.push(format!(
                "it has disturbances the exercise does not allow ({})",
                disturbances.join("; ")
            ));
        }
        let grade = Grade {
            name: handin.name.clone(),
            met: false,
            because: String::new(),
            completed: false,
            steps: 0,
            hash: String::new(),
            locked_edited,
            disturbances,
            changed: teacher.changed(&doc),
            exercise_edited: differs.is_some(),
            over_budget: false,
            points: None,
            max_points: None,
            credit: Vec::new(),
            record: handin.handin.clone(),
            goal_metrics: BTreeMap::new(),
        };
        let run = match broken.is_empty() {
            true => Some(Run::new(handin)?),
            false => None,
        };
        Ok(Replay {
            grade,
            exercise,
            doc,
            broken,
            run,
        })
    }

    /// Replays at most `steps` more, never past the exercise's step budget. True when there is no
    /// more to replay: the run ended, it reached the budget, or it is not replayed at all.
    pub fn advance(&mut self, steps: u64) -> bool {
        let budget = self.step_budget();
        let Some(run) = &mut self.run else {
            return true;
        };
        run.advance(steps.min(budget.saturating_sub(run.steps())));
        run.finished() || run.steps() >= budget
    }

    /// The steps replayed so far.
    pub fn steps(&self) -> u64 {
        self.run.as_ref().map_or(0, Run::steps)
    }

    /// The most steps the replay may take: the exercise's step budget, or none.
    fn step_budget(&self) -> u64 {
        self.exercise
            .budget
            .and_then(|b| b.steps)
            .unwrap_or(u64::MAX)
    }

    /// The grade. `out_of_time`: the grader stopped it at the exercise's time budget; a run that
    /// has not ended is then "over budget", as it is at the step budget, and is not judged.
    pub fn finish(self, out_of_time: bool) -> Grade {
        let budget = self.step_budget();
        let Replay {
            mut grade,
            exercise,
            doc,
            broken,
            run,
        } = self;
        let Some(run) = run else {
            let verdict = exercise.unjudged(format!("not replayed: {}", broken.join("; ")));
            return with_verdict(grade, verdict);
        };
        let outcome = run.outcome();
        grade.completed = outcome.completed;
        grade.steps = outcome.steps;
        grade.hash = outcome.hash;
        grade.goal_metrics = goal_metrics(&exercise, &outcome.metrics);
        let ended = run.finished();
        if !ended && (out_of_time || outcome.steps >= budget) {
            grade.over_budget = true;
            let limit = match exercise.budget {
                Some(b) if out_of_time => format!(
                    "its time budget of {} s",
                    b.seconds.map_or_else(|| "?".into(), |s| s.to_string())
                ),
                _ => format!("its step budget of {budget} steps"),
            };
            let verdict = exercise.unjudged(format!(
                "over budget: the exercise replays a hand-in within {limit}, and this run had not ended at step {}",
                outcome.steps
            ));
            return with_verdict(grade, verdict);
        }
        let verdict = exercise
            .verdict(
                &Outcome {
                    completed: outcome.completed,
                    steps: outcome.steps,
                    metrics: &outcome.metrics,
                    scenario: &doc,
                },
                &[],
            )
            .with_stop(outcome.stopped.as_deref());
        with_verdict(grade, verdict)
    }
}

fn with_verdict(mut grade: Grade, verdict: Verdict) -> Grade {
    grade.met = verdict.met;
    grade.because = verdict.because;
    grade.points = verdict.points;
    grade.max_points = verdict.max_points;
    grade.credit = verdict.credit;
    grade
}

/// The metrics the exercise's goal and credit read, at the end of a run.
fn goal_metrics(
    exercise: &Exercise,
    metrics: &serde_json::Map<String, Value>,
) -> BTreeMap<String, Value> {
    exercise
        .metric_names()
        .into_iter()
        .filter_map(|m| Some((m.clone(), metrics.get(&m)?.clone())))
        .collect()
}

/// Grades `handin` by the class's exercise within the exercise's budget. `seconds` reads the
/// grader's clock (seconds from any fixed moment: the CLI's `Instant`, a worker's
/// `performance.now()`); it is read only when the exercise has a time budget.
pub fn grade(
    handin: Scenario,
    teacher: &Teacher,
    seconds: &mut dyn FnMut() -> f64,
) -> Result<Grade> {
    let limit = teacher.exercise().budget.and_then(|b| b.seconds);
    let Some(limit) = limit else {
        let mut replay = Replay::start(handin, teacher)?;
        replay.advance(u64::MAX);
        return Ok(replay.finish(false));
    };
    let started = seconds();
    let mut replay = Replay::start(handin, teacher)?;
    let mut slice = 1;
    loop {
        let before = seconds();
        if replay.advance(slice) {
            return Ok(replay.finish(false));
        }
        let now = seconds();
        if now - started > limit {
            return Ok(replay.finish(true));
        }
        if now - before < SLICE_SECONDS {
            slice = (slice * 2).min(MAX_SLICE);
        }
    }
}
