//! Conditions compared. Two: the difference of means, Cohen's d, the rank-biserial correlation and
//! the two-sided Mann-Whitney U test ([`Comparison`]), every signed figure the first condition
//! minus the second. Three or more: the Kruskal-Wallis H test ([`KruskalWallis`]), then every pair
//! by [`Comparison`] with its p corrected for the number of pairs by Holm's method ([`holm`]).
//! The experiments' figures and the reproduction report's verdicts use the same numbers.

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

/// The Kruskal-Wallis H test of three or more conditions (any number from two): whether their
/// values come from one distribution, on ranks (ties share their mean rank), H corrected for ties
/// and its p from the chi-squared distribution with k − 1 degrees of freedom, as
/// `scipy.stats.kruskal` computes them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct KruskalWallis {
    /// H, corrected for ties.
    pub h: f64,
    /// Degrees of freedom: the conditions with values, less one.
    pub df: usize,
    /// The upper tail of chi-squared(df) at H.
    pub p: f64,
    /// Values in all conditions together.
    pub n: usize,
}

impl KruskalWallis {
    /// The test of `groups` (non-finite values left out); `None` with fewer than two groups that
    /// have values, or when every value is the same (H is then undefined).
    pub fn of(groups: &[Vec<f64>]) -> Option<KruskalWallis> {
        let groups: Vec<Vec<f64>> = groups
            .iter()
            .map(|g| {
                g.iter()
                    .copied()
                    .filter(|x| x.is_finite())
                    .collect::<Vec<f64>>()
            })
            .filter(|g| !g.is_empty())
            .collect();
        if groups.len() < 2 {
            return None;
        }
        let mut all: Vec<(f64, usize)> = groups
            .iter()
            .enumerate()
            .flat_map(|(i, g)| g.iter().map(move |&x| (x, i)))
            .collect();
        crate::sort::sort_by(&mut all, |a, b| a.0.total_cmp(&b.0));
        let n = all.len();
        let mut rank_sums = vec![0.0; groups.len()];
        let mut ties = 0.0;
        let mut i = 0;
        while i < n {
            let mut j = i;
            while j + 1 < n && all[j + 1].0 == all[i].0 {
                j += 1;
            }
            // Positions i..=j share the mean of ranks i + 1 ..= j + 1.
            let rank = (i + j) as f64 / 2.0 + 1.0;
            for item in &all[i..=j] {
                rank_sums[item.1] += rank;
            }
            let t = (j - i + 1) as f64;
            ties += t.powi(3) - t;
            i = j + 1;
        }
        let nf = n as f64;
        let correction = 1.0 - ties / (nf.powi(3) - nf);
        if correction <= 0.0 {
            return None;
        }
        let sum: f64 = rank_sums
            .iter()
            .zip(&groups)
            .map(|(r, g)| r * r / g.len() as f64)
            .sum();
        let h = (12.0 / (nf * (nf + 1.0)) * sum - 3.0 * (nf + 1.0)) / correction;
        let df = groups.len() - 1;
        Some(KruskalWallis {
            h,
            df,
            p: chi2_upper(h, df),
            n,
        })
    }
}

/// Holm's step-down correction of `p` for as many tests as it holds: the k-th smallest p times
/// (m − k + 1), never below the one before it, at most 1; returned in the order given.
pub fn holm(p: &[f64]) -> Vec<f64> {
    let m = p.len();
    let mut order: Vec<usize> = (0..m).collect();
    crate::sort::sort_by(&mut order, |&a, &b| p[a].total_cmp(&p[b]));
    let mut out = vec![f64::NAN; m];
    let mut floor: f64 = 0.0;
    for (k, &i) in order.iter().enumerate() {
        floor = floor.max(((m - k) as f64 * p[i]).min(1.0));
        out[i] = floor;
    }
    out
}

/// The upper tail of the chi-squared distribution with `df` degrees of freedom at `x`: the
/// regularised upper incomplete gamma Q(df/2, x/2).
pub fn chi2_upper(x: f64, df: usize) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    gamma_q(df as f64 / 2.0, x / 2.0)
}

