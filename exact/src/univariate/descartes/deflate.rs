//! The polynomial that the rational-root candidates are tested against, with the roots found
//! so far divided out (the parent module's documentation, "Rational roots"), and the exact test
//! that a linear factor `q x - p` divides it.
//!
//! While every coefficient fits in an `i128` (Wilkinson's product of degree 20 has 96-bit
//! coefficients, and deflation shrinks them) the polynomial is kept as `i128`s and divided by
//! synthetic division in the ring `Z / 2^128`: one wrapping multiply-add and one
//! multiplication by the inverse of the odd one of `q`, `p` per coefficient, instead of a
//! carry chain and a Hensel division over the limbs of the Mignotte width. **Certificate**
//! (as for [`Limbs::divide_by_linear`], with the headroom taken from the sizes of `p` and `q`
//! instead of the word size): the ring division gives `s` with `(q x - p) s = a` modulo
//! `2^128`; when every `|s_k| < 2^(126 - P)`, `2^P` above `|p|` and `q`, both sides of every
//! coefficient's congruence lie in `[-2^127, 2^127)` (`|q s_(k-1) - p s_k| < 2^127`, and the
//! coefficients `a_k` are `i128`s), so they are equal over `Z`. A non-zero remainder refutes
//! the factor outright (a true quotient satisfies the same recurrence, whose every step is
//! forced by the invertible divisor, so its remainder vanishes modulo `2^128` too). Only a
//! vanishing remainder with a quotient too large for the certificate is undecided, and then the
//! division is repeated on limbs of the Mignotte width, which decides every case.
//!
//! Hand-written: the kernel is a few wrapping multiplications, which no bignum crate offers as
//! a fixed-width ring division.

use super::*;

/// The deflated polynomial, constant term first.
#[derive(Clone, Debug)]
pub(super) enum Deflated {
    /// Every coefficient is this `i128` (`a`); `spare` is the buffer of the next quotient.
    Narrow { a: Vec<i128>, spare: Vec<i128> },
    /// On fixed-width limbs ([`Limbs::divide_by_linear`]).
    Wide(Limbs),
}

/// What the division in `Z / 2^128` decided ([`divide_narrow`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum NarrowDivision {
    /// `q x - p` divides the polynomial, with this quotient (certified).
    Quotient(Vec<i128>),
    /// `q x - p` does not divide the polynomial.
    NotAFactor,
    /// The remainder vanishes modulo `2^128` but the quotient is too large to certify it.
    Undecided,
}

/// The inverse of an odd `d` modulo `2^128` (one Newton step from the inverse modulo `2^64`).
fn inverse_mod_2_128(d: u128) -> u128 {
    debug_assert!(d & 1 == 1);
    let inv = u128::from(crate::bigint::inverse_mod_2_64(d as u64));
    inv.wrapping_mul(2u128.wrapping_sub(d.wrapping_mul(inv)))
}

/// Synthetic division of `a` (degree `n >= 1`, constant term first) by `q x - p` (`q > 0`,
/// `p != 0`, coprime) in the ring `Z / 2^128` (module documentation), the quotient written to
/// the buffer `s` (its contents dropped; no allocation once it has room): from the top by `q`
/// when it is odd (`s_(n-1) = a_n / q`, `s_(k-1) = (a_k + p s_k) / q`, then `a_0 + p s_0 = 0`
/// checked), else from the bottom by `-p` (`s_0 = -a_0 / p`, `s_k = (q s_(k-1) - a_k) / p`, then
/// `q s_(n-1) = a_n` checked), as [`Limbs::divide_by_linear`] does on limbs.
pub(super) fn divide_narrow(a: &[i128], p: i64, q: i64, mut s: Vec<i128>) -> NarrowDivision {
    assert!(
        q > 0 && p != 0 && a.len() >= 2,
        "divide_narrow: q > 0, p != 0, degree >= 1"
    );
    let n = a.len() - 1;
    let (pw, qw) = (p as i128 as u128, q as u128);
    s.clear();
    s.resize(n, 0);
    if q & 1 == 1 {
        let inv = inverse_mod_2_128(qw);
        let mut acc = 0u128;
        for k in (1..=n).rev() {
            acc = (a[k] as u128)
                .wrapping_add(pw.wrapping_mul(acc))
                .wrapping_mul(inv);
            s[k - 1] = acc as i128;
        }
        if (a[0] as u128).wrapping_add(pw.wrapping_mul(acc)) != 0 {
            return NarrowDivision::NotAFactor;
        }
    } else {
        debug_assert!(p & 1 == 1, "p and q are coprime");
        let inv = inverse_mod_2_128(pw);
        let mut acc = 0u128;
        for (k, sk) in s.iter_mut().enumerate() {
            acc = qw
                .wrapping_mul(acc)
                .wrapping_sub(a[k] as u128)
                .wrapping_mul(inv);
            *sk = acc as i128;
        }
        if qw.wrapping_mul(acc) != a[n] as u128 {
            return NarrowDivision::NotAFactor;
        }
    }
    // |p|, q < 2^P; every |s_k| < 2^(126 - P) certifies the congruence as an equality.
    let pbits = 64 - p.unsigned_abs().max(q as u64).leading_zeros();
    let limit = 1u128 << (126 - pbits);
    if s.iter().all(|x| x.unsigned_abs() < limit) {
        NarrowDivision::Quotient(s)
    } else {
        NarrowDivision::Undecided
    }
}

