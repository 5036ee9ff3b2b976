//! Fracta: identical hexagonal units that assemble into a goal shape and repair it after a
//! fault, by the difference-based algorithm of Yoshida, Murata, Tomita, Kurokawa and Kokaji
//! (sections 3 and 4). See `docs/models/fracta.md` for the ODD description and every
//! interpretation made.
//!
//! - [`types`]: the 12 connection types, which can move, and the distances between them;
//! - [`goal`]: goal statements, their text form, "derive from shape", and the difference;
//! - [`paper`]: the paper's claims for the reproduction report;
//! - this module: the units on the lattice, the step (diffusion, activation, irritation, rolls)
//!   and faults.

use std::borrow::Cow;
use std::collections::VecDeque;

use serde::{Deserialize, Serialize};
use serde_json::{json, Map, Value};

use crate::error::{Error, Result};
use crate::hash::StateHasher;
use crate::lattice::{Hex, Lattice, LatticeKind};
use crate::math;
use crate::models::{
    self, Action, Agent, Event, FieldInfo, Layout, LegendEntry, Metrics, Model, ModelEntry,
    ToolInfo,
};
use crate::rng::Rng;
use crate::scenario::Scenario;
use crate::shape;

pub mod goal;
pub mod paper;
pub mod types;

use goal::{Goal, Priorities};
use types::{far_steps, swept_slots, target_slot, types, Turn, Types};

pub const ENTRY: ModelEntry = ModelEntry {
    name: "fracta",
    title: "Fracta: hexagonal self-assembly and self-repair",
    default_max_steps: 20_000,
    build: |s| Ok(Box::new(Fracta::new(s)?)),
    normalize: models::normalized::<Spec>,
};

/// The most units a scenario may hold.
pub const MAX_UNITS: usize = 20_000;
/// The largest lattice side, in cells, margin included.
pub const MAX_SIDE: u32 = 1024;
/// The widest margin around the start shape.
pub const MAX_MARGIN: u32 = 256;

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

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct Spec {
    /// The starting configuration, a hex shape (see [`crate::shape`]).
    start: String,
    /// The goal statements (see [`goal`]).
    goal: String,
    #[serde(default = "defaults::margin")]
    margin: u32,
    #[serde(rename = "K", default = "defaults::k")]
    k: f64,
    #[serde(rename = "L", default = "defaults::l")]
    l: f64,
    #[serde(rename = "G", default = "defaults::g")]
    g: f64,
    #[serde(rename = "I_th", default = "defaults::i_th")]
    i_th: f64,
    #[serde(default = "defaults::stable")]
    stable: f64,
    #[serde(default = "defaults::irritation_gain")]
    irritation_gain: f64,
    #[serde(default = "defaults::temperature")]
    temperature: f64,
    #[serde(default = "defaults::avoid_e")]
    avoid_e: bool,
    #[serde(default = "defaults::priorities")]
    priorities: Priorities,
}

/// Parameter defaults; `docs/models/fracta.md` says why each was chosen.
pub mod defaults {
    use super::Priorities;
    pub fn margin() -> u32 {
        6
    }
    pub fn k() -> f64 {
        0.1
    }
    pub fn l() -> f64 {
        0.05
    }
    pub fn g() -> f64 {
        1.0
    }
    pub fn i_th() -> f64 {
        10.0
    }
    pub fn stable() -> f64 {
        0.1
    }
    pub fn irritation_gain() -> f64 {
        2.0
    }
    pub fn temperature() -> f64 {
        1.0
    }
    pub fn avoid_e() -> bool {
        true
    }
    pub(super) fn priorities() -> Priorities {
        Priorities::Pooled
    }
}

