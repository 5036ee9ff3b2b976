//! The statistics of a condition's runs and of a two-condition comparison: n, mean, sd, median,
//! quartiles, a 95% interval of the mean (Student's t), an effect size (Cohen's d and the
//! rank-biserial correlation) and the Mann-Whitney U test.

use serde::Serialize;

/// The statistics of the finite values of one condition.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Stats {
    pub n: usize,
    pub mean: f64,
    /// Sample standard deviation (n − 1); 0 for one value.
    pub sd: f64,
    pub min: f64,
    pub q1: f64,
    pub median: f64,
    pub q3: f64,
    pub max: f64,
    /// The 95% confidence interval of the mean, mean ± t(0.975, n − 1) · sd / √n; the mean
    /// itself for one value.
    pub ci95: [f64; 2],
}

impl Stats {
    /// The statistics of `values`, non-finite ones left out; `None` without any. The summary is
    /// the reproduction report's ([`crate::reproduce::Stats`]), with the interval added.
    pub fn of(values: &[f64]) -> Option<Stats> {
        let v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
        if v.is_empty() {
            return None;
        }
        let r = crate::reproduce::Stats::of(&v);
        let half = match r.n {
            1 => 0.0,
            n => t975(n - 1) * r.sd / (n as f64).sqrt(),
        };
        Some(Stats {
            n: r.n,
            mean: r.mean,
            sd: r.sd,
            min: r.min,
            q1: r.q1,
            median: r.median,
            q3: r.q3,
            max: r.max,
            ci95: [r.mean - half, r.mean + half],
        })
    }
}

/// Type-7 quantiles, as the reproduction report computes them.
pub use crate::reproduce::quantile;

/// The 0.975 quantile of Student's t with `df` degrees of freedom: exact to three decimals from
/// the table up to 30, then the Cornish-Fisher expansion (error below 1e-4).
pub fn t975(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
        2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
        2.052, 2.048, 2.045, 2.042,
    ];
    if (1..=30).contains(&df) {
        return TABLE[df - 1];
    }
    let z: f64 = 1.959_963_984_540_054;
    let d = df.max(1) as f64;
    z + (z.powi(3) + z) / (4.0 * d)
        + (5.0 * z.powi(5) + 16.0 * z.powi(3) + 3.0 * z) / (96.0 * d * d)
        + (3.0 * z.powi(7) + 19.0 * z.powi(5) + 17.0 * z.powi(3) - 15.0 * z) / (384.0 * d.powi(3))
}

/// Two conditions compared: the difference of means, effect sizes and the Mann-Whitney U test
/// (two-sided).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[schemars(rename = "StatisticalComparison")]
pub struct Comparison {
    /// Mean of the second condition minus mean of the first.
    pub difference: f64,
    /// Cohen's d: the difference over the pooled sd (NaN when both sds are 0).
    pub cohens_d: f64,
    /// U of the first condition: pairs where its value is larger, ties counting one half.
    pub u: f64,
    /// The rank-biserial correlation 2U/(n1·n2) − 1, from −1 (all of the first below the second)
    /// to 1.
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
        let (sa, sb) = (Stats::of(&a)?, Stats::of(&b)?);
        let (n1, n2) = (a.len(), b.len());
        let pooled = match n1 + n2 {
            0..=2 => f64::NAN,
            _ => (((n1 - 1) as f64 * sa.sd.powi(2) + (n2 - 1) as f64 * sb.sd.powi(2))
                / (n1 + n2 - 2) as f64)
                .sqrt(),
        };
        let cohens_d = match pooled > 0.0 {
            true => (sb.mean - sa.mean) / pooled,
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
        kumiki_model::sort::sort_by(&mut all, f64::total_cmp);
        ties |= all.windows(2).any(|w| w[0] == w[1]);
        let (p, method) = match !ties && n1 * n2 <= 10_000 {
            true => (exact_p(n1, n2, u), "exact"),
            false => (normal_p(n1, n2, u, &all), "normal"),
        };
        Some(Comparison {
            difference: sb.mean - sa.mean,
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
