//! AMAS: assembler robots carrying modules along a gradient field the modules compute among
//! themselves (Terada & Murata, sections 4 to 6 and appendices A and B). See
//! `docs/models/amas.md` for the ODD description and every interpretation made.

use std::borrow::Cow;
use std::collections::{HashSet, VecDeque};

use serde_json::{json, Map, Value};

use crate::error::Result;
use crate::hash::StateHasher;
use crate::lattice::{Lattice, LatticeKind, Square};
use crate::models::{
    self, Action, Agent, Event, FieldInfo, Layout, LegendEntry, Metrics, Model, ModelEntry,
    ToolInfo,
};
use crate::rng::Rng;
use crate::scenario::Scenario;

mod actions;
mod field;
mod spec;
mod state;

pub use spec::{Collision, FieldKind, MAX_SIDE, MAX_SUPPLY_ROWS};

use field::{Field, FAR};
use spec::{Params, Spec};
use state::{code, ACTIVE_MASK, BROKEN, CLAIMED, CONVEYOR, FRONT, MODULE, REMOVE, SOURCE, VACANT};

pub const ENTRY: ModelEntry = ModelEntry {
    name: "amas",
    title: "AMAS: assembler robots on a gradient field",
    default_max_steps: 100_000,
    model_version: 1,
    build: |s| Ok(Box::new(Amas::new(s)?)),
    normalize: models::normalized::<Spec>,
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
    /// Lost a collision: avoids occupied modules at its next plan.
    give_way: bool,
    /// Moved at random at its last plan: no effective gradient (footnote 3).
    lost: bool,
}

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
    rng: Rng,
    disturb_rng: Rng,
    /// Modules to be removed that the connection rule lets go now (a bit set over all cells):
    /// their neighbours are the supply area.
    releasable: Vec<u64>,
    /// The structure changed since `releasable` was computed.
    dirty: bool,
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
    events: Vec<Event>,
}

impl Amas {
    pub fn new(scenario: &Scenario) -> Result<Amas> {
        let spec: Spec = models::body(scenario)?;
        let plan = spec::read(spec)?;
        let w = plan.w as usize;
        let sh = plan.shape_h as usize;
        let h = sh + plan.supply_rows as usize;
        let n = w * h;
        let above = sh * w;
        let mut state = vec![0u8; n];
        for (i, s) in state.iter_mut().enumerate().take(above) {
            *s = match (plan.initial[i], plan.stages[0][i]) {
                (true, true) => MODULE,
                (true, false) => MODULE | REMOVE,
                (false, true) => VACANT,
                (false, false) => 0,
            };
        }
        for s in &mut state[above..] {
            *s = MODULE | CONVEYOR;
        }
        let stages: Vec<Vec<u64>> = plan
            .stages
            .iter()
            .map(|cells| {
                let mut bits = vec![0u64; above.div_ceil(64)];
                for (i, _) in cells.iter().enumerate().filter(|(_, &c)| c) {
                    bits[i / 64] |= 1 << (i % 64);
                }
                bits
            })
            .collect();
        let (lower_bound, path_bound) = bounds(
            plan.stages.last().expect("the target is always there"),
            &plan.initial,
            w,
            sh,
            u64::from(plan.robots),
        );
        let supply_cells = w * plan.supply_rows as usize;
        let mut place_rng = Rng::stream(scenario.seed, STREAM_PLACEMENT);
        let starts = place_rng.sample_distinct(supply_cells, plan.robots as usize);
        let mut occupant = vec![NONE; n];
        let robots: Vec<Robot> = starts
            .iter()
            .enumerate()
            .map(|(r, &k)| {
                let cell = above + k;
                occupant[cell] = r as u32;
                Robot {
                    cell: cell as u32,
                    loaded: false,
                    busy: 0,
                    give_way: false,
                    lost: false,
                }
            })
            .collect();
        let robots_n = robots.len();
        let field = match plan.params.field {
            FieldKind::Discrete => Field::discrete(n, w),
            FieldKind::Continuous => Field::continuous(n, w, plan.params.diffusion),
        };
        let mut m = Amas {
            w,
            h,
            supply_top: sh,
            display: vec![0; n],
            state,
            occupant,
            field,
            p: plan.params,
            robots,
            order: (0..robots_n as u32).collect(),
            plans: vec![Plan::Wait; robots_n],
            planned: vec![false; robots_n],
            status: vec![UNKNOWN; robots_n],
            relaying: vec![false; robots_n],
            position: vec![0; robots_n],
            claimed: Vec::new(),
            chain: Vec::new(),
            rng: Rng::new(scenario.seed),
            disturb_rng: Rng::stream(scenario.seed, STREAM_DISTURBANCE),
            releasable: vec![0; n.div_ceil(64)],
            dirty: true,
            stages,
            stage: 0,
            return_mode: false,
            top: 0,
            target_cells: 0,
            vacant: 0,
            to_remove: 0,
            steps: 0,
            collisions: 0,
            relays: 0,
            placed: 0,
            picked: 0,
            dismantled: 0,
            returned: 0,
            removed: 0,
            broken: 0,
            lower_bound,
            path_bound,
            events: Vec::new(),
        };
        m.recount();
        for i in 0..n {
            m.refresh(i);
        }
        m.settle();
        m.top = (0..h)
            .find(|&y| m.state[y * w..(y + 1) * w].iter().any(|&s| s & MODULE != 0))
            .unwrap_or(sh);
        m.reset_field();
        Ok(m)
    }

