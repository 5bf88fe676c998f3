//! The `sample-sphere` kernel without a libm call per sample: angle addition per block, lanes that vectorize.
//!
//! # The kernel
//!
//! The grid is `t_i = fl(i dt)`, `dt = fl(2 pi / n)`, `i = 0..n` (exactly the grid of
//! [`Sweep::sweep`](super::Sweep::sweep), the reference). It is cut into the same fixed chunks of [`CHUNK`]
//! samples (the unit of the deterministic reduction and of the rayon work split), and each chunk
//! into blocks of [`BLOCK`] samples starting at multiples of `BLOCK`. Once per sweep an
//! [`AngleTable`] holds `(cos theta_j, sin theta_j)`, `theta_j = fl(j dt)`, for `j < BLOCK` (libm,
//! `BLOCK` calls). Per block starting at sample `i0`, one libm `sin_cos` of the block's start
//! angle `theta_a = fl(i0 dt)` gives `(C, S)`, and every sample `i = i0 + j` of the block is
//!
//! ```text
//!     cos t_i ~ C cos theta_j - S sin theta_j,        sin t_i ~ S cos theta_j + C sin theta_j
//! ```
//!
//! (angle addition, two products and one sum each). There is no recurrence: every sample is one
//! addition away from a libm value, so the error does not grow along the block, and the block
//! length only trades the cost of one `sin_cos` per block against the table's size in L1
//! (`BLOCK = 512`: 8 KiB of table, one `sin_cos` per 512 samples). A block then takes three
//! simple loops over a buffer of `BLOCK` doubles in L1, each of which the compiler vectorizes
//! (packed `mulpd`/`addpd`/`subpd`, `cmplepd`, `sqrtpd`: two samples per instruction with the
//! baseline SSE2, four with the AVX2 path) without any reassociation:
//!
//! 1. `disc_j = A^2 - B` at the angle-added `(cos, sin)`, by the very same operations as the
//!    reference ([`DiscSampler::disc_cs`]; [`AngleTable::discs`]);
//! 2. the count of `disc_j >= 0` (an integer sum, exact in any order);
//! 3. if the count is not zero: `sqrt(disc_j)` (of `0` for a negative `disc_j`: a select, not a
//!    branch), added to lane `j mod LANES` of [`LANES`] independent sums. A block without a
//!    nonnegative sample would add only `+0` to every lane, which changes no bit, so it is
//!    skipped: the sign of `A^2 - B` changes a few times per period, so most blocks are either
//!    skipped or entirely counted.
//!
//! A chunk's lane sums are added pairwise in a fixed order, and chunks in chunk order, so the
//! result is the same bit for bit on every path and for every number of threads (tested, also
//! against the reduction written out sample by sample).
//!
//! The AVX2 path ([`KernelPath::Avx2`], chosen at run time with `is_x86_feature_detected!`) is the
//! same generic code compiled under `#[target_feature(enable = "avx2")]`; it does not use FMA
//! (Rust never contracts `a * b + c` on its own), which is why both paths give identical bits
//! (tested). The code is hand-written because the speed comes from the data layout (one table
//! per sweep, blocks in L1, lanes): no crate offers this reduction with a stated error bound.
//!
//! # The error bound, derived
//!
//! Let `u = 2^-53` (the unit roundoff), and assume libm's `sin` and `cos` are within one ulp
//! (glibc's documented bound on x86_64; the tests check the resulting bound on every sample).
//! Compare the kernel's `c_i` with the reference `cos_libm(t_i)` (the same for `sin`):
//!
//! 1. *Angle.* `theta_a + theta_j` differs from `t_i = fl(i dt)` only by rounding of the three
//!    products `i0 dt`, `j dt`, `i dt` (`i0 dt + j dt = i dt` exactly in the reals), so by at most
//!    `u (i0 dt + j dt + i dt) = 2 u i dt < 4 pi u (1 + u) < 12.57 u`; `cos` and `sin` are
//!    1-Lipschitz, so this moves the value by less than `12.57 u`.
//! 2. *Inputs.* `C`, `S`, `cos theta_j`, `sin theta_j` each carry a libm error of at most one ulp
//!    of a number of magnitude below 1, i.e. `u` (`cos 0 = 1` is exact). In
//!    `C c' - S s'` these enter as `C e_c' - S e_s'` and `c' e_C - s' e_S`, each at most
//!    `(|C| + |S|) u <= sqrt 2 u`: `2 sqrt 2 u` in all, plus `O(u^2)`.
//! 3. *Rounding.* The two products and the difference round once each: at most
//!    `u (|C c'| + |S s'|) + u |C c' - S s'| <= 2 u` (Cauchy–Schwarz: `|C c'| + |S s'| <= 1`).
//! 4. *The reference* itself is within one ulp, `u`, of the true `cos t_i`.
//!
//! In all: **`|c_i - cos_libm(t_i)| <= (12.57 + 2.83 + 2 + 1) u + O(u^2) < 19 u`** ([`TRIG_ERROR`],
//! `19 * 2^-53 ~ 2.1e-15`), the same for `sin`. This is an absolute bound: 19 ulps of a value in
//! `[1/2, 1)`, 9.5 ulps of 1. A bound in ulps of the value itself cannot exist near a zero of
//! `cos`: there the reference's own value is dominated by the rounding of `t_i` (item 1), which
//! no evaluation of the rounded grid can undo. Measured on the test grids (every sample of 23
//! grids up to `10^6`, and blocks at random starts of the `10^7` grid) the largest difference
//! is `8 u`.
//!
//! *The discriminant.* Write `E = 19 u`, and for the coefficients `a`, `b` of `A`, `B`:
//! `alpha = |a1| + |a2|`, `beta = |b1| + |b2| + 2 (|b3| + |b4| + |b5|)`,
//! `M_A = |a0| + alpha (1 + E)` (a bound of `|A|` and of its terms on the perturbed circle) and
//! `M_B = (|b0| + ... + |b5|) (1 + E)^2`. Moving `(c, s)` by at most `E` in each coordinate moves
//! the exact `A` by `alpha E`, `B` by `beta E (1 + E)` (`c~^2 - c^2 = (c~ - c)(c~ + c)`, and so
//! on) and `A^2 - B` by at most `2 alpha M_A E + beta E (1 + E)`. The evaluation itself (same
//! operations in kernel and reference: `A` three roundings deep, `B` five, then `A * A - B`)
//! is within `R = 8 u M_A^2 + 6 u M_B` of the exact value (`gamma_3` on `A` doubled by the square,
//! one rounding for the square, `gamma_5` on `B`, one for the difference), once for the kernel and
//! once for the reference. So
//!
//! ```text
//!     |disc_kernel - disc_reference| <= D = 2 alpha M_A E + beta E (1 + E) + 2 R
//! ```
//!
//! (times `1.001` for the `O(u^2)` terms; [`AdditionSweep::addition_disc_error`]). As
//! `2 alpha M_A <= 2 M_A^2` and `beta <= 2 M_B`, this is at most
//! `(38 + 16) u M_A^2 + (38 + 12) u M_B`: **`A^2 - B` is within 55 ulps (`u`) of the
//! discriminant's scale `M_A^2 + M_B`** for every configuration (the relative bound of
//! [`AdditionSweep::addition_disc_error_scaled`]). For the workload's configuration (where `A` happens to
//! be constant, `alpha ~ 4e-16`) `D ~ 4.6e-13`, 40 u of its scale `M_A^2 + M_B ~ 105`.
//! Consequently the count differs from the reference's only through samples whose reference
//! `|disc| <= D` (none on the workload's grid of `N = 10^7`, asserted by its test), and every counted
//! sample's `sqrt` differs by at most `D / sqrt(disc_reference)` (or `sqrt D` when
//! `|disc_reference| <= D`).
//!
//! *The sum.* Each lane adds at most `CHUNK / LANES` terms, the lanes are added pairwise
//! (`log2 LANES` levels) and the chunks in order, so the summation is
//! `K = CHUNK / LANES + log2 LANES + ceil(n / CHUNK)` additions deep and its error is at most
//! `gamma_K` times the sum (plus `u` per `sqrt`, correctly rounded, in kernel and reference): at
//! `N = 10^7`, `K = 2662`, `gamma_K ~ 3.0e-13`. The sum `S` is thus within
//! `(gamma_K + 2 u) S + sum_i (D / sqrt disc_i, or sqrt D)` of the exact sum of the reference's
//! square roots ([`sum_error_bound`]; `3.35e-13 S` for the workload at `N = 10^7`), inside the `1e-12`
//! relative agreement with numpy that the check value asks (numpy sums pairwise, its own error
//! is smaller).

