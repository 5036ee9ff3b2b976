//! The scenario body of the CHOBIE II model: its parameters, their limits, and the world text
//! (terrain and robots) read into a typed plan.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::limits::LIMITS;
use kumiki_model::bounds::{self, Bound, Bounded};
use kumiki_model::error::{Error, Result};
use kumiki_model::limits::Limits;

/// What the robots do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Task {
    /// Section 3.3: crawl to the right by successive transformations.
    #[default]
    Crawl,
    /// Section 3.4: build a bridge from the cliff, adapting to overloads.
    Bridge,
}

/// Who decides which line drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Leader {
    /// Section 3.1: a temporary leader elected by local signals after every transformation.
    #[default]
    Temporary,
    /// The baseline the paper argues against: one fixed robot gathers the whole map.
    Permanent,
}

/// How the crawl copes with initial forms the first algorithm cannot handle (section IV).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Only the three-rule election of section 3.3.
    #[default]
    First,
    /// Figure 16: try the algorithms one after another until one elects a leader.
    TrialAndError,
    /// Figure 17: check the structure's characteristics first, then apply one algorithm.
    Cautious,
}

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "ChobieSpec", transform = bounds::in_schema::<Spec>)]
pub struct Spec {
    /// The side view, top row first: `=` terrain (ground and cliff), `#` a robot, `.` empty.
    pub world: String,
    /// Empty columns added on the right, each a copy of the rightmost column's terrain.
    #[serde(default)]
    pub extend: u32,
    /// What the robots do: crawl (section 3.3) or build a bridge (3.4).
    #[serde(default)]
    pub task: Task,
    /// Who decides which line drives.
    #[serde(default)]
    pub leader: Leader,
    /// How the crawl copes with forms the first algorithm cannot handle (section IV).
    #[serde(default)]
    pub method: Method,
    /// Figure 18: check leader kinds in a fixed priority sequence, so one kind commands.
    #[serde(default)]
    pub priority: bool,
    /// Figure 12: switch to load-adaptation mode on overload (bridge task).
    #[serde(default = "yes")]
    pub adaptation: bool,
    /// Bridge task: extend the bridge in construction mode. Off, the robots only watch their
    /// loads and adapt (the demonstration of figure 14).
    #[serde(default = "yes")]
    pub construction: bool,
    /// Completed when the crawl has moved this many cells, or the bridge spans this many cells.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal: Option<u32>,
    /// The flat part of the base carries the robots' sliding guide and holds the robots resting
    /// on it. Off, the base only pushes, and the structure tips over the cliff edge when the
    /// weights and loads beyond it outweigh those on the base.
    #[serde(default = "yes")]
    pub anchored: bool,
    /// A downward load on the bridge's tip robot (the rightmost of the lowest row), newtons.
    #[serde(default)]
    pub tip_load: f64,
    /// Side of a robot, metres.
    #[serde(default = "defaults::cell_size")]
    pub cell_size: f64,
    /// Thickness of each of the two lateral ABS boards that carry the load, metres.
    #[serde(default = "defaults::board")]
    pub board: f64,
    /// Young's modulus of ABS, pascals.
    #[serde(default = "defaults::youngs_modulus")]
    pub youngs_modulus: f64,
    /// Mass of one robot, kilograms.
    #[serde(default = "defaults::robot_mass")]
    pub robot_mass: f64,
    #[serde(default = "defaults::gravity")]
    pub gravity: f64,
    /// Tensile strength of ABS, pascals.
    #[serde(default = "defaults::tensile_strength")]
    pub tensile_strength: f64,
    /// The overload threshold is tensile_strength / safety_factor.
    #[serde(default = "defaults::safety_factor")]
    pub safety_factor: f64,
    /// Time for a signal to cross one robot, microseconds (section 3.2: about 10).
    #[serde(default = "defaults::hop_us")]
    pub hop_us: f64,
}

