//! AMAS: assembler robots carrying modules along a gradient field the modules compute among
//! themselves (Terada & Murata, sections 4 to 6 and appendices A and B). See
//! `crate/models/amas/README.md` for the ODD description and every interpretation made.

use std::borrow::Cow;
use std::collections::BTreeMap;

use serde_json::{Map, Value};

use kumiki_model::entry::{self, ModelEntry, Pin, PinValue};
use kumiki_model::error::Result;
use kumiki_model::hash::StateHasher;
use kumiki_model::model::{Action, Agent, Event, Layout, Metric, Model};
use kumiki_model::rng::Rng;
use kumiki_model::slot::{Rule, Script};

mod act;
mod actions;
mod collision;
mod conflicts;
mod direction;
mod field;
mod init;
pub mod limits;
pub mod metrics;
pub mod paper;
mod plan;
mod settle;
mod spec;
mod state;
mod view;

pub use spec::{Collision, Communication, Direction, FieldKind, GiveWay, RelayWith, Spec};

use field::Field;
use spec::Params;

pub const ENTRY: ModelEntry = ModelEntry {
    name: "amas",
    title: "AMAS: assembler robots on a gradient field",
    default_max_steps: 100_000,
    // 3: the module displays one direction (footnote 3) and only a locked loser gives way (4.6).
    // 4: a robot waiting out a collision penalty may relay (4.6.1).
    model_version: 4,
    metrics: metrics::METRICS,
    limits: &limits::LIMITS,
    parse: entry::parse::<Spec>,
    schema: entry::schema_of::<Spec>(),
    disturbance: entry::schema_of::<actions::Raw>(),
    slots: &[
        <direction::DirectionRule as kumiki_model::slot::Slot>::INFO,
        <collision::CollisionRule as kumiki_model::slot::Slot>::INFO,
    ],
    queries: &[],
    // Links made before a version replay with the readings they were made with.
    pins: &[
        Pin {
            before: 3,
            key: "direction",
            value: PinValue::Choice("robot"),
        },
        Pin {
            before: 3,
            key: "give_way",
            value: PinValue::Choice("every_loser"),
        },
        Pin {
            before: 4,
            key: "relay_with",
            value: PinValue::Choice("idle"),
        },
    ],
};

const NONE: u32 = u32::MAX;

/// Robot kinds in the agent list.
const UNLOADED: u8 = 0;
const LOADED: u8 = 1;
const UNLOADED_LOST: u8 = 2;
const LOADED_LOST: u8 = 3;
/// Event kinds.
const EV_COLLISION: u8 = 0;
const EV_RELAY: u8 = 1;

/// Random streams: robots' choices, initial placement, disturbances.
const STREAM_PLACEMENT: u64 = 1;
const STREAM_DISTURBANCE: u64 = 2;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Robot {
    cell: u32,
    loaded: bool,
    /// Further steps the current action (or collision penalty) still takes.
    busy: u32,
    /// Gives way: avoids occupied modules at its next plan (4.6; see [`collision`]).
    give_way: bool,
    /// The cell it wanted when it last collided, while it pays the penalty ([`NONE`] once it
    /// plans again): a lock holds a robot waiting out a longer penalty too.
    waiting_for: u32,
    /// Moved at random at its last plan: no effective gradient (footnote 3).
    lost: bool,
    /// The highest row (smallest y) it has stood on.
    top: u32,
    /// It has placed a module on the corner row or above it (figure 24).
    placed_past_corner: bool,
    /// The direction it faces (see [`Amas::heading_to`]): a move another way turns first.
    heading: u8,
}

/// Robots start facing up, towards the structure.
const UP: u8 = 1;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Plan {
    /// Still doing an earlier action.
    Busy,
    Wait,
    /// Take a module from the conveyor.
    Pick,
    /// Take the module to be removed at this cell (section 6.2).
    Remove(u32),
    Place(u32),
    /// Hand the module back to the supply (the target is full, modules are still to go).
    Return,
    Move(u32),
    /// Wanted this cell, but a robot with a larger token claimed it first.
    Blocked(u32),
}

/// Move resolution states.
const UNKNOWN: u8 = 0;
const VISITING: u8 = 1;
const MOVES: u8 = 2;
const STAYS: u8 = 3;