use super::{combine, GridSummary, CHUNK};
use exactcheck_float::sampler::DiscSampler;
use rayon::prelude::*;

/// Samples per block: one libm `sin_cos` per block, and the length of the [`AngleTable`].
pub const BLOCK: usize = 512;

/// Independent accumulators (sum and count) per chunk.
pub const LANES: usize = 8;

const _: () = assert!(CHUNK % BLOCK == 0 && BLOCK % LANES == 0 && LANES.is_power_of_two());

/// The unit roundoff `u = 2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// The absolute bound `19 u` on the difference between the kernel's `cos t_i`, `sin t_i` and the
/// reference's `f64::sin_cos(t_i)`, for every sample of every grid (derived in the module doc).
pub const TRIG_ERROR: f64 = 19.0 * U;

/// `(cos theta_j, sin theta_j)`, `theta_j = fl(j dt)`, for `j < min(BLOCK, n)`: computed once per
/// sweep of `n` samples.
#[derive(Clone, Debug, PartialEq)]
pub struct AngleTable {
    dt: f64,
    cos: Vec<f64>,
    sin: Vec<f64>,
}

impl AngleTable {
    /// The table of the grid `t_i = fl(i dt)`, `dt = fl(2 pi / n)` (`n >= 1`).
    ///
    /// # Panics
    /// If `n` is 0 (a grid needs a sample; the CLI checks `--n` before).
    pub fn new(n: usize) -> Self {
        assert!(n > 0, "a grid of 0 samples has no step");
        let dt = std::f64::consts::TAU / n as f64;
        let len = BLOCK.min(n);
        let (sin, cos) = (0..len).map(|j| (j as f64 * dt).sin_cos()).unzip();
        AngleTable { dt, cos, sin }
    }