    fn recount(&mut self) {
        let above = self.supply_top * self.w;
        let (mut vacant, mut remove, mut built) = (0, 0, 0);
        for &s in &self.state[..above] {
            if s & VACANT != 0 {
                vacant += 1;
            } else if s & REMOVE != 0 {
                remove += 1;
            } else if s & MODULE != 0 {
                built += 1;
            }
        }
        self.vacant = vacant;
        self.to_remove = remove;
        self.target_cells = vacant + built;
    }

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

    /// Recomputes the growth-front and supply roles of cell `i` from its neighbours.
    fn refresh(&mut self, i: usize) {
        let s = self.state[i];
        let new = if s & MODULE == 0 {
            s & !(FRONT | SOURCE)
        } else {
            let (nb, k) = self.neighbours(i);
            let mut front = false;
            let mut source = false;
            for &j in &nb[..k] {
                let t = self.state[j];
                front |= t & VACANT != 0;
                source |= t & REMOVE != 0 && self.is_releasable(j);
            }
            // A robot cannot remove the module it stands on: a module that may go now is not
            // itself supply.
            source &= !self.is_releasable(i);
            if s & CONVEYOR != 0 {
                if self.return_mode {
                    front = true;
                } else {
                    source = true;
                }
            }
            (s & !(FRONT | SOURCE))
                | if front { FRONT } else { 0 }
                | if source { SOURCE } else { 0 }
        };
        self.state[i] = new;
        self.display[i] = state::display(new);
    }

    #[inline]
    fn is_releasable(&self, i: usize) -> bool {
        self.releasable[i / 64] >> (i % 64) & 1 == 1
    }

    /// Section 6.2 with 6.3: the neighbours of a module to be removed become supply while the
    /// connection rule lets that module go.
    fn update_releasable(&mut self) {
        if self.to_remove == 0 && self.releasable.iter().all(|&b| b == 0) {
            return;
        }
        let mut changed = Vec::new();
        for i in 0..self.supply_top * self.w {
            let want = self.state[i] & REMOVE != 0 && self.removable(i);
            if want != self.is_releasable(i) {
                self.releasable[i / 64] ^= 1 << (i % 64);
                changed.push(i);
            }
        }
        for i in changed {
            self.refresh_around(i);
        }
    }

    fn refresh_around(&mut self, i: usize) {
        self.refresh(i);
        let (nb, k) = self.neighbours(i);
        for &j in &nb[..k] {
            self.refresh(j);
        }
    }

    /// The value a module takes when it appears or its role changes: what its first update
    /// would give from its neighbours' current values. A broken module keeps its value.
    fn init_value(&mut self, i: usize) {
        let s = self.state[i];
        if s & BROKEN != 0 {
            return;
        }
        let on = s & MODULE != 0;
        let (nb, k) = self.neighbours(i);
        match &mut self.field {
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => {
                if !on {
                    to_supply[i] = FAR;
                    to_front[i] = FAR;
                    return;
                }
                let ms = nb[..k].iter().map(|&j| to_supply[j]).min().unwrap_or(FAR);
                let mf = nb[..k].iter().map(|&j| to_front[j]).min().unwrap_or(FAR);
                to_supply[i] = if s & SOURCE != 0 {
                    0
                } else {
                    ms.saturating_add(1)
                };
                to_front[i] = if s & FRONT != 0 {
                    0
                } else {
                    mf.saturating_add(1)
                };
            }
            Field::Continuous { p, .. } => {
                p[i] = if !on || (s & SOURCE != 0 && s & FRONT == 0) {
                    0.0
                } else if s & FRONT != 0 {
                    1.0
                } else {
                    let mut sum = 0.0f32;
                    let mut cnt = 0.0f32;
                    for &j in &nb[..k] {
                        if self.state[j] & MODULE != 0 {
                            sum += p[j];
                            cnt += 1.0;
                        }
                    }
                    if cnt > 0.0 {
                        sum / cnt
                    } else {
                        0.0
                    }
                };
            }
        }
    }

