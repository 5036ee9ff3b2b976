//! Cubes3d: identical units on the cubic lattice reconfiguring themselves toward a target given
//! as type-lists, by pairwise motion and stochastic relaxation (Yoshida, Murata, Kurokawa, Tomita
//! and Kokaji, "A distributed reconfiguration method for 3-D homogeneous structure", sections 2 to
//! 6; and section 5 of "Experiment of self-repairing modular machine"). See
//! `docs/models/cubes3d.md` for the ODD description and every interpretation made.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};
use serde_json::{json, Map, Value};

use crate::error::{Error, Result};
use crate::hash::StateHasher;
use crate::lattice::LatticeKind;
use crate::math;
use crate::models::{
    self, Action, Agent, Event, FieldInfo, Layout, LegendEntry, Metrics, Model, ModelEntry, Scene,
    ToolInfo,
};
use crate::rng::Rng;
use crate::scenario::Scenario;
use crate::shape::{self, Grid3};

pub mod motion;
pub mod paper;
pub mod typelist;
pub mod types;

use motion::{Scratch, Structure, DIRS, PAD};
use typelist::TypeList;
use types::{CODES, NAMES};

pub const ENTRY: ModelEntry = ModelEntry {
    name: "cubes3d",
    title: "3-D units: type-list targets and stochastic relaxation",
    default_max_steps: 5000,
    model_version: 2,
    build: |s| Ok(Box::new(Cubes::new(s)?)),
    normalize: models::normalized::<Spec>,
};

/// The largest side of the space, in cells (padding included).
pub const MAX_SIDE: u32 = 512;
/// The most cells the space may have.
pub const MAX_CELLS: u64 = 1 << 22;
/// The most units a structure may have.
pub const MAX_UNITS: usize = 100_000;
/// The most targets a scenario may switch between.
pub const MAX_TARGETS: usize = 16;

/// Cell colours by connection type, code 1 (C1) to 9 (C6).
const COLOURS: [&str; CODES] = [
    "", "#e15759", "#f28e2b", "#edc948", "#59a14f", "#4e79a7", "#76b7b2", "#b07aa1", "#ff9da7",
    "#9c755f",
];

/// Event kinds.
const ARRIVED: u8 = 0;
const LEFT: u8 = 1;

/// Per-cell flags that travel with a unit.
const HELD_LIT: u8 = 1;
const HELD_USER: u8 = 2;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Selection {
    /// Equations 7 and 8: P_i ∝ exp(-D_i / T), T = c / log(1 + t).
    Mrf,
    /// Every option (staying included) equally likely.
    Random,
    /// The option of least difference, ties broken at random.
    Steepest,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize)]
pub enum Ground {
    /// No ground: free space on every side.
    #[default]
    #[serde(rename = "none")]
    Open,
    /// A plane under the lowest layer of the shape that units cannot pass.
    #[serde(rename = "floor")]
    Floor,
    /// As `floor`, and units touching the plane are fixed to it (section 6).
    #[serde(rename = "fixed")]
    Fixed,
    /// As `floor`, and the plane holds the units touching it (a support), which may still move.
    #[serde(rename = "anchor")]
    Anchor,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct Spec {
    /// The initial configuration: cubic-lattice text layers from the ground up.
    shape: String,
    targets: Vec<TargetSpec>,
    #[serde(default = "default_selection")]
    selection: Selection,
    #[serde(default = "default_w")]
    w: f64,
    #[serde(default = "default_a")]
    a: f64,
    #[serde(default = "default_c")]
    c: f64,
    #[serde(default = "default_movable")]
    movable: Vec<String>,
    #[serde(default = "one")]
    movers: u32,
    #[serde(default = "default_mover_distance")]
    mover_distance: u32,
    #[serde(default = "default_margin")]
    margin: u32,
    #[serde(default)]
    ground: Ground,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    light: Option<String>,
    #[serde(default = "default_stable_steps")]
    stable_steps: u32,
    /// Model version 1 weighted its light-seeking term by this factor (a form the paper does not
    /// give; see the docs' Interpretations). Every link made then carries it, so it is still
    /// read, and ignored: such a link opens with the notice that results may differ.
    #[serde(default, skip_serializing, rename = "light_priority")]
    _light_priority: Option<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct TargetSpec {
    #[serde(default)]
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    type_lists: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    shape: Option<String>,
    #[serde(default)]
    threshold: f64,
    #[serde(default)]
    hold_lit: bool,
}

fn default_selection() -> Selection {
    Selection::Mrf
}
fn default_w() -> f64 {
    3.0
}
fn default_a() -> f64 {
    1.0
}
fn default_c() -> f64 {
    10.0
}
fn default_movable() -> Vec<String> {
    vec!["C1".into(), "C21".into(), "C31".into()]
}
fn one() -> u32 {
    1
}
fn default_mover_distance() -> u32 {
    7
}
fn default_margin() -> u32 {
    8
}
fn default_stable_steps() -> u32 {
    30
}

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
    /// D_0 of the unit in each cell (NaN where there is none).
    diff: Vec<f64>,
    units: Vec<u32>,
    upos: Vec<u32>,
    /// Units that may be chosen to move: of a movable type, not fixed, not held.
    movable: Vec<u32>,
    mpos: Vec<u32>,
    movable_types: u16,
    targets: Vec<Target>,
    /// The target each unit is working toward (section 6: each unit switches its own), per
    /// cell, moving with the unit.
    target: Vec<u8>,
    /// Consecutive steps the unit's D_0 has stayed under its target's threshold, per cell.
    stable: Vec<u32>,
    table: [[f64; CODES]; CODES],
    w: f64,
    c: f64,
    selection: Selection,
    movers: u32,
    mover_distance: u32,
    ground: Ground,
    /// The lowest layer units may occupy.
    floor_z: i32,
    light: Option<usize>,
    stable_steps: u32,
    /// Target switches made by units, all together.
    switches: u64,
    /// Offsets of the cells within Manhattan distance 2.
    near2: Vec<isize>,
    rng: Rng,
    steps: u64,
    moves: u64,
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
    options: Vec<(u32, f64)>,
    weights: Vec<f64>,
    events: Vec<Event>,
}

fn light_dir(text: &str) -> Result<usize> {
    const NAMES: [&str; 6] = ["+x", "-x", "+y", "-y", "+z", "-z"];
    NAMES.iter().position(|n| *n == text).ok_or_else(|| {
        Error::field(
            "light",
            format!(
                "'{text}' is not a direction; use one of {}",
                NAMES.join(", ")
            ),
        )
    })
}

fn check_positive(name: &str, v: f64) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::field(
            name,
            format!("must be a positive finite number, not {v}"),
        ))
    }
}

