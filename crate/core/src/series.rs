//! Every step's metrics of a run, kept in bounded memory for the live chart.
//!
//! The page draws far fewer frames than a fast run takes steps, so a chart fed from frames misses
//! what happens between them: a fault and its repair inside one frame never show. A [`Series`] is
//! fed every step instead. It keeps each metric's least and greatest value per *bucket* of steps:
//! one step a bucket at first; when more than [`Series::capacity`] buckets are held, neighbouring
//! pairs merge and a bucket covers twice the steps. A short spike therefore survives any amount of
//! merging as the minimum or maximum of its bucket. Memory: at most `capacity` buckets of one step
//! number and two values per metric, `capacity × (8 + 16 × metrics)` bytes (1.4 MB for the default
//! 4096 buckets and 20 metrics).
//!
//! [`Series::decimate`] then merges buckets once more into as many as the chart has pixels, for
//! drawing only.

use crate::models::{Metrics, Model};

/// Buckets kept before pairs merge: full resolution for the first 4096 steps.
pub const DEFAULT_CAPACITY: usize = 4096;

#[derive(Clone, Debug)]
pub struct Series {
    names: Vec<String>,
    capacity: usize,
    /// Steps a bucket covers: a power of two. Bucket `k` covers steps `[k·span, (k+1)·span)`.
    span: u64,
    /// The bucket number of each bucket held, ascending.
    keys: Vec<u64>,
    /// Per bucket, per metric: the least and the greatest value recorded (NaN when none was a
    /// number), `names.len()` values a bucket.
    mins: Vec<f64>,
    maxs: Vec<f64>,
    /// The last step recorded.
    last: Option<u64>,
    /// The metrics in the order [`Series::record_model`] was last given them, with their slots.
    order: Vec<(&'static str, Option<usize>)>,
}

/// A metric's values drawn as a band: per point, the first step of its range and the least and
/// greatest value within it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Band {
    pub steps: Vec<f64>,
    pub min: Vec<f64>,
    pub max: Vec<f64>,
}

impl Series {
    /// An empty series for the metrics in `first` (the names are fixed from it; a metric that
    /// appears later is not recorded).
    pub fn new(first: &Metrics, capacity: usize) -> Series {
        Series {
            names: {
                let mut names: Vec<String> = first.keys().cloned().collect();
                kumiki_model::sort::sort(&mut names);
                names
            },
            capacity: capacity.max(2),
            span: 1,
            keys: Vec::new(),
            mins: Vec::new(),
            maxs: Vec::new(),
            last: None,
            order: Vec::new(),
        }
    }

    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Steps each bucket covers now.
    pub fn span(&self) -> u64 {
        self.span
    }

    /// Buckets held.
    pub fn len(&self) -> usize {
        self.keys.len()
    }

    pub fn is_empty(&self) -> bool {
        self.keys.is_empty()
    }

    /// The last step recorded.
    pub fn last_step(&self) -> Option<u64> {
        self.last
    }

    /// Records the metrics at `step`. A step at or before the last one recorded is ignored: after
    /// going back, a run passes through the very same states again.
    pub fn record(&mut self, step: u64, metrics: &Metrics) {
        let Some(at) = self.open(step) else {
            return;
        };
        for (name, value) in metrics {
            let value = value
                .as_f64()
                .or_else(|| value.as_bool().map(|b| f64::from(u8::from(b))));
            let slot = self.slot_of(name);
            self.put(at, slot, value);
        }
        self.close();
    }

    /// [`Series::record`] of the model's metrics as it stands, read one by one
    /// ([`Model::each_metric`]) without building a map: the page records every step. A model
    /// gives its metrics in the same order each step, so each one's place is looked up by name
    /// once and then known by its position (checked by the name's address, not its letters).
    pub fn record_model(&mut self, step: u64, model: &dyn Model) {
        let Some(at) = self.open(step) else {
            return;
        };
        let mut position = 0;
        model.each_metric(&mut |name, value| {
            let slot = match self.order.get(position) {
                Some(&(known, slot)) if std::ptr::eq(known, name) => slot,
                _ => {
                    let slot = self.slot_of(name);
                    self.order.truncate(position);
                    self.order.push((name, slot));
                    slot
                }
            };
            position += 1;
            self.put(at, slot, value.plotted());
        });
        self.close();
    }

