//! Going back in a run: keyframes, and deterministic replay from the nearest one.
//!
//! A [`Timeline`] keeps a copy of the run every `every` steps, at most `capacity` copies, the
//! first of them the run's start. When it is full it drops every other keyframe and doubles the
//! interval, so the copies cover the whole run evenly and memory stays at `capacity` model states
//! however long the run grows. Seeking to a step replays from the keyframe before it; because runs
//! are deterministic the state reached is bit-identical to the one first passed through. With a
//! capacity of 0 (a lattice so large that one copy of its state is over the keyframes' memory
//! budget) nothing is copied: the start is rebuilt from the scenario and replayed from there.

use crate::run::Run;
use crate::scenario::Scenario;

pub struct Timeline {
    /// Keyframes in step order; the first, when there is one, is the run's start.
    frames: Vec<Run>,
    every: u64,
    capacity: usize,
}

impl Timeline {
    /// A timeline from `start`, keeping at most `capacity` keyframes (0: none, 1: the start only),
    /// the first `every` steps apart.
    pub fn new(start: &Run, every: u64, capacity: usize) -> Timeline {
        Timeline {
            frames: if capacity > 0 {
                vec![start.snapshot()]
            } else {
                Vec::new()
            },
            every: every.max(1),
            capacity,
        }
    }

    /// Call after each step: keeps a keyframe when the run stands on a multiple of the interval
    /// past the last keyframe and there is room for more than the start, and says whether it did.
    pub fn record(&mut self, run: &Run) -> bool {
        let step = run.steps();
        let last = self.frames.last().map_or(0, Run::steps);
        if self.capacity < 2 || step <= last || step % self.every != 0 {
            return false;
        }
        self.frames.push(run.snapshot());
        if self.frames.len() > self.capacity {
            self.coarsen();
        }
        true
    }

    /// Doubles the interval and drops the keyframes off it. Called when the timeline is full, and
    /// by a caller that finds keyframes cost too much next to the steps between them.
    pub fn coarsen(&mut self) {
        self.every *= 2;
        let every = self.every;
        self.frames.retain(|f| f.steps() % every == 0);
    }

    /// The step replaying to `step` starts from: the latest keyframe at or before it, or 0 (the
    /// start rebuilt from the scenario).
    pub fn replay_from(&self, step: u64) -> u64 {
        let i = self.frames.partition_point(|f| f.steps() <= step);
        i.checked_sub(1).map_or(0, |i| self.frames[i].steps())
    }

    /// The run at `step`, replayed from the latest keyframe at or before it under `scenario`
    /// (the run's present scenario, with every disturbance clicked since the keyframe), or from
    /// the start rebuilt from `scenario` when there is none. A step past the run's end gives its
    /// end.
    pub fn seek(&self, step: u64, scenario: &Scenario) -> Run {
        let i = self.frames.partition_point(|f| f.steps() <= step);
        let mut run = match i.checked_sub(1) {
            Some(i) => {
                let mut run = self.frames[i].snapshot();
                run.reschedule(scenario);
                run
            }
            // The scenario built this run once; it builds the same start again.
            None => Run::new(scenario.clone()).expect("a scenario that was run builds again"),
        };
        run.advance(step - run.steps());
        run
    }

    /// Forgets the keyframes after `step`: the run forks there.
    pub fn truncate(&mut self, step: u64) {
        self.frames
            .truncate(self.frames.partition_point(|f| f.steps() <= step).max(1));
    }

