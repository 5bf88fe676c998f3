use super::*;
use crate::Radical;
use exactcheck_core::OrderedField;
use num_bigint::BigInt;
use proptest::prelude::*;

fn alg(s: &str) -> Algebraic {
    s.parse().unwrap_or_else(|e| panic!("{s}: {e}"))
}

fn upoly(c: &[i64]) -> UPoly {
    UPoly::from_i64_coeffs(c)
}

fn sqrt_int(n: i64) -> Algebraic {
    Algebraic::from_integer(n).sqrt().expect("non-negative")
}

#[test]
fn resultant_matches_known_values() {
    // Res(x^2 - 2, x^2 - 3) = prod over +-sqrt 2 of (2 - 3) = 1.
    assert_eq!(
        upoly(&[-2, 0, 1]).resultant(&upoly(&[-3, 0, 1])),
        Rational::ONE
    );
    // Res(x - a, g) = g(a).
    let g = upoly(&[5, -1, 3]);
    assert_eq!(
        upoly(&[-7, 1]).resultant(&g),
        g.eval(&Rational::from_integer(7))
    );
    // Res(A, B) = (-1)^(mn) Res(B, A) with m = 3, n = 2; a common root gives 0.
    let a = upoly(&[1, 2, 0, 1]);
    assert_eq!(a.resultant(&g), g.resultant(&a));
    assert!(upoly(&[-1, 0, 1]).resultant(&upoly(&[-1, 1])).is_zero());
    // Sylvester determinant by hand: Res(x^2 + 1, 2x + 3) = 4 * ((-3/2)^2 + 1) = 13.
    assert_eq!(
        upoly(&[1, 0, 1]).resultant(&upoly(&[3, 2])),
        Rational::from_integer(13)
    );
}

#[test]
fn interpolation_recovers_a_polynomial() {
    let p = upoly(&[3, -1, 0, 2, 5]);
    let pts: Vec<_> = (-2..3)
        .map(|x| {
            let x = Rational::from_integer(x);
            (x.clone(), p.eval(&x))
        })
        .collect();
    assert_eq!(UPoly::interpolate(&pts), p);
    assert_eq!(upoly(&[1, 2, 3]).reversed(), upoly(&[3, 2, 1]));
}

#[test]
fn sum_of_square_roots_has_the_known_minimal_polynomial() {
    let s = sqrt_int(2) + sqrt_int(3);
    assert_eq!(s.minimal_polynomial(), Some(&upoly(&[1, 0, -10, 0, 1])));
    let p = sqrt_int(2) * sqrt_int(3);
    assert_eq!(p.defining_polynomial(), &upoly(&[-6, 0, 1]));
    assert_eq!(p.to_string(), "sqrt(6)");
    // The difference of conjugates and a cancellation back to a rational.
    assert_eq!((s.clone() - sqrt_int(3)).to_string(), "sqrt(2)");
    let back = s.clone() - sqrt_int(2) - sqrt_int(3);
    assert!(back.is_zero());
    assert_eq!((s.clone() * s).to_string(), "5 + 2*sqrt(6)");
}

#[test]
fn cubic_root_by_index_and_errors() {
    let f = upoly(&[1, -3, 0, 1]); // x^3 - 3x + 1: roots 2 cos(2 pi k / 9)
    let r: Vec<Algebraic> = (0..3).map(|i| Algebraic::root_of(&f, i).unwrap()).collect();
    assert!(r[0] < r[1] && r[1] < r[2]);
    assert_eq!(r[2], Algebraic::cos_pi(2, 9).unwrap().scale_i64(2));
    assert_eq!(
        r.iter().fold(Algebraic::zero(), |a, b| a + b),
        Algebraic::zero()
    );
    assert_eq!(
        Algebraic::root_of(&f, 3).unwrap_err(),
        RootError::IndexOutOfRange { index: 3, count: 3 }
    );
    assert_eq!(
        Algebraic::root_of(&UPoly::zero(), 0).unwrap_err(),
        RootError::ZeroPolynomial
    );
    // A repeated and a rational root: x = 1/2 exactly.
    let g = upoly(&[1, -2])
        .mul_ref(&upoly(&[1, -2]))
        .mul_ref(&upoly(&[-2, 0, 1]));
    assert_eq!(
        Algebraic::root_of(&g, 1).unwrap().to_rational(),
        Some(&Rational::new(1, 2).unwrap())
    );
    assert!(
        r[0].to_string().starts_with("Root(x^3 - 3*x + 1, "),
        "{}",
        r[0]
    );
    assert!(r[0].to_string().ends_with("≈ -1.8793852416"), "{}", r[0]);
}

