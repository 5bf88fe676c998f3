//! The `sample-sphere` kernel without a libm call per sample: the discriminant as a trigonometric
//! polynomial, angle addition per block, lanes that vectorize.
//!
//! # The kernel
//!
//! With `A = a0 + a1 cos t + a2 sin t` and `B = b0 + b1 cos t + b2 sin t + b3 cos^2 t +
//! b4 cos t sin t + b5 sin^2 t` (the sampler's coefficients), `cos^2 = (1 + cos 2t) / 2`,
//! `sin^2 = (1 - cos 2t) / 2` and `cos sin = sin 2t / 2` turn the discriminant into a
//! trigonometric polynomial of degree 2 ([`Trig2`], computed once per sweep):
//!
//! ```text
//!     A^2 - B = d0 + d1 cos t + d2 sin t + d3 cos 2t + d4 sin 2t,
//!     d0 = a0^2 + (a1^2 + a2^2) / 2 - b0 - (b3 + b5) / 2,   d1 = 2 a0 a1 - b1,   d2 = 2 a0 a2 - b2,
//!     d3 = (a1^2 - a2^2) / 2 - (b3 - b5) / 2,               d4 = a1 a2 - b4 / 2.
//! ```
//!
//! The grid is `t_i = fl(i dt)`, `dt = fl(2 pi / n)`, `i = 0..n` (exactly the grid of
//! [`Sweep::sweep`](super::Sweep::sweep), the reference). It is cut into the same fixed chunks of
//! [`CHUNK`] samples (the unit of the deterministic reduction and of the rayon work split), and
//! each chunk into blocks of [`BLOCK`] samples starting at multiples of `BLOCK`. Once per sweep an
//! [`AngleTable`] holds `cos theta_j`, `sin theta_j`, `cos 2 theta_j`, `sin 2 theta_j`,
//! `theta_j = fl(j dt)`, for `j < BLOCK` (libm, `2 BLOCK` calls). Per block starting at sample
//! `i0`, libm's `sin_cos` of `theta_a = fl(i0 dt)` gives `(C1, S1)`, the double-angle formulas
//! `(C2, S2)` of `2 theta_a`, and angle addition folds them into the block's coefficients
//! ([`AngleTable::block`]):
//!
//! ```text
//!     C2 = C1 C1 - S1 S1,   S2 = 2 S1 C1,
//!     e1 = d1 C1 + d2 S1,   e2 = d2 C1 - d1 S1,   e3 = d3 C2 + d4 S2,   e4 = d4 C2 - d3 S2,
//! ```
//!
//! since `d1 cos(a + b) + d2 sin(a + b) = (d1 cos a + d2 sin a) cos b + (d2 cos a - d1 sin a) sin b`.
//! Every sample `i = i0 + j` of the block is then
//!
//! ```text
//!     disc_i = (((d0 + e1 cos theta_j) + e2 sin theta_j) + e3 cos 2 theta_j) + e4 sin 2 theta_j
//! ```
//!
//! **4 multiplications and 4 additions per sample** (the straightforward evaluation at angle-added
//! `cos t`, `sin t` takes 14 and 10: 4 and 2 for the angle addition, 10 and 8 for `A^2 - B`),
//! then one comparison, and a square root and an addition for the counted samples. There is no
//! recurrence: every sample is one angle addition away from libm values, so the error does not
//! grow along the block. A block takes two simple loops over a buffer of `BLOCK` doubles in L1,
//! which the compiler vectorizes (packed `mulpd`/`addpd`, `cmplepd`, `sqrtpd`: two samples per
//! instruction with the baseline SSE2, four with the AVX2 path, eight with the AVX-512 path)
//! without any reassociation:
//!
//! 1. `disc_j` into the buffer and the count of `disc_j >= 0` (an integer sum, exact in any
//!    order; [`AngleTable::discs`]);
//! 2. if the count is not zero: `sqrt(disc_j)` (of `0` for a negative `disc_j`: a select, not a
//!    branch), added to lane `j mod LANES` of [`LANES`] independent sums. A block without a
//!    nonnegative sample would add only `+0` to every lane, which changes no bit, so it is
//!    skipped: the sign of `A^2 - B` changes a few times per period, so most blocks are either
//!    skipped or entirely counted.
//!
//! The tables take `4 * 8 * BLOCK` bytes (16 KiB) and the buffer 4 KiB, inside L1.
//! A chunk's lane sums are added pairwise in a fixed order, and chunks in chunk order, so the
//! result is the same bit for bit on every path and for every number of threads (tested, also
//! against the reduction written out sample by sample).
//!
//! The AVX2 and AVX-512 paths ([`KernelPath::Avx2`], [`KernelPath::Avx512`], the widest one the
//! CPU runs chosen at run time with `is_x86_feature_detected!`) are the same generic code compiled
//! under `#[target_feature(enable = "avx2")]` and `#[target_feature(enable = "avx512f")]`; they do
//! not use FMA (Rust never contracts `a * b + c` on its own), which is why all paths give
//! identical bits (tested). With AVX-512 the eight lanes are one register and a square root
//! instruction takes eight samples: on a core whose square root unit is 512 bits wide (AMD Zen 5:
//! one `vsqrtpd` per about 7.5 cycles for 4 or 8 roots alike) that halves the cost of the counted
//! samples, which is most of the kernel's time. The AVX-512 target feature is stable since Rust
//! 1.89; with an older compiler the path is compiled out (`rustversion`) and reports itself
//! unavailable. The code is hand-written because the speed comes from the algebra and the data
//! layout (one table per sweep, blocks in L1, lanes): no crate offers this reduction with a
//! stated error bound.
//!
//! # The error bound, derived
//!
//! Let `u = 2^-53` (the unit roundoff), `gamma_k = k u / (1 - k u)`, and assume libm's `sin` and
//! `cos` are within one ulp (glibc's documented bound on x86_64; the tests check the resulting
//! bound on every sample), i.e. within `u` of the true value for arguments of magnitude below 1.
//! Let `P(t)` be the exact `A(t)^2 - B(t)` for the sampler's (f64) coefficients: the kernel and the
//! reference ([`DiscSampler::discriminant`], `A^2 - B` at libm's `cos t_i`, `sin t_i`) are both
//! compared with `P(t_i)`.
//!
//! *The kernel against `P`.* Let `T_k` be the sum of the absolute values of the terms of `d_k`'s
//! formula above (e.g. `T_1 = 2 |a0 a1| + |b1|`); `T_0 + ... + T_4 <= (|a0| + |a1| + |a2|)^2 +
//! |b0| + ... + |b5|`.
//! 1. *Coefficients.* Each `d_k` is computed with at most five roundings on any term (`a1^2`: a
//!    product and four sums; the halvings are exact): `|d~_k - d_k| <= delta_k = gamma_5 T_k`,
//!    which moves the polynomial by at most `delta_0 + ... + delta_4` (`|cos|, |sin| <= 1`).
//! 2. *Angle.* `theta_a + theta_j` differs from `t_i = fl(i dt)` only by the rounding of the three
//!    products `i0 dt`, `j dt`, `i dt` (`i0 dt + j dt = i dt` in the reals), so by at most
//!    `u (i0 dt + j dt + i dt) = 2 u i dt < 4 pi u (1 + u) < 12.57 u`, and the doubled angles by
//!    twice that (doubling is exact). With `r1 = |d~1| + |d~2|`, `r2 = |d~3| + |d~4|` the
//!    polynomial's derivative is at most `r1 + 2 r2`: this moves it by `12.57 u (r1 + 2 r2)`.
//! 3. *Block coefficients.* `C1`, `S1` are within `u` of `cos theta_a`, `sin theta_a`; then
//!    `C2 = C1 C1 - S1 S1` is within `2 (|c| + |s|) u + u (c^2 + s^2) + u |c^2 - s^2| <=
//!    (2 sqrt 2 + 2) u < 4.83 u` of `cos 2 theta_a` and `S2 = 2 S1 C1` within `(2 sqrt 2 + 1) u`
//!    of `sin 2 theta_a` (first order). `e1` rounds two products and a sum: `e1`, `e2` are
//!    within `eta_1 = r1 (u + gamma_2 (1 + u))` of their exact values, `e3`, `e4` within
//!    `eta_2 = r2 (4.83 u + gamma_2 (1 + 4.83 u))`, and the exact ones are at most `r1`, `r2`.
//! 4. *Table.* The table's cosines and sines are within `u` each: `2 (eta_1 + eta_2) (1 + u) +
//!    2 u (r1 + r2)` for items 3 and 4 together.
//! 5. *Evaluation.* Four products and four sums, each term at most five roundings deep:
//!    `gamma_5 (|d~0| + 2 (r1 + r2 + eta_1 + eta_2) (1 + u))`.
//!
//! *The reference against `P`* (libm's `cos t_i`, `sin t_i` within `u`, then `A` three
//! roundings deep, `B` five, `A * A - B`): with `alpha = |a1| + |a2|`,
//! `beta = |b1| + |b2| + 2 (|b3| + |b4| + |b5|)`, `M_A = |a0| + alpha (1 + u)` and
//! `M_B = (|b0| + ... + |b5|) (1 + u)^2`, at most `2 alpha M_A u + beta u (1 + u) + 8 u M_A^2 +
//! 6 u M_B`.
//!
//! The sum of the two, times `1.001` for the `O(u^2)` terms, is the bound `D` on
//! `|disc_kernel - disc_reference|` ([`AdditionSweep::addition_disc_error`]). With
//! `X = r1 + r2 <= S - T_0` and `S = M_A^2 + M_B` the kernel's part is at most
//! `5 u S + 12.57 u (X + r2) + 7.66 u r2 + 8 u X + 5 u (T_0 + 2 X) <= 55.8 u S` and the
//! reference's at most `10 u M_A^2 + 8 u M_B`: **`A^2 - B` is within 66 ulps (`u`) of the
//! discriminant's scale
//! `M_A^2 + M_B`** for every configuration (the relative bound of
//! [`AdditionSweep::addition_disc_error_scaled`]). For the workload's configuration (where `A`
//! happens to be constant) `D ~ 3.4e-13`, 29 u of its scale `M_A^2 + M_B ~ 105`.
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
//! square roots ([`sum_error_bound`]; `3.25e-13 S` for the workload at `N = 10^7`), inside
//! the `1e-12` relative agreement with numpy that the check value asks (numpy sums pairwise, its
//! own error is smaller).

