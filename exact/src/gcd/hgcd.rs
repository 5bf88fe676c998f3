//! Schönhage's half-gcd and the subquadratic gcd built on it, in the formulation of Möller
//! ("On Schönhage's algorithm and subquadratic integer gcd computation", Math. Comp. 77
//! (2008)), which is the one GMP's `mpn_hgcd` and `mpn_gcd` implement.
//!
//! # Reduction
//!
//! Write `B = 2^64` (one limb). For `a, b` of at most `n` limbs let `s = floor(n/2) + 1`. A
//! *reduction step* replaces the larger of two operands `a >= b`, both at least `B^s`, by
//! `a - q b` for the largest quotient `q >= 1` that keeps it at least `B^s`: the plain Euclidean
//! step `(a, b) -> (b, a mod b)` when `a mod b >= B^s`, otherwise `(a, b) -> (a - (q-1) b, b)`
//! with the true quotient `q` (and no step at all when `q = 1`). Each step is `(a; b) = E (a';
//! b')` with `E = [q 1; 1 0]` (det -1) or `E = [1 q; 0 1]` (det 1), so the product `M` of the
//! steps is a matrix of non-negative integers with `det M = ±1` and `(a; b) = M (a'; b')`; in
//! particular `gcd(a, b) = gcd(a', b')`. Steps are possible exactly while both operands are at
//! least `B^s` and differ by at least `B^s`; when no step is possible the pair is *reduced*:
//!
//! > `a', b' >= B^s` and `|a' - b'| < B^s`.
//!
//! [`half_gcd`] (`hgcd`) returns `M` and that reduced pair. Since `a >= m01 b'` and
//! `b >= m11 b'` (and likewise with `a'`), every entry of `M` is below `B^(n - s) <= B^(s-1)`.
//! The reduced pair has about `n/2` limbs: half of the Euclidean descent of `a, b`, found by
//! the recursion below with multiplications instead of `n/2` quadratic-cost steps.
//!
//! # Möller's lemma: reducing the leading limbs reduces the whole number
//!
//! Split `a = a_hi B^p + a_lo`, `b = b_hi B^p + b_lo` (`a_lo, b_lo < B^p`), let `a_hi, b_hi`
//! have `n'` limbs, and let `hgcd(a_hi, b_hi)` give `M` and `(α, β)`, both at least `B^(s')`
//! (`s' = floor(n'/2) + 1`). Then `M^-1 (a; b) = (α B^p + x; β B^p + y)` with
//! `x = ±(m11 a_lo - m01 b_lo)`, `y = ±(m00 b_lo - m10 a_lo)`, `|x|, |y| < B^(n' - s') B^p <=
//! B^(s'-1+p)`, so both new operands exceed `B^(s'+p) - B^(s'+p-1) >= B^(s'+p-1)`: they stay
//! positive (the subtraction in `Mat::adjust` cannot underflow) and large. `hgcd(a, b)` of
//! `n` limbs therefore runs (GMP's `mpn_hgcd`):
//!
//! 1. `hgcd` on the leading `n - p` limbs, `p = floor(n/2)`, applied to the whole numbers by
//!    the lemma: they drop to about `3n/4` limbs (and stay at least `B^s`, since
//!    `s' + p - 1 >= s` for `n >= 3`);
//! 2. single steps until at most `floor(3n/4) + 1` limbs remain (rarely more than one);
//! 3. if more than `s + 2` limbs remain (`n''` of them), `hgcd` on the leading
//!    `2 (n'' - s) - 1` limbs (`p = 2s - n'' + 1`): the outputs are at least `B^(s'+p-1) = B^s`
//!    and about `s + 1` limbs long; the matrices multiply;
//! 4. single steps until the pair is reduced.
//!
//! Below `HgcdTuning::hgcd_base` limbs only step 4 runs: that is the base case, quadratic but
//! with Lehmer's double-word steps. The cost is `H(n) = 2 H(n/2) + O(M(n))`, i.e.
//! `O(M(n) log n)` with `M` the multiplication cost (num-bigint's Karatsuba and Toom-3).
//!
//! # Steps
//!
//! A step first tries Lehmer's simulation (`lehmer_simulate_min`) on the leading 128
//! bits of both operands, at the shift `e` where `a`'s leading bit is bit 127 of the window.
//! Its certified quotients are the true ones and each simulated remainder `r'` equals the true
//! one divided by `2^e` up to an error below `2^63` (the cosequences are below `2^63`), so
//! requiring `r' >= 2^(64 s - e) + 2^63` keeps the true remainders at least `B^s`. When the
//! simulation certifies nothing (large quotient, window at the reduction floor, fewer than
//! three limbs), the step is an exact division (num-bigint) as in the definition above. The
//! cosequence matrix multiplies `M` from the right in one fused pass over `M`'s rows.
//!
//! # The gcd
//!
//! [`gcd_hgcd_tuned`] repeats: order `a >= b`; below `HgcdTuning::gcd_lehmer_below` limbs hand
//! over to [`super::gcd_lehmer`]; if `a` is more than a limb longer than `b`, one division
//! step; otherwise `hgcd` of the leading `n - p` limbs (`p = floor(2n/3)` as in GMP's
//! `mpn_gcd`; `HgcdTuning::split`: `p = 0` was the slowest at 10^5 and 3 10^5 bits, `floor(n/3)`
//! within the noise of `floor(2n/3)`), applied to the
//! whole numbers by the lemma, or, when that pair is already reduced, one Euclidean step. Every
//! pass shrinks the operands, and the gcd is unchanged because every matrix is unimodular.
//!
//! # Where it pays
//!
//! num-bigint's multiplication (Karatsuba, Toom-3) is several times slower than GMP's, and the
//! Lehmer steps above are fast (double-word simulation, fused update), so the crossover is
//! late: about 300,000 bits ([`super::HGCD_GCD_THRESHOLD`]), against a few hundred limbs in
//! GMP. At 10^6 bits the half-gcd takes about 0.6 of Lehmer's time, and the ratio keeps falling
//! (`O(M(n) log n)` against `O(n^2)`).
//!
//! Why hand-written: num-integer's `Integer::gcd` for `BigUint` is Stein's binary algorithm
//! (quadratic, with a large constant) and num-bigint has no subquadratic gcd; GMP's is C
//! under the LGPL. Only num-bigint's multiplication and division are used.

