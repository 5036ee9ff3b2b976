//! One step is one transformation cycle (figures 6 and 12):
//! 1. (bridge) each robot checks its load; an overload is announced in the first slot and every
//!    robot switches to load-adaptation mode, otherwise to construction mode;
//! 2. the leader is elected (or, in the baseline, the permanent leader gathers the map);
//! 3. the leader announces itself, then sends the drive command in three slots: route, which
//!    robots drive, direction;
//! 4. the driving lines move one cell if the motion constraints allow it;
//! 5. the driven robots send the completion signal that resynchronises everyone;
//! 6. the stress of the new configuration is solved.

use kumiki_model::slot::Stop;

use super::election::{self, Elected, Kind, Mode};
use super::frame;
use super::motion::{Drive, RIGHT, UP};
use super::signals::{self, kind, Comm};
use super::spec::{Leader, Method, Task};
use super::Failure;

/// An order: the leader, the lines it drives, and the hops from it to the first line.
type Order = (u32, Vec<Drive>, u64);
use super::{Chobie, Last};

impl Chobie {
    /// One transformation; a script in the slot `leader` that goes past a cap stops it after
    /// the load check, before anything moves.
    pub(super) fn cycle(&mut self) -> Result<(), Stop> {
        let mut comm = Comm::default();
        if self.p.task == Task::Bridge {
            let overloaded: Vec<u32> = self.overloaded_robots();
            comm.flood(
                &self.body,
                &overloaded,
                kind::OVERLOAD,
                "mode: a robot over its threshold announces an overload",
            );
            let mode = if self.p.adaptation && !overloaded.is_empty() {
                Mode::Adaptation
            } else {
                Mode::Construction
            };
            if self.mode == Mode::Adaptation && mode == Mode::Construction {
                self.resumed += 1;
            }
            self.mode = mode;
        }
        let idle = (self.mode == Mode::Construction && !self.p.construction)
            || self.failure != Failure::Standing;
        let leaders = match self.p.leader {
            _ if idle => Vec::new(),
            Leader::Temporary => self.elect(&mut comm)?,
            Leader::Permanent => self.direct(&mut comm)?,
        };
        let (orders, step7) = self.orders(&leaders);
        if self.p.leader == Leader::Temporary && !orders.is_empty() {
            self.send_commands(&mut comm, &orders);
        }
        let drives: Vec<Drive> = orders.into_iter().flat_map(|o| o.1).collect();
        let mut last = Last {
            leaders,
            ..Last::default()
        };
        if self.p.leader == Leader::Permanent && !drives.is_empty() {
            self.broadcast_command(&mut comm, &drives);
        }
        if !drives.is_empty() {
            match self.body.check(&drives) {
                Ok(moving) => {
                    self.body.apply(&moving);
                    self.totals.transformations += 1;
                    self.totals.energy += moving.len() as u64;
                    if self.mode == Mode::Adaptation {
                        self.totals.adaptations += 1;
                    }
                    if step7 {
                        self.totals.reinforcements += 1;
                    }
                    last.driven = moving.iter().map(|m| m.0).collect();
                    last.moved = true;
                    let senders = last.driven.clone();
                    comm.flood(
                        &self.body,
                        &senders,
                        kind::ANNOUNCE,
                        "completion: the robots that moved signal the end of the move",
                    );
                }
                Err(_) => self.totals.refused += 1,
            }
        } else if !last.leaders.is_empty() {
            self.totals.refused += 1;
        }
        self.totals.slots += comm.slots;
        self.totals.messages += comm.messages;
        last.slots = comm.slots;
        last.messages = comm.messages;
        last.signals = comm.signals;
        last.trace = comm.trace;
        self.last = last;
        self.solve();
        Ok(())
    }

