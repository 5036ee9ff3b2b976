//! The sizes a `fracta` scenario may ask for, under the page's limits and the large ones
//! ([`kumiki_model::limits`]); `kumiki schema` tables them in `docs/scenario-format.md`.

use kumiki_model::limits::{LimitRow, ModelLimits};

/// The hex lattice of `fracta`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FractaLimits {
    /// The largest lattice side, in cells, margin included.
    pub side: u32,
    /// The most units.
    pub units: usize,
    /// The widest margin around the start shape.
    pub margin: u32,
}

/// The model's sizes; `LIMITS.of(limits)` gives those of the limits a scenario is read under.
pub const LIMITS: ModelLimits<FractaLimits> = ModelLimits {
    page: FractaLimits {
        side: 1024,
        units: 20_000,
        margin: 256,
    },
    large: FractaLimits {
        side: 4096,
        units: 200_000,
        margin: 1024,
    },
    rows: &[
        LimitRow::new("lattice side, margin included", |l| l.side.into()),
        LimitRow::new("units", |l| l.units as u64),
        LimitRow::new("`margin`", |l| l.margin.into()),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_a_row() {
        // Every field set to its own value: the struct literal fails to compile when a field is
        // added, and the rows must then read each value exactly once.
        let distinct = FractaLimits {
            side: 1,
            units: 2,
            margin: 3,
        };
        assert!(LIMITS.reads_each_field_once(&distinct, 3));
    }
}
