//! A run as the page plays it: stepped forward, rewound to any step passed through, forked by a
//! click in the past, with every step's metrics kept for the live chart.
//!
//! [`Playback`] holds the [`Run`], its [`Timeline`] of keyframes and its [`Series`]. It reads no
//! clock of its own: [`Playback::advance`] is handed one, so the page passes `performance.now()`
//! and a native test passes a clock it drives itself. The clock only decides how often keyframes
//! are kept, never what the run does.

use schemars::JsonSchema;
use serde::Serialize;

use crate::error::Result;
use crate::hash;
use crate::models::{Action, Metrics, Scene};
use crate::run::Run;
use crate::scenario::Disturbance;
use crate::series::{self, Series};
use crate::timeline::Timeline;

/// Memory the keyframes of one run may take, in bytes, estimated from the cell count at
/// [`KEYFRAME_CELL_BYTES`] a cell: a lattice whose one copy is over it keeps no keyframe, and goes
/// back by rebuilding its start from the scenario.
pub const KEYFRAME_BYTES: usize = 96 << 20;
/// Bytes a keyframe is estimated to take per lattice cell: above what any model's state takes a
/// cell (AMAS, the largest, about 10; docs/benchmarks.md), so the estimate stays on the safe side.
pub const KEYFRAME_CELL_BYTES: usize = 16;
/// Most keyframes a run keeps, however small its lattice.
pub const KEYFRAME_COUNT: usize = 256;
/// Steps between the first keyframes; the interval doubles as the run grows.
pub const KEYFRAME_EVERY: u64 = 16;
/// The share of stepping time keyframes may take. A small model in a large lattice copies more
/// bytes per keyframe than its steps touch, so its interval grows (by powers of two) until copies
/// cost at most this.
pub const KEYFRAME_TIME_SHARE: f64 = 0.05;
/// Keyframes are judged too costly only once this much time (ms) has been measured, so that one
/// slow copy among fast steps (or a coarse clock: browsers round `performance.now()` to 0.1 ms)
/// does not often widen the interval. Short, so that a fast model (a few microseconds a step, a
/// copy costing 40 steps) stops copying at every 16th step within its first fifty steps: over
/// a whole millisecond such a model spent as long copying as stepping (the bench's
/// cubes-box12-ladder, 1000 steps from its start). A wrong widening costs little: the interval
/// is set so that replaying it takes about twenty copies' time.
const COST_WINDOW_MS: f64 = 0.25;

/// Time spent stepping and copying keyframes since the interval last changed, in milliseconds,
/// and the steps and copies it covers.
#[derive(Default)]
struct KeyframeCost {
    total: f64,
    copying: f64,
    steps: u64,
    copies: u64,
}

impl KeyframeCost {
    /// The interval at which keyframes would take at most their share of the time measured, when
    /// `every` is too short for that; starts a new measure when it is. Judged once
    /// [`COST_WINDOW_MS`] have been measured, and then straight to the interval needed (a power
    /// of two times `every`), so a fast model does not copy at the first interval for long.
    fn needs_interval(&mut self, every: u64) -> Option<u64> {
        let stepping = (self.total - self.copying).max(0.0);
        let costly = self.copying > KEYFRAME_TIME_SHARE * stepping && self.total > COST_WINDOW_MS;
        if !costly {
            return None;
        }
        let per_copy = self.copying / self.copies.max(1) as f64;
        let per_step = stepping / self.steps.max(1) as f64;
        let mut interval = every * 2;
        while (interval as f64) * per_step * KEYFRAME_TIME_SHARE < per_copy
            && interval < u64::MAX / 2
        {
            interval *= 2;
        }
        *self = KeyframeCost::default();
        Some(interval)
    }
}

/// A metric's every-step record, merged for drawing (a [`series::Band`] with its name and span).
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct ChartBand {
    pub metric: String,
    /// The first step of each point's range.
    pub steps: Vec<f64>,
    /// The least and the greatest value over each point's steps.
    pub min: Vec<f64>,
    pub max: Vec<f64>,
    /// Steps per recorded bucket: 1 until the record is full, then doubling.
    pub span: u64,
}

