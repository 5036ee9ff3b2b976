//! Two conditions compared: the difference of means, Cohen's d, the rank-biserial correlation and
//! the two-sided Mann-Whitney U test. The experiments' figures and the reproduction report's
//! verdicts use the same numbers.

use serde::Serialize;

use crate::report::Stats;

/// Two conditions compared: the difference of means, effect sizes and the Mann-Whitney U test
/// (two-sided). Every signed figure takes the first condition's side: the difference and Cohen's d
/// are the first minus the second, U counts the pairs where the first is larger, and all three are
/// positive when the first condition's values tend to be larger.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[schemars(rename = "StatisticalComparison")]
pub struct Comparison {
    /// Mean of the first condition minus mean of the second.
    pub difference: f64,
    /// Cohen's d: the difference (first minus second) over the pooled sd (NaN when both sds are 0).
    pub cohens_d: f64,
    /// U of the first condition: pairs where its value is larger, ties counting one half.
    pub u: f64,
    /// The rank-biserial correlation 2U/(n1·n2) − 1, from −1 (all of the first below the second)
    /// to 1 (all of the first above).
    pub rank_biserial: f64,
    /// Two-sided p of U: exact (the distribution of U counted) without ties and with
    /// n1·n2 ≤ 10 000, else the normal approximation with tie and continuity correction.
    pub p: f64,
    /// `exact` or `normal`.
    pub method: &'static str,
}

impl Comparison {
    pub fn of(a: &[f64], b: &[f64]) -> Option<Comparison> {
        let a: Vec<f64> = a.iter().copied().filter(|x| x.is_finite()).collect();
        let b: Vec<f64> = b.iter().copied().filter(|x| x.is_finite()).collect();
        if a.is_empty() || b.is_empty() {
            return None;
        }
        let (sa, sb) = (Stats::of(&a), Stats::of(&b));
        let (n1, n2) = (a.len(), b.len());
        let pooled = match n1 + n2 {
            0..=2 => f64::NAN,
            _ => (((n1 - 1) as f64 * sa.sd.powi(2) + (n2 - 1) as f64 * sb.sd.powi(2))
                / (n1 + n2 - 2) as f64)
                .sqrt(),
        };
        let cohens_d = match pooled > 0.0 {
            true => (sa.mean - sb.mean) / pooled,
            false => f64::NAN,
        };
        let mut u = 0.0;
        let mut ties = false;
        for x in &a {
            for y in &b {
                if x > y {
                    u += 1.0;
                } else if x == y {
                    u += 0.5;
                    ties = true;
                }
            }
        }
        let pairs = (n1 * n2) as f64;
        // Ties within a condition matter to the normal approximation's variance, and to
        // whether the exact count applies.
        let mut all: Vec<f64> = a.iter().chain(&b).copied().collect();
        crate::sort::sort_by(&mut all, f64::total_cmp);
        ties |= all.windows(2).any(|w| w[0] == w[1]);
        let (p, method) = match !ties && n1 * n2 <= 10_000 {
            true => (exact_p(n1, n2, u), "exact"),
            false => (normal_p(n1, n2, u, &all), "normal"),
        };
        Some(Comparison {
            difference: sa.mean - sb.mean,
            cohens_d,
            u,
            rank_biserial: 2.0 * u / pairs - 1.0,
            p,
            method,
        })
    }
}

/// Two-sided exact p of U for samples of n1 and n2 without ties: the number of arrangements
/// giving each U, counted by the recurrence c(n1, n2, u) = c(n1 − 1, n2, u − n2) + c(n1, n2 − 1, u).
fn exact_p(n1: usize, n2: usize, u: f64) -> f64 {
    let max = n1 * n2;
    // counts[j][k]: arrangements of i values of the first and j of the second with U = k,
    // built up over i.
    let mut prev: Vec<Vec<f64>> = (0..=n2).map(|_| vec![1.0]).collect();
    for i in 1..=n1 {
        let mut cur: Vec<Vec<f64>> = Vec::with_capacity(n2 + 1);
        cur.push(vec![1.0]);
        for j in 1..=n2 {
            let mut c = vec![0.0; i * j + 1];
            for (k, v) in prev[j].iter().enumerate() {
                c[k + j] += v;
            }
            for (k, v) in cur[j - 1].iter().enumerate() {
                c[k] += v;
            }
            cur.push(c);
        }
        prev = cur;
    }
    let counts = &prev[n2];
    let total: f64 = counts.iter().sum();
    let k = u.round() as usize;
    let low = k.min(max - k);
    let tail: f64 = counts[..=low].iter().sum::<f64>() / total;
    (2.0 * tail).min(1.0)
}

/// Two-sided p of U by the normal approximation, the variance corrected for ties and a
/// continuity correction of one half.
fn normal_p(n1: usize, n2: usize, u: f64, sorted: &[f64]) -> f64 {
    let (a, b) = (n1 as f64, n2 as f64);
    let n = a + b;
    let mut tie_sum = 0.0;
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i;
        while j + 1 < sorted.len() && sorted[j + 1] == sorted[i] {
            j += 1;
        }
        let t = (j - i + 1) as f64;
        tie_sum += t.powi(3) - t;
        i = j + 1;
    }
    let var = a * b / 12.0 * ((n + 1.0) - tie_sum / (n * (n - 1.0)));
    if var <= 0.0 {
        return 1.0;
    }
    let z = ((u - a * b / 2.0).abs() - 0.5).max(0.0) / var.sqrt();
    libm::erfc(z / std::f64::consts::SQRT_2).min(1.0)
}

#[cfg(test)]
mod tests {
    use super::Comparison;

    #[test]
    fn every_signed_figure_takes_the_first_conditions_side() {
        let c = Comparison::of(&[6.0, 7.0, 8.0], &[1.0, 2.0, 3.0]).unwrap();
        assert_eq!((c.difference, c.u, c.rank_biserial), (5.0, 9.0, 1.0));
        assert!(c.cohens_d > 0.0);
        let r = Comparison::of(&[1.0, 2.0, 3.0], &[6.0, 7.0, 8.0]).unwrap();
        assert_eq!((r.difference, r.u, r.rank_biserial), (-5.0, 0.0, -1.0));
        assert_eq!(r.p, c.p);
        assert!(Comparison::of(&[], &[1.0]).is_none());
    }
}
