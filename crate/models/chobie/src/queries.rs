//! Helper calls for editors and the CLI: the crawl forms of figure 7, reconstructed.

use serde_json::{json, Value};

use kumiki_model::error::{Error, Result};

/// The largest crawl drawn by the query.
pub const MAX_CRAWL: u64 = 4001;

/// The world text of crawl form `form` (1 to 4) for `robots` = 2k + 1 robots: form 1 is a lower
/// tier of k + 1 robots with k robots on its left above; each form's single leader turns it into
/// the next, and form 4 turns into form 1 one cell to the right.
pub fn crawl_world(robots: u64, form: u64, margin: u64) -> String {
    let k = (robots - 1) / 2;
    // (upper tier start, upper length, lower tier start, lower length) per form.
    let (us, ul, ls, ll) = match form {
        1 => (0, k, 0, k + 1),
        2 => (1, k, 0, k + 1),
        3 => (0, k + 1, 1, k),
        _ => (1, k + 1, 1, k),
    };
    let w = (k + 2 + margin) as usize;
    let row = |start: u64, len: u64| {
        let mut s = String::with_capacity(w);
        for x in 0..w as u64 {
            s.push(if x >= start && x < start + len {
                '#'
            } else {
                '.'
            });
        }
        s
    };
    format!(
        "{}\n{}\n{}\n{}\n",
        ".".repeat(w),
        row(us, ul),
        row(ls, ll),
        "=".repeat(w)
    )
}

/// `{"robots": n, "form": f, "margin": m}` → `{"world": text}`.
pub fn crawl(args: &Value) -> Result<Value> {
    let n = args
        .get("robots")
        .and_then(Value::as_u64)
        .ok_or_else(|| Error::field("robots", "give the number of robots, an odd number ≥ 3"))?;
    if n < 3 || n % 2 == 0 || n > MAX_CRAWL {
        return Err(Error::field(
            "robots",
            format!("the crawl forms need an odd number of robots from 3 to {MAX_CRAWL}"),
        ));
    }
    let form = args.get("form").map_or(Some(1), Value::as_u64).unwrap_or(0);
    if !(1..=4).contains(&form) {
        return Err(Error::field("form", "a crawl form is 1, 2, 3 or 4"));
    }
    let margin = args
        .get("margin")
        .map_or(Some(10), Value::as_u64)
        .unwrap_or(u64::MAX);
    if margin > 1000 {
        return Err(Error::field("margin", "from 0 to 1000 empty columns"));
    }
    Ok(json!({ "world": crawl_world(n, form, margin) }))
}
