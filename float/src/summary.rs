//! Mergeable summaries of a sweep's errors: what lets a sweep run as shards on many machines and
//! be merged into exactly the report one run would give.
//!
//! A [`Distribution`] is the multiset of one error measure (ulps, or relative error) over the
//! compared samples, kept as a map from value to count. Counts, maxima and worst cases merge
//! trivially; a median does not, unless the summary it is read from merges. So the report's
//! median and mean are **always** read from this summary, in one run as in a merged one:
//!
//! * while the multiset has at most [`EXACT_DISTINCT`] distinct values it is kept **exactly**,
//!   and the median is the exact median (the mean of the two middle values for an even count);
//! * beyond that it is **collapsed**: every value is replaced by its bucket's lower edge, the
//!   double with the same sign, exponent and top [`BUCKET_MANTISSA_BITS`] mantissa bits
//!   (relative resolution `2^-8`, about 0.4 %), and every later value is bucketed on arrival.
//!
//! Bucketing is idempotent and the collapse decision depends only on the multiset (a summary is
//! collapsed exactly when its multiset has more than [`EXACT_DISTINCT`] distinct values, or when
//! it was built from a collapsed part — and then the whole has more too), so merging summaries in
//! any order and grouping gives the same summary as one pass over all samples. The mean is read
//! from the map in ascending order, so it too is a function of the summary alone.
//!
//! Herbie's "bits of error" ([`herbie_bits`]) is averaged with an exact fixed-point accumulator
//! ([`BitsSum`]) for the same reason: a sum of `f64`s depends on the order of addition.

use exactcheck_exact::to_f64::Format;
use std::collections::BTreeMap;

/// Distinct values kept exactly before a [`Distribution`] collapses to buckets.
pub const EXACT_DISTINCT: usize = 65_536;

/// Mantissa bits kept by a collapsed [`Distribution`]'s buckets.
pub const BUCKET_MANTISSA_BITS: u32 = 8;

/// The multiset of a non-negative error measure (`+inf` allowed), mergeable (module docs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Distribution {
    /// Whether the values are bucketed.
    collapsed: bool,
    /// Value (as the bits of a non-negative double, whose order is the numeric order) to count.
    counts: BTreeMap<u64, u64>,
}

/// The bucket of a non-negative double's bits.
fn bucket(bits: u64) -> u64 {
    let drop = 52 - BUCKET_MANTISSA_BITS;
    bits & !((1u64 << drop) - 1)
}

impl Distribution {
    /// The empty distribution.
    pub fn new() -> Distribution {
        Distribution::default()
    }

    /// Adds one value; a NaN or a negative value (not an error measure) reads as `+inf`, and
    /// `-0.0` as `0`.
    pub fn push(&mut self, v: f64) {
        let v = if v.is_nan() || v < 0.0 {
            f64::INFINITY
        } else {
            v + 0.0
        };
        self.add_bits(v.to_bits(), 1);
    }

    fn add_bits(&mut self, bits: u64, n: u64) {
        let key = if self.collapsed { bucket(bits) } else { bits };
        *self.counts.entry(key).or_insert(0) += n;
        if !self.collapsed && self.counts.len() > EXACT_DISTINCT {
            self.collapse();
        }
    }

    fn collapse(&mut self) {
        let old = std::mem::take(&mut self.counts);
        self.collapsed = true;
        for (bits, n) in old {
            *self.counts.entry(bucket(bits)).or_insert(0) += n;
        }
    }

    /// Adds every value of `other` (the union of the multisets, see the module docs).
    pub fn merge(&mut self, other: &Distribution) {
        if other.collapsed && !self.collapsed {
            self.collapse();
        }
        for (&bits, &n) in &other.counts {
            self.add_bits(bits, n);
        }
    }

    /// Whether the values are bucketed (the median and mean are then those of the bucket edges).
    pub fn is_collapsed(&self) -> bool {
        self.collapsed
    }