    /// The grid step `dt`.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Writes `cos t_i`, `sin t_i` for the samples `i = i0 .. i0 + c.len()` by angle addition from
    /// `t_{i0}` (one `sin_cos`), each within [`TRIG_ERROR`] of `f64::sin_cos(t_i)`.
    ///
    /// # Panics
    /// If `c` and `s` differ in length or are longer than the table.
    pub fn rotate(&self, i0: usize, c: &mut [f64], s: &mut [f64]) {
        assert!(c.len() == s.len() && c.len() <= self.cos.len());
        let (sa, ca) = (i0 as f64 * self.dt).sin_cos();
        for (((co, so), &cj), &sj) in c.iter_mut().zip(s.iter_mut()).zip(&self.cos).zip(&self.sin) {
            (*co, *so) = add_angles(ca, sa, cj, sj);
        }
    }

    /// Writes the discriminant `A^2 - B` of `sampler` at the samples `i = i0 .. i0 + d.len()`,
    /// from the angle-addition `cos t_i`, `sin t_i` of [`AngleTable::rotate`] (the kernel's first
    /// pass; within [`AdditionSweep::addition_disc_error`] of [`DiscSampler::discriminant`]).
    ///
    /// # Panics
    /// If `d` is longer than the table.
    #[inline(always)]
    pub fn discs(&self, sampler: &DiscSampler, i0: usize, d: &mut [f64]) {
        assert!(d.len() <= self.cos.len());
        let (sa, ca) = (i0 as f64 * self.dt).sin_cos();
        for ((o, &cj), &sj) in d.iter_mut().zip(&self.cos).zip(&self.sin) {
            let (c, s) = add_angles(ca, sa, cj, sj);
            *o = sampler.disc_cs(c, s);
        }
    }
}

/// `(cos(a + b), sin(a + b))` from `cos a`, `sin a`, `cos b`, `sin b`.
#[inline(always)]
fn add_angles(ca: f64, sa: f64, cb: f64, sb: f64) -> (f64, f64) {
    (ca * cb - sa * sb, sa * cb + ca * sb)
}

/// The per-lane sums and the count of one chunk.
#[derive(Clone, Copy, Debug)]
struct Lanes {
    sum: [f64; LANES],
    count: usize,
}

impl Lanes {
    const ZERO: Lanes = Lanes {
        sum: [0.0; LANES],
        count: 0,
    };

