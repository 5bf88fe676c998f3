//! The workload `sample-sphere`: f64 sampling of the Spaeth cylinder/sphere discriminant
//! ([`exactcheck_float::sampler::DiscSampler`]) on the grid `t_i = i 2 pi / n`, counting the
//! real points and summing `sqrt(A^2 - B)` as a checksum.
//!
//! The grid is cut into fixed chunks of [`CHUNK`] samples whose partial results are combined in
//! chunk order, so the result does not depend on the number of threads. The sweeps:
//! * [`Sweep::sweep`] (and `sweep_serial`), the reference: `f64::sin_cos` per sample, one
//!   running sum per chunk;
//! * [`AdditionSweep::sweep_addition`] (and `sweep_addition_serial`), the fast kernel of
//!   [`addition`]: the discriminant as a trigonometric polynomial of degree 2, angle addition per
//!   block (one `sin_cos` per 512 samples), 4 multiplications and 4 additions per sample,
//!   discriminants and square roots in vectorized lanes (SSE2, AVX2 or AVX-512, detected at run
//!   time, identical bits), within the error bounds derived there of the reference;
//! * [`sweep_direct`], the baseline: the derived formulas evaluated per sample.
//!
//! The timed region of [`run`] covers what the anchor's (`sample_sphere_numpy.py`) does: from
//! the configuration to the check values (coefficients, the angle table, the sweep). Starting
//! rayon's worker threads is process set-up (as the Python interpreter's start is for numpy) and
//! happens before it.

use crate::rational_sum::problem;
use crate::{Elapsed, Stopwatch};
use clap::ValueEnum;
use exactcheck_core::cylinder_sphere::CylinderSphere;
use exactcheck_float::sampler::DiscSampler;
use rayon::prelude::*;

pub mod addition;

pub use addition::{
    sum_depth, sum_error_bound, AdditionSweep, AngleTable, KernelPath, Trig2, ANGLE_ERROR, BLOCK,
    LANES,
};

/// Samples per chunk (cache-sized; also the unit of the deterministic reduction).
pub const CHUNK: usize = 1 << 14;

/// What a sweep over a grid found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridSummary {
    /// Samples with `A^2 - B >= 0` (real points).
    pub count_nonneg: usize,
    /// `sum sqrt(A^2 - B)` over those samples (a checksum of the evaluated values).
    pub sum_sqrt: f64,
}

/// The reference sweeps of a sampler over the grid.
pub trait Sweep {
    /// Sweeps the grid `t_i = i 2 pi / n`, `i = 0..n`, on all cores.
    fn sweep(&self, n: usize) -> GridSummary;
    /// The same sweep on the calling thread only.
    fn sweep_serial(&self, n: usize) -> GridSummary;
}

impl Sweep for DiscSampler {
    fn sweep(&self, n: usize) -> GridSummary {
        let dt = std::f64::consts::TAU / n as f64;
        let parts: Vec<GridSummary> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|k| {
                chunk_with(k * CHUNK, ((k + 1) * CHUNK).min(n), dt, |t| {
                    self.discriminant(t)
                })
            })
            .collect();
        combine(&parts)
    }

    fn sweep_serial(&self, n: usize) -> GridSummary {
        let dt = std::f64::consts::TAU / n as f64;
        let parts: Vec<GridSummary> = (0..n.div_ceil(CHUNK))
            .map(|k| {
                chunk_with(k * CHUNK, ((k + 1) * CHUNK).min(n), dt, |t| {
                    self.discriminant(t)
                })
            })
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

/// How the samples are evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Variant {
    /// The discriminant as a degree-2 trigonometric polynomial, angle addition per block of 512
    /// samples (one `sin_cos` per block), summed in vectorized lanes, all cores (within 66 u of
    /// the discriminant's scale of the per-sample evaluation).
    Addition,
    /// The angle-addition kernel on one thread (the same result bit for bit).
    AdditionSerial,
    /// Precomputed trigonometric coefficients, all cores.
    Coef,
    /// Precomputed coefficients, one thread.
    CoefSerial,
    /// The derived formulas evaluated per sample with `sin_cos`, one thread (the baseline).
    Direct,
}

/// Runs the workload on `n` samples and formats the result like `sample_sphere_numpy.py` (one
/// JSON line) or as text.
pub fn run(n: usize, variant: Variant, json: bool) -> String {
    let cs = problem::<f64>();
    rayon::broadcast(|_| ());
    let watch = Stopwatch::start();
    let summary = match variant {
        Variant::Addition => DiscSampler::new(&cs).sweep_addition(n),
        Variant::AdditionSerial => DiscSampler::new(&cs).sweep_addition_serial(n),
        Variant::Coef => DiscSampler::new(&cs).sweep(n),
        Variant::CoefSerial => DiscSampler::new(&cs).sweep_serial(n),
        Variant::Direct => sweep_direct(&cs, n),
    };
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    let value = variant.to_possible_value().expect("no variant is skipped");
    let name = value.get_name();
    if json {
        format!(
            "{{\"tool\": \"exactcheck\", \"variant\": \"{name}\", \"N\": {n}, \"seconds\": {seconds}, \"cpu_seconds\": {cpu}, \"samples_per_s\": {}, \"count_nonneg\": {}, \"sum_sqrt\": \"{:?}\", \"threads\": {}}}",
            n as f64 / seconds,
            summary.count_nonneg,
            summary.sum_sqrt,
            match variant {
                Variant::Addition | Variant::Coef => rayon::current_num_threads(),
                _ => 1,
            }
        )
    } else {
        format!(
            "sample-sphere (f64 Spaeth discriminant), N = {n}, variant {name}\n  samples with disc >= 0: {}\n  sum of sqrt(disc): {:?}\n  time: {:.4} s ({:.1} M samples/s)",
            summary.count_nonneg,
            summary.sum_sqrt,
            seconds,
            n as f64 / seconds / 1e6
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The configuration of the workload, in f64.
    pub(super) fn workload_configuration() -> CylinderSphere<f64> {
        problem()
    }

    #[test]
    fn parallel_and_serial_sweeps_agree_exactly() {
        let s = DiscSampler::new(&workload_configuration());
        let n = 3 * CHUNK + 17;
        assert_eq!(s.sweep(n), s.sweep_serial(n));
        let direct = sweep_direct(&workload_configuration(), n);
        assert_eq!(direct.count_nonneg, s.sweep(n).count_nonneg);
    }
}
