//! The first phase of a step (sections 4 and 5): the units choose among their reachable
//! positions by the MRF rule or a baseline, and one (or a few, far apart) move.

use super::connect::Scratch;
use super::spec::Selection;
use super::Cubes;
use kumiki_model::math;

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
    /// that chose to move, and asks only as many as needed. With a light, a unit whose choice
    /// approaches the source goes before one whose choice does not (section 6: "a higher moving
    /// priority to reachable positions approaching the light source").
    pub(super) fn move_units(&mut self, temp: f64, s: &mut Scratch) {
        let mut order = std::mem::take(&mut self.order);
        order.clear();
        order.extend_from_slice(&self.movable);
        self.arrived.clear();
        self.deferred.clear();
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
            let Some(dest) = self.decide(p, temp, s) else {
                continue;
            };
            if self.light.is_some() && self.along_light(dest) <= self.along_light(p) {
                self.deferred.push((p as u32, dest as u32));
                continue;
            }
            self.do_move(p, dest);
            self.arrived.push(dest as u32);
        }
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
        self.order = order;
    }

    /// Steps (i) to (iii) of section 4 for the unit at `p`: its reachable positions, their
    /// differences, and its choice, `None` for staying where it is. The MRF weighs "no motion"
    /// (i = 0, D_0) and each reachable position by exp(-D_i / T) (section 4.2); steepest
    /// descent takes the option of least difference among the same ("always selected"), ties
    /// broken at random; random selection takes one of the reachable positions, each alike, so
    /// a unit that can move does.
    pub(super) fn decide(&mut self, p: usize, temp: f64, s: &mut Scratch) -> Option<usize> {
        self.st.reachable(p, s);
        if s.moves.is_empty() {
            return None;
        }
        let target = self.target[p];
        self.options.clear();
        if self.selection != Selection::Random {
            self.options.push((p as u32, self.d0(p)));
        }
        for m in &s.moves {
            let d = self.difference(target, &self.st.profile_after(p, m.dest as usize));
            self.options.push((m.dest, d));
        }
        let n = self.options.len();
        let least = self
            .options
            .iter()
            .map(|o| o.1)
            .fold(f64::INFINITY, f64::min);
        self.weights.clear();
        let pick = match self.selection {
            Selection::Mrf => {
                for o in &self.options {
                    self.weights.push(math::exp(-(o.1 - least) / temp));
                }
                self.rng.weighted(&self.weights).unwrap_or(0)
            }
            Selection::Random => self.rng.index(n),
            Selection::Steepest => {
                for o in &self.options {
                    self.weights.push(if o.1 == least { 1.0 } else { 0.0 });
                }
                self.rng.weighted(&self.weights).unwrap_or(0)
            }
        };
        let dest = self.options[pick].0 as usize;
        (dest != p).then_some(dest)
    }
}
