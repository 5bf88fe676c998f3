//! The fast f64 sampler of the cylinder/sphere discriminant (Spaeth,; workload W3).
//!
//! `A(t)` and `B(t)` are reduced once per configuration to fixed trigonometric-polynomial
//! coefficients ([`TrigCoefficients`], derived by the same generic code that the exact side runs),
//! then evaluated in batches over many `t`, on all cores (rayon). The grid is cut into fixed
//! chunks whose partial results are combined in chunk order, so the result does not depend on the
//! number of threads.
//!
//! Two sweeps of the grid `t_i = i 2 pi / n`:
//! * [`DiscSampler::sweep`] (and `sweep_serial`), the reference: `f64::sin_cos` per sample, one
//!   running sum per chunk;
//! * [`DiscSampler::sweep_addition`] (and `sweep_addition_serial`), the fast kernel of
//!   [`addition`]: angle addition per block (one `sin_cos` per 512 samples), discriminants and
//!   square roots in vectorized lanes, within the error bounds derived there of the reference.

use exactcheck_core::cylinder_sphere::{CylinderSphere, TrigCoefficients};
use rayon::prelude::*;

pub mod addition;

pub use addition::{sum_depth, sum_error_bound, AngleTable, KernelPath, BLOCK, LANES, TRIG_ERROR};

/// Samples per chunk (cache-sized; also the unit of the deterministic reduction).
pub const CHUNK: usize = 1 << 14;

/// Coefficients of `A` and `B` as plain f64 arrays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiscSampler {
    a: [f64; 3],
    b: [f64; 6],
}

/// What a sweep over a grid found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridSummary {
    /// Samples with `A^2 - B >= 0` (real points).
    pub count_nonneg: usize,
    /// `sum sqrt(A^2 - B)` over those samples (a checksum of the evaluated values).
    pub sum_sqrt: f64,
}

impl DiscSampler {
    /// The sampler of a configuration given in f64 (coefficients derived in f64).
    pub fn new(cs: &CylinderSphere<f64>) -> Self {
        Self::from_coefficients(&cs.trig_coefficients())
    }

    /// The sampler from coefficients (e.g. exact ones rounded to f64).
    pub fn from_coefficients(c: &TrigCoefficients<f64>) -> Self {
        DiscSampler { a: c.a, b: c.b }
    }

    /// `(A, B)` at `(cos t, sin t)`.
    #[inline(always)]
    pub fn ab(&self, c: f64, s: f64) -> (f64, f64) {
        let [a0, a1, a2] = self.a;
        let [b0, b1, b2, b3, b4, b5] = self.b;
        let a = a0 + a1 * c + a2 * s;
        let b = b0 + b1 * c + b2 * s + c * (b3 * c + b4 * s) + b5 * s * s;
        (a, b)
    }

    /// The discriminant `A^2 - B` at `(cos t, sin t)` (the operations every sweep uses).
    #[inline(always)]
    pub fn disc_cs(&self, c: f64, s: f64) -> f64 {
        let (a, b) = self.ab(c, s);
        a * a - b
    }

    /// The discriminant `A^2 - B` at the angle `t` (radians).
    #[inline]
    pub fn discriminant(&self, t: f64) -> f64 {
        let (s, c) = t.sin_cos();
        self.disc_cs(c, s)
    }

    /// The roots `u = -A +- sqrt(A^2 - B)` at `t`, if real.
    pub fn roots(&self, t: f64) -> Option<(f64, f64)> {
        let (s, c) = t.sin_cos();
        let (a, b) = self.ab(c, s);
        let d = a * a - b;
        (d >= 0.0).then(|| (-a - d.sqrt(), -a + d.sqrt()))
    }

    fn chunk(&self, lo: usize, hi: usize, dt: f64) -> GridSummary {
        chunk_with(lo, hi, dt, |t| self.discriminant(t))
    }

