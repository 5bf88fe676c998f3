//! Fast greatest common divisors for machine words and [`BigUint`].
//!
//! num-integer's `Integer::gcd` for `BigUint` is Stein's binary algorithm: about one
//! subtract-and-shift pass over the whole number per bit of the inputs, which makes it
//! quadratic with a large constant, and num-bigint has no subquadratic gcd. This module
//! provides:
//!
//! * [`gcd_u64`] and [`gcd_u128`]: binary gcds on machine words (with a remainder step first
//!   when the operands differ much in size, and [`gcd_u128`] dropping to [`gcd_u64`] as soon as
//!   both operands fit in 64 bits);
//! * [`gcd_biguint`], the main entry point: the subquadratic half-gcd algorithm ([`hgcd`],
//!   [`half_gcd`]) when both operands have at least [`HGCD_GCD_THRESHOLD`] limbs, and below
//!   that [`gcd_lehmer`];
//! * [`gcd_lehmer`]: word-sized shortcuts (and a shift when one operand is a power of two, as
//!   the denominators of doubles are), one division step when the operands differ in size
//!   by more than a limb, and otherwise Lehmer's algorithm on 64-bit limbs (quadratic; the
//!   reference the half-gcd path is tested against);
//! * [`gcd_biguint_u64`] and [`gcd_bigint_abs`], conveniences built on those.
//!
//! # Lehmer's algorithm
//!
//! The design follows Knuth's Algorithm L with Collins' stopping condition (Jebelean,
//! "Improving the multiprecision Euclidean algorithm", 1993), as in Go's `math/big`, but with a
//! *double-word* simulation: the Euclidean algorithm is simulated on the leading 128 bits of both
//! operands, as long as the cosequences fit in a 64-bit word. Each simulation therefore replaces
//! roughly 64 bits' worth of Euclidean steps by one fused in-place pass over the limbs of both
//! operands (four 64×64→128-bit products per limb). When the simulation cannot certify a single
//! quotient (a huge quotient, or operands agreeing on all their leading bits) one plain
//! Euclidean step `A, B = B, A mod B` is done with num-bigint's division.
//!
//! # Half-gcd
//!
//! Lehmer's algorithm still costs `O(n^2)` for `n`-limb operands. Above
//! [`HGCD_GCD_THRESHOLD`] limbs [`gcd_biguint`] uses Schönhage's half-gcd in Möller's
//! formulation (the one of GMP's `mpn_hgcd`), `O(M(n) log n)` with `M(n)` the cost of
//! num-bigint's multiplication: see the [`hgcd`] module. Its base case and its single steps
//! are the Lehmer steps above, kept above a floor (`lehmer_simulate_min`) and accumulated into
//! a cosequence matrix.
//!
//! There is no `unsafe`, and nothing panics but the half-gcd's two `expect`s on a broken
//! invariant (a negative operand, which Möller's lemma rules out); `gcd(0, 0) = 0`.

use num_bigint::{BigInt, BigUint};
use num_traits::{One, Zero};

/// Leading-zero difference above which [`gcd_u64`] starts with a remainder step.
const U64_REM_THRESHOLD: u32 = 16;
/// Leading-zero difference above which [`gcd_u128`] starts with a remainder step.
const U128_REM_THRESHOLD: u32 = 32;
/// Bound on the cosequences of a Lehmer step, so that the fused update fits in `i128`.
const COSEQ_MAX: u64 = (1 << 63) - 1;

pub mod hgcd;
pub use hgcd::{gcd_hgcd_tuned, half_gcd, HalfGcd, HgcdTuning, HGCD_TUNING};

/// Limbs (64 bits) that both operands of [`gcd_biguint`] must have for the half-gcd path;
/// below it Lehmer's algorithm is faster (measured with criterion, `bench/criterion/benches/gcd.rs`,
/// group `hgcd_vs_lehmer`).
pub const HGCD_GCD_THRESHOLD: usize = 4700;

