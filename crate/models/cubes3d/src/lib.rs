//! Cubes3d: identical units on the cubic lattice reconfiguring themselves toward a target given
//! as type-lists, by pairwise motion and stochastic relaxation (Yoshida, Murata, Kurokawa, Tomita
//! and Kokaji, "A distributed reconfiguration method for 3-D homogeneous structure", sections 2 to
//! 6; and section 5 of "Experiment of self-repairing modular machine"). See
//! `crate/models/cubes3d/README.md` for the ODD description and every interpretation made.
//!
//! - [`types`]: the connection types and the distances between them; [`typelist`]: type-lists,
//!   their text form, and the unique description of a shape;
//! - [`motion`]: the structure and the pairwise motion; `connect`: its connectivity rule;
//! - `spec`: the scenario keys, their defaults and checks; `init`: building the model; `state`:
//!   the per-cell books every phase reads; `light`: positions along the light;
//! - one file per step phase, in order: `choose` (the units choose and one moves, each by the
//!   selection rule of `select`, the rule slot `select` a scenario's script may take), `switch`
//!   (each unit switches its own target);
//! - `view` and this module's [`Model`] implementation: the outputs; `actions`: disturbances and
//!   clicks; [`queries`]: helper calls for the editors; [`paper`]: the claims for the
//!   reproduction report.

use std::borrow::Cow;
use std::rc::Rc;

use serde_json::{Map, Value};

use kumiki_model::entry::{self, ModelEntry, Pin, PinValue, Query};
use kumiki_model::error::Result;
use kumiki_model::hash::StateHasher;
use kumiki_model::model::{Action, Agent, Event, Layout, Metric, Model, Scene};
use kumiki_model::rng::Rng;
use kumiki_model::slot::Script;

mod actions;
mod choose;
pub mod connect;
mod init;
mod light;
pub mod limits;
pub mod metrics;
pub mod motion;
pub mod paper;
pub mod queries;
mod select;
mod spec;
mod state;
mod switch;
pub mod typelist;
pub mod types;
mod view;

use connect::Scratch;
use motion::Structure;
pub use queries::{query_check, query_derive};
pub use spec::{Checked, Clock, Ground, Log, Priority, Selection, Spec, TargetSpec};
use types::CODES;

pub const ENTRY: ModelEntry = ModelEntry {
    name: "cubes3d",
    title: "3-D units: type-list targets and stochastic relaxation",
    default_max_steps: 5000,
    // 5: the light's priority on each unit's positions, each unit's clock restarting at its
    // switch of target (section 6), and "no motion" among random selection's options.
    model_version: 5,
    metrics: metrics::METRICS,
    limits: &limits::LIMITS,
    parse: entry::parse::<Spec>,
    schema: entry::schema_of::<Spec>(),
    disturbance: entry::schema_of::<actions::ActionSpec>(),
    slots: &[<select::Select as kumiki_model::slot::Slot>::INFO],
    queries: &[
        Query {
            name: "derive",
            description: "The type-lists of a shape: {\"shape\": cubic layers} or {\"units\": [[x, y, z], ...]}",
            run: query_derive,
        },
        Query {
            name: "check",
            description: "Checks type-lists ({\"type_lists\": text}) and returns them in normal form",
            run: query_check,
        },
    ],
    // Links made before version 5 replay with the readings they were made with.
    pins: &[
        Pin {
            before: 5,
            key: "priority",
            value: PinValue::Choice("units"),
        },
        Pin {
            before: 5,
            key: "clock",
            value: PinValue::Choice("run"),
        },
        Pin {
            before: 5,
            key: "random_stays",
            value: PinValue::Switch(false),
        },
    ],
};

/// The most targets any limits allow: target numbers fit the per-cell byte and a counting array.
const MAX_TARGETS: usize = crate::limits::LIMITS.large.targets;

/// Event kinds.
const ARRIVED: u8 = 0;
const LEFT: u8 = 1;

/// Per-cell flags that travel with a unit.
const HELD_LIT: u8 = 1;
const HELD_USER: u8 = 2;

/// A target: its type-lists (unit type and six padded neighbour slots each) and a shape to draw
/// as a ghost when the scenario gave one.
#[derive(Clone)]
struct Target {
    name: String,
    lists: Vec<[u8; 7]>,
    ghost: Vec<u32>,
    threshold: f64,
    hold_lit: bool,
}

