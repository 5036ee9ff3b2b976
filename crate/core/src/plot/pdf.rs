//! A laid-out figure ([`Drawing`]) as a one-page PDF, written directly: the page is the canvas
//! (one SVG pixel a point), the texts are set in Helvetica and Helvetica-Bold, two of the
//! standard fonts every PDF reader has (the figures' font, measured with the same widths, so the
//! layout's room holds), with WinAnsi encoding; a character that encoding lacks is written as the
//! nearest it has (`−` as `-`, `≤` as `<=`) or `?`. Bands are filled at 15% opacity, as in the SVG.

use std::fmt::Write;

use super::draw::{Anchor, Drawing, Item, Text};
use super::text::width;

/// The figure as PDF bytes.
pub fn pdf(d: &Drawing) -> Vec<u8> {
    let content = content(d);
    let objects = [
        "<< /Type /Catalog /Pages 2 0 R >>".to_string(),
        "<< /Type /Pages /Kids [3 0 R] /Count 1 >>".to_string(),
        format!(
            "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {} {}] /Resources << /Font << /F1 4 0 R /F2 5 0 R >> /ExtGState << /Band 6 0 R >> >> /Contents 7 0 R >>",
            d.width, d.height
        ),
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>"
            .to_string(),
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica-Bold /Encoding /WinAnsiEncoding >>"
            .to_string(),
        "<< /Type /ExtGState /ca 0.15 >>".to_string(),
        format!(
            "<< /Length {} >>\nstream\n{content}\nendstream",
            content.len()
        ),
        format!(
            "<< /Title ({}) /Producer ({}) >>",
            String::from_utf8_lossy(&literal(&d.title)),
            crate::experiment::PROGRAM_VERSION
        ),
    ];
    let mut out: Vec<u8> = b"%PDF-1.4\n%\xe2\xe3\xcf\xd3\n".to_vec();
    let mut offsets = Vec::with_capacity(objects.len());
    for (i, body) in objects.iter().enumerate() {
        offsets.push(out.len());
        out.extend_from_slice(format!("{} 0 obj\n", i + 1).as_bytes());
        // Every string was written in escapes, so each object's text is ASCII.
        out.extend_from_slice(body.as_bytes());
        out.extend_from_slice(b"\nendobj\n");
    }
    let xref = out.len();
    let mut table = format!("xref\n0 {}\n0000000000 65535 f \n", objects.len() + 1);
    for o in offsets {
        let _ = writeln!(table, "{o:010} 00000 n ");
    }
    let _ = write!(
        table,
        "trailer\n<< /Size {} /Root 1 0 R /Info {} 0 R >>\nstartxref\n{xref}\n%%EOF\n",
        objects.len() + 1,
        objects.len()
    );
    out.extend_from_slice(table.as_bytes());
    out
}

fn rgb(hex: &str) -> String {
    let v = u32::from_str_radix(hex.trim_start_matches('#'), 16).unwrap_or(0);
    let c = |shift: u32| f64::from((v >> shift) & 0xff) / 255.0;
    format!("{:.3} {:.3} {:.3}", c(16), c(8), c(0))
}

fn content(d: &Drawing) -> String {
    let h = d.height;
    let mut s = String::from("1 j 1 J\n");
    let path = |s: &mut String, points: &[(f64, f64)]| {
        for (i, (x, y)) in points.iter().enumerate() {
            let op = if i == 0 { "m" } else { "l" };
            let _ = writeln!(s, "{x:.2} {:.2} {op}", h - y);
        }
    };
    for item in &d.items {
        match item {
            Item::Text(t) => text(&mut s, t, h),
            Item::Line {
                from, to, stroke, ..
            } => {
                let _ = writeln!(
                    s,
                    "{} RG 1 w {:.2} {:.2} m {:.2} {:.2} l S",
                    rgb(stroke),
                    from.0,
                    h - from.1,
                    to.0,
                    h - to.1
                );
            }
            Item::Rect {
                x,
                y,
                w,
                h: rh,
                fill,
                ..
            } => {
                let _ = writeln!(
                    s,
                    "{} rg {x:.2} {:.2} {w:.2} {rh:.2} re f",
                    rgb(fill),
                    h - y - rh
                );
            }
            Item::Band { points, fill } => {
                let _ = writeln!(s, "q /Band gs {} rg", rgb(fill));
                path(&mut s, points);
                s.push_str("h f Q\n");
            }
            Item::Polyline { points, stroke } => {
                let _ = writeln!(s, "{} RG 2 w", rgb(stroke));
                path(&mut s, points);
                s.push_str("S\n");
            }
            Item::Circle { at, r, fill, .. } => circle(&mut s, (at.0, h - at.1), *r, fill),
            Item::Group(_) | Item::End => {}
        }
    }
    s
}

