//! Sections 4.6 and 5.1: what a robot that could not do what it planned does next. "The robot
//! that has the largest token wins the priority to move. Other robots cannot move until the
//! collision is resolved", and "the penalty for collision" takes one time step (5.1, by default).
//! One pure function of typed inputs ([`outcome`]); the step's conflict phase (`conflicts.rs`)
//! finds the [`Conflict`] and applies the [`Outcome`]. Module relay (4.6.1) is settled before it:
//! a loaded and an unloaded robot that meet swap loads instead of colliding, where the robot in
//! the way can take part ([`relays`], another pure function).

use kumiki_model::rng::Rng;
use kumiki_model::slot::{Field, Slot, SlotInfo};
use serde::{Deserialize, Serialize};

use super::spec::{GiveWay, RelayWith};

/// What the robot on the module another wants is doing, for module relay (4.6.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Partner {
    /// It stays this step: it planned to wait, or could not do what it planned.
    Stays,
    /// It is still waiting out the penalty of a collision: "Other robots cannot move until the
    /// collision is resolved" (4.6).
    Penalised,
    /// It moves away, or is busy with an action (a pick, a placement, a relay, a move of several
    /// steps).
    Busy,
}

/// Whether a loaded and an unloaded robot relay when one wants the other's module and the other
/// is `partner`: "When two robots collide with each other, the one carrying the module hands it
/// off to the other" (4.6.1). A robot waiting out a penalty is still in its collision, so it may
/// relay, unless only robots that planned this step may ([`RelayWith::Idle`]).
pub fn relays(partner: Partner, rule: RelayWith) -> bool {
    match (partner, rule) {
        (Partner::Stays, _) => true,
        (Partner::Penalised, RelayWith::Waiting) => true,
        (Partner::Penalised, RelayWith::Idle) | (Partner::Busy, _) => false,
    }
}

/// Why a robot could not do what it planned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Conflict {
    /// A robot with a larger token claimed the same cell (a module, a vacant site, a module to
    /// remove) first.
    Claimed,
    /// The robot on the module it wants stays there. `ahead_gives_way`: that robot gives way,
    /// or waits, directly or through others, on a robot that does: the queue must make room
    /// for it to step aside.
    Occupied { ahead_gives_way: bool },
    /// Locked: the robot on the module it wants wants this robot's module, directly (head-on)
    /// or round a ring of robots each wanting the next one's module. Waiting alone would hold
    /// both for good. `ahead_larger`: that robot holds the larger token.
    Locked { ahead_larger: bool },
}

/// What the robot does about it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// Keeps its course and waits, without penalty: the larger token of a lock, which the other
    /// resolves by stepping aside.
    Keeps,
    /// Pays the penalty, then plans again.
    Waits,
    /// Pays the penalty, then steps to the best module no robot stands on at its next plan.
    GivesWay,
}

/// The outcome of `conflict` under the rule of who gives way: the robots a lock holds (the
/// smaller tokens of the ring, and the robots queued behind one of them), or every loser.
pub fn outcome(conflict: Conflict, rule: GiveWay) -> Outcome {
    match (conflict, rule) {
        (
            Conflict::Locked {
                ahead_larger: false,
            },
            _,
        ) => Outcome::Keeps,
        (Conflict::Locked { ahead_larger: true }, _) => Outcome::GivesWay,
        (_, GiveWay::EveryLoser) => Outcome::GivesWay,
        (
            Conflict::Occupied {
                ahead_gives_way: true,
            },
            GiveWay::Locked,
        ) => Outcome::GivesWay,
        (_, GiveWay::Locked) => Outcome::Waits,
    }
}

/// The rule slot `collision`: what a robot that lost a collision does next, from what it knows
/// of the collision. Asked in the conflict phase (`conflicts.rs`) of every robot that could not
/// do what it planned, after module relay was settled; the paper's rule is [`outcome`].
pub struct CollisionRule;

/// Why a robot could not do what it planned, in words.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    Claimed,
    Occupied,
    Locked,
}

/// What a robot that lost a collision knows of it: the slot's input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Meeting {
    /// Why it could not do what it planned.
    pub conflict: Kind,
    /// For `occupied`: the robot in the way gives way, or waits on one that does.
    pub ahead_gives_way: bool,
    /// For `locked`: the robot in the way holds the larger token.
    pub ahead_larger: bool,
    /// The scenario's rule of who gives way (`locked` or `every_loser`).
    pub give_way: GiveWay,
    /// The robot carries a module.
    pub loaded: bool,
}