    /// How many keyframes are kept, and the interval between them.
    pub fn keyframes(&self) -> (usize, u64) {
        (self.frames.len(), self.every)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets;
    use serde_json::json;

    fn run(preset: &str) -> Run {
        Run::new(presets::scenario(preset).unwrap()).unwrap()
    }

    /// Runs to `end`, recording; returns the run, its timeline and the hash at every step.
    fn recorded(preset: &str, end: u64, capacity: usize) -> (Run, Timeline, Vec<u64>) {
        let mut r = run(preset);
        let mut t = Timeline::new(&r, 4, capacity);
        let mut hashes = vec![r.state_hash()];
        while r.steps() < end && r.step() {
            t.record(&r);
            hashes.push(r.state_hash());
        }
        (r, t, hashes)
    }

    #[test]
    fn going_back_then_forward_gives_identical_hashes_in_every_model() {
        for preset in [
            "amas-L",
            "fracta-triangle10-3spares-corner",
            "cubes-box12-ladder",
        ] {
            let (end, timeline, hashes) = recorded(preset, 300, 8);
            let last = end.steps();
            let (frames, every) = timeline.keyframes();
            assert!(
                frames <= 8 && every >= 4,
                "{preset}: {frames} keyframes, every {every}"
            );
            for back in [0, 1, 37, last / 2, last.saturating_sub(1), last] {
                let mut r = timeline.seek(back, end.scenario());
                assert_eq!(r.steps(), back, "{preset}");
                assert_eq!(r.state_hash(), hashes[back as usize], "{preset} at {back}");
                r.advance(last - back);
                assert_eq!(
                    r.state_hash(),
                    end.state_hash(),
                    "{preset} forward from {back}"
                );
            }
        }
    }

    #[test]
    fn with_no_room_for_a_keyframe_going_back_rebuilds_the_start() {
        for capacity in [0, 1] {
            let (end, timeline, hashes) = recorded("amas-L", 120, capacity);
            assert_eq!(
                timeline.keyframes().0,
                capacity,
                "nothing past the start is kept"
            );
            for back in [0, 1, 37, 119, 120] {
                assert_eq!(timeline.replay_from(back), 0);
                let r = timeline.seek(back, end.scenario());
                assert_eq!(r.steps(), back);
                assert_eq!(
                    r.state_hash(),
                    hashes[back as usize],
                    "capacity {capacity}, step {back}"
                );
            }
        }
    }

    #[test]
    fn keyframes_stay_within_capacity_and_thin_evenly() {
        let (end, timeline, _) = recorded("amas-square28", 1000, 5);
        let last = end.steps();
        assert!(last > 500, "{last}");
        let (frames, every) = timeline.keyframes();
        assert!(frames <= 5, "{frames}");
        assert!(every >= last / 5, "every {every} over {last} steps");
        let steps: Vec<u64> = timeline.frames.iter().map(Run::steps).collect();
        assert_eq!(steps[0], 0);
        assert!(steps.iter().all(|s| s % every == 0), "{steps:?}");
    }

    #[test]
    fn coarsening_keeps_the_start_and_the_new_multiples_and_seeks_alike() {
        let (end, mut timeline, hashes) = recorded("amas-L", 200, 64);
        let (before, every) = timeline.keyframes();
        timeline.coarsen();
        let (after, doubled) = timeline.keyframes();
        assert_eq!(doubled, every * 2);
        assert!(after < before && after >= before / 2, "{before} -> {after}");
        let steps: Vec<u64> = timeline.frames.iter().map(Run::steps).collect();
        assert_eq!(steps[0], 0);
        assert!(steps.iter().all(|s| s % doubled == 0), "{steps:?}");
        let r = timeline.seek(end.steps() - 1, end.scenario());
        assert_eq!(r.state_hash(), hashes[end.steps() as usize - 1]);
    }

    #[test]
    fn a_click_after_a_keyframe_is_replayed_and_a_fork_forgets_the_future() {
        let mut r = run("amas-L");
        let mut t = Timeline::new(&r, 10, 16);
        while r.steps() < 125 && r.step() {
            t.record(&r);
        }
        r.apply_now(
            json!({"kind": "remove", "count": 3})
                .as_object()
                .unwrap()
                .clone(),
        )
        .unwrap();
        while r.steps() < 150 && r.step() {
            t.record(&r);
        }
        // Replay from a keyframe taken before the click.
        t.truncate(120);
        let replayed = t.seek(150, r.scenario());
        assert_eq!(replayed.state_hash(), r.state_hash());
        // Without the click the state at 150 differs: the click is really replayed.
        let before_click = t.seek(150, &presets::scenario("amas-L").unwrap());
        assert_ne!(before_click.state_hash(), r.state_hash());

        t.truncate(30);
        assert_eq!(t.frames.last().unwrap().steps(), 30);
        let mut fork = t.seek(30, r.scenario());
        fork.advance(120);
        assert_eq!(
            fork.state_hash(),
            r.state_hash(),
            "same schedule, same future"
        );
    }
}
