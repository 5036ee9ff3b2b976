//! Every size a scenario may ask for: one bound every model shares (the cells a shape text may
//! span) and each model's own, declared in its crate ([`ModelLimits`]) and found through its
//! registry entry.
//!
//! Scenarios arrive from links anyone can send, so each size is computed from the text in checked
//! 64-bit arithmetic and compared with these limits before anything of that size is allocated.
//! [`Limits::PAGE`] fits what the page can draw and run responsively, and is what every
//! scenario is read under unless a caller asks otherwise; [`Limits::LARGE`] is for the command
//! line (`--allow-large`), where a run may take minutes and gigabytes. A model's sizes come in the
//! same two scales, and each is described once by a [`LimitRow`]; `kumiki schema` writes them all
//! as the table in `docs/scenario-format.md`.

/// Limits on what a scenario may ask for. A scenario read under one set of limits keeps them, so
/// its overrides and its run are checked the same way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The cells a shape text may span (rows padded to the widest), on any lattice.
    pub shape_cells: u64,
    /// Which of each model's own limits apply ([`ModelLimits::of`]).
    pub scale: Scale,
}

/// The two scales of limits: the page's, and the command line's larger ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    Page,
    Large,
}

impl Limits {
    /// What the page can draw and run responsively: every link opens under these. AMAS alone
    /// reaches 4096 a side (16 M cells, about 10 bytes a cell in the core; docs/benchmarks.md
    /// gives what the page holds and draws at that size).
    pub const PAGE: Limits = Limits {
        shape_cells: 1 << 24,
        scale: Scale::Page,
    };

    /// For the command line (`--allow-large`): sixteen times the page's cells or more, still
    /// within what one machine holds (a few gigabytes at most).
    pub const LARGE: Limits = Limits {
        shape_cells: 1 << 28,
        scale: Scale::Large,
    };
}

/// A model's own limits: its sizes `L` under the page's limits and under the large ones, and one
/// row per size for the documentation. A model crate declares one and names it in its entry.
pub struct ModelLimits<L: 'static> {
    pub page: L,
    pub large: L,
    /// Every field of `L`, described once (the model's test checks, with
    /// [`ModelLimits::reads_each_field_once`], that none is left out).
    pub rows: &'static [LimitRow<L>],
}

impl<L> ModelLimits<L> {
    /// The model's sizes under `limits`.
    #[inline]
    pub const fn of(&self, limits: &Limits) -> &L {
        match limits.scale {
            Scale::Page => &self.page,
            Scale::Large => &self.large,
        }
    }

    /// Whether the rows read each field of `distinct` exactly once, when its `fields` fields hold
    /// 1, 2, …, `fields`: written as a struct literal in the model's test, it stops compiling
    /// when a field is added, and this then fails until the field has its row.
    pub fn reads_each_field_once(&self, distinct: &L, fields: u64) -> bool {
        let mut read: Vec<u64> = self.rows.iter().map(|r| (r.read)(distinct)).collect();
        read.sort_unstable();
        read == (1..=fields).collect::<Vec<u64>>()
    }
}

/// One limit as the documentation tables it: what it bounds, and how to read it from a model's
/// sizes.
pub struct LimitRow<L> {
    pub what: &'static str,
    pub read: fn(&L) -> u64,
    /// Written as a power of two (`2^24`) rather than in digits.
    pub power_of_two: bool,
}

impl<L> LimitRow<L> {
    /// A limit written in digits.
    pub const fn new(what: &'static str, read: fn(&L) -> u64) -> LimitRow<L> {
        LimitRow {
            what,
            read,
            power_of_two: false,
        }
    }

    /// A limit written as a power of two.
    pub const fn pow2(what: &'static str, read: fn(&L) -> u64) -> LimitRow<L> {
        LimitRow {
            what,
            read,
            power_of_two: true,
        }
    }
}

/// A model's limits as the table shows them, whatever the type of its sizes: what a
/// [`ModelEntry`](crate::entry::ModelEntry) holds.
pub trait LimitTable: Sync {
    /// One line per row: what it bounds, the page's value and the large one.
    fn lines(&self) -> Vec<TableLine>;
}

impl<L: Sync> LimitTable for ModelLimits<L> {
    fn lines(&self) -> Vec<TableLine> {
        self.rows
            .iter()
            .map(|r| TableLine {
                what: r.what,
                page: (r.read)(&self.page),
                large: (r.read)(&self.large),
                power_of_two: r.power_of_two,
            })
            .collect()
    }
}

/// One line of the limits table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableLine {
    pub what: &'static str,
    pub page: u64,
    pub large: u64,
    /// Written as a power of two (`2^24`) rather than in digits.
    pub power_of_two: bool,
}

impl TableLine {
    /// The line of the bound every model shares.
    pub fn shape_cells() -> TableLine {
        TableLine {
            what: "cells a shape text spans (width × height × layers; rows padded to the widest)",
            page: Limits::PAGE.shape_cells,
            large: Limits::LARGE.shape_cells,
            power_of_two: true,
        }
    }

    /// The line as the table writes it, for `model` (`every` or a model's name in backticks).
    pub fn markdown(&self, model: &str) -> String {
        format!(
            "| {model} | {} | {} | {} |\n",
            self.what,
            self.show(self.page),
            self.show(self.large)
        )
    }

    /// A value as the table writes it: `2^k`, or digits with a space between thousands from
    /// 10 000 on.
    fn show(&self, n: u64) -> String {
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

    #[derive(Clone, Copy)]
    struct Sizes {
        side: u32,
        cells: u64,
    }

    const SIZES: ModelLimits<Sizes> = ModelLimits {
        page: Sizes {
            side: 512,
            cells: 1 << 22,
        },
        large: Sizes {
            side: 12_345,
            cells: 1 << 26,
        },
        rows: &[
            LimitRow::new("side", |l| l.side.into()),
            LimitRow::pow2("cells", |l| l.cells),
        ],
    };

    #[test]
    fn a_model_reads_its_sizes_of_the_scale_in_force() {
        assert_eq!(SIZES.of(&Limits::PAGE).side, 512);
        assert_eq!(SIZES.of(&Limits::LARGE).side, 12_345);
        assert!(SIZES.reads_each_field_once(&Sizes { side: 1, cells: 2 }, 2));
        assert!(!SIZES.reads_each_field_once(&Sizes { side: 1, cells: 2 }, 3));
    }

    #[test]
    fn a_table_line_writes_powers_of_two_and_groups_thousands() {
        let lines: Vec<String> = SIZES.lines().iter().map(|l| l.markdown("`m`")).collect();
        assert_eq!(lines[0], "| `m` | side | 512 | 12 345 |\n");
        assert_eq!(lines[1], "| `m` | cells | 2^22 | 2^26 |\n");
        assert_eq!(
            TableLine::shape_cells().markdown("every"),
            "| every | cells a shape text spans (width × height × layers; rows padded to the widest) | 2^24 | 2^28 |\n"
        );
    }
}
