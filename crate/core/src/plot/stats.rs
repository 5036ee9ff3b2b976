//! The statistics of a condition's runs and of conditions compared: n, mean, sd, median,
//! quartiles and a 95% interval of the mean (Student's t). Two conditions are compared by
//! [`Comparison`] (first minus second), three or more by [`KruskalWallis`] and every pair with
//! [`holm`]'s correction; these live in the contract so that a model's paper findings test their
//! claims with the same statistics the figures show.

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

pub use kumiki_model::stats::{holm, Comparison, KruskalWallis};