    /// Adds the discriminants `d[j]`: the number of nonnegative ones to the count, and
    /// `sqrt(d[j])` (`0` if negative) to lane `j mod LANES` (`d` is overwritten by the roots).
    /// A block without a nonnegative `d[j]` adds only zeros: it is skipped, which changes no bit
    /// (the lane sums start at `+0` and `x + (+0) = x` for every `x` but `-0`, which a sum of
    /// `+0` and roots `>= +0` or `-0` never is).
    #[inline(always)]
    fn add(&mut self, d: &mut [f64]) {
        let count = d.iter().filter(|&&x| x >= 0.0).count();
        if count == 0 {
            return;
        }
        self.count += count;
        for x in d.iter_mut() {
            *x = (if *x >= 0.0 { *x } else { 0.0 }).sqrt();
        }
        let mut acc = self.sum;
        let mut blocks = d.chunks_exact(LANES);
        for b in &mut blocks {
            let b: &[f64; LANES] = b.try_into().expect("chunks of LANES");
            acc = std::array::from_fn(|k| acc[k] + b[k]);
        }
        for (a, &x) in acc.iter_mut().zip(blocks.remainder()) {
            *a += x;
        }
        self.sum = acc;
    }

    /// The lanes added pairwise in a fixed order.
    fn finish(self) -> GridSummary {
        let mut s = self.sum;
        let mut width = LANES;
        while width > 1 {
            width /= 2;
            for k in 0..width {
                s[k] += s[k + width];
            }
        }
        GridSummary {
            count_nonneg: self.count,
            sum_sqrt: s[0],
        }
    }
}

/// Which compiled form of the kernel runs (the results are identical bit for bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KernelPath {
    /// The portable build (SSE2 on x86_64: two samples per instruction).
    Portable,
    /// The same code compiled for AVX2 (four samples per instruction), x86_64 only.
    Avx2,
}

impl KernelPath {
    /// The fastest path this CPU runs.
    pub fn detect() -> Self {
        if KernelPath::Avx2.is_available() {
            KernelPath::Avx2
        } else {
            KernelPath::Portable
        }
    }

    /// Whether this CPU runs the path.
    pub fn is_available(self) -> bool {
        match self {
            KernelPath::Portable => true,
            #[cfg(target_arch = "x86_64")]
            KernelPath::Avx2 => is_x86_feature_detected!("avx2"),
            #[cfg(not(target_arch = "x86_64"))]
            KernelPath::Avx2 => false,
        }
    }

    fn chunk(self, s: &DiscSampler, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
        match self {
            KernelPath::Portable => chunk_generic(s, table, lo, hi),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: a `KernelPath::Avx2` reaches here only after `is_available` confirmed
            // AVX2 on this CPU (`sweep_addition_with` checks it; `detect` picks it only then).
            KernelPath::Avx2 => unsafe { chunk_avx2(s, table, lo, hi) },
            #[cfg(not(target_arch = "x86_64"))]
            KernelPath::Avx2 => unreachable!("AVX2 is never available off x86_64"),
        }
    }
}

/// The chunk kernel compiled with AVX2 enabled.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn chunk_avx2(s: &DiscSampler, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
    chunk_generic(s, table, lo, hi)
}

/// Samples `lo..hi` (`lo` a multiple of `BLOCK`): per block the discriminants by angle
/// addition into a buffer in L1, then the count and the lanes.
#[inline(always)]
fn chunk_generic(s: &DiscSampler, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
    let mut d = [0.0; BLOCK];
    let mut lanes = Lanes::ZERO;
    let mut i0 = lo;
    while i0 < hi {
        let len = BLOCK.min(hi - i0);
        let d = &mut d[..len];
        table.discs(s, i0, d);
        lanes.add(d);
        i0 += len;
    }
    lanes.finish()
}

/// The angle-addition sweeps of a sampler and their error bound.
pub trait AdditionSweep {
    /// Sweeps the grid `t_i = i 2 pi / n` with the angle-addition kernel, on all cores, on the
    /// fastest [`KernelPath`]. Within the bounds of the module doc of the reference
    /// [`super::Sweep::sweep`]; independent of the number of threads. An empty grid (`n = 0`)
    /// gives the empty summary, as the reference does.
    fn sweep_addition(&self, n: usize) -> GridSummary;

    /// [`AdditionSweep::sweep_addition`] on the calling thread only (the same result).
    fn sweep_addition_serial(&self, n: usize) -> GridSummary;

    /// The angle-addition sweep on a given path, on all cores (`parallel`) or on this thread;
    /// `None` if this CPU does not run `path`.
    fn sweep_addition_with(
        &self,
        n: usize,
        path: KernelPath,
        parallel: bool,
    ) -> Option<GridSummary>;