/// Greatest common divisor of two `u64` (binary gcd; `gcd_u64(0, 0) == 0`).
///
/// When one operand is much smaller than the other (more than 16 bits shorter) a single
/// remainder step `a % b` is done first, which removes the size difference at the cost of one
/// hardware division.
#[inline]
pub fn gcd_u64(a: u64, b: u64) -> u64 {
    let (mut a, mut b) = if a >= b { (a, b) } else { (b, a) };
    if b == 0 {
        return a;
    }
    if a.is_power_of_two() || b.is_power_of_two() {
        // gcd(2^j, x) = 2^min(j, tz(x)): the lower of the two lowest set bits, no loop (the
        // denominators of doubles and dyadic rationals).
        return (a & a.wrapping_neg()).min(b & b.wrapping_neg());
    }
    if b.leading_zeros() - a.leading_zeros() > U64_REM_THRESHOLD {
        a %= b;
        if a == 0 {
            return b;
        }
    }
    // Both non-zero from here on; strip the common power of two, then make both odd.
    let k = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    b >>= b.trailing_zeros();
    loop {
        // Both odd: replace the larger by the odd part of the difference. The shift amount is
        // taken from the wrapping difference, which has the same trailing zeros as |a - b|.
        let d = b.wrapping_sub(a);
        if d == 0 {
            return a << k;
        }
        let s = d.trailing_zeros();
        let m = a.min(b);
        b = a.abs_diff(b) >> s;
        a = m;
    }
}

/// Greatest common divisor of two `u128` (binary gcd; `gcd_u128(0, 0) == 0`).
///
/// Uses [`gcd_u64`] as soon as both operands fit in 64 bits, and a remainder step first when
/// the operands differ in size by more than 32 bits.
#[inline]
pub fn gcd_u128(a: u128, b: u128) -> u128 {
    let (mut a, mut b) = if a >= b { (a, b) } else { (b, a) };
    if a >> 64 == 0 {
        return u128::from(gcd_u64(a as u64, b as u64));
    }
    if b == 0 {
        return a;
    }
    if a.is_power_of_two() || b.is_power_of_two() {
        // As in gcd_u64: no remainder step, no loop.
        return (a & a.wrapping_neg()).min(b & b.wrapping_neg());
    }
    if b.leading_zeros() - a.leading_zeros() > U128_REM_THRESHOLD {
        a %= b;
        if a == 0 {
            return b;
        }
        // Now a < b.
        if b >> 64 == 0 {
            return u128::from(gcd_u64(a as u64, b as u64));
        }
    }
    let k = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    b >>= b.trailing_zeros();
    loop {
        // Both odd, as in gcd_u64.
        if (a | b) >> 64 == 0 {
            return u128::from(gcd_u64(a as u64, b as u64)) << k;
        }
        let d = b.wrapping_sub(a);
        if d == 0 {
            return a << k;
        }
        let s = d.trailing_zeros();
        let m = a.min(b);
        b = a.abs_diff(b) >> s;
        a = m;
    }
}

/// Greatest common divisor of a [`BigUint`] and a `u64`.
///
/// Returns `Some(gcd)` whenever the gcd fits in a `u64`, which is always the case when
/// `b != 0` (the gcd then divides `b`); returns `None` only when `b == 0` and `a >= 2^64`
/// (the gcd is then `a` itself). One pass of single-limb remainder over the limbs of `a` (no
/// allocation, unlike `&BigUint % u64`, which clones), then [`gcd_u64`].
pub fn gcd_biguint_u64(a: &BigUint, b: u64) -> Option<u64> {
    if b == 0 {
        return fit_u64(a);
    }
    if b == 1 {
        return Some(1);
    }
    let r = match fit_u64(a) {
        Some(w) => w,
        None => crate::bigint::rem_1_big(a, b),
    };
    Some(gcd_u64(b, r))
}

/// Greatest common divisor of the magnitudes of two [`BigInt`]s (`gcd(0, 0) = 0`).
///
/// Same as [`gcd_biguint`] on `a.magnitude()` and `b.magnitude()`.
pub fn gcd_bigint_abs(a: &BigInt, b: &BigInt) -> BigUint {
    gcd_biguint(a.magnitude(), b.magnitude())
}

/// Greatest common divisor of two [`BigUint`]s (`gcd(0, 0) = 0`); a drop-in, much faster
/// replacement for num-integer's `Integer::gcd`.
///
/// When both operands have at least [`HGCD_GCD_THRESHOLD`] limbs (64 bits each) this is the
/// subquadratic half-gcd algorithm ([`hgcd`]); otherwise, and for what is left once the
/// half-gcd has brought the operands below that size, it is [`gcd_lehmer`].
pub fn gcd_biguint(a: &BigUint, b: &BigUint) -> BigUint {
    if a.bits().min(b.bits()) >= 64 * HGCD_GCD_THRESHOLD as u64 {
        return gcd_hgcd_tuned(a, b, HGCD_TUNING);
    }
    gcd_lehmer(a, b)
}

