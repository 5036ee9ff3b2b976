//! The scenario keys of the model, their defaults and their checks: a description is checked
//! whole, within the scenario's limits, before anything is built.

use serde::{Deserialize, Serialize};

use super::motion::PAD;
use super::typelist::{self, TypeList};
use super::{actions, types, Cubes};
use kumiki_model::bounds::{self, Bound, Bounded};
use kumiki_model::error::{Error, Result};
use kumiki_model::limits::Limits;
use kumiki_model::model::{self, Action, Model};
use kumiki_model::shape::{self, Grid3};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Selection {
    /// Equations 7 and 8: P_i ∝ exp(-D_i / T), T = c / log(1 + t).
    Mrf,
    /// Every reachable position equally likely (a unit that can move does).
    Random,
    /// The option of least difference, ties broken at random.
    Steepest,
}

/// Where the light's priority applies (section 6: "the units assign a higher moving priority to
/// reachable positions approaching the light source").
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum Priority {
    /// On each unit's own reachable positions: a unit that can approach the light chooses among
    /// staying and the positions that approach it; the others only when it has none.
    #[default]
    Positions,
    /// On the units (model version 4 and before): each unit chooses among all its positions, and
    /// a unit whose choice approaches the light moves before one whose choice does not.
    Units,
    /// None: the light only holds the units that see it when they switch to a target with
    /// `hold_lit`.
    None,
}

/// Which steps t of equation 8 counts.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum Clock {
    /// The steps since the unit took up its current target: with two or more targets, each
    /// switch starts the process (i)-(iii) of section 4 anew (section 6). With one target the
    /// same as `run`.
    #[default]
    Target,
    /// The steps of the whole run (model version 4 and before): T is not reset at a switch.
    Run,
}

/// The logarithm of equation 8.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum Log {
    /// The natural logarithm, as in Geman and Geman's schedule, which section 4.2 cites.
    #[default]
    Natural,
    /// The base-10 logarithm: T is ln 10 ≈ 2.3 times higher at every step.
    Ten,
}

