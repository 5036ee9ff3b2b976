//! The one source of randomness. Every model draws from a [`Rng`] seeded from its scenario, so a
//! scenario and a seed give the same run natively and in wasm.
//!
//! Only fixed-width integer draws are offered: sampling a `usize` range would draw differently on
//! 64-bit native targets and 32-bit wasm.

use rand::{Rng as _, RngCore, SeedableRng};
use rand_pcg::Pcg64Mcg;

/// A seeded, portable pseudo-random generator (PCG 64 MCG, pinned crate version).
#[derive(Clone, Debug)]
pub struct Rng(Pcg64Mcg);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(Pcg64Mcg::seed_from_u64(seed))
    }

    /// An independent stream for a sub-process (disturbances, initial placement), so adding
    /// draws in one process does not shift another.
    pub fn stream(seed: u64, stream: u64) -> Self {
        Rng::new(seed ^ stream.wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(17))
    }

    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        self.0.next_u32()
    }

    /// Uniform in `0..n`. Panics if `n == 0`.
    #[inline]
    pub fn below(&mut self, n: u32) -> u32 {
        self.0.random_range(0..n)
    }

    /// Uniform index into a slice of length `n` (at most `u32::MAX`).
    #[inline]
    pub fn index(&mut self, n: usize) -> usize {
        let n = u32::try_from(n).expect("Rng::index: length exceeds u32");
        self.below(n) as usize
    }

    /// Uniform in `[0, 1)`.
    #[inline]
    pub fn unit(&mut self) -> f64 {
        self.0.random::<f64>()
    }

    /// True with probability `p`.
    #[inline]
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// Fisher-Yates shuffle.
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.index(i + 1);
            items.swap(i, j);
        }
    }

    pub fn choose<'a, T>(&mut self, items: &'a [T]) -> Option<&'a T> {
        if items.is_empty() {
            None
        } else {
            Some(&items[self.index(items.len())])
        }
    }

    /// An index drawn with probability proportional to `weights[i]` (non-negative, finite).
    /// Returns `None` when every weight is zero.
    #[inline]
    pub fn weighted(&mut self, weights: &[f64]) -> Option<usize> {
        let total: f64 = weights.iter().sum();
        if total.is_nan() || total <= 0.0 {
            return None;
        }
        let mut target = self.unit() * total;
        let mut last = None;
        for (i, &w) in weights.iter().enumerate() {
            if w > 0.0 {
                if target < w {
                    return Some(i);
                }
                target -= w;
                last = Some(i);
            }
        }
        last
    }

    /// `k` distinct indices out of `0..n`, in draw order (partial Fisher-Yates).
    pub fn sample_distinct(&mut self, n: usize, k: usize) -> Vec<usize> {
        let mut pool: Vec<usize> = (0..n).collect();
        let k = k.min(n);
        for i in 0..k {
            let j = i + self.index(n - i);
            pool.swap(i, j);
        }
        pool.truncate(k);
        pool
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_stream() {
        let mut a = Rng::new(42);
        let mut b = Rng::new(42);
        for _ in 0..100 {
            assert_eq!(a.next_u64(), b.next_u64());
        }
        assert_ne!(Rng::new(1).next_u64(), Rng::new(2).next_u64());
    }

    #[test]
    fn pinned_values_do_not_drift() {
        // The values rand 0.9.2 and rand_pcg 0.9.0 gave when the golden hashes were made. If this
        // fails, the generator, its seeding or its range sampling changed, and every golden hash
        // and every shared link's run with it.
        let mut r = Rng::new(7);
        let u64s: Vec<u64> = (0..3).map(|_| r.next_u64()).collect();
        assert_eq!(
            u64s,
            [
                12_726_360_963_827_698_830,
                8_784_933_628_230_385_458,
                4_994_307_442_345_819_819
            ]
        );
        let below: Vec<u32> = (0..6).map(|_| r.below(1000)).collect();
        assert_eq!(below, [384, 561, 331, 231, 405, 228]);
        assert_eq!(r.unit().to_bits(), 0.246_767_400_509_228_52_f64.to_bits());
        let mut s = Rng::stream(7, 3);
        let stream: Vec<u32> = (0..3).map(|_| s.next_u32()).collect();
        assert_eq!(stream, [1_766_022_660, 256_879_144, 3_801_951_831]);
    }

    #[test]
    fn weighted_respects_zero_weights() {
        let mut r = Rng::new(3);
        for _ in 0..1000 {
            let i = r.weighted(&[0.0, 2.0, 0.0, 1.0]).unwrap();
            assert!(i == 1 || i == 3);
        }
        assert_eq!(r.weighted(&[0.0, 0.0]), None);
    }

    #[test]
    fn sample_distinct_is_distinct() {
        let mut r = Rng::new(9);
        let mut s = r.sample_distinct(50, 20);
        assert_eq!(s.len(), 20);
        s.sort_unstable();
        s.dedup();
        assert_eq!(s.len(), 20);
        assert!(s.iter().all(|&i| i < 50));
    }

    #[test]
    fn shuffle_is_a_permutation() {
        let mut r = Rng::new(11);
        let mut v: Vec<u32> = (0..100).collect();
        r.shuffle(&mut v);
        assert_ne!(v, (0..100).collect::<Vec<_>>());
        v.sort_unstable();
        assert_eq!(v, (0..100).collect::<Vec<_>>());
    }
}