use super::{combine, GridSummary, CHUNK};
use exactcheck_float::sampler::DiscSampler;
use rayon::prelude::*;

#[cfg(test)]
mod tests;

/// Samples per block: one libm `sin_cos` per block, and the length of the [`AngleTable`].
pub const BLOCK: usize = 512;

/// Independent accumulators (sum and count) per chunk.
pub const LANES: usize = 8;

const _: () = assert!(CHUNK % BLOCK == 0 && BLOCK % LANES == 0 && LANES.is_power_of_two());

/// The unit roundoff `u = 2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// `gamma_k = k u / (1 - k u)`.
fn gamma(k: f64) -> f64 {
    k * U / (1.0 - k * U)
}

/// The bound `4 pi u (1 + u) < 12.57 u` on `|theta_a + theta_j - t_i|` (module doc, item 2).
pub const ANGLE_ERROR: f64 = 12.57 * U;

/// The bound `(2 sqrt 2 + 2) u < 4.83 u` (first order) on the block's `C2`, `S2` from the double-angle
/// formulas against `cos 2 theta_a`, `sin 2 theta_a` (module doc, item 3).
const DOUBLE_ANGLE_ERROR: f64 = 4.83 * U;

/// The discriminant `A^2 - B` of a sampler as the trigonometric polynomial
/// `d0 + d1 cos t + d2 sin t + d3 cos 2t + d4 sin 2t` (module doc), with the coefficients rounded
/// to f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trig2 {
    /// `[d0, d1, d2, d3, d4]`.
    pub d: [f64; 5],
    /// `[T_0, ..., T_4]`: the sums of the absolute values of each formula's terms.
    terms: [f64; 5],
}