fn parse_shape(text: &str, path: &str) -> Result<Grid3> {
    let g = shape::parse_cubic(text).map_err(|e| e.within(path))?;
    if g.count() < 2 {
        return Err(Error::field(
            path,
            "needs at least two units ('#' cells): a lone unit has no connection type and cannot move",
        ));
    }
    Ok(g)
}

impl Cubes {
    pub fn new(scenario: &Scenario) -> Result<Cubes> {
        let spec: Spec = models::body(scenario)?;
        check_positive("w", spec.w)?;
        check_positive("a", spec.a)?;
        check_positive("c", spec.c)?;
        if spec.stable_steps == 0 {
            return Err(Error::field("stable_steps", "must be at least 1"));
        }
        if spec.movers == 0 || spec.movers > 1024 {
            return Err(Error::field("movers", "must be from 1 to 1024"));
        }
        if spec.mover_distance == 0 || spec.mover_distance > 1000 {
            return Err(Error::field("mover_distance", "must be from 1 to 1000"));
        }
        if spec.margin > 200 {
            return Err(Error::field("margin", "must be at most 200 cells"));
        }
        let mut movable_types = 0u16;
        for (i, name) in spec.movable.iter().enumerate() {
            let code = types::code(name).ok_or_else(|| {
                Error::field(
                    format!("movable[{i}]"),
                    format!(
                        "unknown connection type '{name}'; known: {}",
                        types::known_names()
                    ),
                )
            })?;
            movable_types |= 1 << code;
        }
        let light = spec.light.as_deref().map(light_dir).transpose()?;

        let shape = parse_shape(&spec.shape, "shape")?;
        if shape.count() > MAX_UNITS {
            return Err(Error::field(
                "shape",
                format!("{} units exceed the limit of {MAX_UNITS}", shape.count()),
            ));
        }
        if spec.targets.is_empty() {
            return Err(Error::field("targets", "give at least one target"));
        }
        if spec.targets.len() > MAX_TARGETS {
            return Err(Error::field(
                "targets",
                format!("at most {MAX_TARGETS} targets"),
            ));
        }
        let mut target_shapes: Vec<Option<Grid3>> = Vec::new();
        let mut target_lists: Vec<Vec<TypeList>> = Vec::new();
        for (i, t) in spec.targets.iter().enumerate() {
            let path = format!("targets[{i}]");
            let g = t
                .shape
                .as_deref()
                .map(|s| parse_shape(s, &format!("{path}.shape")))
                .transpose()?;
            let lists =
                match (&t.type_lists, &g) {
                    (Some(text), _) => typelist::parse(text)
                        .map_err(|e| e.within(&format!("{path}.type_lists")))?,
                    (None, Some(g)) => typelist::describe_grid(g)
                        .map_err(|e| e.within(&format!("{path}.shape")))?,
                    (None, None) => {
                        return Err(Error::field(
                            path,
                            "give type_lists, a shape to derive them from, or both",
                        ))
                    }
                };
            if !(t.threshold.is_finite() && t.threshold >= 0.0) {
                return Err(Error::field(
                    format!("{path}.threshold"),
                    "must be a finite number of at least 0",
                ));
            }
            if t.hold_lit && light.is_none() {
                return Err(Error::field(
                    format!("{path}.hold_lit"),
                    "needs a light direction (the light key)",
                ));
            }
            target_lists.push(lists);
            target_shapes.push(g);
        }

        // The space: the largest shape plus the margin on every side (none under a ground plane),
        // plus the padding.
        let m = spec.margin;
        let mut ext = [shape.w, shape.h, shape.d];
        for g in target_shapes.iter().flatten() {
            ext = [ext[0].max(g.w), ext[1].max(g.h), ext[2].max(g.d)];
        }
        let grounded = spec.ground != Ground::Open;
        let below = if grounded { 0 } else { m };
        let dims = [
            2 * PAD + 2 * m + ext[0],
            2 * PAD + 2 * m + ext[1],
            2 * PAD + below + m + ext[2],
        ];
        let cells = dims.iter().map(|&d| u64::from(d)).product::<u64>();
        if dims.iter().any(|&d| d > MAX_SIDE) || cells > MAX_CELLS {
            return Err(Error::field(
                "shape",
                format!(
                    "the space the shapes need with margin {m} ({}×{}×{} cells) exceeds the limit of {MAX_SIDE} per side and {MAX_CELLS} cells",
                    dims[0], dims[1], dims[2]
                ),
            ));
        }
        let off = [PAD + m, PAD + m, PAD + below];
        let mut st = Structure::new(
            dims,
            [PAD; 3],
            [dims[0] - PAD, dims[1] - PAD, dims[2] - PAD],
        );
        if matches!(spec.ground, Ground::Fixed | Ground::Anchor) {
            st.plane = Some(PAD as i32);
        }
        let place = |st: &Structure, g: &Grid3| -> Vec<usize> {
            typelist::grid_units(g)
                .into_iter()
                .filter_map(|(x, y, z)| {
                    st.index([x + off[0] as i32, y + off[1] as i32, z + off[2] as i32])
                })
                .collect()
        };
        let start = place(&st, &shape);
        st.place(&start);
        // A unit touching no other has no type, so it would not even count as placed.
        if start.iter().any(|&c| !st.occupied(c)) || !st.connected() {
            return Err(Error::field(
                "shape",
                "the units are not all connected; every unit must touch the others face to face",
            ));
        }
        let targets = spec
            .targets
            .iter()
            .zip(target_lists)
            .zip(&target_shapes)
            .map(|((t, lists), g)| Target {
                name: t.name.clone(),
                lists: lists.iter().map(TypeList::padded).collect(),
                ghost: g
                    .as_ref()
                    .map(|g| place(&st, g).into_iter().map(|c| c as u32).collect())
                    .unwrap_or_default(),
                threshold: t.threshold,
                hold_lit: t.hold_lit,
            })
            .collect();

        let mut near2 = Vec::new();
        let [w, h, _] = dims;
        for dz in -2i32..=2 {
            for dy in -2i32..=2 {
                for dx in -2i32..=2 {
                    if dx.abs() + dy.abs() + dz.abs() <= 2 {
                        near2.push(
                            dx as isize + (dy as isize + dz as isize * h as isize) * w as isize,
                        );
                    }
                }
            }
        }
        let len = st.len();
        let mut model = Cubes {
            flags: vec![0; len],
            diff: vec![f64::NAN; len],
            units: Vec::with_capacity(start.len()),
            upos: vec![u32::MAX; len],
            movable: Vec::new(),
            mpos: vec![u32::MAX; len],
            movable_types,
            targets,
            target: vec![0; len],
            stable: vec![0; len],
            table: typelist::diff_table(spec.a),
            w: spec.w,
            c: spec.c,
            selection: spec.selection,
            movers: spec.movers,
            mover_distance: spec.mover_distance,
            ground: spec.ground,
            floor_z: PAD as i32,
            light,
            stable_steps: spec.stable_steps,
            switches: 0,
            near2,
            rng: Rng::stream(scenario.seed, 1),
            steps: 0,
            moves: 0,
            zero: 0,
            start_light: 0.0,
            scratch: Scratch::default(),
            order: Vec::new(),
            deferred: Vec::new(),
            arrived: Vec::new(),
            options: Vec::new(),
            weights: Vec::new(),
            events: Vec::new(),
            st,
        };
        for &c in &start {
            model.upos[c] = model.units.len() as u32;
            model.units.push(c as u32);
        }
        model.recompute_all();
        model.start_light = model.light_position();
        Ok(model)
    }