#[test]
fn nested_radicals_denest_and_print() {
    assert_eq!(alg("sqrt(3 + 2 sqrt(2))").to_string(), "1 + sqrt(2)");
    assert_eq!(alg("sqrt(3 + 2 sqrt(2))"), alg("1 + sqrt(2)"));
    assert_eq!(alg("sqrt(5 - 2 sqrt(6))").to_string(), "-sqrt(2) + sqrt(3)");
    assert_eq!(
        alg("sqrt(2 + sqrt(3))").to_string(),
        "(sqrt(2) + sqrt(6))/2"
    );
    let c = alg("sqrt(2 + sqrt(2))/2");
    assert_eq!(c, Algebraic::cos_pi(1, 8).unwrap());
    assert_eq!(c.to_string(), "sqrt(2 + sqrt(2))/2");
    assert_eq!(c.minimal_polynomial(), Some(&upoly(&[1, 0, -8, 0, 8])));
    assert_eq!(
        alg("-sqrt(2 + sqrt(3))").to_string(),
        "(-sqrt(2) - sqrt(6))/2"
    );
    assert_eq!(alg("sqrt(7 - sqrt(5))").to_string(), "sqrt(7 - sqrt(5))");
    // Round trip of the printed form.
    for s in [
        "sqrt(2 + sqrt(2))",
        "(1 - 3*sqrt(5))/7",
        "sqrt(7 - sqrt(5))/3",
    ] {
        let x = alg(s);
        assert_eq!(alg(&x.to_string()), x, "{s} printed {x}");
    }
}

#[test]
fn signs_zero_tests_and_comparison() {
    let x = alg("sqrt(2) + sqrt(3)");
    let y = alg("sqrt(10)");
    // (sqrt 2 + sqrt 3)^2 = 5 + 2 sqrt 6 < 10 since 2 sqrt 6 < 5.
    assert!(x < y);
    assert_eq!((x.clone() - y.clone()).sign(), Sign::Negative);
    let z = x.clone() * x.clone() - alg("5 + 2 sqrt(6)");
    assert!(z.is_zero());
    assert_eq!(z.sign(), Sign::Zero);
    // Close but different: sqrt(2) vs 1.41421356237 and vs 99/70.
    assert!(alg("sqrt(2)") > alg("1.41421356237"));
    assert!(alg("sqrt(2)") < alg("99/70"));
    assert_eq!(alg("sqrt(2)").inverse().unwrap(), alg("sqrt(2)/2"));
    assert!(Algebraic::zero().inverse().is_err());
    assert!(alg("1 - sqrt(2)").sqrt().is_none());
    assert_eq!(alg("(1 + sqrt(2))^2").sqrt().unwrap(), alg("1 + sqrt(2)"));
}

#[test]
fn cosines_of_small_angles_print_as_radicals() {
    let c = |p, q| Algebraic::cos_pi(p, q).unwrap().to_string();
    assert_eq!(c(1, 5), "(1 + sqrt(5))/4");
    assert_eq!(c(2, 5), "(-1 + sqrt(5))/4");
    assert_eq!(c(1, 3), "1/2");
    assert_eq!(c(1, 2), "0");
    assert_eq!(c(1, 1), "-1");
    assert_eq!(c(0, 7), "1");
    assert_eq!(c(1, 6), "sqrt(3)/2");
    assert_eq!(c(-1, 4), "sqrt(2)/2");
    assert_eq!(c(3, 4), "-sqrt(2)/2");
    assert_eq!(c(7, 4), "sqrt(2)/2");
    assert_eq!(c(1, -3), "1/2");
    let s = |p, q| Algebraic::sin_pi(p, q).unwrap().to_string();
    assert_eq!(s(1, 6), "1/2");
    assert_eq!(s(1, 4), "sqrt(2)/2");
    assert_eq!(s(-1, 2), "-1");
    assert_eq!(s(1, 1), "0");
    assert_eq!(s(1, 10), "(-1 + sqrt(5))/4");
    let t = |p, q| Algebraic::tan_pi(p, q).unwrap().to_string();
    assert_eq!(t(1, 4), "1");
    assert_eq!(t(1, 8), "-1 + sqrt(2)");
    assert_eq!(t(1, 3), "sqrt(3)");
    assert_eq!(t(-1, 6), "-sqrt(3)/3");
    assert_eq!(t(3, 4), "-1");
    assert_eq!(
        Algebraic::tan_pi(1, 2).unwrap_err(),
        TrigError::TanUndefined { p: 1, q: 2 }
    );
    assert_eq!(
        Algebraic::cos_pi(1, 0).unwrap_err(),
        TrigError::ZeroDenominator
    );
    assert!(matches!(
        Algebraic::cos_pi(1, i64::MAX),
        Err(TrigError::Limit(_))
    ));
    // cos(2 pi/7): the cubic 8x^3 + 4x^2 - 4x - 1.
    let c7 = Algebraic::cos_pi(2, 7).unwrap();
    assert_eq!(c7.minimal_polynomial(), Some(&upoly(&[-1, -4, 4, 8])));
    // sin^2 + cos^2 = 1 and tan = sin/cos, through the resultant arithmetic.
    for (p, q) in [(1, 7), (3, 11), (5, 12), (-2, 9)] {
        let (s, c) = (
            Algebraic::sin_pi(p, q).unwrap(),
            Algebraic::cos_pi(p, q).unwrap(),
        );
        assert_eq!(s.square() + c.square(), Algebraic::one(), "{p}/{q}");
        assert_eq!(Algebraic::tan_pi(p, q).unwrap(), s / c, "{p}/{q}");
    }
}

