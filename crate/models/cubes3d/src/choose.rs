//! The first phase of a step (sections 4 to 6): each unit's options (its reachable positions,
//! with the light's priority) and temperature, its choice by the selection rule, and the one
//! (or few, far apart) that move.

use super::connect::Scratch;
use super::select::{Position, Select};
use super::spec::{Clock, Log, Priority, Selection};
use super::Cubes;
use kumiki_model::math;
use kumiki_model::slot::{Slot, Stop};

impl Cubes {
    /// Is `c` at least `mover_distance` (Manhattan) from every unit that moved this step?
    pub(super) fn far_from_movers(&self, c: usize) -> bool {
        let cc = self.st.coord(c);
        self.arrived.iter().all(|&o| {
            let oc = self.st.coord(o as usize);
            let dist: i32 = (0..3).map(|k| (cc[k] - oc[k]).abs()).sum();
            dist >= self.mover_distance as i32
        })
    }

    /// One control step's moves (section 5): every unit makes its choice, and of those that
    /// choose to move, one moves (up to `movers` with footnote 2, each at least
    /// `mover_distance` from the others). Asking the units in a random order and letting the
    /// first that chooses to move go gives each of them the same chance as drawing among all
    /// that chose to move, and asks only as many as needed. With a light and the priority on
    /// units (model version 4 and before), a unit whose choice approaches the source goes
    /// before one whose choice does not. A script in the slot `select` that stops ends the
    /// step's moves where it stopped.
    pub(super) fn move_units(&mut self, s: &mut Scratch) -> Result<(), Stop> {
        let mut order = std::mem::take(&mut self.order);
        order.clear();
        order.extend_from_slice(&self.movable);
        self.arrived.clear();
        self.deferred.clear();
        let on_units = self.light.is_some() && self.priority == Priority::Units;
        let chosen = self.choose_moves(&mut order, on_units, s);
        self.order = order;
        chosen?;
        if on_units {
            self.move_deferred(s);
        }
        Ok(())
    }

    /// The units of `order` asked in a random order, each moving where it chooses, until
    /// `movers` have moved.
    fn choose_moves(
        &mut self,
        order: &mut [u32],
        on_units: bool,
        s: &mut Scratch,
    ) -> Result<(), Stop> {
        let want = self.movers as usize;
        let n = order.len();
        for k in 0..n {
            if self.arrived.len() == want {
                break;
            }
            let j = k + self.rng.index(n - k);
            order.swap(k, j);
            let p = order[k] as usize;
            if !self.eligible(p) || !self.far_from_movers(p) {
                continue;
            }
            let Some(dest) = self.decide(p, s)? else {
                continue;
            };
            if on_units && self.along_light(dest) <= self.along_light(p) {
                self.deferred.push((p as u32, dest as u32));
                continue;
            }
            self.do_move(p, dest);
            self.arrived.push(dest as u32);
        }
        Ok(())
    }

    /// The priority on units (model version 4 and before): the moves chosen this step that do
    /// not approach the light, while movers are still wanted.
    fn move_deferred(&mut self, s: &mut Scratch) {
        let want = self.movers as usize;
        let mut deferred = std::mem::take(&mut self.deferred);
        for &(p, dest) in &deferred {
            if self.arrived.len() == want {
                break;
            }
            let (p, dest) = (p as usize, dest as usize);
            if !self.eligible(p) || !self.far_from_movers(p) {
                continue;
            }
            // An earlier move of this step may have changed what this unit can reach.
            self.st.reachable(p, s);
            if s.moves.iter().any(|m| m.dest as usize == dest) {
                self.do_move(p, dest);
                self.arrived.push(dest as u32);
            }
        }
        deferred.clear();
        self.deferred = deferred;
    }

    /// The temperature T of equation 8 for the unit at `p`: C / log(1 + t), t the control step
    /// being taken counted on the run's clock or from the unit's last switch of target.
    pub(super) fn temperature(&self, p: usize) -> f64 {
        match self.steps_on_target(p) {
            t if t == self.steps => self.run_temperature,
            t => self.temperature_at(t + 1),
        }
    }

    /// C / log(1 + t) with the scenario's logarithm.
    pub(super) fn temperature_at(&self, t: u64) -> f64 {
        let c = match self.log {
            Log::Natural => self.c,
            Log::Ten => self.c * std::f64::consts::LN_10,
        };
        c / math::ln_1p(t as f64)
    }

    /// Control steps the unit at `p` has worked toward its target before this one, on the clock
    /// the scenario chose.
    fn steps_on_target(&self, p: usize) -> u64 {
        match self.clock {
            Clock::Run => self.steps,
            Clock::Target => self.steps - self.took[self.upos[p] as usize],
        }
    }

    /// Steps (i) to (iii) of section 4 for the unit at `p`: its reachable positions, their
    /// differences, and its choice by the selection rule (the slot `select`, `select.rs`),
    /// `None` for staying where it is. Its options are "no motion" (i = 0, D_0) and its
    /// reachable positions; with a light and the priority on positions, only the reachable
    /// positions that approach the light when it has any (section 6). Random selection leaves
    /// "no motion" out when `random_stays` is false (model version 4 and before).
    pub(super) fn decide(&mut self, p: usize, s: &mut Scratch) -> Result<Option<usize>, Stop> {
        self.st.reachable(p, s);
        if s.moves.is_empty() {
            return Ok(None);
        }
        self.senses.options.clear();
        let target = self.target[p];
        if self.selection != Selection::Random || self.random_stays {
            let difference = self.d0(p);
            self.senses.options.push(Position {
                cell: p as u32,
                difference,
                stay: true,
            });
        }
        let here = self.along_light(p);
        let ahead = self.light.is_some()
            && self.priority == Priority::Positions
            && s.moves
                .iter()
                .any(|m| self.along_light(m.dest as usize) > here);
        for m in &s.moves {
            if ahead && self.along_light(m.dest as usize) <= here {
                continue;
            }
            let profile = self.st.profile_after(p, m.dest as usize);
            let difference = self.difference(target, &profile);
            self.senses.options.push(Position {
                cell: m.dest,
                difference,
                stay: false,
            });
        }
        let (temperature, t) = (self.temperature(p), self.steps_on_target(p));
        let unit = &mut self.senses;
        unit.selection = self.selection;
        unit.temperature = temperature;
        unit.t = t;
        let pick = self.select.decide(unit, Some(&mut self.rng));
        let options = &self.senses.options;
        let cell = pick.and_then(|i| match options.get(i) {
            Some(o) => Ok(o.cell),
            None => Err(Stop(format!(
                "rule '{}' answered {i}; it must answer an index of its {} options (0 to {})",
                Select::INFO.name,
                options.len(),
                options.len() - 1
            ))),
        });
        match cell? {
            c if c == p as u32 => Ok(None),
            c => Ok(Some(c as usize)),
        }
    }
}
