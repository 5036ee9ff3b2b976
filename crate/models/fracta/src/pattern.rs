//! Bond patterns (section 3.1): the 6-bit mask of a hexagonal unit's neighbours, its images under
//! the symmetries of the hexagon, and the 60° roll about a neighbour with the cells it sweeps.
//! The connection types (`types.rs`) are the classes of these patterns; the type graph
//! (`links.rs`) follows from the rolls.

/// A rolling direction, as seen from the pivot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Turn {
    /// Counter-clockwise about the pivot: from the pivot in slot `p`, the target is slot `p - 1`.
    Ccw,
    /// Clockwise about the pivot: the target is slot `p + 1`.
    Cw,
}

impl Turn {
    pub const BOTH: [Turn; 2] = [Turn::Ccw, Turn::Cw];

    /// The pivot's slot as seen from the cell a roll about `pivot` lands in: one slot back
    /// against the turn, so that rolling on in the same turn keeps going round the same pivot.
    pub fn back(self, pivot: usize) -> usize {
        match self {
            Turn::Ccw => (pivot + 1) % 6,
            Turn::Cw => (pivot + 5) % 6,
        }
    }

    /// The slot `k` steps from `pivot` in this turn's direction of travel.
    fn slot(self, pivot: usize, k: usize) -> usize {
        match self {
            Turn::Ccw => (pivot + 6 - k) % 6,
            Turn::Cw => (pivot + k) % 6,
        }
    }
}

/// The slot a unit lands in when it rolls about its neighbour in slot `pivot`.
pub fn target_slot(pivot: usize, turn: Turn) -> usize {
    turn.slot(pivot, 1)
}

/// The neighbour slots a rolling unit sweeps, target first. Rolling about the vertex it shares
/// with the pivot and the target cell, a hexagon passes over the target, the cell beside both
/// the target and its start, the cell opposite the pivot, and one cell further out
/// ([`far_steps`]); the test suite checks this against the polygons.
pub fn swept_slots(pivot: usize, turn: Turn) -> [usize; 3] {
    [
        turn.slot(pivot, 1),
        turn.slot(pivot, 2),
        turn.slot(pivot, 3),
    ]
}

/// The one swept cell that is not a neighbour of the rolling unit: the cell beyond the target
/// and the second swept slot, reached from the unit's cell by these two steps. It does not
/// belong to the unit's connection type, so it does not decide movability; the model checks it
/// as the collision avoidance of the paper's low-level control (section 4).
pub fn far_steps(pivot: usize, turn: Turn) -> [usize; 2] {
    [turn.slot(pivot, 1), turn.slot(pivot, 2)]
}

/// Pattern `mask` turned by `k` steps of 60° counter-clockwise.
pub fn rotate(mask: u8, k: usize) -> u8 {
    let (m, k) = (u32::from(mask & 63), k % 6);
    (((m << k) | (m >> (6 - k))) & 63) as u8
}

/// Pattern `mask` mirrored in the east-west axis: direction `d` becomes `(6 - d) % 6`.
pub fn reflect(mask: u8) -> u8 {
    (0..6)
        .filter(|d| mask & (1 << d) != 0)
        .fold(0, |m, d| m | 1 << ((6 - d) % 6))
}

/// The 12 images of a pattern under the symmetries of the hexagon.
pub fn images(mask: u8) -> [u8; 12] {
    let mut out = [0; 12];
    let r = reflect(mask);
    for k in 0..6 {
        out[k] = rotate(mask, k);
        out[6 + k] = rotate(r, k);
    }
    out
}

/// The smallest image of a pattern: one representative per class.
pub fn canonical(mask: u8) -> u8 {
    images(mask).into_iter().min().unwrap_or(mask)
}

/// Number of separate arcs of consecutive bonds around the hexagon (0 for no bonds).
pub fn arcs(mask: u8) -> u32 {
    if mask & 63 == 63 {
        return 1;
    }
    (0..6)
        .filter(|&d| mask & (1 << d) != 0 && mask & (1 << ((d + 5) % 6)) == 0)
        .count() as u32
}

/// Whether a unit with neighbours `mask` may roll about its neighbour in slot `pivot`.
///
/// Section 3.1: a movable unit rotates without carrying other units and keeps the whole system
/// connected. The unit keeps its bond to the pivot and lets every other bond go; the cells it
/// sweeps ([`swept_slots`]) must be empty; and its neighbours must stay connected once it has
/// left, which they do without looking further when its bonds form one arc (each neighbour then
/// touches the next). Cells further away are not looked at: the paper decides movability from
/// the connection type alone.
pub fn roll_ok(mask: u8, pivot: usize, turn: Turn) -> bool {
    mask & (1 << pivot) != 0
        && swept_slots(pivot, turn)
            .iter()
            .all(|&s| mask & (1 << s) == 0)
        && arcs(mask) == 1
}

/// Whether some roll is possible for a unit with neighbours `mask`.
pub fn can_roll(mask: u8) -> bool {
    (0..6).any(|p| Turn::BOTH.iter().any(|&t| roll_ok(mask, p, t)))
}
