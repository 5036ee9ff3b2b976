//! The sizes a `chobie` scenario may ask for, under the page's limits and the large ones
//! ([`kumiki_model::limits`]); `kumiki schema` tables them in `docs/scenario-format.md`.

use kumiki_model::limits::{LimitRow, ModelLimits};

/// The side view of `chobie`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChobieLimits {
    /// The largest world side, in cells (the world text plus `extend`).
    pub side: u32,
    /// The most robots a world may hold. The stress solve of every step costs about
    /// robots × (3 × robots across the short side)² operations, so a square block of the page's
    /// limit takes a fraction of a second per step.
    pub robots: usize,
    /// The largest goal, in cells.
    pub goal: u32,
}

/// The model's sizes; `LIMITS.of(limits)` gives those of the limits a scenario is read under.
pub const LIMITS: ModelLimits<ChobieLimits> = ModelLimits {
    page: ChobieLimits {
        side: 2048,
        robots: 5_000,
        goal: 100_000,
    },
    large: ChobieLimits {
        side: 8192,
        robots: 50_000,
        goal: 1_000_000,
    },
    rows: &[
        LimitRow::new("world side (text plus `extend`)", |l| l.side.into()),
        LimitRow::new("robots", |l| l.robots as u64),
        LimitRow::new("`goal`, cells", |l| l.goal.into()),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_a_row() {
        // Every field set to its own value: the struct literal fails to compile when a field is
        // added, and the rows must then read each value exactly once.
        let distinct = ChobieLimits {
            side: 1,
            robots: 2,
            goal: 3,
        };
        assert!(LIMITS.reads_each_field_once(&distinct, 3));
    }
}
