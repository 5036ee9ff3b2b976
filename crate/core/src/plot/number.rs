//! One rule for every number a figure, a summary, an export's figure or the page shows, so a
//! value reads the same everywhere (the page gets it through its wasm module's `format_number`):
//!
//! - below 1000 (in size): four significant digits, trailing zeros dropped (165.25 → 165.3,
//!   0.98876 → 0.9888, 2.5 → 2.5);
//! - from 1000: one decimal at most, thousands grouped by commas (9825.5 → 9,825.5, 12000 →
//!   12,000);
//! - below 0.001 or from 10^15: three significant digits in scientific form (8.09e-34);
//! - not a number or infinite: "–".
//!
//! Rounding is half away from zero on the number's shortest decimal form, the digits JSON writes
//! and a person reads, so 165.25 is 165.3 and -165.25 is -165.3.

/// A number as every figure and table shows it.
pub fn format(v: f64) -> String {
    if !v.is_finite() {
        return "–".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let sign = if v < 0.0 { "-" } else { "" };
    let a = v.abs();
    let (digits, exp) = shortest(a);
    if !(1e-3..1e15).contains(&a) {
        let (d, e) = round(&digits, exp, 3);
        let mantissa = positional(&d, 0);
        return format!("{sign}{mantissa}e{e}");
    }
    let keep = match a >= 1000.0 {
        // One decimal: the digits before the point and one after.
        true => (exp + 2) as usize,
        false => 4,
    };
    let (d, e) = round(&digits, exp, keep);
    let text = positional(&d, e);
    let text = match e >= 3 {
        true => group(&text),
        false => text,
    };
    format!("{sign}{text}")
}

/// The shortest decimal digits of `a` (> 0) and the exponent of the first: `a = d.ddd × 10^exp`.
fn shortest(a: f64) -> (Vec<u8>, i32) {
    let text = format!("{a:e}");
    let (mantissa, exp) = text.split_once('e').expect("{:e} writes an exponent");
    let digits = mantissa
        .bytes()
        .filter(u8::is_ascii_digit)
        .map(|b| b - b'0')
        .collect();
    (digits, exp.parse().expect("an exponent"))
}

/// `digits` (first at 10^exp) rounded half away from zero to `keep` significant digits, trailing
/// zeros dropped; the exponent grows when rounding carries (9.9995 → 10.00).
fn round(digits: &[u8], exp: i32, keep: usize) -> (Vec<u8>, i32) {
    let keep = keep.max(1);
    if digits.len() <= keep {
        return (trim(digits.to_vec()), exp);
    }
    let mut out = digits[..keep].to_vec();
    let mut exp = exp;
    if digits[keep] >= 5 {
        let mut i = keep;
        loop {
            if i == 0 {
                out.insert(0, 1);
                out.pop();
                exp += 1;
                break;
            }
            i -= 1;
            if out[i] == 9 {
                out[i] = 0;
            } else {
                out[i] += 1;
                break;
            }
        }
    }
    (trim(out), exp)
}

fn trim(mut d: Vec<u8>) -> Vec<u8> {
    while d.len() > 1 && d.last() == Some(&0) {
        d.pop();
    }
    d
}

/// Digits with the first at 10^exp, written out: `[1, 6, 5, 3]` at 2 is "165.3".
fn positional(d: &[u8], exp: i32) -> String {
    let digit = |i: i32| -> char {
        match usize::try_from(i).ok().and_then(|i| d.get(i)) {
            Some(x) => char::from(b'0' + x),
            None => '0',
        }
    };
    let mut s = String::new();
    if exp < 0 {
        s.push_str("0.");
        s.extend(std::iter::repeat_n('0', (-exp - 1) as usize));
        s.extend(d.iter().map(|x| char::from(b'0' + x)));
        return s;
    }
    for i in 0..=exp {
        s.push(digit(i));
    }
    if d.len() as i32 > exp + 1 {
        s.push('.');
        for i in exp + 1..d.len() as i32 {
            s.push(digit(i));
        }
    }
    s
}

/// Thousands grouped by commas in the whole part.
fn group(text: &str) -> String {
    let (whole, fraction) = match text.split_once('.') {
        Some((w, f)) => (w, Some(f)),
        None => (text, None),
    };
    let mut out = String::new();
    for (i, c) in whole.chars().enumerate() {
        if i > 0 && (whole.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    if let Some(f) = fraction {
        out.push('.');
        out.push_str(f);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::format;

    #[test]
    fn one_rule_for_every_size() {
        let cases = [
            (165.25, "165.3"),
            (-165.25, "-165.3"),
            (165.2, "165.2"),
            (9825.5, "9,825.5"),
            (9825.0, "9,825"),
            (12_345_678.96, "12,345,679"),
            (0.988_76, "0.9888"),
            (2.5, "2.5"),
            (-3.98, "-3.98"),
            (999.96, "1,000"),
            (9.999_51, "10"),
            (0.001_234_56, "0.001235"),
            (8.0912e-34, "8.09e-34"),
            (0.000_5, "5e-4"),
            (2e15, "2e15"),
            (0.0, "0"),
            (1.0, "1"),
            (100.0, "100"),
            (f64::NAN, "–"),
        ];
        for (v, want) in cases {
            assert_eq!(format(v), want, "{v}");
        }
    }
}