    /// The number of values.
    pub fn len(&self) -> u64 {
        self.counts.values().sum()
    }

    /// Whether there is no value.
    pub fn is_empty(&self) -> bool {
        self.counts.is_empty()
    }

    /// The value of rank `k` (0-based, ascending).
    fn at(&self, k: u64) -> f64 {
        let mut seen = 0;
        for (&bits, &n) in &self.counts {
            seen += n;
            if k < seen {
                return f64::from_bits(bits);
            }
        }
        unreachable!("rank {k} below the count {seen}")
    }

    /// The median (the mean of the two middle values for an even count; 0 when empty).
    pub fn median(&self) -> f64 {
        let n = self.len();
        if n == 0 {
            return 0.0;
        }
        let (a, b) = (self.at((n - 1) / 2), self.at(n / 2));
        if a == b {
            a
        } else {
            a + (b - a) / 2.0
        }
    }

    /// The mean of the finite values (0 when there is none), summed in ascending order.
    pub fn mean_finite(&self) -> f64 {
        let (mut sum, mut count) = (0.0f64, 0u64);
        for (&bits, &n) in &self.counts {
            let v = f64::from_bits(bits);
            if v.is_finite() {
                sum += v * n as f64;
                count += n;
            }
        }
        if count == 0 {
            0.0
        } else {
            sum / count as f64
        }
    }

    /// The `(value, count)` pairs in ascending order (for serialisation).
    pub fn entries(&self) -> Vec<(f64, u64)> {
        self.counts
            .iter()
            .map(|(&bits, &n)| (f64::from_bits(bits), n))
            .collect()
    }

    /// The largest value (its bucket edge when collapsed); 0 when empty, as a sweep's maximum
    /// starts at 0.
    pub fn largest(&self) -> f64 {
        self.counts
            .last_key_value()
            .map_or(0.0, |(&bits, _)| f64::from_bits(bits))
    }

    /// Whether `v` is the largest value: equal to it, or in its bucket when collapsed (the
    /// maximum of the empty distribution is 0). False for a NaN or negative `v`.
    pub fn largest_is(&self, v: f64) -> bool {
        if v.is_nan() || v < 0.0 {
            return false;
        }
        let bits = (v + 0.0).to_bits();
        let key = if self.collapsed { bucket(bits) } else { bits };
        key == self.largest().to_bits()
    }

    /// How many values are infinite.
    pub fn infinite(&self) -> u64 {
        self.counts
            .get(&f64::INFINITY.to_bits())
            .copied()
            .unwrap_or(0)
    }

    /// Bounds on how many values exceed `t`: exact (both equal) unless collapsed, where the
    /// values of the bucket holding `t` may lie on either side of it.
    pub fn count_above(&self, t: f64) -> (u64, u64) {
        let (mut surely, mut maybe) = (0u64, 0u64);
        for (&bits, &n) in &self.counts {
            let v = f64::from_bits(bits);
            if v > t {
                surely += n;
            } else if self.collapsed && t >= 0.0 && bucket((t + 0.0).to_bits()) == bits {
                maybe += n;
            }
        }
        (surely, surely + maybe)
    }

    /// Rebuilds a distribution from [`Distribution::entries`] and [`Distribution::is_collapsed`].
    ///
    /// # Errors
    /// A value that is NaN or negative, a zero count, counts whose total exceeds `u64::MAX`, or
    /// a collapsed summary with a value that is not a bucket edge (not something this module
    /// wrote).
    pub fn from_entries(collapsed: bool, entries: &[(f64, u64)]) -> Result<Distribution, String> {
        let mut d = Distribution {
            collapsed,
            counts: BTreeMap::new(),
        };
        let mut total = 0u64;
        for &(v, n) in entries {
            if v.is_nan() || v < 0.0 || n == 0 {
                return Err(format!(
                    "summary entry ({v}, {n}) is not a value with a count"
                ));
            }
            total = total
                .checked_add(n)
                .ok_or_else(|| format!("summary counts add up to more than {}", u64::MAX))?;
            let bits = (v + 0.0).to_bits();
            if collapsed && bucket(bits) != bits {
                return Err(format!("collapsed summary value {v} is not a bucket edge"));
            }
            *d.counts.entry(bits).or_insert(0) += n;
        }
        if !collapsed && d.counts.len() > EXACT_DISTINCT {
            d.collapse();
        }
        Ok(d)
    }
}