    /// Equation 4 for a unit whose type and sorted neighbour types are `prof`, against target
    /// `target`: the least weighted difference over its type-lists.
    fn difference(&self, target: u8, prof: &[u8; 7]) -> f64 {
        let mut best = f64::INFINITY;
        for l in &self.targets[target as usize].lists {
            let mut s = self.w * self.table[l[0] as usize][prof[0] as usize];
            for n in 1..7 {
                s += self.table[l[n] as usize][prof[n] as usize];
            }
            if s < best {
                best = s;
            }
        }
        best
    }

    fn z(&self, i: usize) -> i32 {
        let [w, h, _] = self.st.dims;
        (i / (w as usize * h as usize)) as i32
    }

    /// Fixed to the ground plane (section 6).
    fn fixed(&self, i: usize) -> bool {
        self.ground == Ground::Fixed && self.z(i) == self.floor_z
    }

    /// May the unit at `i` be chosen to move?
    fn eligible(&self, i: usize) -> bool {
        let t = self.st.types[i];
        t != 0
            && self.movable_types & (1 << t) != 0
            && self.flags[i] & (HELD_LIT | HELD_USER) == 0
            && !self.fixed(i)
    }

    /// Brings the unit at `i` into or out of the movable set.
    fn refresh(&mut self, i: usize) {
        let want = self.eligible(i);
        let have = self.mpos[i] != u32::MAX;
        if want && !have {
            self.mpos[i] = self.movable.len() as u32;
            self.movable.push(i as u32);
        } else if !want && have {
            let k = self.mpos[i] as usize;
            let last = *self.movable.last().expect("the set holds i");
            self.movable.swap_remove(k);
            if last as usize != i {
                self.mpos[last as usize] = k as u32;
            }
            self.mpos[i] = u32::MAX;
        }
    }