    /// Field values before any update: the destinations hold their fixed values, every other
    /// module knows nothing yet.
    fn reset_field(&mut self) {
        for i in 0..self.state.len() {
            let s = self.state[i];
            let on = s & ACTIVE_MASK == MODULE;
            match &mut self.field {
                Field::Discrete {
                    to_supply,
                    to_front,
                    ..
                } => {
                    to_supply[i] = if on && s & SOURCE != 0 { 0 } else { FAR };
                    to_front[i] = if on && s & FRONT != 0 { 0 } else { FAR };
                }
                Field::Continuous { p, .. } => {
                    p[i] = if on && s & FRONT != 0 { 1.0 } else { 0.0 };
                }
            }
        }
    }

    /// Stage switching (section 6.4) and the supply taking modules back when the target is
    /// full but modules are still to be removed.
    fn settle(&mut self) {
        while self.vacant == 0 && self.to_remove == 0 && self.stage + 1 < self.stages.len() {
            self.stage += 1;
            let above = self.supply_top * self.w;
            for i in 0..above {
                let inside = self.stages[self.stage][i / 64] >> (i % 64) & 1 == 1;
                let s = self.state[i];
                self.state[i] = if s & MODULE != 0 {
                    if inside {
                        s & !REMOVE
                    } else {
                        s | REMOVE
                    }
                } else if inside {
                    VACANT
                } else {
                    0
                };
            }
            self.recount();
            self.dirty = true;
            for i in 0..self.state.len() {
                self.refresh(i);
            }
        }
        let back = self.vacant == 0 && self.to_remove > 0;
        if back != self.return_mode {
            self.return_mode = back;
            for i in self.supply_top * self.w..self.state.len() {
                self.refresh(i);
            }
        }
        if self.dirty {
            self.dirty = false;
            self.update_releasable();
        }
    }

    /// How far module `j` is from where a robot wants to go: lower is better.
    #[inline]
    fn cost(&self, j: usize, loaded: bool) -> f32 {
        match &self.field {
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => f32::from(if loaded { to_front[j] } else { to_supply[j] }),
            Field::Continuous { p, .. } => {
                if loaded {
                    -p[j]
                } else {
                    p[j]
                }
            }
        }
    }

    /// Blackboard (4.6.2): a module is engaged when a robot has written a plan on it, or a
    /// robot stands on it that has not written a plan to leave it (or plans to come to `me`).
    fn engaged(&self, c: usize, me: usize) -> bool {
        if self.state[c] & CLAIMED != 0 {
            return true;
        }
        let o = self.occupant[c];
        if o == NONE {
            return false;
        }
        match (self.planned[o as usize], self.plans[o as usize]) {
            (true, Plan::Move(t)) => t as usize == me,
            _ => true,
        }
    }

    fn pick_random(&mut self, options: &[u32]) -> Option<u32> {
        match options.len() {
            0 => None,
            1 => Some(options[0]),
            n => Some(options[self.rng.index(n)]),
        }
    }

    /// The module of lowest cost among `options`, ties broken at random.
    fn pick_lowest(&mut self, options: &[(u32, f32)]) -> Option<u32> {
        let best = options
            .iter()
            .map(|&(_, c)| c)
            .fold(f32::INFINITY, f32::min);
        let mut pick = [0u32; 4];
        let mut m = 0;
        for &(j, c) in options {
            if c == best {
                pick[m] = j;
                m += 1;
            }
        }
        self.pick_random(&pick[..m])
    }