/// `x` as an `i128` when it fits (from its two lowest magnitude digits).
fn i128_of(x: &BigInt) -> Option<i128> {
    if x.bits() > 127 {
        return None;
    }
    let mut digits = x.magnitude().iter_u64_digits();
    let lo = u128::from(digits.next().unwrap_or(0));
    let hi = u128::from(digits.next().unwrap_or(0));
    let m = ((hi << 64) | lo) as i128;
    Some(if x.is_negative() { -m } else { m })
}

impl Deflated {
    fn narrow(a: Vec<i128>) -> Deflated {
        let spare = Vec::with_capacity(a.len());
        Deflated::Narrow { a, spare }
    }

    /// `a` as `i128`s when every coefficient fits, else on `w` limbs (`w` at least
    /// [`super::super::limbs::linear_factor_width`]`(a)`).
    pub(super) fn new(a: &[BigInt], w: usize) -> Deflated {
        match a.iter().map(i128_of).collect() {
            Some(narrow) => Deflated::narrow(narrow),
            None => Deflated::Wide(Limbs::from_bigints_width(a, w)),
        }
    }

    /// The number of coefficients.
    pub(super) fn len(&self) -> usize {
        match self {
            Deflated::Narrow { a, .. } => a.len(),
            Deflated::Wide(l) => l.len(),
        }
    }

    /// Divides by `q x - p` in place when it is a factor (`q > 0`, `p != 0`, coprime; degree
    /// at least 1) and says whether it was. `w` is the limb width of the wide division, at least
    /// [`super::super::limbs::linear_factor_width`] of the original polynomial (whose factors
    /// are the deflated one's), so no factor is missed.
    pub(super) fn divide(&mut self, p: i64, q: i64, w: usize) -> bool {
        let wide = match self {
            Deflated::Narrow { a, spare } => match divide_narrow(a, p, q, std::mem::take(spare)) {
                NarrowDivision::Quotient(s) => {
                    *spare = std::mem::replace(a, s);
                    return true;
                }
                NarrowDivision::NotAFactor => return false,
                NarrowDivision::Undecided => Limbs::from_i128s(a, w.max(2)),
            },
            Deflated::Wide(l) => std::mem::replace(l, Limbs::from_i128s(&[], 2)),
        };
        let quotient = wide.divide_by_linear(p, q);
        *self = match &quotient {
            Some(s) => match s.to_i128s() {
                Some(narrow) => Deflated::narrow(narrow),
                None => Deflated::Wide(s.clone()),
            },
            None => match wide.to_i128s() {
                Some(narrow) => Deflated::narrow(narrow),
                None => Deflated::Wide(wide),
            },
        };
        quotient.is_some()
    }

