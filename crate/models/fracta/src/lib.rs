//! Fracta: identical hexagonal units that assemble into a goal shape and repair it after a
//! fault, by the difference-based algorithm of Yoshida, Murata, Tomita, Kurokawa and Kokaji
//! (sections 3 and 4). See `crate/models/fracta/README.md` for the ODD description and every
//! interpretation made.
//!
//! - `pattern`: bond patterns, their symmetries and the roll; [`types`]: the 12 connection
//!   types (classes of patterns), which can move, and the distances between them (`links`: the
//!   type graph);
//! - [`goal`]: goal statements, their text form, "derive from shape", and the difference;
//! - `spec`: the scenario keys, their defaults and checks; `init`: building the model and the
//!   per-unit data every phase reads;
//! - one file per step phase, in order: `faults` (OK signals and cut-off), `diffuse`
//!   (equations 2 to 5), `plan` (legal motions and the choice of direction), `commit` (rolls
//!   carried out, conflicts cancelled); `activation` and `roll`: the rule slots a scenario's
//!   script may take, equation 3 with condition 5 and the choice of direction;
//! - `view` and this module's [`Model`] implementation: the outputs; `actions`: faults;
//!   [`queries`]: helper calls for the editors; [`paper`]: the claims for the reproduction
//!   report; [`search`]: the fewest motions a repair needs, beside them.

use std::borrow::Cow;
use std::collections::VecDeque;
use std::rc::Rc;

use serde::{Deserialize, Serialize};
use serde_json::{json, Map, Value};

use kumiki_model::entry::{self, ModelEntry};
use kumiki_model::error::{Error, Result};
use kumiki_model::hash::StateHasher;
use kumiki_model::lattice::{Hex, Lattice, LatticeKind};
use kumiki_model::model::{
    self, Action, Agent, Event, FieldInfo, Layout, LegendEntry, Metric, Model, ToolInfo,
};
use kumiki_model::rng::Rng;
use kumiki_model::shape;
use kumiki_model::slot::{Rule, Script, Stop};

mod actions;
mod activation;
mod commit;
mod derive;
mod diffuse;
mod faults;
pub mod goal;
mod init;
pub mod limits;
mod links;
pub mod metrics;
pub mod paper;
mod pattern;
mod plan;
pub mod queries;
mod roll;
pub mod search;
mod spec;
pub mod types;
mod view;

use actions::Fault;
use goal::{Goal, Priorities};
use pattern::{far_steps, swept_slots, target_slot, Turn};
pub use spec::{defaults, Spec};
use spec::{params, Params};
use types::{types, Types};

pub const ENTRY: ModelEntry = ModelEntry {
    name: "fracta",
    title: "Fracta: hexagonal self-assembly and self-repair",
    default_max_steps: 20_000,
    model_version: 7,
    metrics: metrics::METRICS,
    limits: &limits::LIMITS,
    parse: entry::parse::<Spec>,
    schema: entry::schema_of::<Spec>(),
    disturbance: entry::schema_of::<actions::FaultAction>(),
    slots: &[
        <activation::Activation as kumiki_model::slot::Slot>::INFO,
        <roll::Roll as kumiki_model::slot::Slot>::INFO,
    ],
    queries: &[
        entry::Query {
            name: "derive",
            description: "Goal statements of a hex shape ({\"shape\": text}); shapes separated by '---' give priorities 1, 2, ...",
            run: queries::derive,
        },
        entry::Query {
            name: "check",
            description: "Checks goal statements ({\"goal\": text}) and returns them in normal form",
            run: queries::check,
        },
        entry::Query {
            name: "types",
            description: "The connection types: name, ASCII spelling, bonds, movable, colour",
            run: queries::types,
        },
    ],
    pins: &[],
};

