//! AMAS: assembler robots carrying modules along a gradient field (Terada & Murata, sections 4
//! and 5). See `docs/models/amas.md` for the ODD description and the interpretations made.

use std::borrow::Cow;

use serde::Deserialize;
use serde_json::{json, Map, Value};

use crate::error::{Error, Result};
use crate::hash::StateHasher;
use crate::lattice::{Lattice, LatticeKind, Square};
use crate::models::{
    self, Action, Agent, Event, FieldInfo, Layout, LegendEntry, Metrics, Model, ModelEntry,
    ToolInfo,
};
use crate::rng::Rng;
use crate::scenario::Scenario;
use crate::shape;

pub const ENTRY: ModelEntry = ModelEntry {
    name: "amas",
    title: "AMAS: assembler robots on a gradient field",
    default_max_steps: 100_000,
    build: |s| Ok(Box::new(Amas::new(s)?)),
};

/// The largest lattice side accepted, in cells.
pub const MAX_SIDE: u32 = 2048;

/// Cell codes, also the codes of the cell buffer the page draws.
pub mod cell {
    pub const EMPTY: u8 = 0;
    /// Part of the target, not yet built.
    pub const VACANT: u8 = 1;
    pub const SUPPLY: u8 = 2;
    /// A supply module next to a vacant target cell.
    pub const SUPPLY_FRONT: u8 = 3;
    pub const MODULE: u8 = 4;
    /// A built module next to a vacant target cell: the growth front.
    pub const MODULE_FRONT: u8 = 5;

    pub fn is_module(c: u8) -> bool {
        c >= SUPPLY
    }
    pub fn is_supply(c: u8) -> bool {
        c == SUPPLY || c == SUPPLY_FRONT
    }
    pub fn is_front(c: u8) -> bool {
        c == SUPPLY_FRONT || c == MODULE_FRONT
    }
}

/// Robot kinds in the agent list.
const UNLOADED: u8 = 0;
const LOADED: u8 = 1;
/// Event kinds.
const COLLISION: u8 = 0;

/// Distance value of cells a field has not reached.
const FAR: u16 = u16::MAX;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Spec {
    /// Target shape rows, top first; the supply row is added below the last row.
    target: String,
    robots: u32,
    #[serde(default = "one")]
    field_updates_per_step: u32,
}

