//! The scenario body of the AMAS model: parsing, limits and the shapes laid on the lattice.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};
use crate::lattice::{Lattice, Square};
use crate::shape::{self, Grid2};

/// The largest lattice side accepted, in cells, supply rows included.
pub const MAX_SIDE: u32 = 2048;
/// The largest number of supply rows.
pub const MAX_SUPPLY_ROWS: u32 = 64;
/// The largest `field_updates_per_step`.
pub const MAX_UPDATES: u32 = 1000;
/// The largest duration of one action, in steps.
pub const MAX_DURATION: u32 = 1000;
/// The largest number of stage targets before the final one.
pub const MAX_STAGES: usize = 64;
/// The largest number of cells of all stage targets together (lattice cells × targets).
pub const MAX_STAGE_CELLS: u64 = 1 << 26;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum FieldKind {
    /// Equation 1: one diffusing potential, growth front high, supply low.
    #[default]
    Continuous,
    /// Equation 2: two distance fields, one per destination.
    Discrete,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Collision {
    /// Random tokens: the largest moves, the others wait (section 4.6).
    #[default]
    Token,
    /// Token, and a loaded robot meeting an unloaded one hands its module over (4.6.1).
    Relay,
    /// Plans are written on the target module and read before moving (4.6.2).
    Blackboard,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Communication {
    /// Robots settle a whole chain of moves at once: a robot may follow one that leaves its
    /// module even when that robot itself follows another.
    #[default]
    Chain,
    /// Appendix A.1 (2): a robot hears the robots within two modules. It follows a robot that
    /// leaves its module only when that robot moves onto a free module.
    Radius2,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    /// The final target shape: shape text (rows, top first) or `{"rect": [w, h]}`.
    pub target: Value,
    /// Intermediate targets built, in order, before `target` (section 6.4).
    #[serde(default)]
    pub stages: Vec<Value>,
    /// Modules already built when the run starts.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial: Option<Value>,
    pub robots: u32,
    #[serde(default)]
    pub field: FieldKind,
    #[serde(default)]
    pub collision: Collision,
    #[serde(default = "default_updates")]
    pub field_updates_per_step: u32,
    /// D of equation 1.
    #[serde(default = "default_diffusion")]
    pub diffusion: f64,
    /// Footnote 3: below this spread of the neighbours' values there is no effective gradient.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient_threshold: Option<f64>,
    #[serde(default = "one")]
    pub supply_rows: u32,
    #[serde(default = "one")]
    pub move_duration: u32,
    #[serde(default = "one")]
    pub pick_duration: u32,
    #[serde(default = "one")]
    pub place_duration: u32,
    #[serde(default = "one")]
    pub relay_duration: u32,
    #[serde(default = "one")]
    pub collision_penalty: u32,
    /// Appendix B: steps a turn (left, right or 180°) takes before a move in a new direction.
    #[serde(default)]
    pub turn_duration: u32,
    #[serde(default)]
    pub communication: Communication,
}

fn one() -> u32 {
    1
}

pub const DEFAULT_UPDATES: u32 = 10;

fn default_updates() -> u32 {
    DEFAULT_UPDATES
}

pub const DEFAULT_DIFFUSION: f64 = 0.2;

fn default_diffusion() -> f64 {
    DEFAULT_DIFFUSION
}

/// Default threshold of footnote 3 for each field: distances are whole numbers, so 1 means
/// "all equal"; the potential runs from 0 to 1.
pub fn default_threshold(field: FieldKind) -> f64 {
    match field {
        FieldKind::Discrete => 1.0,
        FieldKind::Continuous => 1e-4,
    }
}

/// The checked parameters the model runs with.
#[derive(Clone, Copy, Debug)]
pub struct Params {
    pub field: FieldKind,
    pub collision: Collision,
    pub updates: u32,
    pub diffusion: f32,
    pub threshold: f32,
    pub move_d: u32,
    pub pick_d: u32,
    pub place_d: u32,
    pub relay_d: u32,
    pub penalty: u32,
    pub turn_d: u32,
    pub communication: Communication,
}

/// Everything the model needs to start: the lattice size, the stage targets and the initial
/// structure as rows of booleans over the lattice (supply rows excluded).
pub struct Plan {
    pub w: u32,
    /// Rows above the supply.
    pub shape_h: u32,
    pub supply_rows: u32,
    /// Every stage target, the final one last, each `shape_h × w`.
    pub stages: Vec<Vec<bool>>,
    pub initial: Vec<bool>,
    pub robots: u32,
    pub params: Params,
}

fn shape_value(v: &Value, path: &str) -> Result<Grid2> {
    match v {
        Value::String(text) => {
            let g = shape::parse_square(text).map_err(|e| e.within(path))?;
            if g.count() == 0 {
                return Err(Error::field(path, "has no '#' cells"));
            }
            Ok(g)
        }
        Value::Object(map) => {
            let rect = match (map.get("rect"), map.len()) {
                (Some(Value::Array(r)), 1) if r.len() == 2 => r,
                _ => {
                    return Err(Error::field(
                        path,
                        "expected shape text ('#' and '.' rows) or {\"rect\": [width, height]}",
                    ))
                }
            };
            let side = |v: &Value, what: &str| -> Result<u32> {
                match v.as_u64() {
                    Some(n) if (1..=u64::from(MAX_SIDE)).contains(&n) => Ok(n as u32),
                    _ => Err(Error::field(
                        format!("{path}.rect"),
                        format!("{what} must be a whole number from 1 to {MAX_SIDE}"),
                    )),
                }
            };
            let (w, h) = (side(&rect[0], "width")?, side(&rect[1], "height")?);
            Ok(Grid2 {
                w,
                h,
                cells: vec![true; (w * h) as usize],
            })
        }
        _ => Err(Error::field(
            path,
            "expected shape text ('#' and '.' rows) or {\"rect\": [width, height]}",
        )),
    }
}

/// Lays `g` on a `w × h` grid, bottom-left aligned.
fn lay(g: &Grid2, w: u32, h: u32) -> Vec<bool> {
    let mut out = vec![false; (w * h) as usize];
    let dy = h - g.h;
    for y in 0..g.h {
        for x in 0..g.w {
            if g.get(x, y) {
                out[((y + dy) * w + x) as usize] = true;
            }
        }
    }
    out
}

/// Cells of `cells` (rows above the supply) that no path inside `cells` joins to the supply.
fn unreached(cells: &[bool], w: u32, h: u32) -> usize {
    let lattice = Square::new(w, h);
    let (w, h) = (w as usize, h as usize);
    let mut seen = vec![false; cells.len()];
    let mut stack: Vec<usize> = (0..w)
        .map(|x| (h - 1) * w + x)
        .filter(|&i| cells[i])
        .collect();
    for &i in &stack {
        seen[i] = true;
    }
    while let Some(i) = stack.pop() {
        for j in lattice.neighbours(i) {
            if cells[j] && !seen[j] {
                seen[j] = true;
                stack.push(j);
            }
        }
    }
    cells.iter().zip(&seen).filter(|(&c, &s)| c && !s).count()
}

fn duration(v: u32, name: &str) -> Result<u32> {
    if (1..=MAX_DURATION).contains(&v) {
        Ok(v)
    } else {
        Err(Error::field(
            name,
            format!("must be from 1 to {MAX_DURATION} steps"),
        ))
    }
}

pub fn read(spec: Spec) -> Result<Plan> {
    if spec.stages.len() > MAX_STAGES {
        return Err(Error::field(
            "stages",
            format!("at most {MAX_STAGES} stages"),
        ));
    }
    // Rectangles are cheap to write and costly to hold: bound them before building any.
    let declared: u64 = spec
        .stages
        .iter()
        .chain(std::iter::once(&spec.target))
        .map(|v| match v.get("rect").and_then(Value::as_array) {
            Some(r) => r
                .iter()
                .filter_map(Value::as_u64)
                .product::<u64>()
                .min(1 << 32),
            None => 0,
        })
        .sum();
    if declared > MAX_STAGE_CELLS {
        return Err(Error::field(
            "stages",
            format!("the targets hold more than {MAX_STAGE_CELLS} cells in all"),
        ));
    }
    let mut shapes = Vec::with_capacity(spec.stages.len() + 1);
    for (i, v) in spec.stages.iter().enumerate() {
        shapes.push((
            format!("stages[{i}]"),
            shape_value(v, &format!("stages[{i}]"))?,
        ));
    }
    shapes.push(("target".to_string(), shape_value(&spec.target, "target")?));
    let initial = match &spec.initial {
        Some(v) => Some(shape_value(v, "initial")?),
        None => None,
    };
    if !(1..=MAX_SUPPLY_ROWS).contains(&spec.supply_rows) {
        return Err(Error::field(
            "supply_rows",
            format!("must be from 1 to {MAX_SUPPLY_ROWS}"),
        ));
    }
    let w = shapes
        .iter()
        .map(|(_, g)| g.w)
        .chain(initial.iter().map(|g| g.w))
        .max()
        .unwrap_or(1);
    let shape_h = shapes
        .iter()
        .map(|(_, g)| g.h)
        .chain(initial.iter().map(|g| g.h))
        .max()
        .unwrap_or(1);
    if w > MAX_SIDE || shape_h + spec.supply_rows > MAX_SIDE {
        let (path, _) = shapes.last().expect("the target is always there");
        return Err(Error::field(
            path.as_str(),
            format!(
                "{w}×{} cells (with the supply rows) exceeds the limit of {MAX_SIDE}×{MAX_SIDE}",
                shape_h + spec.supply_rows
            ),
        ));
    }
    if shapes.len() as u64 * u64::from(w) * u64::from(shape_h) > MAX_STAGE_CELLS {
        return Err(Error::field(
            "stages",
            format!(
                "{} stage targets of {w}×{shape_h} cells are too many; at most {MAX_STAGE_CELLS} cells in all",
                shapes.len()
            ),
        ));
    }
    let mut stages = Vec::with_capacity(shapes.len());
    for (path, g) in &shapes {
        let laid = lay(g, w, shape_h);
        let n = unreached(&laid, w, shape_h);
        if n > 0 {
            return Err(Error::field(
                path.as_str(),
                format!("{n} target cells are not connected to the supply row below the shape"),
            ));
        }
        stages.push(laid);
    }
    let initial = match &initial {
        Some(g) => {
            let laid = lay(g, w, shape_h);
            let n = unreached(&laid, w, shape_h);
            if n > 0 {
                return Err(Error::field(
                    "initial",
                    format!("{n} modules are not connected to the supply row below the shape"),
                ));
            }
            laid
        }
        None => vec![false; (w * shape_h) as usize],
    };
    if spec.robots == 0 {
        return Err(Error::field("robots", "at least one robot is needed"));
    }
    let supply_cells = u64::from(w) * u64::from(spec.supply_rows);
    if u64::from(spec.robots) > supply_cells {
        return Err(Error::field(
            "robots",
            format!(
                "{} robots do not fit on the {supply_cells} modules of the supply area \
                 ({w} wide, {} rows; raise supply_rows)",
                spec.robots, spec.supply_rows
            ),
        ));
    }
    if !(1..=MAX_UPDATES).contains(&spec.field_updates_per_step) {
        return Err(Error::field(
            "field_updates_per_step",
            format!("must be from 1 to {MAX_UPDATES}"),
        ));
    }
    if !(spec.diffusion > 0.0 && spec.diffusion <= 0.25) {
        return Err(Error::field(
            "diffusion",
            "must be above 0 and at most 0.25 (larger values make equation 1 unstable)",
        ));
    }
    let threshold = spec
        .gradient_threshold
        .unwrap_or_else(|| default_threshold(spec.field));
    if !(threshold.is_finite() && threshold >= 0.0) {
        return Err(Error::field(
            "gradient_threshold",
            "must be a number of at least 0",
        ));
    }
    let params = Params {
        field: spec.field,
        collision: spec.collision,
        updates: spec.field_updates_per_step,
        diffusion: spec.diffusion as f32,
        threshold: threshold as f32,
        move_d: duration(spec.move_duration, "move_duration")?,
        pick_d: duration(spec.pick_duration, "pick_duration")?,
        place_d: duration(spec.place_duration, "place_duration")?,
        relay_d: duration(spec.relay_duration, "relay_duration")?,
        penalty: duration(spec.collision_penalty, "collision_penalty")?,
        turn_d: if spec.turn_duration <= MAX_DURATION {
            spec.turn_duration
        } else {
            return Err(Error::field(
                "turn_duration",
                format!("must be from 0 to {MAX_DURATION} steps"),
            ));
        },
        communication: spec.communication,
    };
    Ok(Plan {
        w,
        shape_h,
        supply_rows: spec.supply_rows,
        stages,
        initial,
        robots: spec.robots,
        params,
    })
}
