//! The scenario body of the AMAS model: parsing, limits and the shapes laid on the lattice.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::{actions, Amas};
use crate::limits::{AmasLimits, LIMITS};
use kumiki_model::bounds::{self, Bound, Bounded};
use kumiki_model::error::{Error, Result};
use kumiki_model::lattice::{Lattice, Square};
use kumiki_model::limits::Limits;
use kumiki_model::model::{self, Action, Model};
use kumiki_model::shape::{self, Grid2};

/// The largest `field_updates_per_step`.
pub const MAX_UPDATES: u32 = 1000;
/// The largest duration of one action, in steps.
pub const MAX_DURATION: u32 = 1000;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum FieldKind {
    /// Equation 1: one diffusing potential, growth front high, supply low.
    #[default]
    Continuous,
    /// Equation 2: two distance fields, one per destination.
    Discrete,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
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

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
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

/// Footnote 3: who chooses among neighbouring modules that are equally good for the robot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Direction {
    /// The module under the robot displays one direction, the best neighbour, the first in
    /// footnote 3's order N, S, E, W among equally good ones; every robot reading it gets that
    /// one. A robot chooses at random only where its module shows "no effective gradient".
    #[default]
    Module,
    /// Each robot draws at random among equally good neighbours at every plan (Kumiki's reading
    /// before model version 3).
    Robot,
}

/// Sections 4.6 and 5.1: which robots that lost a collision step aside at their next plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum GiveWay {
    /// Only the robots a lock holds: of robots meeting head-on (or round a ring, each wanting
    /// the next one's module) those with the smaller token, and the robots queued behind one of
    /// them, which must make room for it. Every other loser waits out the penalty and plans
    /// again.
    #[default]
    Locked,
    /// Every robot that paid a penalty steps to the best free module at its next plan
    /// (Kumiki's reading before model version 3).
    EveryLoser,
}

/// Sections 4.6.1 and 5.1: which robots a loaded robot and an unloaded one may relay with when
/// one wants the other's module.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, Default, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RelayWith {
    /// A robot that waits: one that could not move, or one still waiting out a collision
    /// penalty, which is still in its collision until it is resolved.
    #[default]
    Waiting,
    /// Only a robot that planned this step: one waiting out a penalty of several steps takes no
    /// part (Kumiki's reading before model version 4).
    Idle,
}

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "AmasSpec", transform = bounds::in_schema::<Spec>)]
pub struct Spec {
    /// The final target shape: shape text (rows, top first) or `{"rect": [w, h]}`.
    pub target: Value,
    /// Intermediate targets built, in order, before `target` (section 6.4).
    #[serde(default)]
    pub stages: Vec<Value>,
    /// Modules already built when the run starts.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial: Option<Value>,
    /// Assembler robots, placed at random on distinct supply modules; at most one per supply
    /// module.
    pub robots: u32,
    /// The gradient field the modules compute (equation 1 or 2).
    #[serde(default)]
    pub field: FieldKind,
    /// How robots settle conflicts over a module (section 4.6).
    #[serde(default)]
    pub collision: Collision,
    /// Field updates (sweeps) per step, U.
    #[serde(default = "default_updates")]
    pub field_updates_per_step: u32,
    /// D of equation 1; above 0.25 the update is unstable.
    #[serde(default = "default_diffusion")]
    pub diffusion: f64,
    /// Footnote 3: below this spread of the neighbours' values there is no effective gradient.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient_threshold: Option<f64>,
    /// Rows of the module supply under the shape.
    #[serde(default = "one")]
    pub supply_rows: u32,
    /// Steps a move to a neighbouring module takes.
    #[serde(default = "one")]
    pub move_duration: u32,
    /// Steps picking a module from the supply takes.
    #[serde(default = "one")]
    pub pick_duration: u32,
    /// Steps placing a module takes.
    #[serde(default = "one")]
    pub place_duration: u32,
    /// Steps handing a module over to another robot takes (collision `relay`).
    #[serde(default = "one")]
    pub relay_duration: u32,
    /// Steps a robot that lost a collision waits.
    #[serde(default = "one")]
    pub collision_penalty: u32,
    /// Appendix B: steps a turn (left, right or 180°) takes before a move in a new direction.
    #[serde(default)]
    pub turn_duration: u32,
    /// How far robots hear each other when they settle moves (appendix A.1).
    #[serde(default)]
    pub communication: Communication,
    /// Footnote 3: the module displays one direction, or each robot draws among equally good
    /// neighbours.
    #[serde(default)]
    pub direction: Direction,
    /// Which robots that lost a collision step aside at their next plan (4.6).
    #[serde(default)]
    pub give_way: GiveWay,
    /// Whether a robot waiting out a collision penalty may relay (4.6.1).
    #[serde(default)]
    pub relay_with: RelayWith,
}

