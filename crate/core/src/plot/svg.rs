//! A [`Figure`] as a standalone SVG document: the title and what is drawn in words, one panel
//! per facet with labelled axes (units in brackets), the series in the palette with their bands
//! or whiskers, and a legend in words. The page shows and exports this text; `kumiki sweep
//! --plot svg` writes it.

use std::fmt::Write;

use super::figure::{Figure, FigureKind, Panel};
use super::labels::{name_of, spread_words, statistic_words};
use super::Spread;

pub const COLORS: [&str; 10] = [
    "#2b6cb0", "#d9822b", "#0f9960", "#c23030", "#7157d9", "#29a634", "#a67908", "#d13913",
    "#00998c", "#634dbf",
];
const WIDTH: f64 = 720.0;
const LEFT: f64 = 78.0;
const RIGHT: f64 = 24.0;
const PLOT_H: f64 = 240.0;
const SUMMARY_WIDTH: f64 = 820.0;
const FONT: &str = "font-family=\"system-ui, -apple-system, Segoe UI, Roboto, sans-serif\"";

/// Text for SVG: `&`, `<`, `>` and `"` escaped.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number as an axis or table shows it: up to 4 significant digits, no trailing zeros.
pub fn short_number(v: f64) -> String {
    if !v.is_finite() {
        return "–".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e6).contains(&a) {
        return format!("{v:.2e}");
    }
    let digits = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
    let s = format!("{v:.digits$}");
    match s.contains('.') {
        true => s.trim_end_matches('0').trim_end_matches('.').to_string(),
        false => s,
    }
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

/// The figure as an SVG document.
pub fn svg(f: &Figure) -> String {
    let mut body = String::new();
    let mut y = 28.0;
    let _ = writeln!(body, "<text x=\"{LEFT}\" y=\"{y}\" font-size=\"17\" font-weight=\"600\" fill=\"#1f2933\">{}</text>", escape(&f.title));
    y += 20.0;
    let _ = writeln!(
        body,
        "<text x=\"{LEFT}\" y=\"{y}\" font-size=\"12\" fill=\"#52606d\">{}</text>",
        escape(&f.described)
    );
    y += 16.0;
    if f.kind == FigureKind::Summary {
        y = summary(&mut body, f, y);
    } else {
        for p in &f.panels {
            y = panel(&mut body, f, p, y);
        }
        y = legend(&mut body, f, y);
    }
    let height = y + 12.0;
    let width = if f.kind == FigureKind::Summary {
        SUMMARY_WIDTH
    } else {
        WIDTH
    };
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" {FONT} role=\"img\">\n<title>{}</title>\n<desc>{}</desc>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n{body}</svg>\n",
        escape(&f.title),
        escape(&f.described)
    )
}