// ------------------------------------------------------------------------------ 50 digits

/// `floor(atan(1/x) * scale)` up to a few units, by the alternating series.
fn atan_inv(x: u64, scale: &BigInt) -> BigInt {
    let x2 = BigInt::from(x * x);
    let mut power = scale / BigInt::from(x); // scale / x^(2k+1)
    let mut sum = BigInt::from(0);
    let mut k = 0u64;
    while power != BigInt::from(0) {
        let term = &power / BigInt::from(2 * k + 1);
        if k % 2 == 0 {
            sum += term;
        } else {
            sum -= term;
        }
        power /= &x2;
        k += 1;
    }
    sum
}

/// `cos(2 pi / n) * 10^60` to within a few units, by Machin's formula and the Taylor series in
/// fixed point: an evaluation independent of the algebraic machinery.
fn cos_fixed(n: u64) -> BigInt {
    let scale = BigInt::from(10).pow(60);
    let pi = atan_inv(5, &scale) * 16 - atan_inv(239, &scale) * 4;
    let theta = pi * 2 / BigInt::from(n);
    let theta2 = &theta * &theta / &scale;
    let mut term = scale.clone();
    let mut sum = scale.clone();
    let mut k = 1u64;
    while term != BigInt::from(0) {
        let t: BigInt = &term * &theta2 / &scale;
        term = -t / BigInt::from((2 * k - 1) * (2 * k));
        sum += &term;
        k += 1;
    }
    sum
}

fn totient_naive(n: u64) -> usize {
    (1..=n)
        .filter(|k| num_integer::Integer::gcd(k, &n) == 1)
        .count()
}

#[test]
fn cos_two_pi_over_n_degrees_and_fifty_digits() {
    let tol = Rational::from(BigInt::from(10).pow(50)).recip().unwrap();
    let scale = Rational::from(BigInt::from(10).pow(60));
    for n in 1..=60u64 {
        let c = Algebraic::cos_pi(2, n as i64).unwrap();
        let expected = if n <= 2 { 1 } else { totient_naive(n) / 2 };
        assert_eq!(c.degree(), expected, "n = {n}");
        assert!(c.minimal_polynomial().is_some());
        let approx = Rational::from(cos_fixed(n)) / &scale;
        let (lo, hi) = c.enclosure(200);
        assert!(
            lo.sub_ref(&tol) < approx && approx < hi.add_ref(&tol),
            "n = {n}"
        );
        // The defining polynomial vanishes on the value (via the 50-digit value's sign change).
        let f = c.defining_polynomial();
        if !c.is_rational() {
            assert_ne!(f.sign_at(&lo.sub_ref(&tol)), f.sign_at(&hi.add_ref(&tol)));
        }
    }
}

// ------------------------------------------------------------------------------ vs Radical

/// `a + b sqrt(c)` in both types.
fn both(a: i64, b: i64, c: u64) -> (Algebraic, Radical) {
    let alg = Algebraic::from_integer(a)
        + Algebraic::from_integer(b) * Algebraic::from_integer(c as i64).sqrt().unwrap();
    let rad = Radical::from_i64(a) + Radical::from_i64(b) * Radical::sqrt_of(c);
    (alg, rad)
}

