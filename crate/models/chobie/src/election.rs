//! Temporary leaders: who becomes leader after a transformation, and which lines it commands.
//!
//! - [`three_rule`]: the election of section 3.3 (figure 8) and its four leader kinds, rule 3
//!   asked of the slot `leader` ([`three_rule_with`]);
//! - [`row_end`] and [`corner`]: the second and third algorithms of section IV for forms (b)
//!   and (c), where the first elects nobody;
//! - [`adaptation`]: steps 2-6 of the load-adaptation algorithm of section 3.4;
//! - [`Elected::command`]: the lines each kind drives, in each mode.

use kumiki_model::slot::{Rule, Stop};

use super::leader::{self, Heard, Leader, Senses};
use super::motion::{Body, Drive, DOWN, LEFT, NONE, RIGHT, UP};
use super::signals::{kind, Comm};

/// Leader kinds. The first four are the combinations of the two signals a leader hears in the
/// three-rule election (vertical source, then horizontal source), in the order of the crawl's
/// forms 1 to 4, which is also the priority sequence of figure 18.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
#[repr(u8)]
pub enum Kind {
    TopRight = 0,
    TopLeft = 1,
    BottomLeft = 2,
    BottomRight = 3,
    /// Second algorithm: the left end of a row with nothing above or below.
    RowEnd = 4,
    /// Third algorithm: the upper-left corner of a block.
    Corner = 5,
    /// Load adaptation, step 3.
    Leader1 = 6,
    /// Load adaptation, step 5.
    Leader2 = 7,
}

impl Kind {
    pub const ALL: [Kind; 8] = [
        Kind::TopRight,
        Kind::TopLeft,
        Kind::BottomLeft,
        Kind::BottomRight,
        Kind::RowEnd,
        Kind::Corner,
        Kind::Leader1,
        Kind::Leader2,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::TopRight => "leader: top + right",
            Kind::TopLeft => "leader: top + left",
            Kind::BottomLeft => "leader: bottom + left",
            Kind::BottomRight => "leader: bottom + right",
            Kind::RowEnd => "leader: row end (2nd algorithm)",
            Kind::Corner => "leader: corner (3rd algorithm)",
            Kind::Leader1 => "leader 1 (load adaptation)",
            Kind::Leader2 => "leader 2 (load adaptation)",
        }
    }

    pub fn color(self) -> &'static str {
        match self {
            Kind::TopRight => "#d9822b",
            Kind::TopLeft => "#c23030",
            Kind::BottomLeft => "#7157d9",
            Kind::BottomRight => "#0d8050",
            Kind::RowEnd => "#8f398f",
            Kind::Corner => "#2965cc",
            Kind::Leader1 => "#a82a2a",
            Kind::Leader2 => "#a66321",
        }
    }
}

/// What the leaders command: the crawl's forms, the bridge's construction mode, or its
/// load-adaptation mode (figure 12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Mode {
    Crawl = 0,
    Construction = 1,
    Adaptation = 2,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Elected {
    pub robot: u32,
    pub kind: Kind,
}

/// The three-rule election of section 3.3, in two slots, with the paper's rule 3.
pub fn three_rule(body: &Body, comm: &mut Comm) -> Vec<Elected> {
    let paper = Rule::paper();
    three_rule_with(body, comm, &paper, Mode::Crawl).expect("the paper's rule never stops")
}

/// The three-rule election of section 3.3, in two slots, rule 3 decided by `rule` (the slot
/// `leader`, [`super::leader`]):
/// 1. every robot signals in all four directions;
/// 2. a robot that heard from top or bottom stops signalling left and right;
/// 3. a robot that heard from a vertical and a horizontal direction is the leader.
///
/// In the paper's rule the vertical source is named top when it heard from top, the horizontal
/// one right when it heard from right (a robot hearing both ways picks those). A script in the
/// slot that goes past a cap stops the election.
pub fn three_rule_with(
    body: &Body,
    comm: &mut Comm,
    rule: &Rule<Leader>,
    mode: Mode,
) -> Result<Vec<Elected>, Stop> {
    all_directions(body, comm);
    comm.slot(RULE_2);
    let vertical = |r: u32| body.has(r, UP) || body.has(r, DOWN);
    for r in 0..body.len() as u32 {
        if !vertical(r) {
            let faces = [LEFT, RIGHT]
                .iter()
                .filter(|&&d| body.has(r, d))
                .fold(0u8, |m, &d| m | 1 << d);
            comm.send_toward(body, r, faces, kind::ELECTION);
        }
    }
    let mode = leader::mode_name(mode);
    let mut out = Vec::new();
    for r in 0..body.len() as u32 {
        let hears = |d: usize| {
            let n = body.nbr(r, d);
            n != NONE && !vertical(n)
        };
        let senses = Senses {
            first: Heard {
                right: body.has(r, RIGHT),
                up: body.has(r, UP),
                left: body.has(r, LEFT),
                down: body.has(r, DOWN),
            },
            second: Heard {
                right: hears(RIGHT),
                left: hears(LEFT),
                ..Heard::default()
            },
            mode,
        };
        if let Some(form) = rule.decide(&senses, None)? {
            out.push(Elected {
                robot: r,
                kind: form.kind(),
            });
        }
    }
    Ok(out)
}

/// The meanings of the election's slots, as the page shows them.
pub const RULE_1: &str = "election, rule 1: every robot signals in all four directions";
pub const RULE_2: &str =
    "election, rule 2: robots that heard from top or bottom fall silent; the others signal left and right";