    /// The bound `D` on `|disc_kernel - disc_reference|` at every sample (module doc): the
    /// angle-addition kernel's `A^2 - B` against [`DiscSampler::discriminant`] at the same `t_i`.
    fn addition_disc_error(&self) -> f64;

    /// [`AdditionSweep::addition_disc_error`] in units of `u (M_A^2 + M_B)`, `u = 2^-53`: the
    /// number of ulps of the discriminant's scale (its largest possible terms) it amounts to.
    fn addition_disc_error_scaled(&self) -> f64;
}

impl AdditionSweep for DiscSampler {
    fn sweep_addition(&self, n: usize) -> GridSummary {
        self.sweep_addition_with(n, KernelPath::detect(), true)
            .expect("the detected path is available")
    }

    fn sweep_addition_serial(&self, n: usize) -> GridSummary {
        self.sweep_addition_with(n, KernelPath::detect(), false)
            .expect("the detected path is available")
    }

    fn sweep_addition_with(
        &self,
        n: usize,
        path: KernelPath,
        parallel: bool,
    ) -> Option<GridSummary> {
        if !path.is_available() {
            return None;
        }
        if n == 0 {
            return Some(combine(&[]));
        }
        let table = AngleTable::new(n);
        let chunk = |k: usize| path.chunk(self, &table, k * CHUNK, ((k + 1) * CHUNK).min(n));
        let chunks = n.div_ceil(CHUNK);
        let parts: Vec<GridSummary> = if parallel {
            (0..chunks).into_par_iter().map(chunk).collect()
        } else {
            (0..chunks).map(chunk).collect()
        };
        Some(combine(&parts))
    }

    fn addition_disc_error(&self) -> f64 {
        let (alpha, beta, ma, mb) = magnitudes(self);
        let e = TRIG_ERROR;
        let r = 8.0 * U * ma * ma + 6.0 * U * mb;
        (2.0 * alpha * ma * e + beta * e * (1.0 + e) + 2.0 * r) * 1.001
    }

    fn addition_disc_error_scaled(&self) -> f64 {
        let (_, _, ma, mb) = magnitudes(self);
        self.addition_disc_error() / (U * (ma * ma + mb))
    }
}

/// The magnitudes of the module doc's error bound: `(alpha, beta, M_A, M_B)`.
fn magnitudes(s: &DiscSampler) -> (f64, f64, f64, f64) {
    let e = 1.0 + TRIG_ERROR;
    let (a, b) = s.coefficients();
    let [a0, a1, a2] = a.map(f64::abs);
    let [b0, b1, b2, b3, b4, b5] = b.map(f64::abs);
    let alpha = a1 + a2;
    let beta = b1 + b2 + 2.0 * (b3 + b4 + b5);
    let ma = a0 + alpha * e;
    let mb = (b0 + b1 + b2 + b3 + b4 + b5) * e * e;
    (alpha, beta, ma, mb)
}

/// The summation depth `K` of a sweep of `n` samples (lane, pairwise lane sum, chunks in order).
pub fn sum_depth(n: usize) -> usize {
    CHUNK / LANES + LANES.trailing_zeros() as usize + n.div_ceil(CHUNK)
}

/// The bound of the module doc on `|kernel sum - exact sum of sqrt(reference disc)|` for a sweep
/// of `n` samples whose kernel sum is `sum`, given the reference discriminants and the
/// per-sample bound `d` ([`AdditionSweep::addition_disc_error`]):
/// `(gamma_K + 2 u) sum + sum_i (d / sqrt(disc_i) if disc_i > d, sqrt(d) if |disc_i| <= d)`
/// (`2 u`: the kernel's and the reference's correctly rounded `sqrt`).
pub fn sum_error_bound(n: usize, sum: f64, reference_discs: &[f64], d: f64) -> f64 {
    let k = sum_depth(n) as f64;
    let gamma = k * U / (1.0 - k * U);
    let per_sample: f64 = reference_discs
        .iter()
        .map(|&x| {
            if x > d {
                d / x.sqrt()
            } else if x >= -d {
                d.sqrt()
            } else {
                0.0
            }
        })
        .sum();
    ((gamma + 2.0 * U) * sum.abs() + per_sample) * 1.001
}

#[cfg(test)]
mod tests {
    use super::super::tests::w3;
    use super::super::Sweep;
    use super::*;
    use exactcheck_core::cylinder_sphere::{Angle, CylinderSphere};
    use exactcheck_core::rng::splitmix64;
    use exactcheck_core::Vec3;
    use exactcheck_float::convert::fsum;
    use std::f64::consts::TAU;

