//! Where the light is (section 6): positions along it, and which units see it.

use super::motion::DIRS;
use super::Cubes;

impl Cubes {
    /// The component of a cell's position along the light (0 without light).
    pub(super) fn along_light(&self, i: usize) -> f64 {
        match self.light {
            None => 0.0,
            Some(d) => {
                let c = self.st.coord(i);
                let v = DIRS[d];
                f64::from(c[0] * v[0] + c[1] * v[1] + c[2] * v[2])
            }
        }
    }

    /// Centre of mass along the light.
    pub(super) fn light_position(&self) -> f64 {
        let n = self.units.len().max(1) as f64;
        self.units
            .iter()
            .map(|&c| self.along_light(c as usize))
            .sum::<f64>()
            / n
    }

    /// Does the unit at `i` see the light: no unit between it and the source?
    pub(super) fn lit(&self, i: usize) -> bool {
        let Some(d) = self.light else {
            return false;
        };
        let mut c = self.st.coord(i);
        loop {
            let v = DIRS[d];
            c = [c[0] + v[0], c[1] + v[1], c[2] + v[2]];
            match self.st.index(c) {
                None => return true,
                Some(j) if self.st.occupied(j) => return false,
                Some(_) => {}
            }
        }
    }
}