/// Slot 1 of every election: each robot lights all four faces.
pub fn all_directions(body: &Body, comm: &mut Comm) {
    comm.slot(RULE_1);
    for r in 0..body.len() as u32 {
        comm.send(body, r, body.degree(r) as u64, kind::ELECTION);
    }
}

/// Second algorithm (form (b)): after one all-directions slot, a robot that heard only from its
/// right is the left end of a lone row and becomes leader.
pub fn row_end(body: &Body) -> Vec<Elected> {
    (0..body.len() as u32)
        .filter(|&r| body.has(r, RIGHT) && body.degree(r) == 1)
        .map(|robot| Elected {
            robot,
            kind: Kind::RowEnd,
        })
        .collect()
}

/// Third algorithm (form (c)): after one all-directions slot, a robot that heard from exactly
/// bottom and right is an upper-left corner and becomes leader.
pub fn corner(body: &Body) -> Vec<Elected> {
    (0..body.len() as u32)
        .filter(|&r| body.has(r, RIGHT) && body.has(r, DOWN) && body.degree(r) == 2)
        .map(|robot| Elected {
            robot,
            kind: Kind::Corner,
        })
        .collect()
}

/// Steps 2-6 of the load-adaptation algorithm (step 1, the overload signal, is the mode slot):
/// 2. a robot on the right edge (no robot to its right) sends a signal to bottom;
/// 3. an overloaded robot that receives from top becomes leader 1, unless a robot or the terrain
///    is under it (it is thick there already);
/// 4. otherwise it sends a signal to left;
/// 5. a robot receiving from right that also receives from top becomes leader 2;
/// 6. otherwise it passes the signal on to its left.
///
/// Two slots: the right-edge signal, then the leftward relay.
pub fn adaptation(body: &Body, overloaded: &[bool], comm: &mut Comm) -> Vec<Elected> {
    comm.slot("load adaptation, step 2: each robot on the right edge signals to bottom");
    let from_top = |r: u32| {
        let t = body.nbr(r, UP);
        t != NONE && !body.has(t, RIGHT)
    };
    for r in 0..body.len() as u32 {
        if !body.has(r, RIGHT) && body.has(r, DOWN) {
            comm.send_toward(body, r, 1 << DOWN, kind::CHAIN);
        }
    }
    comm.slot("load adaptation, steps 3-6: overloaded robots relay the signal left to leader 2");
    let mut out = Vec::new();
    let mut leader2 = vec![false; body.len()];
    for r in 0..body.len() as u32 {
        if !overloaded[r as usize] {
            continue;
        }
        if from_top(r) {
            // Step 7 takes the leader under the tier. A robot with a robot or the terrain
            // under it is thick there already; its overload is at its joint with the single
            // tier beside it, which the relay of its neighbour there brings the reserves to.
            if !body.has(r, DOWN) && !body.grounded(r) {
                out.push(Elected {
                    robot: r,
                    kind: Kind::Leader1,
                });
            }
            continue;
        }
        let mut cur = r;
        loop {
            let left = body.nbr(cur, LEFT);
            if left == NONE {
                break;
            }
            comm.send_toward(body, cur, 1 << LEFT, kind::CHAIN);
            if from_top(left) {
                leader2[left as usize] = true;
                break;
            }
            cur = left;
        }
    }
    out.extend(
        (0..body.len() as u32)
            .filter(|&r| leader2[r as usize])
            .map(|robot| Elected {
                robot,
                kind: Kind::Leader2,
            }),
    );
    out
}

impl Elected {
    /// The lines this leader drives in `mode`, and the hops from the leader to the first of
    /// them (the route slot). Empty when the kind has no command in this mode.
    pub fn command(&self, body: &Body, mode: Mode) -> (Vec<Drive>, u64) {
        let r = self.robot;
        let line = |robot: u32, dir: usize| Drive {
            robots: body.line(robot, dir),
            dir,
        };
        let near = |d: usize| body.nbr(r, d);
        match (mode, self.kind) {
            (Mode::Crawl, Kind::TopRight) => (vec![line(near(UP), RIGHT)], 1),
            (Mode::Crawl, Kind::TopLeft) => (vec![line(near(LEFT), UP)], 1),
            (Mode::Crawl, Kind::BottomLeft) => (vec![line(r, RIGHT)], 0),
            (Mode::Crawl, Kind::BottomRight) => (vec![line(near(RIGHT), DOWN)], 1),
            (Mode::Crawl, Kind::RowEnd | Kind::Corner) => (vec![line(r, RIGHT)], 0),
            // Construction: every leader of the three rules stands on the lower tier and drives
            // it right on the base; the robots resting on it stay where they are (the cycle adds
            // the top neighbour's line when the tier cannot move without it).
            (
                Mode::Construction,
                Kind::TopRight | Kind::TopLeft | Kind::BottomRight | Kind::BottomLeft,
            ) => (vec![line(r, RIGHT)], 0),
            // Step 7: two drive commands, its own column down and its right neighbour's up;
            // the cycle treats them as two orders (each dropped if it cannot be made).
            (Mode::Adaptation, Kind::Leader1) => {
                let mut drives = vec![line(r, DOWN)];
                if near(RIGHT) != NONE {
                    drives.push(line(near(RIGHT), UP));
                }
                (drives, 0)
            }
            (Mode::Adaptation, Kind::Leader2) => (vec![line(near(UP), RIGHT)], 1),
            _ => (Vec::new(), 0),
        }
    }
}