use std::cmp::Ordering;
use std::mem;

use num_bigint::BigUint;
use num_integer::Integer;
use num_traits::{CheckedSub, One, Zero};

use super::{
    from_limbs, gcd_lehmer, lehmer_simulate_min, lehmer_update, top128, trim, Cosequences,
};

/// The size parameters of the half-gcd algorithm, in 64-bit limbs. [`HGCD_TUNING`] holds the
/// measured ones (used by [`super::gcd_biguint`] and [`half_gcd`]); the tests use small ones so
/// that the recursion runs deep on small numbers, and the benchmarks compare others.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HgcdTuning {
    /// `hgcd` of operands of at most this many limbs runs the single steps alone (the base
    /// case).
    pub hgcd_base: usize,
    /// [`gcd_hgcd_tuned`] hands over to [`super::gcd_lehmer`] once the smaller operand has
    /// fewer limbs.
    pub gcd_lehmer_below: usize,
    /// [`gcd_hgcd_tuned`] runs `hgcd` on the leading `n - floor(n * split / 3)` limbs of its
    /// `n`-limb operands (0, 1 or 2; larger values count as 2).
    pub split: usize,
}

/// The measured tuning: `hgcd_base` and `split` from interleaved timing runs at 10^5 and
/// 3 10^5 bits (`hgcd_base` 20 to 250 limbs, `split` 0 to 2; larger bases and splits 1, 2 were
/// faster, within noise of each other from 150 limbs on), re-measured by the criterion group
/// `hgcd_tuning` of `bench/criterion/benches/gcd.rs`; `gcd_lehmer_below` is the crossover
/// [`super::HGCD_GCD_THRESHOLD`] (group `hgcd_crossover`; handing over at 1500 or 3000 limbs
/// instead made no measurable difference at 10^6 bits).
pub const HGCD_TUNING: HgcdTuning = HgcdTuning {
    hgcd_base: 150,
    gcd_lehmer_below: super::HGCD_GCD_THRESHOLD,
    split: 2,
};

/// The result of [`half_gcd`]: `(a, b) = M (a', b')`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HalfGcd {
    /// `M = [[m00, m01], [m10, m11]]`, non-negative entries, `det M = ±1`.
    pub matrix: [[BigUint; 2]; 2],
    /// `det M`: `1` or `-1`.
    pub det: i8,
    /// The reduced first operand `a'`.
    pub a: BigUint,
    /// The reduced second operand `b'`.
    pub b: BigUint,
}