    /// Grid sizes: tiny, odd, around the lane, block and chunk boundaries, up to 10^6.
    const GRIDS: &[usize] = &[
        1,
        2,
        3,
        5,
        7,
        8,
        9,
        17,
        100,
        BLOCK - 1,
        BLOCK,
        BLOCK + 1,
        BLOCK + LANES - 1,
        1000,
        2 * BLOCK + 3,
        4099,
        CHUNK - 1,
        CHUNK,
        CHUNK + 1,
        2 * CHUNK + BLOCK + 5,
        99_991,
        262_147,
        1_000_003,
    ];

    #[test]
    fn an_empty_grid_is_the_empty_summary_as_in_the_reference() {
        let s = DiscSampler::new(&w3());
        assert_eq!(s.sweep_addition(0), s.sweep(0));
        assert_eq!(s.sweep_addition_serial(0), s.sweep(0));
        assert_eq!(s.sweep(0).count_nonneg, 0);
    }

    /// The reference `(cos t_i, sin t_i)`: libm at `t_i = fl(i dt)`.
    fn reference_cs(dt: f64, i: usize) -> (f64, f64) {
        let (s, c) = (i as f64 * dt).sin_cos();
        (c, s)
    }

    /// Calls `f(i, c, s)` with the kernel's cos and sin of every sample, block by block as the
    /// sweep computes them.
    fn for_each_kernel_sample(n: usize, mut f: impl FnMut(usize, f64, f64)) {
        let table = AngleTable::new(n);
        let (mut c, mut s) = ([0.0; BLOCK], [0.0; BLOCK]);
        for i0 in (0..n).step_by(BLOCK) {
            let len = BLOCK.min(n - i0);
            table.rotate(i0, &mut c[..len], &mut s[..len]);
            for j in 0..len {
                f(i0 + j, c[j], s[j]);
            }
        }
    }