impl Trig2 {
    /// The polynomial of a sampler's `A^2 - B`.
    pub fn new(s: &DiscSampler) -> Self {
        let ([a0, a1, a2], [b0, b1, b2, b3, b4, b5]) = s.coefficients();
        let d = [
            a0 * a0 + 0.5 * (a1 * a1 + a2 * a2) - b0 - 0.5 * (b3 + b5),
            2.0 * a0 * a1 - b1,
            2.0 * a0 * a2 - b2,
            0.5 * (a1 * a1 - a2 * a2) - 0.5 * (b3 - b5),
            a1 * a2 - 0.5 * b4,
        ];
        let ([a0, a1, a2], [b0, b1, b2, b3, b4, b5]) = (
            s.coefficients().0.map(f64::abs),
            s.coefficients().1.map(f64::abs),
        );
        let terms = [
            a0 * a0 + 0.5 * (a1 * a1 + a2 * a2) + b0 + 0.5 * (b3 + b5),
            2.0 * a0 * a1 + b1,
            2.0 * a0 * a2 + b2,
            0.5 * (a1 * a1 + a2 * a2) + 0.5 * (b3 + b5),
            a1 * a2 + 0.5 * b4,
        ];
        Trig2 { d, terms }
    }

    /// The polynomial at the angle `t` with libm's `sin_cos` of `t` and `2 t` (a plain evaluation,
    /// the reference of the tests).
    pub fn at(&self, t: f64) -> f64 {
        let [d0, d1, d2, d3, d4] = self.d;
        let ((s, c), (s2, c2)) = (t.sin_cos(), (2.0 * t).sin_cos());
        d0 + d1 * c + d2 * s + d3 * c2 + d4 * s2
    }