    /// Recomputes D_0 of the unit at `i`, keeping the count of zeros.
    fn rediff(&mut self, i: usize) {
        if !self.st.occupied(i) {
            return;
        }
        let new = self.difference(self.target[i], &self.st.profile(i));
        let old = self.diff[i];
        if old == 0.0 && new != 0.0 {
            self.zero -= 1;
        } else if old != 0.0 && new == 0.0 {
            self.zero += 1;
        }
        self.diff[i] = new;
    }

    fn recompute_all(&mut self) {
        for k in 0..self.units.len() {
            let c = self.units[k] as usize;
            self.rediff(c);
            self.refresh(c);
        }
    }

    /// Bookkeeping after the units at or next to `cells` changed: D_0 within distance 2 (their
    /// own type or a neighbour's may have changed), membership within distance 1.
    fn after_change(&mut self, cells: &[usize]) {
        for &c in cells {
            for k in 0..self.near2.len() {
                let x = (c as isize + self.near2[k]) as usize;
                self.rediff(x);
            }
        }
        for &c in cells {
            self.refresh(c);
            for d in 0..6 {
                let x = self.st.nb(c, d);
                self.refresh(x);
            }
        }
    }

    /// Takes the unit at `i` out of the books before it leaves its cell.
    fn vacate(&mut self, i: usize) {
        if self.diff[i] == 0.0 {
            self.zero -= 1;
        }
        self.diff[i] = f64::NAN;
        self.flags[i] = 0;
        self.target[i] = 0;
        self.stable[i] = 0;
        let k = self.upos[i] as usize;
        self.upos[i] = u32::MAX;
        self.units.swap_remove(k);
        if k < self.units.len() {
            self.upos[self.units[k] as usize] = k as u32;
        }
    }

    fn do_move(&mut self, from: usize, to: usize) {
        let flags = self.flags[from];
        let target = self.target[from];
        let stable = self.stable[from];
        let k = self.upos[from];
        // Moving keeps the unit's place in the list, so sums over units keep their order.
        if self.diff[from] == 0.0 {
            self.zero -= 1;
        }
        self.diff[from] = f64::NAN;
        self.flags[from] = 0;
        self.target[from] = 0;
        self.stable[from] = 0;
        self.upos[from] = u32::MAX;
        self.units[k as usize] = to as u32;
        self.upos[to] = k;
        self.flags[to] = flags;
        self.target[to] = target;
        self.stable[to] = stable;
        self.st.relocate(from, to);
        self.after_change(&[from, to]);
        self.moves += 1;
        self.events.push(Event {
            cell: to as u32,
            kind: ARRIVED,
        });
        self.events.push(Event {
            cell: from as u32,
            kind: LEFT,
        });
    }

    /// The component of a cell's position along the light (0 without light).
    fn along_light(&self, i: usize) -> f64 {
        match self.light {
            None => 0.0,
            Some(d) => {
                let c = self.st.coord(i);
                let v = DIRS[d];
                f64::from(c[0] * v[0] + c[1] * v[1] + c[2] * v[2])
            }
        }
    }

    /// Centre of mass along the light.
    fn light_position(&self) -> f64 {
        let n = self.units.len().max(1) as f64;
        self.units
            .iter()
            .map(|&c| self.along_light(c as usize))
            .sum::<f64>()
            / n
    }

    /// Does the unit at `i` see the light: no unit between it and the source?
    fn lit(&self, i: usize) -> bool {
        let Some(d) = self.light else {
            return false;
        };
        let mut c = self.st.coord(i);
        loop {
            let v = DIRS[d];
            c = [c[0] + v[0], c[1] + v[1], c[2] + v[2]];
            match self.st.index(c) {
                None => return true,
                Some(j) if self.st.occupied(j) => return false,
                Some(_) => {}
            }
        }
    }

    fn total_difference(&self) -> f64 {
        self.units.iter().map(|&c| self.diff[c as usize]).sum()
    }

