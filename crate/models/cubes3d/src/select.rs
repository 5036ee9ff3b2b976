//! Step (iii) of a control step (sections 4.2 and 5): the selection rule, a unit's choice among
//! its options from their differences and the temperature, and the rule slot `select` a
//! scenario's script may take. The options and the temperature are made by the caller
//! (`choose.rs`: the reachable positions, the light's priority, the clock); the rule reads
//! nothing else, so a rule is a function of what is passed here ([`Senses`]).
//!
//! The paper compares three rules (section 5): the MRF's stochastic relaxation (equations 7 and
//! 8, "proposed"), "random" and "steepest-descent selection of reachable position". The
//! scenario's `selection` names one; the slot's paper script holds all three and follows it.

use kumiki_model::math;
use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::Serialize;

use super::spec::Selection;

/// The most options a unit can have: "no motion" and 24 reachable positions (6 carriers, 2 axes
/// of rotation each, 2 senses).
pub const MAX_OPTIONS: usize = 25;

/// One option of a unit's choice: "no motion" (the text's i = 0, the unit's own cell) or a
/// reachable position, with the difference D_i the unit would have there (equation 4).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Position {
    /// The cell, which the script does not see: it chooses by index.
    #[serde(skip)]
    pub cell: u32,
    pub difference: f64,
    /// "No motion": the unit's own cell.
    pub stay: bool,
}

/// What a unit senses when it chooses (the slot's input): its options, the temperature of
/// equation 8, the control steps t on its clock, and the rule the scenario names.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Senses {
    pub selection: Selection,
    pub temperature: f64,
    /// Control steps before this one on the unit's clock of equation 8: since it took up its
    /// target (since the start when it never switched), or since the start with `clock` `run`.
    pub t: u64,
    pub options: Vec<Position>,
}

impl Default for Senses {
    fn default() -> Self {
        Senses {
            selection: Selection::Mrf,
            temperature: 0.0,
            t: 0,
            options: Vec::new(),
        }
    }
}

/// The slot.
pub struct Select;

impl Slot for Select {
    type Input = Senses;
    /// The index of the chosen option.
    type Output = usize;
    const INFO: SlotInfo = SlotInfo {
        name: "select",
        title: "3-D units: the selection rule (step iii, equations 7 and 8)",
        about: "Each unit asked in a control step (in a random order, until one chooses to move, or `movers` with footnote 2) chooses among its options: \"no motion\" and its reachable positions, each with the difference D_i it would have there (equation 4), after the light's priority on positions. The paper's three rules are the built-in, the one the scenario's `selection` names: the MRF's stochastic relaxation (option i with probability exp(-D_i / T) / Z), steepest descent (the least difference, ties at random) and random selection (every option alike).",
        input: &[
            Field {
                name: "options",
                kind: "list of maps: difference (float), stay (bool)",
                about: "the unit's options: \"no motion\" first (stay true, its present difference D_0; left out of random selection's options with random_stays false), then its reachable positions (stay false), each with the difference D_i it would have there",
            },
            Field {
                name: "temperature",
                kind: "float",
                about: "T of equation 8, C / log(1 + t)",
            },
            Field {
                name: "t",
                kind: "int",
                about: "control steps before this one on the unit's clock (since it took up its target with clock \"target\", since the start with \"run\")",
            },
            Field {
                name: "selection",
                kind: "string",
                about: "the rule the scenario names: \"mrf\", \"random\" or \"steepest\"",
            },
        ],
        output: "the index of the chosen option in options (an integer from 0); choosing the option with stay true is \"no motion\"",
        paper: concat!(
            include_str!("../rules/select.rhai"),
            "\n",
            include_str!("../rules/mrf.rhai"),
            "\n",
            include_str!("../rules/random.rhai"),
            "\n",
            include_str!("../rules/steepest.rhai"),
        ),
        random: true,
    };

    /// `mrf`: option i with probability exp(−D_i / T) / Z (equation 7); `steepest`: the option
    /// of least difference ("always selected"), ties at random; `random`: every option alike.
    fn paper(unit: &Senses, rng: Option<&mut Rng>) -> usize {
        let rng = rng.expect("the selection rule draws from the model's generator");
        let options = &unit.options;
        let least = options
            .iter()
            .map(|o| o.difference)
            .fold(f64::INFINITY, f64::min);
        let mut weights = [0.0; MAX_OPTIONS];
        let weights = &mut weights[..options.len()];
        match unit.selection {
            Selection::Mrf => {
                // Shifted by the least difference, which Z cancels: no weight underflows to 0 all
                // together at a low temperature.
                for (w, o) in weights.iter_mut().zip(options) {
                    *w = math::exp(-(o.difference - least) / unit.temperature);
                }
                rng.weighted(weights).unwrap_or(0)
            }
            Selection::Random => rng.index(options.len()),
            Selection::Steepest => {
                for (w, o) in weights.iter_mut().zip(options) {
                    *w = if o.difference == least { 1.0 } else { 0.0 };
                }
                rng.weighted(weights).unwrap_or(0)
            }
        }
    }
}
