//! The scenario keys of the model, their defaults and their checks.

use super::*;
use kumiki_model::bounds::Bound;

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "FractaSpec", transform = kumiki_model::bounds::in_schema::<Spec>)]
pub struct Spec {
    /// The starting configuration, a hex shape (see [`crate::shape`]).
    pub(super) start: String,
    /// The goal statements (see [`goal`]).
    pub(super) goal: String,
    /// Free cells around the start shape's bounding box.
    #[serde(default = "defaults::margin")]
    pub(super) margin: u32,
    /// Diffusion coefficient (equation 2); above 1/6 a unit with six neighbours would overshoot.
    #[serde(rename = "K", default = "defaults::k")]
    pub(super) k: f64,
    /// Leak constant, movable units only (equation 2).
    #[serde(rename = "L", default = "defaults::l")]
    pub(super) l: f64,
    /// Activation threshold (equation 3).
    #[serde(rename = "G", default = "defaults::g")]
    pub(super) g: f64,
    /// Irritation threshold (condition 5), above 0.
    #[serde(rename = "I_th", default = "defaults::i_th")]
    pub(super) i_th: f64,
    /// x counts as stable when |Δx| is below this (equation 4).
    #[serde(default = "defaults::stable")]
    pub(super) stable: f64,
    /// How much x is raised when irritation fires.
    #[serde(default = "defaults::irritation_gain")]
    pub(super) irritation_gain: f64,
    /// Temperature of the choice between the two rolls.
    #[serde(default = "defaults::temperature")]
    pub(super) temperature: f64,
    /// No motion ends as an `e` (the hardware rule of section 4): a unit keeps rolling about its
    /// pivot until it touches a second unit; off, every motion is one 60° roll.
    #[serde(default = "defaults::avoid_e")]
    pub(super) avoid_e: bool,
    /// No motion encloses empty cells (a region of up to 7 empty cells cut off from the
    /// lattice's edge). Off by default: the paper states no such rule.
    #[serde(default = "defaults::no_holes")]
    pub(super) no_holes: bool,
    /// How lower-priority goal statements count in the difference.
    #[serde(default = "defaults::priorities")]
    pub(super) priorities: Priorities,
}

impl kumiki_model::bounds::Bounded for Spec {
    const BOUNDS: &'static [Bound<Spec>] = &[
        Bound::new("margin", |s: &Spec| Some(s.margin.into()))
            .up_to(|l| crate::limits::LIMITS.of(l).margin.into())
            .unit("cells"),
        Bound::new("K", |s: &Spec| Some(s.k))
            .at_least(0.0)
            .at_most(1.0 / 6.0)
            .why("above 1/6 a unit with six neighbours would overshoot the average"),
        Bound::new("L", |s: &Spec| Some(s.l))
            .at_least(0.0)
            .at_most(1000.0),
        Bound::new("G", |s: &Spec| Some(s.g))
            .at_least(0.0)
            .at_most(1000.0),
        Bound::new("I_th", |s: &Spec| Some(s.i_th))
            .above(0.0)
            .at_most(1e9),
        Bound::new("stable", |s: &Spec| Some(s.stable))
            .at_least(0.0)
            .at_most(1000.0),
        Bound::new("irritation_gain", |s: &Spec| Some(s.irritation_gain))
            .at_least(0.0)
            .at_most(1000.0),
        Bound::new("temperature", |s: &Spec| Some(s.temperature))
            .at_least(0.001)
            .at_most(1e6),
    ];
}

/// Parameter defaults; `crate/models/fracta/README.md` says why each was chosen.
pub mod defaults {
    use super::Priorities;
    pub fn margin() -> u32 {
        6
    }
    pub fn k() -> f64 {
        0.1
    }
    pub fn l() -> f64 {
        0.3
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
    pub fn no_holes() -> bool {
        false
    }
    pub(super) fn priorities() -> Priorities {
        Priorities::Pooled
    }
}

#[derive(Clone, Copy, Debug)]
pub(super) struct Params {
    pub(super) k: f64,
    pub(super) l: f64,
    pub(super) g: f64,
    pub(super) i_th: f64,
    pub(super) stable: f64,
    pub(super) gain: f64,
    pub(super) temperature: f64,
    pub(super) avoid_e: bool,
    pub(super) no_holes: bool,
    pub(super) priorities: Priorities,
}

/// The parameters the model runs with (their ranges are checked with the description).
pub(super) fn params(s: &Spec) -> Params {
    Params {
        k: s.k,
        l: s.l,
        g: s.g,
        i_th: s.i_th,
        stable: s.stable,
        gain: s.irritation_gain,
        temperature: s.temperature,
        avoid_e: s.avoid_e,
        no_holes: s.no_holes,
        priorities: s.priorities,
    }
}