    /// Where the values of the metric `name` go in a bucket, if it is recorded.
    fn slot_of(&self, name: &str) -> Option<usize> {
        // The names are sorted (see `new`).
        self.names.binary_search_by(|n| n.as_str().cmp(name)).ok()
    }

    /// Starts recording `step`: the first value of its bucket's slots, opening the bucket when it
    /// is new; none when the step was recorded already.
    fn open(&mut self, step: u64) -> Option<usize> {
        if self.last.is_some_and(|last| step <= last) {
            return None;
        }
        self.last = Some(step);
        let key = step / self.span;
        let k = self.names.len();
        if self.keys.last() != Some(&key) {
            self.keys.push(key);
            self.mins.extend(std::iter::repeat_n(f64::NAN, k));
            self.maxs.extend(std::iter::repeat_n(f64::NAN, k));
        }
        Some((self.keys.len() - 1) * k)
    }

    /// Widens the slot's range in the bucket starting at `at` to hold `value`.
    fn put(&mut self, at: usize, slot: Option<usize>, value: Option<f64>) {
        if let (Some(i), Some(v)) = (slot, value) {
            // f64::min and max keep the number when the other side is NaN.
            self.mins[at + i] = self.mins[at + i].min(v);
            self.maxs[at + i] = self.maxs[at + i].max(v);
        }
    }

    /// Ends recording a step: merges buckets when more than the capacity are held.
    fn close(&mut self) {
        if self.keys.len() > self.capacity {
            self.merge_pairs();
        }
    }

    /// Doubles the span: buckets `2j` and `2j + 1` become bucket `j`.
    fn merge_pairs(&mut self) {
        self.span *= 2;
        let k = self.names.len();
        let mut out = 0;
        for i in 0..self.keys.len() {
            let key = self.keys[i] / 2;
            if out > 0 && self.keys[out - 1] == key {
                for m in 0..k {
                    self.mins[(out - 1) * k + m] =
                        self.mins[(out - 1) * k + m].min(self.mins[i * k + m]);
                    self.maxs[(out - 1) * k + m] =
                        self.maxs[(out - 1) * k + m].max(self.maxs[i * k + m]);
                }
            } else {
                self.keys[out] = key;
                for m in 0..k {
                    self.mins[out * k + m] = self.mins[i * k + m];
                    self.maxs[out * k + m] = self.maxs[i * k + m];
                }
                out += 1;
            }
        }
        self.keys.truncate(out);
        self.mins.truncate(out * k);
        self.maxs.truncate(out * k);
    }

    /// Forgets every bucket that reaches past `step`: the run forked there. The bucket holding
    /// `step` goes too (its values cannot be taken apart), so up to `span − 1` steps before the
    /// fork are no longer shown.
    pub fn truncate(&mut self, step: u64) {
        let keep = self
            .keys
            .iter()
            .take_while(|&&key| (key + 1) * self.span - 1 <= step)
            .count();
        let k = self.names.len();
        self.keys.truncate(keep);
        self.mins.truncate(keep * k);
        self.maxs.truncate(keep * k);
        self.last = self.last.map(|last| last.min(step));
    }

