//! Initialisation (ODD "Initialisation"): the lattice, the supply row full of modules, the
//! robots on distinct supply modules, the field before any update, and the bounds of footnote 2.

use std::collections::{BTreeMap, VecDeque};

use super::field::{Field, FAR};
use super::spec;
use super::state::{ACTIVE_MASK, CONVEYOR, FRONT, MODULE, REMOVE, SOURCE, VACANT};
use super::{
    Amas, FieldKind, Plan, Robot, NONE, STREAM_DISTURBANCE, STREAM_PLACEMENT, UNKNOWN, UP,
};
use kumiki_model::lattice::{Lattice, Square};
use kumiki_model::rng::Rng;
use kumiki_model::slot::Rule;

impl Amas {
    /// The model at step 0, from its checked plan (see [`spec::Spec::validate`]).
    pub fn from_checked(plan: spec::Plan, seed: u64) -> Amas {
        let w = plan.w as usize;
        let sh = plan.shape_h as usize;
        let h = sh + plan.supply_rows as usize;
        let n = w * h;
        let above = sh * w;
        let mut state = vec![0u8; n];
        for (i, s) in state.iter_mut().enumerate().take(above) {
            *s = match (plan.initial[i], plan.stages[0][i]) {
                (true, true) => MODULE,
                (true, false) => MODULE | REMOVE,
                (false, true) => VACANT,
                (false, false) => 0,
            };
        }
        for s in &mut state[above..] {
            *s = MODULE | CONVEYOR;
        }
        let stages: Vec<Vec<u64>> = plan
            .stages
            .iter()
            .map(|cells| {
                let mut bits = vec![0u64; above.div_ceil(64)];
                for (i, _) in cells.iter().enumerate().filter(|(_, &c)| c) {
                    bits[i / 64] |= 1 << (i % 64);
                }
                bits
            })
            .collect();
        let (lower_bound, path_bound) = bounds(
            plan.stages.last().expect("the target is always there"),
            &plan.initial,
            w,
            sh,
            u64::from(plan.robots),
        );
        let corner_row = corner_row(
            plan.stages.last().expect("the target is always there"),
            w,
            sh,
        );
        // The plan's shapes (a byte a cell each) are read: freed before the model's larger
        // buffers are made, so they are not held beside them. In wasm, memory that grew never
        // shrinks, and the page's 4096² lattice would keep them for good.
        let spec::Plan {
            supply_rows,
            robots: robot_count,
            params,
            stages: shapes,
            initial,
            ..
        } = plan;
        drop((shapes, initial));
        let supply_cells = w * supply_rows as usize;
        let mut place_rng = Rng::stream(seed, STREAM_PLACEMENT);
        let starts = place_rng.sample_distinct(supply_cells, robot_count as usize);
        let mut occupant = vec![NONE; n];
        let robots: Vec<Robot> = starts
            .iter()
            .enumerate()
            .map(|(r, &k)| {
                let cell = above + k;
                occupant[cell] = r as u32;
                Robot {
                    cell: cell as u32,
                    loaded: false,
                    busy: 0,
                    give_way: false,
                    waiting_for: NONE,
                    lost: false,
                    top: (cell / w) as u32,
                    placed_past_corner: false,
                    heading: UP,
                }
            })
            .collect();
        let robots_n = robots.len();
        let field = match params.field {
            FieldKind::Discrete => Field::discrete(n, w),
            FieldKind::Continuous => Field::continuous(n, w, params.diffusion),
        };
        let mut m = Amas {
            w,
            h,
            supply_top: sh,
            display: vec![0; n],
            state,
            occupant,
            field,
            p: params,
            robots,
            order: (0..robots_n as u32).collect(),
            plans: vec![Plan::Wait; robots_n],
            planned: vec![false; robots_n],
            status: vec![UNKNOWN; robots_n],
            relaying: vec![false; robots_n],
            position: vec![0; robots_n],
            claimed: Vec::new(),
            chain: Vec::new(),
            losers: Vec::new(),
            collision_rule: Rule::paper(),
            direction_rule: Rule::paper(),
            stopped: None,
            yielding: vec![false; robots_n],
            ahead: vec![NONE; robots_n],
            lock: vec![0; robots_n],
            rng: Rng::new(seed),
            disturb_rng: Rng::stream(seed, STREAM_DISTURBANCE),
            releasable: vec![0; n.div_ceil(64)],
            dirty: true,
            reuse: false,
            stages,
            stage: 0,
            return_mode: false,
            top: 0,
            target_cells: 0,
            vacant: 0,
            to_remove: 0,
            steps: 0,
            collisions: 0,
            relays: 0,
            placed: 0,
            picked: 0,
            dismantled: 0,
            returned: 0,
            removed: 0,
            broken: 0,
            lower_bound,
            path_bound,
            corner_row,
            corner_relays: 0,
            collision_cells: BTreeMap::new(),
            corner_collisions: 0,
            above_corner_collisions: 0,
            supply_collisions: 0,
            mixed_collisions: 0,
            loaded_collisions: 0,
            unloaded_collisions: 0,
            wandering: 0,
            events: Vec::new(),
        };
        m.recount();
        for i in 0..n {
            m.refresh(i);
        }
        m.settle();
        m.top = (0..h)
            .find(|&y| m.state[y * w..(y + 1) * w].iter().any(|&s| s & MODULE != 0))
            .unwrap_or(sh);
        m.reset_field();
        m
    }

