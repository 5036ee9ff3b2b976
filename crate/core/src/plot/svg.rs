//! A [`Figure`] laid out for publishing: the title, a "partial" mark for a cancelled sweep, what
//! is drawn in words, one panel per facet on one shared y axis (said under the legend), labelled
//! axes (units in brackets; the y label once for all panels), the series with their bands or
//! whiskers, a legend in words, and for a summary its table and comparisons, with the direction
//! of every signed figure stated once. Every text is measured with the figures' font and wrapped
//! or given room, so nothing is clipped at any length; [`svg`] writes the layout as SVG and
//! [`super::pdf::pdf`] as PDF. The page shows and exports the SVG; `kumiki sweep --plot` writes
//! either.

use super::draw::{Anchor, Drawing, Item, Text};
use super::figure::{Figure, FigureKind, Panel};
use super::labels::{spread_words, statistic_words};
use super::number::format as num;
use super::table;
use super::text::{width, wrap};
use super::Spread;

pub use super::draw::escape;

pub const COLORS: [&str; 10] = [
    "#2b6cb0", "#d9822b", "#0f9960", "#c23030", "#7157d9", "#29a634", "#a67908", "#d13913",
    "#00998c", "#634dbf",
];
pub(super) const INK: &str = "#1f2933";
const MUTED: &str = "#52606d";
const GRID: &str = "#d9e2ec";
const WARN: &str = "#c23030";
const WIDTH: f64 = 720.0;
/// The canvas's margin left and right of every text.
pub(super) const MARGIN: f64 = 16.0;
const RIGHT: f64 = 24.0;
const PLOT_H: f64 = 240.0;
pub(super) const SUMMARY_MIN_WIDTH: f64 = 640.0;
/// The widest a summary's text column grows before its cells wrap.
pub(super) const SUMMARY_TEXT_COLUMN: f64 = 240.0;

/// The figure as an SVG document.
pub fn svg(f: &Figure) -> String {
    layout(f).svg()
}

/// The figure laid out on its canvas.
pub fn layout(f: &Figure) -> Drawing {
    let width = match f.kind {
        FigureKind::Summary => table::width_of(f),
        _ => WIDTH,
    };
    let mut d = Drawing {
        width,
        height: 0.0,
        title: f.title.clone(),
        desc: f.described.clone(),
        items: Vec::new(),
    };
    let mut y = 10.0;
    y = paragraph(&mut d, &f.title, 17.0, true, INK, y, 22.0);
    if let Some(p) = f.partial {
        y = paragraph(
            &mut d,
            &format!("{} (cancelled)", p.words()),
            13.0,
            true,
            WARN,
            y,
            17.0,
        );
    }
    y = paragraph(&mut d, &f.described, 12.0, false, MUTED, y, 16.0);
    y += 6.0;
    y = match f.kind {
        FigureKind::Summary => table::summary(&mut d, f, y),
        _ => charts(&mut d, f, y),
    };
    d.height = (y + 12.0).ceil();
    d
}

/// Wrapped text from the left margin, one line every `leading`, the first line's top at `top`;
/// returns the top of what follows.
#[allow(clippy::too_many_arguments)]
pub(super) fn paragraph(
    d: &mut Drawing,
    text: &str,
    size: f64,
    bold: bool,
    fill: &'static str,
    top: f64,
    leading: f64,
) -> f64 {
    if text.is_empty() {
        return top;
    }
    let mut y = top;
    for line in wrap(text, size, bold, d.width - 2.0 * MARGIN) {
        d.text(MARGIN, y + size, size, bold, Anchor::Start, fill, line);
        y += leading;
    }
    y
}

/// Round tick values covering `lo..hi` (1, 2 or 5 times a power of ten apart).
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = (hi - lo).max(1e-12);
    let raw = span / 5.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| span / s <= 6.0)
        .unwrap_or(10.0 * mag);
    let mut t = (lo / step).ceil() * step;
    let mut out = Vec::new();
    while t <= hi + step * 1e-9 {
        out.push(if t.abs() < step * 1e-9 { 0.0 } else { t });
        t += step;
    }
    out
}

struct Scale {
    lo: f64,
    hi: f64,
    log: bool,
    from: f64,
    to: f64,
}

