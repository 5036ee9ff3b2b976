//! Nothing clipped: every built-in figure, and figures whose titles, names and labels run long,
//! keep every text inside the canvas, in the SVG and in the PDF alike. Each output is read back
//! as written (the SVG's `<text>` elements; the PDF's text matrices) and each text measured with
//! the figures' font (Helvetica's advance widths, an upper bound of the faces named), so a test
//! fails when a writer places a text where the layout did not.

use serde_json::{json, Value};

use super::draw::{Anchor, Text};
use super::figure::{figures, Figure};
use super::svg::{layout, svg};
use super::tests::made_up_rows;
use super::text::width;
use crate::experiment::Experiment;
use crate::presets;

/// The texts of an SVG document as written, and its width and height.
fn svg_texts(doc: &str) -> (f64, f64, Vec<Text>) {
    let attr = |tag: &str, name: &str| -> Option<String> {
        let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(tag[start..].split('"').next()?.to_string())
    };
    let head = &doc[..doc.find('>').unwrap()];
    let w: f64 = attr(head, "width").unwrap().parse().unwrap();
    let h: f64 = attr(head, "height").unwrap().parse().unwrap();
    let mut texts = Vec::new();
    for part in doc.split("<text").skip(1) {
        let (tag, rest) = part.split_once('>').unwrap();
        let content = rest.split("</text>").next().unwrap();
        let unescaped = content
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&amp;", "&");
        let num = |n: &str| attr(tag, n).unwrap().parse::<f64>().unwrap();
        texts.push(Text {
            x: num("x"),
            y: num("y"),
            size: num("font-size"),
            bold: attr(tag, "font-weight").is_some(),
            anchor: match attr(tag, "text-anchor").as_deref() {
                Some("middle") => Anchor::Middle,
                Some("end") => Anchor::End,
                _ => Anchor::Start,
            },
            fill: "",
            text: unescaped,
            rotated: attr(tag, "transform").is_some_and(|t| t.starts_with("rotate(-90")),
        });
    }
    (w, h, texts)
}

/// The texts of a PDF page as written: each `BT /F s Tf … a b c d e f Tm (text) Tj ET`, as a
/// start-anchored text on the page turned back into the canvas's coordinates, and the page size.
fn pdf_texts(pdf: &[u8]) -> (f64, f64, Vec<(Text, f64)>) {
    let doc = String::from_utf8_lossy(pdf);
    let media = doc.split("/MediaBox [0 0 ").nth(1).unwrap();
    let mut dims = media.split(']').next().unwrap().split(' ');
    let w: f64 = dims.next().unwrap().parse().unwrap();
    let h: f64 = dims.next().unwrap().parse().unwrap();
    let mut texts = Vec::new();
    for part in doc.split("BT /").skip(1) {
        let line = part.split(" ET").next().unwrap();
        let bold = line.starts_with("F2");
        let words: Vec<&str> = line.split(' ').collect();
        let size: f64 = words[1].parse().unwrap();
        let tm = words.iter().position(|w| *w == "Tm").unwrap();
        let m: Vec<f64> = words[tm - 6..tm]
            .iter()
            .map(|v| v.parse().unwrap())
            .collect();
        let raw = line
            .split_once(" (")
            .unwrap()
            .1
            .rsplit_once(") Tj")
            .unwrap()
            .0;
        let text = unescape_pdf(raw);
        // The width the PDF draws: the fonts' advances of the bytes written.
        let drawn = width(&text, size, bold);
        let rotated = m[0] == 0.0;
        texts.push((
            Text {
                x: m[4],
                y: h - m[5],
                size,
                bold,
                anchor: Anchor::Start,
                fill: "",
                text,
                rotated,
            },
            drawn,
        ));
    }
    (w, h, texts)
}

/// A PDF string's bytes back as text (WinAnsi read as Latin-1; the dashes as one wide glyph).
fn unescape_pdf(raw: &str) -> String {
    let mut out = String::new();
    let mut chars = raw.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        let next = chars.next().unwrap();
        if next.is_ascii_digit() {
            let code: String = [next, chars.next().unwrap(), chars.next().unwrap()]
                .iter()
                .collect();
            let b = u8::from_str_radix(&code, 8).unwrap();
            out.push(match b {
                0x96 => '–',
                0x97 => '—',
                0x85 => '…',
                b => char::from(b),
            });
        } else {
            out.push(next);
        }
    }
    out
}

fn inside(what: &str, w: f64, h: f64, b: [f64; 4], text: &str) {
    assert!(
        b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
        "{what}: '{text}' at {b:?} leaves the {w} × {h} canvas"
    );
}

