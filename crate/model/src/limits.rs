//! Every size a scenario may ask for, in one place, per model and lattice.
//!
//! Scenarios arrive from links anyone can send, so each size is computed from the text in checked
//! 64-bit arithmetic and compared with these limits before anything of that size is allocated.
//! [`Limits::PAGE`] fits what the page can draw and run responsively, and is what every
//! scenario is read under unless a caller asks otherwise; [`Limits::LARGE`] is for the command
//! line (`--allow-large`), where a run may take minutes and gigabytes. [`ROWS`] describes each
//! limit once; `kumiki schema` writes them as the table in `docs/scenario-format.md`.

/// Limits on what a scenario may ask for. A scenario read under one set of limits keeps them, so
/// its overrides and its run are checked the same way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The cells a shape text may span (rows padded to the widest), on any lattice.
    pub shape_cells: u64,
    pub amas: AmasLimits,
    pub chobie: ChobieLimits,
    pub cubes3d: Cubes3dLimits,
    pub fracta: FractaLimits,
}

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

impl Limits {
    /// What the page can draw and run responsively: every link opens under these. AMAS alone
    /// reaches 4096 a side (16 M cells, about 10 bytes a cell in the core; docs/benchmarks.md
    /// gives what the page holds and draws at that size).
    pub const PAGE: Limits = Limits {
        shape_cells: 1 << 24,
        amas: AmasLimits {
            side: 4096,
            supply_rows: 64,
            stages: 64,
            stage_cells: 1 << 26,
        },
        chobie: ChobieLimits {
            side: 2048,
            robots: 5_000,
            goal: 100_000,
        },
        cubes3d: Cubes3dLimits {
            side: 512,
            cells: 1 << 22,
            units: 100_000,
            targets: 16,
        },
        fracta: FractaLimits {
            side: 1024,
            units: 20_000,
            margin: 256,
        },
    };

    /// For the command line (`--allow-large`): sixteen times the page's cells or more, still
    /// within what one machine holds (a few gigabytes at most).
    pub const LARGE: Limits = Limits {
        shape_cells: 1 << 28,
        amas: AmasLimits {
            side: 8192,
            supply_rows: 256,
            stages: 256,
            stage_cells: 1 << 28,
        },
        chobie: ChobieLimits {
            side: 8192,
            robots: 50_000,
            goal: 1_000_000,
        },
        cubes3d: Cubes3dLimits {
            side: 1024,
            cells: 1 << 26,
            units: 1_000_000,
            targets: 64,
        },
        fracta: FractaLimits {
            side: 4096,
            units: 200_000,
            margin: 1024,
        },
    };
}

/// One limit as the documentation tables it: the model (or `every`), what it bounds, and how to
/// read it from a set of limits.
pub struct LimitRow {
    pub model: &'static str,
    pub what: &'static str,
    pub read: fn(&Limits) -> u64,
    /// Written as a power of two (`2^24`) rather than in digits.
    pub power_of_two: bool,
}

const fn row(model: &'static str, what: &'static str, read: fn(&Limits) -> u64) -> LimitRow {
    LimitRow {
        model,
        what,
        read,
        power_of_two: false,
    }
}

const fn row_pow2(model: &'static str, what: &'static str, read: fn(&Limits) -> u64) -> LimitRow {
    LimitRow {
        model,
        what,
        read,
        power_of_two: true,
    }
}

/// Every field of [`Limits`], described once (a test checks that none is left out).
pub const ROWS: &[LimitRow] = &[
    row_pow2(
        "every",
        "cells a shape text spans (width × height × layers; rows padded to the widest)",
        |l| l.shape_cells,
    ),
    row("`amas`", "lattice side, supply rows included", |l| {
        l.amas.side.into()
    }),
    row("`amas`", "supply rows", |l| l.amas.supply_rows.into()),
    row("`amas`", "stage targets before the final one", |l| {
        l.amas.stages as u64
    }),
    row_pow2(
        "`amas`",
        "cells of all stage targets together (lattice cells × targets)",
        |l| l.amas.stage_cells,
    ),
    row("`chobie`", "world side (text plus `extend`)", |l| {
        l.chobie.side.into()
    }),
    row("`chobie`", "robots", |l| l.chobie.robots as u64),
    row("`chobie`", "`goal`, cells", |l| l.chobie.goal.into()),
    row(
        "`cubes3d`",
        "side of the space (shapes, margin and padding)",
        |l| l.cubes3d.side.into(),
    ),
    row_pow2("`cubes3d`", "cells of the space", |l| l.cubes3d.cells),
    row("`cubes3d`", "units", |l| l.cubes3d.units as u64),
    row("`cubes3d`", "targets", |l| l.cubes3d.targets as u64),
    row("`fracta`", "lattice side, margin included", |l| {
        l.fracta.side.into()
    }),
    row("`fracta`", "units", |l| l.fracta.units as u64),
    row("`fracta`", "`margin`", |l| l.fracta.margin.into()),
];