#[derive(Clone)]
pub struct Amas {
    w: usize,
    h: usize,
    /// First row of the supply area.
    supply_top: usize,
    state: Vec<u8>,
    display: Vec<u8>,
    /// Robot standing on each cell, or NONE.
    occupant: Vec<u32>,
    field: Field,
    p: Params,
    robots: Vec<Robot>,
    /// Planning order of this step: earlier is a larger token.
    order: Vec<u32>,
    plans: Vec<Plan>,
    planned: Vec<bool>,
    status: Vec<u8>,
    relaying: Vec<bool>,
    position: Vec<u32>,
    claimed: Vec<u32>,
    /// Scratch list of robots along a chain of moves.
    chain: Vec<u32>,
    /// Scratch: the robots that could not do what they planned this step, with the cell each
    /// wanted and why, and which of them give way as the smaller token of a lock.
    losers: Vec<(u32, u32, collision::Conflict)>,
    /// What a robot that lost a collision does: the paper's rule, or a scenario's script (the
    /// slot `collision`).
    collision_rule: Rule<collision::CollisionRule>,
    /// What the module under a robot shows it: the paper's rule, or a scenario's script (the
    /// slot `direction`).
    direction_rule: Rule<direction::DirectionRule>,
    /// Why a script stopped the run, once one did.
    stopped: Option<String>,
    yielding: Vec<bool>,
    /// Scratch: the robot each robot waits on this step, and its lock bits (`conflicts.rs`).
    ahead: Vec<u32>,
    lock: Vec<u8>,
    rng: Rng,
    disturb_rng: Rng,
    /// Modules to be removed that the connection rule lets go now (a bit set over all cells):
    /// their neighbours are the supply area.
    releasable: Vec<u64>,
    /// The structure changed since `releasable` was computed.
    dirty: bool,
    /// Some module to be removed may go now: the disassembly area is the module supply and
    /// the conveyor stops offering modules, so dismantled modules are reused (section 6).
    reuse: bool,
    /// Stage targets as bit sets over the rows above the supply, the final target last.
    stages: Vec<Vec<u64>>,
    stage: usize,
    /// The target is full but modules are still to be removed: the supply takes them back.
    return_mode: bool,
    /// First row holding a module: rows above it hold no field values.
    top: usize,
    target_cells: u64,
    vacant: u64,
    to_remove: u64,
    steps: u64,
    collisions: u64,
    relays: u64,
    placed: u64,
    picked: u64,
    dismantled: u64,
    returned: u64,
    removed: u64,
    broken: u64,
    lower_bound: u64,
    path_bound: u64,
    /// Figure 24: the lowest row where the final target narrows (the corner robots pass to
    /// reach the narrower part), or its top row if it never narrows.
    corner_row: u32,
    corner_relays: u64,
    /// Collisions per cell (the cell a penalised robot wanted): the heat map. Only cells that
    /// saw a collision are kept, so a large lattice pays nothing per cell for it.
    collision_cells: BTreeMap<u32, u32>,
    /// Collisions on the corner row or the row below it (figure 24's corner), above those
    /// rows, and on the supply rows.
    corner_collisions: u64,
    above_corner_collisions: u64,
    supply_collisions: u64,
    /// Collisions between a loaded and an unloaded robot, between two loaded robots and between
    /// two unloaded ones (appendix A.1), by their loads when they planned.
    mixed_collisions: u64,
    loaded_collisions: u64,
    unloaded_collisions: u64,
    /// Plans made with no effective gradient (footnote 3) or on a broken module: the robot
    /// picked its way at random.
    wandering: u64,
    events: Vec<Event>,
}

impl Amas {
    #[inline]
    fn neighbours(&self, i: usize) -> ([usize; 4], usize) {
        let (w, x, y) = (self.w, i % self.w, i / self.w);
        let mut out = [0; 4];
        let mut k = 0;
        if x + 1 < w {
            out[k] = i + 1;
            k += 1;
        }
        if y > 0 {
            out[k] = i - w;
            k += 1;
        }
        if x > 0 {
            out[k] = i - 1;
            k += 1;
        }
        if y + 1 < self.h {
            out[k] = i + w;
            k += 1;
        }
        (out, k)
    }
}

impl Model for Amas {
    fn layout(&self) -> Layout {
        self.describe_layout()
    }