/// Greatest common divisor of two [`BigUint`]s (`gcd(0, 0) = 0`) by Lehmer's algorithm: the
/// quadratic reference for [`gcd_biguint`], which uses it below [`HGCD_GCD_THRESHOLD`] limbs.
///
/// * a zero operand: the other one is returned;
/// * an operand that is a power of two `2^j`: `2^min(j, tz)` with `tz` the other's trailing zeros;
/// * an operand that fits in one 64-bit limb: a single-limb remainder, then [`gcd_u64`];
/// * both operands fitting in 128 bits: [`gcd_u128`];
/// * bit lengths differing by more than 64: one division step `a % b` first;
/// * otherwise Lehmer's algorithm on 64-bit limbs (see the module documentation), finished by
///   a word-sized gcd.
pub fn gcd_lehmer(a: &BigUint, b: &BigUint) -> BigUint {
    if a.is_zero() {
        return b.clone();
    }
    if b.is_zero() {
        return a.clone();
    }
    if a.is_one() || b.is_one() {
        return BigUint::one();
    }
    if let Some(g) = gcd_power_of_two(a, b) {
        return g;
    }
    let (a, b) = if a >= b { (a, b) } else { (b, a) };
    // Here a >= b > 0.
    if let Some(bw) = fit_u64(b) {
        let r = match fit_u64(a) {
            Some(aw) => aw % bw,
            None => crate::bigint::rem_1_big(a, bw),
        };
        return BigUint::from(gcd_u64(bw, r));
    }
    if let Some(aw) = fit_u128(a) {
        // b fits as well since b <= a.
        let bw = fit_u128(b).unwrap_or(0);
        return BigUint::from(gcd_u128(aw, bw));
    }
    if a.bits() - b.bits() > 64 {
        let r = a % b;
        if r.is_zero() {
            return b.clone();
        }
        return lehmer_gcd(b.to_u64_digits(), r.to_u64_digits());
    }
    lehmer_gcd(a.to_u64_digits(), b.to_u64_digits())
}

/// `gcd(a, b)` for non-zero `a`, `b` of which one is a power of two, `2^min(tz(a), tz(b))` (a
/// shift, no division); `None` when neither is. The denominators of doubles and of every value
/// built from them by ring operations are powers of two, so most gcds of normalisation in a
/// sweep over double inputs end here.
#[inline]
fn gcd_power_of_two(a: &BigUint, b: &BigUint) -> Option<BigUint> {
    let (ta, tb) = (a.trailing_zeros()?, b.trailing_zeros()?);
    let power = |x: &BigUint, t: u64| x.bits() == t + 1;
    (power(a, ta) || power(b, tb)).then(|| BigUint::one() << ta.min(tb))
}

/// `Some(x)` when `x < 2^64`.
#[inline]
fn fit_u64(x: &BigUint) -> Option<u64> {
    if x.bits() <= 64 {
        Some(x.iter_u64_digits().next().unwrap_or(0))
    } else {
        None
    }
}

/// `Some(x)` when `x < 2^128`.
#[inline]
fn fit_u128(x: &BigUint) -> Option<u128> {
    if x.bits() <= 128 {
        let mut it = x.iter_u64_digits();
        let lo = it.next().unwrap_or(0);
        let hi = it.next().unwrap_or(0);
        Some(u128::from(hi) << 64 | u128::from(lo))
    } else {
        None
    }
}

/// `x mod d` for a number given by its 64-bit limbs, least significant first (`d != 0`), one
/// `u128` remainder per limb: the reference for [`crate::bigint::rem_1`], which replaced it.
#[cfg(test)]
fn rem_limbs_u64<I: DoubleEndedIterator<Item = u64>>(limbs: I, d: u64) -> u64 {
    if d == 0 {
        return 0;
    }
    let d = u128::from(d);
    let mut r: u128 = 0;
    for w in limbs.rev() {
        r = ((r << 64) | u128::from(w)) % d;
    }
    r as u64
}

/// Builds a [`BigUint`] from 64-bit limbs, least significant first.
fn from_limbs(limbs: &[u64]) -> BigUint {
    let mut digits = Vec::with_capacity(2 * limbs.len());
    for &w in limbs {
        digits.push(w as u32);
        digits.push((w >> 32) as u32);
    }
    BigUint::new(digits)
}