    /// A metric's band over at most `points` points spanning the steps recorded, each the least
    /// and greatest value of the buckets it covers. Empty for a metric not recorded.
    pub fn decimate(&self, name: &str, points: usize) -> Band {
        let Some(m) = self.names.iter().position(|n| n == name) else {
            return Band::default();
        };
        let (Some(&first), Some(&last)) = (self.keys.first(), self.keys.last()) else {
            return Band::default();
        };
        let k = self.names.len();
        // Consecutive buckets per point, so that points never split a bucket.
        let per = (last - first + 1).div_ceil(points.max(1) as u64).max(1);
        let mut band = Band::default();
        let mut group = None;
        for (i, &key) in self.keys.iter().enumerate() {
            let (lo, hi) = (self.mins[i * k + m], self.maxs[i * k + m]);
            let g = (key - first) / per;
            if group == Some(g) {
                let j = band.min.len() - 1;
                band.min[j] = band.min[j].min(lo);
                band.max[j] = band.max[j].max(hi);
            } else {
                group = Some(g);
                band.steps.push(((first + g * per) * self.span) as f64);
                band.min.push(lo);
                band.max.push(hi);
            }
        }
        band
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn metrics(v: f64) -> Metrics {
        let mut m = Metrics::new();
        m.insert("value".into(), json!(v));
        m.insert("done".into(), json!(v > 5.0));
        m.insert("label".into(), json!("text"));
        m
    }

    #[test]
    fn every_step_is_kept_until_the_capacity_then_pairs_merge() {
        let mut s = Series::new(&metrics(0.0), 8);
        for step in 0..8 {
            s.record(step, &metrics(step as f64));
        }
        assert_eq!((s.len(), s.span()), (8, 1));
        s.record(8, &metrics(8.0));
        assert_eq!((s.len(), s.span()), (5, 2));
        let band = s.decimate("value", 100);
        assert_eq!(band.steps, vec![0.0, 2.0, 4.0, 6.0, 8.0]);
        assert_eq!(band.min, vec![0.0, 2.0, 4.0, 6.0, 8.0]);
        assert_eq!(band.max, vec![1.0, 3.0, 5.0, 7.0, 8.0]);
        assert_eq!(s.decimate("done", 100).max, vec![0.0, 0.0, 0.0, 1.0, 1.0]);
        assert!(s.decimate("label", 100).min.iter().all(|v| v.is_nan()));
    }

    #[test]
    fn memory_stays_bounded_and_a_one_step_spike_survives() {
        let mut s = Series::new(&metrics(0.0), 64);
        for step in 0..100_000u64 {
            let v = if step == 77_777 { -5.0 } else { 1.0 };
            s.record(step, &metrics(v));
            assert!(s.len() <= 64);
        }
        assert!(s.span() >= 100_000 / 64);
        let band = s.decimate("value", 10);
        assert!(band.steps.len() <= 10);
        assert_eq!(band.min.iter().cloned().fold(f64::INFINITY, f64::min), -5.0);
        assert_eq!(
            band.max.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
            1.0
        );
    }

    #[test]
    fn steps_replayed_after_going_back_are_not_recorded_twice_and_a_fork_truncates() {
        let mut s = Series::new(&metrics(0.0), 4);
        for step in 0..10 {
            s.record(step, &metrics(step as f64));
        }
        s.record(3, &metrics(100.0));
        assert_eq!(s.decimate("value", 100).max.last(), Some(&9.0));
        assert_eq!(s.span(), 4);
        // Buckets [0, 4) and [4, 8) end by step 9; [8, 12) does not and goes.
        s.truncate(9);
        assert_eq!(s.decimate("value", 100).steps, vec![0.0, 4.0]);
        s.record(10, &metrics(-1.0));
        assert_eq!(s.decimate("value", 100).min, vec![0.0, 4.0, -1.0]);
        assert_eq!(s.last_step(), Some(10));
    }

    #[test]
    fn reading_the_model_records_what_its_metrics_map_holds() {
        for name in crate::presets::names() {
            let scenario = crate::presets::scenario(name).unwrap();
            let mut model = scenario.build().unwrap();
            let first = model.metrics();
            let (mut by_map, mut by_model) = (Series::new(&first, 64), Series::new(&first, 64));
            for step in 0..40 {
                by_map.record(step, &model.metrics());
                by_model.record_model(step, model.as_ref());
                model.step();
            }
            for metric in first.keys() {
                let (a, b) = (by_map.decimate(metric, 16), by_model.decimate(metric, 16));
                assert_eq!(format!("{a:?}"), format!("{b:?}"), "{name}: {metric}");
            }
        }
    }
}
