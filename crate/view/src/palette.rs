//! Colours: legend colours to RGBA tables, and the heat map (viridis, sampled) for fields.

use kumiki_model::model::LegendEntry;

pub type Rgba = [u8; 4];

/// The colour of empty space behind every view.
pub const BACKGROUND: Rgba = [27, 35, 44, 255];

/// Parses #rgb, #rrggbb or #rrggbbaa; anything else is mid grey.
pub fn parse_color(css: &str) -> Rgba {
    let hex = css.trim().trim_start_matches('#');
    let full: String = if hex.len() == 3 {
        hex.chars().flat_map(|c| [c, c]).collect()
    } else {
        hex.to_string()
    };
    if !(full.len() == 6 || full.len() == 8) || !full.bytes().all(|b| b.is_ascii_hexdigit()) {
        return [128, 128, 128, 255];
    }
    let n = |i: usize| u8::from_str_radix(&full[i..i + 2], 16).unwrap_or(0);
    [n(0), n(2), n(4), if full.len() == 8 { n(6) } else { 255 }]
}

/// 256 RGBA entries indexed by code; codes without a legend entry are transparent.
pub fn legend_table(legend: &[LegendEntry]) -> Vec<u8> {
    let mut table = vec![0u8; 256 * 4];
    for e in legend {
        let at = usize::from(e.code) * 4;
        table[at..at + 4].copy_from_slice(&parse_color(&e.color));
    }
    table
}

const VIRIDIS: [[f64; 3]; 11] = [
    [68.0, 1.0, 84.0],
    [72.0, 35.0, 116.0],
    [64.0, 67.0, 135.0],
    [52.0, 94.0, 141.0],
    [41.0, 120.0, 142.0],
    [32.0, 144.0, 140.0],
    [34.0, 167.0, 132.0],
    [68.0, 190.0, 112.0],
    [121.0, 209.0, 81.0],
    [189.0, 222.0, 38.0],
    [253.0, 231.0, 37.0],
];

/// Viridis at `t` in [0, 1], unrounded (0–255 per channel).
pub fn heat(t: f64) -> [f64; 3] {
    let x = t.clamp(0.0, 1.0) * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    std::array::from_fn(|c| a[c] + (b[c] - a[c]) * f)
}

/// 256 RGBA entries of the heat map, for lookup textures and per-cell colours.
pub fn heat_table() -> Vec<u8> {
    let mut table = vec![255u8; 256 * 4];
    for i in 0..256 {
        let c = heat(i as f64 / 255.0);
        for k in 0..3 {
            table[i * 4 + k] = c[k].round() as u8;
        }
    }
    table
}

/// The finite minimum and maximum of a field, or (0, 1) when it has no finite value.
pub fn range(data: &[f32]) -> (f32, f32) {
    let (lo, hi) = data
        .iter()
        .filter(|v| v.is_finite())
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    if lo <= hi {
        (lo, hi)
    } else {
        (0.0, 1.0)
    }
}

/// A CSS colour string for Canvas 2D.
pub fn css([r, g, b, a]: Rgba) -> String {
    format!("rgba({r},{g},{b},{:.3})", f64::from(a) / 255.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_parse_in_every_written_form() {
        assert_eq!(parse_color("#fa0"), [255, 170, 0, 255]);
        assert_eq!(parse_color("#1b232c"), [27, 35, 44, 255]);
        assert_eq!(parse_color(" #11223380 "), [17, 34, 51, 128]);
        assert_eq!(parse_color("tomato"), [128, 128, 128, 255]);
        assert_eq!(parse_color("#12345"), [128, 128, 128, 255]);
    }

    #[test]
    fn legend_tables_leave_unnamed_codes_clear() {
        let t = legend_table(&[LegendEntry::new(3, "block", "#ff0000")]);
        assert_eq!(&t[12..16], &[255, 0, 0, 255]);
        assert!(t[..12].iter().chain(&t[16..]).all(|&b| b == 0));
    }

    #[test]
    fn heat_runs_from_dark_violet_to_yellow() {
        let t = heat_table();
        assert_eq!(&t[..4], &[68, 1, 84, 255]);
        assert_eq!(&t[255 * 4..], &[253, 231, 37, 255]);
        assert_eq!(range(&[f32::NAN, 2.0, -1.0, f32::INFINITY]), (-1.0, 2.0));
        assert_eq!(range(&[f32::NAN]), (0.0, 1.0));
    }
}