#[derive(Clone, Copy, Debug)]
struct Params {
    k: f64,
    l: f64,
    g: f64,
    i_th: f64,
    stable: f64,
    gain: f64,
    temperature: f64,
    avoid_e: bool,
    priorities: Priorities,
}

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
    closest: Vec<u16>,
    /// Working units with difference 0.
    zero: usize,
    /// Faulty units not yet cut off.
    pending: usize,
    // Scratch.
    new_x: Vec<f64>,
    active: Vec<u32>,
    plans: Vec<Plan>,
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
    pub fn new(scenario: &Scenario) -> Result<Fracta> {
        let spec: Spec = models::body(scenario)?;
        let p = check_params(&spec)?;
        let goal = Goal::parse(&spec.goal).map_err(|e| Error::field("goal", e))?;
        let start = shape::parse_hex(&spec.start).map_err(|e| e.within("start"))?;
        if spec.margin > MAX_MARGIN {
            return Err(Error::field(
                "margin",
                format!("{} is wider than the limit of {MAX_MARGIN}", spec.margin),
            ));
        }
        let count = start.count();
        if count == 0 {
            return Err(Error::field("start", "has no '#' cells"));
        }
        if count > MAX_UNITS {
            return Err(Error::field(
                "start",
                format!("{count} units exceed the limit of {MAX_UNITS}"),
            ));
        }
        // Place the shape `margin` rows down and at least `margin` columns in, moving it in axial
        // coordinates so that its odd rows keep their offsets relative to its even ones.
        let m = spec.margin as i32;
        let mut axial: Vec<(i32, i32)> = Vec::with_capacity(count);
        for y in 0..start.h {
            for x in 0..start.w {
                if start.get(x, y) {
                    let (q, r) = Hex::to_axial(crate::lattice::Coord::xy(x as i32, y as i32));
                    axial.push((q, r + m));
                }
            }
        }
        let min_x = axial
            .iter()
            .map(|&(q, r)| Hex::from_axial(q, r).x)
            .min()
            .unwrap_or(0);
        let shift = m - min_x;
        let placed: Vec<crate::lattice::Coord> = axial
            .iter()
            .map(|&(q, r)| Hex::from_axial(q + shift, r))
            .collect();
        let max_x = placed.iter().map(|c| c.x).max().unwrap_or(0);
        let w = (max_x + 1 + m) as u64;
        let h = u64::from(start.h) + 2 * u64::from(spec.margin);
        if w > u64::from(MAX_SIDE) || h > u64::from(MAX_SIDE) {
            return Err(Error::field(
                "start",
                format!("{w}×{h} cells with the margin exceeds the limit of {MAX_SIDE}×{MAX_SIDE}"),
            ));
        }
        let lattice = Hex::new(w as u32, h as u32);
        let n = lattice.len();
        let nbr: Vec<[u32; 6]> = (0..n)
            .map(|i| {
                let mut out = [NO_UNIT; 6];
                for (d, slot) in out.iter_mut().enumerate() {
                    if let Some(j) = lattice.neighbour(i, d) {
                        *slot = j as u32;
                    }
                }
                out
            })
            .collect();
        let mut occ = vec![NO_UNIT; n];
        let mut units = Vec::with_capacity(count);
        for (id, c) in placed.iter().enumerate() {
            let cell = lattice.index(*c).expect("placed inside the lattice") as u32;
            occ[cell as usize] = id as u32;
            units.push(Unit {
                cell,
                status: Status::Working,
                x: 0.0,
                irr: 0.0,
            });
        }
        let mut model = Fracta {
            lattice,
            nbr,
            occ,
            ghost: vec![code::EMPTY; n],
            working: (0..count as u32).collect(),
            units,
            goal,
            p,
            rng: Rng::new(scenario.seed),
            steps: 0,
            mask: vec![0; count],
            class: vec![0; count],
            diff: vec![0; count],
            closest: vec![0; count],
            zero: 0,
            pending: 0,
            new_x: vec![0.0; count],
            active: Vec::new(),
            plans: Vec::new(),
            busy: vec![u64::MAX; count],
            moves: 0,
            conflicts: 0,
            irritations: 0,
            faults: 0,
            cut_off: 0,
            stranded: 0,
            last_fault: None,
            events: Vec::new(),
        };
        if model.components().len() > 1 {
            return Err(Error::field(
                "start",
                "the units fall apart into pieces; fracta units are always connected",
            ));
        }
        model.refresh();
        model.restart();
        Ok(model)
    }

    /// Neighbour mask of a cell: bit d set when a unit (working or faulty) is in direction d.
    #[inline]
    fn ring(&self, cell: u32) -> u8 {
        let nb = &self.nbr[cell as usize];
        let mut m = 0u8;
        for (d, &j) in nb.iter().enumerate() {
            if j != NO_UNIT && self.occ[j as usize] != NO_UNIT {
                m |= 1 << d;
            }
        }
        m
    }

    /// Sorted classes of the units around `cell`, from the current occupancy, written into
    /// `out`; returns how many.
    fn neighbour_classes(&self, cell: u32, out: &mut [u8; 6], fresh: bool) -> usize {
        let t = types();
        let mut n = 0;
        for &j in &self.nbr[cell as usize] {
            if j == NO_UNIT {
                continue;
            }
            let v = self.occ[j as usize];
            if v != NO_UNIT {
                out[n] = if fresh {
                    t.of(self.ring(j))
                } else {
                    self.class[v as usize]
                };
                n += 1;
            }
        }
        out[..n].sort_unstable();
        n
    }

    /// Recomputes every unit's neighbour mask, type and difference.
    fn refresh(&mut self) {
        let t = types();
        for u in 0..self.units.len() {
            if matches!(self.units[u].status, Status::Working | Status::Faulty) {
                let m = self.ring(self.units[u].cell);
                self.mask[u] = m;
                self.class[u] = t.of(m);
            }
        }
        self.zero = 0;
        let mut nb = [0u8; 6];
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            let n = self.neighbour_classes(self.units[u].cell, &mut nb, false);
            let c = self
                .goal
                .difference(&t.dist, self.class[u], &nb[..n], self.p.priorities);
            self.diff[u] = c.difference;
            self.closest[u] = c.statement;
            if c.difference == 0 {
                self.zero += 1;
            }
        }
    }

    /// Connected groups of working units, each as a list of ids, in order of their smallest id.
    fn components(&self) -> Vec<Vec<u32>> {
        let mut seen = vec![false; self.units.len()];
        let mut out = Vec::new();
        for &u in &self.working {
            if seen[u as usize] {
                continue;
            }
            seen[u as usize] = true;
            let mut group = vec![u];
            let mut queue = VecDeque::from([u]);
            while let Some(v) = queue.pop_front() {
                for &j in &self.nbr[self.units[v as usize].cell as usize] {
                    if j == NO_UNIT {
                        continue;
                    }
                    let w = self.occ[j as usize];
                    if w != NO_UNIT
                        && !seen[w as usize]
                        && self.units[w as usize].status == Status::Working
                    {
                        seen[w as usize] = true;
                        group.push(w);
                        queue.push_back(w);
                    }
                }
            }
            out.push(group);
        }
        out
    }

    /// Section 4: a unit that sends no "OK" at the start of a step is cut off by its neighbours.
    /// If that splits the system, the largest part carries on (the part holding the smallest
    /// unit id among equals) and the others are stranded.
    fn cut_off_faulty(&mut self) {
        if self.pending == 0 {
            return;
        }
        for u in 0..self.units.len() {
            if self.units[u].status == Status::Faulty {
                let cell = self.units[u].cell;
                self.units[u].status = Status::CutOff;
                self.occ[cell as usize] = NO_UNIT;
                self.ghost[cell as usize] = code::CUT_OFF;
                self.cut_off += 1;
                self.events.push(Event {
                    cell,
                    kind: event::CUT_OFF,
                });
            }
        }
        self.pending = 0;
        let groups = self.components();
        if groups.len() > 1 {
            let keep = groups
                .iter()
                .enumerate()
                .max_by_key(|(i, g)| (g.len(), std::cmp::Reverse(*i)))
                .map(|(i, _)| i)
                .unwrap_or(0);
            for (i, g) in groups.iter().enumerate() {
                if i == keep {
                    continue;
                }
                for &u in g {
                    let cell = self.units[u as usize].cell;
                    self.units[u as usize].status = Status::Stranded;
                    self.occ[cell as usize] = NO_UNIT;
                    self.ghost[cell as usize] = code::STRANDED;
                    self.stranded += 1;
                }
            }
            self.working
                .retain(|&u| self.units[u as usize].status == Status::Working);
        }
        self.refresh();
        // The structure the units form has changed: equation 2 starts again from its initial
        // state (section 3.3 / 4: the self-repair process is launched anew).
        self.restart();
    }

    /// Equation 2's initial state, x(i, 0) = diff(i, 0), and no irritation, for every working
    /// unit: at the start and whenever a cut-off changes the structure the units form.
    fn restart(&mut self) {
        for &u in &self.working {
            let unit = &mut self.units[u as usize];
            unit.x = f64::from(self.diff[u as usize]);
            unit.irr = 0.0;
        }
    }

    /// Equations 2, 4 and 5 for every working unit at once, then the activation rule
    /// (equation 3, or irritation for movable units). Fills `active`.
    fn diffuse(&mut self) {
        let t = types();
        let p = self.p;
        self.active.clear();
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            let unit = self.units[u];
            let mut flux = 0.0;
            for &j in &self.nbr[unit.cell as usize] {
                if j != NO_UNIT {
                    let v = self.occ[j as usize];
                    if v != NO_UNIT {
                        flux += self.units[v as usize].x - unit.x;
                    }
                }
            }
            let movable = t.info[self.class[u] as usize].movable;
            let dx = p.k * flux - if movable { p.l } else { 0.0 };
            let mut x = (unit.x + dx).max(0.0);
            let diff = f64::from(self.diff[u]);
            let mut irr = unit.irr;
            let mut fired = false;
            if dx.abs() < p.stable {
                irr += flux.abs().max((diff - unit.x).abs());
            }
            if irr > p.i_th {
                x += p.gain * (diff - unit.x).max(0.0);
                irr = 0.0;
                fired = true;
                self.irritations += 1;
                self.events.push(Event {
                    cell: unit.cell,
                    kind: event::IRRITATED,
                });
            }
            self.units[u].irr = irr;
            self.new_x[u] = x;
            if movable && (p.g * unit.x < diff || fired) {
                self.active.push(u as u32);
            }
        }
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            self.units[u].x = self.new_x[u];
        }
    }

    /// Where the unit on `cell` with neighbours `mask` ends when it rolls about slot `pivot`, if
    /// it may. One 60° roll is legal by the rule of [`types::roll_ok`], with every swept cell
    /// inside the lattice and the far swept cell free (collision avoidance). With `avoid_e` the
    /// unit does not stop as an `e` (section 4): while the cell it reached touches no unit but
    /// the pivot, it rolls on about the same pivot, each 60° legal in the same way, and the
    /// motion is impossible if it would come round to where it started.
    fn legal(&self, cell: u32, mask: u8, pivot: usize, turn: Turn) -> Option<u32> {
        let (mut at, mut mask, mut pivot) = (cell, mask, pivot);
        for _ in 0..5 {
            let target = self.roll_once(at, mask, pivot, turn)?;
            if !self.p.avoid_e {
                return Some(target);
            }
            // Bonds at the target once the unit has left its starting cell.
            let there = self.ring_without(target, cell);
            if there.count_ones() >= 2 {
                return Some(target);
            }
            // Seen from the target, the pivot sits one slot back against the turn.
            (at, mask, pivot) = (target, there, turn.back(pivot));
        }
        None
    }

    /// The cell one legal 60° roll about slot `pivot` takes the unit on `at` (neighbours `mask`)
    /// to.
    fn roll_once(&self, at: u32, mask: u8, pivot: usize, turn: Turn) -> Option<u32> {
        if !types::roll_ok(mask, pivot, turn) {
            return None;
        }
        let nb = &self.nbr[at as usize];
        if swept_slots(pivot, turn).iter().any(|&s| nb[s] == NO_UNIT) {
            return None;
        }
        let target = nb[target_slot(pivot, turn)];
        let [_, beyond] = far_steps(pivot, turn);
        let far = self.nbr[target as usize][beyond];
        if far == NO_UNIT || self.occ[far as usize] != NO_UNIT {
            return None;
        }
        Some(target)
    }

    /// Neighbour mask of `cell` with the cell `gone` counted as empty.
    fn ring_without(&self, cell: u32, gone: u32) -> u8 {
        let nb = &self.nbr[cell as usize];
        let mut m = 0u8;
        for (d, &j) in nb.iter().enumerate() {
            if j != NO_UNIT && j != gone && self.occ[j as usize] != NO_UNIT {
                m |= 1 << d;
            }
        }
        m
    }

    /// The difference the unit `u` would have after rolling from `from` to `to`, every other
    /// unit staying put.
    fn difference_after(&mut self, u: u32, from: u32, to: u32) -> u32 {
        let t = types();
        self.occ[from as usize] = NO_UNIT;
        self.occ[to as usize] = u;
        let own = t.of(self.ring(to));
        let mut nb = [0u8; 6];
        let n = self.neighbour_classes(to, &mut nb, true);
        let d = self
            .goal
            .difference(&t.dist, own, &nb[..n], self.p.priorities)
            .difference;
        self.occ[to as usize] = NO_UNIT;
        self.occ[from as usize] = u;
        d
    }

    /// Section 3.2.4: each active unit picks clockwise or counter-clockwise, the direction that
    /// leaves it the smaller difference being the likelier (Boltzmann weights at `temperature`).
    fn plan(&mut self) {
        self.plans.clear();
        for k in 0..self.active.len() {
            let u = self.active[k];
            let cell = self.units[u as usize].cell;
            let mask = self.mask[u as usize];
            let mut options: [(Plan, u32); 2] = [(
                Plan {
                    unit: u,
                    pivot: 0,
                    pivot_slot: 0,
                    turn: Turn::Ccw,
                },
                0,
            ); 2];
            let mut n = 0;
            for pivot in 0..6 {
                for turn in Turn::BOTH {
                    if let Some(target) = self.legal(cell, mask, pivot, turn) {
                        let d = self.difference_after(u, cell, target);
                        if n < 2 {
                            let pivot_cell = self.nbr[cell as usize][pivot];
                            options[n] = (
                                Plan {
                                    unit: u,
                                    pivot: self.occ[pivot_cell as usize],
                                    pivot_slot: pivot as u8,
                                    turn,
                                },
                                d,
                            );
                            n += 1;
                        }
                    }
                }
            }
            let chosen = match n {
                0 => continue,
                1 => options[0].0,
                _ => {
                    let (d0, d1) = (f64::from(options[0].1), f64::from(options[1].1));
                    // P(first) = e^(-d0/T) / (e^(-d0/T) + e^(-d1/T)).
                    let p0 = 1.0 / (1.0 + math::exp((d0 - d1) / self.p.temperature));
                    if self.rng.unit() < p0 {
                        options[0].0
                    } else {
                        options[1].0
                    }
                }
            };
            self.plans.push(chosen);
        }
    }

    /// Carries out the planned rolls one by one in a random order. A roll goes ahead only if,
    /// in the configuration left by the rolls before it, it is still legal and neither its unit
    /// nor its pivot has already taken part in a roll this step; otherwise it is cancelled (a
    /// conflict) and the unit waits.
    fn commit(&mut self) {
        let stamp = self.steps;
        let mut plans = std::mem::take(&mut self.plans);
        self.rng.shuffle(&mut plans);
        for plan in &plans {
            let u = plan.unit;
            let cell = self.units[u as usize].cell;
            let pivot_cell = self.nbr[cell as usize][plan.pivot_slot as usize];
            let ok = pivot_cell != NO_UNIT
                && self.busy[u as usize] != stamp
                && self.busy[plan.pivot as usize] != stamp
                && self.occ[pivot_cell as usize] == plan.pivot;
            let target = if ok {
                let mask = self.ring(cell);
                self.legal(cell, mask, plan.pivot_slot as usize, plan.turn)
            } else {
                None
            };
            match target {
                Some(to) => {
                    self.occ[cell as usize] = NO_UNIT;
                    self.occ[to as usize] = u;
                    self.ghost[to as usize] = code::EMPTY;
                    self.units[u as usize].cell = to;
                    self.busy[u as usize] = stamp;
                    self.busy[plan.pivot as usize] = stamp;
                    self.moves += 1;
                    self.events.push(Event {
                        cell: to,
                        kind: event::MOVED,
                    });
                }
                None => {
                    self.conflicts += 1;
                    self.events.push(Event {
                        cell,
                        kind: event::CONFLICT,
                    });
                }
            }
        }
        self.plans = plans;
    }

    fn mean_difference(&self) -> f64 {
        if self.working.is_empty() {
            return 0.0;
        }
        let sum: u64 = self
            .working
            .iter()
            .map(|&u| u64::from(self.diff[u as usize]))
            .sum();
        sum as f64 / self.working.len() as f64
    }

    /// Empty cells enclosed by units: not reachable from the lattice's edge through empty cells.
    /// A ring of units round such a cell cannot open (its units are not movable) and no unit can
    /// roll into it, so a goal without holes is then out of reach for good.
    fn holes(&self) -> u64 {
        let n = self.occ.len();
        let mut outside = vec![false; n];
        let mut queue: VecDeque<u32> = VecDeque::new();
        for (i, out) in outside.iter_mut().enumerate() {
            if self.nbr[i].contains(&NO_UNIT) && self.occ[i] == NO_UNIT {
                *out = true;
                queue.push_back(i as u32);
            }
        }
        while let Some(i) = queue.pop_front() {
            for &j in &self.nbr[i as usize] {
                if j != NO_UNIT && !outside[j as usize] && self.occ[j as usize] == NO_UNIT {
                    outside[j as usize] = true;
                    queue.push_back(j);
                }
            }
        }
        (0..n)
            .filter(|&i| self.occ[i] == NO_UNIT && !outside[i])
            .count() as u64
    }

    /// The working unit on a cell named by an action.
    fn working_unit_at(&self, cell: u64) -> Result<u32> {
        let u = self.occ[cell as usize];
        if u == NO_UNIT || self.units[u as usize].status != Status::Working {
            return Err(Error::field(
                "cells",
                format!("cell {cell} holds no working unit"),
            ));
        }
        Ok(u)
    }

    /// Reads a fault action. Only what holds at any step is checked here (the kind, cells inside
    /// the lattice, an existing unit number), since a scheduled fault is checked against the
    /// starting state; whether a working unit is there is checked when it is applied.
    fn parse_fault(&self, action: &Action) -> Result<Fault> {
        let a: FaultAction = crate::error::from_value(Value::Object(action.clone()))?;
        if a.kind != "fault" {
            return Err(Error::field(
                "kind",
                format!("unknown disturbance '{}'; known: fault", a.kind),
            ));
        }
        match (a.cells, a.unit) {
            (Some(cells), None) => {
                if cells.is_empty() {
                    return Err(Error::field("cells", "name at least one cell"));
                }
                if let Some(c) = cells.iter().find(|&&c| c >= self.occ.len() as u64) {
                    return Err(Error::field(
                        "cells",
                        format!("cell {c} is outside the lattice"),
                    ));
                }
                Ok(Fault::Cells(cells))
            }
            (None, Some(u)) => {
                if u >= self.units.len() as u64 {
                    return Err(Error::field(
                        "unit",
                        format!(
                            "there is no unit {u}; units are numbered 0 to {} in reading order of the start shape",
                            self.units.len() - 1
                        ),
                    ));
                }
                Ok(Fault::Unit(u as u32))
            }
            _ => Err(Error::field(
                "",
                "give either cells (lattice cell indices) or unit (a unit number)",
            )),
        }
    }
}

