//! The rule slot `activation`: whether a movable unit moves this step (section 3.2.4, equation
//! 3, and condition 5 of section 3.2.5), from its diffusion variable, its difference and its
//! irritation. Asked in the diffusion phase (`diffuse.rs`) of every working movable unit, after
//! equations 2 and 4 and condition 5 were evaluated; a unit that is not movable never moves.

use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::Serialize;

/// The slot.
pub struct Activation;

/// What a movable unit senses when it decides whether to move.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Senses {
    /// Its diffusion variable x(i, t), before this step's change (equation 2).
    pub x: f64,
    /// Its difference diff(i, t) from the closest goal statement.
    pub difference: u32,
    /// Its flux x̄(i, t), the sum of its neighbours' x less its own.
    pub flux: f64,
    /// The activation threshold G of equation 3.
    pub threshold: f64,
    /// Its irritation fired this step (condition 5): irr(i, t) went past I_th and was reset.
    pub irritated: bool,
}

impl Slot for Activation {
    type Input = Senses;
    /// Whether the unit is active: it plans a roll.
    type Output = bool;
    const INFO: SlotInfo = SlotInfo {
        name: "activation",
        title: "Fracta: which units move (equation 3 and condition 5)",
        about: "Each working movable unit, in every step's diffusion phase (after equation 2 and the irritation of equations 4 and 5), decides whether it is activated to roll. An active unit then plans a roll (the slot roll, or the paper's choice of direction). Units that are not movable never move.",
        input: &[
            Field {
                name: "x",
                kind: "float",
                about: "its diffusion variable x(i, t), the average difference around it (equation 2), before this step's change",
            },
            Field {
                name: "difference",
                kind: "int",
                about: "its difference diff(i, t) from the closest goal statement",
            },
            Field {
                name: "flux",
                kind: "float",
                about: "its flux, the sum over its neighbours of x(j, t) - x(i, t)",
            },
            Field {
                name: "threshold",
                kind: "float",
                about: "the activation threshold G (the scenario's g)",
            },
            Field {
                name: "irritated",
                kind: "bool",
                about: "its irritation went past I_th this step (condition 5) and was reset",
            },
        ],
        output: "true (the unit is active and plans a roll) or false",
        paper: include_str!("../rules/activation.rhai"),
        random: false,
    };

    /// Equation 3, G x(i, t) < diff(i, t), or condition 5.
    #[inline]
    fn paper(unit: &Senses, _: Option<&mut Rng>) -> bool {
        unit.threshold * unit.x < f64::from(unit.difference) || unit.irritated
    }
}
