//! Property tests of the fast `Rational` against num-rational's `BigRational` (the independent
//! reference): every operation agrees and leaves a canonical value; the field laws hold. The
//! generator covers both tiers and the boundary between them (values near 2^127).

use exactcheck_core::{Field, OrderedField, Ring, Sign};
use exactcheck_exact::{PlainRational, Rational, RationalScalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

/// Integers of assorted sizes: tiny, word-sized, near the inline limit, and multi-limb.
fn int() -> impl Strategy<Value = BigInt> {
    prop_oneof![
        (-20i64..20).prop_map(BigInt::from),
        any::<i64>().prop_map(BigInt::from),
        any::<i128>().prop_map(BigInt::from),
        (any::<i128>(), -3i32..3).prop_map(|(x, k)| (BigInt::from(1) << 127) * k + x),
        proptest::collection::vec(any::<u32>(), 1..12).prop_map(|d| {
            BigInt::from_slice(num_bigint::Sign::Plus, &d) * if d[0] & 1 == 0 { 1 } else { -1 }
        }),
    ]
}

fn nonzero_int() -> impl Strategy<Value = BigInt> {
    int().prop_map(|x| if x.is_zero() { BigInt::from(7) } else { x })
}

/// Rationals with shared factors between numerators and denominators, so cancellations happen.
fn big_rational() -> impl Strategy<Value = BigRational> {
    (
        int(),
        nonzero_int(),
        prop_oneof![Just(1i64), 2i64..50, any::<i64>()],
    )
        .prop_map(|(n, d, k)| {
            let k = BigInt::from(if k == 0 { 1 } else { k });
            BigRational::new(n * &k, d * k)
        })
}

fn rational() -> impl Strategy<Value = (Rational, BigRational)> {
    big_rational().prop_map(|b| (Rational::from(&b), b))
}

fn check(r: &Rational, b: &BigRational) -> Result<(), TestCaseError> {
    prop_assert!(r.is_canonical(), "not canonical: {r:?}");
    prop_assert_eq!(&r.to_big_rational(), b);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn operations_match_big_rational((x, bx) in rational(), (y, by) in rational()) {
        check(&x, &bx)?;
        check(&(&x + &y), &(&bx + &by))?;
        check(&(&x - &y), &(&bx - &by))?;
        check(&(&x * &y), &(&bx * &by))?;
        check(&x.square(), &(&bx * &bx))?;
        check(&-&x, &-&bx)?;
        if by.is_zero() {
            prop_assert!(x.checked_div(&y).is_err());
        } else {
            check(&(&x / &y), &(&bx / &by))?;
        }
        prop_assert_eq!(x.cmp(&y), bx.cmp(&by));
        prop_assert_eq!(x == y, bx == by);
        let expected_sign = if bx.is_positive() { Sign::Positive } else if bx.is_negative() { Sign::Negative } else { Sign::Zero };
        prop_assert_eq!(x.sign(), expected_sign);
    }

    #[test]
    fn assign_operators_match((x, bx) in rational(), (y, by) in rational()) {
        let mut s = x.clone(); s += &y; check(&s, &(&bx + &by))?;
        let mut d = x.clone(); d -= y.clone(); check(&d, &(&bx - &by))?;
        let mut m = x.clone(); m *= &y; check(&m, &(&bx * &by))?;
    }

    #[test]
    fn field_laws((x, _) in rational(), (y, _) in rational(), (z, _) in rational()) {
        prop_assert_eq!((&x + &y) + &z, &x + (&y + &z));
        prop_assert_eq!((&x * &y) * &z, &x * (&y * &z));
        prop_assert_eq!(&x + &y, &y + &x);
        prop_assert_eq!(&x * &y, &y * &x);
        prop_assert_eq!(&x * (&y + &z), &x * &y + &x * &z);
        prop_assert_eq!(&x - &x, Rational::zero());
        prop_assert_eq!(&x + Rational::zero(), x.clone());
        prop_assert_eq!(&x * Rational::one(), x.clone());
        if !x.is_zero() {
            prop_assert_eq!(&x * x.inv().unwrap(), Rational::one());
        } else {
            prop_assert!(x.inv().is_err());
        }
    }

    #[test]
    fn text_round_trip((x, _) in rational()) {
        let back: Rational = x.to_string().parse().unwrap();
        prop_assert_eq!(back, x);
    }

    #[test]
    fn plain_rational_agrees((x, bx) in rational(), (y, by) in rational()) {
        let (px, py) = (PlainRational(bx), PlainRational(by));
        let fast = (&x * &y + &x - &y).to_big_rational();
        let plain = (px.clone() * &py + &px - &py).to_big_rational();
        prop_assert_eq!(fast, plain);
        prop_assert_eq!(Rational::from_big_rational(&px.to_big_rational()), x);
    }
}

/// Big rationals only: multi-limb numerators and denominators with shared factors (the paths of
/// `add_big`/`mul_big` and the direct subtraction), and, with `mixed`, one inline operand.
fn multi_limb() -> impl Strategy<Value = BigRational> {
    let limbs = || proptest::collection::vec(any::<u32>(), 5..12);
    (limbs(), limbs(), any::<bool>(), 1u64..1 << 40).prop_map(|(n, d, neg, k)| {
        let sign = if neg {
            num_bigint::Sign::Minus
        } else {
            num_bigint::Sign::Plus
        };
        let n = BigInt::from_slice(sign, &n) * k;
        let d = BigInt::from_slice(num_bigint::Sign::Plus, &d) * k + 1;
        BigRational::new(n, d)
    })
}

fn fast_and_plain(b: &BigRational) -> (Rational, PlainRational) {
    (Rational::from(b), PlainRational(b.clone()))
}

/// The fast result is canonical and equals the plain one.
fn same(fast: &Rational, plain: &PlainRational) -> Result<(), TestCaseError> {
    prop_assert!(fast.is_canonical(), "not canonical: {fast:?}");
    prop_assert_eq!(fast.to_big_rational(), plain.to_big_rational());
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Subtraction and multiplication in every operand form, on big and mixed-tier inputs,
    /// against `PlainRational`: `x - y` is computed directly (no negated copy of `y`) and
    /// `mul_big` multiplies borrowed magnitudes, so each form must still give canonical values.
    #[test]
    fn big_sub_and_mul_match_plain(
        bx in multi_limb(),
        by in multi_limb(),
        small in any::<i64>(),
        shared in any::<bool>(),
    ) {
        // With `shared`, y has x's denominator (the equal-denominator path of add_big).
        let by = if shared { BigRational::new(by.numer().clone(), bx.denom().clone()) } else { by };
        let (x, px) = fast_and_plain(&bx);
        let (y, py) = fast_and_plain(&by);
        let (z, pz) = fast_and_plain(&BigRational::from_integer(BigInt::from(small)));
        for (a, pa, b, pb) in [(&x, &px, &y, &py), (&x, &px, &z, &pz), (&z, &pz, &x, &px), (&x, &px, &x, &px)] {
            same(&(a - b), &(pa.clone() - pb))?;
            same(&(a.clone() - b), &(pa.clone() - pb))?;
            same(&(a.clone() - b.clone()), &(pa.clone() - pb))?;
            same(&(a * b), &(pa.clone() * pb))?;
            same(&(a.clone() * b.clone()), &(pa.clone() * pb))?;
            same(&a.sub_ref(b), &(pa.clone() - pb))?;
            let mut d = a.clone();
            d -= b;
            same(&d, &(pa.clone() - pb))?;
            let mut m = a.clone();
            m *= b.clone();
            same(&m, &(pa.clone() * pb))?;
        }
        prop_assert!((&x - &x).is_zero());
        prop_assert_eq!(&(&x - &y) + &y, x.clone());
    }
}

#[test]
fn big_products_cancel_crossed_factors() {
    // (p/q) * (q/p) with multi-limb coprime p, q: both crossed gcds are the whole operands.
    let p: BigInt = (BigInt::from(1) << 200) + 1;
    let q: BigInt = (BigInt::from(1) << 199) - 1;
    let x = Rational::from(&BigRational::new(p.clone(), q.clone()));
    let y = Rational::from(&BigRational::new(q, p));
    let one = &x * &y;
    assert!(one.is_inline() && one == Rational::one());
    // and a product with gcds of one keeps every factor.
    let z = Rational::from(&BigRational::new(
        BigInt::from(3),
        (BigInt::from(1) << 130) + 7,
    ));
    let xz = &x * &z;
    assert!(xz.is_canonical());
    assert_eq!(
        xz.to_big_rational(),
        x.to_big_rational() * z.to_big_rational()
    );
}

#[test]
fn tier_boundary() {
    // 2^127 - 1 is the largest inline magnitude; one more goes to the big tier and back.
    let max = Rational::from_i128_ratio(i128::MAX, 1).unwrap();
    assert!(max.is_inline());
    let over = &max + Rational::one();
    assert!(!over.is_inline() && over.is_canonical());
    let back = &over - Rational::one();
    assert!(back.is_inline());
    assert_eq!(back, max);
    let neg = -&over;
    assert!(!neg.is_inline() && neg.is_canonical());
}

/// Dyadic rationals `m 2^e` as doubles produce them (53-bit mantissas, exponents far below and
/// above zero) and wider ones, whose products overflow the inline tier.
fn dyadic() -> impl Strategy<Value = BigRational> {
    (
        prop_oneof![
            (-(1i64 << 53)..(1i64 << 53)).prop_map(BigInt::from),
            any::<i128>().prop_map(BigInt::from),
        ],
        -300i32..300,
    )
        .prop_map(|(m, e)| {
            let p = BigInt::from(1) << e.unsigned_abs();
            if e < 0 {
                BigRational::new(m, p)
            } else {
                BigRational::from_integer(m * p)
            }
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Sums, products and quotients of dyadic values (gcds against powers of two, products
    /// formed wide) against num-rational, and the regress throughput formula
    /// `((x + y)(z - w) - x z / (y + 2))(w + 1) + x y` on them.
    #[test]
    fn dyadic_operations_match_big_rational(
        bx in dyadic(), by in dyadic(), bz in dyadic(), bw in dyadic()
    ) {
        let [x, y, z, w] = [&bx, &by, &bz, &bw].map(Rational::from);
        check(&(&x + &y), &(&bx + &by))?;
        check(&(&x - &y), &(&bx - &by))?;
        check(&(&x * &y), &(&bx * &by))?;
        if !by.is_zero() {
            check(&(&x / &y), &(&bx / &by))?;
        }
        let two = Rational::from_integer(2);
        let b2 = BigRational::from_integer(BigInt::from(2));
        if !(&by + &b2).is_zero() {
            let f = &(&(&(&(&x + &y) * &(&z - &w)) - &(&(&x * &z) / &(&y + &two))) * &(&w + &Rational::ONE)) + &(&x * &y);
            let bf = (((&bx + &by) * (&bz - &bw)) - (&bx * &bz) / (&by + &b2)) * (&bw + BigRational::from_integer(BigInt::from(1))) + &bx * &by;
            check(&f, &bf)?;
        }
    }
}