/// Cell codes beyond the connection types (codes 1 to 12 are the type classes, see
/// [`types::Types::info`]).
pub mod code {
    pub const EMPTY: u8 = 0;
    /// A unit whose power failed: it sends no "OK" and is cut off at the start of the next step.
    pub const FAULTY: u8 = 13;
    /// Where a faulty unit was cut off and taken away (drawn until a unit moves in).
    pub const CUT_OFF: u8 = 14;
    /// Where a unit was that a cut-off separated from the rest of the system.
    pub const STRANDED: u8 = 15;
}

/// Event kinds.
pub mod event {
    pub const MOVED: u8 = 0;
    pub const CONFLICT: u8 = 1;
    pub const IRRITATED: u8 = 2;
    pub const CUT_OFF: u8 = 3;
}

const NO_UNIT: u32 = u32::MAX;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Status {
    Working,
    /// Power cut; still in place until its neighbours notice.
    Faulty,
    CutOff,
    Stranded,
}

#[derive(Clone, Copy, Debug)]
struct Unit {
    cell: u32,
    status: Status,
    /// The diffusion variable x (equation 2).
    x: f64,
    /// Irritation (equation 4).
    irr: f64,
}

/// A planned roll.
#[derive(Clone, Copy, Debug)]
struct Plan {
    unit: u32,
    pivot: u32,
    pivot_slot: u8,
    turn: Turn,
}

#[derive(Clone)]
pub struct Fracta {
    lattice: Hex,
    /// Neighbour cell of each cell in each direction, or `NO_UNIT` outside the lattice.
    nbr: Vec<[u32; 6]>,
    /// The unit on each cell (working or faulty), or `NO_UNIT`.
    occ: Vec<u32>,
    /// Display marks of units taken away ([`code::CUT_OFF`], [`code::STRANDED`]).
    ghost: Vec<u8>,
    units: Vec<Unit>,
    /// Ids of the working units, ascending.
    working: Vec<u32>,
    goal: Goal,
    p: Params,
    rng: Rng,
    steps: u64,
    // Per unit, refreshed after every change: neighbour mask, type, difference, closest statement.
    mask: Vec<u8>,
    class: Vec<u8>,
    diff: Vec<u32>,
    /// Each working unit's difference when the diffusion phase last ran: irritation grows
    /// only while it stays the same.
    last_diff: Vec<u32>,
    closest: Vec<u16>,
    /// Working units with difference 0.
    zero: usize,
    /// Faulty units not yet cut off.
    pending: usize,
    // Scratch.
    new_x: Vec<f64>,
    /// Active units this step, each with whether its irritation fired (condition 5) rather
    /// than equation 3 activating it.
    active: Vec<(u32, bool)>,
    /// Scratch for the units a motion touches.
    touched: Vec<u32>,
    plans: Vec<Plan>,
    /// Equation 3 and condition 5: the paper's, or a scenario's script (the slot `activation`).
    activation: Rule<activation::Activation>,
    /// The choice of roll: the paper's, or a scenario's script (the slot `roll`).
    roll: Rule<roll::Roll>,
    /// Why a script stopped the run, once one did.
    stopped: Option<String>,
    busy: Vec<u64>,
    // Counters.
    moves: u64,
    conflicts: u64,
    irritations: u64,
    faults: u64,
    cut_off: u64,
    stranded: u64,
    last_fault: Option<u64>,
    events: Vec<Event>,
}

impl Fracta {
    /// A step's first half: faults are cut off, x diffuses, units are activated and plan. A
    /// script in a rule slot that stops ends it where it stopped.
    fn decide(&mut self) -> std::result::Result<(), Stop> {
        self.events.clear();
        self.cut_off_faulty();
        self.diffuse()?;
        self.plan()
    }

    /// A step's second half: the plans are carried out and the statements refreshed.
    fn act(&mut self) {
        self.commit();
        self.refresh();
        self.steps += 1;
    }
}