fn one() -> u32 {
    1
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Robot {
    cell: u32,
    loaded: bool,
    /// Lost a collision last step: gives way this step by stepping to a free module.
    giving_way: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Plan {
    Wait,
    Pick,
    Place(u32),
    Move(u32),
}

pub struct Amas {
    lattice: Square,
    cells: Vec<u8>,
    to_supply: Vec<u16>,
    to_front: Vec<u16>,
    /// Robot index standing on each cell, or `u32::MAX`.
    occupant: Vec<u32>,
    robots: Vec<Robot>,
    /// Step stamp of the last reservation of each cell, for conflict detection.
    reserved: Vec<u64>,
    order: Vec<u32>,
    plans: Vec<Plan>,
    updates_per_step: u32,
    rng: Rng,
    steps: u64,
    target_cells: u32,
    vacant: u32,
    placed: u64,
    collisions: u64,
    removed: u64,
    lower_bound: u64,
    events: Vec<Event>,
}

impl Amas {
    pub fn new(scenario: &Scenario) -> Result<Amas> {
        let spec: Spec = models::body(scenario)?;
        let target = shape::parse_square(&spec.target).map_err(|e| e.within("target"))?;
        if target.count() == 0 {
            return Err(Error::field("target", "has no '#' cells"));
        }
        let (w, h) = (target.w, target.h + 1);
        if w > MAX_SIDE || h > MAX_SIDE {
            return Err(Error::field(
                "target",
                format!("{w}×{h} cells (with the supply row) exceeds the limit of {MAX_SIDE}×{MAX_SIDE}"),
            ));
        }
        if spec.robots == 0 {
            return Err(Error::field("robots", "at least one robot is needed"));
        }
        if spec.robots > w {
            return Err(Error::field(
                "robots",
                format!(
                    "{} robots do not fit on the supply row of {w} modules",
                    spec.robots
                ),
            ));
        }
        if spec.field_updates_per_step == 0 || spec.field_updates_per_step > 1000 {
            return Err(Error::field(
                "field_updates_per_step",
                "must be from 1 to 1000",
            ));
        }
        let lattice = Square::new(w, h);
        let n = (w * h) as usize;
        let mut cells = vec![cell::EMPTY; n];
        for y in 0..target.h {
            for x in 0..w {
                if target.get(x, y) {
                    cells[(y * w + x) as usize] = cell::VACANT;
                }
            }
        }
        for x in 0..w {
            cells[((h - 1) * w + x) as usize] = cell::SUPPLY;
        }
        let unreached = unreachable_targets(&lattice, &cells);
        if unreached > 0 {
            return Err(Error::field(
                "target",
                format!(
                    "{unreached} target cells are not connected to the supply row below the shape"
                ),
            ));
        }
        let mut rng = Rng::new(scenario.seed);
        let starts = rng.sample_distinct(w as usize, spec.robots as usize);
        let mut occupant = vec![u32::MAX; n];
        let robots: Vec<Robot> = starts
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                let c = (h - 1) * w + x as u32;
                occupant[c as usize] = i as u32;
                Robot {
                    cell: c,
                    loaded: false,
                    giving_way: false,
                }
            })
            .collect();
        let target_cells = target.count() as u32;
        let mut model = Amas {
            lattice,
            to_supply: vec![FAR; n],
            to_front: vec![FAR; n],
            occupant,
            reserved: vec![u64::MAX; n],
            order: (0..spec.robots).collect(),
            plans: vec![Plan::Wait; spec.robots as usize],
            updates_per_step: spec.field_updates_per_step,
            robots,
            rng,
            steps: 0,
            target_cells,
            vacant: target_cells,
            placed: 0,
            collisions: 0,
            removed: 0,
            lower_bound: 0,
            events: Vec::new(),
            cells,
        };
        model.lower_bound = model.footnote_lower_bound();
        for i in 0..n {
            model.refresh_front(i);
        }
        for _ in 0..model.updates_per_step {
            model.update_fields();
        }
        Ok(model)
    }

    /// Footnote 2: twice the Manhattan distance from the supply area to every target cell, minus
    /// robots × the distance to the farthest target cell.
    fn footnote_lower_bound(&self) -> u64 {
        let (w, h) = (self.lattice.w as usize, self.lattice.h as usize);
        let mut sum = 0u64;
        let mut far = 0u64;
        for (i, &c) in self.cells.iter().enumerate() {
            if c == cell::VACANT || (cell::is_module(c) && !cell::is_supply(c)) {
                let d = (h - 1 - i / w) as u64;
                sum += 2 * d;
                far = far.max(d);
            }
        }
        sum.saturating_sub(self.robots.len() as u64 * far)
    }

    fn is_vacant_neighbour(&self, i: usize) -> bool {
        self.lattice
            .neighbours(i)
            .any(|j| self.cells[j] == cell::VACANT)
    }

    /// Recomputes whether module `i` is on the growth front.
    fn refresh_front(&mut self, i: usize) {
        let c = self.cells[i];
        if !cell::is_module(c) {
            return;
        }
        let front = self.is_vacant_neighbour(i);
        self.cells[i] = match (cell::is_supply(c), front) {
            (true, true) => cell::SUPPLY_FRONT,
            (true, false) => cell::SUPPLY,
            (false, true) => cell::MODULE_FRONT,
            (false, false) => cell::MODULE,
        };
    }

    fn refresh_around(&mut self, i: usize) {
        self.refresh_front(i);
        for d in 0..4 {
            if let Some(j) = self.lattice.neighbour(i, d) {
                self.refresh_front(j);
            }
        }
    }

    /// One sweep of equation 2 over every module, in lattice order, for both fields. A module
    /// reads its neighbours' current values (modules update one after another, as in the
    /// pseudo-code of section 5.1).
    fn update_fields(&mut self) {
        let w = self.lattice.w as usize;
        let n = self.cells.len();
        for i in 0..n {
            let c = self.cells[i];
            if !cell::is_module(c) {
                self.to_supply[i] = FAR;
                self.to_front[i] = FAR;
                continue;
            }
            let mut ms = FAR;
            let mut mf = FAR;
            let mut take = |j: usize| {
                if cell::is_module(self.cells[j]) {
                    ms = ms.min(self.to_supply[j]);
                    mf = mf.min(self.to_front[j]);
                }
            };
            if i % w + 1 < w {
                take(i + 1);
            }
            if i % w > 0 {
                take(i - 1);
            }
            if i >= w {
                take(i - w);
            }
            if i + w < n {
                take(i + w);
            }
            self.to_supply[i] = if cell::is_supply(c) {
                0
            } else {
                ms.saturating_add(1)
            };
            self.to_front[i] = if cell::is_front(c) {
                0
            } else {
                mf.saturating_add(1)
            };
        }
    }

    /// The module a robot at `at` steps onto, following `field` downhill. Where every module
    /// around shows the same value there is no effective gradient (footnote 3) and the robot
    /// picks a module at random.
    fn choose_move(&mut self, at: usize, loaded: bool) -> Option<u32> {
        let field = if loaded {
            &self.to_front
        } else {
            &self.to_supply
        };
        let mut options = [0u32; 4];
        let mut values = [0u16; 4];
        let mut n = 0;
        for j in self.lattice.neighbours(at) {
            if cell::is_module(self.cells[j]) {
                options[n] = j as u32;
                values[n] = field[j];
                n += 1;
            }
        }
        if n == 0 {
            return None;
        }
        let lo = *values[..n].iter().min().unwrap();
        let hi = *values[..n].iter().max().unwrap();
        if lo == hi {
            return Some(options[self.rng.index(n)]);
        }
        let mut best = [0u32; 4];
        let mut m = 0;
        for k in 0..n {
            if values[k] == lo {
                best[m] = options[k];
                m += 1;
            }
        }
        Some(best[self.rng.index(m)])
    }

    /// A free module next to `at` (no robot, not claimed this step), chosen at random.
    fn free_neighbour(&mut self, at: usize) -> Option<u32> {
        let stamp = self.steps;
        let mut free = [0u32; 4];
        let mut n = 0;
        for j in self.lattice.neighbours(at) {
            if cell::is_module(self.cells[j])
                && self.occupant[j] == u32::MAX
                && self.reserved[j] != stamp
            {
                free[n] = j as u32;
                n += 1;
            }
        }
        (n > 0).then(|| free[self.rng.index(n)])
    }

    fn plan(&mut self, r: usize) -> Plan {
        let Robot {
            cell: at,
            loaded,
            giving_way,
        } = self.robots[r];
        let at = at as usize;
        if giving_way {
            self.robots[r].giving_way = false;
            if let Some(to) = self.free_neighbour(at) {
                return Plan::Move(to);
            }
        }
        if loaded && cell::is_front(self.cells[at]) {
            let mut vacant = [0u32; 4];
            let mut n = 0;
            for j in self.lattice.neighbours(at) {
                if self.cells[j] == cell::VACANT {
                    vacant[n] = j as u32;
                    n += 1;
                }
            }
            return Plan::Place(vacant[self.rng.index(n)]);
        }
        if !loaded && cell::is_supply(self.cells[at]) {
            return Plan::Pick;
        }
        match self.choose_move(at, loaded) {
            Some(to) => Plan::Move(to),
            None => Plan::Wait,
        }
    }

    /// Robots plan in a random order. Reaching for a module another robot stands on, or one an
    /// earlier planner claimed, is a collision: the token exchange of section 4.6 is equivalent
    /// to the random planning order. The loser waits this step (the collision penalty) and gives
    /// way the next, so two robots meeting head-on in a corridor do not block each other forever.
    fn plan_all(&mut self) {
        let stamp = self.steps;
        self.rng.shuffle(&mut self.order);
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            let mut plan = self.plan(r);
            if let Plan::Move(to) | Plan::Place(to) = plan {
                let t = to as usize;
                let blocked = self.reserved[t] == stamp
                    || (matches!(plan, Plan::Move(_)) && self.occupant[t] != u32::MAX);
                if blocked {
                    self.collisions += 1;
                    self.events.push(Event {
                        cell: to,
                        kind: COLLISION,
                    });
                    self.robots[r].giving_way = true;
                    plan = Plan::Wait;
                } else {
                    self.reserved[t] = stamp;
                }
            }
            self.plans[r] = plan;
        }
    }

    fn act_all(&mut self) {
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            match self.plans[r] {
                Plan::Wait => {}
                Plan::Pick => self.robots[r].loaded = true,
                Plan::Place(t) => {
                    let t = t as usize;
                    self.cells[t] = cell::MODULE;
                    self.vacant -= 1;
                    self.placed += 1;
                    self.robots[r].loaded = false;
                    self.refresh_around(t);
                }
                Plan::Move(to) => {
                    let from = self.robots[r].cell as usize;
                    self.occupant[from] = u32::MAX;
                    self.occupant[to as usize] = r as u32;
                    self.robots[r].cell = to;
                }
            }
        }
    }

    fn removable(&self, i: usize) -> Result<()> {
        match self.cells.get(i) {
            None => Err(Error::field(
                "cells",
                format!("cell {i} is outside the lattice"),
            )),
            Some(&c) if !cell::is_module(c) || cell::is_supply(c) => Err(Error::field(
                "cells",
                format!("cell {i} holds no built module"),
            )),
            Some(_) if self.occupant[i] != u32::MAX => {
                Err(Error::field("cells", format!("a robot stands on cell {i}")))
            }
            Some(_) => Ok(()),
        }
    }

    fn remove(&mut self, i: usize) {
        self.cells[i] = cell::VACANT;
        self.vacant += 1;
        self.removed += 1;
        self.refresh_around(i);
    }
}