/// Schönhage's half-gcd (see the module documentation of `gcd::hgcd`): with `n` the number of
/// 64-bit limbs of `max(a, b)` and `s = floor(n/2) + 1`, returns the matrix `M` of non-negative
/// integers with `det M = ±1` and the reduced pair `a', b'` with `(a, b) = M (a', b')`,
/// `a', b' >= 2^(64 s)` and `|a' - b'| < 2^(64 s)`. Returns `None` when `(a, b)` admits no
/// reduction step (`min(a, b) < 2^(64 s)` or `|a - b| < 2^(64 s)`).
pub fn half_gcd(a: &BigUint, b: &BigUint) -> Option<HalfGcd> {
    half_gcd_tuned(a, b, HGCD_TUNING)
}

/// [`half_gcd`] with explicit size parameters.
pub(super) fn half_gcd_tuned(a: &BigUint, b: &BigUint, t: HgcdTuning) -> Option<HalfGcd> {
    let (mut a, mut b) = (a.clone(), b.clone());
    let m = hgcd(&mut a, &mut b, t)?;
    let [m00, m01, m10, m11] = m.e.map(|e| from_limbs(&e));
    Some(HalfGcd {
        matrix: [[m00, m01], [m10, m11]],
        det: if m.neg { -1 } else { 1 },
        a,
        b,
    })
}

/// The subquadratic gcd (see the module documentation) with explicit size parameters,
/// `gcd(0, 0) = 0`: [`super::gcd_biguint`] is this with [`HGCD_TUNING`] above
/// [`super::HGCD_GCD_THRESHOLD`] limbs. Public for the benchmarks, which force the half-gcd
/// path at every size with a small `gcd_lehmer_below`.
pub fn gcd_hgcd_tuned(a: &BigUint, b: &BigUint, t: HgcdTuning) -> BigUint {
    let (mut a, mut b) = (a.clone(), b.clone());
    loop {
        if a < b {
            mem::swap(&mut a, &mut b);
        }
        let nb = nlimbs(&b);
        if nb < t.gcd_lehmer_below.max(1) {
            // Also the end of the loop: b = 0 has 0 limbs.
            return gcd_lehmer(&a, &b);
        }
        let n = nlimbs(&a);
        if n > nb + 1 {
            let r = &a % &b;
            a = mem::replace(&mut b, r);
            continue;
        }
        let p = n * t.split.min(2) / 3;
        if reduce(&mut a, &mut b, p, t).is_none() {
            let r = &a % &b;
            a = mem::replace(&mut b, r);
        }
    }
}

/// Number of 64-bit limbs of `x` (0 for 0).
#[inline]
fn nlimbs(x: &BigUint) -> usize {
    x.bits().div_ceil(64) as usize
}

/// `x` as `(x >> 64 p, x mod 2^(64 p))`.
fn split(x: &BigUint, p: usize) -> (BigUint, BigUint) {
    let d = x.to_u64_digits();
    if d.len() <= p {
        (BigUint::zero(), x.clone())
    } else {
        (from_limbs(&d[p..]), from_limbs(&d[..p]))
    }
}

/// `hgcd` in place: when a reduction step is possible, reduces `(a, b)` (see [`half_gcd`])
/// and returns `M`; otherwise leaves `a, b` unchanged and returns `None`.
fn hgcd(a: &mut BigUint, b: &mut BigUint, t: HgcdTuning) -> Option<Mat> {
    let n = nlimbs(a).max(nlimbs(b));
    let s = n / 2 + 1;
    let mut m = Mat::identity();
    let mut progress = false;
    if n > t.hgcd_base.max(2) {
        // 1. The leading half.
        if let Some(m1) = reduce(a, b, n / 2, t) {
            m = m1;
            progress = true;
        }
        // 2. Single steps down to 3n/4 + 1 limbs.
        let n2 = 3 * n / 4 + 1;
        if nlimbs(a).max(nlimbs(b)) > n2 {
            let (moved, reducible) = run_steps(a, b, s, &mut m, n2);
            progress |= moved;
            if !reducible {
                return progress.then_some(m);
            }
        }
        // 3. The leading 2 (nn - s) - 1 limbs.
        let nn = nlimbs(a).max(nlimbs(b));
        if nn > s + 2 {
            if let Some(m1) = reduce(a, b, 2 * s - nn + 1, t) {
                m = m.mul(&m1);
                progress = true;
            }
        }
    }
    // 4. Single steps until reduced (the whole algorithm in the base case).
    let (moved, _) = run_steps(a, b, s, &mut m, 0);
    progress |= moved;
    progress.then_some(m)
}

