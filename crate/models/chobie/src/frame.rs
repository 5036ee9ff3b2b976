//! The plane-frame stress model. Each robot is a node with three degrees of freedom (x, y,
//! rotation); each locked contact between face neighbours is a Timoshenko beam element one cell
//! long (a robot is as deep as it is long, so shear deformation is not negligible); robots resting on the terrain are clamped to it (the base carries the same sliding
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
    // Timoshenko's element: shear deformation softens the bending terms by 1 + φ.
    let p = m.phi;
    let (k1, k2, k3, k4) = (
        12.0 * ei / (l * l * l * (1.0 + p)),
        6.0 * ei / (l * l * (1.0 + p)),
        (4.0 + p) * ei / (l * (1.0 + p)),
        (2.0 - p) * ei / (l * (1.0 + p)),
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
    solve_against(m, pos, elems, fixed, &[], loads, &mut Scratch::default())
}

/// The memory of the stiffness matrix's band, kept by the caller from one solve to the next: a
/// thousand robots need megabytes, which allocated anew at each step would go back to the system
/// and come again as page faults. It is no part of the state: a copy (a keyframe of the page's
/// timeline) starts empty.
#[derive(Debug, Default)]
pub struct Scratch(Vec<f64>);

impl Clone for Scratch {
    fn clone(&self) -> Scratch {
        Scratch::default()
    }
}

/// [`solve`] with walls: a node marked in `walls` has terrain against its left face, which can
/// push it right but not pull it (a unilateral contact, like a robot pressed against the cliff
/// face under the bridge's root). The frame is solved with those nodes held in x; a wall that
/// would have to pull lets go, and the frame is solved again until every wall pushes.
pub fn solve_against(
    m: &Mechanics,
    pos: &[(i32, i32)],
    elems: &[(u32, u32)],
    fixed: &[bool],
    walls: &[bool],
    loads: &[[f64; 3]],
    band: &mut Scratch,
) -> Option<Solution> {
    let mut held: Vec<bool> = (0..pos.len())
        .map(|i| walls.get(i).copied().unwrap_or(false) && !fixed[i])
        .collect();
    loop {
        let (sol, reaction) = solve_held(m, pos, elems, fixed, &held, loads, band)?;
        let mut released = false;
        for (i, r) in reaction.iter().enumerate() {
            if held[i] && *r < 0.0 {
                held[i] = false;
                released = true;
            }
        }
        if !released {
            return Some(sol);
        }
    }
}