/// The position of a double in the order of all doubles (`-0.0` and `0.0` share one; adjacent
/// doubles differ by one). `None` for NaN.
pub fn ordinal(x: f64) -> Option<i64> {
    if x.is_nan() {
        return None;
    }
    let bits = (x + 0.0).to_bits() as i64;
    Some(if bits < 0 { -(bits & i64::MAX) } else { bits })
}

/// Herbie's bits of error of `approx` against the double nearest to the exact value:
/// `log2(1 + n)` with `n` the number of doubles between them (their ordinal distance); 64 for a
/// NaN on either side.
pub fn herbie_bits(approx: f64, rounded_exact: f64) -> f64 {
    match (ordinal(approx), ordinal(rounded_exact)) {
        (Some(a), Some(b)) => ((a as i128 - b as i128).unsigned_abs() as f64 + 1.0).log2(),
        _ => 64.0,
    }
}

/// [`herbie_bits`] over the values of `format`: `log2(1 + n)` with `n` the number of values of
/// the format between `approx` and `rounded_exact` (both values of it); the format's width (64
/// or 32) for a NaN on either side.
pub fn herbie_bits_in(format: Format, approx: f64, rounded_exact: f64) -> f64 {
    match format {
        Format::Binary64 => herbie_bits(approx, rounded_exact),
        Format::Binary32 => {
            if approx.is_nan() || rounded_exact.is_nan() {
                return 32.0;
            }
            let d = (format.ordinal(approx) - format.ordinal(rounded_exact)).unsigned_abs();
            (d as f64 + 1.0).log2()
        }
    }
}

/// An exact sum of bits-of-error values: each is rounded once to a multiple of `2^-40` and added
/// as an integer, so the sum (and the mean) does not depend on the order of the samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BitsSum {
    /// The sum in units of `2^-40`.
    pub units: u128,
    /// The number of values summed.
    pub count: u64,
}

impl BitsSum {
    const SCALE: f64 = (1u64 << 40) as f64;

    /// Adds one value in `[0, 64]`.
    pub fn push(&mut self, bits: f64) {
        self.units += (bits.clamp(0.0, 64.0) * Self::SCALE).round() as u128;
        self.count += 1;
    }

    /// Adds another sum.
    pub fn merge(&mut self, other: &BitsSum) {
        self.units += other.units;
        self.count += other.count;
    }

    /// Whether every value summed can have been at most `max_bits` (each was rounded to a
    /// multiple of `2^-40` alone, so the sum is at most `count` times the rounded maximum).
    pub fn within(&self, max_bits: f64) -> bool {
        let top = (max_bits.clamp(0.0, 64.0) * Self::SCALE).round() as u128;
        self.units <= top * u128::from(self.count)
    }

