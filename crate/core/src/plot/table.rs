//! A summary figure's body: its table, each column as wide as its widest cell (text columns
//! wrap past a width), and under it the comparisons, their direction stated once, each test and
//! pair on its own wrapped lines.

use super::draw::{Anchor, Drawing};
use super::figure::Figure;
use super::labels::name_of;
use super::number::format as num;
use super::svg::{paragraph, INK, MARGIN, SUMMARY_MIN_WIDTH, SUMMARY_TEXT_COLUMN};
use super::text::{width, wrap};

const HEAD: [&str; 8] = [
    "condition",
    "value",
    "n",
    "mean",
    "sd",
    "median",
    "IQR",
    "95% CI",
];

/// A summary's cells as shown: condition and value (wrapped when long), then the numbers.
fn summary_cells(f: &Figure) -> Vec<Vec<String>> {
    f.table
        .iter()
        .map(|r| {
            let value = match r.unit.as_str() {
                "" => name_of(&r.value),
                u => format!("{} [{u}]", name_of(&r.value)),
            };
            let mut cells = vec![r.condition.join(", "), value];
            match &r.stats {
                Some(s) => cells.extend([
                    s.n.to_string(),
                    num(s.mean),
                    num(s.sd),
                    num(s.median),
                    format!("{} to {}", num(s.q1), num(s.q3)),
                    format!("{} to {}", num(s.ci95[0]), num(s.ci95[1])),
                ]),
                None => cells.push("0".into()),
            }
            cells
        })
        .collect()
}

/// Each column's width: its widest cell or heading, text columns at most
/// [`SUMMARY_TEXT_COLUMN`] (their cells wrap).
fn column_widths(f: &Figure) -> [f64; 8] {
    let mut w = HEAD.map(|h| width(h, 11.0, true));
    for cells in summary_cells(f) {
        for (c, t) in cells.iter().enumerate() {
            w[c] = w[c].max(width(t, 11.0, false));
        }
    }
    w[0] = w[0].min(SUMMARY_TEXT_COLUMN);
    w[1] = w[1].min(SUMMARY_TEXT_COLUMN);
    w
}

const GAP: f64 = 18.0;

pub(super) fn width_of(f: &Figure) -> f64 {
    let w = column_widths(f);
    (2.0 * MARGIN + w.iter().sum::<f64>() + GAP * 7.0)
        .max(SUMMARY_MIN_WIDTH)
        .ceil()
}

/// The table (text columns start at their x, number columns end there), then the comparisons:
/// their direction stated once, each test and pair on its own wrapped lines.
pub(super) fn summary(d: &mut Drawing, f: &Figure, mut y: f64) -> f64 {
    let w = column_widths(f);
    let mut xs = [0.0; 8];
    let mut x = MARGIN;
    for c in 0..8 {
        xs[c] = if c >= 2 { x + w[c] } else { x };
        x += w[c] + GAP;
    }
    y += 12.0;
    for (c, h) in HEAD.iter().enumerate() {
        let anchor = if c >= 2 { Anchor::End } else { Anchor::Start };
        d.text(xs[c], y, 11.0, true, anchor, INK, *h);
    }
    for cells in summary_cells(f) {
        y += 16.0;
        let mut lines = 1;
        for (c, t) in cells.iter().enumerate() {
            match c {
                0 | 1 => {
                    let wrapped = wrap(t, 11.0, false, w[c]);
                    lines = lines.max(wrapped.len());
                    for (k, line) in wrapped.into_iter().enumerate() {
                        d.text(
                            xs[c],
                            y + 14.0 * k as f64,
                            11.0,
                            false,
                            Anchor::Start,
                            INK,
                            line,
                        );
                    }
                }
                _ => d.text(xs[c], y, 11.0, false, Anchor::End, INK, t.clone()),
            }
        }
        y += 14.0 * (lines - 1) as f64;
    }
    if f.comparisons.is_empty() && f.omnibus.is_empty() {
        return y + 8.0;
    }
    y += 12.0;
    let direction = format!("Comparisons: {}.", f.direction);
    y = paragraph(d, &direction, 11.0, true, INK, y, 15.0);
    for o in &f.omnibus {
        let t = &o.test;
        let text = format!(
            "{}: Kruskal-Wallis H = {}, df = {}, p = {} ({} conditions, n = {})",
            name_of(&o.value),
            num(t.h),
            t.df,
            num(t.p),
            o.conditions.len(),
            t.n
        );
        y = paragraph(d, &text, 11.0, false, INK, y + 2.0, 15.0);
    }
    for c in &f.comparisons {
        let k = &c.comparison;
        let holm = c.p_holm.map_or(String::new(), |p| {
            format!(", Holm-corrected p = {}", num(p))
        });
        let text = format!(
            "{}: {} minus {}: difference {}, Cohen's d {}, rank-biserial {}, Mann-Whitney U {} (p = {}, {}{holm})",
            name_of(&c.value),
            c.conditions[0],
            c.conditions[1],
            num(k.difference),
            num(k.cohens_d),
            num(k.rank_biserial),
            num(k.u),
            num(k.p),
            k.method
        );
        y = paragraph(d, &text, 11.0, false, INK, y + 2.0, 15.0);
    }
    y + 4.0
}
