//! Property tests of `Radical` (multi-quadratic numbers) and `ComplexRadical`: the field laws,
//! the canonical form after every operation, agreement with f64 evaluation where that is
//! reliable, exact sign decisions where it is not, square roots, and the parse/print round trip.
//! Fixtures: Chiang's Example 4 with sqrt 2 and sqrt 6, Table 1 with 1/sqrt 2, and Juettler's
//! Satz 5 (the imaginary focal lines).

use exactcheck_core::{Field, OrderedField, Ring, Sign, Sqrt};
use exactcheck_exact::radical::{ComplexRadical, Radical};
use exactcheck_exact::ParseRadicalError;
use exactcheck_exact::Rational;
use proptest::prelude::*;

/// Radicands over the primes 2, 3, 5, 7 (so every field involved has degree at most 16).
const RADICANDS: [u64; 12] = [1, 2, 3, 5, 6, 7, 10, 14, 15, 21, 30, 35];

fn small_rational() -> impl Strategy<Value = Rational> {
    (-20i64..=20, 1i64..=9).prop_map(|(n, d)| Rational::new(n, d).unwrap())
}

/// `sum c_k sqrt(m_k)` built through the public API, with up to `max_terms` terms.
fn radical_with(max_terms: usize) -> impl Strategy<Value = Radical> {
    proptest::collection::vec((0..RADICANDS.len(), small_rational()), 0..=max_terms).prop_map(
        |terms| {
            let mut x = Radical::zero();
            for (k, c) in terms {
                x += Radical::sqrt_of(RADICANDS[k]).scale(&c);
            }
            x
        },
    )
}

fn radical() -> impl Strategy<Value = Radical> {
    radical_with(4)
}