impl Scale {
    fn at(&self, v: f64) -> f64 {
        let (lo, hi, v) = match self.log {
            true => (self.lo.log10(), self.hi.log10(), v.max(self.lo).log10()),
            false => (self.lo, self.hi, v),
        };
        self.from + (v - lo) / (hi - lo).max(1e-12) * (self.to - self.from)
    }
}

/// The y range every panel shares, and its ticks; `None` when nothing has a value.
fn y_axis(f: &Figure) -> Option<(f64, f64, Vec<f64>)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for pt in f
        .panels
        .iter()
        .flat_map(|p| p.series.iter().flat_map(|s| s.points.iter()))
    {
        for v in [Some(pt.y), pt.band.map(|b| b[0]), pt.band.map(|b| b[1])]
            .into_iter()
            .flatten()
        {
            if v.is_finite() && (!f.log_y || v > 0.0) {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if !lo.is_finite() {
        return None;
    }
    if matches!(f.kind, FigureKind::Bars | FigureKind::Histogram) {
        lo = lo.min(0.0);
    }
    if hi <= lo {
        hi = lo + 1.0;
    }
    Some(match f.log_y {
        true => {
            let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
            let b = b.max(a + 1);
            (
                10f64.powi(a),
                10f64.powi(b),
                (a..=b).map(|e| 10f64.powi(e)).collect(),
            )
        }
        false => {
            let t = ticks(lo, hi);
            (lo.min(t[0]), hi.max(*t.last().unwrap_or(&hi)), t)
        }
    })
}

/// Every panel on one y axis, the y label once beside them all, then the legend and notes.
fn charts(d: &mut Drawing, f: &Figure, top: f64) -> f64 {
    let Some((ylo, yhi, yticks)) = y_axis(f) else {
        d.text(
            MARGIN,
            top + 14.0,
            12.0,
            false,
            Anchor::Start,
            MUTED,
            "No values to draw.",
        );
        return top + 24.0;
    };
    let tick_w = yticks
        .iter()
        .map(|t| width(&num(*t), 11.0, false))
        .fold(0.0, f64::max);
    // The y label's lines stand beside the ticks, each turned to read upwards, centred on the
    // panels; wrapped to one plot's height, they never run past the panels.
    let label_lines = wrap(&f.y_label, 12.0, false, PLOT_H);
    let left = MARGIN + 15.0 * label_lines.len() as f64 + 8.0 + tick_w + 6.0;
    let mut y = top;
    let mut span = (f64::INFINITY, top);
    for p in &f.panels {
        let (plot_top, plot_bottom, next) = panel(d, f, p, y, left, (ylo, yhi, &yticks));
        span = (span.0.min(plot_top), plot_bottom);
        y = next;
    }
    let mid = (span.0 + span.1) / 2.0;
    for (i, line) in label_lines.into_iter().enumerate() {
        d.items.push(Item::Text(Text {
            x: MARGIN + 9.0 + 15.0 * i as f64,
            y: mid,
            size: 12.0,
            bold: false,
            anchor: Anchor::Middle,
            fill: INK,
            text: line,
            rotated: true,
        }));
    }
    legend(d, f, y)
}

/// One panel: its title, grid, ticks, x label and series. Returns the plot's top and bottom and
/// the top of what follows.
fn panel(
    d: &mut Drawing,
    f: &Figure,
    p: &Panel,
    mut y: f64,
    left: f64,
    (ylo, yhi, yticks): (f64, f64, &[f64]),
) -> (f64, f64, f64) {
    // A panel's title stands over its plot, clear of the y label beside the panels.
    if !p.title.is_empty() {
        y += 4.0;
        for line in wrap(&p.title, 13.0, true, d.width - left - MARGIN) {
            d.text(left, y + 13.0, 13.0, true, Anchor::Start, INK, line);
            y += 17.0;
        }
    }
    y += 8.0;
    let (top, bottom) = (y, y + PLOT_H);
    let right = d.width - RIGHT;
    let (mut xlo, mut xhi) = (f64::INFINITY, f64::NEG_INFINITY);
    for pt in p.series.iter().flat_map(|s| s.points.iter()) {
        xlo = xlo.min(pt.x);
        xhi = xhi.max(pt.x);
    }
    if !xlo.is_finite() {
        d.text(
            left,
            top + 16.0,
            12.0,
            false,
            Anchor::Start,
            MUTED,
            "No values to draw.",
        );
        return (top, top + 20.0, top + 28.0);
    }
    if let Some(w) = p.bin_width {
        xlo -= w / 2.0;
        xhi += w / 2.0;
    }
    if f.kind == FigureKind::Bars {
        xlo = -0.5;
        xhi = p.categories.len() as f64 - 0.5;
    }
    if xhi <= xlo {
        xlo -= 0.5;
        xhi += 0.5;
    }
    let xs = Scale {
        lo: xlo,
        hi: xhi,
        log: false,
        from: left,
        to: right,
    };
    let ys = Scale {
        lo: ylo,
        hi: yhi,
        log: f.log_y,
        from: bottom,
        to: top,
    };
    for t in yticks {
        let yy = ys.at(*t);
        d.line((left, yy), (right, yy), GRID);
        d.text(
            left - 6.0,
            yy + 4.0,
            11.0,
            false,
            Anchor::End,
            MUTED,
            num(*t),
        );
    }
    let xticks: Vec<(f64, String)> = match f.kind {
        FigureKind::Bars => p
            .categories
            .iter()
            .enumerate()
            .map(|(i, c)| (i as f64, c.clone()))
            .collect(),
        _ => ticks(xlo, xhi).into_iter().map(|t| (t, num(t))).collect(),
    };
    for (t, label) in &xticks {
        let xx = xs.at(*t);
        d.line((xx, bottom), (xx, bottom + 4.0), MUTED);
        // A long label is moved in to stay on the canvas.
        let half = width(label, 11.0, false) / 2.0;
        let at = xx.clamp(MARGIN + half, d.width - MARGIN - half);
        d.text(
            at,
            bottom + 16.0,
            11.0,
            false,
            Anchor::Middle,
            MUTED,
            label.clone(),
        );
    }
    d.line((left, bottom), (right, bottom), MUTED);
    d.line((left, top), (left, bottom), MUTED);
    let mut y_after = bottom + 22.0;
    for line in wrap(&f.x_label, 12.0, false, right - left) {
        d.text(
            (left + right) / 2.0,
            y_after + 12.0,
            12.0,
            false,
            Anchor::Middle,
            INK,
            line,
        );
        y_after += 15.0;
    }
    series(d, f, p, &xs, &ys, ylo);
    (top, bottom, y_after + 10.0)
}

/// Every series label of the figure, in the order the legend lists them: a series has one colour
/// in every panel, the legend's.
fn labels(f: &Figure) -> Vec<&str> {
    let mut labels: Vec<&str> = Vec::new();
    for p in &f.panels {
        for s in &p.series {
            if !labels.contains(&s.label.as_str()) {
                labels.push(&s.label);
            }
        }
    }
    labels
}

fn color_of(f: &Figure, label: &str) -> &'static str {
    let i = labels(f).iter().position(|l| *l == label).unwrap_or(0);
    COLORS[i % COLORS.len()]
}

fn series(d: &mut Drawing, f: &Figure, p: &Panel, xs: &Scale, ys: &Scale, ylo: f64) {
    let groups = p.series.len().max(1) as f64;
    for (i, s) in p.series.iter().enumerate() {
        let color = color_of(f, &s.label);
        d.items.push(Item::Group(s.label.clone()));
        match f.kind {
            FigureKind::Bars | FigureKind::Histogram => {
                let slot = match p.bin_width {
                    Some(w) => (xs.at(w) - xs.at(0.0)).abs(),
                    None => (xs.at(1.0) - xs.at(0.0)) * 0.8 / groups,
                };
                for pt in &s.points {
                    let x0 = match p.bin_width {
                        Some(_) => xs.at(pt.x) - slot / 2.0,
                        None => xs.at(pt.x) - (xs.at(1.0) - xs.at(0.0)) * 0.4 + slot * i as f64,
                    };
                    let (y0, y1) = (ys.at(pt.y), ys.at(ylo.max(0.0)));
                    d.items.push(Item::Rect {
                        x: x0,
                        y: y0.min(y1),
                        w: slot * 0.92,
                        h: (y1 - y0).abs(),
                        fill: color,
                        data: format!(" data-y=\"{}\" data-n=\"{}\"", pt.y, pt.n),
                    });
                    if let Some([lo, hi]) = pt.band {
                        let xm = x0 + slot * 0.46;
                        d.items.push(Item::Line {
                            from: (xm, ys.at(lo)),
                            to: (xm, ys.at(hi)),
                            stroke: INK,
                            data: format!(" data-band=\"{lo} {hi}\""),
                        });
                    }
                }
            }
            _ => {
                let banded: Vec<_> = s
                    .points
                    .iter()
                    .filter_map(|pt| pt.band.map(|b| (pt.x, b)))
                    .collect();
                if banded.len() == s.points.len() && !banded.is_empty() {
                    let mut points: Vec<(f64, f64)> = banded
                        .iter()
                        .map(|(x, b)| (xs.at(*x), ys.at(b[1])))
                        .collect();
                    points.extend(banded.iter().rev().map(|(x, b)| (xs.at(*x), ys.at(b[0]))));
                    d.items.push(Item::Band {
                        points,
                        fill: color,
                    });
                }
                d.items.push(Item::Polyline {
                    points: s
                        .points
                        .iter()
                        .map(|pt| (xs.at(pt.x), ys.at(pt.y)))
                        .collect(),
                    stroke: color,
                });
                if s.points.len() < 40 {
                    for pt in &s.points {
                        let band = pt.band.map_or(String::new(), |[lo, hi]| {
                            format!(" data-band=\"{lo} {hi}\"")
                        });
                        d.items.push(Item::Circle {
                            at: (xs.at(pt.x), ys.at(pt.y)),
                            r: 3.0,
                            fill: color,
                            data: format!(
                                " data-x=\"{}\" data-y=\"{}\" data-n=\"{}\"{band}",
                                pt.x, pt.y, pt.n
                            ),
                        });
                    }
                }
            }
        }
        d.items.push(Item::End);
    }
}

/// The legend, each label beside its colour (wrapped when it is longer than a line), then what
/// the lines and bands are and, with facets, that the panels share their y axis.
fn legend(d: &mut Drawing, f: &Figure, mut y: f64) -> f64 {
    let labels = labels(f);
    let room = d.width - 2.0 * MARGIN - 19.0;
    let mut x = MARGIN;
    y += 4.0;
    for (i, label) in labels.iter().enumerate() {
        let lines = wrap(label, 12.0, false, room);
        let w = 19.0
            + lines
                .iter()
                .map(|l| width(l, 12.0, false))
                .fold(0.0, f64::max)
            + 14.0;
        if x + w > d.width - MARGIN && x > MARGIN {
            x = MARGIN;
            y += 18.0;
        }
        d.items.push(Item::Rect {
            x,
            y: y + 3.0,
            w: 14.0,
            h: 10.0,
            fill: COLORS[i % COLORS.len()],
            data: String::new(),
        });
        for (k, line) in lines.iter().enumerate() {
            d.text(
                x + 19.0,
                y + 12.0 + 15.0 * k as f64,
                12.0,
                false,
                Anchor::Start,
                INK,
                line.clone(),
            );
        }
        y += 15.0 * (lines.len() - 1) as f64;
        x += w;
    }
    y += 20.0;
    if let (Some(st), Some(sp)) = (f.statistic, f.spread) {
        let what = match (f.kind, sp) {
            (_, Spread::None) => format!("{}s; no spread drawn", statistic_words(st)),
            (FigureKind::Bars, sp) => format!(
                "bars: {}s; whiskers: {}",
                statistic_words(st),
                spread_words(sp)
            ),
            (_, sp) => format!(
                "lines: {}s; bands: {}",
                statistic_words(st),
                spread_words(sp)
            ),
        };
        y = paragraph(d, &what, 12.0, false, MUTED, y, 16.0);
    }
    if f.panels.len() > 1 {
        y = paragraph(
            d,
            "The panels share one y axis.",
            12.0,
            false,
            MUTED,
            y,
            16.0,
        );
    }
    y
}
