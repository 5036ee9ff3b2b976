//! Footnote 3: the direction the module under a robot displays, and what the robot is shown.
//! "Every module holds the values of the gradient field its neighbors have. The discretized
//! direction (N, S, E, W) calculated by these values is displayed to the robot. When these values
//! do not differ (i.e. difference between the maximum and minimum values is less than threshold),
//! the module displays 'no effective gradient' to the robot and the robot randomly decides its
//! direction." One pure function of typed inputs ([`shown`]); planning (`plan.rs`) reads the
//! neighbours into a [`Reading`] and acts on what is [`Shown`]. The rule slot `direction`
//! ([`DirectionRule`]) lets a scenario's script show the robot its way in place of [`shown`].

use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::{Deserialize, Serialize};

use super::spec::Direction;

/// The neighbour slots, in footnote 3's order.
pub const N: usize = 0;
pub const S: usize = 1;
pub const E: usize = 2;
pub const W: usize = 3;

/// The slots in the order Kumiki listed a cell's neighbours before model version 3 (right, up,
/// left, down). A robot that chooses at random draws in this order, so that runs of the
/// per-robot reading replay as they did.
pub const LISTED: [usize; 4] = [E, N, W, S];

/// What the module under a robot holds about its four neighbouring sites, by slot (N, S, E, W).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reading {
    /// The value each neighbouring module last sent, as a cost for this robot (lower is nearer
    /// its destination); `None` where no module is.
    pub cost: [Option<f32>; 4],
    /// Whether the robot may step onto that module (a blackboard closes the modules other
    /// robots' plans engage; giving way closes those a robot stands on).
    pub open: [bool; 4],
}

/// What the robot is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(from = "Answer")]
pub enum Shown {
    /// The module displays this direction (a slot).
    Toward(usize),
    /// The best open neighbours, equally good, as a set of slots (bit `1 << slot`): the robot
    /// draws one (the per-robot reading).
    Among(u8),
    /// There is a gradient but no open module to step onto: the robot waits.
    Nowhere,
    /// No effective gradient: the spread of the neighbours' values is below the threshold (or
    /// no neighbour is a module). The robot picks its way at random.
    NoGradient,
}

/// What the module shows a robot whose neighbours read `reading`. The gradient is judged on
/// every neighbouring module's value, open or not; the direction is the open module of lowest
/// cost. With [`Direction::Module`] the module shows one, the first in the order N, S, E, W
/// among equally good ones, a rule it applies alone, so every robot reading it gets the same;
/// with [`Direction::Robot`] it shows them all and the robot draws.
pub fn shown(reading: &Reading, threshold: f32, rule: Direction) -> Shown {
    match spread(reading) {
        Some(spread) if spread >= threshold => {}
        _ => return Shown::NoGradient,
    }
    let open = |slot: usize| match reading.open[slot] {
        true => reading.cost[slot],
        false => None,
    };
    let best = (0..4).filter_map(open).fold(f32::INFINITY, f32::min);
    let among = (0..4)
        .filter(|&slot| open(slot) == Some(best))
        .fold(0u8, |set, slot| set | 1 << slot);
    match (among, rule) {
        (0, _) => Shown::Nowhere,
        (set, Direction::Module) => Shown::Toward(set.trailing_zeros() as usize),
        (set, Direction::Robot) => Shown::Among(set),
    }
}

/// The difference between the largest and the smallest value the module holds, as the module
/// computes it (in single precision); `None` where no neighbour is a module.
fn spread(reading: &Reading) -> Option<f32> {
    let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
    for &c in reading.cost.iter().flatten() {
        lo = lo.min(c);
        hi = hi.max(c);
    }
    (hi >= lo).then_some(hi - lo)
}

/// One value for each neighbouring site, by its compass name, as a script reads it
/// (`robot.cost.N`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct Compass<T> {
    N: T,
    S: T,
    E: T,
    W: T,
}

impl<T: Copy> From<[T; 4]> for Compass<T> {
    fn from(v: [T; 4]) -> Self {
        Compass {
            N: v[N],
            S: v[S],
            E: v[E],
            W: v[W],
        }
    }
}