fn r(s: &str) -> Radical {
    s.parse().unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

/// Canonical form, checked from the outside: radicands strictly increasing and square-free, no
/// zero coefficient.
fn check_canonical(x: &Radical) -> Result<(), TestCaseError> {
    prop_assert!(x.is_canonical(), "not canonical: {x:?}");
    let terms = x.terms();
    for w in terms.windows(2) {
        prop_assert!(w[0].0 < w[1].0, "unsorted: {x:?}");
    }
    for (m, c) in terms {
        prop_assert!(!c.is_zero(), "zero coefficient in {x:?}");
        let m = m.as_u64().expect("small radicand");
        prop_assert!(m >= 1);
        for p in [2u64, 3, 5, 7, 11, 13] {
            prop_assert!(m % (p * p) != 0, "radicand {m} not square-free");
        }
    }
    Ok(())
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + scale)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn ring_laws(x in radical(), y in radical(), z in radical()) {
        for v in [&x, &y, &z] {
            check_canonical(v)?;
        }
        let s = &x + &y;
        let p = &x * &y;
        check_canonical(&s)?;
        check_canonical(&p)?;
        check_canonical(&(&x - &y))?;
        prop_assert_eq!(&s, &(&y + &x));
        prop_assert_eq!(&p, &(&y * &x));
        prop_assert_eq!(&(&s + &z), &(&x + &(&y + &z)));
        prop_assert_eq!(&(&p * &z), &(&x * &(&y * &z)));
        prop_assert_eq!(&(&x * &(&y + &z)), &(&p + &(&x * &z)));
        prop_assert!((&x - &x).is_zero());
        prop_assert_eq!(&(&x + &(-&x)), &Radical::zero());
        prop_assert_eq!(&x.square(), &(&x * &x));
        prop_assert_eq!(&(&x * &Radical::one()), &x);
        // Owned and borrowed operators agree.
        prop_assert_eq!(&(x.clone() + y.clone()), &s);
        prop_assert_eq!(&(x.clone() - &y), &(&x - &y));
        let mut acc = x.clone();
        acc *= &y;
        prop_assert_eq!(&acc, &p);
    }

    #[test]
    fn inverses(x in radical(), y in radical()) {
        match x.inv() {
            Err(_) => prop_assert!(x.is_zero()),
            Ok(ix) => {
                check_canonical(&ix)?;
                prop_assert_eq!(&(&x * &ix), &Radical::one());
                let d = y.checked_div(&x).unwrap();
                check_canonical(&d)?;
                prop_assert_eq!(&(&d * &x), &y);
            }
        }
    }

    #[test]
    fn agrees_with_f64(x in radical(), y in radical()) {
        let (fx, fy) = (x.to_f64(), y.to_f64());
        let scale = fx.abs() + fy.abs();
        prop_assert!(close((&x + &y).to_f64(), fx + fy, scale));
        prop_assert!(close((&x - &y).to_f64(), fx - fy, scale));
        prop_assert!(close((&x * &y).to_f64(), fx * fy, fx.abs() * fy.abs()));
        if let Ok(ix) = x.inv() {
            prop_assert!(close(ix.to_f64() * fx, 1.0, 1.0));
        }
        // The sign: the filtered answer is always the exact one, and matches f64 away from 0.
        let d = &x - &y;
        prop_assert_eq!(d.sign(), d.sign_exact());
        let fd = fx - fy;
        if fd.abs() > 1e-6 * (1.0 + scale) {
            prop_assert_eq!(d.sign(), if fd > 0.0 { Sign::Positive } else { Sign::Negative });
            prop_assert_eq!(x > y, fd > 0.0);
        }
        prop_assert_eq!(x.cmp(&y), y.cmp(&x).reverse());
    }

    /// Near-ties: x against the exact value of a nearby double (a few ulps away, or the nearest
    /// one), where f64 evaluation cannot decide; the filtered sign must equal the unfiltered
    /// exact one, and agree with `<`, `>` and the sign of the difference.
    #[test]
    fn near_ties_are_decided_exactly(x in radical_with(3), k in -8i64..8) {
        let approx = x.to_f64() + k as f64 * f64::EPSILON * x.to_f64().abs();
        // Every double with |v| < 2^11 is an integer multiple of 2^-52 below 2^63.
        let scaled = approx * 2f64.powi(52);
        prop_assume!(scaled.abs() < 2f64.powi(62));
        let b = Radical::from(Rational::from_i128_ratio(scaled as i128, 1i128 << 52).unwrap());
        let d = &x - &b;
        prop_assert_eq!(d.sign(), d.sign_exact());
        prop_assert_eq!(x > b, d.sign() == Sign::Positive);
        prop_assert_eq!(x < b, d.sign() == Sign::Negative);
        prop_assert_eq!(x == b, d.sign() == Sign::Zero);
    }

    /// sqrt(x^2) = |x| for x = a + b sqrt(p): the denesting of the claim list's quadratics.
    #[test]
    fn sqrt_of_square_two_terms(a in small_rational(), b in small_rational(), k in 1..RADICANDS.len()) {
        let x = Radical::from(a) + Radical::sqrt_of(RADICANDS[k]).scale(&b);
        let y = x.square().sqrt();
        prop_assert_eq!(y, Some(x.abs()));
    }

    /// sqrt(x^2) = |x| for general elements (the algorithm is complete: x^2 always has a
    /// multi-quadratic root).
    #[test]
    fn sqrt_of_square_general(x in radical_with(4)) {
        let y = x.square().sqrt().expect("a square has a root");
        check_canonical(&y)?;
        prop_assert_eq!(y, x.abs());
    }

    /// Non-squares: `sqrt(x)` either fails or is verified (y >= 0, y^2 = x).
    #[test]
    fn sqrt_is_verified(x in radical()) {
        match x.sqrt() {
            Some(y) => {
                prop_assert!(y.sign() != Sign::Negative);
                prop_assert_eq!(&y.square(), &x);
            }
            // Every non-negative rational has a root in the type.
            None => prop_assert!(x.sign() == Sign::Negative || !x.is_rational()),
        }
    }

    #[test]
    fn print_parse_round_trip(x in radical()) {
        let s = x.to_string();
        let back: Radical = s.parse().map_err(|e| TestCaseError::fail(format!("{s:?}: {e}")))?;
        prop_assert_eq!(back, x);
    }

    #[test]
    fn complex_field_laws(a in radical_with(2), b in radical_with(2), c in radical_with(2), d in radical_with(2)) {
        let x = ComplexRadical::new(a, b);
        let y = ComplexRadical::new(c, d);
        let i = ComplexRadical::i();
        prop_assert_eq!(&(&x * &y), &(&y * &x));
        prop_assert_eq!(&(&x * &(&y + &i)), &(&(&x * &y) + &(&x * &i)));
        prop_assert_eq!(&x.square(), &(&x * &x));
        prop_assert_eq!(&(&x * &x.conj()), &ComplexRadical::from(x.norm_sqr()));
        match x.inv() {
            Err(_) => prop_assert!(x.is_zero()),
            Ok(ix) => prop_assert_eq!(&x * &ix, ComplexRadical::one()),
        }
        let s = x.to_string();
        let back: ComplexRadical = s.parse().map_err(|e| TestCaseError::fail(format!("{s:?}: {e}")))?;
        prop_assert_eq!(back, x.clone());
        if let Some(root) = x.square().sqrt() {
            prop_assert!(root == x || root == -&x);
        }
    }
}