#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize, Serialize, schemars::JsonSchema,
)]
pub enum Ground {
    /// No ground: free space on every side.
    #[default]
    #[serde(rename = "none")]
    Open,
    /// A plane under the lowest layer of the shape that units cannot pass.
    #[serde(rename = "floor")]
    Floor,
    /// As `floor`, and units touching the plane never move (a reading of section 6).
    #[serde(rename = "fixed")]
    Fixed,
    /// As `floor`, and the plane holds the units touching it (a support) and the structure: a
    /// unit on it may be carried off while another still touches it (section 6).
    #[serde(rename = "anchor")]
    Anchor,
}

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "Cubes3dSpec", transform = bounds::in_schema::<Spec>)]
pub struct Spec {
    /// The initial configuration: cubic-lattice text layers from the ground up, at least two
    /// units, connected face to face.
    pub(super) shape: String,
    /// The targets, the first one worked toward first (section 6 switches between them).
    pub(super) targets: Vec<TargetSpec>,
    /// The choice rule of step 4.
    #[serde(default = "default_selection")]
    pub(super) selection: Selection,
    /// W of equation 4, above 0.
    #[serde(default = "default_w")]
    pub(super) w: f64,
    /// a of equation 5, above 0.
    #[serde(default = "default_a")]
    pub(super) a: f64,
    /// C of equation 8, above 0.
    #[serde(default = "default_c")]
    pub(super) c: f64,
    /// The movable connection types (section 3.3).
    #[serde(default = "default_movable")]
    pub(super) movable: Vec<String>,
    /// Units moving per step (footnote 2).
    #[serde(default = "one")]
    pub(super) movers: u32,
    /// Least Manhattan distance between the movers of one step.
    #[serde(default = "default_mover_distance")]
    pub(super) mover_distance: u32,
    /// Free cells around the shapes.
    #[serde(default = "default_margin")]
    pub(super) margin: u32,
    /// A ground plane under the lowest layer.
    #[serde(default)]
    pub(super) ground: Ground,
    /// The direction in which the light source lies: +x, -x, +y, -y, +z or -z.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) light: Option<String>,
    /// t_stable of section 6: steps a unit stays under its target's threshold before it switches.
    #[serde(default = "default_stable_steps")]
    pub(super) stable_steps: u32,
    /// Where the light's priority applies: on each unit's reachable positions (section 6), on
    /// which unit's chosen move goes first (model version 4 and before), or nowhere.
    #[serde(default, skip_serializing_if = "is_default")]
    pub(super) priority: Priority,
    /// What t of equation 8 counts: the steps since the unit took up its current target, or the
    /// steps of the run (model version 4 and before).
    #[serde(default, skip_serializing_if = "is_default")]
    pub(super) clock: Clock,
    /// The logarithm of equation 8, natural or base 10.
    #[serde(default, skip_serializing_if = "is_default")]
    pub(super) log: Log,
    /// Whether random selection counts "no motion" (i = 0) among its options, as the MRF and
    /// steepest descent do; false: it always takes a reachable position (model version 4 and
    /// before).
    #[serde(default = "yes", skip_serializing_if = "is_yes")]
    pub(super) random_stays: bool,
    /// With a single target, end the run when it is complete (every unit's D_0 is 0). False
    /// lets the units go on choosing after that, as the figures' fixed-length runs of the
    /// comparison rules need.
    #[serde(default = "yes", skip_serializing_if = "is_yes")]
    pub(super) stop_at_goal: bool,
    /// Model version 1 weighted its light-seeking term by this factor (a form the paper does not
    /// give; see the docs' Interpretations). Every link made then carries it, so it is still
    /// read, and ignored: such a link opens with the notice that results may differ.
    #[serde(default, skip_serializing, rename = "light_priority")]
    _light_priority: Option<f64>,
}

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(transform = bounds::in_schema::<TargetSpec>)]
pub struct TargetSpec {
    #[serde(default)]
    pub(super) name: String,
    /// The target's type-lists, `C31[C41, C31, C31]` and so on.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) type_lists: Option<String>,
    /// A cubic shape drawn as a ghost; without `type_lists` they are derived from it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) shape: Option<String>,
    /// D_th: a unit under it for `stable_steps` switches to the next target (0 never does).
    #[serde(default)]
    pub(super) threshold: f64,
    /// Hold a unit that sees the light when it switches to this target (needs `light`).
    #[serde(default)]
    pub(super) hold_lit: bool,
}

impl Bounded for Spec {
    const BOUNDS: &'static [Bound<Spec>] = &[
        Bound::length("targets", |s: &Spec| Some(s.targets.len() as f64))
            .at_least(1.0)
            .up_to(|l| crate::limits::LIMITS.of(l).targets as f64),
        Bound::new("w", |s: &Spec| Some(s.w)).above(0.0),
        Bound::new("a", |s: &Spec| Some(s.a)).above(0.0),
        Bound::new("c", |s: &Spec| Some(s.c)).above(0.0),
        Bound::new("movers", |s: &Spec| Some(s.movers.into()))
            .at_least(1.0)
            .at_most(1024.0),
        Bound::new("mover_distance", |s: &Spec| Some(s.mover_distance.into()))
            .at_least(1.0)
            .at_most(1000.0),
        Bound::new("margin", |s: &Spec| Some(s.margin.into()))
            .at_most(200.0)
            .unit("cells"),
        Bound::new("stable_steps", |s: &Spec| Some(s.stable_steps.into())).at_least(1.0),
    ];
}

impl Bounded for TargetSpec {
    const BOUNDS: &'static [Bound<TargetSpec>] =
        &[Bound::new("threshold", |t: &TargetSpec| Some(t.threshold)).at_least(0.0)];
}

/// A description whose every key is checked: the shapes and type-lists read from their text,
/// and the space they need.
#[derive(Clone)]
pub struct Checked {
    pub(super) spec: Spec,
    pub(super) movable_types: u16,
    pub(super) light: Option<usize>,
    pub(super) shape: Grid3,
    pub(super) target_lists: Vec<Vec<TypeList>>,
    pub(super) target_shapes: Vec<Option<Grid3>>,
    pub(super) dims: [u32; 3],
    /// Margin cells under the shape (none on a ground plane).
    pub(super) below: u32,
    /// The most units the structure may grow to by added units.
    pub(super) max_units: usize,
}

