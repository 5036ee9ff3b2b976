//! The sizes a `cubes3d` scenario may ask for, under the page's limits and the large ones
//! ([`kumiki_model::limits`]); `kumiki schema` tables them in `docs/scenario-format.md`.

use kumiki_model::limits::{LimitRow, ModelLimits};

/// The cubic lattice of `cubes3d`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cubes3dLimits {
    /// The largest side of the space, in cells (margin and padding included).
    pub side: u32,
    /// The most cells the space may have.
    pub cells: u64,
    /// The most units a structure may have.
    pub units: usize,
    /// The most targets a scenario may switch between.
    pub targets: usize,
}

/// The model's sizes; `LIMITS.of(limits)` gives those of the limits a scenario is read under.
pub const LIMITS: ModelLimits<Cubes3dLimits> = ModelLimits {
    page: Cubes3dLimits {
        side: 512,
        cells: 1 << 22,
        units: 100_000,
        targets: 16,
    },
    large: Cubes3dLimits {
        side: 1024,
        cells: 1 << 26,
        units: 1_000_000,
        targets: 64,
    },
    rows: &[
        LimitRow::new("side of the space (shapes, margin and padding)", |l| {
            l.side.into()
        }),
        LimitRow::pow2("cells of the space", |l| l.cells),
        LimitRow::new("units", |l| l.units as u64),
        LimitRow::new("targets", |l| l.targets as u64),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_a_row() {
        // Every field set to its own value: the struct literal fails to compile when a field is
        // added, and the rows must then read each value exactly once.
        let distinct = Cubes3dLimits {
            side: 1,
            cells: 2,
            units: 3,
            targets: 4,
        };
        assert!(LIMITS.reads_each_field_once(&distinct, 4));
    }
}