    pub(super) fn recount(&mut self) {
        let above = self.supply_top * self.w;
        let (mut vacant, mut remove, mut built) = (0, 0, 0);
        for &s in &self.state[..above] {
            if s & VACANT != 0 {
                vacant += 1;
            } else if s & REMOVE != 0 {
                remove += 1;
            } else if s & MODULE != 0 {
                built += 1;
            }
        }
        self.vacant = vacant;
        self.to_remove = remove;
        self.target_cells = vacant + built;
    }

    /// Field values before any update: the destinations hold their fixed values, every other
    /// module knows nothing yet.
    pub(super) fn reset_field(&mut self) {
        for i in 0..self.state.len() {
            let s = self.state[i];
            let on = s & ACTIVE_MASK == MODULE;
            match &mut self.field {
                Field::Discrete {
                    to_supply,
                    to_front,
                    ..
                } => {
                    to_supply[i] = if on && s & SOURCE != 0 { 0 } else { FAR };
                    to_front[i] = if on && s & FRONT != 0 { 0 } else { FAR };
                }
                Field::Continuous { p, .. } => {
                    p[i] = if on && s & FRONT != 0 { 1.0 } else { 0.0 };
                }
            }
        }
    }
}

/// The row of the corner of figure 24: going up from the supply, the first row of `target`
/// holding fewer or more cells than the row below it (where an L or a T turns, standing on its
/// foot or on its stem); the top row of the target if none does.
fn corner_row(target: &[bool], w: usize, sh: usize) -> u32 {
    let count = |y: usize| target[y * w..(y + 1) * w].iter().filter(|&&c| c).count();
    let top = (0..sh).find(|&y| count(y) > 0).unwrap_or(0);
    (top..sh.saturating_sub(1))
        .rev()
        .find(|&y| count(y) != count(y + 1))
        .unwrap_or(top) as u32
}

/// Footnote 2 and the tighter bound through the shape: Σ 2·d over the modules to assemble,
/// minus robots × the largest d; d is the vertical distance to the supply area (footnote 2) or
/// the shortest path to the supply through the target shape.
fn bounds(target: &[bool], initial: &[bool], w: usize, sh: usize, robots: u64) -> (u64, u64) {
    let mut dist = vec![u32::MAX; target.len()];
    let mut queue = VecDeque::new();
    for x in 0..w {
        let i = (sh - 1) * w + x;
        if target[i] {
            dist[i] = 1;
            queue.push_back(i);
        }
    }
    let lattice = Square::new(w as u32, sh as u32);
    while let Some(i) = queue.pop_front() {
        for j in lattice.neighbours(i) {
            if target[j] && dist[j] == u32::MAX {
                dist[j] = dist[i] + 1;
                queue.push_back(j);
            }
        }
    }
    let (mut sum_v, mut max_v, mut sum_p, mut max_p) = (0u64, 0u64, 0u64, 0u64);
    for i in 0..target.len() {
        if target[i] && !initial[i] {
            let v = (sh - i / w) as u64;
            let p = u64::from(dist[i]);
            sum_v += 2 * v;
            max_v = max_v.max(v);
            sum_p += 2 * p;
            max_p = max_p.max(p);
        }
    }
    (
        sum_v.saturating_sub(robots * max_v),
        sum_p.saturating_sub(robots * max_p),
    )
}
