//! Linear-time kernels on little-endian 64-bit limb slices: remainder by one limb, exact
//! division by one limb, and the linear combination `A*m1 ± B*m2` of two big numbers with
//! one-limb multipliers.
//!
//! These are the operations of adding a word-sized rational `c/d` to a big one `a/b` by
//! Henrici's method ([`crate::rational`]): `b mod d`, `b / g` (exact, `g = gcd(b, d)`),
//! `a (d/g) + c (b/g)`, and its remainder by `g`. Workload W2 `seq` (the running sum
//! `s += disc`, whose denominator grows to tens of thousands of digits while every `disc` fits
//! in machine words) spends nearly all its time there. num-bigint 0.4 does them with a clone of
//! the big operand and one hardware (or `u128` library) division per limb, which profiled at
//! roughly four times GMP's cost per limb. num-bigint keeps `BigInt`/`BigUint` as the public
//! types; no maintained crate with a compatible licence offers these kernels on its limbs (GMP
//! bindings are LGPL and C), so they are written here, on the limbs read from
//! `BigUint::iter_u64_digits`/`to_u64_digits`.
//!
//! # Algorithms
//! * **Remainder by a limb `d < 2^61`** ([`rem_1`]): the folding method of GMP's
//!   `mpn_mod_1s_4p` (Möller and Granlund, "Improved division by invariant integers", IEEE Trans.
//!   Computers 60 (2011), section 8 and GMP's implementation notes): with `c_i = 2^(64 i) mod d`
//!   precomputed, four limbs and the two-limb running residue `(rh, rl)` are folded per step
//!   into `w0 + w1 c1 + w2 c2 + w3 c3 + rl c4 + rh c5`, which stays below `2^64 (1 + 5 d) <
//!   2^128`; no division happens inside the loop (the dependency chain is one multiply-add per
//!   four limbs), and one `u128` remainder finishes. Larger `d` use Möller–Granlund's
//!   division by an invariant normalised divisor with a precomputed reciprocal (their
//!   Algorithm 4), one limb per step.
//! * **Exact division by a limb** ([`divexact_1`]): Jebelean's exact division ("An algorithm
//!   for exact division", J. Symbolic Computation 15 (1993)) in the form of GMP's
//!   `mpn_divexact_1`: the quotient is produced from the least significant limb upwards as
//!   `q_i = (x_i - borrow) * d^(-1) mod 2^64` — multiplications only; the factor `2^s` of an
//!   even divisor is shifted out on the fly.
//! * **Linear combination** ([`lin_comb`]): one pass with a two-limb carry (a signed one for
//!   differences, negated by a two's-complement pass when the result is negative).
//!
//! Every kernel is tested against num-bigint's `%`, `/`, `*` and `+`/`-` (module tests).

use num_bigint::BigUint;

/// Largest divisor handled by the folding remainder ([`rem_1`] uses the reciprocal method
/// above it): keeps the folded sum `w0 + 5 (2^64 - 1) (d - 1)` below `2^128`.
const FOLD_MAX: u64 = 1 << 61;

/// `x mod d` for a number given by its limbs (least significant first); `d != 0`.
///
/// # Panics
/// If `d == 0` (a caller bug: the remainder is undefined).
pub fn rem_1(x: &[u64], d: u64) -> u64 {
    assert!(d != 0, "rem_1: division by zero");
    if d == 1 {
        return 0;
    }
    if d < FOLD_MAX {
        rem_1_fold(x, d)
    } else {
        rem_1_preinv(x, d)
    }
}

/// The folding remainder for `2 <= d < 2^61` (see the module documentation).
fn rem_1_fold(x: &[u64], d: u64) -> u64 {
    let dd = u128::from(d);
    // c[i] = 2^(64 i) mod d for i = 0..=5.
    let mut c = [0u64; 6];
    c[0] = 1 % d;
    c[1] = ((u128::from(u64::MAX) + 1) % dd) as u64;
    for i in 2..6 {
        c[i] = (u128::from(c[i - 1]) * u128::from(c[1]) % dd) as u64;
    }
    let m = |a: u64, b: u64| u128::from(a) * u128::from(b);
    let (mut rh, mut rl) = (0u64, 0u64);
    let n = x.len();
    let k = n % 4;
    // Leading partial block of k limbs: (rh, rl) = 0, so the fold is the plain weighted sum.
    if k > 0 {
        let mut s = 0u128;
        for j in 0..k {
            s += m(x[n - k + j], c[j]);
        }
        rh = (s >> 64) as u64;
        rl = s as u64;
    }
    let mut i = n - k;
    while i >= 4 {
        i -= 4;
        let s = u128::from(x[i])
            + m(x[i + 1], c[1])
            + m(x[i + 2], c[2])
            + m(x[i + 3], c[3])
            + m(rl, c[4])
            + m(rh, c[5]);
        rh = (s >> 64) as u64;
        rl = s as u64;
    }
    ((m(rh, c[1]) + u128::from(rl)) % dd) as u64
}