    /// The move the module under the robot shows it (footnote 3): towards the best neighbour,
    /// or, with no effective gradient, a random neighbouring module. On a blackboard the robot
    /// avoids engaged modules and takes the best free one.
    fn follow(&mut self, r: usize, i: usize, loaded: bool, board: bool) -> Plan {
        let (nb, k) = self.neighbours(i);
        let mut walk = [0u32; 4];
        let mut nw = 0;
        let mut valued = [(0u32, 0f32); 4];
        let mut nv = 0;
        for &j in &nb[..k] {
            let s = self.state[j];
            if s & MODULE == 0 || (board && self.engaged(j, i)) {
                continue;
            }
            walk[nw] = j as u32;
            nw += 1;
            if s & MODULE != 0 {
                valued[nv] = (j as u32, self.cost(j, loaded));
                nv += 1;
            }
        }
        // The gradient is judged on every neighbouring module's value, engaged or not; the
        // module under the robot holds the last value each neighbour sent, broken or not.
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        for &j in &nb[..k] {
            if self.state[j] & MODULE != 0 {
                let c = self.cost(j, loaded);
                lo = lo.min(c);
                hi = hi.max(c);
            }
        }
        if hi - lo >= self.p.threshold && hi >= lo {
            return self
                .pick_lowest(&valued[..nv])
                .map_or(Plan::Wait, Plan::Move);
        }
        self.robots[r].lost = true;
        self.pick_random(&walk[..nw]).map_or(Plan::Wait, Plan::Move)
    }

    /// A robot that lost a collision steps, at its next plan, to the best module for itself
    /// that no robot stands on: it moves on if the way has cleared, or aside if it has not.
    fn give_way(&mut self, i: usize, loaded: bool) -> Option<u32> {
        let (nb, k) = self.neighbours(i);
        let mut opts = [(0u32, 0f32); 4];
        let mut n = 0;
        for &j in &nb[..k] {
            if self.state[j] & MODULE != 0 && self.occupant[j] == NONE {
                let c = self.cost(j, loaded);
                opts[n] = (j as u32, c);
                n += 1;
            }
        }
        self.pick_lowest(&opts[..n])
    }

    /// What robot `r` wants to do this step.
    fn decide(&mut self, r: usize) -> Plan {
        let rb = self.robots[r];
        let i = rb.cell as usize;
        let s = self.state[i];
        let board = self.p.collision == Collision::Blackboard;
        self.robots[r].lost = false;
        if rb.give_way {
            self.robots[r].give_way = false;
            if let Some(c) = self.give_way(i, rb.loaded) {
                return Plan::Move(c);
            }
        }
        if s & ACTIVE_MASK != MODULE {
            // A broken module tells the robot nothing: it walks at random.
            let (nb, k) = self.neighbours(i);
            let mut walk = [0u32; 4];
            let mut n = 0;
            for &j in &nb[..k] {
                if self.state[j] & MODULE != 0 && !(board && self.engaged(j, i)) {
                    walk[n] = j as u32;
                    n += 1;
                }
            }
            self.robots[r].lost = true;
            return self.pick_random(&walk[..n]).map_or(Plan::Wait, Plan::Move);
        }
        let (nb, k) = self.neighbours(i);
        if rb.loaded {
            if s & FRONT != 0 {
                if s & CONVEYOR != 0 && self.return_mode {
                    return Plan::Return;
                }
                let mut opts = [0u32; 4];
                let mut n = 0;
                for &j in &nb[..k] {
                    let t = self.state[j];
                    if t & VACANT != 0 && !(board && t & CLAIMED != 0) {
                        opts[n] = j as u32;
                        n += 1;
                    }
                }
                if n > 0 {
                    return self.pick_random(&opts[..n]).map_or(Plan::Wait, Plan::Place);
                }
                if board {
                    return Plan::Wait;
                }
            }
            return self.follow(r, i, true, board);
        }
        if s & SOURCE != 0 {
            let mut opts = [0u32; 4];
            let mut n = 0;
            for &j in &nb[..k] {
                let t = self.state[j];
                if t & REMOVE != 0
                    && self.is_releasable(j)
                    && self.occupant[j] == NONE
                    && !(board && t & CLAIMED != 0)
                {
                    opts[n] = j as u32;
                    n += 1;
                }
            }
            if n > 0 {
                return self
                    .pick_random(&opts[..n])
                    .map_or(Plan::Wait, Plan::Remove);
            }
            if s & CONVEYOR != 0 && !self.return_mode {
                return Plan::Pick;
            }
        }
        self.follow(r, i, false, board)
    }