/// Removes leading (most significant) zero limbs.
#[inline]
fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// The value of at most two limbs as a `u128`.
#[inline]
fn limbs_u128(x: &[u64]) -> u128 {
    let lo = x.first().copied().unwrap_or(0);
    let hi = x.get(1).copied().unwrap_or(0);
    u128::from(hi) << 64 | u128::from(lo)
}

/// The 128 bits of `x` starting `h` bits below the top of limb `n - 1` (limbs past the end of
/// `x` read as zero); requires `n >= 3` and `h < 64`.
#[inline]
fn top128(x: &[u64], n: usize, h: u32) -> u128 {
    let limb = |i: usize| u128::from(x.get(i).copied().unwrap_or(0));
    let hi = limb(n - 1) << 64 | limb(n - 2);
    if h == 0 {
        hi
    } else {
        hi << h | limb(n - 3) >> (64 - h)
    }
}

/// The cosequence matrix found by [`lehmer_simulate`]: after `m >= 1` certified Euclidean
/// steps, the new operands are (with magnitudes `x1, y1, x2, y2`)
///
/// * `m` even: `A' = x1*A - y1*B`, `B' = y2*B - x2*A`;
/// * `m` odd:  `A' = y1*B - x1*A`, `B' = x2*A - y2*B`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Cosequences {
    x1: u64,
    y1: u64,
    x2: u64,
    y2: u64,
    odd: bool,
}

/// Quotient and remainder of `a / b` for `a >= b > 0`, with fast paths for the small
/// quotients that dominate the Euclidean algorithm: quotients 1 and 2 by subtraction, and
/// quotients below 2^24 by a floating-point estimate from the leading bits (avoiding the slow
/// 128-bit division routine).
#[inline]
fn divrem_u128(a: u128, b: u128) -> (u128, u128) {
    let d = a - b;
    if d < b {
        return (1, d);
    }
    let d2 = d - b;
    if d2 < b {
        return (2, d2);
    }
    if a >> 64 == 0 {
        let (a, b) = (a as u64, b as u64);
        return (u128::from(a / b), u128::from(a % b));
    }
    let q = a / b;
    (q, a - q * b)
}

/// `x + q*y` when it is at most [`COSEQ_MAX`] (with `x, y <= COSEQ_MAX` and `q <= COSEQ_MAX`).
#[inline]
fn coseq_next(x: u64, q: u64, y: u64) -> Option<u64> {
    let t = u128::from(q) * u128::from(y) + u128::from(x);
    if t <= u128::from(COSEQ_MAX) {
        Some(t as u64)
    } else {
        None
    }
}

/// Simulates the Euclidean algorithm on the leading 128 bits `t1 >= t2` of `A >= B` (taken at
/// the same shift), certifying each quotient with Collins' condition and stopping before a
/// cosequence exceeds 64 bits. Returns `None` when not a single quotient could be certified.
#[inline(always)]
fn lehmer_simulate(t1: u128, t2: u128) -> Option<Cosequences> {
    simulate::<false>(t1, t2, 0)
}

/// [`lehmer_simulate`] that moreover keeps every simulated remainder it returns at least
/// `min`: it stops before the first quotient whose remainder would fall below `min` (the
/// half-gcd's steps use this to keep both operands above `2^(64 s)`, see [`hgcd`]). With
/// `min = 0` it is exactly [`lehmer_simulate`].
fn lehmer_simulate_min(t1: u128, t2: u128, min: u128) -> Option<Cosequences> {
    simulate::<true>(t1, t2, min)
}