/// The reciprocal `floor((2^128 - 1) / d) - 2^64` of a normalised divisor (`d >= 2^63`).
#[inline]
fn reciprocal(d: u64) -> u64 {
    debug_assert!(d >> 63 == 1);
    (u128::MAX / u128::from(d) - (1u128 << 64)) as u64
}

/// Möller–Granlund Algorithm 4: `(<u1, u0> div d, <u1, u0> mod d)` for a normalised `d` with
/// reciprocal `v` and `u1 < d`.
#[inline]
fn div_2by1(u1: u64, u0: u64, d: u64, v: u64) -> (u64, u64) {
    let q = (u128::from(v) * u128::from(u1)).wrapping_add(u128::from(u1) << 64 | u128::from(u0));
    let mut q1 = ((q >> 64) as u64).wrapping_add(1);
    let q0 = q as u64;
    let mut r = u0.wrapping_sub(q1.wrapping_mul(d));
    if r > q0 {
        q1 = q1.wrapping_sub(1);
        r = r.wrapping_add(d);
    }
    if r >= d {
        q1 = q1.wrapping_add(1);
        r -= d;
    }
    (q1, r)
}

/// `x mod d` for any `d >= 2` by division with a precomputed reciprocal, one limb per step:
/// the stream `x 2^s` is divided by the normalised `d 2^s` and the remainder shifted back.
fn rem_1_preinv(x: &[u64], d: u64) -> u64 {
    let s = d.leading_zeros();
    let dn = d << s;
    let v = reciprocal(dn);
    let n = x.len();
    if n == 0 {
        return 0;
    }
    if s == 0 {
        let mut r = 0u64;
        for &w in x.iter().rev() {
            r = div_2by1(r, w, dn, v).1;
        }
        return r;
    }
    // r starts as the s bits shifted out of the top limb (< 2^s <= 2^63 <= dn).
    let mut r = x[n - 1] >> (64 - s);
    for i in (0..n).rev() {
        let lo = if i > 0 { x[i - 1] >> (64 - s) } else { 0 };
        r = div_2by1(r, x[i] << s | lo, dn, v).1;
    }
    r >> s
}

/// The inverse of an odd `d` modulo `2^64` (Newton's iteration, doubling the correct bits from
/// the 3 that `d` itself gives).
#[inline]
fn inverse_mod_2_64(d: u64) -> u64 {
    debug_assert!(d & 1 == 1);
    let mut inv = d;
    for _ in 0..5 {
        inv = inv.wrapping_mul(2u64.wrapping_sub(d.wrapping_mul(inv)));
    }
    inv
}

/// `x / d` when `d` divides `x` exactly (`d != 0`), by Jebelean's exact division (see the
/// module documentation); the result has no leading zero limbs. The result is meaningless
/// (but the call is safe) when `d` does not divide `x`.
///
/// # Panics
/// If `d == 0`.
pub fn divexact_1(x: &[u64], d: u64) -> Vec<u64> {
    assert!(d != 0, "divexact_1: division by zero");
    let s = d.trailing_zeros();
    let odd = d >> s;
    let inv = inverse_mod_2_64(odd);
    let n = x.len();
    let mut out = Vec::with_capacity(n);
    let mut c = 0u64;
    for i in 0..n {
        let y = if s == 0 {
            x[i]
        } else {
            let next = if i + 1 < n { x[i + 1] << (64 - s) } else { 0 };
            x[i] >> s | next
        };
        let (l, borrow) = y.overflowing_sub(c);
        let q = l.wrapping_mul(inv);
        out.push(q);
        c = ((u128::from(q) * u128::from(odd)) >> 64) as u64 + u64::from(borrow);
    }
    trim(&mut out);
    out
}

