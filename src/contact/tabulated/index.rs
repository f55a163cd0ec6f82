//! The lookup index of a segment: a bucket from the bit pattern of
//! `max(d − d₀, 0) + bias` (a piecewise-linear logarithm of `d`), then a
//! short walk to the interval holding `d` (see the module documentation's
//! lookup).

use super::segment::{d_of_u, Interval, Segment};
/// Largest lookup index per segment (entries).
const MAX_INDEX: usize = 1 << 16;

impl Segment {
    /// Index key of `d` (see [`Segment::interval`]): never negative, as
    /// `max(d − d0, 0) + bias ≥ bias`.
    #[inline]
    pub(super) fn key(&self, d: f64) -> u64 {
        ((d - self.d0).max(0.0) + self.bias).to_bits() - self.bias_bits
    }

    #[inline(always)]
    pub(super) fn interval(&self, d: f64) -> &Interval {
        let b = ((self.key(d) >> self.shift) as usize).min(self.index.len() - 1);
        // SAFETY (the invariants of `build`, and a segment is never changed
        // after it): the index is not empty, so `b` is in range; its entries
        // are below `intervals.len() == ends.len()`; the last end is +∞ and
        // the walk compares a finite value (NaN becomes f64::MAX), so it
        // stops in range.
        unsafe {
            let mut i = *self.index.get_unchecked(b) as usize;
            let dw = d.min(f64::MAX);
            while dw >= *self.ends.get_unchecked(i) {
                i += 1;
            }
            self.intervals.get_unchecked(i)
        }
    }

    /// Fill `shift` and `index` for the intervals, `ends` their ends in `d`
    /// (the last one still finite).
    pub(super) fn build_index(&mut self, ends: &[f64]) {
        // The coarsest index (largest shift) whose buckets hold at most two
        // interval starts, within MAX_INDEX entries.
        let keys: Vec<u64> = self
            .intervals
            .iter()
            .map(|iv| self.key(d_of_u(self.sqrt, iv.lo)))
            .collect();
        let kmax = self.key(ends[ends.len() - 1]);
        let mut best = 62u32;
        for shift in (0..=62u32).rev() {
            let nb = (kmax >> shift) + 1;
            if nb as usize > MAX_INDEX {
                break;
            }
            best = shift;
            let mut worst = 0;
            let mut run = 0;
            let mut prev = None;
            for &k in &keys {
                let b = Some(k >> shift);
                run = if b == prev { run + 1 } else { 1 };
                prev = b;
                worst = worst.max(run);
            }
            if worst <= 2 {
                break;
            }
        }
        self.shift = best;
        let nb = ((kmax >> best) + 1) as usize;
        let mut index = Vec::with_capacity(nb);
        let mut j = 0usize;
        for b in 0..nb as u64 {
            // Largest interval whose start key lies in an earlier bucket.
            while j + 1 < keys.len() && (keys[j + 1] >> best) < b {
                j += 1;
            }
            index.push(j as u32);
        }
        self.index = index;
    }
}