impl Meeting {
    /// What a robot carrying a module or not (`loaded`) knows of `conflict` under `give_way`.
    pub fn of(conflict: Conflict, give_way: GiveWay, loaded: bool) -> Meeting {
        let (kind, ahead_gives_way, ahead_larger) = match conflict {
            Conflict::Claimed => (Kind::Claimed, false, false),
            Conflict::Occupied { ahead_gives_way } => (Kind::Occupied, ahead_gives_way, false),
            Conflict::Locked { ahead_larger } => (Kind::Locked, false, ahead_larger),
        };
        Meeting {
            conflict: kind,
            ahead_gives_way,
            ahead_larger,
            give_way,
            loaded,
        }
    }

    /// The conflict it describes.
    fn conflict(&self) -> Conflict {
        match self.conflict {
            Kind::Claimed => Conflict::Claimed,
            Kind::Occupied => Conflict::Occupied {
                ahead_gives_way: self.ahead_gives_way,
            },
            Kind::Locked => Conflict::Locked {
                ahead_larger: self.ahead_larger,
            },
        }
    }
}

impl Slot for CollisionRule {
    type Input = Meeting;
    type Output = Outcome;
    const INFO: SlotInfo = SlotInfo {
        name: "collision",
        title: "AMAS: what a robot does after a collision (sections 4.6 and 5.1)",
        about: "Each robot that could not do what it planned (a larger token claimed the cell first, a robot stands on the module it wants, or two robots want each other's modules) decides what it does next: keep its course without penalty, pay the penalty and plan again, or pay the penalty and step aside to the best free module at its next plan. Module relay is settled before: a loaded and an unloaded robot that meet swap loads instead of colliding.",
        input: &[
            Field {
                name: "conflict",
                kind: "string",
                about: "why it could not do what it planned: \"claimed\" (a larger token claimed the cell first), \"occupied\" (a robot stays on the module it wants) or \"locked\" (the robot in the way wants its module, directly or round a ring)",
            },
            Field {
                name: "ahead_gives_way",
                kind: "bool",
                about: "for \"occupied\": the robot in the way gives way, or waits on one that does, so the queue must make room",
            },
            Field {
                name: "ahead_larger",
                kind: "bool",
                about: "for \"locked\": the robot in the way holds the larger token",
            },
            Field {
                name: "give_way",
                kind: "string",
                about: "the scenario's rule of who gives way: \"locked\" (the robots a lock holds) or \"every_loser\"",
            },
            Field {
                name: "loaded",
                kind: "bool",
                about: "the robot carries a module",
            },
        ],
        output: "\"keeps\" (keeps its course and waits without penalty), \"waits\" (pays the penalty, then plans again) or \"gives_way\" (pays the penalty, then steps aside)",
        paper: include_str!("../rules/collision.rhai"),
        random: false,
    };

    #[inline]
    fn paper(meeting: &Meeting, _: Option<&mut Rng>) -> Outcome {
        outcome(meeting.conflict(), meeting.give_way)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_robots_a_lock_holds_give_way() {
        use Conflict::*;
        use Outcome::*;
        let occupied = |ahead_gives_way| Occupied { ahead_gives_way };
        for rule in [GiveWay::Locked, GiveWay::EveryLoser] {
            assert_eq!(
                outcome(
                    Locked {
                        ahead_larger: false
                    },
                    rule
                ),
                Keeps
            );
            assert_eq!(outcome(Locked { ahead_larger: true }, rule), GivesWay);
            assert_eq!(outcome(occupied(true), rule), GivesWay);
        }
        assert_eq!(outcome(Claimed, GiveWay::Locked), Waits);
        assert_eq!(outcome(occupied(false), GiveWay::Locked), Waits);
        assert_eq!(outcome(Claimed, GiveWay::EveryLoser), GivesWay);
        assert_eq!(outcome(occupied(false), GiveWay::EveryLoser), GivesWay);
    }

    #[test]
    fn a_robot_waiting_out_a_penalty_may_relay() {
        for rule in [RelayWith::Waiting, RelayWith::Idle] {
            assert!(relays(Partner::Stays, rule));
            assert!(!relays(Partner::Busy, rule));
        }
        assert!(relays(Partner::Penalised, RelayWith::Waiting));
        assert!(!relays(Partner::Penalised, RelayWith::Idle));
    }
}