/// Every text of the figure inside its canvas: as laid out, as the SVG writes it and as the PDF
/// writes it.
fn nothing_clipped(what: &str, f: &Figure) {
    let d = layout(f);
    for t in d.texts() {
        inside(
            &format!("{what} (layout)"),
            d.width,
            d.height,
            t.bounds(),
            &t.text,
        );
    }
    let (w, h, texts) = svg_texts(&svg(f));
    assert_eq!(
        texts.len(),
        d.texts().count(),
        "{what}: the SVG writes every text"
    );
    for t in &texts {
        inside(&format!("{what} (SVG)"), w, h, t.bounds(), &t.text);
    }
    let (w, h, texts) = pdf_texts(&super::pdf::pdf(&d));
    assert_eq!(
        texts.len(),
        d.texts().count(),
        "{what}: the PDF writes every text"
    );
    for (t, drawn) in &texts {
        let b = t.bounds();
        inside(&format!("{what} (PDF)"), w, h, b, &t.text);
        let along = if t.rotated { b[3] - b[1] } else { b[2] - b[0] };
        assert!(
            (along - drawn).abs() < 1e-6,
            "{what}: PDF text '{}'",
            t.text
        );
    }
}

#[test]
fn every_built_in_figure_keeps_every_text_inside_its_canvas() {
    let mut count = 0;
    for name in presets::experiment_names() {
        let e = Experiment::named_or_json(name).unwrap();
        let rows = made_up_rows(&e);
        let models: Vec<&str> = e.scenarios.iter().map(|s| s.model()).collect();
        for (i, f) in figures(&e.plots, &rows, &models).iter().enumerate() {
            nothing_clipped(&format!("{name} figure {}", i + 1), f);
            count += 1;
        }
    }
    assert!(count > 20, "{count} figures");
}

fn long_experiment(plot: Value) -> Experiment {
    let long = "a very long name that goes on and on ".repeat(2);
    let scenario = |n: usize, robots: u64| {
        let mut s = presets::scenario("amas-L").unwrap().to_value();
        s["name"] = json!(format!("{long}{n}").chars().take(100).collect::<String>());
        s["robots"] = json!(robots);
        s
    };
    Experiment::from_value(json!({
        "version": 1,
        "name": "long",
        "title": "A title that says far more than a title should, ".repeat(6),
        "scenarios": [scenario(1, 2), scenario(2, 3), scenario(3, 4)],
        "grid": {"field": ["continuous", "discrete"]},
        "seeds": 3,
        "plot": plot,
    }))
    .unwrap()
}

#[test]
fn figures_keep_long_titles_names_and_labels_inside_their_canvas() {
    let label = "an axis label written out in full, with its reasons, ".repeat(4);
    let plots = json!([
        {"kind": "summary", "group": ["scenario", "params.field"], "values": ["steps", "metrics.total_steps", "metrics.collisions"]},
        {"kind": "lines", "x": "seed", "y": ["steps", "metrics.total_steps"], "series": "scenario", "facet": "params.field", "x_label": label, "y_label": label},
        {"kind": "bars", "x": "scenario", "y": "metrics.total_steps", "series": "params.field", "y_label": label},
        {"kind": "histogram", "value": "metrics.total_steps", "series": "scenario", "x_label": label},
    ]);
    let e = long_experiment(plots);
    let rows = made_up_rows(&e);
    let figs = figures(&e.plots, &rows, &["amas"]);
    assert!(figs[0].omnibus.len() == 3 && figs[0].comparisons.len() == 3 * 15);
    for (i, f) in figs.iter().enumerate() {
        nothing_clipped(&format!("long figure {}", i + 1), f);
    }
    let mut partial = figs[0].clone();
    partial.partial = Some(super::figure::Partial { runs: 7, of: 54 });
    assert!(svg(&partial).contains("partial: 7 of 54 runs (cancelled)"));
    nothing_clipped("partial summary", &partial);
}

#[test]
fn faceted_panels_share_one_y_axis_and_one_y_label() {
    let e = long_experiment(
        json!({"kind": "lines", "x": "seed", "y": "steps", "facet": "scenario", "y_label": "steps taken"}),
    );
    let f = &figures(&e.plots, &made_up_rows(&e), &["amas"])[0];
    assert_eq!(f.panels.len(), 3);
    let doc = svg(f);
    assert_eq!(doc.matches(">steps taken</text>").count(), 1, "one y label");
    assert!(doc.contains("The panels share one y axis."));
    // Each panel draws the same y ticks.
    let (_, _, texts) = svg_texts(&doc);
    let ticks: Vec<&str> = texts
        .iter()
        .filter(|t| t.anchor == Anchor::End && !t.rotated)
        .map(|t| t.text.as_str())
        .collect();
    assert_eq!(ticks.len() % 3, 0);
    let per = ticks.len() / 3;
    assert!(ticks[..per] == ticks[per..2 * per] && ticks[..per] == ticks[2 * per..]);
}
