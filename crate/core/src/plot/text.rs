//! The figures' one font, and the width of a text in it. Every figure names the family of
//! Helvetica and the faces drawn to its metrics (Arial, Liberation Sans, Arimo, Nimbus Sans), so
//! it lays out alike on every machine; the PDF uses Helvetica itself, one of the standard fonts
//! every PDF reader has. A text's width is measured with Helvetica's advance widths (Adobe's
//! Core 14 metrics), kerning left out, so a measure never falls short of what is drawn; a
//! character outside the table counts one em, wider than any glyph in it.

/// The `font-family` of every figure: Helvetica and the faces with its advance widths.
pub const FAMILY: &str = "Helvetica, Arial, 'Liberation Sans', Arimo, 'Nimbus Sans', sans-serif";

/// How far the baseline lies below a line's top, and the descent below it, in ems (the font's
/// ascender, 718, and descender, 207, in thousandths).
pub const ASCENT: f64 = 0.718;
pub const DESCENT: f64 = 0.207;

/// The width of `text` at `size` (pixels or points), in the same unit.
pub fn width(text: &str, size: f64, bold: bool) -> f64 {
    let table = if bold { &BOLD } else { &REGULAR };
    let thousandths: u32 = text.chars().map(|c| advance(c, table)).sum();
    f64::from(thousandths) * size / 1000.0
}

/// `text` broken into lines no wider than `max` at `size`: between words where it can, inside a
/// word longer than a line.
pub fn wrap(text: &str, size: f64, bold: bool, max: f64) -> Vec<String> {
    let fits = |s: &str| width(s, size, bold) <= max;
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let joined = match line.is_empty() {
            true => word.to_string(),
            false => format!("{line} {word}"),
        };
        if fits(&joined) {
            line = joined;
            continue;
        }
        if !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        // A word wider than a line is cut where it must be.
        for c in word.chars() {
            line.push(c);
            if !fits(&line) && line.chars().count() > 1 {
                line.pop();
                lines.push(std::mem::replace(&mut line, c.to_string()));
            }
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

fn advance(c: char, table: &[u16; 95]) -> u32 {
    let same = match c {
        ' '..='~' => return u32::from(table[c as usize - 32]),
        '\u{a0}' => ' ',
        // The dashes, signs and marks the figures write, at their width in the font.
        '–' | '•' => return 556,
        '—' | '…' | '‰' => return 1000,
        '±' | '×' | '−' | '÷' => return 584,
        // The PDF's font has no ≤, ≥ or ≠ and writes <=, >= and !=: measured as those.
        '≤' | '≥' | '≠' => return 1168,
        '·' => return 278,
        '°' => return 400,
        '‘' | '’' | '“' | '”' => return quote(c, std::ptr::eq(table, &BOLD)),
        // A letter with a mark is as wide as the letter.
        'à'..='å' => 'a',
        'è'..='ë' => 'e',
        'ì'..='ï' => 'i',
        'ò'..='ö' => 'o',
        'ù'..='ü' => 'u',
        'À'..='Å' => 'A',
        'È'..='Ë' => 'E',
        'Ò'..='Ö' => 'O',
        'Ù'..='Ü' => 'U',
        'ç' => 'c',
        'ñ' => 'n',
        _ => return 1000,
    };
    advance(same, table)
}

/// Curly quotes: single 222 (bold 278), double 333 (bold 500).
fn quote(c: char, bold: bool) -> u32 {
    match (matches!(c, '‘' | '’'), bold) {
        (true, false) => 222,
        (true, true) => 278,
        (false, false) => 333,
        (false, true) => 500,
    }
}

/// Helvetica's advance widths of the printable ASCII characters, space to tilde, in thousandths
/// of an em (the apostrophe is `quotesingle`, the backquote `grave`).
const REGULAR: [u16; 95] = [
    278, 278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333, 278, 278, 556, 556, 556,
    556, 556, 556, 556, 556, 556, 556, 278, 278, 584, 584, 584, 556, 1015, 667, 667, 722, 722, 667,
    611, 778, 722, 278, 500, 667, 556, 833, 722, 778, 667, 778, 722, 667, 611, 722, 667, 944, 667,
    667, 611, 278, 278, 278, 469, 556, 333, 556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500,
    222, 833, 556, 556, 556, 556, 333, 500, 278, 556, 500, 722, 500, 500, 500, 334, 260, 334, 584,
];
/// Helvetica Bold's, likewise.
const BOLD: [u16; 95] = [
    278, 333, 474, 556, 556, 889, 722, 238, 333, 333, 389, 584, 278, 333, 278, 278, 556, 556, 556,
    556, 556, 556, 556, 556, 556, 556, 333, 333, 584, 584, 584, 611, 975, 722, 722, 722, 722, 667,
    611, 778, 722, 278, 556, 722, 611, 833, 722, 778, 667, 778, 722, 667, 611, 722, 667, 944, 667,
    667, 611, 333, 278, 333, 584, 556, 333, 556, 611, 556, 611, 556, 333, 611, 611, 278, 278, 556,
    278, 889, 611, 611, 611, 611, 389, 556, 333, 611, 556, 778, 556, 556, 500, 389, 280, 389, 584,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widths_are_helveticas_advances() {
        // "Kumiki": K 667 + u 556 + m 833 + i 222 + k 500 + i 222 = 3000 thousandths.
        assert_eq!(width("Kumiki", 10.0, false), 30.0);
        assert_eq!(
            width("Kumiki", 10.0, true),
            10.0 * (722.0 + 611.0 + 889.0 + 278.0 + 556.0 + 278.0) / 1000.0
        );
        assert_eq!(width("漢", 12.0, false), 12.0);
        assert_eq!(width("a–b", 1.0, false), (556.0 + 556.0 + 556.0) / 1000.0);
    }

    #[test]
    fn wrapped_lines_fit_and_keep_every_character() {
        let text =
            "a comparison line that runs on and on, with averyveryverylongwordthatmustbecut in it";
        let lines = wrap(text, 11.0, false, 80.0);
        assert!(lines.len() > 3);
        assert!(
            lines.iter().all(|l| width(l, 11.0, false) <= 80.0),
            "{lines:?}"
        );
        assert_eq!(lines.concat().replace(' ', ""), text.replace(' ', ""));
        assert_eq!(wrap("short", 11.0, false, 80.0), vec!["short"]);
    }
}