    /// The bound of the module doc's items 1 to 5 on `|disc_kernel - P(t_i)|`.
    fn kernel_error(&self) -> f64 {
        let [d0, d1, d2, d3, d4] = self.d.map(f64::abs);
        let (r1, r2) = (d1 + d2, d3 + d4);
        let delta: f64 = self.terms.iter().map(|t| gamma(5.0) * t).sum();
        let eta1 = r1 * (U + gamma(2.0) * (1.0 + U));
        let eta2 = r2 * (DOUBLE_ANGLE_ERROR + gamma(2.0) * (1.0 + DOUBLE_ANGLE_ERROR));
        delta
            + ANGLE_ERROR * (r1 + 2.0 * r2)
            + 2.0 * (eta1 + eta2) * (1.0 + U)
            + 2.0 * U * (r1 + r2)
            + gamma(5.0) * (d0 + 2.0 * (r1 + r2 + eta1 + eta2) * (1.0 + U))
    }
}

/// `cos theta_j`, `sin theta_j`, `cos 2 theta_j`, `sin 2 theta_j`, `theta_j = fl(j dt)`, for
/// `j < min(BLOCK, n)`: computed once per sweep of `n` samples.
#[derive(Clone, Debug, PartialEq)]
pub struct AngleTable {
    dt: f64,
    cos: Vec<f64>,
    sin: Vec<f64>,
    cos2: Vec<f64>,
    sin2: Vec<f64>,
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
        let (mut cos, mut sin, mut cos2, mut sin2) = (
            Vec::with_capacity(len),
            Vec::with_capacity(len),
            Vec::with_capacity(len),
            Vec::with_capacity(len),
        );
        for j in 0..len {
            let theta = j as f64 * dt;
            let ((s, c), (s2, c2)) = (theta.sin_cos(), (2.0 * theta).sin_cos());
            cos.push(c);
            sin.push(s);
            cos2.push(c2);
            sin2.push(s2);
        }
        AngleTable {
            dt,
            cos,
            sin,
            cos2,
            sin2,
        }
    }

    /// The grid step `dt`.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The coefficients `[d0, e1, e2, e3, e4]` of the block starting at sample `i0`: the
    /// polynomial's `d1 .. d4` turned by the block's start angle `theta_a = fl(i0 dt)` (module doc).
    #[inline(always)]
    pub fn block(&self, p: &Trig2, i0: usize) -> [f64; 5] {
        let [d0, d1, d2, d3, d4] = p.d;
        let a = i0 as f64 * self.dt;
        let (s1, c1) = a.sin_cos();
        let (c2, s2) = (c1 * c1 - s1 * s1, 2.0 * s1 * c1);
        [
            d0,
            d1 * c1 + d2 * s1,
            d2 * c1 - d1 * s1,
            d3 * c2 + d4 * s2,
            d4 * c2 - d3 * s2,
        ]
    }

    /// Writes the discriminant at the samples `i = i0 .. i0 + d.len()` (the kernel's first pass,
    /// within [`AdditionSweep::addition_disc_error`] of [`DiscSampler::discriminant`]) and
    /// returns how many are `>= 0`.
    ///
    /// # Panics
    /// If `d` is longer than the table.
    #[inline(always)]
    pub fn discs(&self, p: &Trig2, i0: usize, d: &mut [f64]) -> usize {
        let len = d.len();
        assert!(len <= self.cos.len());
        let [d0, e1, e2, e3, e4] = self.block(p, i0);
        let (c, s) = (&self.cos[..len], &self.sin[..len]);
        let (c2, s2) = (&self.cos2[..len], &self.sin2[..len]);
        let mut count = 0u64;
        for j in 0..len {
            let x = d0 + e1 * c[j] + e2 * s[j] + e3 * c2[j] + e4 * s2[j];
            d[j] = x;
            count += u64::from(x >= 0.0);
        }
        count as usize
    }
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

    /// Adds the discriminants `d[j]`, `count` of which are nonnegative: `count` to the count, and
    /// `sqrt(d[j])` (`0` if negative) to lane `j mod LANES` (`d` is overwritten by the roots).
    /// A block without a nonnegative `d[j]` adds only zeros: it is skipped, which changes no bit
    /// (the lane sums start at `+0` and `x + (+0) = x` for every `x` but `-0`, which a sum of
    /// `+0` and roots `>= +0` or `-0` never is).
    #[inline(always)]
    fn add(&mut self, d: &mut [f64], count: usize) {
        if count == 0 {
            return;
        }
        self.count += count;
        // Two loops (roots in place, then the lanes): fused, the compiler keeps the lanes in
        // two-wide registers and takes the square roots two at a time instead of four.
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
    /// The same code compiled for AVX-512F (eight samples per instruction, the eight lanes in one
    /// register), x86_64 with a compiler of version 1.89 or newer (where the target feature is
    /// stable) only.
    Avx512,
}