impl Model for Fracta {
    fn layout(&self) -> Layout {
        let t = types();
        let mut cells: Vec<LegendEntry> = t
            .info
            .iter()
            .enumerate()
            .skip(1)
            .map(|(c, info)| LegendEntry::new(c as u8, info.name, info.color))
            .collect();
        cells.push(LegendEntry::new(code::FAULTY, "faulty (no OK)", "#db3737"));
        cells.push(LegendEntry::new(code::CUT_OFF, "cut off", "#e4d7d7"));
        cells.push(LegendEntry::new(code::STRANDED, "stranded", "#d5d9de"));
        Layout {
            lattice: LatticeKind::Hex,
            dims: [self.lattice.w, self.lattice.h, 1],
            cells,
            agents: Vec::new(),
            events: vec![
                LegendEntry::new(event::MOVED, "rolled", "#2b95d6"),
                LegendEntry::new(event::CONFLICT, "roll cancelled (conflict)", "#f29d49"),
                LegendEntry::new(event::IRRITATED, "irritation fired", "#9b59b6"),
                LegendEntry::new(event::CUT_OFF, "cut off", "#db3737"),
            ],
            fields: vec![
                FieldInfo {
                    name: "difference".into(),
                    label: "difference to the closest statement".into(),
                    arrows: false,
                },
                FieldInfo {
                    name: "x".into(),
                    label: "diffusion variable x".into(),
                    arrows: false,
                },
                FieldInfo {
                    name: "irritation".into(),
                    label: "irritation".into(),
                    arrows: false,
                },
            ],
            tools: vec![ToolInfo {
                name: "fault".into(),
                label: "Fault (cut power)".into(),
                action: json!({"kind": "fault"})
                    .as_object()
                    .cloned()
                    .unwrap_or_default(),
            }],
            cell_labels: true,
            goal: true,
            chart: "mean_difference".into(),
        }
    }

    fn step(&mut self) {
        match self.decide() {
            Ok(()) => self.act(),
            Err(stop) => {
                self.stopped = Some(stop.0);
                self.steps += 1;
            }
        }
    }