/// One frame of a run, as the page's panels show it: where the run stands and its metrics, with
/// what was asked for beside them. The lattice itself is never in it: the view reads the model's
/// buffers in place.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Frame {
    pub steps: u64,
    /// The furthest step reached since the last fork: where the timeline ends.
    pub furthest: u64,
    pub max_steps: u64,
    pub finished: bool,
    pub completed: bool,
    /// The 64-bit state hash in hex, when asked for (it costs a pass over the state).
    pub hash: Option<String>,
    #[schemars(with = "crate::models::MetricValues")]
    pub metrics: Metrics,
    /// The model's scene when it changed since the last frame that carried one, else null.
    pub scene: Option<Scene>,
    /// The charted metric's record, when one was asked for.
    pub chart: Option<ChartBand>,
}

/// One run with the keyframes that let it go back and the record of its metrics.
pub struct Playback {
    /// `None` only within [`Playback::seek`], between freeing the state at hand and building the
    /// one sought, so a large lattice never holds two states at once.
    run: Option<Run>,
    timeline: Timeline,
    /// The furthest step reached since the last fork: the end of the timeline.
    furthest: u64,
    /// The disturbances the scenario came with; a fork keeps them and drops later clicks.
    authored: Vec<Disturbance>,
    /// Every step's metrics, for the live chart.
    series: Series,
    cost: KeyframeCost,
}

impl Playback {
    /// Plays `run` from where it stands, keeping keyframes within [`KEYFRAME_BYTES`].
    pub fn new(run: Run) -> Playback {
        let capacity = keyframe_capacity(run.model().layout().dims);
        let metrics = run.model().metrics();
        let mut series = Series::new(&metrics, series::DEFAULT_CAPACITY);
        series.record(run.steps(), &metrics);
        Playback {
            timeline: Timeline::new(&run, KEYFRAME_EVERY, capacity),
            furthest: run.steps(),
            authored: run.scenario().disturbances.clone(),
            series,
            cost: KeyframeCost::default(),
            run: Some(run),
        }
    }

    pub fn run(&self) -> &Run {
        self.run.as_ref().expect("a playback always holds its run")
    }

    fn run_mut(&mut self) -> &mut Run {
        self.run.as_mut().expect("a playback always holds its run")
    }

    /// Every step's metrics since the start (or the last fork).
    pub fn series(&self) -> &Series {
        &self.series
    }

    /// The furthest step reached, where the timeline ends.
    pub fn furthest(&self) -> u64 {
        self.furthest
    }

    /// Keyframes kept and the steps between them.
    pub fn keyframes(&self) -> (usize, u64) {
        self.timeline.keyframes()
    }

    /// The run as it stands, for the page: with the state hash when `hashed`, and with `chart`'s
    /// metric merged into at most `points` points when one is given. The scene is left out: the
    /// caller knows whether it changed.
    pub fn frame(&self, hashed: bool, chart: Option<(&str, usize)>) -> Frame {
        let run = self.run();
        Frame {
            steps: run.steps(),
            furthest: self.furthest,
            max_steps: run.scenario().max_steps,
            finished: run.finished(),
            completed: run.model().completed(),
            hash: hashed.then(|| hash::hex(run.state_hash())),
            metrics: run.model().metrics(),
            scene: None,
            chart: chart.map(|(metric, points)| {
                let band = self.series.decimate(metric, points);
                ChartBand {
                    metric: metric.to_string(),
                    steps: band.steps,
                    min: band.min,
                    max: band.max,
                    span: self.series.span(),
                }
            }),
        }
    }

