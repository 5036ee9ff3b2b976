//! The rule slot `roll`: which way an active unit rolls (section 3.2.4: "The motion is
//! stochastic in such a way that the direction which gives smaller difference after the
//! movement is chosen with larger probability"), or whether it stays. Asked in the planning
//! phase (`plan.rs`) of every active unit that has a legal roll.

use kumiki_model::math;
use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::Serialize;

use super::pattern::Turn;

/// The slot.
pub struct Roll;

/// One legal roll of the unit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Candidate {
    /// `"cw"` or `"ccw"`, about the pivot.
    #[serde(serialize_with = "turn_name")]
    pub turn: Turn,
    /// The pivot's side of the unit: 0 east, 1 north-east, 2 north-west, 3 west, 4 south-west,
    /// 5 south-east.
    pub pivot: u8,
    /// How much the roll changes the summed difference of the units whose statement it
    /// changes (negative: it lowers it).
    pub change: i64,
}

fn turn_name<S: serde::Serializer>(turn: &Turn, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(match turn {
        Turn::Cw => "cw",
        Turn::Ccw => "ccw",
    })
}

/// The legal rolls of a unit, at most two, kept on the stack and seen by a script as a list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rolls {
    items: [Candidate; 2],
    len: usize,
}

impl Rolls {
    pub const NONE: Rolls = Rolls {
        items: [Candidate {
            turn: Turn::Ccw,
            pivot: 0,
            change: 0,
        }; 2],
        len: 0,
    };

    /// Adds `roll`, when there are fewer than two.
    pub fn push(&mut self, roll: Candidate) {
        if self.len < 2 {
            self.items[self.len] = roll;
            self.len += 1;
        }
    }

    pub fn as_slice(&self) -> &[Candidate] {
        &self.items[..self.len]
    }
}

impl Serialize for Rolls {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.as_slice())
    }
}

/// What an active unit senses when it plans its roll.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Senses {
    /// Its legal rolls, one or two (the first two found, pivots in direction order,
    /// counter-clockwise before clockwise).
    pub options: Rolls,
    /// Its irritation activated it (condition 5), not equation 3.
    pub irritated: bool,
    /// The temperature of the choice (the scenario's `temperature`).
    pub temperature: f64,
}

impl Slot for Roll {
    type Input = Senses;
    /// The index of the chosen roll, or none to stay.
    type Output = Option<usize>;
    const INFO: SlotInfo = SlotInfo {
        name: "roll",
        title: "Fracta: which way an active unit rolls (section 3.2.4)",
        about: "Each active unit (the slot activation) that has a legal roll chooses one, or stays, in every step's planning phase. The rolls chosen are then carried out one at a time in a random order, one that the earlier ones made impossible cancelled (a conflict). The paper's rule: a unit activated by equation 3 moves only when a roll lowers the difference around it (section 3.2 (iii): \"it moves towards the direction to make it smaller\"), one whose irritation fired moves whatever the change; with two rolls, the first with probability 1 / (1 + exp((change_0 - change_1) / T)).",
        input: &[
            Field {
                name: "options",
                kind: "list of maps: turn (string), pivot (int), change (int)",
                about: "its legal rolls, one or two: turn \"cw\" or \"ccw\" about the pivot; pivot, the side the pivot is on (0 east, 1 north-east, 2 north-west, 3 west, 4 south-west, 5 south-east); change, how much the roll changes the summed difference of the units whose statement it changes",
            },
            Field {
                name: "irritated",
                kind: "bool",
                about: "its irritation activated it (condition 5), not equation 3",
            },
            Field {
                name: "temperature",
                kind: "float",
                about: "the temperature of the choice (the scenario's temperature)",
            },
        ],
        output: "() (it stays) or the index of the chosen roll in options (0 or 1)",
        paper: include_str!("../rules/roll.rhai"),
        random: true,
    };

    /// The direction that lowers the difference more is the likelier (Boltzmann weights of the
    /// changes); a unit equation 3 activated stays unless a roll lowers it.
    fn paper(unit: &Senses, rng: Option<&mut Rng>) -> Option<usize> {
        let options = unit.options.as_slice();
        if options.is_empty() || (!unit.irritated && options.iter().all(|o| o.change >= 0)) {
            return None;
        }
        if options.len() == 1 {
            return Some(0);
        }
        let rng = rng.expect("the roll draws from the model's generator");
        let (d0, d1) = (options[0].change as f64, options[1].change as f64);
        // P(first) = e^(-d0/T) / (e^(-d0/T) + e^(-d1/T)).
        let p0 = 1.0 / (1.0 + math::exp((d0 - d1) / unit.temperature));
        Some(if rng.unit() < p0 { 0 } else { 1 })
    }
}