enum Fault {
    Cells(Vec<u64>),
    Unit(u32),
}

/// A fault (section 4): `{"kind": "fault", "unit": 3}` cuts the power of unit 3 (units are
/// numbered in reading order of the start shape); `{"kind": "fault", "cells": [i]}` of the unit
/// on lattice cell i (the click tool).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FaultAction {
    kind: String,
    #[serde(default)]
    cells: Option<Vec<u64>>,
    #[serde(default)]
    unit: Option<u64>,
}

fn check_params(s: &Spec) -> Result<Params> {
    let range = |name: &str, v: f64, lo: f64, hi: f64, open_lo: bool| -> Result<f64> {
        let low_ok = if open_lo { v > lo } else { v >= lo };
        if v.is_finite() && low_ok && v <= hi {
            Ok(v)
        } else {
            Err(Error::field(
                name,
                format!(
                    "{v} is out of range; expected {} {lo} and at most {hi}",
                    if open_lo { "more than" } else { "at least" }
                ),
            ))
        }
    };
    Ok(Params {
        // K above 1/6 lets a unit with six neighbours overshoot the average (x would oscillate).
        k: range("K", s.k, 0.0, 1.0 / 6.0, false)?,
        l: range("L", s.l, 0.0, 1000.0, false)?,
        g: range("G", s.g, 0.0, 1000.0, false)?,
        i_th: range("I_th", s.i_th, 0.0, 1e9, true)?,
        stable: range("stable", s.stable, 0.0, 1000.0, false)?,
        gain: range("irritation_gain", s.irritation_gain, 0.0, 1000.0, false)?,
        temperature: range("temperature", s.temperature, 0.001, 1e6, false)?,
        avoid_e: s.avoid_e,
        priorities: s.priorities,
    })
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
            chart: "mean_difference".into(),
        }
    }

    fn step(&mut self) {
        self.events.clear();
        self.cut_off_faulty();
        self.diffuse();
        self.plan();
        self.commit();
        self.refresh();
        self.steps += 1;
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        !self.working.is_empty() && self.pending == 0 && self.zero == self.working.len()
    }

    fn metrics(&self) -> Metrics {
        let mut m = Map::new();
        m.insert("completed".into(), self.completed().into());
        m.insert("steps".into(), self.steps.into());
        m.insert("mean_difference".into(), json!(self.mean_difference()));
        m.insert("moves".into(), self.moves.into());
        m.insert("conflicts".into(), self.conflicts.into());
        m.insert("irritations".into(), self.irritations.into());
        m.insert("units".into(), (self.working.len() as u64).into());
        m.insert("faults".into(), self.faults.into());
        m.insert("cut_off".into(), self.cut_off.into());
        m.insert("stranded".into(), self.stranded.into());
        m.insert("holes".into(), self.holes().into());
        // Null until the goal is reached: from the start when there was no fault, from the
        // last fault when there was one.
        let done = self.completed();
        let (convergence, repair) = match self.last_fault {
            None if done => (Value::from(self.steps), Value::Null),
            Some(at) if done => (Value::Null, Value::from(self.steps - at)),
            _ => (Value::Null, Value::Null),
        };
        m.insert("convergence_steps".into(), convergence);
        m.insert("repair_steps".into(), repair);
        m
    }

    fn hash_state(&self, h: &mut StateHasher) {
        for u in &self.units {
            h.u32(u.cell);
            h.u8(u.status as u8);
            h.f64(u.x);
            h.f64(u.irr);
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
        self.parse_fault(action).map(|_| ())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        let targets = match self.parse_fault(action)? {
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

/// Helper calls for editors and the CLI (see `models::query`).
pub mod queries {
    use super::*;

    fn text<'a>(args: &'a Value, key: &str) -> Result<&'a str> {
        args.get(key)
            .and_then(Value::as_str)
            .ok_or_else(|| Error::field(key, "expected text"))
    }

    /// `derive`: the statements of one or more hex shapes (`{"shape": text}`) separated by lines
    /// holding `---`: the first shape gives priority 1, the next the statements it adds at
    /// priority 2, and so on. Answers `{"goal": text}`.
    pub fn derive(args: &Value) -> Result<Value> {
        let input = text(args, "shape")?;
        let mut shapes = Vec::new();
        for (i, block) in input.split("\n---").enumerate() {
            let block = block.trim_start_matches('-');
            let g = shape::parse_hex(block).map_err(|e| match e {
                Error::Field { reason, .. } if input.contains("---") => {
                    Error::field("shape", format!("shape {}: {reason}", i + 1))
                }
                other => other.within("shape"),
            })?;
            shapes.push(g);
        }
        let goal = goal::derive(&shapes).map_err(|e| Error::field("shape", e))?;
        Ok(json!({ "goal": goal.text() }))
    }

    /// `check`: parses `{"goal": text}` and answers it in normal form (sorted, canonical names),
    /// or an error naming the line and the problem.
    pub fn check(args: &Value) -> Result<Value> {
        let goal = Goal::parse(text(args, "goal")?).map_err(|e| Error::field("goal", e))?;
        Ok(json!({ "goal": goal.text() }))
    }

    /// `types`: the connection types: code, name, ASCII spelling, bonds, movable, colour.
    pub fn types(_args: &Value) -> Result<Value> {
        let t: &Types = super::types();
        let list: Vec<Value> = t
            .info
            .iter()
            .enumerate()
            .skip(1)
            .map(|(c, i)| {
                json!({
                    "code": c, "name": i.name, "ascii": i.ascii, "aliases": i.aliases,
                    "bonds": i.bonds, "movable": i.movable, "color": i.color,
                    "from_paper": i.paper, "description": i.description,
                })
            })
            .collect();
        Ok(json!({ "types": list }))
    }
}

#[cfg(test)]
mod tests;