    /// The orders the leaders send: (leader, lines, route hops). In construction, a leader whose tier cannot slide alone (the robots
    /// resting on it would be left behind) drives its top neighbour's line with it. If all
    /// orders can be made together they are; otherwise an order that cannot be carried out on
    /// its own is dropped (its lines stay locked) and the rest must be feasible together.
    /// The flag says whether a leader 1's order (step 7 of section 3.4) is among them.
    fn orders(&self, leaders: &[Elected]) -> (Vec<Order>, bool) {
        let body = &self.body;
        let mut orders: Vec<(Kind, Order)> = Vec::new();
        for e in leaders {
            let (mut lines, route) = e.command(body, self.mode);
            if lines.is_empty() {
                continue;
            }
            if self.mode == Mode::Construction && body.check(&lines).is_err() {
                let top = body.nbr(e.robot, UP);
                if top != super::motion::NONE {
                    lines.push(Drive {
                        robots: body.line(top, RIGHT),
                        dir: RIGHT,
                    });
                }
            }
            // Step 7: its column slides down against its right neighbour's, which rises with
            // it where it can; where the two cannot move together, the leader's own column
            // drives alone (the neighbour holds), or failing that the neighbour's rises alone.
            if e.kind == Kind::Leader1 && lines.len() == 2 && body.check(&lines).is_err() {
                if let Some(one) = lines
                    .iter()
                    .find(|l| body.check(std::slice::from_ref(*l)).is_ok())
                {
                    lines = vec![one.clone()];
                }
            }
            orders.push((e.kind, (e.robot, lines, route)));
        }
        let joint = |orders: &[(Kind, Order)]| {
            let all: Vec<Drive> = orders.iter().flat_map(|o| o.1 .1.iter().cloned()).collect();
            body.check(&all).is_ok()
        };
        if orders.len() > 1 && !joint(&orders) {
            orders.retain(|o| body.check(&o.1 .1).is_ok());
            // Step 3 "then go to step 7": where leader 1's commands and leader 2's cannot be
            // made together, leader 1's go first.
            if !joint(&orders) && orders.iter().any(|o| o.0 == Kind::Leader1) {
                orders.retain(|o| o.0 == Kind::Leader1);
            }
        }
        let step7 = orders.iter().any(|o| o.0 == Kind::Leader1);
        (orders.into_iter().map(|o| o.1).collect(), step7)
    }

    /// The temporary-leader election with the selected method and priority sequence.
    fn elect(&mut self, comm: &mut Comm) -> Result<Vec<Elected>, Stop> {
        let body = &self.body;
        let (rule, mode) = (&self.leader, self.mode);
        let three_rule = |body, comm: &mut Comm| election::three_rule_with(body, comm, rule, mode);
        let leaders = match self.mode {
            Mode::Adaptation => {
                let over: Vec<bool> = self.stress.iter().map(|&s| self.overloaded(s)).collect();
                election::adaptation(body, &over, comm)
            }
            Mode::Construction => three_rule(body, comm)?,
            Mode::Crawl => {
                match self.p.method {
                    Method::First => three_rule(body, comm)?,
                    Method::TrialAndError => {
                        let first = three_rule(body, comm)?;
                        if !first.is_empty() {
                            first
                        } else {
                            self.totals.election_failures += 1;
                            comm.slot("trial and error: no leader; every robot starts the second algorithm");
                            election::all_directions(body, comm);
                            let second = election::row_end(body);
                            if !second.is_empty() {
                                second
                            } else {
                                self.totals.election_failures += 1;
                                comm.slot("trial and error: no leader; every robot starts the third algorithm");
                                election::all_directions(body, comm);
                                election::corner(body)
                            }
                        }
                    }
                    Method::Cautious => {
                        // The first two slots give every robot its neighbours and the rule-2
                        // signals; then one slot per algorithm, in order, until one has a leader.
                        let first = three_rule(body, comm)?;
                        let tries = [first, election::row_end(body), election::corner(body)];
                        let found = tries.iter().position(|t| !t.is_empty());
                        let checks = found.map_or(tries.len(), |i| i + 1);
                        for _ in 1..checks {
                            comm.slot("cautious: the next algorithm's leader test");
                        }
                        found.map(|i| tries[i].clone()).unwrap_or_default()
                    }
                }
            }
        };
        let leaders = self.announce(comm, leaders);
        if leaders.is_empty() {
            self.totals.election_failures += 1;
        }
        Ok(leaders)
    }

    /// The announcement slot; with the priority sequence (figure 18) one slot per kind, in
    /// order, until a kind is present, and only that kind commands.
    fn announce(&self, comm: &mut Comm, mut leaders: Vec<Elected>) -> Vec<Elected> {
        if self.p.priority && self.mode == Mode::Crawl {
            let best = leaders
                .iter()
                .map(|e| e.kind)
                .min_by_key(|&k| self.p.rank(k));
            let order = self.p.order;
            let silent = best.map_or(order.len(), |k| {
                order.iter().position(|&o| o == k).unwrap_or(0)
            });
            for _ in 0..silent {
                comm.slot("priority sequence: no leader of this kind");
            }
            leaders.retain(|e| Some(e.kind) == best);
        }
        let origins: Vec<u32> = leaders.iter().map(|e| e.robot).collect();
        comm.flood(
            &self.body,
            &origins,
            kind::ANNOUNCE,
            "announcement: the leaders make themselves known",
        );
        leaders
    }