    /// Section 6.3: a module with one connection is removable; with two to four, only when all
    /// its neighbours stay connected without it. The neighbours first look for each other
    /// around the module (its eight surrounding cells), then through the whole structure.
    fn removable(&self, c: usize) -> bool {
        let (nb, k) = self.neighbours(c);
        let mut mods = [0usize; 4];
        let mut m = 0;
        for &j in &nb[..k] {
            if self.state[j] & MODULE != 0 {
                mods[m] = j;
                m += 1;
            }
        }
        if m <= 1 {
            return true;
        }
        // The ring E, NE, N, NW, W, SW, S, SE; even positions are the four neighbours.
        let (x, y) = ((c % self.w) as i64, (c / self.w) as i64);
        let ring: [(i64, i64); 8] = [
            (1, 0),
            (1, -1),
            (0, -1),
            (-1, -1),
            (-1, 0),
            (-1, 1),
            (0, 1),
            (1, 1),
        ];
        let here = |(dx, dy): (i64, i64)| {
            let (nx, ny) = (x + dx, y + dy);
            nx >= 0
                && ny >= 0
                && (nx as usize) < self.w
                && (ny as usize) < self.h
                && self.state[ny as usize * self.w + nx as usize] & MODULE != 0
        };
        let filled: [bool; 8] = std::array::from_fn(|q| here(ring[q]));
        if filled.iter().all(|&f| f) {
            return true;
        }
        // Count runs of filled ring cells that hold a neighbour.
        let start = (0..8).find(|&q| !filled[q]).unwrap_or(0);
        let mut runs = 0;
        let mut in_run = false;
        let mut run_has = false;
        for step in 1..=8 {
            let q = (start + step) % 8;
            if filled[q] {
                if !in_run {
                    in_run = true;
                    run_has = false;
                }
                run_has |= q % 2 == 0;
            } else if in_run {
                in_run = false;
                if run_has {
                    runs += 1;
                }
            }
        }
        if in_run && run_has {
            runs += 1;
        }
        if runs <= 1 {
            return true;
        }
        // Through the structure: search from one neighbour until the others are found.
        let mut seen: HashSet<usize> = HashSet::new();
        let mut queue = VecDeque::new();
        seen.insert(c);
        seen.insert(mods[0]);
        queue.push_back(mods[0]);
        let mut missing = m - 1;
        while let Some(i) = queue.pop_front() {
            let (nb, k) = self.neighbours(i);
            for &j in &nb[..k] {
                if self.state[j] & MODULE != 0 && seen.insert(j) {
                    if mods[1..m].contains(&j) {
                        missing -= 1;
                        if missing == 0 {
                            return true;
                        }
                    }
                    queue.push_back(j);
                }
            }
        }
        false
    }

    fn claim(&mut self, c: usize) {
        self.state[c] |= CLAIMED;
        self.claimed.push(c as u32);
    }

    /// Token and relay: whether robot `r`'s move goes ahead, following the robots ahead of it.
    /// A move onto a module whose robot stays, or around a cycle (two robots meeting head-on),
    /// does not.
    fn resolve(&mut self, r: usize) {
        if self.status[r] != UNKNOWN {
            return;
        }
        self.chain.clear();
        let mut cur = r;
        let result = loop {
            self.status[cur] = VISITING;
            self.chain.push(cur as u32);
            let Plan::Move(t) = self.plans[cur] else {
                break STAYS;
            };
            let o = self.occupant[t as usize];
            if o == NONE {
                break MOVES;
            }
            let o = o as usize;
            match self.status[o] {
                MOVES => break MOVES,
                STAYS | VISITING => break STAYS,
                _ => {
                    if matches!(self.plans[o], Plan::Move(_)) {
                        cur = o;
                    } else {
                        self.status[o] = STAYS;
                        break STAYS;
                    }
                }
            }
        };
        for &q in &self.chain {
            self.status[q as usize] = result;
        }
    }

    fn collide(&mut self, r: usize, at: u32) {
        self.collisions += 1;
        self.robots[r].give_way = true;
        self.robots[r].busy = self.p.penalty - 1;
        self.events.push(Event {
            cell: at,
            kind: EV_COLLISION,
        });
    }