fn from_radical(r: &Radical) -> Algebraic {
    alg(&r.to_string())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn radical_arithmetic_agrees(
        a in -9i64..10, b in -9i64..10, c in 2u64..12,
        d in -9i64..10, e in -9i64..10, f in 2u64..12,
    ) {
        let (x, rx) = both(a, b, c);
        let (y, ry) = both(d, e, f);
        prop_assert_eq!(x.sign(), rx.sign());
        prop_assert_eq!(x.compare(&y), rx.clone().sub_ref(&ry).sign().cmp(&Sign::Zero));
        prop_assert_eq!(x.add_ref(&y), from_radical(&rx.add_ref(&ry)));
        prop_assert_eq!(x.mul_ref(&y), from_radical(&rx.mul_ref(&ry)));
        prop_assert_eq!((x.clone() - y.clone()).is_zero(), rx == ry);
        if !ry.is_zero() {
            prop_assert_eq!(x.clone() / y.clone(), from_radical(&(rx.clone() / ry.clone())));
        }
        // A quadratic irrational prints as the Radical field's number.
        prop_assert_eq!(alg(&x.to_string()), x.clone());
        if let Some(s) = crate::expr::Coefficient::try_sqrt(&rx) {
            prop_assert_eq!(x.sqrt().unwrap(), from_radical(&s));
        }
    }
}

#[test]
fn degree_limit_and_parse_errors() {
    let x = alg("sqrt(2) + sqrt(3) + sqrt(5)");
    assert_eq!(x.degree(), 8);
    assert!(x.check_limits().is_ok());
    assert!("sqrt(-2)".parse::<Algebraic>().is_err());
    assert!("x + 1".parse::<Algebraic>().is_err());
}

// ------------------------------------------------------------------------------ minimality

/// The Chebyshev polynomial `T_n` (`T_0 = 1`, `T_1 = x`, `T_(k+1) = 2x T_k - T_(k-1)`).
fn chebyshev(n: usize) -> UPoly {
    let (mut a, mut b) = (UPoly::one(), UPoly::x());
    if n == 0 {
        return a;
    }
    let two_x = upoly(&[0, 2]);
    for _ in 1..n {
        let next = two_x.mul_ref(&b).sub_ref(&a);
        a = std::mem::replace(&mut b, next);
    }
    b
}

/// `cos(2 pi / n)` as a root of the reducible `T_n(x) - 1` (whose roots are the `cos(2 pi k/n)`):
/// factoring must reduce it to the minimal polynomial of degree `phi(n)/2`, the same as the
/// cyclotomic construction of [`Algebraic::cos_pi`], with the same value.
#[test]
fn cos_two_pi_over_n_from_chebyshev_is_minimal() {
    for n in 3..=60u64 {
        let f = chebyshev(n as usize).sub_ref(&UPoly::one());
        // Distinct roots cos(2 pi k/n), k = 0..=n/2, increasing as k decreases: cos(2 pi/n) is
        // the second largest.
        let count = f.square_free_part().isolate_roots().len();
        let c = Algebraic::root_of(&f, count - 2).unwrap();
        let expected = Algebraic::cos_pi(2, n as i64).unwrap();
        assert_eq!(c.degree(), totient_naive(n) / 2, "n = {n}");
        assert_eq!(
            c.minimal_polynomial(),
            expected.minimal_polynomial(),
            "n = {n}"
        );
        assert_eq!(c, expected, "n = {n}");
    }
    // Known small cases: cos(2 pi/5) = (sqrt 5 - 1)/4, root of 4x^2 + 2x - 1; cos(2 pi/7) of
    // 8x^3 + 4x^2 - 4x - 1; cos(2 pi/9) of 8x^3 - 6x + 1.
    for (n, p) in [
        (5usize, vec![-1, 2, 4]),
        (7, vec![-1, -4, 4, 8]),
        (9, vec![1, -6, 0, 8]),
    ] {
        let f = chebyshev(n).sub_ref(&UPoly::one());
        let count = f.square_free_part().isolate_roots().len();
        let c = Algebraic::root_of(&f, count - 2).unwrap();
        assert_eq!(c.minimal_polynomial(), Some(&upoly(&p)), "n = {n}");
    }
}