/// `hgcd` of the leading limbs `a >> 64 p`, `b >> 64 p`, applied to the whole numbers by
/// Möller's lemma; `None` (and `a, b` unchanged) when the leading limbs admit no step.
fn reduce(a: &mut BigUint, b: &mut BigUint, p: usize, t: HgcdTuning) -> Option<Mat> {
    if p == 0 {
        return hgcd(a, b, t);
    }
    let (mut ah, al) = split(a, p);
    let (mut bh, bl) = split(b, p);
    let m = hgcd(&mut ah, &mut bh, t)?;
    let (na, nb) = m.adjust(ah, bh, &al, &bl, p);
    *a = na;
    *b = nb;
    Some(m)
}

/// Runs [`step`] on `a, b` (converted to limbs once) while the longer has more than `target`
/// limbs and a step is possible, accumulating the steps into `m`. Returns whether any step was
/// made and whether the pair may still admit a step (`false`: it is reduced).
fn run_steps(
    a: &mut BigUint,
    b: &mut BigUint,
    s: usize,
    m: &mut Mat,
    target: usize,
) -> (bool, bool) {
    let mut la = a.to_u64_digits();
    let mut lb = b.to_u64_digits();
    let mut moved = false;
    let mut reducible = true;
    while la.len().max(lb.len()) > target {
        match step(&mut la, &mut lb, s, m) {
            Step::Reduced => moved = true,
            Step::ReducedLast => {
                moved = true;
                reducible = false;
                break;
            }
            Step::Irreducible => {
                reducible = false;
                break;
            }
        }
    }
    if moved {
        *a = from_limbs(&la);
        *b = from_limbs(&lb);
    }
    (moved, reducible)
}

/// Outcome of one [`step`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Step {
    /// A step was made.
    Reduced,
    /// A step was made and the pair is now reduced.
    ReducedLast,
    /// No step is possible; the operands are unchanged.
    Irreducible,
}

/// Compares two trimmed limb vectors as numbers.
fn cmp_limbs(a: &[u64], b: &[u64]) -> Ordering {
    a.len()
        .cmp(&b.len())
        .then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

/// One reduction step (see the module documentation) on trimmed limbs, keeping both operands
/// at least `B^s`; multiplies `m` from the right by the step's matrix.
fn step(a: &mut Vec<u64>, b: &mut Vec<u64>, s: usize, m: &mut Mat) -> Step {
    let swapped = cmp_limbs(a, b) == Ordering::Less;
    if swapped {
        mem::swap(a, b);
    }
    // Here a >= b.
    if b.len() <= s {
        if swapped {
            mem::swap(a, b);
        }
        return Step::Irreducible;
    }
    let n = a.len();
    if n >= 3 {
        let h = a[n - 1].leading_zeros();
        // The window holds bits e .. e + 128 of both operands; 2^(64 s) is its bit `lo`.
        let e = 64 * n as i64 - i64::from(h) - 128;
        let lo = 64 * s as i64 - e;
        if lo <= 125 {
            let floor = if lo > 0 { 1u128 << lo } else { 1 };
            let min = floor + (1u128 << 63);
            if let Some(c) = lehmer_simulate_min(top128(a, n, h), top128(b, n, h), min) {
                b.resize(n, 0);
                lehmer_update(a, b, c);
                trim(a);
                trim(b);
                if swapped {
                    m.swap_columns();
                }
                m.mul_cosequences(&c);
                return Step::Reduced;
            }
        }
    }
    // One exact division step.
    let (ba, bb) = (from_limbs(a), from_limbs(b));
    let (q, r) = ba.div_rem(&bb);
    if nlimbs(&r) > s {
        // (a; b) = [q 1; 1 0] (b; r)
        *a = mem::take(b);
        *b = r.to_u64_digits();
        if swapped {
            m.swap_columns();
        }
        m.mul_quotient(&q);
        Step::Reduced
    } else if q.is_one() {
        // a - b = r < B^s: reduced.
        if swapped {
            mem::swap(a, b);
        }
        Step::Irreducible
    } else {
        // (a; b) = [1 q-1; 0 1] (r + b; b), and (r + b) - b = r < B^s: reduced.
        *a = (r + bb).to_u64_digits();
        if swapped {
            m.swap_columns();
        }
        m.mul_upper(&(q - 1u32));
        Step::ReducedLast
    }
}

/// A 2x2 matrix of non-negative integers with determinant ±1, `(a; b) = M (a'; b')`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Mat {
    /// `m00, m01, m10, m11` as trimmed little-endian 64-bit limbs.
    e: [Vec<u64>; 4],
    /// `det M = -1` (otherwise `+1`).
    neg: bool,
}

impl Mat {
    fn identity() -> Mat {
        Mat {
            e: [vec![1], Vec::new(), Vec::new(), vec![1]],
            neg: false,
        }
    }