    /// The mean (0 when empty).
    pub fn mean(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            self.units as f64 / Self::SCALE / self.count as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;

    #[test]
    fn exact_medians_and_means() {
        let mut d = Distribution::new();
        assert_eq!((d.median(), d.mean_finite()), (0.0, 0.0));
        for v in [3.0, 1.0, 2.0, f64::INFINITY] {
            d.push(v);
        }
        assert_eq!(d.median(), 2.5);
        assert_eq!(d.mean_finite(), 2.0);
        d.push(-0.0);
        assert_eq!(d.median(), 2.0);
        assert!(!d.is_collapsed());
    }

    /// Merging shards in any grouping gives the one-pass summary, collapsed or not.
    #[test]
    fn merging_equals_one_pass() {
        for n in [100usize, 100_000] {
            let mut rng = Rng::new(7);
            let values: Vec<f64> = (0..n)
                .map(|_| {
                    if rng.uniform(0.0, 1.0) < 0.01 {
                        f64::INFINITY
                    } else {
                        rng.uniform(0.0, 1e6).floor() / 4.0
                    }
                })
                .collect();
            let mut whole = Distribution::new();
            values.iter().for_each(|&v| whole.push(v));
            for parts in [2, 3, 7] {
                let mut merged = Distribution::new();
                for chunk in values.chunks(n.div_ceil(parts)).rev() {
                    let mut d = Distribution::new();
                    chunk.iter().for_each(|&v| d.push(v));
                    merged.merge(&d);
                }
                assert_eq!(merged, whole, "n = {n}, {parts} parts");
            }
            assert_eq!(whole.is_collapsed(), n > EXACT_DISTINCT);
            let back = Distribution::from_entries(whole.is_collapsed(), &whole.entries());
            assert_eq!(back, Ok(whole));
        }
    }

    #[test]
    fn collapsed_medians_are_close() {
        let mut d = Distribution::new();
        for i in 1..=100_001 {
            d.push(f64::from(i));
        }
        assert!(d.is_collapsed());
        let m = d.median();
        assert!((m - 50001.0).abs() / 50001.0 < 1.0 / 256.0, "{m}");
        assert!(Distribution::from_entries(true, &[(1.1, 1)]).is_err());
        assert!(Distribution::from_entries(false, &[(f64::NAN, 1)]).is_err());
    }

    /// What a shard's consistency check reads from a summary, and counts that cannot add up.
    #[test]
    fn largest_infinite_and_counts_above() {
        let mut d = Distribution::new();
        assert!(d.largest_is(0.0) && !d.largest_is(f64::NAN));
        for v in [0.5, 3.0, f64::INFINITY, 3.0] {
            d.push(v);
        }
        assert!(d.largest_is(f64::INFINITY) && !d.largest_is(3.0));
        assert_eq!(d.infinite(), 1);
        assert_eq!(d.count_above(1.0), (3, 3));
        assert_eq!(d.count_above(3.0), (1, 1));
        let c = Distribution::from_entries(true, &[(1.0, 2), (2.0, 5)]).unwrap();
        // 2.0 is a bucket edge: values in [2, 2 + 2^-7) may lie on either side of 2.001.
        assert_eq!(c.count_above(2.001), (0, 5));
        assert_eq!(c.count_above(1.5), (5, 5));
        assert!(c.largest_is(2.001) && !c.largest_is(2.1));
        let e = Distribution::from_entries(false, &[(1.0, u64::MAX), (2.0, 1)]).unwrap_err();
        assert!(e.contains("add up to more than"), "{e}");
        let mut b = BitsSum::default();
        b.push(3.0);
        b.push(5.0);
        assert!(b.within(5.0) && !b.within(3.9));
    }

    #[test]
    fn ordinals_and_bits() {
        assert_eq!(ordinal(0.0), ordinal(-0.0));
        assert_eq!(ordinal(f64::from_bits(1)), Some(1));
        assert_eq!(ordinal(-f64::from_bits(1)), Some(-1));
        assert_eq!(ordinal(1.0).map(|o| o + 1), ordinal(1.0 + f64::EPSILON));
        assert_eq!(herbie_bits(1.0, 1.0), 0.0);
        assert_eq!(herbie_bits(1.0 + f64::EPSILON, 1.0), 1.0);
        assert_eq!(herbie_bits(f64::NAN, 1.0), 64.0);
        assert!(herbie_bits(f64::MAX, -f64::MAX) <= 64.0);
        let mut s = BitsSum::default();
        s.push(1.0);
        s.push(2.0);
        assert_eq!(s.mean(), 1.5);
    }
}