impl Bounded for Spec {
    const BOUNDS: &'static [Bound<Spec>] = &[
        Bound::new("extend", |s: &Spec| Some(s.extend.into()))
            .up_to(|l| LIMITS.of(l).side.into())
            .unit("columns"),
        Bound::new("goal", |s: &Spec| s.goal.map(f64::from))
            .at_least(1.0)
            .up_to(|l| LIMITS.of(l).goal.into())
            .unit("cells"),
        Bound::new("tip_load", |s: &Spec| Some(s.tip_load))
            .at_least(0.0)
            .at_most(1e7),
        Bound::new("cell_size", |s: &Spec| Some(s.cell_size))
            .above(0.0)
            .at_most(1e3),
        Bound::new("board", |s: &Spec| Some(s.board))
            .above(0.0)
            .at_most(1e3),
        Bound::new("youngs_modulus", |s: &Spec| Some(s.youngs_modulus))
            .above(0.0)
            .at_most(1e15),
        Bound::new("robot_mass", |s: &Spec| Some(s.robot_mass))
            .at_least(0.0)
            .at_most(1e6),
        Bound::new("gravity", |s: &Spec| Some(s.gravity))
            .at_least(0.0)
            .at_most(1e3),
        Bound::new("tensile_strength", |s: &Spec| Some(s.tensile_strength))
            .above(0.0)
            .at_most(1e15),
        Bound::new("safety_factor", |s: &Spec| Some(s.safety_factor))
            .above(0.0)
            .at_most(1e6),
        Bound::new("hop_us", |s: &Spec| Some(s.hop_us))
            .above(0.0)
            .at_most(1e9),
    ];
}

fn yes() -> bool {
    true
}

/// Parameter defaults; `crate/models/chobie/README.md` says where each comes from.
pub mod defaults {
    pub fn cell_size() -> f64 {
        0.1
    }
    pub fn board() -> f64 {
        0.003
    }
    pub fn youngs_modulus() -> f64 {
        2.2e9
    }
    pub fn robot_mass() -> f64 {
        0.6
    }
    pub fn gravity() -> f64 {
        9.81
    }
    pub fn tensile_strength() -> f64 {
        40e6
    }
    pub fn safety_factor() -> f64 {
        10.0
    }
    pub fn hop_us() -> f64 {
        10.0
    }
}

/// The checked material and geometry the stress model uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mechanics {
    /// Element length (the cell size), metres.
    pub length: f64,
    pub e: f64,
    /// Section area and second moment of area of a contact, m² and m⁴.
    pub area: f64,
    pub inertia: f64,
    /// Distance from the neutral axis to the outer fibre, metres.
    pub fibre: f64,
    /// Weight of one robot, newtons.
    pub weight: f64,
    /// Overload threshold, pascals.
    pub threshold: f64,
    /// Breaking stress (the tensile strength), pascals.
    pub strength: f64,
    /// Timoshenko's shear parameter of one element, φ = 12·E·I / (κ·G·A·L²): the bending
    /// stiffness over the shear stiffness. About 3.2 for a robot as deep as it is long.
    pub phi: f64,
}

/// Poisson's ratio of ABS (typical, 0.35), for the shear modulus G = E / (2(1 + ν)).
pub const POISSON: f64 = 0.35;
/// Timoshenko's shear coefficient of a rectangular section.
pub const SHEAR_COEFFICIENT: f64 = 5.0 / 6.0;

impl Mechanics {
    /// Two lateral boards of thickness `board` and height `cell_size` carry each contact (the
    /// description's ranges checked before).
    pub fn from_spec(s: &Spec) -> Result<Mechanics> {
        let (a, t) = (s.cell_size, s.board);
        if t * 2.0 > a {
            return Err(Error::field(
                "board",
                "two boards must fit in the robot: board ≤ cell_size / 2",
            ));
        }
        let (e, mass, g) = (s.youngs_modulus, s.robot_mass, s.gravity);
        let (strength, safety) = (s.tensile_strength, s.safety_factor);
        let (area, inertia) = (2.0 * t * a, 2.0 * t * a * a * a / 12.0);
        let shear = e / (2.0 * (1.0 + POISSON));
        Ok(Mechanics {
            length: a,
            e,
            area,
            inertia,
            phi: 12.0 * e * inertia / (SHEAR_COEFFICIENT * shear * area * a * a),
            fibre: a / 2.0,
            weight: mass * g,
            threshold: strength / safety,
            strength,
        })
    }
}

/// What a cell of the world text holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tile {
    Empty,
    Ground,
    Robot,
}

/// The world read from its text: `tiles[y * w + x]`, row 0 at the top.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct World {
    pub w: u32,
    pub h: u32,
    pub tiles: Vec<Tile>,
}

impl World {
    pub fn get(&self, x: i32, y: i32) -> Tile {
        if x < 0 || y < 0 || x >= self.w as i32 || y >= self.h as i32 {
            Tile::Empty
        } else {
            self.tiles[y as usize * self.w as usize + x as usize]
        }
    }
}