impl Bounded for Spec {
    const BOUNDS: &'static [Bound<Spec>] = &[
        Bound::length("stages", |s: &Spec| Some(s.stages.len() as f64))
            .up_to(|l| LIMITS.of(l).stages as f64),
        Bound::new("robots", |s: &Spec| Some(s.robots.into()))
            .at_least(1.0)
            .says("at least one robot is needed"),
        Bound::new("field_updates_per_step", |s: &Spec| {
            Some(s.field_updates_per_step.into())
        })
        .at_least(1.0)
        .at_most(MAX_UPDATES as f64),
        Bound::new("diffusion", |s: &Spec| Some(s.diffusion))
            .above(0.0)
            .at_most(0.25)
            .why("larger values make equation 1 unstable"),
        Bound::new("gradient_threshold", |s: &Spec| s.gradient_threshold).at_least(0.0),
        Bound::new("supply_rows", |s: &Spec| Some(s.supply_rows.into()))
            .at_least(1.0)
            .up_to(|l| LIMITS.of(l).supply_rows.into()),
        steps(
            Bound::new("move_duration", |s: &Spec| Some(s.move_duration.into())),
            1.0,
        ),
        steps(
            Bound::new("pick_duration", |s: &Spec| Some(s.pick_duration.into())),
            1.0,
        ),
        steps(
            Bound::new("place_duration", |s: &Spec| Some(s.place_duration.into())),
            1.0,
        ),
        steps(
            Bound::new("relay_duration", |s: &Spec| Some(s.relay_duration.into())),
            1.0,
        ),
        steps(
            Bound::new("collision_penalty", |s: &Spec| {
                Some(s.collision_penalty.into())
            }),
            1.0,
        ),
        steps(
            Bound::new("turn_duration", |s: &Spec| Some(s.turn_duration.into())),
            0.0,
        ),
    ];
}

/// A duration from `least` to [`MAX_DURATION`] steps.
const fn steps(bound: Bound<Spec>, least: f64) -> Bound<Spec> {
    bound
        .at_least(least)
        .at_most(MAX_DURATION as f64)
        .unit("steps")
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
    pub direction: Direction,
    pub give_way: GiveWay,
    pub relay_with: RelayWith,
}

/// Everything the model needs to start: the lattice size, the stage targets and the initial
/// structure as rows of booleans over the lattice (supply rows excluded).
#[derive(Clone)]
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

fn shape_value(v: &Value, path: &str, limits: &Limits) -> Result<Grid2> {
    let max_side = LIMITS.of(limits).side;
    match v {
        Value::String(text) => {
            let g = shape::parse_square_within(text, limits).map_err(|e| e.within(path))?;
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
                    Some(n) if (1..=u64::from(max_side)).contains(&n) => Ok(n as u32),
                    _ => Err(Error::field(
                        format!("{path}.rect"),
                        format!("{what} {v} is not a whole number from 1 to {max_side}"),
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

impl Plan {
    /// Cells of the lattice: the rows above the supply and the supply rows.
    pub fn cells(&self) -> usize {
        self.w as usize * (self.shape_h + self.supply_rows) as usize
    }
}

impl model::Spec for Spec {
    type Checked = Plan;

    fn validate(&self, limits: &Limits) -> Result<Plan> {
        read(self, limits)
    }

    fn check_action(plan: &Plan, action: &Action) -> Result<()> {
        actions::parse(action, plan.cells()).map(|_| ())
    }

    fn build(plan: Plan, seed: u64) -> Box<dyn Model> {
        Box::new(Amas::from_checked(plan, seed))
    }
}

/// Checks every key and lays the shapes on the lattice, allocating no more than the shapes.
fn read(spec: &Spec, limits: &Limits) -> Result<Plan> {
    let AmasLimits {
        side: max_side,
        stage_cells: max_stage_cells,
        ..
    } = *LIMITS.of(limits);
    // Rectangles are cheap to write and costly to hold: bound them before building any.
    let declared: u64 = spec
        .stages
        .iter()
        .chain(std::iter::once(&spec.target))
        .map(|v| match v.get("rect").and_then(Value::as_array) {
            Some(r) => r
                .iter()
                .filter_map(Value::as_u64)
                .try_fold(1u64, u64::checked_mul)
                .map_or(1 << 32, |n| n.min(1 << 32)),
            None => 0,
        })
        .fold(0u64, u64::saturating_add);
    if declared > max_stage_cells {
        return Err(Error::field(
            "stages",
            format!("the targets hold more than {max_stage_cells} cells in all"),
        ));
    }
    let mut shapes = Vec::with_capacity(spec.stages.len() + 1);
    for (i, v) in spec.stages.iter().enumerate() {
        shapes.push((
            format!("stages[{i}]"),
            shape_value(v, &format!("stages[{i}]"), limits)?,
        ));
    }
    shapes.push((
        "target".to_string(),
        shape_value(&spec.target, "target", limits)?,
    ));
    let initial = match &spec.initial {
        Some(v) => Some(shape_value(v, "initial", limits)?),
        None => None,
    };
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
    if w > max_side || shape_h + spec.supply_rows > max_side {
        let (path, _) = shapes.last().expect("the target is always there");
        return Err(Error::field(
            path.as_str(),
            format!(
                "{w}×{} cells (with the supply rows) exceeds the limit of {max_side}×{max_side}",
                shape_h + spec.supply_rows
            ),
        ));
    }
    if shapes.len() as u64 * u64::from(w) * u64::from(shape_h) > max_stage_cells {
        return Err(Error::field(
            "stages",
            format!(
                "{} stage targets of {w}×{shape_h} cells are too many; at most {max_stage_cells} cells in all",
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
    let threshold = spec
        .gradient_threshold
        .unwrap_or_else(|| default_threshold(spec.field));
    let params = Params {
        field: spec.field,
        collision: spec.collision,
        updates: spec.field_updates_per_step,
        diffusion: spec.diffusion as f32,
        threshold: threshold as f32,
        move_d: spec.move_duration,
        pick_d: spec.pick_duration,
        place_d: spec.place_duration,
        relay_d: spec.relay_duration,
        penalty: spec.collision_penalty,
        turn_d: spec.turn_duration,
        communication: spec.communication,
        direction: spec.direction,
        give_way: spec.give_way,
        relay_with: spec.relay_with,
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