#[test]
fn printed_examples() {
    // the claim list, Table 1: 1/sqrt 2 and its rationalized form.
    assert_eq!(r("1/sqrt(2)"), r("sqrt(2)/2"));
    // Chiang's Example 4 mixes sqrt 2 and sqrt 6: their product lies in Q(sqrt 3).
    assert_eq!(r("sqrt(2)*sqrt(6)"), r("2*sqrt(3)"));
    assert_eq!(
        Radical::sqrt_of(2) * Radical::sqrt_of(6),
        Radical::sqrt_of(3).scale(&q("2"))
    );
    assert_eq!(r("1 + sqrt(2)").inv().unwrap(), r("sqrt(2) - 1"));
    assert_eq!(r("(1+sqrt(2))^-1"), r("sqrt(2) - 1"));
    assert_eq!(r("sqrt(3 - 2*sqrt(2))"), r("sqrt(2) - 1"));
    assert_eq!(r("(2+sqrt(2))/3").to_string(), "2/3 + sqrt(2)/3");
    assert_eq!(r("0.1"), Radical::from(q("1/10")));
    assert_eq!(r("-3/4"), Radical::from(q("-3/4")));
    assert_eq!(r("sqrt(1/8)"), r("sqrt(2)/4"));
    assert_eq!(r("sqrt(12/5)"), r("2*sqrt(15)/5"));
    assert_eq!(Radical::sqrt_of(72), r("6*sqrt(2)"));
    // Table 1's parabola plane (1, 1, sqrt 2): the weight 1 + sqrt 2 and its negative.
    assert_eq!(r("-sqrt(2)-1"), -r("1+sqrt(2)"));
    // Example 4's first weight, w0 = q0z = sqrt 2, printed 1.41.
    assert!(r("sqrt(2)") > r("1.41") && r("sqrt(2)") < r("1.415"));
}

#[test]
fn close_comparisons_are_exact() {
    let x = r("sqrt(2) + sqrt(3)"); // 3.14626436994197234232...
    assert!(x < r("sqrt(10)"));
    // x^2 = 5 + 2 sqrt 6 = 9.89897948556635...
    assert!(x < r("sqrt(9.899)"));
    assert!(x > r("sqrt(9.898979485)"));
    assert!(x < r("sqrt(9.898979486)"));
    // 3.1462643699419726 is the f64 nearest to x; as a decimal rational it lies above x ...
    assert!(x < r("3.1462643699419726"));
    assert!(x > r("3.1462643699419723"));
    // ... and f64 evaluation rounds both to the same value.
    assert_eq!(2f64.sqrt() + 3f64.sqrt(), 3.1462643699419726);
    // Equal values written differently compare equal.
    assert_eq!(x.cmp(&r("sqrt(5 + 2*sqrt(6))")), std::cmp::Ordering::Equal);
    // sqrt(n^2 + 1) - n < 1/(2n) for n = 10^8: in f64 the left side is exactly 0.
    let n = r("100000000");
    let lhs = r("sqrt(10000000000000001)") - &n;
    assert_eq!(lhs.to_f64(), 0.0);
    assert_eq!(lhs.sign(), Sign::Positive);
    assert!(lhs < (n.scale(&q("2"))).inv().unwrap());
    assert!(lhs > (n.scale(&q("2")) + Radical::one()).inv().unwrap());
}