    fn plan_all(&mut self) {
        self.rng.shuffle(&mut self.order);
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            self.position[r] = k as u32;
            self.planned[r] = false;
            self.status[r] = UNKNOWN;
            self.relaying[r] = false;
        }
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            let plan = if self.robots[r].busy > 0 {
                self.robots[r].busy -= 1;
                Plan::Busy
            } else {
                self.decide(r)
            };
            let plan = match plan {
                Plan::Move(t) | Plan::Place(t) | Plan::Remove(t) => {
                    if self.state[t as usize] & CLAIMED != 0 {
                        Plan::Blocked(t)
                    } else {
                        self.claim(t as usize);
                        plan
                    }
                }
                other => other,
            };
            self.plans[r] = plan;
            self.planned[r] = true;
        }
    }

    /// Token and relay rules: decides which moves go ahead, then hands modules over (relay)
    /// or charges the collision penalty to the robots that must wait.
    fn settle_conflicts(&mut self) {
        let n = self.robots.len();
        for r in 0..n {
            if matches!(self.plans[r], Plan::Move(_)) {
                self.resolve(r);
            }
        }
        if self.p.collision == Collision::Blackboard {
            return;
        }
        if self.p.collision == Collision::Relay {
            for k in 0..n {
                let r = self.order[k] as usize;
                let Plan::Move(t) = self.plans[r] else {
                    continue;
                };
                let o = self.occupant[t as usize];
                if self.status[r] != STAYS || self.relaying[r] || o == NONE {
                    continue;
                }
                let o = o as usize;
                let o_idle = match self.plans[o] {
                    Plan::Wait | Plan::Blocked(_) => true,
                    Plan::Move(_) => self.status[o] == STAYS,
                    _ => false,
                };
                if o_idle && !self.relaying[o] && self.robots[r].loaded != self.robots[o].loaded {
                    // 4.6.1: the robot carrying the module hands it to the other.
                    self.relaying[r] = true;
                    self.relaying[o] = true;
                    self.robots[r].loaded = !self.robots[r].loaded;
                    self.robots[o].loaded = !self.robots[o].loaded;
                    self.robots[r].busy = self.p.relay_d - 1;
                    self.robots[o].busy = self.p.relay_d - 1;
                    self.relays += 1;
                    self.events.push(Event {
                        cell: t,
                        kind: EV_RELAY,
                    });
                }
            }
        }
        for k in 0..n {
            let r = self.order[k] as usize;
            if self.relaying[r] {
                continue;
            }
            let t = match self.plans[r] {
                Plan::Blocked(t) => t,
                Plan::Move(t) if self.status[r] == STAYS => t,
                _ => continue,
            };
            let o = self.occupant[t as usize];
            if o == NONE {
                // Lost the claim on a free module to a larger token.
                self.collide(r, t);
                continue;
            }
            let o = o as usize;
            let here = self.robots[r].cell;
            // Head-on: the robot ahead wants this robot's module.
            let head_on = matches!(self.plans[o], Plan::Move(x) | Plan::Blocked(x) if x == here)
                && !self.relaying[o];
            if head_on && self.position[o] > self.position[r] {
                // The larger token keeps its priority and waits for the other to step aside.
                continue;
            }
            self.collide(r, t);
        }
    }

    fn act_all(&mut self) {
        let n = self.robots.len();
        let moves =
            |m: &Amas, r: usize| matches!(m.plans[r], Plan::Move(_)) && m.status[r] == MOVES;
        for r in 0..n {
            if moves(self, r) {
                self.occupant[self.robots[r].cell as usize] = NONE;
            }
        }
        for r in 0..n {
            if let Plan::Move(t) = self.plans[r] {
                if self.status[r] == MOVES {
                    self.occupant[t as usize] = r as u32;
                    self.robots[r].cell = t;
                    self.robots[r].busy = self.p.move_d - 1;
                }
            }
        }
        for k in 0..n {
            let r = self.order[k] as usize;
            if self.relaying[r] {
                continue;
            }
            match self.plans[r] {
                Plan::Pick => {
                    self.robots[r].loaded = true;
                    self.robots[r].busy = self.p.pick_d - 1;
                    self.picked += 1;
                }
                Plan::Remove(t) => {
                    let t = t as usize;
                    if self.state[t] & REMOVE != 0 && self.occupant[t] == NONE && self.removable(t)
                    {
                        self.take(t);
                        self.robots[r].loaded = true;
                        self.robots[r].busy = self.p.pick_d - 1;
                        self.dismantled += 1;
                    }
                }
                Plan::Place(t) => {
                    let t = t as usize;
                    if self.state[t] & VACANT != 0 {
                        self.put(t);
                        self.robots[r].loaded = false;
                        self.robots[r].busy = self.p.place_d - 1;
                        self.placed += 1;
                    }
                }
                Plan::Return => {
                    self.robots[r].loaded = false;
                    self.robots[r].busy = self.p.place_d - 1;
                    self.returned += 1;
                }
                _ => {}
            }
        }
        for &c in &self.claimed {
            self.state[c as usize] &= !CLAIMED;
        }
        self.claimed.clear();
    }

    /// A module is placed at vacant target cell `t`.
    fn put(&mut self, t: usize) {
        self.state[t] = (self.state[t] & !VACANT) | MODULE;
        self.vacant -= 1;
        self.dirty = true;
        self.refresh_around(t);
        self.init_value(t);
        self.top = self.top.min(t / self.w);
    }

    /// The module to be removed at `t` is taken away.
    fn take(&mut self, t: usize) {
        self.state[t] &= CLAIMED;
        self.to_remove -= 1;
        self.dirty = true;
        self.refresh_around(t);
        self.init_value(t);
    }

    /// The fraction of the current target that is built.
    fn built_fraction(&self) -> f64 {
        if self.target_cells == 0 {
            1.0
        } else {
            (self.target_cells - self.vacant) as f64 / self.target_cells as f64
        }
    }
}