    /// Sweeps the grid `t_i = i 2 pi / n`, `i = 0..n`, on all cores.
    pub fn sweep(&self, n: usize) -> GridSummary {
        let dt = std::f64::consts::TAU / n as f64;
        let parts: Vec<GridSummary> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|k| self.chunk(k * CHUNK, ((k + 1) * CHUNK).min(n), dt))
            .collect();
        combine(&parts)
    }

    /// The same sweep on the calling thread only.
    pub fn sweep_serial(&self, n: usize) -> GridSummary {
        let dt = std::f64::consts::TAU / n as f64;
        let parts: Vec<GridSummary> = (0..n.div_ceil(CHUNK))
            .map(|k| self.chunk(k * CHUNK, ((k + 1) * CHUNK).min(n), dt))
            .collect();
        combine(&parts)
    }
}

/// Counts and sums over the samples `lo..hi` of the grid, for any discriminant function.
fn chunk_with(lo: usize, hi: usize, dt: f64, disc: impl Fn(f64) -> f64) -> GridSummary {
    let mut count = 0;
    let mut sum = 0.0;
    for i in lo..hi {
        let d = disc(i as f64 * dt);
        if d >= 0.0 {
            count += 1;
            sum += d.sqrt();
        }
    }
    GridSummary {
        count_nonneg: count,
        sum_sqrt: sum,
    }
}

fn combine(parts: &[GridSummary]) -> GridSummary {
    parts.iter().fold(
        GridSummary {
            count_nonneg: 0,
            sum_sqrt: 0.0,
        },
        |acc, p| GridSummary {
            count_nonneg: acc.count_nonneg + p.count_nonneg,
            sum_sqrt: acc.sum_sqrt + p.sum_sqrt,
        },
    )
}

/// The baseline: a plain per-sample evaluation of the derived formulas
/// ([`CylinderSphere::coefficients_at`]) with `sin_cos`, one thread, no precomputed coefficients.
pub fn sweep_direct(cs: &CylinderSphere<f64>, n: usize) -> GridSummary {
    let dt = std::f64::consts::TAU / n as f64;
    let disc = |t: f64| {
        let (s, c) = t.sin_cos();
        let (a, b) = cs.coefficients_at(&c, &s);
        a * a - b
    };
    let parts: Vec<GridSummary> = (0..n.div_ceil(CHUNK))
        .map(|k| chunk_with(k * CHUNK, ((k + 1) * CHUNK).min(n), dt, disc))
        .collect();
    combine(&parts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::cylinder_sphere::Angle;
    use exactcheck_core::Vec3;

    /// The W3 configuration (`w2::problem` of the CLI, in f64).
    pub(super) fn w3() -> CylinderSphere<f64> {
        CylinderSphere {
            a: 1.0 / 3.0,
            b: -2.0 / 7.0,
            r: 5.0,
            beta: Angle {
                cos: 3.0 / 5.0,
                sin: 4.0 / 5.0,
            },
            gamma: Angle {
                cos: 5.0 / 13.0,
                sin: -12.0 / 13.0,
            },
            center: Vec3::new(1.0, 2.0, 4.0),
            radius: 5.0,
        }
    }

    #[test]
    fn coefficients_reproduce_the_direct_formula() {
        let cs = w3();
        let s = DiscSampler::new(&cs);
        for k in 0..100 {
            let t = k as f64 * 0.0628;
            let (sn, c) = t.sin_cos();
            let (a1, b1) = cs.coefficients_at(&c, &sn);
            let (a2, b2) = s.ab(c, sn);
            assert!((a1 - a2).abs() <= 1e-12 * (1.0 + a1.abs()));
            assert!((b1 - b2).abs() <= 1e-12 * (1.0 + b1.abs()));
        }
    }

    #[test]
    fn parallel_and_serial_sweeps_agree_exactly() {
        let s = DiscSampler::new(&w3());
        let n = 3 * CHUNK + 17;
        assert_eq!(s.sweep(n), s.sweep_serial(n));
        let direct = sweep_direct(&w3(), n);
        assert_eq!(direct.count_nonneg, s.sweep(n).count_nonneg);
    }
}