impl KernelPath {
    /// The fastest path this CPU runs.
    pub fn detect() -> Self {
        if KernelPath::Avx512.is_available() {
            KernelPath::Avx512
        } else if KernelPath::Avx2.is_available() {
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
            #[cfg(target_arch = "x86_64")]
            KernelPath::Avx512 => avx512_available(),
            #[cfg(not(target_arch = "x86_64"))]
            KernelPath::Avx512 => false,
        }
    }

    fn chunk(self, s: &Trig2, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
        match self {
            KernelPath::Portable => chunk_generic(s, table, lo, hi),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: a `KernelPath::Avx2` reaches here only after `is_available` confirmed
            // AVX2 on this CPU (`sweep_addition_with` checks it; `detect` picks it only then).
            KernelPath::Avx2 => unsafe { chunk_avx2(s, table, lo, hi) },
            #[cfg(not(target_arch = "x86_64"))]
            KernelPath::Avx2 => unreachable!("AVX2 is never available off x86_64"),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: as for AVX2, `is_available` confirmed AVX-512F on this CPU before.
            KernelPath::Avx512 => unsafe { chunk_avx512(s, table, lo, hi) },
            #[cfg(not(target_arch = "x86_64"))]
            KernelPath::Avx512 => unreachable!("AVX-512 is never available off x86_64"),
        }
    }
}

/// Whether this CPU runs AVX-512F (the target feature is stable, so compiled for, since Rust 1.89).
#[rustversion::since(1.89)]
#[cfg(target_arch = "x86_64")]
fn avx512_available() -> bool {
    is_x86_feature_detected!("avx512f")
}

/// Never: this compiler does not compile for AVX-512F (the target feature is stable since 1.89).
#[rustversion::before(1.89)]
#[cfg(target_arch = "x86_64")]
fn avx512_available() -> bool {
    false
}

/// The chunk kernel compiled with AVX-512F enabled.
///
/// # Safety
/// The CPU must support AVX-512F.
#[rustversion::since(1.89)]
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
unsafe fn chunk_avx512(s: &Trig2, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
    chunk_generic(s, table, lo, hi)
}

/// Never called: [`avx512_available`] is false with this compiler.
///
/// # Safety
/// None needed: it panics.
#[rustversion::before(1.89)]
#[cfg(target_arch = "x86_64")]
unsafe fn chunk_avx512(_: &Trig2, _: &AngleTable, _: usize, _: usize) -> GridSummary {
    unreachable!("AVX-512 is never available with this compiler")
}

/// The chunk kernel compiled with AVX2 enabled.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn chunk_avx2(s: &Trig2, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
    chunk_generic(s, table, lo, hi)
}

/// Samples `lo..hi` (`lo` a multiple of `BLOCK`): per block the discriminants by angle
/// addition into a buffer in L1, then the count and the lanes.
#[inline(always)]
fn chunk_generic(s: &Trig2, table: &AngleTable, lo: usize, hi: usize) -> GridSummary {
    let mut d = [0.0; BLOCK];
    let mut lanes = Lanes::ZERO;
    let mut i0 = lo;
    while i0 < hi {
        let len = BLOCK.min(hi - i0);
        let d = &mut d[..len];
        let count = table.discs(s, i0, d);
        lanes.add(d, count);
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
        let p = Trig2::new(self);
        let chunk = |k: usize| path.chunk(&p, &table, k * CHUNK, ((k + 1) * CHUNK).min(n));
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
        let reference =
            2.0 * alpha * ma * U + beta * U * (1.0 + U) + 8.0 * U * ma * ma + 6.0 * U * mb;
        (Trig2::new(self).kernel_error() + reference) * 1.001
    }

    fn addition_disc_error_scaled(&self) -> f64 {
        let (_, _, ma, mb) = magnitudes(self);
        self.addition_disc_error() / (U * (ma * ma + mb))
    }
}

/// The magnitudes of the module doc's error bound: `(alpha, beta, M_A, M_B)`.
fn magnitudes(s: &DiscSampler) -> (f64, f64, f64, f64) {
    let e = 1.0 + U;
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