fn panel(out: &mut String, f: &Figure, p: &Panel, mut y: f64) -> f64 {
    if !p.title.is_empty() {
        y += 18.0;
        let _ = writeln!(out, "<text x=\"{LEFT}\" y=\"{y}\" font-size=\"13\" font-weight=\"600\" fill=\"#1f2933\">{}</text>", escape(&p.title));
    }
    y += 10.0;
    let top = y;
    let bottom = y + PLOT_H;
    let points = p.series.iter().flat_map(|s| s.points.iter());
    let (mut xlo, mut xhi, mut ylo, mut yhi) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for pt in points {
        xlo = xlo.min(pt.x);
        xhi = xhi.max(pt.x);
        for v in [Some(pt.y), pt.band.map(|b| b[0]), pt.band.map(|b| b[1])]
            .into_iter()
            .flatten()
        {
            if v.is_finite() && (!f.log_y || v > 0.0) {
                ylo = ylo.min(v);
                yhi = yhi.max(v);
            }
        }
    }
    if !xlo.is_finite() {
        let _ = writeln!(out, "<text x=\"{LEFT}\" y=\"{}\" font-size=\"12\" fill=\"#52606d\">No values to draw.</text>", top + 16.0);
        return top + 28.0;
    }
    let bars = f.kind == FigureKind::Bars || f.kind == FigureKind::Histogram;
    if bars {
        ylo = ylo.min(0.0);
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
    if yhi <= ylo {
        yhi = ylo + 1.0;
    }
    let yticks: Vec<f64> = match f.log_y {
        true => {
            let (a, b) = (ylo.log10().floor() as i32, yhi.log10().ceil() as i32);
            ylo = 10f64.powi(a);
            yhi = 10f64.powi(b.max(a + 1));
            (a..=b.max(a + 1)).map(|e| 10f64.powi(e)).collect()
        }
        false => {
            let t = ticks(ylo, yhi);
            ylo = ylo.min(t[0]);
            yhi = yhi.max(*t.last().unwrap_or(&yhi));
            t
        }
    };
    let xs = Scale {
        lo: xlo,
        hi: xhi,
        log: false,
        from: LEFT,
        to: WIDTH - RIGHT,
    };
    let ys = Scale {
        lo: ylo,
        hi: yhi,
        log: f.log_y,
        from: bottom,
        to: top,
    };
    for t in &yticks {
        let yy = ys.at(*t);
        let _ = writeln!(
            out,
            "<line x1=\"{LEFT}\" x2=\"{}\" y1=\"{yy:.1}\" y2=\"{yy:.1}\" stroke=\"#d9e2ec\"/>",
            WIDTH - RIGHT
        );
        let _ = writeln!(out, "<text x=\"{}\" y=\"{:.1}\" font-size=\"11\" text-anchor=\"end\" fill=\"#52606d\">{}</text>", LEFT - 6.0, yy + 4.0, short_number(*t));
    }
    let xticks: Vec<(f64, String)> = match f.kind {
        FigureKind::Bars => p
            .categories
            .iter()
            .enumerate()
            .map(|(i, c)| (i as f64, c.clone()))
            .collect(),
        _ => ticks(xlo, xhi)
            .into_iter()
            .map(|t| (t, short_number(t)))
            .collect(),
    };
    for (t, label) in &xticks {
        let xx = xs.at(*t);
        let _ = writeln!(
            out,
            "<line x1=\"{xx:.1}\" x2=\"{xx:.1}\" y1=\"{bottom}\" y2=\"{}\" stroke=\"#52606d\"/>",
            bottom + 4.0
        );
        let _ = writeln!(out, "<text x=\"{xx:.1}\" y=\"{}\" font-size=\"11\" text-anchor=\"middle\" fill=\"#52606d\">{}</text>", bottom + 16.0, escape(label));
    }
    let _ = writeln!(
        out,
        "<line x1=\"{LEFT}\" x2=\"{}\" y1=\"{bottom}\" y2=\"{bottom}\" stroke=\"#52606d\"/>",
        WIDTH - RIGHT
    );
    let _ = writeln!(
        out,
        "<line x1=\"{LEFT}\" x2=\"{LEFT}\" y1=\"{top}\" y2=\"{bottom}\" stroke=\"#52606d\"/>"
    );
    let _ = writeln!(out, "<text x=\"{:.1}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\" fill=\"#1f2933\">{}</text>", (LEFT + WIDTH - RIGHT) / 2.0, bottom + 34.0, escape(&f.x_label));
    let mid = (top + bottom) / 2.0;
    let _ = writeln!(out, "<text x=\"16\" y=\"{mid:.1}\" font-size=\"12\" text-anchor=\"middle\" fill=\"#1f2933\" transform=\"rotate(-90 16 {mid:.1})\">{}</text>", escape(&f.y_label));
    let groups = p.series.len().max(1) as f64;
    for (i, s) in p.series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let _ = writeln!(out, "<g data-series=\"{}\">", escape(&s.label));
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
                    let _ = writeln!(out, "<rect x=\"{x0:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{color}\" data-y=\"{}\" data-n=\"{}\"/>", y0.min(y1), slot * 0.92, (y1 - y0).abs(), pt.y, pt.n);
                    if let Some([lo, hi]) = pt.band {
                        let xm = x0 + slot * 0.46;
                        let _ = writeln!(out, "<line x1=\"{xm:.1}\" x2=\"{xm:.1}\" y1=\"{:.1}\" y2=\"{:.1}\" stroke=\"#1f2933\" data-band=\"{lo} {hi}\"/>", ys.at(lo), ys.at(hi));
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
                    let mut d = String::new();
                    for (k, (x, b)) in banded.iter().enumerate() {
                        let _ = write!(
                            d,
                            "{}{:.1},{:.1}",
                            if k == 0 { "M" } else { " L" },
                            xs.at(*x),
                            ys.at(b[1])
                        );
                    }
                    for (x, b) in banded.iter().rev() {
                        let _ = write!(d, " L{:.1},{:.1}", xs.at(*x), ys.at(b[0]));
                    }
                    let _ = writeln!(out, "<path d=\"{d} Z\" fill=\"{color}\" fill-opacity=\"0.15\" stroke=\"none\"/>");
                }
                let line: Vec<String> = s
                    .points
                    .iter()
                    .map(|pt| format!("{:.1},{:.1}", xs.at(pt.x), ys.at(pt.y)))
                    .collect();
                let _ = writeln!(
                    out,
                    "<polyline points=\"{}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>",
                    line.join(" ")
                );
                if s.points.len() < 40 {
                    for pt in &s.points {
                        let band = pt.band.map_or(String::new(), |[lo, hi]| {
                            format!(" data-band=\"{lo} {hi}\"")
                        });
                        let _ = writeln!(out, "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3\" fill=\"{color}\" data-x=\"{}\" data-y=\"{}\" data-n=\"{}\"{band}/>", xs.at(pt.x), ys.at(pt.y), pt.x, pt.y, pt.n);
                    }
                }
            }
        }
        let _ = writeln!(out, "</g>");
    }
    bottom + 44.0
}

