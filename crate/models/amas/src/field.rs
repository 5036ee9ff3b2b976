//! The gradient fields, computed by the modules themselves: one synchronous update is every
//! module reading its four neighbours' values of the previous update (Jacobi, not
//! Gauss-Seidel), so
//! information travels one module per update, as it would through neighbour-to-neighbour
//! communication. Rows are processed with straight-line loops over equal-length slices so the
//! compiler vectorises them (SSE natively, SIMD128 in wasm when enabled).

use super::state::{BROKEN, FRONT, MODULE, SOURCE};

/// Distance not (yet) known, or no module here.
pub const FAR: u16 = u16::MAX;

#[derive(Clone)]
pub enum Field {
    /// Equation 2: distances to the supply area and to the growth front.
    Discrete {
        to_supply: Vec<u16>,
        to_front: Vec<u16>,
        /// Row buffers: the previous row's and this row's values before the update.
        rows: [Vec<u16>; 4],
        far: Vec<u16>,
    },
    /// Equation 1: the potential, 1 at the growth front, 0 at the supply.
    Continuous {
        p: Vec<f32>,
        rows: [Vec<f32>; 2],
        d: f32,
        zero: Vec<f32>,
        none: Vec<u8>,
    },
}

impl Field {
    pub fn discrete(n: usize, w: usize) -> Field {
        Field::Discrete {
            to_supply: vec![FAR; n],
            to_front: vec![FAR; n],
            rows: std::array::from_fn(|_| vec![FAR; w]),
            far: vec![FAR; w],
        }
    }

    pub fn continuous(n: usize, w: usize, d: f32) -> Field {
        Field::Continuous {
            p: vec![0.0; n],
            rows: std::array::from_fn(|_| vec![0.0; w]),
            d,
            zero: vec![0.0; w],
            none: vec![0; w],
        }
    }

    /// One synchronous update of every module in rows `top..h`: each row is computed from the
    /// values its neighbours held before this update (kept in two row buffers), so the field
    /// is updated in place. Rows above `top` hold no module and keep their "no value".
    pub fn update(&mut self, state: &[u8], w: usize, top: usize) {
        let h = state.len() / w;
        match self {
            Field::Discrete {
                to_supply,
                to_front,
                rows,
                far,
            } => {
                let [up_s, up_f, old_s, old_f] = rows;
                if top > 0 {
                    up_s.copy_from_slice(&to_supply[(top - 1) * w..top * w]);
                    up_f.copy_from_slice(&to_front[(top - 1) * w..top * w]);
                } else {
                    up_s.copy_from_slice(far);
                    up_f.copy_from_slice(far);
                }
                for y in top..h {
                    let r = y * w;
                    old_s.copy_from_slice(&to_supply[r..r + w]);
                    old_f.copy_from_slice(&to_front[r..r + w]);
                    let (out_s, below_s) = to_supply[r..].split_at_mut(w);
                    let (out_f, below_f) = to_front[r..].split_at_mut(w);
                    let (sd, fd) = if y + 1 < h {
                        (&below_s[..w], &below_f[..w])
                    } else {
                        (&far[..], &far[..])
                    };
                    discrete_row(
                        &state[r..r + w],
                        [up_s, old_s, sd],
                        [up_f, old_f, fd],
                        out_s,
                        out_f,
                    );
                    std::mem::swap(up_s, old_s);
                    std::mem::swap(up_f, old_f);
                }
            }
            Field::Continuous {
                p,
                rows,
                d,
                zero,
                none,
            } => {
                let [up, old] = rows;
                if top > 0 {
                    up.copy_from_slice(&p[(top - 1) * w..top * w]);
                } else {
                    up.copy_from_slice(zero);
                }
                for y in top..h {
                    let r = y * w;
                    old.copy_from_slice(&p[r..r + w]);
                    let su = if y > 0 { &state[r - w..r] } else { &none[..] };
                    let (out, below) = p[r..].split_at_mut(w);
                    let (pd, sd) = if y + 1 < h {
                        (&below[..w], &state[r + w..r + 2 * w])
                    } else {
                        (&zero[..], &none[..])
                    };
                    continuous_row([su, &state[r..r + w], sd], [up, old, pd], out, *d);
                    std::mem::swap(up, old);
                }
            }
        }
    }
}

/// Equation 2 for one row: a module's distance is the least of its neighbours' plus one; the
/// destination modules hold 0; cells without a module hold FAR, which no minimum ever picks
/// up. A module whose communication broke keeps the value it had, and its neighbours keep the
/// value they last heard from it.
#[inline(always)]
fn discrete_cell(s: u8, old: (u16, u16), ms: u16, mf: u16) -> (u16, u16) {
    if s & MODULE == 0 {
        (FAR, FAR)
    } else if s & BROKEN != 0 {
        old
    } else {
        let vs = if s & SOURCE != 0 {
            0
        } else {
            ms.saturating_add(1)
        };
        let vf = if s & FRONT != 0 {
            0
        } else {
            mf.saturating_add(1)
        };
        (vs, vf)
    }
}