    /// The drive command in three slots shared by all leaders: the route from each leader to
    /// its first line, a signal along every driven line (which robots drive), and again along
    /// the lines driven right or up (the direction slot: a signal means right or up, silence
    /// left or down).
    fn send_commands(&self, comm: &mut Comm, orders: &[(u32, Vec<Drive>, u64)]) {
        let body = &self.body;
        comm.slot("command, route: each leader signals the way to its first line");
        for (leader, _, route) in orders {
            comm.send_along(body, *leader, *route, kind::COMMAND);
        }
        comm.slot("command, drive: a signal runs along every line that drives");
        for line in orders.iter().flat_map(|o| &o.1) {
            comm.send_along(
                body,
                line.robots[0],
                line.robots.len() as u64,
                kind::COMMAND,
            );
        }
        comm.slot(
            "command, direction: a signal along a line means right or up, silence left or down",
        );
        for line in orders.iter().flat_map(|o| &o.1) {
            if matches!(line.dir, RIGHT | UP) {
                comm.send_along(
                    body,
                    line.robots[0],
                    line.robots.len() as u64,
                    kind::COMMAND,
                );
            }
        }
    }

    /// The baseline: a permanent leader with global information. Every robot reports its cell
    /// to it (2·⌈log₂ side⌉ bits, each ON bit a message per hop, relayed through the leader's
    /// faces), and it picks the command with the same rules (and the priority sequence), free
    /// of election slots.
    fn direct(&mut self, comm: &mut Comm) -> Result<Vec<Elected>, Stop> {
        let body = &self.body;
        let side = body.w.max(body.h).max(2);
        let bits = 2 * (32 - (side - 1).leading_zeros()) as u64;
        let hops = signals::hops(body, self.permanent);
        let mut sent = 0u64;
        for r in 0..body.len() as u32 {
            let (x, y) = body.pos[r as usize];
            let ones = (x as u32).count_ones() + (y as u32).count_ones();
            sent += ones as u64 * hops[r as usize] as u64;
        }
        let faces = body.degree(self.permanent).max(1) as u64;
        let gather = ((body.len() as u64 - 1) * bits).div_ceil(faces).max(1);
        comm.open(
            gather,
            "baseline: every robot reports its cell to the permanent leader, bit by bit",
        );
        comm.send_along(body, self.permanent, sent, kind::GATHER);
        let mut scratch = Comm::default();
        let (rule, mode) = (&self.leader, self.mode);
        let three_rule = |body, comm: &mut Comm| election::three_rule_with(body, comm, rule, mode);
        let mut leaders = match self.mode {
            Mode::Adaptation => {
                let over: Vec<bool> = self.stress.iter().map(|&s| self.overloaded(s)).collect();
                election::adaptation(body, &over, &mut scratch)
            }
            Mode::Construction => three_rule(body, &mut scratch)?,
            Mode::Crawl => {
                let mut all = three_rule(body, &mut scratch)?;
                if all.is_empty() {
                    all = election::row_end(body);
                }
                if all.is_empty() {
                    all = election::corner(body);
                }
                let best = all.iter().map(|e| e.kind).min_by_key(|&k| self.p.rank(k));
                all.retain(|e| Some(e.kind) == best);
                all
            }
        };
        if leaders.is_empty() {
            self.totals.election_failures += 1;
        }
        kumiki_model::sort::sort_by_key(&mut leaders, |e| (e.kind, e.robot));
        Ok(leaders)
    }

    /// The baseline's command: the ids of the driving robots (⌈log₂ n⌉ bits each) and a
    /// direction bit, flooded bit by bit from the permanent leader.
    fn broadcast_command(&self, comm: &mut Comm, drives: &[Drive]) {
        let body = &self.body;
        let n = body.len().max(2) as u32;
        let id_bits = (32 - (n - 1).leading_zeros()) as u64;
        let robots: u64 = drives.iter().map(|d| d.robots.len() as u64).sum();
        comm.open(
            robots * id_bits + 1,
            "baseline: the permanent leader floods the driving robots' ids and the direction",
        );
        let flood: u64 = (0..body.len() as u32).map(|r| body.degree(r) as u64).sum();
        let ones: u64 = drives
            .iter()
            .flat_map(|d| d.robots.iter())
            .map(|&r| r.count_ones() as u64)
            .sum::<u64>()
            + drives
                .first()
                .map_or(0, |d| matches!(d.dir, RIGHT | UP) as u64);
        comm.send_along(body, self.permanent, ones * flood, kind::COMMAND);
    }

    pub(super) fn overloaded(&self, stress: f64) -> bool {
        stress > self.p.mech.threshold
    }

    fn overloaded_robots(&self) -> Vec<u32> {
        (0..self.body.len() as u32)
            .filter(|&r| self.overloaded(self.stress[r as usize]))
            .collect()
    }

