//! Step phase 2: diffusion, irritation and activation (equations 2 to 5).

use kumiki_model::slot::Stop;

use super::activation::Senses;
use super::*;

impl Fracta {
    /// Equations 2, 4 and 5 for every working unit at once, then the activation rule
    /// (equation 3, or irritation for movable units: the slot `activation`). Fills `active`,
    /// noting which units irritation activated. A script in the slot that stops ends the phase
    /// where it stopped.
    pub(super) fn diffuse(&mut self) -> Result<(), Stop> {
        let t = types();
        let p = self.p;
        self.active.clear();
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            let unit = self.units[u];
            let mut flux = 0.0;
            for &j in &self.nbr[unit.cell as usize] {
                if j != NO_UNIT {
                    let v = self.occ[j as usize];
                    if v != NO_UNIT {
                        flux += self.units[v as usize].x - unit.x;
                    }
                }
            }
            let movable = t.info[self.class[u] as usize].movable;
            let dx = p.k * flux - if movable { p.l } else { 0.0 };
            let mut x = (unit.x + dx).max(0.0);
            let diff = f64::from(self.diff[u]);
            let mut irr = unit.irr;
            let mut fired = false;
            // Irritation "increases during deadlock state" (section 3.2 (i)): while x is stable
            // (equation 4) and the unit's own difference is what it was a step before. A unit
            // whose difference changed is not stuck: the structure around it has just changed
            // (interpretation 9).
            let still = self.last_diff[u] == self.diff[u];
            self.last_diff[u] = self.diff[u];
            if dx.abs() < p.stable && still {
                irr += flux.abs().max((diff - unit.x).abs());
            }
            if irr > p.i_th {
                x += p.gain * (diff - unit.x).max(0.0);
                irr = 0.0;
                fired = true;
                self.irritations += 1;
                self.events.push(Event {
                    cell: unit.cell,
                    kind: event::IRRITATED,
                });
            }
            self.units[u].irr = irr;
            self.new_x[u] = x;
            if movable {
                let senses = Senses {
                    x: unit.x,
                    difference: self.diff[u],
                    flux,
                    threshold: p.g,
                    irritated: fired,
                };
                if self.activation.decide(&senses, None)? {
                    self.active.push((u as u32, fired));
                }
            }
        }
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            self.units[u].x = self.new_x[u];
        }
        Ok(())
    }
}