    /// The target most units are working toward (the lower index on a tie).
    fn main_target(&self) -> usize {
        let mut count = [0usize; MAX_TARGETS];
        for &c in &self.units {
            count[self.target[c as usize] as usize] += 1;
        }
        let best = count.iter().copied().max().unwrap_or(0);
        count.iter().position(|&n| n == best).unwrap_or(0)
    }

    /// The unit at `c` moves on to target `to` (section 6): if that target asks for it and the
    /// unit sees the light, it holds still until its next switch.
    fn switch_unit(&mut self, c: usize, to: usize) {
        self.target[c] = to as u8;
        self.stable[c] = 0;
        self.switches += 1;
        self.flags[c] &= !HELD_LIT;
        if self.targets[to].hold_lit && self.lit(c) {
            self.flags[c] |= HELD_LIT;
        }
        self.rediff(c);
        self.refresh(c);
    }

    /// The switching rule of section 6, run by every unit after each step: a unit whose D_0
    /// has stayed under its target's threshold for `stable_steps` steps moves on to the next
    /// target.
    fn switch_targets(&mut self) {
        for k in 0..self.units.len() {
            let c = self.units[k] as usize;
            if self.diff[c] < self.targets[self.target[c] as usize].threshold {
                self.stable[c] += 1;
            } else {
                self.stable[c] = 0;
            }
            if self.stable[c] >= self.stable_steps {
                let next = (self.target[c] as usize + 1) % self.targets.len();
                self.switch_unit(c, next);
            }
        }
    }

    /// Is `c` at least `mover_distance` (Manhattan) from every unit that moved this step?
    fn far_from_movers(&self, c: usize) -> bool {
        let cc = self.st.coord(c);
        self.arrived.iter().all(|&o| {
            let oc = self.st.coord(o as usize);
            let dist: i32 = (0..3).map(|k| (cc[k] - oc[k]).abs()).sum();
            dist >= self.mover_distance as i32
        })
    }

    /// One control step's moves (section 5): every unit makes its choice, and of those that
    /// choose to move, one moves (up to `movers` with footnote 2, each at least
    /// `mover_distance` from the others). Asking the units in a random order and letting the
    /// first that chooses to move go gives each of them the same chance as drawing among all
    /// that chose to move, and asks only as many as needed. With a light, a unit whose choice
    /// approaches the source goes before one whose choice does not (section 6: "a higher moving
    /// priority to reachable positions approaching the light source").
    fn move_units(&mut self, temp: f64, s: &mut Scratch) {
        let mut order = std::mem::take(&mut self.order);
        order.clear();
        order.extend_from_slice(&self.movable);
        self.arrived.clear();
        self.deferred.clear();
        let want = self.movers as usize;
        if self.selection == Selection::Steepest {
            while self.arrived.len() < want {
                let Some((p, dest)) = self.steepest(&order, s) else {
                    break;
                };
                self.do_move(p, dest);
                self.arrived.push(dest as u32);
            }
            self.order = order;
            return;
        }
        let n = order.len();
        for k in 0..n {
            if self.arrived.len() == want {
                break;
            }
            let j = k + self.rng.index(n - k);
            order.swap(k, j);
            let p = order[k] as usize;
            if !self.eligible(p) || !self.far_from_movers(p) {
                continue;
            }
            let Some(dest) = self.decide(p, temp, s) else {
                continue;
            };
            if self.light.is_some() && self.along_light(dest) <= self.along_light(p) {
                self.deferred.push((p as u32, dest as u32));
                continue;
            }
            self.do_move(p, dest);
            self.arrived.push(dest as u32);
        }
        let mut deferred = std::mem::take(&mut self.deferred);
        for &(p, dest) in &deferred {
            if self.arrived.len() == want {
                break;
            }
            let (p, dest) = (p as usize, dest as usize);
            if !self.eligible(p) || !self.far_from_movers(p) {
                continue;
            }
            // An earlier move of this step may have changed what this unit can reach.
            self.st.reachable(p, s);
            if s.moves.iter().any(|m| m.dest as usize == dest) {
                self.do_move(p, dest);
                self.arrived.push(dest as u32);
            }
        }
        deferred.clear();
        self.deferred = deferred;
        self.order = order;
    }

    /// The steepest-descent baseline of section 5: of all the reachable positions of the units
    /// that may move (and are far enough from this step's movers), the one with the least
    /// difference, ties broken at random. A unit takes it whether or not it is better than
    /// staying: the rule selects a reachable position.
    fn steepest(&mut self, units: &[u32], s: &mut Scratch) -> Option<(usize, usize)> {
        let mut best = None;
        let mut least = f64::INFINITY;
        let mut ties = 0u32;
        for &p in units {
            let p = p as usize;
            if !self.eligible(p) || !self.far_from_movers(p) {
                continue;
            }
            self.st.reachable(p, s);
            for m in &s.moves {
                let dest = m.dest as usize;
                let d = self.difference(self.target[p], &self.st.profile_after(p, dest));
                if d < least {
                    (least, ties, best) = (d, 1, Some((p, dest)));
                } else if d == least {
                    ties += 1;
                    if self.rng.below(ties) == 0 {
                        best = Some((p, dest));
                    }
                }
            }
        }
        best
    }

