//! The robots on the side-view lattice and their only motion: whole lines sliding one cell
//! (section 3.1 and figure 3). A transformation is checked before it is made: the line
//! constraint, something fixed to slide against, no robot joining or leaving another head-on,
//! and afterwards one connected piece resting on the terrain.

use super::spec::{Tile, World};

/// No robot on a cell.
pub const NONE: u32 = u32::MAX;

/// Directions as on the square lattice: 0 right (+x), 1 up (-y), 2 left, 3 down (+y).
pub const DX: [i32; 4] = [1, 0, -1, 0];
pub const DY: [i32; 4] = [0, -1, 0, 1];
pub const RIGHT: usize = 0;
pub const UP: usize = 1;
pub const LEFT: usize = 2;
pub const DOWN: usize = 3;

/// One line told to drive one cell in a direction along its own axis.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Drive {
    /// The robots of the line, in order along it.
    pub robots: Vec<u32>,
    pub dir: usize,
}

/// Why a transformation was not made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// Two commands tell one robot to go two ways.
    Conflict,
    /// A robot would leave the lattice or enter terrain or an occupied cell.
    Blocked,
    /// A moving group has nothing fixed to slide against.
    NoPartner,
    /// A robot would meet or leave another face-on along the motion (figure 3b).
    HeadOn,
    /// The structure would fall apart or lose the terrain.
    Disconnected,
}

/// The lattice: terrain and robots. Robot ids never change; their cells do.
#[derive(Clone, Debug)]
pub struct Body {
    pub w: u32,
    pub h: u32,
    pub ground: Vec<bool>,
    /// The robot on each cell, or [`NONE`].
    pub occ: Vec<u32>,
    /// The cell of each robot as (x, y), y down.
    pub pos: Vec<(i32, i32)>,
}

impl Body {
    pub fn from_world(world: &World) -> Body {
        let mut body = Body {
            w: world.w,
            h: world.h,
            ground: world.tiles.iter().map(|t| *t == Tile::Ground).collect(),
            occ: vec![NONE; world.tiles.len()],
            pos: Vec::new(),
        };
        for y in 0..world.h as i32 {
            for x in 0..world.w as i32 {
                if world.get(x, y) == Tile::Robot {
                    let i = body.index(x, y).unwrap_or_default();
                    body.occ[i] = body.pos.len() as u32;
                    body.pos.push((x, y));
                }
            }
        }
        body
    }

