//! The rule slot `leader`: rule 3 of the three-rule election (section 3.3, figure 8), the robot's
//! decision whether it is the temporary leader and which form it recognises, from the signals it
//! heard in the election's two slots. Rules 1 and 2 (who signals in each slot) stay the paper's.
//!
//! The decision is taken wherever the three rules elect: the crawl's first algorithm (alone, or
//! first in the trial-and-error and cautious methods), the bridge's construction mode, and the
//! permanent leader's choice in the baseline.

use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::{Deserialize, Serialize};

use super::election::{Kind, Mode};

/// The slot.
pub struct Leader;

/// The faces a robot heard a signal from in one slot.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Heard {
    pub right: bool,
    pub up: bool,
    pub left: bool,
    pub down: bool,
}

/// What a robot senses when it decides: the signals of the election's two slots, and the mode
/// the load-check slot put every robot in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Senses {
    pub first: Heard,
    pub second: Heard,
    pub mode: &'static str,
}

/// The form a leader recognises: the leader kinds the crawl's forms command (the four of the
/// three rules, and the second and third algorithms' row end and corner).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Form {
    TopRight,
    TopLeft,
    BottomLeft,
    BottomRight,
    RowEnd,
    Corner,
}

impl Form {
    pub fn kind(self) -> Kind {
        match self {
            Form::TopRight => Kind::TopRight,
            Form::TopLeft => Kind::TopLeft,
            Form::BottomLeft => Kind::BottomLeft,
            Form::BottomRight => Kind::BottomRight,
            Form::RowEnd => Kind::RowEnd,
            Form::Corner => Kind::Corner,
        }
    }
}

/// The mode's name as the script sees it.
pub fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Crawl => "crawl",
        Mode::Construction => "construction",
        Mode::Adaptation => "adaptation",
    }
}

const FACES: &str = "map of bool: right, up, left, down";

impl Slot for Leader {
    type Input = Senses;
    type Output = Option<Form>;
    const INFO: SlotInfo = SlotInfo {
        name: "leader",
        title: "CHOBIE II: who leads, and in which form (rule 3 of the election)",
        about: "Each robot, after the election's two slots (rule 1: every robot signals in all four directions; rule 2: a robot that heard from top or bottom stops signalling left and right), decides whether it is the temporary leader and which form it recognises. Its kind sets the line it commands (the model's README, 'Three-rule election'). Asked of every robot wherever the three rules elect: the crawl's first algorithm (with every method), the bridge's construction mode and the permanent-leader baseline.",
        input: &[
            Field {
                name: "first",
                kind: FACES,
                about: "the faces it heard a signal from in slot 1 (a robot on that face)",
            },
            Field {
                name: "second",
                kind: FACES,
                about: "the faces it heard a signal from in slot 2 (a neighbour on its left or right that heard nothing from top or bottom)",
            },
            Field {
                name: "mode",
                kind: "string",
                about: "\"crawl\" or \"construction\" (the bridge's mode, from the load-check slot)",
            },
        ],
        output: "() (not a leader) or the form it leads: \"top_right\", \"top_left\", \"bottom_left\", \"bottom_right\", \"row_end\" or \"corner\"",
        paper: include_str!("../rules/leader.rhai"),
        random: false,
    };

    /// Rule 3: a robot that heard from a vertical direction in slot 1 and from a horizontal one
    /// in slot 2 leads; top when it heard from top, right when it heard from right.
    fn paper(robot: &Senses, _: Option<&mut Rng>) -> Option<Form> {
        let (first, second) = (robot.first, robot.second);
        if !first.up && !first.down {
            return None;
        }
        let right = match (second.right, second.left) {
            (true, _) => true,
            (false, true) => false,
            (false, false) => return None,
        };
        Some(match (first.up, right) {
            (true, true) => Form::TopRight,
            (true, false) => Form::TopLeft,
            (false, true) => Form::BottomRight,
            (false, false) => Form::BottomLeft,
        })
    }
}