/// `x * m` (no leading zero limbs).
pub fn mul_1(x: &[u64], m: u64) -> Vec<u64> {
    let mut out = Vec::with_capacity(x.len() + 1);
    let mut carry = 0u64;
    for &w in x {
        let p = u128::from(w) * u128::from(m) + u128::from(carry);
        out.push(p as u64);
        carry = (p >> 64) as u64;
    }
    out.push(carry);
    trim(&mut out);
    out
}

/// The signed linear combination `(-1)^an A m1 + (-1)^bn B m2` of two numbers given by limbs,
/// as `(magnitude limbs without leading zeros, negative)`; zero is `(vec![], false)`.
pub fn lin_comb(a: &[u64], an: bool, m1: u64, b: &[u64], bn: bool, m2: u64) -> (Vec<u64>, bool) {
    let n = a.len().max(b.len());
    let limb = |x: &[u64], i: usize| x.get(i).copied().unwrap_or(0);
    let mut out = Vec::with_capacity(n + 3);
    if an == bn {
        // Magnitudes add. Carry < 2^66: the high halves of two products plus a small carry.
        let mut carry = 0u128;
        for i in 0..n {
            let p = u128::from(limb(a, i)) * u128::from(m1);
            let q = u128::from(limb(b, i)) * u128::from(m2);
            let lo = u128::from(p as u64) + u128::from(q as u64) + carry;
            out.push(lo as u64);
            carry = (p >> 64) + (q >> 64) + (lo >> 64);
        }
        out.push(carry as u64);
        out.push((carry >> 64) as u64);
        trim(&mut out);
        let negative = an && !out.is_empty();
        return (out, negative);
    }
    // Magnitudes subtract: D = A m1 - B m2 with a signed carry (|carry| < 2^65).
    let mut carry = 0i128;
    for i in 0..n {
        let p = u128::from(limb(a, i)) * u128::from(m1);
        let q = u128::from(limb(b, i)) * u128::from(m2);
        let lo = i128::from(p as u64) - i128::from(q as u64) + carry;
        out.push(lo as u64);
        carry = (p >> 64) as i128 - (q >> 64) as i128 + (lo >> 64);
    }
    // The carry as two two's-complement limbs: D = out + carry 2^(64 n) exactly.
    out.push(carry as u64);
    out.push((carry >> 64) as u64);
    let d_negative = carry < 0;
    if d_negative {
        // |D| = -D: two's complement of the (n + 2)-limb representation.
        let mut add = true;
        for w in out.iter_mut() {
            let (v, o) = (!*w).overflowing_add(u64::from(add));
            *w = v;
            add = o;
        }
    }
    trim(&mut out);
    // The sign of the result: an when A m1 dominates (D > 0), bn when B m2 does.
    let negative = !out.is_empty() && if d_negative { bn } else { an };
    (out, negative)
}