impl LimitRow {
    /// The limit under `limits` as the table writes it: `2^k`, or digits with a space between
    /// thousands from 10 000 on.
    fn show(&self, limits: &Limits) -> String {
        let n = (self.read)(limits);
        if self.power_of_two && n.is_power_of_two() {
            return format!("2^{}", n.trailing_zeros());
        }
        let digits = n.to_string();
        if digits.len() < 5 {
            return digits;
        }
        let mut out = String::new();
        for (i, c) in digits.chars().enumerate() {
            if i > 0 && (digits.len() - i) % 3 == 0 {
                out.push(' ');
            }
            out.push(c);
        }
        out
    }
}

/// The limits as a Markdown table: one row of [`ROWS`] a line, page and large side by side.
pub fn markdown_table() -> String {
    let mut out = String::from("| model | what | page | large |\n| --- | --- | ---: | ---: |\n");
    for row in ROWS {
        out.push_str(&format!(
            "| {} | {} | {} | {} |\n",
            row.model,
            row.what,
            row.show(&Limits::PAGE),
            row.show(&Limits::LARGE)
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shape_text_spanning_more_cells_than_allowed_is_refused_before_it_is_allocated() {
        // One long row and many short ones describe a rectangle of 2^25 cells in 40 KB.
        let text = format!("{}\n{}", "#".repeat(1 << 12), "#\n".repeat(1 << 13));
        let page = crate::shape::parse_square_within(&text, &Limits::PAGE).unwrap_err();
        assert_eq!(
            page.to_string(),
            "the shape spans 4096 × 8193 cells, more than the 16777216 a shape may have"
        );
        assert!(crate::shape::parse_square_within(&text, &Limits::LARGE).is_ok());
    }

    #[test]
    fn the_table_has_a_row_for_every_limit() {
        // Every field set to its own value: the struct literal fails to compile when a field is
        // added, and the rows must then read each value exactly once.
        let distinct = Limits {
            shape_cells: 1,
            amas: AmasLimits {
                side: 2,
                supply_rows: 3,
                stages: 4,
                stage_cells: 5,
            },
            chobie: ChobieLimits {
                side: 6,
                robots: 7,
                goal: 8,
            },
            cubes3d: Cubes3dLimits {
                side: 9,
                cells: 10,
                units: 11,
                targets: 12,
            },
            fracta: FractaLimits {
                side: 13,
                units: 14,
                margin: 15,
            },
        };
        let mut read: Vec<u64> = ROWS.iter().map(|r| (r.read)(&distinct)).collect();
        read.sort_unstable();
        assert_eq!(read, (1..=15).collect::<Vec<u64>>());
    }

    #[test]
    fn the_table_writes_powers_of_two_and_groups_thousands() {
        let table = markdown_table();
        assert!(table.contains("| every | cells a shape text spans (width × height × layers; rows padded to the widest) | 2^24 | 2^28 |"), "{table}");
        assert!(
            table.contains("| `chobie` | robots | 5000 | 50 000 |"),
            "{table}"
        );
        assert!(
            table.contains("| `cubes3d` | units | 100 000 | 1 000 000 |"),
            "{table}"
        );
        assert_eq!(table.lines().count(), ROWS.len() + 2);
    }

    #[test]
    fn large_allows_at_least_what_the_page_allows() {
        let (p, l) = (Limits::PAGE, Limits::LARGE);
        assert!(l.shape_cells >= p.shape_cells);
        assert!(l.amas.side >= p.amas.side && l.amas.stage_cells >= p.amas.stage_cells);
        assert!(l.amas.supply_rows >= p.amas.supply_rows && l.amas.stages >= p.amas.stages);
        assert!(l.chobie.side >= p.chobie.side && l.chobie.robots >= p.chobie.robots);
        assert!(l.chobie.goal >= p.chobie.goal);
        assert!(l.cubes3d.side >= p.cubes3d.side && l.cubes3d.cells >= p.cubes3d.cells);
        assert!(l.cubes3d.units >= p.cubes3d.units && l.cubes3d.targets >= p.cubes3d.targets);
        assert!(l.fracta.side >= p.fracta.side && l.fracta.units >= p.fracta.units);
        assert!(l.fracta.margin >= p.fracta.margin);
    }
}