    /// The coefficients as `BigInt`s (for the tests).
    #[cfg(test)]
    pub(super) fn to_bigints(&self) -> Vec<BigInt> {
        match self {
            Deflated::Narrow { a, .. } => a.iter().map(|&x| BigInt::from(x)).collect(),
            Deflated::Wide(l) => l.to_bigints(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;
    use proptest::prelude::*;

    /// `(q x - p) g`.
    fn times_linear(g: &[BigInt], p: i64, q: i64) -> Vec<BigInt> {
        let mut a = vec![BigInt::zero(); g.len() + 1];
        for (i, c) in g.iter().enumerate() {
            a[i + 1] += c * q;
            a[i] -= c * p;
        }
        a
    }

    fn narrow(a: &[BigInt]) -> Option<Vec<i128>> {
        a.iter().map(ToPrimitive::to_i128).collect()
    }

    #[test]
    fn inverse_mod_2_128_inverts() {
        for d in [
            1u128,
            3,
            5,
            0xffff_ffff_ffff_ffff,
            (1 << 127) + 1,
            u128::MAX,
        ] {
            assert_eq!(d.wrapping_mul(inverse_mod_2_128(d)), 1, "{d}");
        }
    }

    #[test]
    fn i128_of_matches_to_i128_below_2_127() {
        let one = BigInt::one();
        for x in [
            BigInt::zero(),
            BigInt::from(-1),
            BigInt::from(u64::MAX),
            -BigInt::from(u64::MAX),
            (&one << 126u32) + BigInt::from(3),
            -(&one << 126u32),
            (&one << 127u32) - BigInt::one(),
            -((&one << 127u32) - BigInt::one()),
        ] {
            let x: BigInt = x;
            assert_eq!(i128_of(&x), x.to_i128(), "{x}");
        }
        // i128::MIN itself and everything wider are refused (127 bits and more).
        assert_eq!(i128_of(&-(&one << 127u32)), None);
        assert_eq!(i128_of(&(&one << 127u32)), None);
    }

    #[test]
    fn i128_limbs_round_trip() {
        let v = [0i128, 1, -1, i128::MAX, i128::MIN, 1 << 64, -(1 << 64) - 5];
        for w in [2usize, 3, 5] {
            let l = Limbs::from_i128s(&v, w);
            assert_eq!(l.to_i128s().expect("fits"), v.to_vec());
            let big: Vec<BigInt> = v.iter().map(|&x| BigInt::from(x)).collect();
            assert_eq!(l.to_bigints(), big);
        }
        let wide = Limbs::from_bigints(&[BigInt::one() << 127u32]);
        assert_eq!(wide.to_i128s(), None);
        let word = Limbs::from_bigints(&[BigInt::from(-7)]);
        assert_eq!(word.to_i128s(), Some(vec![-7]));
    }

    #[test]
    fn a_quotient_too_large_is_undecided_and_decided_on_limbs() {
        // (3 x - 1) g with a coefficient of g near 2^125: the remainder vanishes modulo 2^128
        // but the quotient leaves the certificate's range; the limbs decide.
        let g = vec![BigInt::one() << 124u32, BigInt::from(5)];
        let a = times_linear(&g, 1, 3);
        let na = narrow(&a).expect("fits");
        assert_eq!(
            divide_narrow(&na, 1, 3, Vec::new()),
            NarrowDivision::Undecided
        );
        let w = super::super::super::limbs::linear_factor_width(&a);
        let mut d = Deflated::new(&a, w);
        assert!(matches!(d, Deflated::Narrow { .. }));
        assert!(d.divide(1, 3, w));
        assert_eq!(d.to_bigints(), g);
        assert!(matches!(d, Deflated::Narrow { .. }));
        // A polynomial past i128 starts wide and turns narrow once its quotient fits.
        let g: Vec<BigInt> = vec![BigInt::from(7), BigInt::from(-3), BigInt::one()];
        let a = times_linear(&times_linear(&g, 1 << 40, 1), -(1 << 50), 1);
        let mut a2 = a.clone();
        a2.iter_mut().for_each(|c| *c *= BigInt::one() << 40u32);
        let w = super::super::super::limbs::linear_factor_width(&a2);
        let mut d = Deflated::new(&a2, w);
        assert!(matches!(d, Deflated::Wide(_)));
        assert!(!d.divide(3, 1, w));
        assert!(d.divide(-(1 << 50), 1, w));
        assert!(matches!(d, Deflated::Narrow { .. }));
        assert!(d.divide(1 << 40, 1, w));
        let expected: Vec<BigInt> = g.iter().map(|c| c << 40u32).collect();
        assert_eq!(d.to_bigints(), expected);
        assert_eq!(d.len(), 3);
    }

    /// Random `g` (coefficients up to about 120 bits) and linear factors with words of every
    /// size: the `i128` division agrees with the `BigInt` reference ([`divide_by_linear_factor`])
    /// on true factors and on other candidates, and the deflated polynomial with the limb path
    /// behind it always does.
    #[test]
    fn narrow_division_agrees_with_the_bigint_reference() {
        let mut rng = Rng::new(3303);
        for round in 0..600 {
            let bits = [3u32, 40, 64, 100, 120][round % 5];
            let Some((g, p, q)) =
                super::super::tests::random_linear_factor_case(&mut rng, 14, bits, 40)
            else {
                continue;
            };
            let a = times_linear(&g, p, q);
            let w = super::super::super::limbs::linear_factor_width(&a);
            for (p2, q2) in [(p, q), (p + 1, q), (p, q + 2), (p + q, q), (1, 1), (-1, 2)] {
                if p2 == 0 || q2 <= 0 || num_integer::Integer::gcd(&p2, &q2) != 1 {
                    continue;
                }
                let expected = divide_by_linear_factor(&a, p2, q2);
                if let Some(na) = narrow(&a) {
                    match divide_narrow(&na, p2, q2, vec![7; 3]) {
                        NarrowDivision::Quotient(s) => {
                            let s: Vec<BigInt> = s.into_iter().map(BigInt::from).collect();
                            assert_eq!(Some(s), expected, "round {round}: ({q2} x - {p2})");
                        }
                        NarrowDivision::NotAFactor => {
                            assert_eq!(expected, None, "round {round}: ({q2} x - {p2})");
                        }
                        NarrowDivision::Undecided => {}
                    }
                }
                let mut d = Deflated::new(&a, w);
                let divided = d.divide(p2, q2, w);
                assert_eq!(
                    divided,
                    expected.is_some(),
                    "round {round}: ({q2} x - {p2})"
                );
                let after = if divided {
                    expected.expect("divided")
                } else {
                    a.clone()
                };
                assert_eq!(d.to_bigints(), after, "round {round}: ({q2} x - {p2})");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]
        /// Products of small linear factors and a random cofactor: every factor divides out,
        /// a decoy `p / (61 q)` (no factor's root) only when the reference says so, and the
        /// deflated polynomial is the reference quotient at every step.
        #[test]
        fn deflation_by_true_factors_matches_the_reference(
            roots in proptest::collection::vec((-60i64..=60, 1i64..=60), 1..8),
            rest in proptest::collection::vec(-(1i64 << 40)..=(1i64 << 40), 1..6),
        ) {
            let mut factors: Vec<(i64, i64)> = Vec::new();
            for (p, q) in roots {
                let g = num_integer::Integer::gcd(&p, &q);
                if p != 0 && !factors.contains(&(p / g, q / g)) {
                    factors.push((p / g, q / g));
                }
            }
            let mut rest: Vec<BigInt> = rest.into_iter().map(BigInt::from).collect();
            if rest.last().is_some_and(Zero::is_zero) {
                *rest.last_mut().expect("non-empty") = BigInt::one();
            }
            let mut a = rest;
            for &(p, q) in &factors {
                a = times_linear(&a, p, q);
            }
            let w = super::super::super::limbs::linear_factor_width(&a);
            let mut d = Deflated::new(&a, w);
            let mut reference = a.clone();
            for &(p, q) in factors.iter().rev() {
                let expected = divide_by_linear_factor(&reference, p, 61 * q);
                prop_assert_eq!(d.divide(p, 61 * q, w), expected.is_some());
                if let Some(s) = expected {
                    reference = s;
                }
                let s = divide_by_linear_factor(&reference, p, q).expect("a true factor");
                prop_assert!(d.divide(p, q, w));
                reference = s;
                prop_assert_eq!(d.to_bigints(), reference.clone());
            }
        }
    }
}
