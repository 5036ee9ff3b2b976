//! The scenario keys of the model, their defaults and their checks.

use super::*;

#[derive(Clone, Debug, PartialEq, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "FractaSpec")]
pub struct Spec {
    /// The starting configuration, a hex shape (see [`crate::shape`]).
    pub(super) start: String,
    /// The goal statements (see [`goal`]).
    pub(super) goal: String,
    /// Free cells around the start shape's bounding box.
    #[serde(default = "defaults::margin")]
    #[schemars(range(max = crate::limits::LIMITS.page.margin))]
    pub(super) margin: u32,
    /// Diffusion coefficient (equation 2); above 1/6 a unit with six neighbours would overshoot.
    #[serde(rename = "K", default = "defaults::k")]
    #[schemars(range(min = 0.0, max = 0.16666666666666666))]
    pub(super) k: f64,
    /// Leak constant, movable units only (equation 2).
    #[serde(rename = "L", default = "defaults::l")]
    #[schemars(range(min = 0.0, max = 1000.0))]
    pub(super) l: f64,
    /// Activation threshold (equation 3).
    #[serde(rename = "G", default = "defaults::g")]
    #[schemars(range(min = 0.0, max = 1000.0))]
    pub(super) g: f64,
    /// Irritation threshold (condition 5), above 0.
    #[serde(rename = "I_th", default = "defaults::i_th")]
    #[schemars(range(max = 1e9))]
    pub(super) i_th: f64,
    /// x counts as stable when |Δx| is below this (equation 4).
    #[serde(default = "defaults::stable")]
    #[schemars(range(min = 0.0, max = 1000.0))]
    pub(super) stable: f64,
    /// How much x is raised when irritation fires.
    #[serde(default = "defaults::irritation_gain")]
    #[schemars(range(min = 0.0, max = 1000.0))]
    pub(super) irritation_gain: f64,
    /// Temperature of the choice between the two rolls.
    #[serde(default = "defaults::temperature")]
    #[schemars(range(min = 0.001, max = 1e6))]
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

pub(super) fn check_params(s: &Spec) -> Result<Params> {
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
        no_holes: s.no_holes,
        priorities: s.priorities,
    })
}