    /// Steps (i) to (iii) of section 4 for the unit at `p`: its reachable positions, their
    /// differences, and its choice, `None` for staying where it is. The MRF rule weighs
    /// staying (D_0, "no motion" as i = 0) against every position; the random rule of section
    /// 5 selects a reachable position, so a unit that can move does. (Steepest descent is
    /// [`Cubes::steepest`].)
    fn decide(&mut self, p: usize, temp: f64, s: &mut Scratch) -> Option<usize> {
        self.st.reachable(p, s);
        if s.moves.is_empty() {
            return None;
        }
        let target = self.target[p];
        self.options.clear();
        if self.selection == Selection::Mrf {
            self.options.push((p as u32, self.diff[p]));
        }
        for m in &s.moves {
            let d = self.difference(target, &self.st.profile_after(p, m.dest as usize));
            self.options.push((m.dest, d));
        }
        let n = self.options.len();
        let least = self
            .options
            .iter()
            .map(|o| o.1)
            .fold(f64::INFINITY, f64::min);
        self.weights.clear();
        let pick = if self.selection == Selection::Mrf {
            for o in &self.options {
                self.weights.push(math::exp(-(o.1 - least) / temp));
            }
            self.rng.weighted(&self.weights).unwrap_or(0)
        } else {
            self.rng.index(n)
        };
        let dest = self.options[pick].0 as usize;
        (dest != p).then_some(dest)
    }

    /// The difference and reachable positions (with the difference at each) of the unit at `p`.
    fn reach_report(&self, p: usize) -> Vec<(u32, f64)> {
        let mut s = Scratch::default();
        self.st.reachable(p, &mut s);
        s.moves
            .iter()
            .map(|m| {
                (
                    m.dest,
                    self.difference(self.target[p], &self.st.profile_after(p, m.dest as usize)),
                )
            })
            .collect()
    }

    fn in_space(&self, i: usize) -> Result<()> {
        if i >= self.st.len() {
            return Err(Error::field(
                "cells",
                format!("cell {i} is outside the lattice"),
            ));
        }
        Ok(())
    }

    fn remove_unit(&mut self, i: usize) -> Result<()> {
        if !self.st.occupied(i) {
            return Err(Error::field("cells", format!("cell {i} holds no unit")));
        }
        if self.units.len() <= 2 {
            return Err(Error::field("cells", "the last two units stay"));
        }
        let mut s = std::mem::take(&mut self.scratch);
        let ok = self.st.stays_connected(i, None, &mut s);
        self.scratch = s;
        if !ok {
            return Err(Error::field(
                "cells",
                format!("removing the unit in cell {i} would split the structure"),
            ));
        }
        self.vacate(i);
        self.st.remove(i);
        self.after_change(&[i]);
        Ok(())
    }

    fn add_unit(&mut self, i: usize) -> Result<()> {
        if self.st.wall[i] {
            return Err(Error::field(
                "cells",
                format!("cell {i} is outside the space units may use"),
            ));
        }
        if self.st.occupied(i) {
            return Err(Error::field(
                "cells",
                format!("cell {i} already holds a unit"),
            ));
        }
        if self.st.mask(i) == 0 {
            return Err(Error::field(
                "cells",
                format!("cell {i} touches no unit; a new unit must join the structure"),
            ));
        }
        if self.units.len() >= MAX_UNITS {
            return Err(Error::field("cells", format!("at most {MAX_UNITS} units")));
        }
        self.target[i] = self.main_target() as u8;
        self.upos[i] = self.units.len() as u32;
        self.units.push(i as u32);
        self.st.add(i);
        self.after_change(&[i]);
        Ok(())
    }
}

/// A disturbance or click: `{"kind": "remove" | "add" | "hold", "cells": [i]}` removes a unit
/// (if the rest stays connected), adds one next to the structure, or toggles whether a unit is
/// held in place; `{"kind": "switch"}` moves to the next target now.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ActionSpec {
    kind: String,
    #[serde(default)]
    cells: Vec<u32>,
}

fn parse_action(action: &Action) -> Result<ActionSpec> {
    let a: ActionSpec = crate::error::from_value(Value::Object(action.clone()))?;
    match a.kind.as_str() {
        "remove" | "add" | "hold" => {
            if a.cells.len() != 1 {
                return Err(Error::field("cells", "give exactly one cell, like [42]"));
            }
        }
        "switch" => {}
        other => {
            return Err(Error::field(
                "kind",
                format!("unknown action '{other}'; known: remove, add, hold, switch"),
            ))
        }
    }
    Ok(a)
}

