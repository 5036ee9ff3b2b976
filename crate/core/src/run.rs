//! A run: a model driven through its scenario's schedule up to its step limit.

use crate::error::Result;
use crate::hash::{self, StateHasher};
use crate::models::{Action, Model};
use crate::rules::Installed;
use crate::scenario::{Disturbance, Scenario};
pub use kumiki_model::row::Outcome;

pub struct Run {
    scenario: Scenario,
    model: Box<dyn Model>,
    /// Index of the next scheduled disturbance.
    next: usize,
    /// The scripts in the model's rule slots, whose budgets start again each step.
    rules: Installed,
}

impl Run {
    /// Builds the scenario's model, once, from what reading the scenario learnt (nothing is
    /// checked again), with its rules' scripts in their slots.
    pub fn new(mut scenario: Scenario) -> Result<Run> {
        let mut model = scenario.build_once()?;
        let rules = scenario.install(model.as_mut())?;
        Ok(Run {
            scenario,
            model,
            next: 0,
            rules,
        })
    }

    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    pub fn model(&self) -> &dyn Model {
        self.model.as_ref()
    }

    pub fn steps(&self) -> u64 {
        self.model.steps()
    }

    /// Finished at the step limit, when the goal is reached and nothing is left to happen, or
    /// when a rule's script stopped the run.
    pub fn finished(&self) -> bool {
        self.model.steps() >= self.scenario.max_steps
            || (self.model.completed() && self.next >= self.scenario.disturbances.len())
            || self.model.stopped().is_some()
    }

    /// Why a rule's script stopped the run (the rule, the line and the cap), if one did.
    pub fn stopped(&self) -> Option<&str> {
        self.model.stopped()
    }

    /// Applies the disturbances due now, then takes one step. Returns false, doing nothing, once
    /// the run is finished.
    pub fn step(&mut self) -> bool {
        self.apply_due();
        if self.finished() {
            return false;
        }
        self.rules.begin_step();
        self.model.step();
        true
    }

    /// Up to `n` steps; returns how many were taken.
    pub fn advance(&mut self, n: u64) -> u64 {
        let mut done = 0;
        while done < n && self.step() {
            done += 1;
        }
        done
    }

    pub fn run_to_end(&mut self) {
        while self.step() {}
    }

    fn apply_due(&mut self) {
        let now = self.model.steps();
        while let Some(d) = self.scenario.disturbances.get(self.next) {
            if d.at > now {
                break;
            }
            // The form was checked when the scenario was read; an action that does not fit the
            // state at its step changes nothing, the same way in every replay.
            let _ = self.model.apply(&d.action);
            self.next += 1;
        }
    }

    /// Applies an action now and records it in the scenario, so the share link replays it. An
    /// action that fails is not recorded.
    pub fn apply_now(&mut self, action: Action) -> Result<()> {
        self.model.check_action(&action)?;
        self.apply_due();
        self.model.apply(&action)?;
        let at = self.model.steps();
        self.scenario
            .disturbances
            .insert(self.next, Disturbance { at, action });
        self.next += 1;
        Ok(())
    }

    /// A copy of the run as it stands, to continue independently (a keyframe).
    pub fn snapshot(&self) -> Run {
        Run {
            scenario: self.scenario.clone(),
            model: self.model.snapshot(),
            next: self.next,
            rules: self.rules.clone(),
        }
    }

    /// The same run state under `scenario`, whose disturbances may differ from this run's after
    /// the present step: those before it are taken as applied, the rest are still to come. A
    /// keyframe taken before a click is replayed this way with the click.
    pub fn reschedule(&mut self, scenario: &Scenario) {
        let now = self.model.steps();
        self.next = scenario.disturbances.iter().filter(|d| d.at < now).count();
        self.scenario = scenario.clone();
    }

    pub fn state_hash(&self) -> u64 {
        let mut h = StateHasher::new();
        h.u64(self.model.steps());
        self.model.hash_state(&mut h);
        h.finish()
    }

    pub fn outcome(&self) -> Outcome {
        Outcome {
            scenario: self.scenario.name.clone(),
            seed: self.scenario.seed,
            completed: self.model.completed(),
            steps: self.model.steps(),
            hash: hash::hex(self.state_hash()),
            metrics: self.model.metrics(),
            stopped: self.model.stopped().map(str::to_string),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{counts, link, presets};

    /// Reading a scenario checks its model's description and actions without building the
    /// model; the run builds it, once, and checks nothing again.
    #[test]
    fn one_load_from_a_link_builds_its_model_once() {
        for name in presets::names() {
            let link = link::encode(&presets::scenario(name).unwrap());
            let before = counts::builds();
            let scenario = link::open(&link).unwrap().scenario;
            let edited = scenario.with_override("seed", 7.into()).unwrap();
            assert_eq!(counts::builds(), before, "{name}: reading built the model");
            let checks = counts::checks();
            let run = Run::new(edited).unwrap();
            assert_eq!(counts::builds(), before + 1, "{name}");
            assert_eq!(counts::checks(), checks, "{name}: the run checked it again");
            assert_eq!(run.steps(), 0);
        }
    }
}