    fn install(&mut self, slot: &str, script: Rc<dyn Script>) -> Result<()> {
        match slot {
            "activation" => self.activation.install(script),
            "roll" => self.roll.install(script),
            _ => {
                return Err(Error::field(
                    format!("rules.{slot}"),
                    "fracta has two rule slots: activation and roll",
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
        !self.working.is_empty() && self.pending == 0 && self.zero == self.working.len()
    }

    fn each_metric(&self, f: &mut dyn FnMut(&'static str, Metric)) {
        f("completed", Metric::Flag(self.completed()));
        f("steps", Metric::Count(self.steps));
        f("mean_difference", Metric::Real(self.mean_difference()));
        f("moves", Metric::Count(self.moves));
        f("conflicts", Metric::Count(self.conflicts));
        f("irritations", Metric::Count(self.irritations));
        f("units", Metric::Count(self.working.len() as u64));
        f("faults", Metric::Count(self.faults));
        f("cut_off", Metric::Count(self.cut_off));
        f("stranded", Metric::Count(self.stranded));
        f("holes", Metric::Count(self.holes()));
        // Missing until the goal is reached: from the start when there was no fault, from the
        // last fault when there was one.
        let done = self.completed();
        let (convergence, repair) = match self.last_fault {
            None if done => (Metric::Count(self.steps), Metric::Missing),
            Some(at) if done => (Metric::Missing, Metric::Count(self.steps - at)),
            _ => (Metric::Missing, Metric::Missing),
        };
        f("convergence_steps", convergence);
        f("repair_steps", repair);
    }

    fn hash_state(&self, h: &mut StateHasher) {
        for u in &self.units {
            h.u32(u.cell);
            h.u8(u.status as u8);
            h.f64(u.x);
            h.f64(u.irr);
        }
        for &d in &self.last_diff {
            h.u32(d);
        }
        h.u64(self.moves);
        h.u64(self.conflicts);
        h.u64(self.irritations);
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        let mut out = self.ghost.clone();
        for u in 0..self.units.len() {
            let unit = &self.units[u];
            match unit.status {
                Status::Working => out[unit.cell as usize] = self.class[u],
                Status::Faulty => out[unit.cell as usize] = code::FAULTY,
                Status::CutOff | Status::Stranded => {}
            }
        }
        Cow::Owned(out)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let value: fn(&Fracta, usize) -> f32 = match name {
            "difference" => |m, u| m.diff[u] as f32,
            "x" => |m, u| m.units[u].x as f32,
            "irritation" => |m, u| m.units[u].irr as f32,
            _ => return None,
        };
        let mut out = vec![f32::NAN; self.occ.len()];
        for &u in &self.working {
            out[self.units[u as usize].cell as usize] = value(self, u as usize);
        }
        Some(Cow::Owned(out))
    }

    fn agents(&self) -> Vec<Agent> {
        Vec::new()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn bonds(&self) -> Cow<'_, [u8]> {
        let mut out = vec![0u8; self.occ.len()];
        for u in &self.units {
            if matches!(u.status, Status::Working | Status::Faulty) {
                out[u.cell as usize] = self.ring(u.cell);
            }
        }
        Cow::Owned(out)
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        actions::parse_fault(action, self.occ.len(), self.units.len()).map(|_| ())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        let targets = match actions::parse_fault(action, self.occ.len(), self.units.len())? {
            Fault::Cells(cells) => cells
                .iter()
                .map(|&c| self.working_unit_at(c))
                .collect::<Result<Vec<u32>>>()?,
            Fault::Unit(u) if self.units[u as usize].status == Status::Working => vec![u],
            Fault::Unit(u) => return Err(Error::field("unit", format!("unit {u} is not working"))),
        };
        for u in targets {
            if self.units[u as usize].status == Status::Working {
                self.units[u as usize].status = Status::Faulty;
                self.pending += 1;
                self.faults += 1;
            }
        }
        self.working
            .retain(|&u| self.units[u as usize].status == Status::Working);
        self.last_fault = Some(self.steps);
        self.refresh();
        Ok(())
    }

    fn inspect(&self, cell: usize) -> Map<String, Value> {
        let t = types();
        let mut m = Map::new();
        if cell >= self.occ.len() {
            return m;
        }
        let c = self.lattice.coord(cell);
        m.insert("x".into(), c.x.into());
        m.insert("y".into(), c.y.into());
        let u = self.occ[cell];
        if u == NO_UNIT {
            match self.ghost[cell] {
                code::CUT_OFF => m.insert("status".into(), "a faulty unit was cut off here".into()),
                code::STRANDED => m.insert(
                    "status".into(),
                    "a unit separated from the system by a cut-off was here".into(),
                ),
                _ => None,
            };
            return m;
        }
        let ui = u as usize;
        let unit = &self.units[ui];
        m.insert("unit".into(), u.into());
        let info = &t.info[self.class[ui] as usize];
        m.insert("type".into(), info.name.into());
        m.insert("bonds".into(), u64::from(info.bonds).into());
        m.insert("movable".into(), info.movable.into());
        if unit.status == Status::Faulty {
            m.insert(
                "status".into(),
                "faulty: sends no OK, cut off at the start of the next step".into(),
            );
            return m;
        }
        m.insert("status".into(), "working".into());
        let mut nb = [0u8; 6];
        let n = self.neighbour_classes(unit.cell, &mut nb, false);
        let now = goal::Statement::new(self.class[ui], nb[..n].to_vec(), 1);
        m.insert("statement".into(), now.text().into());
        if let Some(s) = self.goal.statements().get(self.closest[ui] as usize) {
            m.insert("closest_statement".into(), s.text().into());
            m.insert("closest_priority".into(), u64::from(s.priority).into());
        }
        m.insert("difference".into(), self.diff[ui].into());
        m.insert("x".into(), json!(unit.x));
        m.insert("irritation".into(), json!(unit.irr));
        m
    }
}

#[cfg(test)]
mod tests;