/// A disturbance: `{"kind": "remove", "count": N}` removes N built modules chosen at random
/// among those no robot stands on; `{"kind": "remove", "cells": [i, ...]}` removes those cells.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RemoveAction {
    kind: String,
    #[serde(default)]
    count: Option<u32>,
    #[serde(default)]
    cells: Option<Vec<u32>>,
}

fn parse_action(action: &Action) -> Result<RemoveAction> {
    let a: RemoveAction = crate::error::from_value(Value::Object(action.clone()))?;
    if a.kind != "remove" {
        return Err(Error::field(
            "kind",
            format!("unknown disturbance '{}'; known: remove", a.kind),
        ));
    }
    match (&a.count, &a.cells) {
        (Some(_), None) | (None, Some(_)) => Ok(a),
        _ => Err(Error::field("", "give either count or cells")),
    }
}

impl Model for Amas {
    fn layout(&self) -> Layout {
        Layout {
            lattice: LatticeKind::Square,
            dims: [self.lattice.w, self.lattice.h, 1],
            cells: vec![
                LegendEntry::new(cell::VACANT, "target (vacant)", "#dfe6ee"),
                LegendEntry::new(cell::SUPPLY, "supply", "#c9a66b"),
                LegendEntry::new(cell::SUPPLY_FRONT, "supply at growth front", "#d9822b"),
                LegendEntry::new(cell::MODULE, "module", "#5b7083"),
                LegendEntry::new(cell::MODULE_FRONT, "growth front", "#2b95d6"),
            ],
            agents: vec![
                LegendEntry::new(UNLOADED, "robot", "#f2f2f2"),
                LegendEntry::new(LOADED, "robot carrying a module", "#f29d49"),
            ],
            events: vec![LegendEntry::new(COLLISION, "collision", "#db3737")],
            fields: vec![
                FieldInfo {
                    name: "to_supply".into(),
                    label: "distance to supply".into(),
                    arrows: true,
                },
                FieldInfo {
                    name: "to_front".into(),
                    label: "distance to growth front".into(),
                    arrows: true,
                },
            ],
            cell_labels: false,
            tools: vec![ToolInfo {
                name: "remove".into(),
                label: "Remove module".into(),
                action: json!({"kind": "remove"})
                    .as_object()
                    .cloned()
                    .unwrap_or_default(),
            }],
        }
    }