#[derive(Clone)]
pub struct Cubes {
    st: Structure,
    /// Flags per cell (`HELD_*`), moving with their unit.
    flags: Vec<u8>,
    /// The units' cells; a unit keeps its place in this list when it moves.
    units: Vec<u32>,
    /// Each cell's place in `units` (`u32::MAX` where there is no unit).
    upos: Vec<u32>,
    /// D_0 of each unit, in the order of `units` (NaN for a moment while it moves). Kept per
    /// unit rather than per cell so that a keyframe copies little beyond the cell types.
    diff: Vec<f64>,
    /// Units that may be chosen to move: of a movable type, not fixed, not held.
    movable: Vec<u32>,
    mpos: Vec<u32>,
    movable_types: u16,
    targets: Vec<Target>,
    /// The target each unit is working toward (section 6: each unit switches its own), per
    /// cell, moving with the unit.
    target: Vec<u8>,
    /// Consecutive steps each unit's D_0 has stayed under its target's threshold, in the order
    /// of `units`.
    stable: Vec<u32>,
    /// The step after which each unit took up its current target (0 for the start), in the
    /// order of `units`: its clock of equation 8 with `clock` "target".
    took: Vec<u64>,
    table: [[f64; CODES]; CODES],
    w: f64,
    /// Every D_0 is a whole number small enough that their sum is exact in any order (the
    /// default W and a are): [`Cubes::total_difference`] then adds in several lanes at once.
    whole_diffs: bool,
    c: f64,
    log: Log,
    clock: Clock,
    /// T of this step on the run's clock.
    run_temperature: f64,
    selection: Selection,
    random_stays: bool,
    priority: Priority,
    movers: u32,
    mover_distance: u32,
    ground: Ground,
    /// The lowest layer units may occupy.
    floor_z: i32,
    light: Option<usize>,
    stable_steps: u32,
    /// End the run when the single target is complete (`stop_at_goal`).
    stop_at_goal: bool,
    /// The first step after which the single target was complete, if it has been.
    reached: Option<u64>,
    /// The most units the structure may grow to by added units.
    max_units: usize,
    /// Target switches made by units, all together.
    switches: u64,
    /// Offsets of the cells within Manhattan distance 2.
    near2: Vec<isize>,
    rng: Rng,
    steps: u64,
    moves: u64,
    /// With a light: moves that ended nearer the light, and moves that ended farther from it.
    moves_toward: u64,
    moves_away: u64,
    /// Units whose D_0 is exactly 0.
    zero: usize,
    /// Centre of mass along the light at the start.
    start_light: f64,
    scratch: Scratch,
    /// The movable units in this step's random order.
    order: Vec<u32>,
    /// Moves chosen this step that do not approach the light, in the order they were chosen.
    deferred: Vec<(u32, u32)>,
    /// Cells the units that moved this step arrived at.
    arrived: Vec<u32>,
    /// What the unit choosing senses, kept from one choice to the next.
    senses: select::Senses,
    /// The selection rule: the paper's, or a scenario's script (the slot `select`).
    select: kumiki_model::slot::Rule<select::Select>,
    /// Why a script stopped the run, once one did.
    stopped: Option<String>,
    events: Vec<Event>,
}

impl Model for Cubes {
    fn layout(&self) -> Layout {
        self.describe_layout()
    }

    fn scene(&self) -> Scene {
        self.describe_scene()
    }

    /// Every pair of face-adjacent units is bonded (a unit connects to all its neighbours).
    fn bonds(&self) -> Cow<'_, [u8]> {
        self.bond_masks()
    }

    fn step(&mut self) {
        self.events.clear();
        self.run_temperature = self.temperature_at(self.steps + 1);
        let mut s = std::mem::take(&mut self.scratch);
        let moved = self.move_units(&mut s);
        self.scratch = s;
        self.steps += 1;
        if let Err(stop) = moved {
            self.stopped = Some(stop.0);
            return;
        }
        if self.targets.len() > 1 {
            self.switch_targets();
        } else if self.reached.is_none() && self.zero == self.units.len() {
            self.reached = Some(self.steps);
        }
    }

    fn install(&mut self, slot: &str, script: Rc<dyn Script>) -> Result<()> {
        match slot {
            "select" => {
                self.select.install(script);
                Ok(())
            }
            _ => Err(kumiki_model::Error::field(
                format!("rules.{slot}"),
                "cubes3d has one rule slot: select",
            )),
        }
    }

    fn stopped(&self) -> Option<&str> {
        self.stopped.as_deref()
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        self.stop_at_goal && self.targets.len() == 1 && self.zero == self.units.len()
    }

    fn each_metric(&self, f: &mut dyn FnMut(&'static str, Metric)) {
        self.each_metric_value(f);
    }

    fn hash_state(&self, h: &mut StateHasher) {
        h.bytes(&self.st.types);
        h.bytes(&self.flags);
        for &u in &self.units {
            h.u32(u);
        }
        for &u in &self.movable {
            h.u32(u);
        }
        h.bytes(&self.target);
        for &s in &self.stable {
            h.u32(s);
        }
        // The clocks count only with the per-target clock and two or more targets; the run's
        // clock is the step count.
        if self.targets.len() > 1 && self.clock == Clock::Target {
            for &t in &self.took {
                h.u64(t);
            }
        }
        h.u64(self.switches);
        h.u64(self.reached.map_or(0, |s| s + 1));
        h.u64(self.moves);
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        Cow::Borrowed(&self.st.types)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        self.field_values(name)
    }

    fn agents(&self) -> Vec<Agent> {
        Vec::new()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        self.check(action)
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        self.perform(action)
    }

    fn inspect(&self, i: usize) -> Map<String, Value> {
        self.inspect_cell(i)
    }
}

#[cfg(test)]
mod tests;