/// What the module under a robot holds and what it is asked for: the slot's input.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sight {
    /// Each neighbour's value as a cost for this robot (lower is nearer its destination);
    /// `()` where no module is.
    pub cost: Compass<Option<f32>>,
    /// Whether the robot may step onto each neighbour.
    pub open: Compass<bool>,
    /// The largest value less the smallest, as the module computes it; `()` where no neighbour
    /// is a module.
    pub spread: Option<f32>,
    /// The scenario's threshold of an effective gradient.
    pub threshold: f32,
    /// The scenario's reading of who chooses among equally good neighbours.
    pub rule: Direction,
    /// The robot carries a module.
    pub loaded: bool,
    /// The robot gives way after a collision: it steps to the best module no robot stands on
    /// (`open`), on any gradient at all.
    pub giving_way: bool,
}

impl Sight {
    /// What a robot sees in `reading`, asked to plan (`giving_way` false) or to give way.
    pub fn of(
        reading: &Reading,
        threshold: f32,
        rule: Direction,
        loaded: bool,
        giving_way: bool,
    ) -> Sight {
        Sight {
            cost: reading.cost.into(),
            open: reading.open.into(),
            spread: spread(reading),
            threshold,
            rule,
            loaded,
            giving_way,
        }
    }

    /// The reading it was made from.
    fn reading(&self) -> Reading {
        let c = self.cost;
        let o = self.open;
        Reading {
            cost: [c.N, c.S, c.E, c.W],
            open: [o.N, o.S, o.E, o.W],
        }
    }
}

/// A neighbour's compass name in a script's answer.
#[derive(Clone, Copy, Debug, Deserialize)]
enum Way {
    N,
    S,
    E,
    W,
}

impl Way {
    fn slot(self) -> usize {
        match self {
            Way::N => N,
            Way::S => S,
            Way::E => E,
            Way::W => W,
        }
    }
}

/// A word a script may answer.
#[derive(Clone, Copy, Debug, Deserialize)]
enum Word {
    N,
    S,
    E,
    W,
    #[serde(rename = "wait")]
    Wait,
    #[serde(rename = "no_gradient")]
    NoGradient,
}

/// A script's answer: one word, or the neighbours the robot draws among.
#[derive(Deserialize)]
#[serde(untagged)]
enum Answer {
    Word(Word),
    Among(Vec<Way>),
}

impl From<Answer> for Shown {
    fn from(answer: Answer) -> Shown {
        let toward = |way: Way| Shown::Toward(way.slot());
        match answer {
            Answer::Word(Word::N) => toward(Way::N),
            Answer::Word(Word::S) => toward(Way::S),
            Answer::Word(Word::E) => toward(Way::E),
            Answer::Word(Word::W) => toward(Way::W),
            Answer::Word(Word::Wait) => Shown::Nowhere,
            Answer::Word(Word::NoGradient) => Shown::NoGradient,
            Answer::Among(ways) => match ways.iter().fold(0u8, |set, w| set | 1 << w.slot()) {
                0 => Shown::Nowhere,
                set => Shown::Among(set),
            },
        }
    }
}

/// The rule slot `direction`: what the module under a robot shows it (footnote 3), from the
/// values its neighbours hold. Asked at every plan of a robot on a working module that follows
/// the field, and of a robot giving way after a collision; the paper's rule is [`shown`].
pub struct DirectionRule;

impl Slot for DirectionRule {
    type Input = Sight;
    type Output = Shown;
    const INFO: SlotInfo = SlotInfo {
        name: "direction",
        title: "AMAS: the direction a module shows its robot (footnote 3)",
        about: "The module under a robot holds the values of the gradient field its four neighbours have, as costs for this robot (lower is nearer the supply for an empty robot, nearer the front for a loaded one), and shows the robot where to go: one neighbouring module, several equally good ones for the robot to draw among, \"wait\" (a gradient, but no module the robot may step onto), or \"no effective gradient\", on which the robot walks to a random open neighbour. Asked at every plan of a robot that follows the field, and of a robot that gives way after a collision: it steps to the best module no robot stands on.",
        input: &[
            Field {
                name: "cost",
                kind: "map of float or ()",
                about: "each neighbour's value as a cost for this robot, by compass name (cost.N, cost.S, cost.E, cost.W); () where no module is",
            },
            Field {
                name: "open",
                kind: "map of bool",
                about: "whether the robot may step onto each neighbour (open.N, ...): a module no other robot's plan engages on a blackboard, or, giving way, one no robot stands on",
            },
            Field {
                name: "spread",
                kind: "float or ()",
                about: "the largest value less the smallest, as the module computes it (in single precision); () where no neighbour is a module",
            },
            Field {
                name: "threshold",
                kind: "float",
                about: "the scenario's threshold: a spread below it is \"no effective gradient\"",
            },
            Field {
                name: "rule",
                kind: "string",
                about: "the scenario's reading of footnote 3: \"module\" (the module shows the first best in the order N, S, E, W) or \"robot\" (each robot draws among the best)",
            },
            Field {
                name: "loaded",
                kind: "bool",
                about: "the robot carries a module",
            },
            Field {
                name: "giving_way",
                kind: "bool",
                about: "the robot gives way after a collision: it takes the best open module on any gradient",
            },
        ],
        output: "\"N\", \"S\", \"E\" or \"W\" (a neighbouring module), a list of them (the robot draws among them), \"wait\" or \"no_gradient\"",
        paper: include_str!("../rules/direction.rhai"),
        random: false,
    };