    /// Number of robots.
    pub fn len(&self) -> usize {
        self.pos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    pub fn index(&self, x: i32, y: i32) -> Option<usize> {
        (x >= 0 && y >= 0 && x < self.w as i32 && y < self.h as i32)
            .then(|| y as usize * self.w as usize + x as usize)
    }

    pub fn robot_at(&self, x: i32, y: i32) -> u32 {
        self.index(x, y).map_or(NONE, |i| self.occ[i])
    }

    pub fn ground_at(&self, x: i32, y: i32) -> bool {
        self.index(x, y).is_some_and(|i| self.ground[i])
    }

    /// The robot next to `r` in direction `d`, or [`NONE`].
    pub fn nbr(&self, r: u32, d: usize) -> u32 {
        let (x, y) = self.pos[r as usize];
        self.robot_at(x + DX[d], y + DY[d])
    }

    pub fn has(&self, r: u32, d: usize) -> bool {
        self.nbr(r, d) != NONE
    }

    /// True when the robot rests on the terrain (terrain directly below it).
    pub fn grounded(&self, r: u32) -> bool {
        let (x, y) = self.pos[r as usize];
        self.ground_at(x, y + 1)
    }

    /// The maximal run of robots through `r` along the axis of direction `d` (horizontal for
    /// left/right, vertical for up/down), ordered from the far end against `d` to the far end
    /// along it.
    pub fn line(&self, r: u32, d: usize) -> Vec<u32> {
        let back = (d + 2) % 4;
        let mut start = r;
        while self.has(start, back) {
            start = self.nbr(start, back);
        }
        let mut out = vec![start];
        let mut cur = start;
        while self.has(cur, d) {
            cur = self.nbr(cur, d);
            out.push(cur);
        }
        out
    }

    /// Number of robot neighbours of each robot's faces.
    pub fn degree(&self, r: u32) -> usize {
        (0..4).filter(|&d| self.has(r, d)).count()
    }

    /// Every robot reachable from robot 0 over faces, as a mask; with `moved`, the positions
    /// after a move (robot → new cell) are used.
    fn connected_with(&self, pos: &[(i32, i32)], occ: impl Fn(i32, i32) -> u32) -> bool {
        if pos.is_empty() {
            return true;
        }
        let mut seen = vec![false; pos.len()];
        let mut stack = vec![0u32];
        seen[0] = true;
        let mut count = 0;
        while let Some(r) = stack.pop() {
            count += 1;
            let (x, y) = pos[r as usize];
            for d in 0..4 {
                let n = occ(x + DX[d], y + DY[d]);
                if n != NONE && !seen[n as usize] {
                    seen[n as usize] = true;
                    stack.push(n);
                }
            }
        }
        count == pos.len()
    }

    /// One piece, resting on the terrain.
    pub fn sound(&self) -> bool {
        self.connected_with(&self.pos, |x, y| self.robot_at(x, y))
            && (0..self.len() as u32).any(|r| self.grounded(r))
    }

    /// Checks a set of drives made together and returns each moving robot's displacement.
    pub fn check(&self, drives: &[Drive]) -> Result<Vec<(u32, usize)>, Refusal> {
        let mut dir_of = vec![usize::MAX; self.len()];
        let mut moving = Vec::new();
        for drive in drives {
            for &r in &drive.robots {
                match dir_of[r as usize] {
                    usize::MAX => {
                        dir_of[r as usize] = drive.dir;
                        moving.push((r, drive.dir));
                    }
                    d if d == drive.dir => {}
                    _ => return Err(Refusal::Conflict),
                }
            }
        }
        let new_pos = |r: u32| {
            let (x, y) = self.pos[r as usize];
            match dir_of[r as usize] {
                usize::MAX => (x, y),
                d => (x + DX[d], y + DY[d]),
            }
        };
        // Target cells: inside, not terrain, not kept by a robot that stays.
        for &(r, _) in &moving {
            let (x, y) = new_pos(r);
            let Some(i) = self.index(x, y) else {
                return Err(Refusal::Blocked);
            };
            if self.ground[i] {
                return Err(Refusal::Blocked);
            }
            let o = self.occ[i];
            if o != NONE && dir_of[o as usize] == usize::MAX {
                return Err(Refusal::Blocked);
            }
        }
        // Two moving robots may not end on one cell.
        let mut after = self.occ.clone();
        for &(r, _) in &moving {
            let (x, y) = self.pos[r as usize];
            if let Some(i) = self.index(x, y) {
                after[i] = NONE;
            }
        }
        for &(r, _) in &moving {
            let (x, y) = new_pos(r);
            let i = self.index(x, y).unwrap_or_default();
            if after[i] != NONE {
                return Err(Refusal::Blocked);
            }
            after[i] = r;
        }
        let at = |x: i32, y: i32| self.index(x, y).map_or(NONE, |i| after[i]);
        // Along the motion axis no robot meets or leaves one moving differently.
        for &(r, d) in &moving {
            let (x, y) = new_pos(r);
            for e in [d, (d + 2) % 4] {
                let ahead = at(x + DX[e], y + DY[e]);
                if ahead != NONE && dir_of[ahead as usize] != d {
                    return Err(Refusal::HeadOn);
                }
                let before = self.nbr(r, e);
                if before != NONE && dir_of[before as usize] != d {
                    return Err(Refusal::HeadOn);
                }
            }
        }
        // Each group moving together needs a fixed robot or terrain beside it to push against.
        let mut group = vec![usize::MAX; self.len()];
        let mut next = 0;
        for &(r, d) in &moving {
            if group[r as usize] != usize::MAX {
                continue;
            }
            let mut stack = vec![r];
            group[r as usize] = next;
            let mut anchored = false;
            while let Some(m) = stack.pop() {
                let (x, y) = self.pos[m as usize];
                for e in 0..4 {
                    let n = self.nbr(m, e);
                    let side = e % 2 != d % 2;
                    if n != NONE && dir_of[n as usize] == d {
                        if group[n as usize] == usize::MAX {
                            group[n as usize] = next;
                            stack.push(n);
                        }
                    } else if side && (n != NONE || self.ground_at(x + DX[e], y + DY[e])) {
                        anchored = true;
                    }
                }
            }
            if !anchored {
                return Err(Refusal::NoPartner);
            }
            next += 1;
        }
        let pos: Vec<(i32, i32)> = (0..self.len() as u32).map(new_pos).collect();
        let grounded = pos.iter().any(|&(x, y)| self.ground_at(x, y + 1));
        if !grounded || !self.connected_with(&pos, at) {
            return Err(Refusal::Disconnected);
        }
        Ok(moving)
    }

    /// Makes a checked move.
    pub fn apply(&mut self, moving: &[(u32, usize)]) {
        for &(r, _) in moving {
            let (x, y) = self.pos[r as usize];
            if let Some(i) = self.index(x, y) {
                if self.occ[i] == r {
                    self.occ[i] = NONE;
                }
            }
        }
        for &(r, d) in moving {
            let (x, y) = self.pos[r as usize];
            let p = (x + DX[d], y + DY[d]);
            self.pos[r as usize] = p;
            let i = self.index(p.0, p.1).unwrap_or_default();
            self.occ[i] = r;
        }
    }

    /// Mean x of the robots, in cells.
    pub fn centre_x(&self) -> f64 {
        self.pos.iter().map(|p| p.0 as f64).sum::<f64>() / self.len().max(1) as f64
    }
}
