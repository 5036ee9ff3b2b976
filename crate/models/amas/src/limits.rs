//! The sizes a `amas` scenario may ask for, under the page's limits and the large ones
//! ([`kumiki_model::limits`]); `kumiki schema` tables them in `docs/scenario-format.md`.

use kumiki_model::limits::{LimitRow, ModelLimits};

/// The square lattice of `amas`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AmasLimits {
    /// The largest lattice side, in cells, supply rows included.
    pub side: u32,
    /// The most supply rows.
    pub supply_rows: u32,
    /// The most stage targets before the final one.
    pub stages: usize,
    /// The most cells of all stage targets together (lattice cells × targets).
    pub stage_cells: u64,
}

/// The model's sizes; `LIMITS.of(limits)` gives those of the limits a scenario is read under.
pub const LIMITS: ModelLimits<AmasLimits> = ModelLimits {
    page: AmasLimits {
        side: 4096,
        supply_rows: 64,
        stages: 64,
        stage_cells: 1 << 26,
    },
    large: AmasLimits {
        side: 8192,
        supply_rows: 256,
        stages: 256,
        stage_cells: 1 << 28,
    },
    rows: &[
        LimitRow::new("lattice side, supply rows included", |l| l.side.into()),
        LimitRow::new("supply rows", |l| l.supply_rows.into()),
        LimitRow::new("stage targets before the final one", |l| l.stages as u64),
        LimitRow::pow2(
            "cells of all stage targets together (lattice cells × targets)",
            |l| l.stage_cells,
        ),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_a_row() {
        // Every field set to its own value: the struct literal fails to compile when a field is
        // added, and the rows must then read each value exactly once.
        let distinct = AmasLimits {
            side: 1,
            supply_rows: 2,
            stages: 3,
            stage_cells: 4,
        };
        assert!(LIMITS.reads_each_field_once(&distinct, 4));
    }
}