/// Footnote 2 and the tighter bound through the shape: Σ 2·d over the modules to assemble,
/// minus robots × the largest d; d is the vertical distance to the supply area (footnote 2) or
/// the shortest path to the supply through the target shape.
fn bounds(target: &[bool], initial: &[bool], w: usize, sh: usize, robots: u64) -> (u64, u64) {
    let mut dist = vec![u32::MAX; target.len()];
    let mut queue = VecDeque::new();
    for x in 0..w {
        let i = (sh - 1) * w + x;
        if target[i] {
            dist[i] = 1;
            queue.push_back(i);
        }
    }
    let lattice = Square::new(w as u32, sh as u32);
    while let Some(i) = queue.pop_front() {
        for j in lattice.neighbours(i) {
            if target[j] && dist[j] == u32::MAX {
                dist[j] = dist[i] + 1;
                queue.push_back(j);
            }
        }
    }
    let (mut sum_v, mut max_v, mut sum_p, mut max_p) = (0u64, 0u64, 0u64, 0u64);
    for i in 0..target.len() {
        if target[i] && !initial[i] {
            let v = (sh - i / w) as u64;
            let p = u64::from(dist[i]);
            sum_v += 2 * v;
            max_v = max_v.max(v);
            sum_p += 2 * p;
            max_p = max_p.max(p);
        }
    }
    (
        sum_v.saturating_sub(robots * max_v),
        sum_p.saturating_sub(robots * max_p),
    )
}