/// One linear solve with the nodes in `held` restrained in x; also returns each node's x
/// reaction (positive: the support pushes the node right).
fn solve_held(
    m: &Mechanics,
    pos: &[(i32, i32)],
    elems: &[(u32, u32)],
    fixed: &[bool],
    held: &[bool],
    loads: &[[f64; 3]],
    memory: &mut Scratch,
) -> Option<(Solution, Vec<f64>)> {
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
    // One sort for either axis: the standard library compiles a sort per closure.
    let wide = maxx - minx >= maxy - miny;
    order.sort_by_key(|&i| {
        let (x, y) = pos[i as usize];
        if wide {
            (x, y)
        } else {
            (y, x)
        }
    });
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
    // Every element runs right or down one cell (see [`elements`]): two stiffness matrices.
    let right = element_matrix(m, 1.0, 0.0);
    let down = element_matrix(m, 0.0, -1.0);
    let stiffness = |s: f64| if s == 0.0 { &right } else { &down };
    let mut k = Banded::new(dofs, band, std::mem::take(&mut memory.0));
    let dir = |i: u32, j: u32| {
        let (xi, yi) = pos[i as usize];
        let (xj, yj) = pos[j as usize];
        ((xj - xi) as f64, (yi - yj) as f64)
    };
    let dof = |node: u32, d: usize| match rank[node as usize] {
        usize::MAX => None,
        _ if d == 0 && held[node as usize] => None,
        r => Some(3 * r + d),
    };
    for &(i, j) in elems {
        let ke = stiffness(dir(i, j).1);
        let map: [Option<usize>; 6] =
            std::array::from_fn(|a| dof(if a < 3 { i } else { j }, a % 3));
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
    // A held x gets an identity row, so the numbering (and the band) stays as it is.
    let mut any_held = false;
    for (node, &h) in held.iter().enumerate() {
        if h && rank[node] != usize::MAX {
            k.add(3 * rank[node], 3 * rank[node], 1.0);
            any_held = true;
        }
    }
    let factored = k.factor().is_some();
    if factored {
        k.solve(&mut f);
    }
    memory.0 = k.a;
    if !factored {
        return None;
    }
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
    let mut reaction = vec![0.0f64; if any_held { n } else { 0 }];
    for &(i, j) in elems {
        let (c, s) = dir(i, j);
        let ke = stiffness(s);
        let u: [f64; 6] = std::array::from_fn(|a| disp[if a < 3 { i } else { j } as usize][a % 3]);
        let fg: [f64; 6] = std::array::from_fn(|a| (0..6).map(|b| ke[a][b] * u[b]).sum());
        if any_held {
            reaction[i as usize] += fg[0];
            reaction[j as usize] += fg[3];
        }
        let t = rotation(c, s);
        let fl: [f64; 6] = std::array::from_fn(|a| (0..6).map(|b| t[a][b] * fg[b]).sum());
        let axial = fl[3];
        let (mi, mj) = (fl[2], fl[5]);
        forces.push([axial, mi, mj]);
        let peak = axial.abs() / m.area + mi.abs().max(mj.abs()) * m.fibre / m.inertia;
        stress[i as usize] = stress[i as usize].max(peak);
        stress[j as usize] = stress[j as usize].max(peak);
    }
    if any_held {
        for (node, r) in reaction.iter_mut().enumerate() {
            *r -= loads[node][0];
        }
    }
    Some((
        Solution {
            disp,
            forces,
            stress,
        },
        reaction,
    ))
}

/// A symmetric banded matrix, lower band stored column by column: entry (i, j), j ≤ i ≤ j + b,
/// at `j·(b + 1) + (i − j)`, so each column of the band is one contiguous slice.
struct Banded {
    n: usize,
    b: usize,
    a: Vec<f64>,
}

impl Banded {
    /// A zero matrix of `n` rows and half-bandwidth `b`, in `memory` (cleared and resized).
    fn new(n: usize, b: usize, mut memory: Vec<f64>) -> Banded {
        let b = b.min(n.saturating_sub(1));
        memory.clear();
        memory.resize(n * (b + 1), 0.0);
        Banded { n, b, a: memory }
    }

    fn at(&self, i: usize, j: usize) -> usize {
        j * (self.b + 1) + (i - j)
    }

    fn add(&mut self, i: usize, j: usize, v: f64) {
        let p = self.at(i, j);
        self.a[p] += v;
    }

    /// In-place Cholesky factorisation, L Lᵀ; None if not positive definite. Column by column
    /// (left-looking): column j of L is its column of the matrix less L(j, k)·(column k of L)
    /// for every earlier column k whose L(j, k) is not zero, subtracted in order of k, four
    /// columns per pass over the target so that it is loaded and stored once per four. The
    /// loops carry no running sum, so they vectorise as written, with the same operations in
    /// the same order on every target.
    fn factor(&mut self) -> Option<()> {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        let mut from: Vec<(usize, f64)> = Vec::with_capacity(b);
        for j in 0..n {
            let m = b.min(n - 1 - j);
            let (done, rest) = self.a.split_at_mut(j * w);
            let col = &mut rest[..m + 1];
            from.clear();
            from.extend(
                (j.saturating_sub(b)..j)
                    .map(|k| (k, done[k * w + (j - k)]))
                    .filter(|&(_, l)| l != 0.0),
            );
            // Column k holds rows k..=min(k + b, n - 1); from row j on, that is `len(k)` entries.
            let source = |k: usize| &done[k * w + (j - k)..k * w + b.min(n - 1 - k) + 1];
            let mut groups = from.chunks_exact(4);
            for g in groups.by_ref() {
                let [(k0, l0), (k1, l1), (k2, l2), (k3, l3)] = [g[0], g[1], g[2], g[3]];
                let (s0, s1, s2, s3) = (source(k0), source(k1), source(k2), source(k3));
                // Lengths grow with k: all four columns reach the first s0.len() rows.
                let common = s0.len();
                for ((((t, &x0), &x1), &x2), &x3) in col[..common]
                    .iter_mut()
                    .zip(s0)
                    .zip(&s1[..common])
                    .zip(&s2[..common])
                    .zip(&s3[..common])
                {
                    *t = (((*t - l0 * x0) - l1 * x1) - l2 * x2) - l3 * x3;
                }
                for (t, target) in col.iter_mut().enumerate().take(s3.len()).skip(common) {
                    for (s, l) in [(s1, l1), (s2, l2), (s3, l3)] {
                        if let Some(&x) = s.get(t) {
                            *target -= l * x;
                        }
                    }
                }
            }
            for &(k, l) in groups.remainder() {
                for (t, &x) in col.iter_mut().zip(source(k)) {
                    *t -= l * x;
                }
            }
            let d = col[0];
            if d <= 0.0 || !d.is_finite() {
                return None;
            }
            let d = d.sqrt();
            col[0] = d;
            for v in &mut col[1..] {
                *v /= d;
            }
        }
        Some(())
    }

    /// Solves L Lᵀ x = f in place.
    fn solve(&self, f: &mut [f64]) {
        let w = self.b + 1;
        for k in 0..self.n {
            let m = self.b.min(self.n - 1 - k);
            let col = &self.a[k * w..k * w + m + 1];
            let x = f[k] / col[0];
            f[k] = x;
            if x != 0.0 {
                for (t, &l) in f[k + 1..=k + m].iter_mut().zip(&col[1..]) {
                    *t -= x * l;
                }
            }
        }
        for k in (0..self.n).rev() {
            let m = self.b.min(self.n - 1 - k);
            let col = &self.a[k * w..k * w + m + 1];
            f[k] = (f[k] - dot(&col[1..], &f[k + 1..=k + m])) / col[0];
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