impl Model for Cubes {
    fn layout(&self) -> Layout {
        let tool = |name: &str, label: &str| ToolInfo {
            name: name.into(),
            label: label.into(),
            action: json!({ "kind": name })
                .as_object()
                .cloned()
                .unwrap_or_default(),
        };
        let mut tools = vec![
            tool("remove", "Remove unit"),
            tool("add", "Add unit"),
            tool("hold", "Hold / release unit"),
        ];
        if self.targets.len() > 1 {
            tools.push(tool("switch", "Switch target"));
        }
        let mut fields = vec![
            FieldInfo {
                name: "difference".into(),
                label: "difference D from the target (eq. 4)".into(),
                arrows: false,
            },
            FieldInfo {
                name: "movable".into(),
                label: "may move (1) or not (0)".into(),
                arrows: false,
            },
            FieldInfo {
                name: "reachable".into(),
                label: "number of reachable positions".into(),
                arrows: false,
            },
        ];
        if self.light.is_some() {
            fields.push(FieldInfo {
                name: "lit".into(),
                label: "sees the light (1) or not (0)".into(),
                arrows: false,
            });
        }
        Layout {
            lattice: LatticeKind::Cubic,
            dims: self.st.dims,
            cells: (1..CODES)
                .map(|c| LegendEntry::new(c as u8, NAMES[c], COLOURS[c]))
                .collect(),
            agents: Vec::new(),
            events: vec![
                LegendEntry::new(ARRIVED, "unit arrived", "#2b95d6"),
                LegendEntry::new(LEFT, "unit left", "#db3737"),
            ],
            fields,
            tools,
            cell_labels: true,
            goal: self.targets.len() == 1,
            chart: if self.light.is_some() {
                "displacement"
            } else {
                "mean_difference"
            }
            .into(),
        }
    }

    fn scene(&self) -> Scene {
        Scene {
            ghost: self.targets[self.main_target()].ghost.clone(),
            light: self.light.map(|d| DIRS[d].map(|v| v as f32)),
            ground: (self.ground != Ground::Open).then_some(self.floor_z as u32),
        }
    }

    /// Every pair of face-adjacent units is bonded (a unit connects to all its neighbours).
    fn bonds(&self) -> Cow<'_, [u8]> {
        let mut masks = vec![0u8; self.st.len()];
        for &c in &self.units {
            let c = c as usize;
            for d in 0..6 {
                if self.st.types[self.st.nb(c, d)] != 0 {
                    masks[c] |= 1 << d;
                }
            }
        }
        Cow::Owned(masks)
    }

    fn step(&mut self) {
        self.events.clear();
        let temp = self.c / math::ln_1p((self.steps + 1) as f64);
        let mut s = std::mem::take(&mut self.scratch);
        self.move_units(temp, &mut s);
        self.scratch = s;
        self.steps += 1;
        if self.targets.len() > 1 {
            self.switch_targets();
        }
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        self.targets.len() == 1 && self.zero == self.units.len()
    }

    fn metrics(&self) -> Metrics {
        let n = self.units.len();
        let mut m = Map::new();
        m.insert("steps".into(), self.steps.into());
        m.insert("moves".into(), self.moves.into());
        m.insert("units".into(), n.into());
        m.insert(
            "mean_difference".into(),
            json!(self.total_difference() / n as f64),
        );
        m.insert("matched".into(), json!(self.zero as f64 / n as f64));
        m.insert("completed".into(), u64::from(self.zero == n).into());
        m.insert("movable".into(), self.movable.len().into());
        m.insert("connectivity_checks".into(), self.scratch.checks.into());
        m.insert("connectivity_searches".into(), self.scratch.searches.into());
        m.insert(
            "connectivity_search_cells".into(),
            self.scratch.search_cells.into(),
        );
        if self.targets.len() > 1 {
            m.insert("target".into(), self.main_target().into());
            m.insert("switches".into(), self.switches.into());
        }
        if self.light.is_some() {
            m.insert(
                "displacement".into(),
                json!(self.light_position() - self.start_light),
            );
        }
        m
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
        for &u in &self.units {
            h.u32(self.stable[u as usize]);
        }
        h.u64(self.switches);
        h.u64(self.moves);
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        Cow::Borrowed(&self.st.types)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let per_unit = |f: &dyn Fn(usize) -> f32| -> Cow<'_, [f32]> {
            let mut out = vec![f32::NAN; self.st.len()];
            for &c in &self.units {
                out[c as usize] = f(c as usize);
            }
            Cow::Owned(out)
        };
        match name {
            "difference" => Some(per_unit(&|c| self.diff[c] as f32)),
            "movable" => Some(per_unit(&|c| f32::from(u8::from(self.eligible(c))))),
            "reachable" => {
                let mut s = Scratch::default();
                let mut out = vec![f32::NAN; self.st.len()];
                for &c in &self.units {
                    let c = c as usize;
                    out[c] = if self.eligible(c) {
                        self.st.reachable(c, &mut s);
                        s.moves.len() as f32
                    } else {
                        0.0
                    };
                }
                Some(Cow::Owned(out))
            }
            "lit" if self.light.is_some() => Some(per_unit(&|c| f32::from(u8::from(self.lit(c))))),
            _ => None,
        }
    }

    fn agents(&self) -> Vec<Agent> {
        Vec::new()
    }

    fn events(&self) -> Vec<Event> {
        self.events.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        let a = parse_action(action)?;
        for &c in &a.cells {
            self.in_space(c as usize)?;
        }
        if a.kind == "switch" && self.targets.len() < 2 {
            return Err(Error::field("kind", "switch needs two or more targets"));
        }
        Ok(())
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        self.check_action(action)?;
        let a = parse_action(action)?;
        match a.kind.as_str() {
            "switch" => {
                let next = (self.main_target() + 1) % self.targets.len();
                for k in 0..self.units.len() {
                    self.switch_unit(self.units[k] as usize, next);
                }
                Ok(())
            }
            kind => {
                let c = a.cells[0] as usize;
                match kind {
                    "remove" => self.remove_unit(c),
                    "add" => self.add_unit(c),
                    _ => {
                        if !self.st.occupied(c) {
                            return Err(Error::field("cells", format!("cell {c} holds no unit")));
                        }
                        self.flags[c] ^= HELD_USER;
                        self.refresh(c);
                        Ok(())
                    }
                }
            }
        }
    }

    fn inspect(&self, i: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if i >= self.st.len() {
            return m;
        }
        let c = self.st.coord(i);
        m.insert("x".into(), c[0].into());
        m.insert("y".into(), c[1].into());
        m.insert("z".into(), c[2].into());
        let target = &self.targets[if self.st.occupied(i) {
            self.target[i] as usize
        } else {
            self.main_target()
        }];
        if !target.name.is_empty() {
            m.insert("target".into(), target.name.clone().into());
        }
        if !self.st.occupied(i) {
            m.insert("unit".into(), false.into());
            m.insert("ghost".into(), target.ghost.contains(&(i as u32)).into());
            return m;
        }
        m.insert("unit".into(), true.into());
        let prof = self.st.profile(i);
        let list = TypeList::new(
            prof[0],
            prof[1..].iter().copied().filter(|&t| t != 0).collect(),
        );
        m.insert("type".into(), NAMES[prof[0] as usize].into());
        m.insert("type_list".into(), list.to_string().into());
        m.insert("difference".into(), json!(self.diff[i]));
        m.insert("movable".into(), self.eligible(i).into());
        m.insert("fixed".into(), self.fixed(i).into());
        m.insert(
            "held".into(),
            (self.flags[i] & (HELD_LIT | HELD_USER) != 0).into(),
        );
        if self.light.is_some() {
            m.insert("lit".into(), self.lit(i).into());
        }
        let reach = if self.eligible(i) {
            self.reach_report(i)
        } else {
            Vec::new()
        };
        m.insert(
            "reachable".into(),
            reach.iter().map(|r| Value::from(r.0)).collect(),
        );
        m.insert(
            "reachable_differences".into(),
            reach.iter().map(|r| json!(r.1)).collect(),
        );
        m
    }
}