/// A circle as four Bézier quarters.
fn circle(s: &mut String, (x, y): (f64, f64), r: f64, fill: &str) {
    let k = 0.552_284_75 * r;
    let _ = writeln!(
        s,
        "{} rg {:.2} {y:.2} m {:.2} {:.2} {:.2} {:.2} {x:.2} {:.2} c {:.2} {:.2} {:.2} {:.2} {:.2} {y:.2} c {:.2} {:.2} {:.2} {:.2} {x:.2} {:.2} c {:.2} {:.2} {:.2} {:.2} {:.2} {y:.2} c f",
        rgb(fill),
        x + r,
        x + r, y + k, x + k, y + r, y + r,
        x - k, y + r, x - r, y + k, x - r,
        x - r, y - k, x - k, y - r, y - r,
        x + k, y - r, x + r, y - k, x + r,
    );
}

fn text(s: &mut String, t: &Text, h: f64) {
    let w = width(&t.text, t.size, t.bold);
    let before = match t.anchor {
        Anchor::Start => 0.0,
        Anchor::Middle => w / 2.0,
        Anchor::End => w,
    };
    let font = if t.bold { "F2" } else { "F1" };
    let y = h - t.y;
    let matrix = match t.rotated {
        // Reads upwards: the text's direction is the page's +y.
        true => format!("0 1 -1 0 {:.2} {:.2}", t.x, y - before),
        false => format!("1 0 0 1 {:.2} {y:.2}", t.x - before),
    };
    let _ = writeln!(
        s,
        "BT /{font} {} Tf {} rg {matrix} Tm ({}) Tj ET",
        t.size,
        rgb(t.fill),
        String::from_utf8_lossy(&literal(&t.text))
    );
}

/// A PDF string's inside: the text in WinAnsi, `(`, `)` and `\` escaped and every byte outside
/// printable ASCII as an octal escape.
fn literal(text: &str) -> Vec<u8> {
    let mut out = Vec::new();
    for b in win_ansi(text) {
        match b {
            b'(' | b')' | b'\\' => out.extend_from_slice(&[b'\\', b]),
            0x20..=0x7e => out.push(b),
            _ => out.extend_from_slice(format!("\\{b:03o}").as_bytes()),
        }
    }
    out
}

/// The text in WinAnsi (Windows-1252) bytes.
fn win_ansi(text: &str) -> Vec<u8> {
    let mut out = Vec::new();
    for c in text.chars() {
        let b: &[u8] = match c {
            ' '..='~' => &[c as u8],
            '\u{a0}'..='\u{ff}' => &[c as u32 as u8],
            '–' => &[0x96],
            '—' => &[0x97],
            '…' => &[0x85],
            '‘' => &[0x91],
            '’' => &[0x92],
            '“' => &[0x93],
            '”' => &[0x94],
            '•' => &[0x95],
            '‰' => &[0x89],
            '−' => b"-",
            '≤' => b"<=",
            '≥' => b">=",
            '≠' => b"!=",
            _ => b"?",
        };
        out.extend_from_slice(b);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_into_win_ansi() {
        assert_eq!(literal("a (b) \\ c"), b"a \\(b\\) \\\\ c".to_vec());
        assert_eq!(literal("1–2 ±"), b"1\\2262 \\261".to_vec());
        assert_eq!(literal("≤ 漢"), b"<= ?".to_vec());
    }
}