fn discrete_row(st: &[u8], s: [&[u16]; 3], f: [&[u16]; 3], os: &mut [u16], of: &mut [u16]) {
    let w = st.len();
    let [su, sm, sd] = s;
    let [fu, fm, fd] = f;
    let edge = |x: usize| {
        let l = |v: &[u16]| if x > 0 { v[x - 1] } else { FAR };
        let r = |v: &[u16]| if x + 1 < w { v[x + 1] } else { FAR };
        let ms = l(sm).min(r(sm)).min(su[x]).min(sd[x]);
        let mf = l(fm).min(r(fm)).min(fu[x]).min(fd[x]);
        discrete_cell(st[x], (sm[x], fm[x]), ms, mf)
    };
    if w <= 2 {
        for x in 0..w {
            (os[x], of[x]) = edge(x);
        }
        return;
    }
    (os[0], of[0]) = edge(0);
    (os[w - 1], of[w - 1]) = edge(w - 1);
    let n = w - 2;
    // Equal-length slices, so the loop runs without bounds checks and vectorises.
    let (sl, sc, sr, su, sd) = (&sm[..n], &sm[1..=n], &sm[2..2 + n], &su[1..=n], &sd[1..=n]);
    let (fl, fc, fr, fu, fd) = (&fm[..n], &fm[1..=n], &fm[2..2 + n], &fu[1..=n], &fd[1..=n]);
    let st = &st[1..=n];
    let (os, of) = (&mut os[1..=n], &mut of[1..=n]);
    for i in 0..n {
        let ms = sl[i].min(sr[i]).min(su[i]).min(sd[i]);
        let mf = fl[i].min(fr[i]).min(fu[i]).min(fd[i]);
        // Masks in 16 bits: all ones where the condition holds.
        let s = u16::from(st[i]);
        let off = 0u16.wrapping_sub(u16::from(s & u16::from(MODULE) == 0));
        let frozen = 0u16.wrapping_sub(u16::from(s & u16::from(BROKEN) != 0));
        let src = 0u16.wrapping_sub(u16::from(s & u16::from(SOURCE) != 0));
        let front = 0u16.wrapping_sub(u16::from(s & u16::from(FRONT) != 0));
        os[i] = (ms.saturating_add(1) & !src & !frozen) | (sc[i] & frozen) | off;
        of[i] = (mf.saturating_add(1) & !front & !frozen) | (fc[i] & frozen) | off;
    }
}

/// Equation 1 for one row, explicit Euler: P += D Σ (P_j − P) over the neighbouring modules
/// only, so nothing leaks across a completed edge (a Neumann boundary). The growth front is
/// held at 1 and the supply at 0 (the front wins where a module is both). Cells without a
/// module hold 0, which adds nothing to the sum. A module whose communication broke keeps its
/// value, and its neighbours keep the value they last heard from it.
#[inline(always)]
fn continuous_value(s: u8, p: f32, sum: f32, k: f32, d: f32) -> f32 {
    let v = p + d * (sum - k * p);
    if s & MODULE == 0 {
        0.0
    } else if s & BROKEN != 0 {
        p
    } else if s & FRONT != 0 {
        1.0
    } else if s & SOURCE != 0 {
        0.0
    } else {
        v
    }
}

#[inline(always)]
fn on(s: u8) -> f32 {
    if s & MODULE != 0 {
        1.0
    } else {
        0.0
    }
}

fn continuous_row(s: [&[u8]; 3], p: [&[f32]; 3], out: &mut [f32], d: f32) {
    let [su, sm, sd] = s;
    let [pu, pm, pd] = p;
    let w = sm.len();
    let edge = |x: usize| {
        let (pl, sl) = if x > 0 {
            (pm[x - 1], sm[x - 1])
        } else {
            (0.0, 0)
        };
        let (pr, sr) = if x + 1 < w {
            (pm[x + 1], sm[x + 1])
        } else {
            (0.0, 0)
        };
        let sum = pl + pr + pu[x] + pd[x];
        let k = on(sl) + on(sr) + on(su[x]) + on(sd[x]);
        continuous_value(sm[x], pm[x], sum, k, d)
    };
    if w <= 2 {
        for (x, o) in out.iter_mut().enumerate() {
            *o = edge(x);
        }
        return;
    }
    out[0] = edge(0);
    out[w - 1] = edge(w - 1);
    let n = w - 2;
    let (pl, pc, pr, pu, pd) = (&pm[..n], &pm[1..=n], &pm[2..2 + n], &pu[1..=n], &pd[1..=n]);
    let (sl, sc, sr, su, sd) = (&sm[..n], &sm[1..=n], &sm[2..2 + n], &su[1..=n], &sd[1..=n]);
    let out = &mut out[1..=n];
    let on_bit = |s: u8| u32::from(s & MODULE);
    for i in 0..n {
        let sum = pl[i] + pr[i] + pu[i] + pd[i];
        let k = (on_bit(sl[i]) + on_bit(sr[i]) + on_bit(su[i]) + on_bit(sd[i])) as f32;
        let p = pc[i];
        let v = p + d * (sum - k * p);
        // The same as `continuous_value`, with bit masks instead of branches.
        let s = sc[i];
        let live = s & (MODULE | BROKEN) == MODULE;
        let keep = 0u32.wrapping_sub(u32::from(live && s & (FRONT | SOURCE) == 0));
        let frozen = 0u32.wrapping_sub(u32::from(s & BROKEN != 0));
        let one = 0u32.wrapping_sub(u32::from(live && s & FRONT != 0)) & 1.0f32.to_bits();
        out[i] = f32::from_bits((v.to_bits() & keep) | (p.to_bits() & frozen) | one);
    }
}
