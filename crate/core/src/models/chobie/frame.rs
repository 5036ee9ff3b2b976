//! The plane-frame stress model. Each robot is a node with three degrees of freedom (x, y,
//! rotation); each locked contact between face neighbours is an Euler-Bernoulli beam element one
//! cell long; robots resting on the terrain are clamped to it (the base carries the same sliding
//! guide and locking rods as a robot). Loads are nodal: each robot's weight and the applied loads.
//!
//! The stiffness matrix is symmetric positive definite and banded once the nodes are numbered
//! along the structure's longer axis, so it is solved exactly by a banded Cholesky factorisation:
//! n·b² work for n unknowns and half-bandwidth b, about 3·(robots across the short side) here.
//! Frame elements with nodal loads are exact, so the results match beam theory to rounding.

use super::spec::Mechanics;

/// Nodal displacements and the stress each robot carries.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Solution {
    /// Per node: x and y displacement (metres, y up) and rotation (radians, counter-clockwise).
    pub disp: Vec<[f64; 3]>,
    /// Per element (in [`elements`] order): axial force (tension positive) and the bending
    /// moments at its two ends, local sign convention.
    pub forces: Vec<[f64; 3]>,
    /// Per node: the largest |N|/A + |M|·c/I over the ends of the elements it belongs to, Pa.
    pub stress: Vec<f64>,
}

/// The elements: every pair of face neighbours, each once, as (left or upper node, the other).
pub fn elements(pos: &[(i32, i32)], at: &dyn Fn(i32, i32) -> Option<u32>) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for (i, &(x, y)) in pos.iter().enumerate() {
        for (dx, dy) in [(1, 0), (0, 1)] {
            if let Some(j) = at(x + dx, y + dy) {
                out.push((i as u32, j));
            }
        }
    }
    out
}

/// The 6×6 element stiffness in global axes for an element of direction (c, s).
fn element_matrix(m: &Mechanics, c: f64, s: f64) -> [[f64; 6]; 6] {
    let l = m.length;
    let ea = m.e * m.area / l;
    let ei = m.e * m.inertia;
    let (k1, k2, k3, k4) = (
        12.0 * ei / (l * l * l),
        6.0 * ei / (l * l),
        4.0 * ei / l,
        2.0 * ei / l,
    );
    let local = [
        [ea, 0.0, 0.0, -ea, 0.0, 0.0],
        [0.0, k1, k2, 0.0, -k1, k2],
        [0.0, k2, k3, 0.0, -k2, k4],
        [-ea, 0.0, 0.0, ea, 0.0, 0.0],
        [0.0, -k1, -k2, 0.0, k1, -k2],
        [0.0, k2, k4, 0.0, -k2, k3],
    ];
    let t = rotation(c, s);
    let mut kt = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            kt[i][j] = (0..6).map(|k| local[i][k] * t[k][j]).sum();
        }
    }
    let mut out = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            out[i][j] = (0..6).map(|k| t[k][i] * kt[k][j]).sum();
        }
    }
    out
}

fn rotation(c: f64, s: f64) -> [[f64; 6]; 6] {
    let mut t = [[0.0; 6]; 6];
    for b in [0, 3] {
        t[b][b] = c;
        t[b][b + 1] = s;
        t[b + 1][b] = -s;
        t[b + 1][b + 1] = c;
        t[b + 2][b + 2] = 1.0;
    }
    t
}