#[test]
fn complex_examples() {
    let i = ComplexRadical::i();
    assert_eq!(&i * &i, -ComplexRadical::one());
    let parsed: ComplexRadical = "sqrt(-1)".parse().unwrap();
    assert_eq!(parsed, i);
    assert_eq!(
        "sqrt(-4)".parse::<ComplexRadical>().unwrap().to_string(),
        "2*i"
    );
    assert_eq!("-i".parse::<ComplexRadical>().unwrap().to_string(), "-i");
    assert_eq!(
        "1/2 - sqrt(3)/2*i"
            .parse::<ComplexRadical>()
            .unwrap()
            .to_string(),
        "1/2 - sqrt(3)/2*i"
    );
    assert_eq!(
        "(1 + sqrt(2))*i".parse::<ComplexRadical>().unwrap().im,
        r("1 + sqrt(2)")
    );
    // (1 + i)^-1 = (1 - i)/2.
    let z: ComplexRadical = "1 + i".parse().unwrap();
    assert_eq!(z.inv().unwrap(), "(1 - i)/2".parse().unwrap());
    assert_eq!("sqrt(2*i)".parse::<ComplexRadical>().unwrap(), z);
    // the claim list, Satz 5 / (14): the focal line points (1,0,0,i) and (0,1,-i,0) lie on the
    // absolute quadric x0^2 + x1^2 + x2^2 + x3^2 = 0, and so does every combination of them.
    let one = ComplexRadical::one();
    let zero = ComplexRadical::zero();
    let quadric = |p: [&ComplexRadical; 4]| p.iter().fold(zero.clone(), |acc, x| acc + x.square());
    assert!(quadric([&one, &zero, &zero, &i]).is_zero());
    assert!(quadric([&zero, &one, &(-&i), &zero]).is_zero());
    let (xi, zeta) = (r("sqrt(2)"), r("3/5"));
    let (xi, zeta) = (ComplexRadical::from(xi), ComplexRadical::from(zeta));
    let point = [&xi, &zeta, &(-(&zeta * &i)), &(&xi * &i)];
    assert!(quadric(point).is_zero());
    assert!(matches!(
        "i".parse::<Radical>(),
        Err(ParseRadicalError::NotConstant { pos: 0, .. })
    ));
}

#[test]
fn errors_are_typed() {
    assert!(matches!(
        "1/(sqrt(2) - sqrt(2))".parse::<Radical>(),
        Err(ParseRadicalError::DivisionByZero { pos: 2 })
    ));
    assert!(matches!(
        "sqrt(sqrt(2))".parse::<Radical>(),
        Err(ParseRadicalError::NoSqrt { pos: 0, .. })
    ));
    assert!(matches!(
        "1 + sqrt(-2)".parse::<Radical>(),
        Err(ParseRadicalError::NoSqrt { pos: 4, .. })
    ));
    assert!(matches!(
        "log(1)".parse::<Radical>(),
        Err(ParseRadicalError::UnknownFunction { pos: 0, .. })
    ));
    let e = "2 * * 3".parse::<Radical>().unwrap_err();
    assert_eq!(
        e.to_string(),
        "unexpected '*' at 4: expected a number, a variable or '('"
    );
    assert_eq!(Radical::zero().inv(), Err(exactcheck_core::ZeroDivisor));
    assert_eq!(Radical::sqrt_rational(&q("-1")), None);
}
