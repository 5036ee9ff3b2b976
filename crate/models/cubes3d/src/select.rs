//! Step (iii) of a control step (sections 4.2 and 5): the selection rule, a unit's choice among
//! its options from their differences and the temperature. The options and the temperature are
//! made by the caller (`choose.rs`: the reachable positions, the light's priority, the clock);
//! the rule reads nothing else, so a rule is a function of what is passed here.

use super::spec::Selection;
use kumiki_model::math;
use kumiki_model::rng::Rng;

/// One option of a unit's choice: "no motion" (the text's i = 0, the unit's own cell) or a
/// reachable position, with the difference D_i the unit would have there (equation 4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Position {
    pub cell: u32,
    pub difference: f64,
}

/// What a unit knows of itself when it chooses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitState {
    /// Its cell: an option at this cell is "no motion".
    pub cell: u32,
    /// Its difference D_0 where it is.
    pub difference: f64,
    /// The target it works toward, counting from 0.
    pub target: u8,
    /// Control steps before this one on its clock of equation 8: since it took up that target
    /// (since the start when it never switched), or since the start with `clock` `run`.
    pub steps_on_target: u64,
}

/// A unit's choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Choice {
    Stay,
    /// To this cell.
    Move(u32),
}

/// The rule of `selection` over `options` (not empty) at temperature `temperature`, drawing from
/// `rng`; `weights` is a buffer for the draw. `mrf`: option i with probability
/// exp(−D_i / T) / Z (equation 7); `steepest`: the option of least difference ("always
/// selected"), ties at random; `random`: every option alike.
pub fn select(
    selection: Selection,
    options: &[Position],
    temperature: f64,
    unit: &UnitState,
    rng: &mut Rng,
    weights: &mut Vec<f64>,
) -> Choice {
    let least = options
        .iter()
        .map(|o| o.difference)
        .fold(f64::INFINITY, f64::min);
    weights.clear();
    let pick = match selection {
        Selection::Mrf => {
            // Shifted by the least difference, which Z cancels: no weight underflows to 0 all
            // together at a low temperature.
            weights.extend(
                options
                    .iter()
                    .map(|o| math::exp(-(o.difference - least) / temperature)),
            );
            rng.weighted(weights).unwrap_or(0)
        }
        Selection::Random => rng.index(options.len()),
        Selection::Steepest => {
            weights.extend(
                options
                    .iter()
                    .map(|o| if o.difference == least { 1.0 } else { 0.0 }),
            );
            rng.weighted(weights).unwrap_or(0)
        }
    };
    match options[pick].cell {
        c if c == unit.cell => Choice::Stay,
        c => Choice::Move(c),
    }
}