/// Q(a, x) by its series below x = a + 1 and its continued fraction above (Lentz's method), each
/// to a relative 1e-15.
fn gamma_q(a: f64, x: f64) -> f64 {
    let log_front = a * x.ln() - x - libm::lgamma(a);
    if x < a + 1.0 {
        let (mut term, mut sum, mut ap) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        return (1.0 - sum * log_front.exp()).clamp(0.0, 1.0);
    }
    let tiny = 1e-300;
    let mut b = x + 1.0 - a;
    let mut c = 1.0 / tiny;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..10_000 {
        let an = -(i as f64) * (i as f64 - a);
        b += 2.0;
        d = an * d + b;
        if d.abs() < tiny {
            d = tiny;
        }
        c = b + an / c;
        if c.abs() < tiny {
            c = tiny;
        }
        d = 1.0 / d;
        let delta = d * c;
        h *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    (log_front.exp() * h).clamp(0.0, 1.0)
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
    use super::{holm, Comparison, KruskalWallis};

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * b.abs().max(1e-12) || (a - b).abs() < 1e-15
    }

    /// Against SciPy: tests/fixtures/stats-reference.json holds scipy.stats.kruskal and
    /// scipy.stats.mannwhitneyu on data sets with and without ties, three and four conditions and
    /// two, and Holm's correction of SciPy's p values, as scripts/stats-reference.py made them.
    #[test]
    fn kruskal_wallis_mann_whitney_and_holm_match_scipy() {
        let doc: serde_json::Value =
            serde_json::from_str(include_str!("../../../tests/fixtures/stats-reference.json"))
                .unwrap();
        for case in doc["cases"].as_array().unwrap() {
            let name = case["name"].as_str().unwrap();
            let groups: Vec<Vec<f64>> = serde_json::from_value(case["groups"].clone()).unwrap();
            let kw = KruskalWallis::of(&groups).unwrap();
            let (h, p) = (
                case["kruskal"]["h"].as_f64().unwrap(),
                case["kruskal"]["p"].as_f64().unwrap(),
            );
            assert!(close(kw.h, h), "{name}: H {} against {h}", kw.h);
            assert!(close(kw.p, p), "{name}: p {} against {p}", kw.p);
            assert_eq!(kw.df, groups.len() - 1);
            let mut ps = Vec::new();
            for pair in case["pairs"].as_array().unwrap() {
                let (i, j) = (
                    pair["first"].as_u64().unwrap() as usize,
                    pair["second"].as_u64().unwrap() as usize,
                );
                let c = Comparison::of(&groups[i], &groups[j]).unwrap();
                let want = pair["p"].as_f64().unwrap();
                assert_eq!(c.method, pair["method"].as_str().unwrap(), "{name} {i}-{j}");
                assert_eq!(c.u, pair["u"].as_f64().unwrap(), "{name} {i}-{j}: U");
                assert!(close(c.p, want), "{name} {i}-{j}: p {} against {want}", c.p);
                ps.push(c.p);
            }
            for (got, pair) in holm(&ps).iter().zip(case["pairs"].as_array().unwrap()) {
                let want = pair["p_holm"].as_f64().unwrap();
                assert!(close(*got, want), "{name}: Holm p {got} against {want}");
            }
        }
    }

    #[test]
    fn holm_multiplies_the_smallest_by_the_count_and_never_falls() {
        let all_close =
            |got: Vec<f64>, want: &[f64]| got.iter().zip(want).all(|(g, w)| close(*g, *w));
        assert!(all_close(holm(&[0.01, 0.04, 0.03]), &[0.03, 0.06, 0.06]));
        assert!(all_close(holm(&[0.5, 0.001]), &[0.5, 0.002]));
        assert_eq!(holm(&[0.9, 0.8]), vec![1.0, 1.0]);
        assert!(
            KruskalWallis::of(&[vec![1.0, 1.0], vec![1.0]]).is_none(),
            "all values equal"
        );
        assert!(
            KruskalWallis::of(&[vec![1.0, 2.0]]).is_none(),
            "one condition"
        );
    }

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