/// Removes leading (most significant) zero limbs.
#[inline]
pub fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// The [`BigUint`] with the given limbs (least significant first).
pub fn biguint_from_limbs(limbs: &[u64]) -> BigUint {
    let mut digits = Vec::with_capacity(2 * limbs.len());
    for &w in limbs {
        digits.push(w as u32);
        digits.push((w >> 32) as u32);
    }
    BigUint::new(digits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;
    use num_bigint::BigInt;
    use num_traits::Zero;
    use proptest::prelude::*;

    fn limbs(x: &BigUint) -> Vec<u64> {
        x.to_u64_digits()
    }

    fn arb_limbs(max: usize) -> impl Strategy<Value = Vec<u64>> {
        prop::collection::vec(any::<u64>(), 0..max)
    }

    /// Divisors of every size: random u64 shifted right by 0..63 bits, never zero.
    fn arb_divisor() -> impl Strategy<Value = u64> {
        (any::<u64>(), 0u32..64).prop_map(|(d, s)| (d >> s).max(1))
    }

    fn signed(mag: &[u64], neg: bool) -> BigInt {
        let m = BigInt::from(biguint_from_limbs(mag));
        if neg {
            -m
        } else {
            m
        }
    }

    proptest! {
        #[test]
        fn prop_rem_1(x in arb_limbs(30), d in arb_divisor()) {
            let big = biguint_from_limbs(&x);
            let expected = &big % BigUint::from(d);
            prop_assert_eq!(BigUint::from(rem_1(&x, d)), expected.clone());
            // Both methods on every divisor below the folding bound.
            if d >= 2 && d < FOLD_MAX {
                prop_assert_eq!(BigUint::from(rem_1_preinv(&x, d)), expected);
            }
        }

        #[test]
        fn prop_divexact_1(q in arb_limbs(30), d in arb_divisor()) {
            let x = biguint_from_limbs(&q) * BigUint::from(d);
            let got = divexact_1(&limbs(&x), d);
            prop_assert_eq!(biguint_from_limbs(&got), &x / BigUint::from(d));
            prop_assert!(got.last() != Some(&0));
        }

        #[test]
        fn prop_mul_1(x in arb_limbs(30), m in any::<u64>()) {
            let got = mul_1(&x, m);
            prop_assert_eq!(biguint_from_limbs(&got), biguint_from_limbs(&x) * BigUint::from(m));
            prop_assert!(got.last() != Some(&0));
        }

        #[test]
        fn prop_lin_comb(
            a in arb_limbs(20), an in any::<bool>(), m1 in any::<u64>(),
            b in arb_limbs(20), bn in any::<bool>(), m2 in any::<u64>(), s in 0u32..64
        ) {
            let (m1, m2) = (m1 >> s, m2);
            let expected = signed(&a, an) * BigInt::from(m1) + signed(&b, bn) * BigInt::from(m2);
            let (mag, neg) = lin_comb(&a, an, m1, &b, bn, m2);
            prop_assert!(mag.last() != Some(&0));
            prop_assert!(!(mag.is_empty() && neg));
            prop_assert_eq!(signed(&mag, neg), expected);
        }

        #[test]
        fn prop_lin_comb_cancelling(a in arb_limbs(20), an in any::<bool>(), m in 1u64..u64::MAX, d in arb_limbs(3)) {
            // A m - (A m + small) m / m style near-cancellation: B = A (same multiplier) +- d.
            let b: Vec<u64> = limbs(&(biguint_from_limbs(&a) + biguint_from_limbs(&d)));
            let expected = signed(&a, an) * BigInt::from(m) + signed(&b, !an) * BigInt::from(m);
            let (mag, neg) = lin_comb(&a, an, m, &b, !an, m);
            prop_assert_eq!(signed(&mag, neg), expected);
        }
    }

    #[test]
    fn fixed_cases() {
        assert_eq!(rem_1(&[], 7), 0);
        assert_eq!(rem_1(&[5], 1), 0);
        assert_eq!(rem_1(&[u64::MAX; 9], u64::MAX), 0);
        assert_eq!(rem_1(&[u64::MAX; 9], (1 << 61) - 1), rem_1_preinv(&[u64::MAX; 9], (1 << 61) - 1));
        assert_eq!(divexact_1(&[], 3), Vec::<u64>::new());
        assert_eq!(divexact_1(&[0, 1], 1 << 63), vec![2]);
        assert_eq!(mul_1(&[1, 2], 0), Vec::<u64>::new());
        assert_eq!(lin_comb(&[3], false, 2, &[6], true, 1), (vec![], false));
        assert_eq!(lin_comb(&[3], false, 2, &[7], true, 1), (vec![1], true));
        assert_eq!(lin_comb(&[], true, 2, &[], true, 1), (vec![], false));
    }

    #[test]
    fn large_operands() {
        // 10^5-limb operands (6.4 million bits) against num-bigint.
        let mut st = Rng::new(99);
        let x: Vec<u64> = (0..100_000).map(|_| st.next_u64()).collect();
        let big = biguint_from_limbs(&x);
        for d in [3u64, 1_000_000_007, (1 << 61) - 1, (1 << 61) + 1, u64::MAX, 1 << 40] {
            assert_eq!(BigUint::from(rem_1(&x, d)), &big % BigUint::from(d), "d = {d}");
            let prod = &big * BigUint::from(d);
            assert_eq!(biguint_from_limbs(&divexact_1(&limbs(&prod), d)), big);
        }
        assert!(!big.is_zero());
    }
}