#[test]
fn sums_of_radicals_have_minimal_polynomials() {
    // sqrt 2 + sqrt 3 + sqrt 5 (+ sqrt 7): degrees 8 and 16, the resultants' degrees.
    let s3 = sqrt_int(2) + sqrt_int(3) + sqrt_int(5);
    assert_eq!(s3.degree(), 8);
    let s4 = s3.clone() + sqrt_int(7);
    assert_eq!(s4.degree(), 16);
    assert!(s4.minimal_polynomial().is_some());
    // sqrt 2 + sqrt 8 = 3 sqrt 2: the resultant of degree 4 has the quadratic factor.
    let t = sqrt_int(2) + sqrt_int(8);
    assert_eq!(t.minimal_polynomial(), Some(&upoly(&[-18, 0, 1])));
    // Nested radicals in one field: sqrt(2 + sqrt 2) + sqrt(2 - sqrt 2) = sqrt(4 + 2 sqrt 2).
    let u = alg("sqrt(2 + sqrt(2)) + sqrt(2 - sqrt(2))");
    assert_eq!(u.minimal_polynomial(), Some(&upoly(&[8, 0, -8, 0, 1])));
    assert_eq!(u, alg("sqrt(4 + 2*sqrt(2))"));
    // sqrt(2 + sqrt 2) * sqrt(2 - sqrt 2) = sqrt 2.
    assert_eq!(
        alg("sqrt(2 + sqrt(2)) * sqrt(2 - sqrt(2))").to_string(),
        "sqrt(2)"
    );
    // Four nested radicals: the defining polynomial is irreducible (factoring it again finds
    // itself) and the degree is at most the product of the degrees.
    let v = alg("sqrt(2 + sqrt(2)) + sqrt(2 - sqrt(2)) + sqrt(3 + sqrt(3)) + sqrt(5 + sqrt(5))");
    let m = v.minimal_polynomial().expect("factored").clone();
    assert_eq!(m.irreducible_factors().unwrap(), vec![m.clone()]);
    assert!(m.degree() <= 64);
    // Galois conjugates summing to a rational: cos(2pi/7) + cos(4pi/7) + cos(6pi/7) = -1/2.
    let w = Algebraic::cos_pi(2, 7).unwrap()
        + Algebraic::cos_pi(4, 7).unwrap()
        + Algebraic::cos_pi(6, 7).unwrap();
    assert_eq!(w.to_rational(), Some(&Rational::new(-1, 2).unwrap()));
    // A false variant: cos(2pi/7) + cos(4pi/7) is irrational (a cubic).
    let w2 = Algebraic::cos_pi(2, 7).unwrap() + Algebraic::cos_pi(4, 7).unwrap();
    assert_eq!(w2.degree(), 3);
}

#[test]
fn a_root_prints_in_a_variable_apart_from_the_statements() {
    let c = Algebraic::cos_pi(2, 7).unwrap();
    let alone = c.to_string();
    assert!(
        alone.starts_with("Root(8*x^3 + 4*x^2 - 4*x - 1, "),
        "{alone}"
    );
    // No variable: x as always; else z, z1, ... whichever the statement leaves free.
    assert_eq!(root_variable::<&str>(&[]), "x");
    assert_eq!(root_variable(&["x", "y"]), "z");
    assert_eq!(root_variable(&["x", "z", "z1"]), "z2");
    let shown = c.display_in("z");
    assert_eq!(shown, alone.replace('x', "z"));
    // Radicals and rationals print the same in any variable.
    let r = alg("(1 + sqrt(5))/4");
    assert_eq!(r.display_in("z"), r.to_string());
    assert_eq!(
        Algebraic::from_rational(Rational::new(-3, 4).unwrap()).display_in("z"),
        "-3/4"
    );
}

#[test]
fn a_number_field_takes_the_checked_minimal_polynomial() {
    // sqrt(2 + sqrt(2)) + sqrt(3): degree 8, reducible modulo every prime, so its minimality
    // needs recombination (refused past the factor-combinations limit: the corpus case
    // prove_factor_combinations).
    let v = alg("sqrt(2 + sqrt(2)) + sqrt(3)");
    let m = v.checked_minimal_polynomial().unwrap();
    assert_eq!(m.degree(), 8);
    assert_eq!(m.irreducible_factors().unwrap(), vec![m.clone()]);
    assert_eq!(NumberField::new(v).unwrap().degree(), 8);
}