fn described(lists: Vec<TypeList>, units: usize) -> Value {
    json!({
        "type_lists": typelist::to_text(&lists),
        "count": lists.len(),
        "units": units,
    })
}

/// The `derive` query: the unique type-list description of a shape, given as cubic-lattice text
/// (`{"shape": "##\n##\n---\n##\n##\n"}`) or as unit coordinates (`{"units": [[0, 0, 0], ...]}`).
/// Answers `{"type_lists": text, "count": n, "units": n}`.
pub fn query_derive(args: &Value) -> Result<Value> {
    if let Some(text) = args.get("shape") {
        let text = text
            .as_str()
            .ok_or_else(|| Error::field("shape", "expected text"))?;
        let g = shape::parse_cubic(text).map_err(|e| e.within("shape"))?;
        let units = typelist::grid_units(&g);
        let lists = typelist::describe(&units).map_err(|e| e.within("shape"))?;
        Ok(described(lists, units.len()))
    } else if let Some(list) = args.get("units") {
        let units: Vec<(i32, i32, i32)> = crate::error::from_value::<Vec<[i32; 3]>>(list.clone())
            .map_err(|e| e.within("units"))?
            .into_iter()
            .map(|[x, y, z]| (x, y, z))
            .collect();
        if units.len() > MAX_UNITS {
            return Err(Error::field("units", format!("at most {MAX_UNITS} units")));
        }
        let lists = typelist::describe(&units).map_err(|e| e.within("units"))?;
        Ok(described(lists, units.len()))
    } else {
        Err(Error::field("", "derive needs \"shape\" or \"units\""))
    }
}

/// The `check` query: parses `{"type_lists": text}` and answers it in normal form with its count,
/// or an error naming the line and the problem.
pub fn query_check(args: &Value) -> Result<Value> {
    let text = args
        .get("type_lists")
        .and_then(Value::as_str)
        .ok_or_else(|| Error::field("type_lists", "expected text"))?;
    let lists = typelist::parse(text).map_err(|e| e.within("type_lists"))?;
    Ok(json!({ "type_lists": typelist::to_text(&lists), "count": lists.len() }))
}

#[cfg(test)]
mod tests;