/// The simulation behind [`lehmer_simulate`] (`FLOOR = false`: `min` ignored, the check
/// compiled out) and [`lehmer_simulate_min`]; inlined into both so that Lehmer's loop keeps
/// its tight code.
#[inline(always)]
fn simulate<const FLOOR: bool>(t1: u128, t2: u128, min: u128) -> Option<Cosequences> {
    let (mut a1, mut a2) = (t1, t2);
    // Rows of magnitudes (u, v) of r_{k-1}, r_k, r_{k+1} = ±(u*A - v*B) after k steps.
    let (mut u0, mut u1, mut u2): (u64, u64, u64) = (0, 1, 0);
    let (mut v0, mut v1, mut v2): (u64, u64, u64) = (0, 0, 1);
    let mut k: u32 = 0;
    loop {
        // Collins' condition certifies the last quotient computed (step k).
        if a2 < u128::from(v2) || a1 < a2 || a1 - a2 < u128::from(v1) + u128::from(v2) {
            break;
        }
        let (q, r) = divrem_u128(a1, a2);
        if FLOOR && r < min {
            // Steps 1..k are certified and their remainders r_k >= r_{k+1} (= a1, a2) are at
            // least `min` (r_{k+1} was checked when it was computed; r_k >= r_{k+1}).
            if k == 0 {
                return None;
            }
            return Some(Cosequences {
                x1: u1,
                y1: v1,
                x2: u2,
                y2: v2,
                odd: k % 2 == 1,
            });
        }
        // v2 >= 1, so a quotient above COSEQ_MAX always overflows the cosequences.
        let Ok(q) = u64::try_from(q) else {
            break;
        };
        let (nu, nv) = (coseq_next(u1, q, u2), coseq_next(v1, q, v2));
        let (Some(nu), Some(nv)) = (nu, nv) else {
            break;
        };
        (u0, u1, u2) = (u1, u2, nu);
        (v0, v1, v2) = (v1, v2, nv);
        (a1, a2) = (a2, r);
        k += 1;
    }
    // Steps 1..k-1 are certified; the new operands are r_{k-1}, r_k.
    if k < 2 {
        return None;
    }
    Some(Cosequences {
        x1: u0,
        y1: v0,
        x2: u1,
        y2: v1,
        odd: (k - 1) % 2 == 1,
    })
}

/// One fused in-place pass computing the new operands from the cosequences (see
/// [`Cosequences`]). `a` and `b` have the same length (`b` zero-padded). The results are
/// non-negative and smaller than `A`, so the final carries cancel.
fn lehmer_update(a: &mut [u64], b: &mut [u64], c: Cosequences) {
    if c.odd {
        lehmer_update_parity::<true>(a, b, c);
    } else {
        lehmer_update_parity::<false>(a, b, c);
    }
}

#[inline(always)]
fn lehmer_update_parity<const ODD: bool>(a: &mut [u64], b: &mut [u64], c: Cosequences) {
    let (x1, y1, x2, y2) = (
        u128::from(c.x1),
        u128::from(c.y1),
        u128::from(c.x2),
        u128::from(c.y2),
    );
    // All cosequences are below 2^63, so each product is below 2^127 and the difference of two
    // products plus a signed carry (|carry| < 2^63) fits in an i128.
    let (mut ca, mut cb) = (0i128, 0i128);
    for (ai, bi) in a.iter_mut().zip(b.iter_mut()) {
        let (aw, bw) = (u128::from(*ai), u128::from(*bi));
        let xa1 = (x1 * aw) as i128;
        let yb1 = (y1 * bw) as i128;
        let xa2 = (x2 * aw) as i128;
        let yb2 = (y2 * bw) as i128;
        // Even: A' = x1*A - y1*B, B' = y2*B - x2*A; odd: the negations.
        let (ta, tb) = if ODD {
            (yb1 - xa1 + ca, xa2 - yb2 + cb)
        } else {
            (xa1 - yb1 + ca, yb2 - xa2 + cb)
        };
        *ai = ta as u64;
        *bi = tb as u64;
        ca = ta >> 64;
        cb = tb >> 64;
    }
    debug_assert_eq!((ca, cb), (0, 0));
}