impl Spec {
    /// Checks the parameters that need no shape: answers the movable types as a bit set and the
    /// light direction.
    fn check(&self) -> Result<(u16, Option<usize>)> {
        let mut movable_types = 0u16;
        for (i, name) in self.movable.iter().enumerate() {
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
        let light = self.light.as_deref().map(light_dir).transpose()?;
        Ok((movable_types, light))
    }
}

impl model::Spec for Spec {
    type Checked = Checked;

    fn validate(&self, limits: &Limits) -> Result<Checked> {
        let max = *crate::limits::LIMITS.of(limits);
        let (movable_types, light) = self.check()?;

        let shape = parse_shape(&self.shape, "shape", limits)?;
        if shape.count() > max.units {
            return Err(Error::field(
                "shape",
                format!("{} units exceed the limit of {}", shape.count(), max.units),
            ));
        }
        bounds::check_each("targets", &self.targets, limits)?;
        let mut target_shapes: Vec<Option<Grid3>> = Vec::new();
        let mut target_lists: Vec<Vec<TypeList>> = Vec::new();
        for (i, t) in self.targets.iter().enumerate() {
            let path = format!("targets[{i}]");
            let g = t
                .shape
                .as_deref()
                .map(|s| parse_shape(s, &format!("{path}.shape"), limits))
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
        let m = self.margin;
        let mut ext = [shape.w, shape.h, shape.d];
        for g in target_shapes.iter().flatten() {
            ext = [ext[0].max(g.w), ext[1].max(g.h), ext[2].max(g.d)];
        }
        let grounded = self.ground != Ground::Open;
        let below = if grounded { 0 } else { m };
        let dims = [
            2 * PAD + 2 * m + ext[0],
            2 * PAD + 2 * m + ext[1],
            2 * PAD + below + m + ext[2],
        ];
        let cells = dims.iter().map(|&d| u64::from(d)).product::<u64>();
        if dims.iter().any(|&d| d > max.side) || cells > max.cells {
            return Err(Error::field(
                "shape",
                format!(
                    "the space the shapes need with margin {m} ({}×{}×{} cells) exceeds the limit of {} per side and {} cells",
                    dims[0], dims[1], dims[2], max.side, max.cells
                ),
            ));
        }
        if !face_connected(&typelist::grid_units(&shape)) {
            return Err(Error::field(
                "shape",
                "the units are not all connected; every unit must touch the others face to face",
            ));
        }
        Ok(Checked {
            spec: self.clone(),
            movable_types,
            light,
            shape,
            target_lists,
            target_shapes,
            dims,
            below,
            max_units: max.units,
        })
    }

    fn check_action(checked: &Checked, action: &Action) -> Result<()> {
        let cells = checked.dims.iter().map(|&d| d as usize).product();
        actions::check_form(action, cells, checked.spec.targets.len())
    }

    fn build(checked: Checked, seed: u64) -> Box<dyn Model> {
        Box::new(Cubes::from_checked(checked, seed))
    }
}

/// The units form one piece, face to face.
fn face_connected(units: &[(i32, i32, i32)]) -> bool {
    let occupied: std::collections::HashSet<(i32, i32, i32)> = units.iter().copied().collect();
    let mut seen = std::collections::HashSet::new();
    let mut stack: Vec<(i32, i32, i32)> = units.first().copied().into_iter().collect();
    seen.extend(stack.iter().copied());
    while let Some((x, y, z)) = stack.pop() {
        for (dx, dy, dz) in kumiki_model::lattice::Cubic::DIRS {
            let n = (x + dx, y + dy, z + dz);
            if occupied.contains(&n) && seen.insert(n) {
                stack.push(n);
            }
        }
    }
    seen.len() == occupied.len()
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
fn yes() -> bool {
    true
}
fn is_yes(b: &bool) -> bool {
    *b
}
fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

pub(super) fn light_dir(text: &str) -> Result<usize> {
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

fn parse_shape(text: &str, path: &str, limits: &Limits) -> Result<Grid3> {
    let g = shape::parse_cubic_within(text, limits).map_err(|e| e.within(path))?;
    if g.count() < 2 {
        return Err(Error::field(
            path,
            "needs at least two units ('#' cells): a lone unit has no connection type and cannot move",
        ));
    }
    Ok(g)
}