    fn step(&mut self) {
        self.events.clear();
        self.plan_all();
        self.act_all();
        for _ in 0..self.updates_per_step {
            self.update_fields();
        }
        self.steps += 1;
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        self.vacant == 0
    }

    fn metrics(&self) -> Metrics {
        let mut m = Map::new();
        m.insert("steps".into(), self.steps.into());
        m.insert(
            "total_steps".into(),
            (self.steps * self.robots.len() as u64).into(),
        );
        m.insert("collisions".into(), self.collisions.into());
        m.insert("placed".into(), self.placed.into());
        m.insert("removed".into(), self.removed.into());
        m.insert("lower_bound".into(), self.lower_bound.into());
        let built = f64::from(self.target_cells - self.vacant) / f64::from(self.target_cells);
        m.insert("built".into(), json!(built));
        m
    }

    fn hash_state(&self, h: &mut StateHasher) {
        h.bytes(&self.cells);
        h.u16s(&self.to_supply);
        h.u16s(&self.to_front);
        for r in &self.robots {
            h.u32(r.cell);
            h.bool(r.loaded);
            h.bool(r.giving_way);
        }
        h.u64(self.collisions);
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        Cow::Borrowed(&self.cells)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let source = match name {
            "to_supply" => &self.to_supply,
            "to_front" => &self.to_front,
            _ => return None,
        };
        Some(Cow::Owned(
            source
                .iter()
                .map(|&v| if v == FAR { f32::NAN } else { f32::from(v) })
                .collect(),
        ))
    }