fn legend(out: &mut String, f: &Figure, mut y: f64) -> f64 {
    let mut labels: Vec<&str> = Vec::new();
    for p in &f.panels {
        for s in &p.series {
            if !labels.contains(&s.label.as_str()) {
                labels.push(&s.label);
            }
        }
    }
    let mut x = LEFT;
    y += 4.0;
    for (i, label) in labels.iter().enumerate() {
        let w = 28.0 + 6.5 * label.chars().count() as f64;
        if x + w > WIDTH - RIGHT && x > LEFT {
            x = LEFT;
            y += 18.0;
        }
        let _ = writeln!(
            out,
            "<rect x=\"{x:.1}\" y=\"{:.1}\" width=\"14\" height=\"10\" fill=\"{}\"/>",
            y - 9.0,
            COLORS[i % COLORS.len()]
        );
        let _ = writeln!(
            out,
            "<text x=\"{:.1}\" y=\"{y:.1}\" font-size=\"12\" fill=\"#1f2933\">{}</text>",
            x + 19.0,
            escape(label)
        );
        x += w;
    }
    if let (Some(st), Some(sp)) = (f.statistic, f.spread) {
        y += 18.0;
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
        let _ = writeln!(
            out,
            "<text x=\"{LEFT}\" y=\"{y:.1}\" font-size=\"12\" fill=\"#52606d\">{}</text>",
            escape(&what)
        );
    }
    y + 6.0
}

fn summary(out: &mut String, f: &Figure, mut y: f64) -> f64 {
    let head = [
        "condition",
        "value",
        "n",
        "mean",
        "sd",
        "median",
        "IQR",
        "95% CI",
    ];
    // Text columns start at their x; number columns end there.
    let cols = [
        18.0,
        220.0,
        400.0,
        470.0,
        535.0,
        600.0,
        705.0,
        SUMMARY_WIDTH - 12.0,
    ];
    y += 8.0;
    let row = |out: &mut String, y: f64, cells: &[String], weight: &str| {
        for (c, (x, t)) in cols.iter().zip(cells).enumerate() {
            let anchor = if c >= 2 { "end" } else { "start" };

            let _ = writeln!(out, "<text x=\"{x:.1}\" y=\"{y:.1}\" font-size=\"11\" font-weight=\"{weight}\" text-anchor=\"{anchor}\" fill=\"#1f2933\">{}</text>", escape(t));
        }
    };
    row(out, y, &head.map(String::from), "600");
    for r in &f.table {
        y += 16.0;
        let cond = r.condition.join(", ");
        let value = match r.unit.as_str() {
            "" => name_of(&r.value),
            u => format!("{} [{u}]", name_of(&r.value)),
        };
        let cells = match &r.stats {
            Some(s) => vec![
                cond,
                value,
                s.n.to_string(),
                short_number(s.mean),
                short_number(s.sd),
                short_number(s.median),
                format!("{}–{}", short_number(s.q1), short_number(s.q3)),
                format!("{}–{}", short_number(s.ci95[0]), short_number(s.ci95[1])),
            ],
            None => vec![cond, value, "0".into()],
        };
        row(out, y, &cells, "400");
    }
    for c in &f.comparisons {
        y += 18.0;
        let k = &c.comparison;
        let text = format!(
            "{}: {} vs {}: difference {}, Cohen's d {}, rank-biserial {}, Mann-Whitney U {} (p = {}, {})",
            name_of(&c.value),
            c.conditions[0],
            c.conditions[1],
            short_number(k.difference),
            short_number(k.cohens_d),
            short_number(k.rank_biserial),
            short_number(k.u),
            short_number(k.p),
            k.method
        );
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{y:.1}\" font-size=\"11\" fill=\"#1f2933\">{}</text>",
            18.0,
            escape(&text)
        );
    }
    y + 8.0
}