fn action(value: Value) -> Action {
    match value {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

impl Model for Amas {
    fn layout(&self) -> Layout {
        let fields = match self.p.field {
            FieldKind::Continuous => vec![FieldInfo {
                name: "potential".into(),
                label: "potential (eq. 1): 1 at the growth front, 0 at the supply".into(),
                arrows: true,
            }],
            FieldKind::Discrete => vec![
                FieldInfo {
                    name: "to_front".into(),
                    label: "distance to the growth front (eq. 2)".into(),
                    arrows: true,
                },
                FieldInfo {
                    name: "to_supply".into(),
                    label: "distance to the supply (eq. 2)".into(),
                    arrows: true,
                },
            ],
        };
        Layout {
            lattice: LatticeKind::Square,
            dims: [self.w as u32, self.h as u32, 1],
            cells: vec![
                LegendEntry::new(code::VACANT, "target (vacant)", "#dfe6ee"),
                LegendEntry::new(code::SUPPLY, "supply", "#c9a66b"),
                LegendEntry::new(code::SUPPLY_FRONT, "supply at the growth front", "#d9822b"),
                LegendEntry::new(code::MODULE, "module", "#5b7083"),
                LegendEntry::new(code::FRONT, "growth front", "#2b95d6"),
                LegendEntry::new(
                    code::DISASSEMBLY_SUPPLY,
                    "supply (next to a module to remove)",
                    "#a67c52",
                ),
                LegendEntry::new(code::TO_REMOVE, "to be removed", "#c274c2"),
                LegendEntry::new(code::BROKEN, "communication broken", "#30404d"),
            ],
            agents: vec![
                LegendEntry::new(UNLOADED, "robot", "#f2f2f2"),
                LegendEntry::new(LOADED, "robot carrying a module", "#f29d49"),
                LegendEntry::new(UNLOADED_LOST, "robot, no gradient (random move)", "#b8c4ce"),
                LegendEntry::new(
                    LOADED_LOST,
                    "robot carrying, no gradient (random move)",
                    "#c98a4b",
                ),
            ],
            events: vec![
                LegendEntry::new(EV_COLLISION, "collision", "#db3737"),
                LegendEntry::new(EV_RELAY, "module relay", "#0f9960"),
            ],
            fields,
            tools: vec![
                ToolInfo {
                    name: "remove".into(),
                    label: "Remove module (5.4)".into(),
                    action: action(json!({"kind": "remove"})),
                },
                ToolInfo {
                    name: "break".into(),
                    label: "Break communication (5.5)".into(),
                    action: action(json!({"kind": "break"})),
                },
                ToolInfo {
                    name: "dismantle".into(),
                    label: "Mark to be removed (6.2)".into(),
                    action: action(json!({"kind": "dismantle"})),
                },
                ToolInfo {
                    name: "extend".into(),
                    label: "Add target cell".into(),
                    action: action(json!({"kind": "extend"})),
                },
            ],
            cell_labels: false,
            chart: "built".into(),
        }
    }

    fn step(&mut self) {
        self.events.clear();
        self.plan_all();
        self.settle_conflicts();
        self.act_all();
        self.settle();
        for _ in 0..self.p.updates {
            self.field.update(&self.state, self.w, self.top);
        }
        self.steps += 1;
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        self.stage + 1 == self.stages.len() && self.vacant == 0 && self.to_remove == 0
    }

    fn metrics(&self) -> Metrics {
        let mut m = Map::new();
        m.insert("steps".into(), self.steps.into());
        m.insert(
            "total_steps".into(),
            (self.steps * self.robots.len() as u64).into(),
        );
        m.insert("collisions".into(), self.collisions.into());
        m.insert("relays".into(), self.relays.into());
        m.insert("lower_bound".into(), self.lower_bound.into());
        m.insert("path_bound".into(), self.path_bound.into());
        m.insert("built".into(), json!(self.built_fraction()));
        m.insert("placed".into(), self.placed.into());
        m.insert("picked".into(), self.picked.into());
        m.insert("dismantled".into(), self.dismantled.into());
        m.insert("returned".into(), self.returned.into());
        m.insert("removed".into(), self.removed.into());
        m.insert("broken".into(), self.broken.into());
        m.insert("stage".into(), (self.stage as u64 + 1).into());
        m
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
        Cow::Borrowed(&self.display)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let on = |i: usize| self.state[i] & MODULE != 0;
        match (&self.field, name) {
            (Field::Continuous { p, .. }, "potential") => Some(Cow::Owned(
                p.iter()
                    .enumerate()
                    .map(|(i, &v)| if on(i) { v } else { f32::NAN })
                    .collect(),
            )),
            (
                Field::Discrete {
                    to_supply,
                    to_front,
                    ..
                },
                "to_supply" | "to_front",
            ) => {
                let src = if name == "to_supply" {
                    to_supply
                } else {
                    to_front
                };
                Some(Cow::Owned(
                    src.iter()
                        .enumerate()
                        .map(|(i, &v)| {
                            if on(i) && v != FAR {
                                f32::from(v)
                            } else {
                                f32::NAN
                            }
                        })
                        .collect(),
                ))
            }
            _ => None,
        }
    }

    fn agents(&self) -> Vec<Agent> {
        self.robots
            .iter()
            .map(|r| Agent {
                cell: r.cell,
                kind: match (r.loaded, r.lost) {
                    (false, false) => UNLOADED,
                    (true, false) => LOADED,
                    (false, true) => UNLOADED_LOST,
                    (true, true) => LOADED_LOST,
                },
            })
            .collect()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        self.parse(action).map(|_| ())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        let a = self.check(action)?;
        self.perform(&a);
        Ok(())
    }

    fn inspect(&self, i: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if i >= self.state.len() {
            return m;
        }
        let s = self.state[i];
        m.insert("x".into(), (i % self.w).into());
        m.insert("y".into(), (i / self.w).into());
        m.insert("cell".into(), state::describe(s).into());
        let on = s & MODULE != 0;
        match &self.field {
            Field::Continuous { p, .. } => {
                m.insert(
                    "potential".into(),
                    if on { json!(p[i]) } else { Value::Null },
                );
            }
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => {
                let show = |v: u16| {
                    if on && v != FAR {
                        v.into()
                    } else {
                        Value::Null
                    }
                };
                m.insert("to_supply".into(), show(to_supply[i]));
                m.insert("to_front".into(), show(to_front[i]));
            }
        }
        if s & REMOVE != 0 {
            m.insert("removable".into(), self.removable(i).into());
        }
        if self.occupant[i] != NONE {
            let r = self.occupant[i] as usize;
            m.insert("robot".into(), r.into());
            m.insert("loaded".into(), self.robots[r].loaded.into());
            m.insert("busy".into(), self.robots[r].busy.into());
        }
        m
    }
}

#[cfg(test)]
mod tests;