    /// Random configurations (axis point, radii, angles from Pythagorean triples, centre) from
    /// seeded SplitMix64, with the workload's first.
    fn configurations() -> Vec<CylinderSphere<f64>> {
        let mut state = 14;
        let mut uniform = |lo: f64, hi: f64| {
            lo + (hi - lo) * (splitmix64(&mut state) >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut out = vec![w3()];
        for k in 0..4 {
            let angle = |t: f64| Angle {
                cos: (1.0 - t * t) / (1.0 + t * t),
                sin: 2.0 * t / (1.0 + t * t),
            };
            let scale = [1.0, 10.0, 0.01, 1000.0][k];
            out.push(CylinderSphere {
                a: uniform(-1.0, 1.0) * scale,
                b: uniform(-1.0, 1.0) * scale,
                r: uniform(0.5, 3.0) * scale,
                beta: angle(uniform(-2.0, 2.0)),
                gamma: angle(uniform(-2.0, 2.0)),
                center: Vec3::new(
                    uniform(-2.0, 2.0) * scale,
                    uniform(-2.0, 2.0) * scale,
                    uniform(-2.0, 2.0) * scale,
                ),
                radius: uniform(1.0, 4.0) * scale,
            });
        }
        out
    }

    #[test]
    fn every_samples_cos_and_sin_are_within_the_stated_bound() {
        let mut worst: f64 = 0.0;
        for &n in GRIDS {
            let dt = TAU / n as f64;
            let mut seen = 0;
            for_each_kernel_sample(n, |i, c, s| {
                let (rc, rs) = reference_cs(dt, i);
                let err = (c - rc).abs().max((s - rs).abs());
                assert!(err <= TRIG_ERROR, "n = {n}, i = {i}: {err:e}");
                worst = worst.max(err);
                seen += 1;
            });
            assert_eq!(seen, n);
        }
        // The measured worst case, in units of u (printed with --nocapture).
        println!("largest |cos|, |sin| difference: {} u", worst / U);
    }

    #[test]
    fn blocks_may_start_anywhere_within_the_bound() {
        // The bound does not use i0 mod BLOCK: starts at odd places of a 10^7 grid, the
        // largest angles of the grid included.
        let n = 10_000_000;
        let table = AngleTable::new(n);
        let (mut c, mut s) = ([0.0; BLOCK], [0.0; BLOCK]);
        let mut state = 3;
        let mut starts: Vec<usize> = (0..200)
            .map(|_| (splitmix64(&mut state) % (n - BLOCK) as u64) as usize)
            .collect();
        starts.push(n - BLOCK);
        for i0 in starts {
            table.rotate(i0, &mut c, &mut s);
            for j in 0..BLOCK {
                let (rc, rs) = reference_cs(table.dt(), i0 + j);
                assert!((c[j] - rc).abs() <= TRIG_ERROR, "i = {}", i0 + j);
                assert!((s[j] - rs).abs() <= TRIG_ERROR, "i = {}", i0 + j);
            }
        }
    }

    #[test]
    fn every_samples_discriminant_is_within_the_stated_bound() {
        for cs in configurations() {
            let sampler = DiscSampler::new(&cs);
            let d = sampler.addition_disc_error();
            assert!(d > 0.0 && sampler.addition_disc_error_scaled() < 55.0);
            for &n in GRIDS {
                let table = AngleTable::new(n);
                let (mut buf, mut c, mut sn) = ([0.0; BLOCK], [0.0; BLOCK], [0.0; BLOCK]);
                for i0 in (0..n).step_by(BLOCK) {
                    let len = BLOCK.min(n - i0);
                    table.discs(&sampler, i0, &mut buf[..len]);
                    table.rotate(i0, &mut c[..len], &mut sn[..len]);
                    for (j, &kernel) in buf[..len].iter().enumerate() {
                        let i = i0 + j;
                        let reference = sampler.discriminant(i as f64 * table.dt());
                        assert!((kernel - reference).abs() <= d, "n = {n}, i = {i}");
                        // The kernel's discriminant is the formula at the cos and sin that
                        // `rotate` gives (and the first test bounds), bit for bit.
                        assert_eq!(kernel.to_bits(), sampler.disc_cs(c[j], sn[j]).to_bits());
                    }
                }
            }
        }
    }

    #[test]
    fn the_workloads_discriminant_bound_is_as_stated() {
        let s = DiscSampler::new(&w3());
        let d = s.addition_disc_error();
        assert!(d > 4e-13 && d < 5e-13, "{d:e}");
        let scaled = s.addition_disc_error_scaled();
        assert!(scaled > 39.0 && scaled < 41.0, "{scaled}");
    }

    #[test]
    fn count_and_sum_agree_with_the_reference_within_the_stated_bounds() {
        for (k, cs) in configurations().into_iter().enumerate() {
            let sampler = DiscSampler::new(&cs);
            let d = sampler.addition_disc_error();
            for &n in GRIDS {
                if k > 0 && n > 300_000 {
                    continue;
                }
                let dt = TAU / n as f64;
                let discs: Vec<f64> = (0..n)
                    .map(|i| sampler.discriminant(i as f64 * dt))
                    .collect();
                let sure = discs.iter().filter(|&&x| x > d).count();
                let near_zero = discs.iter().filter(|&&x| x.abs() <= d).count();
                let roots: Vec<f64> = discs
                    .iter()
                    .filter(|&&x| x >= 0.0)
                    .map(|x| x.sqrt())
                    .collect();
                let got = sampler.sweep_addition(n);
                assert!(
                    sure <= got.count_nonneg && got.count_nonneg <= sure + near_zero,
                    "config {k}, n = {n}: {} not in {sure}..={}",
                    got.count_nonneg,
                    sure + near_zero
                );
                if near_zero == 0 {
                    assert_eq!(got.count_nonneg, roots.len(), "config {k}, n = {n}");
                }
                let exact = fsum(&roots);
                let bound = sum_error_bound(n, got.sum_sqrt, &discs, d);
                assert!(
                    (got.sum_sqrt - exact).abs() <= bound,
                    "config {k}, n = {n}: {} vs {exact}, bound {bound:e}",
                    got.sum_sqrt
                );
            }
        }
    }

    #[test]
    fn paths_and_thread_counts_give_identical_bits() {
        let paths = [KernelPath::Portable, KernelPath::Avx2];
        for cs in configurations() {
            let s = DiscSampler::new(&cs);
            for &n in GRIDS.iter().filter(|&&n| n <= 300_000) {
                let serial = s.sweep_addition_serial(n);
                assert_eq!(serial, s.sweep_addition(n), "n = {n}");
                for path in paths.into_iter().filter(|p| p.is_available()) {
                    for parallel in [false, true] {
                        assert_eq!(s.sweep_addition_with(n, path, parallel), Some(serial));
                    }
                }
            }
        }
        assert!(KernelPath::Portable.is_available());
        assert!(KernelPath::detect().is_available());
        #[cfg(target_arch = "x86_64")]
        if !KernelPath::Avx2.is_available() {
            assert_eq!(
                workload_sampler().sweep_addition_with(10, KernelPath::Avx2, false),
                None
            );
        }
    }

    /// The kernel's reduction written out plainly, sample by sample: lane `j mod LANES` of
    /// block-relative index `j`, no block skipped, lanes added pairwise, chunks in order.
    fn plain_lanes(s: &DiscSampler, n: usize) -> GridSummary {
        let table = AngleTable::new(n);
        let mut total = GridSummary {
            count_nonneg: 0,
            sum_sqrt: 0.0,
        };
        for lo in (0..n).step_by(CHUNK) {
            let (mut sum, mut count) = ([0.0f64; LANES], 0);
            for i0 in (lo..(lo + CHUNK).min(n)).step_by(BLOCK) {
                let mut d = vec![0.0; BLOCK.min(n - i0)];
                table.discs(s, i0, &mut d);
                for (j, &x) in d.iter().enumerate() {
                    if x >= 0.0 {
                        count += 1;
                        sum[j % LANES] += x.sqrt();
                    } else {
                        sum[j % LANES] += 0.0;
                    }
                }
            }
            let l: Vec<f64> = (0..LANES / 2)
                .map(|k| sum[k] + sum[k + LANES / 2])
                .collect();
            let l: Vec<f64> = (0..LANES / 4).map(|k| l[k] + l[k + LANES / 4]).collect();
            total.count_nonneg += count;
            total.sum_sqrt += l[0] + l[1];
        }
        total
    }

    #[test]
    fn the_reduction_is_the_plain_lane_sum_bit_for_bit() {
        assert_eq!(LANES, 8, "plain_lanes spells out three levels");
        for cs in configurations() {
            let s = DiscSampler::new(&cs);
            for &n in GRIDS.iter().filter(|&&n| n <= 300_000) {
                let got = s.sweep_addition(n);
                let want = plain_lanes(&s, n);
                assert_eq!(got.count_nonneg, want.count_nonneg, "n = {n}");
                assert_eq!(got.sum_sqrt.to_bits(), want.sum_sqrt.to_bits(), "n = {n}");
            }
        }
    }

    fn workload_sampler() -> DiscSampler {
        DiscSampler::new(&w3())
    }

    #[test]
    fn the_summation_depth_is_lanes_blocks_and_chunks() {
        assert_eq!(sum_depth(10_000_000), CHUNK / LANES + 3 + 611);
        assert_eq!(sum_depth(1), CHUNK / LANES + 3 + 1);
    }

    /// The check values of `sample_sphere_numpy.py` at N = 10^7 on every path: count exactly, sum to 1e-12
    /// relative; and the reference sweep's sum (exact sum of its square roots) within the bound.
    #[test]
    #[cfg_attr(debug_assertions, ignore = "release-mode test: 10^7 samples per path")]
    fn check_values_at_ten_million() {
        let n = 10_000_000;
        let s = workload_sampler();
        let numpy = 13229714.773764007;
        for path in [KernelPath::Portable, KernelPath::Avx2] {
            let Some(got) = s.sweep_addition_with(n, path, true) else {
                continue;
            };
            assert_eq!(got.count_nonneg, 3_415_478, "{path:?}");
            assert!(
                (got.sum_sqrt - numpy).abs() <= 1e-12 * numpy,
                "{path:?}: {:?}",
                got.sum_sqrt
            );
        }
        let dt = TAU / n as f64;
        let discs: Vec<f64> = (0..n).map(|i| s.discriminant(i as f64 * dt)).collect();
        let roots: Vec<f64> = discs
            .iter()
            .filter(|&&x| x >= 0.0)
            .map(|x| x.sqrt())
            .collect();
        assert_eq!(roots.len(), 3_415_478);
        let got = s.sweep_addition(n);
        let d = s.addition_disc_error();
        assert_eq!(discs.iter().filter(|&&x| x.abs() <= d).count(), 0);
        let bound = sum_error_bound(n, got.sum_sqrt, &discs, d);
        println!("sum bound at 10^7: {:e} relative", bound / got.sum_sqrt);
        assert!(bound < 3.4e-13 * numpy, "{bound:e}");
        assert!((got.sum_sqrt - fsum(&roots)).abs() <= bound);
    }
}