    fn big(&self, i: usize) -> BigUint {
        from_limbs(&self.e[i])
    }

    /// `M <- M [0 1; 1 0]`.
    fn swap_columns(&mut self) {
        self.e.swap(0, 1);
        self.e.swap(2, 3);
        self.neg = !self.neg;
    }

    /// `M <- M [y2 y1; x2 x1]`, the inverse of a Lehmer step: its operands `(A', B')` satisfy
    /// `(A; B) = [y2 y1; x2 x1] (A'; B')` with determinant `(-1)^steps`.
    fn mul_cosequences(&mut self, c: &Cosequences) {
        let [e0, e1, e2, e3] = &mut self.e;
        row_times_cosequences(e0, e1, c);
        row_times_cosequences(e2, e3, c);
        self.neg ^= c.odd;
    }

    /// `M <- M [q 1; 1 0]`.
    fn mul_quotient(&mut self, q: &BigUint) {
        for (i, j) in [(0, 1), (2, 3)] {
            let first = self.big(i) * q + self.big(j);
            self.e[j] = mem::replace(&mut self.e[i], first.to_u64_digits());
        }
        self.neg = !self.neg;
    }

    /// `M <- M [1 q; 0 1]`.
    fn mul_upper(&mut self, q: &BigUint) {
        for (i, j) in [(0, 1), (2, 3)] {
            self.e[j] = (self.big(i) * q + self.big(j)).to_u64_digits();
        }
    }

    /// `M N`.
    fn mul(&self, other: &Mat) -> Mat {
        let [a0, a1, a2, a3] = [0, 1, 2, 3].map(|i| self.big(i));
        let [b0, b1, b2, b3] = [0, 1, 2, 3].map(|i| other.big(i));
        let entries = [
            &a0 * &b0 + &a1 * &b2,
            &a0 * &b1 + &a1 * &b3,
            &a2 * &b0 + &a3 * &b2,
            &a2 * &b1 + &a3 * &b3,
        ];
        Mat {
            e: entries.map(|x| x.to_u64_digits()),
            neg: self.neg ^ other.neg,
        }
    }

    /// `M^-1 (alpha B^p + a_lo; beta B^p + b_lo)` where `(alpha, beta)` is the pair reduced by
    /// this `M` from the leading limbs (Möller's lemma: both results are positive).
    fn adjust(
        &self,
        alpha: BigUint,
        beta: BigUint,
        a_lo: &BigUint,
        b_lo: &BigUint,
        p: usize,
    ) -> (BigUint, BigUint) {
        let [m00, m01, m10, m11] = [0, 1, 2, 3].map(|i| self.big(i));
        // M^-1 = det [m11 -m01; -m10 m00].
        let (xa, xb) = (&m11 * a_lo, &m01 * b_lo);
        let (ya, yb) = (&m10 * a_lo, &m00 * b_lo);
        let ((xp, xm), (yp, ym)) = if self.neg {
            ((xb, xa), (ya, yb))
        } else {
            ((xa, xb), (yb, ya))
        };
        let shift = 64 * p as u64;
        let na = ((alpha << shift) + xp)
            .checked_sub(&xm)
            .expect("Möller's lemma: the adjusted first operand is positive");
        let nb = ((beta << shift) + yp)
            .checked_sub(&ym)
            .expect("Möller's lemma: the adjusted second operand is positive");
        (na, nb)
    }
}

/// `(p, q) <- (p y2 + q x2, p y1 + q x1)` in one pass over the limbs.
fn row_times_cosequences(p: &mut Vec<u64>, q: &mut Vec<u64>, c: &Cosequences) {
    let (x1, y1, x2, y2) = (
        u128::from(c.x1),
        u128::from(c.y1),
        u128::from(c.x2),
        u128::from(c.y2),
    );
    let n = p.len().max(q.len());
    p.resize(n, 0);
    q.resize(n, 0);
    // Cosequences are below 2^63: each sum of two products is below (2^64 - 1)(2^64 - 2), and
    // with a carry below 2^64 it still fits in a u128.
    let (mut cp, mut cq) = (0u128, 0u128);
    for (pi, qi) in p.iter_mut().zip(q.iter_mut()) {
        let (pw, qw) = (u128::from(*pi), u128::from(*qi));
        let tp = pw * y2 + qw * x2 + cp;
        let tq = pw * y1 + qw * x1 + cq;
        *pi = tp as u64;
        *qi = tq as u64;
        cp = tp >> 64;
        cq = tq >> 64;
    }
    p.push(cp as u64);
    q.push(cq as u64);
    trim(p);
    trim(q);
}

#[cfg(test)]
mod tests;