    fn step(&mut self) {
        self.events.clear();
        if let Err(stop) = self.plan_all().and_then(|()| self.settle_conflicts()) {
            self.stopped = Some(stop.0);
            self.steps += 1;
            return;
        }
        self.act_all();
        self.settle();
        for _ in 0..self.p.updates {
            self.field.update(&self.state, self.w, self.top);
        }
        self.steps += 1;
    }

    fn install(&mut self, slot: &str, script: std::rc::Rc<dyn Script>) -> Result<()> {
        match slot {
            "collision" => self.collision_rule.install(script),
            "direction" => self.direction_rule.install(script),
            _ => {
                return Err(kumiki_model::error::Error::field(
                    format!("rules.{slot}"),
                    "amas has two rule slots: direction and collision",
                ))
            }
        }
        Ok(())
    }

    fn stopped(&self) -> Option<&str> {
        self.stopped.as_deref()
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        self.stage + 1 == self.stages.len() && self.vacant == 0 && self.to_remove == 0
    }

    fn each_metric(&self, f: &mut dyn FnMut(&'static str, Metric)) {
        let robots = self.robots.len();
        f("steps", Metric::Count(self.steps));
        f("total_steps", Metric::Count(self.steps * robots as u64));
        f("collisions", Metric::Count(self.collisions));
        f("relays", Metric::Count(self.relays));
        f("corner_relays", Metric::Count(self.corner_relays));
        f("corner_collisions", Metric::Count(self.corner_collisions));
        f(
            "above_corner_collisions",
            Metric::Count(self.above_corner_collisions),
        );
        f("supply_collisions", Metric::Count(self.supply_collisions));
        f("mixed_collisions", Metric::Count(self.mixed_collisions));
        f("loaded_collisions", Metric::Count(self.loaded_collisions));
        f(
            "unloaded_collisions",
            Metric::Count(self.unloaded_collisions),
        );
        f("wandering", Metric::Count(self.wandering));
        f("lower_bound", Metric::Count(self.lower_bound));
        f("path_bound", Metric::Count(self.path_bound));
        f("built", Metric::Real(self.built_fraction()));
        f("placed", Metric::Count(self.placed));
        f("picked", Metric::Count(self.picked));
        f("dismantled", Metric::Count(self.dismantled));
        f("returned", Metric::Count(self.returned));
        f("removed", Metric::Count(self.removed));
        f("broken", Metric::Count(self.broken));
        f("stage", Metric::Count(self.stage as u64 + 1));
        let below = self
            .robots
            .iter()
            .filter(|r| r.top > self.corner_row)
            .count();
        f(
            "never_past_corner",
            Metric::Real(below as f64 / robots as f64),
        );
        let assemblers = self.robots.iter().filter(|r| r.placed_past_corner).count();
        f(
            "corner_assemblers",
            Metric::Real(assemblers as f64 / robots as f64),
        );
    }

    fn hash_state(&self, h: &mut StateHasher) {
        h.bytes(&self.state);
        match &self.field {
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => {
                h.u16s(to_supply);
                h.u16s(to_front);
            }
            Field::Continuous { p, .. } => h.f32s(p),
        }
        for r in &self.robots {
            h.u32(r.cell);
            h.bool(r.loaded);
            h.u32(r.busy);
            h.bool(r.give_way);
            // Only locks read it, and only where locked robots alone give way.
            if self.p.give_way == GiveWay::Locked {
                h.u32(r.waiting_for);
            }
            // The heading only matters, and only enters the hash, when turns take time.
            if self.p.turn_d > 0 {
                h.u8(r.heading);
            }
        }
        for v in [
            self.collisions,
            self.relays,
            self.placed,
            self.picked,
            self.dismantled,
            self.returned,
            self.removed,
            self.broken,
            self.stage as u64,
        ] {
            h.u64(v);
        }
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        self.cell_codes()
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        self.field_values(name)
    }

    fn agents(&self) -> Vec<Agent> {
        self.agent_list()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        actions::parse(action, self.state.len()).map(|_| ())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        let a = self.check(action)?;
        self.perform(&a);
        Ok(())
    }

    fn inspect(&self, i: usize) -> Map<String, Value> {
        self.inspect_cell(i)
    }
}

#[cfg(test)]
mod tests;
