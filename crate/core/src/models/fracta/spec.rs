//! The scenario keys of the model, their defaults and their checks.

use super::*;

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Spec {
    /// The starting configuration, a hex shape (see [`crate::shape`]).
    pub(super) start: String,
    /// The goal statements (see [`goal`]).
    pub(super) goal: String,
    #[serde(default = "defaults::margin")]
    pub(super) margin: u32,
    #[serde(rename = "K", default = "defaults::k")]
    pub(super) k: f64,
    #[serde(rename = "L", default = "defaults::l")]
    pub(super) l: f64,
    #[serde(rename = "G", default = "defaults::g")]
    pub(super) g: f64,
    #[serde(rename = "I_th", default = "defaults::i_th")]
    pub(super) i_th: f64,
    #[serde(default = "defaults::stable")]
    pub(super) stable: f64,
    #[serde(default = "defaults::irritation_gain")]
    pub(super) irritation_gain: f64,
    #[serde(default = "defaults::temperature")]
    pub(super) temperature: f64,
    #[serde(default = "defaults::avoid_e")]
    pub(super) avoid_e: bool,
    #[serde(default = "defaults::no_holes")]
    pub(super) no_holes: bool,
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
        true
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