    /// Takes up to `n` steps, keeping keyframes and every step's metrics; returns how many were
    /// taken. `now` reads a clock in milliseconds: keyframes that cost more than
    /// [`KEYFRAME_TIME_SHARE`] of the stepping time it measures are kept further apart. The cost
    /// is judged at every keyframe, so one long call (a benchmark's, or a fast run's frame) adapts
    /// as it goes; the clock is read only at keyframe steps.
    pub fn advance(&mut self, n: u64, now: &mut dyn FnMut() -> f64) -> u64 {
        let mut taken = 0;
        let mut mark = now();
        let run = self.run.as_mut().expect("a playback always holds its run");
        while taken < n && run.step() {
            if run.steps() % self.timeline.keyframes().1 == 0 {
                let t = now();
                self.cost.total += t - mark;
                mark = t;
                if self.timeline.record(run) {
                    mark = now();
                    self.cost.copying += mark - t;
                    self.cost.total += mark - t;
                    self.cost.copies += 1;
                    if let Some(every) = self.cost.needs_interval(self.timeline.keyframes().1) {
                        while self.timeline.keyframes().1 < every {
                            self.timeline.coarsen();
                        }
                    }
                }
            }
            self.cost.steps += 1;
            // Steps passed through again after going back are already recorded: the series
            // skips them before reading a metric.
            self.series.record_model(run.steps(), run.model());
            taken += 1;
        }
        self.cost.total += now() - mark;
        self.furthest = self.furthest.max(run.steps());
        taken
    }

    /// Goes to `step` (at most the furthest step reached) by replaying from the keyframe before
    /// it, or on from the step at hand when that is nearer: the state is bit-identical to the one
    /// passed through. Going back frees the state at hand before building the one sought.
    pub fn seek(&mut self, step: u64) {
        let step = step.min(self.furthest);
        let at = self.run().steps();
        if at <= step && self.timeline.replay_from(step) <= at {
            self.run_mut().advance(step - at);
            return;
        }
        let scenario = self.run().scenario().clone();
        self.run = None;
        self.run = Some(self.timeline.seek(step, &scenario));
    }

    /// Applies an action now (a click tool) and records it in the scenario. A click in the past
    /// forks the run: what was clicked later is discarded, the scenario's own disturbances stay,
    /// and the timeline and the series end at the click. Tried on a copy, so a refused click
    /// changes nothing.
    ///
    /// In an exercise, a click the exercise does not allow (its kind not allowed, or all of its
    /// kind used) is refused before anything happens, with the reason.
    pub fn apply(&mut self, action: Action) -> Result<()> {
        let now = self.run().steps();
        self.allowed(&action, now)?;
        if now >= self.furthest {
            self.run_mut().apply_now(action)?;
        } else {
            let mut scenario = self.run().scenario().clone();
            let authored = &self.authored;
            scenario
                .disturbances
                .retain(|d| d.at <= now || authored.contains(d));
            let mut fork = self.run().snapshot();
            fork.reschedule(&scenario);
            fork.apply_now(action)?;
            self.run = Some(fork);
        }
        self.timeline.truncate(now);
        self.series.truncate(now);
        self.furthest = now;
        Ok(())
    }
}

impl Playback {
    /// Whether the exercise in view lets a student add `action` at step `now`: the disturbances
    /// it would be added to are those before `now` and the scenario's own (a click in the past
    /// drops the later ones).
    fn allowed(&self, action: &Action, now: u64) -> Result<()> {
        let kind = action
            .get("kind")
            .and_then(serde_json::Value::as_str)
            .unwrap_or_default();
        let tools = self.run().model().layout().tools;
        let label = tools
            .iter()
            .find(|t| t.action.get("kind").and_then(serde_json::Value::as_str) == Some(kind))
            .map_or(kind, |t| t.label.as_str());
        match self.click_state_at(kind, label, now).0 {
            Some(why) => Err(crate::error::Error::field("", why)),
            None => Ok(()),
        }
    }

    /// What the exercise in view says of a click of `kind` (the tool `label`) made now, as
    /// [`Playback::apply`] judges it: why it is refused (`None` when it may be made), and how
    /// many more of its kind may be added (`None` when no exercise is in view). A click rewound
    /// past (made at a later step) no longer counts: a click now drops it.
    pub fn click_state(&self, kind: &str, label: &str) -> (Option<String>, Option<u32>) {
        self.click_state_at(kind, label, self.run().steps())
    }

