//! Building a model from its scenario (initialisation), and the per-unit data every phase
//! reads: neighbour masks, types, differences, connected groups, and equation 2's initial state.

use super::*;
use kumiki_model::limits::Limits;

/// A description whose every key is checked: its parameters, its goal, and the start shape's
/// units placed on a lattice of `w × h` cells, in reading order.
#[derive(Clone)]
pub struct Checked {
    p: Params,
    goal: Goal,
    placed: Vec<kumiki_model::lattice::Coord>,
    w: u32,
    h: u32,
}

impl model::Spec for Spec {
    type Checked = Checked;

    fn validate(&self, limits: &Limits) -> Result<Checked> {
        let max = *crate::limits::LIMITS.of(limits);
        let p = params(self);
        let goal = Goal::parse(&self.goal).map_err(|e| Error::field("goal", e))?;
        let start = shape::parse_hex_within(&self.start, limits).map_err(|e| e.within("start"))?;
        let count = start.count();
        if count == 0 {
            return Err(Error::field("start", "has no '#' cells"));
        }
        if count > max.units {
            return Err(Error::field(
                "start",
                format!("{count} units exceed the limit of {}", max.units),
            ));
        }
        // Place the shape `margin` rows down and at least `margin` columns in, moving it in axial
        // coordinates so that its odd rows keep their offsets relative to its even ones.
        let m = self.margin as i32;
        let mut axial: Vec<(i32, i32)> = Vec::with_capacity(count);
        for y in 0..start.h {
            for x in 0..start.w {
                if start.get(x, y) {
                    let (q, r) =
                        Hex::to_axial(kumiki_model::lattice::Coord::xy(x as i32, y as i32));
                    axial.push((q, r + m));
                }
            }
        }
        let min_x = axial
            .iter()
            .map(|&(q, r)| Hex::from_axial(q, r).x)
            .min()
            .unwrap_or(0);
        let shift = m - min_x;
        let placed: Vec<kumiki_model::lattice::Coord> = axial
            .iter()
            .map(|&(q, r)| Hex::from_axial(q + shift, r))
            .collect();
        let max_x = placed.iter().map(|c| c.x).max().unwrap_or(0);
        let w = (max_x + 1 + m) as u64;
        let h = u64::from(start.h) + 2 * u64::from(self.margin);
        let side = max.side;
        if w > u64::from(side) || h > u64::from(side) {
            return Err(Error::field(
                "start",
                format!("{w}×{h} cells with the margin exceeds the limit of {side}×{side}"),
            ));
        }
        let lattice = Hex::new(w as u32, h as u32);
        let cells: Vec<usize> = placed
            .iter()
            .map(|c| lattice.index(*c).expect("placed inside the lattice"))
            .collect();
        if !connected(&lattice, &cells) {
            return Err(Error::field(
                "start",
                "the units fall apart into pieces; fracta units are always connected",
            ));
        }
        Ok(Checked {
            p,
            goal,
            placed,
            w: w as u32,
            h: h as u32,
        })
    }

    fn check_action(checked: &Checked, action: &Action) -> Result<()> {
        let cells = checked.w as usize * checked.h as usize;
        actions::parse_fault(action, cells, checked.placed.len()).map(|_| ())
    }

    fn build(checked: Checked, seed: u64) -> Box<dyn Model> {
        Box::new(Fracta::from_checked(checked, seed))
    }
}

/// The units on `cells` form one piece on the lattice.
fn connected(lattice: &Hex, cells: &[usize]) -> bool {
    let occupied: std::collections::HashSet<usize> = cells.iter().copied().collect();
    let mut seen = std::collections::HashSet::new();
    let mut stack: Vec<usize> = cells.first().copied().into_iter().collect();
    seen.extend(stack.iter().copied());
    while let Some(i) = stack.pop() {
        for j in lattice.neighbours(i) {
            if occupied.contains(&j) && seen.insert(j) {
                stack.push(j);
            }
        }
    }
    seen.len() == occupied.len()
}