    /// The robot the tip load acts on: the rightmost robot, the lowest of them (the bridge's
    /// free end; robots that load adaptation puts under the root stay off it).
    pub(super) fn tip(&self) -> u32 {
        (0..self.body.len() as u32)
            .max_by_key(|&r| self.body.pos[r as usize])
            .unwrap_or(0)
    }

    /// Solves the frame for the present configuration and loads.
    pub(super) fn solve(&mut self) {
        let body = &self.body;
        let m = &self.p.mech;
        let elems = frame::elements(&body.pos, &|x, y| {
            let r = body.robot_at(x, y);
            (r != super::motion::NONE).then_some(r)
        });
        let fixed: Vec<bool> = (0..body.len() as u32).map(|r| body.grounded(r)).collect();
        // A robot with terrain against its left face (under the root, against the cliff) is
        // held by it when pressed against it.
        let walls: Vec<bool> = (0..body.len() as u32)
            .map(|r| {
                let (x, y) = body.pos[r as usize];
                body.ground_at(x - 1, y)
            })
            .collect();
        let tip = self.tip();
        let loads: Vec<[f64; 3]> = (0..body.len())
            .map(|r| {
                let tip_load = if r as u32 == tip {
                    self.p.tip_load
                } else {
                    0.0
                };
                [0.0, -(m.weight + self.loads[r] + tip_load), 0.0]
            })
            .collect();
        let band = &mut self.band;
        match frame::solve_against(m, &body.pos, &elems, &fixed, &walls, &loads, band) {
            Some(sol) => {
                self.stress = sol.stress;
                self.disp = sol.disp;
            }
            None => {
                self.stress = vec![f64::INFINITY; body.len()];
                self.disp = vec![[0.0; 3]; body.len()];
            }
        }
        self.worst = self.worst.max(self.peak());
        if self.failure == Failure::Standing {
            if self.peak() > self.p.mech.strength {
                self.failure = Failure::Broken;
            } else if !self.p.anchored && self.overturning() > 0.0 {
                self.failure = Failure::Tipped;
            }
        }
    }

    /// The moment of the robots' weights and the loads about the cliff edge (the top corner of
    /// the last terrain cell under the structure), N·m, positive when it turns the structure
    /// over the edge. Only meaningful when the base does not hold the robots (`anchored` off):
    /// then the terrain can push but not pull, and a positive moment tips the structure.
    pub(super) fn overturning(&self) -> f64 {
        let m = &self.p.mech;
        let pivot = self.edge as f64 + 0.5;
        let tip = self.tip();
        (0..self.body.len())
            .map(|r| {
                let tip_load = if r as u32 == tip {
                    self.p.tip_load
                } else {
                    0.0
                };
                let force = m.weight + self.loads[r] + tip_load;
                force * (self.body.pos[r].0 as f64 - pivot) * m.length
            })
            .sum()
    }

    /// Robots above the row of the robots resting on the terrain: the bridge's reserves (the
    /// crawl's upper tier).
    pub(super) fn reserves(&self) -> usize {
        let body = &self.body;
        let tier = (0..body.len() as u32)
            .filter(|&r| body.grounded(r))
            .map(|r| body.pos[r as usize].1)
            .min()
            .unwrap_or(i32::MIN);
        body.pos.iter().filter(|p| p.1 < tier).count()
    }

    pub(super) fn peak(&self) -> f64 {
        self.stress.iter().copied().fold(0.0, f64::max)
    }

    /// Cells of the structure beyond the cliff edge.
    pub(super) fn span(&self) -> i64 {
        let right = self.body.pos.iter().map(|p| p.0).max().unwrap_or(0);
        (right - self.edge).max(0) as i64
    }

    pub(super) fn distance(&self) -> f64 {
        self.body.centre_x() - self.start_x
    }

    /// The slot length the structure needs: a round trip across it, in microseconds.
    pub(super) fn slot_us(&self) -> f64 {
        2.0 * signals::diameter(&self.body) as f64 * self.p.hop_us
    }

    /// The root stress beam theory gives a straight single-tier cantilever of the present span
    /// under the robots' weight (nodal, one per cell) and the tip load: M·c/I with
    /// M = w·a·n(n + 1)/2 + P·n·a. The mechanics experiment draws it over the frame's result.
    pub(super) fn beam_theory_stress(&self) -> f64 {
        let m = &self.p.mech;
        let n = self.span() as f64;
        let moment = m.weight * m.length * n * (n + 1.0) / 2.0 + self.p.tip_load * n * m.length;
        moment * m.fibre / m.inertia
    }
}