/// Solves the frame. `pos` are lattice cells (y down), `fixed` marks clamped nodes, `loads` are
/// nodal forces (x, y up, moment). Returns None if the stiffness matrix is singular (a part not
/// held by any clamped node).
pub fn solve(
    m: &Mechanics,
    pos: &[(i32, i32)],
    elems: &[(u32, u32)],
    fixed: &[bool],
    loads: &[[f64; 3]],
) -> Option<Solution> {
    let n = pos.len();
    // Number the free nodes along the longer axis for a narrow band.
    let (mut minx, mut maxx, mut miny, mut maxy) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    for &(x, y) in pos {
        minx = minx.min(x);
        maxx = maxx.max(x);
        miny = miny.min(y);
        maxy = maxy.max(y);
    }
    let mut order: Vec<u32> = (0..n as u32).filter(|&i| !fixed[i as usize]).collect();
    if maxx - minx >= maxy - miny {
        order.sort_by_key(|&i| (pos[i as usize].0, pos[i as usize].1));
    } else {
        order.sort_by_key(|&i| (pos[i as usize].1, pos[i as usize].0));
    }
    let mut rank = vec![usize::MAX; n];
    for (k, &i) in order.iter().enumerate() {
        rank[i as usize] = k;
    }
    let dofs = 3 * order.len();
    let mut band = 2;
    for &(i, j) in elems {
        let (ri, rj) = (rank[i as usize], rank[j as usize]);
        if ri != usize::MAX && rj != usize::MAX {
            band = band.max(3 * ri.abs_diff(rj) + 2);
        }
    }
    let mut k = Banded::new(dofs, band);
    let dir = |i: u32, j: u32| {
        let (xi, yi) = pos[i as usize];
        let (xj, yj) = pos[j as usize];
        ((xj - xi) as f64, (yi - yj) as f64)
    };
    let dof = |node: u32, d: usize| match rank[node as usize] {
        usize::MAX => None,
        r => Some(3 * r + d),
    };
    for &(i, j) in elems {
        let (c, s) = dir(i, j);
        let ke = element_matrix(m, c, s);
        let map: Vec<Option<usize>> = (0..6)
            .map(|a| dof(if a < 3 { i } else { j }, a % 3))
            .collect();
        for a in 0..6 {
            for b in 0..6 {
                if let (Some(p), Some(q)) = (map[a], map[b]) {
                    if q <= p {
                        k.add(p, q, ke[a][b]);
                    }
                }
            }
        }
    }
    let mut f = vec![0.0; dofs];
    for (node, load) in loads.iter().enumerate() {
        for (d, &v) in load.iter().enumerate() {
            if let Some(p) = dof(node as u32, d) {
                f[p] = v;
            }
        }
    }
    k.factor()?;
    k.solve(&mut f);
    let disp: Vec<[f64; 3]> = (0..n as u32)
        .map(|node| {
            let mut u = [0.0; 3];
            for (d, v) in u.iter_mut().enumerate() {
                if let Some(p) = dof(node, d) {
                    *v = f[p];
                }
            }
            u
        })
        .collect();
    let mut forces = Vec::with_capacity(elems.len());
    let mut stress = vec![0.0f64; n];
    for &(i, j) in elems {
        let (c, s) = dir(i, j);
        let ke = element_matrix(m, c, s);
        let u: Vec<f64> = disp[i as usize]
            .iter()
            .chain(disp[j as usize].iter())
            .copied()
            .collect();
        let fg: Vec<f64> = (0..6)
            .map(|a| (0..6).map(|b| ke[a][b] * u[b]).sum())
            .collect();
        let t = rotation(c, s);
        let fl: Vec<f64> = (0..6)
            .map(|a| (0..6).map(|b| t[a][b] * fg[b]).sum())
            .collect();
        let axial = fl[3];
        let (mi, mj) = (fl[2], fl[5]);
        forces.push([axial, mi, mj]);
        let peak = axial.abs() / m.area + mi.abs().max(mj.abs()) * m.fibre / m.inertia;
        stress[i as usize] = stress[i as usize].max(peak);
        stress[j as usize] = stress[j as usize].max(peak);
    }
    Some(Solution {
        disp,
        forces,
        stress,
    })
}

/// A symmetric banded matrix, lower band stored row by row: `a[i][i - j]` for j ≤ i.
struct Banded {
    n: usize,
    b: usize,
    a: Vec<f64>,
}

impl Banded {
    fn new(n: usize, b: usize) -> Banded {
        let b = b.min(n.saturating_sub(1));
        Banded {
            n,
            b,
            a: vec![0.0; n * (b + 1)],
        }
    }

    fn at(&self, i: usize, j: usize) -> usize {
        i * (self.b + 1) + (i - j)
    }

    fn add(&mut self, i: usize, j: usize, v: f64) {
        let p = self.at(i, j);
        self.a[p] += v;
    }

    /// In-place Cholesky factorisation, L Lᵀ; None if not positive definite. Row i of the band
    /// holds L(i, i - q) at `i·(b + 1) + q`, so the dot product of two rows' overlapping parts
    /// runs over two contiguous slices.
    fn factor(&mut self) -> Option<()> {
        let b = self.b;
        for i in 0..self.n {
            let lo = i.saturating_sub(b);
            let ri = self.at(i, i);
            for j in lo..=i {
                let rj = self.at(j, j);
                let len = j - lo;
                let dot = dot(
                    &self.a[ri + i - j + 1..ri + i - j + 1 + len],
                    &self.a[rj + 1..rj + 1 + len],
                );
                let p = self.at(i, j);
                let sum = self.a[p] - dot;
                if i == j {
                    if sum <= 0.0 || !sum.is_finite() {
                        return None;
                    }
                    self.a[p] = sum.sqrt();
                } else {
                    self.a[p] = sum / self.a[rj];
                }
            }
        }
        Some(())
    }

    /// Solves L Lᵀ x = f in place.
    fn solve(&self, f: &mut [f64]) {
        let b = self.b;
        for i in 0..self.n {
            let lo = i.saturating_sub(b);
            let ri = self.at(i, i);
            let dot: f64 = self.a[ri + 1..ri + 1 + (i - lo)]
                .iter()
                .rev()
                .zip(&f[lo..i])
                .map(|(x, y)| x * y)
                .sum();
            f[i] = (f[i] - dot) / self.a[ri];
        }
        for i in (0..self.n).rev() {
            let hi = (i + b).min(self.n - 1);
            let dot: f64 = (i + 1..=hi).map(|k| self.a[self.at(k, i)] * f[k]).sum();
            f[i] = (f[i] - dot) / self.a[self.at(i, i)];
        }
    }
}

/// A dot product in four independent partial sums, so the compiler can keep several
/// multiply-adds in flight (a single running sum must be evaluated strictly in order). The
/// order is fixed, so the result is the same on every target.
fn dot(x: &[f64], y: &[f64]) -> f64 {
    let mut acc = [0.0f64; 4];
    let (xc, xr) = x.split_at(x.len() / 4 * 4);
    let (yc, yr) = y.split_at(xc.len());
    for (a, b) in xc.chunks_exact(4).zip(yc.chunks_exact(4)) {
        for k in 0..4 {
            acc[k] += a[k] * b[k];
        }
    }
    let tail: f64 = xr.iter().zip(yr).map(|(a, b)| a * b).sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}