/// Lehmer's gcd on little-endian 64-bit limbs; requires `A >= B` as numbers.
fn lehmer_gcd(mut a: Vec<u64>, mut b: Vec<u64>) -> BigUint {
    trim(&mut a);
    trim(&mut b);
    loop {
        if b.is_empty() {
            return from_limbs(&a);
        }
        if a.len() <= 2 {
            return BigUint::from(gcd_u128(limbs_u128(&a), limbs_u128(&b)));
        }
        if b.len() == 1 {
            let bw = b[0];
            let r = crate::bigint::rem_1(&a, bw);
            return BigUint::from(gcd_u64(bw, r));
        }
        let n = a.len();
        let h = a[n - 1].leading_zeros();
        let t1 = top128(&a, n, h);
        let t2 = top128(&b, n, h);
        match lehmer_simulate(t1, t2) {
            Some(c) => {
                b.resize(n, 0);
                lehmer_update(&mut a, &mut b, c);
                trim(&mut a);
                trim(&mut b);
            }
            None => {
                // No certified quotient: one plain Euclidean step.
                let r = from_limbs(&a) % from_limbs(&b);
                a = b;
                b = r.to_u64_digits();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;
    use num_integer::Integer;
    use proptest::prelude::*;

    fn naive_gcd_u64(mut a: u64, mut b: u64) -> u64 {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    }

    fn naive_gcd_u128(mut a: u128, mut b: u128) -> u128 {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    }

    fn random_biguint(limbs: usize, state: &mut Rng) -> BigUint {
        let v: Vec<u64> = (0..limbs).map(|_| state.next_u64()).collect();
        from_limbs(&v)
    }

    fn check(a: &BigUint, b: &BigUint) {
        let expected = a.gcd(b);
        assert_eq!(gcd_biguint(a, b), expected, "gcd({a:x}, {b:x})");
        assert_eq!(gcd_biguint(b, a), expected, "gcd({b:x}, {a:x})");
    }

    fn fibonacci(n: usize) -> BigUint {
        let (mut x, mut y) = (BigUint::zero(), BigUint::from(1u32));
        for _ in 0..n {
            let z = &x + &y;
            x = y;
            y = z;
        }
        x
    }

    /// A BigUint from random limbs, shifted right by a random amount so that all bit lengths
    /// occur.
    fn arb_biguint(max_limbs: usize) -> impl Strategy<Value = BigUint> {
        (prop::collection::vec(any::<u64>(), 0..max_limbs), 0u32..64)
            .prop_map(|(v, s)| from_limbs(&v) >> s)
    }

    proptest! {
        #[test]
        fn prop_rem_1_matches_reference(v in prop::collection::vec(any::<u64>(), 0..20), d in 1u64..u64::MAX, s in 0u32..64) {
            let d = (d >> s).max(1);
            prop_assert_eq!(crate::bigint::rem_1(&v, d), rem_limbs_u64(v.iter().copied(), d));
        }

        #[test]
        fn prop_gcd_u64(a in any::<u64>(), b in any::<u64>()) {
            prop_assert_eq!(gcd_u64(a, b), naive_gcd_u64(a, b));
        }

        #[test]
        fn prop_gcd_u64_shifted(a in any::<u64>(), b in any::<u64>(), s in 0u32..64, t in 0u32..64) {
            let (a, b) = (a >> s, b >> t);
            prop_assert_eq!(gcd_u64(a, b), naive_gcd_u64(a, b));
        }

        #[test]
        fn prop_gcd_u128(a in any::<u128>(), b in any::<u128>(), s in 0u32..128, t in 0u32..128) {
            let (a, b) = (a >> s, b >> t);
            prop_assert_eq!(gcd_u128(a, b), naive_gcd_u128(a, b));
        }

        /// One operand a power of two (the shortcut), the other any value, in both orders.
        #[test]
        fn prop_gcd_power_of_two(x in any::<u128>(), s in 0u32..128, j in 0u32..128, t in 0u32..128) {
            let (x, p) = (x >> s << (t.min(s)), 1u128 << j);
            prop_assert_eq!(gcd_u128(x, p), naive_gcd_u128(x, p));
            prop_assert_eq!(gcd_u128(p, x), naive_gcd_u128(x, p));
            let (x64, p64) = (x as u64, 1u64 << (j % 64));
            prop_assert_eq!(gcd_u64(x64, p64), naive_gcd_u64(x64, p64));
            prop_assert_eq!(gcd_u64(p64, x64), naive_gcd_u64(x64, p64));
            let (xb, pb) = (BigUint::from(x) << (3 * j), BigUint::one() << (2 * j + s));
            check(&xb, &pb);
        }

        #[test]
        fn prop_gcd_u128_common(a in any::<u64>(), b in any::<u64>(), g in any::<u64>()) {
            let (a, b) = (u128::from(a) * u128::from(g), u128::from(b) * u128::from(g));
            prop_assert_eq!(gcd_u128(a, b), naive_gcd_u128(a, b));
        }

        #[test]
        fn prop_gcd_biguint_random(a in arb_biguint(40), b in arb_biguint(40)) {
            check(&a, &b);
        }

        #[test]
        fn prop_gcd_biguint_common_factor(
            x in arb_biguint(20), y in arb_biguint(20), g in arb_biguint(20)
        ) {
            check(&(&x * &g), &(&y * &g));
        }

        #[test]
        fn prop_gcd_biguint_different_sizes(a in arb_biguint(4), b in arb_biguint(40), g in arb_biguint(3)) {
            check(&(&a * &g), &(&b * &g));
        }

        #[test]
        fn prop_gcd_biguint_close(x in arb_biguint(30), d in arb_biguint(3), g in arb_biguint(10)) {
            // Operands agreeing on their leading bits: the simulation certifies nothing.
            let a = &x * &g;
            let b = &a + &d * &g;
            check(&a, &b);
        }

        #[test]
        fn prop_gcd_biguint_huge_partial_quotient(
            r1 in arb_biguint(12), r2 in arb_biguint(12), q in arb_biguint(6), q2 in 1u64..1000
        ) {
            // Continued fraction [.., q2, q, ..] with a huge partial quotient q in the middle.
            let b = &q * &r1 + &r2;
            let a = &b * q2 + &r1;
            check(&a, &b);
        }

        #[test]
        fn prop_gcd_biguint_u64(a in arb_biguint(10), b in any::<u64>(), s in 0u32..64) {
            let b = b >> s;
            let expected = a.gcd(&BigUint::from(b));
            let got = gcd_biguint_u64(&a, b);
            if a.bits() > 64 && b == 0 {
                prop_assert_eq!(got, None);
            } else {
                prop_assert_eq!(got.map(BigUint::from), Some(expected));
            }
        }

        #[test]
        fn prop_gcd_bigint_abs(a in arb_biguint(8), b in arb_biguint(8), sa in any::<bool>(), sb in any::<bool>()) {
            use num_bigint::Sign;
            let sign = |s: bool| if s { Sign::Minus } else { Sign::Plus };
            let ia = BigInt::from_biguint(sign(sa), a.clone());
            let ib = BigInt::from_biguint(sign(sb), b.clone());
            prop_assert_eq!(gcd_bigint_abs(&ia, &ib), a.gcd(&b));
        }
    }

    #[test]
    fn small_cases() {
        assert_eq!(gcd_u64(0, 0), 0);
        assert_eq!(gcd_u64(0, 7), 7);
        assert_eq!(gcd_u64(7, 0), 7);
        assert_eq!(gcd_u64(12, 18), 6);
        assert_eq!(gcd_u64(u64::MAX, u64::MAX), u64::MAX);
        assert_eq!(gcd_u64(1 << 63, 1 << 40), 1 << 40);
        assert_eq!(gcd_u64(u64::MAX, 1), 1);
        assert_eq!(gcd_u128(0, 0), 0);
        assert_eq!(gcd_u128(u128::MAX, 0), u128::MAX);
        assert_eq!(gcd_u128(u128::MAX, u128::MAX), u128::MAX);
        assert_eq!(gcd_u128(1 << 127, 1 << 100), 1 << 100);
        assert_eq!(gcd_u128(u128::MAX, 3), 3);
        assert_eq!(
            gcd_u128(u128::MAX, u128::from(u64::MAX)),
            u128::from(u64::MAX)
        );
        let z = BigUint::zero();
        assert_eq!(gcd_biguint(&z, &z), z);
        assert_eq!(gcd_biguint_u64(&z, 0), Some(0));
        assert_eq!(gcd_biguint_u64(&(BigUint::from(1u32) << 64u32), 0), None);
        assert_eq!(
            gcd_biguint_u64(&(BigUint::from(1u32) << 64u32), 1 << 40),
            Some(1 << 40)
        );
        assert_eq!(
            gcd_bigint_abs(&BigInt::zero(), &BigInt::from(-5)),
            BigUint::from(5u32)
        );
    }

    #[test]
    fn zeros_equal_and_divisible() {
        let mut st = Rng::new(1);
        let z = BigUint::zero();
        for limbs in [1, 2, 3, 5, 17, 64] {
            let x = random_biguint(limbs, &mut st);
            assert_eq!(gcd_biguint(&x, &z), x);
            assert_eq!(gcd_biguint(&z, &x), x);
            assert_eq!(gcd_biguint(&x, &x), x);
            for m in [1usize, 2, 3, 20] {
                let y = &x * random_biguint(m, &mut st);
                assert_eq!(gcd_biguint(&x, &y), x);
                assert_eq!(gcd_biguint(&y, &x), x);
            }
            let y = &x + 1u32;
            assert_eq!(gcd_biguint(&x, &y), BigUint::from(1u32));
        }
    }

    #[test]
    fn powers_of_two() {
        let one = BigUint::from(1u32);
        for i in [0u32, 1, 63, 64, 65, 127, 128, 129, 191, 192, 500, 1000] {
            for j in [0u32, 1, 63, 64, 65, 127, 128, 129, 191, 192, 500, 1000] {
                let expected = &one << i.min(j);
                assert_eq!(gcd_biguint(&(&one << i), &(&one << j)), expected);
                // Odd parts coprime: 3^k has no factor 2.
                let a = (&one << i) * BigUint::from(3u32).pow(40);
                let b = (&one << j) * BigUint::from(5u32).pow(30);
                assert_eq!(gcd_biguint(&a, &b), expected);
                check(&a, &b);
            }
        }
    }

    #[test]
    fn fibonacci_worst_case() {
        // F(7200) has about 5000 bits; consecutive Fibonacci numbers are coprime and take the
        // maximum number of Euclidean steps (all quotients 1).
        let f = (7190..=7202).map(fibonacci).collect::<Vec<_>>();
        let one = BigUint::from(1u32);
        for w in f.windows(2) {
            assert_eq!(gcd_biguint(&w[0], &w[1]), one);
            assert_eq!(gcd_biguint(&w[1], &w[0]), one);
        }
        // gcd(F(m), F(n)) = F(gcd(m, n)).
        assert_eq!(
            gcd_biguint(&fibonacci(7200), &fibonacci(4800)),
            fibonacci(2400)
        );
        assert_eq!(
            gcd_biguint(&fibonacci(7200), &fibonacci(7190)),
            fibonacci(10)
        );
        assert_eq!(
            gcd_biguint(&fibonacci(6000), &fibonacci(4500)),
            fibonacci(1500)
        );
    }

    #[test]
    fn big_with_large_common_factor() {
        // 3000-limb operands with a 1000-limb common factor, against num-integer.
        let mut st = Rng::new(0x5eed);
        let g = random_biguint(1000, &mut st);
        let x = random_biguint(2000, &mut st);
        let y = random_biguint(2000, &mut st);
        let (a, b) = (&x * &g, &y * &g);
        let expected = a.gcd(&b);
        assert!(expected.bits() >= g.bits());
        assert_eq!(gcd_biguint(&a, &b), expected);
    }

    #[test]
    fn big_self_consistent() {
        // Larger sizes checked without num-integer: the gcd divides both operands and the
        // cofactors are coprime, with known common factor g.
        let mut st = Rng::new(42);
        for (lx, ly, lg) in [
            (3000usize, 2990usize, 500usize),
            (200, 5, 300),
            (4000, 4000, 1),
        ] {
            let g = random_biguint(lg, &mut st);
            let x = random_biguint(lx, &mut st);
            let y = random_biguint(ly, &mut st);
            let (a, b) = (&x * &g, &y * &g);
            let d = gcd_biguint(&a, &b);
            assert!((&d % &g).is_zero());
            assert!((&a % &d).is_zero() && (&b % &d).is_zero());
            let (ca, cb) = (&a / &d, &b / &d);
            assert_eq!(gcd_biguint(&ca, &cb), BigUint::from(1u32));
        }
    }

    #[test]
    fn simulate_certifies_only_true_quotients() {
        // Exhaustive-ish check of the cosequence matrix on 3-limb operands.
        let mut st = Rng::new(7);
        for _ in 0..2000 {
            let a = random_biguint(3, &mut st);
            let b = random_biguint(3, &mut st) >> (st.next_u64() % 70);
            let (a, b) = if a >= b { (a, b) } else { (b, a) };
            if b.bits() <= 128 {
                continue;
            }
            let (la, lb) = (a.to_u64_digits(), b.to_u64_digits());
            let h = la[2].leading_zeros();
            if let Some(c) = lehmer_simulate(top128(&la, 3, h), top128(&lb, 3, h)) {
                let (x1, y1, x2, y2) = (
                    BigInt::from(c.x1),
                    BigInt::from(c.y1),
                    BigInt::from(c.x2),
                    BigInt::from(c.y2),
                );
                let (ia, ib) = (BigInt::from(a.clone()), BigInt::from(b.clone()));
                let s = if c.odd { -1 } else { 1 };
                let na = (&x1 * &ia - &y1 * &ib) * s;
                let nb = (&y2 * &ib - &x2 * &ia) * s;
                // The new pair is a consecutive pair of the true remainder sequence.
                assert!(nb >= BigInt::zero() && na > nb, "{a} {b} {c:?}");
                let mut r = (BigInt::from(a), BigInt::from(b));
                while r.0 != na {
                    assert!(r.1 > BigInt::zero());
                    r = (r.1.clone(), &r.0 % &r.1);
                }
                assert_eq!(r.1, nb);
            }
        }
    }
}