impl Fracta {
    /// The model at step 0, from its checked description.
    pub fn from_checked(checked: Checked, seed: u64) -> Fracta {
        let Checked {
            p,
            goal,
            placed,
            w,
            h,
        } = checked;
        let count = placed.len();
        let lattice = Hex::new(w, h);
        let n = lattice.len();
        let nbr: Vec<[u32; 6]> = (0..n)
            .map(|i| {
                let mut out = [NO_UNIT; 6];
                for (d, slot) in out.iter_mut().enumerate() {
                    if let Some(j) = lattice.neighbour(i, d) {
                        *slot = j as u32;
                    }
                }
                out
            })
            .collect();
        let mut occ = vec![NO_UNIT; n];
        let mut units = Vec::with_capacity(count);
        for (id, c) in placed.iter().enumerate() {
            let cell = lattice.index(*c).expect("placed inside the lattice") as u32;
            occ[cell as usize] = id as u32;
            units.push(Unit {
                cell,
                status: Status::Working,
                x: 0.0,
                irr: 0.0,
            });
        }
        let mut model = Fracta {
            lattice,
            nbr,
            occ,
            ghost: vec![code::EMPTY; n],
            working: (0..count as u32).collect(),
            units,
            goal,
            p,
            rng: Rng::new(seed),
            steps: 0,
            mask: vec![0; count],
            class: vec![0; count],
            diff: vec![0; count],
            last_diff: vec![0; count],
            closest: vec![0; count],
            zero: 0,
            pending: 0,
            new_x: vec![0.0; count],
            active: Vec::new(),
            touched: Vec::new(),
            activation: Default::default(),
            roll: Default::default(),
            stopped: None,
            plans: Vec::new(),
            busy: vec![u64::MAX; count],
            moves: 0,
            conflicts: 0,
            irritations: 0,
            faults: 0,
            cut_off: 0,
            stranded: 0,
            last_fault: None,
            events: Vec::new(),
        };
        model.refresh();
        model.initial_state();
        model
    }

    /// Neighbour mask of a cell: bit d set when a unit (working or faulty) is in direction d.
    #[inline]
    pub(super) fn ring(&self, cell: u32) -> u8 {
        let nb = &self.nbr[cell as usize];
        let mut m = 0u8;
        for (d, &j) in nb.iter().enumerate() {
            if j != NO_UNIT && self.occ[j as usize] != NO_UNIT {
                m |= 1 << d;
            }
        }
        m
    }

    /// Neighbour mask of `cell` with the cell `gone` counted as empty.
    pub(super) fn ring_without(&self, cell: u32, gone: u32) -> u8 {
        let nb = &self.nbr[cell as usize];
        let mut m = 0u8;
        for (d, &j) in nb.iter().enumerate() {
            if j != NO_UNIT && j != gone && self.occ[j as usize] != NO_UNIT {
                m |= 1 << d;
            }
        }
        m
    }

    /// Sorted classes of the units around `cell`, from the current occupancy, written into
    /// `out`; returns how many.
    pub(super) fn neighbour_classes(&self, cell: u32, out: &mut [u8; 6], fresh: bool) -> usize {
        let t = types();
        let mut n = 0;
        for &j in &self.nbr[cell as usize] {
            if j == NO_UNIT {
                continue;
            }
            let v = self.occ[j as usize];
            if v != NO_UNIT {
                out[n] = if fresh {
                    t.of(self.ring(j))
                } else {
                    self.class[v as usize]
                };
                n += 1;
            }
        }
        out[..n].sort_unstable();
        n
    }

    /// Recomputes every unit's neighbour mask, type and difference.
    pub(super) fn refresh(&mut self) {
        let t = types();
        for u in 0..self.units.len() {
            if matches!(self.units[u].status, Status::Working | Status::Faulty) {
                let m = self.ring(self.units[u].cell);
                self.mask[u] = m;
                self.class[u] = t.of(m);
            }
        }
        self.zero = 0;
        let mut nb = [0u8; 6];
        for k in 0..self.working.len() {
            let u = self.working[k] as usize;
            let n = self.neighbour_classes(self.units[u].cell, &mut nb, false);
            let c = self
                .goal
                .difference(&t.dist, self.class[u], &nb[..n], self.p.priorities);
            self.diff[u] = c.difference;
            self.closest[u] = c.statement;
            if c.difference == 0 {
                self.zero += 1;
            }
        }
    }

    /// Connected groups of working units, each as a list of ids, in order of their smallest id.
    pub(super) fn components(&self) -> Vec<Vec<u32>> {
        let mut seen = vec![false; self.units.len()];
        let mut out = Vec::new();
        for &u in &self.working {
            if seen[u as usize] {
                continue;
            }
            seen[u as usize] = true;
            let mut group = vec![u];
            let mut queue = VecDeque::from([u]);
            while let Some(v) = queue.pop_front() {
                for &j in &self.nbr[self.units[v as usize].cell as usize] {
                    if j == NO_UNIT {
                        continue;
                    }
                    let w = self.occ[j as usize];
                    if w != NO_UNIT
                        && !seen[w as usize]
                        && self.units[w as usize].status == Status::Working
                    {
                        seen[w as usize] = true;
                        group.push(w);
                        queue.push_back(w);
                    }
                }
            }
            out.push(group);
        }
        out
    }

    /// Equation 2's initial state, x(i, 0) = diff(i, 0), and no irritation, for every unit at
    /// the start.
    fn initial_state(&mut self) {
        for &u in &self.working {
            let unit = &mut self.units[u as usize];
            unit.x = f64::from(self.diff[u as usize]);
            unit.irr = 0.0;
            self.last_diff[u as usize] = self.diff[u as usize];
        }
    }
}