/// Reads the world text within `limits`; errors name the line and column (counted in the text as
/// written).
pub fn parse_world(text: &str, extend: u32, limits: &Limits) -> Result<World> {
    let max_side = u64::from(LIMITS.of(limits).side);
    let lines: Vec<&str> = text.lines().map(str::trim_end).collect();
    let first = lines.iter().position(|l| !l.is_empty());
    let last = lines.iter().rposition(|l| !l.is_empty());
    let (first, last) = match (first, last) {
        (Some(a), Some(b)) => (a, b),
        _ => {
            return Err(Error::field(
                "world",
                "the world is empty; draw it with '=' (terrain), '#' (robot) and '.' (empty)",
            ))
        }
    };
    let mut rows = Vec::new();
    for (n, line) in lines.iter().enumerate().take(last + 1).skip(first) {
        let mut row = Vec::new();
        for (c, ch) in line.chars().enumerate() {
            row.push(match ch {
                '.' => Tile::Empty,
                '=' => Tile::Ground,
                '#' => Tile::Robot,
                other => {
                    return Err(Error::field(
                        "world",
                        format!(
                            "line {}, column {}: '{other}' is not a tile; use '=' for terrain, '#' for a robot and '.' for empty",
                            n + 1,
                            c + 1
                        ),
                    ))
                }
            });
        }
        rows.push(row);
    }
    let text_w = rows.iter().map(Vec::len).max().unwrap_or(0);
    let w = text_w as u64 + extend as u64;
    let h = rows.len() as u64;
    if w > max_side || h > max_side {
        return Err(Error::field(
            "world",
            format!("the world is {w}×{h} cells (extend included); at most {max_side} a side"),
        ));
    }
    let mut tiles = Vec::with_capacity((w * h) as usize);
    for row in &rows {
        let edge = if row.len() == text_w {
            row.last().copied().filter(|t| *t == Tile::Ground)
        } else {
            None
        };
        tiles.extend(row.iter().copied());
        tiles.extend(std::iter::repeat_n(Tile::Empty, text_w - row.len()));
        tiles.extend(std::iter::repeat_n(
            edge.unwrap_or(Tile::Empty),
            extend as usize,
        ));
    }
    let world = World {
        w: w as u32,
        h: h as u32,
        tiles,
    };
    check_world(&world, first, LIMITS.of(limits).robots)?;
    Ok(world)
}

/// The robots form one piece and at least one rests on the terrain.
fn check_world(world: &World, first_line: usize, max_robots: usize) -> Result<()> {
    let robots: Vec<(i32, i32)> = (0..world.h as i32)
        .flat_map(|y| (0..world.w as i32).map(move |x| (x, y)))
        .filter(|&(x, y)| world.get(x, y) == Tile::Robot)
        .collect();
    if robots.is_empty() {
        return Err(Error::field(
            "world",
            "there is no robot; draw robots with '#'",
        ));
    }
    if robots.len() > max_robots {
        return Err(Error::field(
            "world",
            format!("{} robots are too many; at most {max_robots}", robots.len()),
        ));
    }
    let mut seen = vec![false; world.tiles.len()];
    let idx = |x: i32, y: i32| y as usize * world.w as usize + x as usize;
    let mut stack = vec![robots[0]];
    seen[idx(robots[0].0, robots[0].1)] = true;
    let mut reached = 0;
    while let Some((x, y)) = stack.pop() {
        reached += 1;
        for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            let (nx, ny) = (x + dx, y + dy);
            if world.get(nx, ny) == Tile::Robot && !seen[idx(nx, ny)] {
                seen[idx(nx, ny)] = true;
                stack.push((nx, ny));
            }
        }
    }
    if reached != robots.len() {
        let &(x, y) = robots
            .iter()
            .find(|&&(x, y)| !seen[idx(x, y)])
            .unwrap_or(&robots[0]);
        return Err(Error::field(
            "world",
            format!(
                "line {}, column {}: this robot is not connected to the first one; the robots must form one piece",
                first_line + y as usize + 1,
                x + 1
            ),
        ));
    }
    if !robots
        .iter()
        .any(|&(x, y)| world.get(x, y + 1) == Tile::Ground)
    {
        return Err(Error::field(
            "world",
            "no robot rests on the terrain: put at least one '#' directly above a '='",
        ));
    }
    Ok(())
}