    fn click_state_at(&self, kind: &str, label: &str, now: u64) -> (Option<String>, Option<u32>) {
        let scenario = self.run().scenario();
        let Some(exercise) = &scenario.exercise else {
            return (None, None);
        };
        let list: Vec<serde_json::Value> = scenario
            .disturbances
            .iter()
            .filter(|d| d.at <= now || self.authored.contains(d))
            .map(crate::scenario::Disturbance::to_value)
            .collect();
        let left = exercise
            .allowed(kind)
            .saturating_sub(exercise.added(kind, &list));
        (exercise.click_problem(kind, label, &list), Some(left))
    }
}

/// Keyframes a run on a lattice of `dims` may keep within [`KEYFRAME_BYTES`]: 0 when one copy of
/// its state is estimated over the budget, at most [`KEYFRAME_COUNT`].
pub fn keyframe_capacity(dims: [u32; 3]) -> usize {
    let [w, h, d] = dims.map(|n| n.max(1) as usize);
    let per_frame = KEYFRAME_CELL_BYTES * w * h * d + 4096;
    (KEYFRAME_BYTES / per_frame).min(KEYFRAME_COUNT)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{presets, Scenario};

    fn amas_l() -> Playback {
        Playback::new(Run::new(presets::scenario("amas-L").unwrap()).unwrap())
    }

    fn action(text: &str) -> Action {
        match serde_json::from_str(text).unwrap() {
            serde_json::Value::Object(map) => map,
            _ => unreachable!(),
        }
    }

    fn no_clock() -> impl FnMut() -> f64 {
        || 0.0
    }

    /// The steps of the clicks the scenario in play holds, in order.
    fn click_steps(p: &Playback) -> Vec<u64> {
        p.run()
            .scenario()
            .disturbances
            .iter()
            .map(|d| d.at)
            .collect()
    }

    #[test]
    fn going_back_reaches_the_state_passed_through() {
        let mut p = amas_l();
        let mut hashes = vec![p.run().state_hash()];
        for _ in 0..120 {
            assert_eq!(p.advance(1, &mut no_clock()), 1);
            hashes.push(p.run().state_hash());
        }
        assert_eq!(p.furthest(), 120);
        for back in [0, 1, 15, 16, 17, 63, 119, 120] {
            p.seek(back);
            assert_eq!(p.run().steps(), back);
            assert_eq!(p.run().state_hash(), hashes[back as usize], "step {back}");
        }
        p.seek(500);
        assert_eq!(
            p.run().steps(),
            120,
            "a seek stops at the furthest step reached"
        );
    }

    #[test]
    fn a_click_in_the_past_forks_and_keeps_the_authored_disturbances() {
        let mut scenario: Scenario = presets::scenario("amas-L").unwrap();
        let authored = Disturbance {
            at: 90,
            action: action(r#"{"kind": "remove", "count": 1}"#),
        };
        scenario.disturbances = vec![authored.clone()];
        let mut p = Playback::new(Run::new(scenario).unwrap());
        p.advance(60, &mut no_clock());
        p.apply(action(r#"{"kind": "remove", "count": 2}"#))
            .unwrap();
        p.advance(40, &mut no_clock());
        let before_fork = p.run().state_hash();
        p.seek(30);
        p.apply(action(r#"{"kind": "remove", "count": 3}"#))
            .unwrap();
        assert_eq!(p.furthest(), 30, "the fork ends the timeline at the click");
        assert_eq!(p.series().last_step(), Some(30), "and the series");
        assert_eq!(
            click_steps(&p),
            [30, 90],
            "the later click is dropped, the authored one stays"
        );
        p.advance(70, &mut no_clock());
        assert_eq!(p.run().steps(), 100);
        assert_ne!(
            p.run().state_hash(),
            before_fork,
            "the fork runs differently"
        );
    }

    /// A click of an allowance's last one, rewound past: the page asks the playback, which
    /// answers as its `apply` judges (the click at hand would drop the later one), so the tool is
    /// free again before the click's step and counted again once the run passes it.
    #[test]
    fn a_click_rewound_past_no_longer_counts_against_the_allowance() {
        let mut scenario: Scenario = presets::scenario("amas-L").unwrap();
        let mut doc = scenario.to_value();
        doc["exercise"] = serde_json::json!({
            "title": "One removal", "instructions": "", "goal": "completed",
            "disturbances": {"remove": 1}, "hints": []
        });
        scenario = Scenario::from_value(doc).unwrap();
        let mut p = Playback::new(Run::new(scenario).unwrap());
        let remove = || action(r#"{"kind": "remove", "count": 1}"#);
        assert_eq!(p.click_state("remove", "Remove"), (None, Some(1)));
        p.advance(40, &mut no_clock());
        p.apply(remove()).unwrap();
        p.advance(20, &mut no_clock());
        assert_eq!(p.click_state("remove", "Remove").1, Some(0));
        assert!(p.apply(remove()).is_err(), "the allowance is used");
        p.seek(10);
        assert_eq!(
            p.click_state("remove", "Remove"),
            (None, Some(1)),
            "rewound past, the click no longer counts"
        );
        p.advance(35, &mut no_clock());
        assert_eq!(
            p.click_state("remove", "Remove").1,
            Some(0),
            "played past it again, it counts"
        );
        p.seek(10);
        p.apply(remove()).unwrap();
        assert_eq!(
            click_steps(&p),
            [10],
            "the click made after rewinding replaced the later one"
        );
        assert_eq!(p.click_state("remove", "Remove").1, Some(0));
    }

    #[test]
    fn a_refused_click_changes_nothing() {
        let mut p = amas_l();
        p.advance(50, &mut no_clock());
        p.seek(20);
        let hash = p.run().state_hash();
        assert!(p.apply(action(r#"{"kind": "bogus"}"#)).is_err());
        assert_eq!(p.run().state_hash(), hash);
        assert_eq!(p.furthest(), 50, "the timeline is untouched");
    }

    #[test]
    fn keyframes_that_cost_too_much_time_are_kept_further_apart() {
        // A clock that moves 5 ms at every reading: each keyframe copy seems to take 5 ms, a
        // quarter or more of the time measured, far above the share, so the interval doubles.
        let mut p = amas_l();
        let every = p.keyframes().1;
        let mut t = 0.0;
        let mut clock = || {
            t += 5.0;
            t
        };
        p.advance(4 * KEYFRAME_EVERY, &mut clock);
        assert!(
            p.keyframes().1 > every,
            "interval {} stayed",
            p.keyframes().1
        );

        // With a clock that never moves, the interval stays.
        let mut q = amas_l();
        q.advance(4 * KEYFRAME_EVERY, &mut no_clock());
        assert_eq!(q.keyframes().1, every);
    }

    #[test]
    fn keyframes_stay_within_their_memory_budget() {
        let per_cell = |dims: [u32; 3]| {
            let cells: usize = dims.iter().map(|&n| n.max(1) as usize).product();
            keyframe_capacity(dims) * KEYFRAME_CELL_BYTES * cells
        };
        assert_eq!(keyframe_capacity([28, 28, 0]), KEYFRAME_COUNT);
        for dims in [
            [512, 512, 0],
            [1024, 1024, 0],
            [2048, 2048, 0],
            [64, 64, 64],
        ] {
            assert!(per_cell(dims) <= KEYFRAME_BYTES, "{dims:?}");
            assert!(keyframe_capacity(dims) >= 1, "{dims:?} keeps its start");
        }
        assert_eq!(
            keyframe_capacity([4096, 4096, 0]),
            0,
            "one copy of 16 M cells is over the budget: no keyframe at all"
        );
    }

    #[test]
    fn going_forward_steps_on_from_the_state_at_hand() {
        let mut p = amas_l();
        p.advance(100, &mut no_clock());
        p.seek(40);
        let hash = {
            let mut q = amas_l();
            q.advance(70, &mut no_clock());
            q.run().state_hash()
        };
        p.seek(70);
        assert_eq!(p.run().steps(), 70);
        assert_eq!(p.run().state_hash(), hash);
    }

    #[test]
    fn every_step_is_in_the_series_once_even_after_going_back() {
        let mut p = amas_l();
        p.advance(40, &mut no_clock());
        p.seek(10);
        p.advance(30, &mut no_clock());
        assert_eq!(p.series().last_step(), Some(40));
        assert_eq!(p.series().len(), 41, "steps 0 to 40, each once");
    }
}