    #[inline]
    fn paper(sight: &Sight, _: Option<&mut Rng>) -> Shown {
        let threshold = match sight.giving_way {
            true => f32::NEG_INFINITY,
            false => sight.threshold,
        };
        shown(&sight.reading(), threshold, sight.rule)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reading(cost: [Option<f32>; 4]) -> Reading {
        Reading {
            cost,
            open: cost.map(|c| c.is_some()),
        }
    }

    #[test]
    fn the_module_shows_the_first_best_in_footnote_3s_order() {
        // West and south equally good: the module shows south (N, S, E, W), whoever reads it.
        let r = reading([Some(5.0), Some(3.0), None, Some(3.0)]);
        assert_eq!(shown(&r, 1.0, Direction::Module), Shown::Toward(S));
        assert_eq!(
            shown(&r, 1.0, Direction::Robot),
            Shown::Among(1 << S | 1 << W)
        );
        // A closed best module leaves the best open one.
        let mut closed = r;
        closed.open[S] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Toward(W));
        closed.open[W] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Toward(N));
        closed.open[N] = false;
        assert_eq!(shown(&closed, 1.0, Direction::Module), Shown::Nowhere);
    }

    #[test]
    fn values_that_do_not_differ_show_no_gradient() {
        let flat = reading([Some(2.0), Some(2.0), Some(2.0), None]);
        assert_eq!(shown(&flat, 1.0, Direction::Module), Shown::NoGradient);
        assert_eq!(shown(&flat, 0.0, Direction::Module), Shown::Toward(N));
        // The spread counts closed modules too: the module holds every neighbour's value.
        let mut r = reading([Some(1.0), Some(2.0), None, None]);
        r.open[N] = false;
        assert_eq!(shown(&r, 1.0, Direction::Robot), Shown::Among(1 << S));
        assert_eq!(
            shown(&reading([None; 4]), 0.0, Direction::Module),
            Shown::NoGradient
        );
    }

    #[test]
    fn a_scripts_answer_reads_as_what_the_module_shows() {
        let read = |v: serde_json::Value| serde_json::from_value::<Shown>(v).ok();
        assert_eq!(read(serde_json::json!("W")), Some(Shown::Toward(W)));
        assert_eq!(read(serde_json::json!("wait")), Some(Shown::Nowhere));
        assert_eq!(
            read(serde_json::json!("no_gradient")),
            Some(Shown::NoGradient)
        );
        assert_eq!(
            read(serde_json::json!(["S", "W"])),
            Some(Shown::Among(1 << S | 1 << W))
        );
        assert_eq!(read(serde_json::json!([])), Some(Shown::Nowhere));
        assert_eq!(read(serde_json::json!("up")), None);
        assert_eq!(read(serde_json::json!(["N", "wait"])), None);
    }

    #[test]
    fn the_paper_rule_takes_any_gradient_when_giving_way() {
        let flat = reading([Some(2.0), Some(2.0), None, None]);
        let sight = |giving_way| Sight::of(&flat, 1.0, Direction::Module, false, giving_way);
        assert_eq!(DirectionRule::paper(&sight(false), None), Shown::NoGradient);
        assert_eq!(DirectionRule::paper(&sight(true), None), Shown::Toward(N));
        assert_eq!(sight(false).spread, Some(0.0));
    }
}