/// The degree refusal of `cos(2*pi/q)` is the limit's own error, carried by the expression
/// error as a limit (not as words), with the call's name and position in its message.
#[test]
fn the_trig_degree_refusal_is_a_typed_limit() {
    use crate::expr::{parse_expr, trig_constant, ExprError, TrigRefusal};
    let e = parse_expr("1 + cos(2*pi/1009)").unwrap();
    let err = e.eval_constant::<Algebraic>().unwrap_err();
    let limit = err.limit().expect("a limit error");
    assert!(std::ptr::eq(limit.limit, &limits::ALGEBRAIC_DEGREE));
    assert_eq!(limit.actual, "504");
    assert!(
        matches!(err, ExprError::CallLimit { pos: 4, .. }),
        "{err:?}"
    );
    assert!(
        err.to_string().starts_with(
            "cos at 4: degree of an algebraic number exceeds the limit algebraic-degree"
        ),
        "{err}"
    );
    // A numerator past i64 is past every degree too; tan at pi/2 is no limit.
    let huge = Rational::new(1, 3).unwrap() * Rational::from(BigInt::from(10).pow(30));
    let r = huge.recip().unwrap();
    assert!(matches!(
        trig_constant::<Algebraic>(&r, Trig::Cos),
        Err(TrigRefusal::Limit(_))
    ));
    let half = Rational::new(1, 2).unwrap();
    assert!(matches!(
        trig_constant::<Algebraic>(&half, Trig::Tan),
        Err(TrigRefusal::Why(w)) if w.contains("undefined")
    ));
    // Other errors carry no limit.
    let bad = parse_expr("sqrt(-2)")
        .unwrap()
        .eval_constant::<Algebraic>()
        .unwrap_err();
    assert!(bad.limit().is_none(), "{bad}");
}

#[test]
fn roots_of_higher_index_are_real_roots() {
    // The cube root of 2: a root of x^3 - 2, between 1.25 and 1.26.
    let c = Algebraic::from_integer(2).nth_root(3).unwrap().unwrap();
    assert_eq!(c.minimal_polynomial(), Some(&upoly(&[-2, 0, 0, 1])));
    let (lo, hi) = c.enclosure(20);
    assert!(lo > Rational::new(125, 100).unwrap() && hi < Rational::new(126, 100).unwrap());
    assert_eq!(c.pow(3), Algebraic::from_integer(2));
    // Perfect powers stay rational; an odd index keeps the sign.
    assert_eq!(
        Algebraic::from_integer(-8).nth_root(3).unwrap(),
        Some(Algebraic::from_integer(-2))
    );
    assert_eq!(
        Algebraic::from_rational(Rational::new(16, 81).unwrap())
            .nth_root(4)
            .unwrap(),
        Some(Algebraic::from_rational(Rational::new(2, 3).unwrap()))
    );
    // An even index has no real root of a negative number.
    assert_eq!(Algebraic::from_integer(-2).nth_root(4).unwrap(), None);
    assert_eq!(
        Algebraic::from_integer(0).nth_root(5).unwrap(),
        Some(Algebraic::zero())
    );
    // Cardano: the cube roots of 2 +- sqrt(5) are the golden ratio and its conjugate - 1.
    let s5 = sqrt_int(5);
    let golden = alg("(1 + sqrt(5))/2");
    let plus = (Algebraic::from_integer(2) + s5.clone())
        .nth_root(3)
        .unwrap()
        .unwrap();
    let minus = (Algebraic::from_integer(2) - s5)
        .nth_root(3)
        .unwrap()
        .unwrap();
    assert_eq!(plus, golden);
    assert_eq!(plus + minus, Algebraic::from_integer(1));
    // Parsed as a power with a rational exponent.
    assert_eq!(alg("2^(1/3)"), c);
    assert_eq!(alg("4^(1/3)"), c.pow(2));
    assert_eq!(alg("(-27)^(2/3)"), Algebraic::from_integer(9));
    // The degree n d is checked before f(t^n) is formed.
    assert!(Algebraic::from_integer(2).nth_root(1000).is_err());
}

#[test]
fn rational_roots_of_higher_index_are_exact() {
    use crate::coefficient::Coefficient;
    let q = |n: i64, d: i64| Rational::new(n, d).unwrap();
    assert_eq!(q(27, 8).try_nth_root(3).unwrap(), Some(q(3, 2)));
    assert_eq!(q(-27, 8).try_nth_root(3).unwrap(), Some(q(-3, 2)));
    assert_eq!(q(2, 1).try_nth_root(3).unwrap(), None);
    assert_eq!(q(-16, 1).try_nth_root(4).unwrap(), None);
    assert_eq!(q(1, 32).try_nth_root(5).unwrap(), Some(q(1, 2)));
}