    fn agents(&self) -> Vec<Agent> {
        self.robots
            .iter()
            .map(|r| Agent {
                cell: r.cell,
                kind: if r.loaded { LOADED } else { UNLOADED },
            })
            .collect()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        let a = parse_action(action)?;
        if let Some(cells) = &a.cells {
            for &c in cells {
                self.removable(c as usize)?;
            }
        }
        Ok(())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        self.check_action(action)?;
        let a = parse_action(action)?;
        if let Some(cells) = a.cells {
            for c in cells {
                if self.removable(c as usize).is_ok() {
                    self.remove(c as usize);
                }
            }
        } else if let Some(count) = a.count {
            let candidates: Vec<usize> = (0..self.cells.len())
                .filter(|&i| self.removable(i).is_ok())
                .collect();
            let picks = self.rng.sample_distinct(candidates.len(), count as usize);
            for p in picks {
                self.remove(candidates[p]);
            }
        }
        Ok(())
    }

    fn inspect(&self, i: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if i >= self.cells.len() {
            return m;
        }
        let c = self.lattice.coord(i);
        m.insert("x".into(), c.x.into());
        m.insert("y".into(), c.y.into());
        let show = |v: u16| if v == FAR { Value::Null } else { v.into() };
        m.insert("to_supply".into(), show(self.to_supply[i]));
        m.insert("to_front".into(), show(self.to_front[i]));
        if self.occupant[i] != u32::MAX {
            m.insert("robot".into(), self.occupant[i].into());
        }
        m
    }
}

/// Target cells that no path of target cells joins to the supply row.
fn unreachable_targets(lattice: &Square, cells: &[u8]) -> usize {
    let mut seen = vec![false; cells.len()];
    let mut stack: Vec<usize> = (0..cells.len())
        .filter(|&i| cell::is_supply(cells[i]))
        .collect();
    for &i in &stack {
        seen[i] = true;
    }
    while let Some(i) = stack.pop() {
        for j in lattice.neighbours(i) {
            if !seen[j] && cells[j] == cell::VACANT {
                seen[j] = true;
                stack.push(j);
            }
        }
    }
    (0..cells.len())
        .filter(|&i| cells[i] == cell::VACANT && !seen[i])
        .count()
}

#[cfg(test)]
mod tests;
