//! Tests of the certified enclosures of `transc`: exact values, domains, the constants, the
//! enclosures against the C library (`f64` methods) and against identities.
use super::interval::{Dy, Iv};
use super::transc::{enclose, pi, special, TStop};
use super::*;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Signed;
use proptest::prelude::*;

/// The exact value of a finite double.
fn exact(x: f64) -> Rational {
    Rational::from(BigRational::from_float(x).expect("finite"))
}

fn point(x: f64) -> Iv {
    Iv::from_rational(&exact(x), 64)
}

/// The exact reference of `f` at doubles, as the program `f(x)` or `f(x, y)` evaluates it.
fn reference(f: Func, args: &[f64]) -> Result<Reference, ExactStop> {
    let names = ["x", "y"];
    let p = Program {
        name: f.name().into(),
        inputs: names[..args.len()].iter().map(|s| s.to_string()).collect(),
        slots: 0,
        pre: None,
        outputs: vec![Node::Fun(f, (0..args.len()).map(Node::Input).collect())],
        precision: Format::Binary64,
        input_precision: Vec::new(),
    };
    let x: Vec<Rational> = args.iter().map(|&v| exact(v)).collect();
    p.eval_exact(&x).map(|mut r| r.remove(0))
}

/// The distance in ulps between two doubles of one sign (by their ordinal).
fn ulps(a: f64, b: f64) -> u64 {
    let ord = |v: f64| {
        let i = v.to_bits() as i64;
        if i < 0 {
            i64::MIN - i
        } else {
            i
        }
    };
    ord(a).abs_diff(ord(b))
}

/// Asserts that the correctly rounded reference of `f` at `args` is within one ulp of `libm`.
/// The error allowed to the platform's libm against the correctly rounded value, in ulps: 1,
/// and 2 for the hyperbolic functions and their inverses, which glibc documents to 2 ulps (its
/// published maximum known errors; `acosh` near 1 reaches them).
fn libm_tolerance(f: Func) -> u64 {
    match f {
        Func::Sinh | Func::Cosh | Func::Tanh | Func::Asinh | Func::Acosh | Func::Atanh => 2,
        _ => 1,
    }
}

fn agrees(f: Func, args: &[f64], libm: f64) -> Result<(), TestCaseError> {
    let r = reference(f, args).map_err(|e| TestCaseError::fail(format!("{f:?}{args:?}: {e}")))?;
    let rounded = crate::to_f64::rational_to_f64(&r.value);
    prop_assert!(
        ulps(rounded, libm) <= libm_tolerance(f),
        "{:?}{:?}: certified {:e}, libm {:e}",
        f,
        args,
        rounded,
        libm
    );
    Ok(())
}

/// Whether the enclosure contains the rational `q`.
fn contains(iv: &Iv, q: &BigRational) -> bool {
    &iv.lo.to_big_rational() <= q && q <= &iv.hi.to_big_rational()
}

fn width(iv: &Iv) -> BigRational {
    iv.hi.to_big_rational() - iv.lo.to_big_rational()
}

#[test]
fn pi_matches_its_decimal_expansion() {
    let digits = "3.141592653589793238462643383279502884197169399375105820974944592307816406286208998628034825342117068";
    let q: BigRational = exact_decimal(digits);
    let iv = pi(256);
    let err = BigRational::new(BigInt::from(1), BigInt::from(10).pow(75));
    let lo = iv.lo.to_big_rational();
    let hi = iv.hi.to_big_rational();
    assert!((&lo - &q).abs() < err && (&hi - &q).abs() < err);
    assert!(width(&iv) < BigRational::new(BigInt::from(1), BigInt::from(2).pow(250)));
}

fn exact_decimal(s: &str) -> BigRational {
    let (int, frac) = s.split_once('.').unwrap();
    let n: BigInt = format!("{int}{frac}").parse().unwrap();
    BigRational::new(n, BigInt::from(10).pow(frac.len() as u32))
}

#[test]
fn constants_round_to_the_libm_constants() {
    for (f, c) in [
        (Func::Pi, std::f64::consts::PI),
        (Func::E, std::f64::consts::E),
    ] {
        let r = reference(f, &[]).unwrap();
        assert!(!r.exact);
        assert_eq!(crate::to_f64::rational_to_f64(&r.value), c, "{f:?}");
    }
}

#[test]
fn exact_values_are_exact() {
    let cases: &[(Func, &[f64], f64)] = &[
        (Func::Sin, &[0.0], 0.0),
        (Func::Cos, &[0.0], 1.0),
        (Func::Tan, &[0.0], 0.0),
        (Func::Exp, &[0.0], 1.0),
        (Func::Expm1, &[0.0], 0.0),
        (Func::Log, &[1.0], 0.0),
        (Func::Log1p, &[0.0], 0.0),
        (Func::Log2, &[0.125], -3.0),
        (Func::Log10, &[1000.0], 3.0),
        (Func::Exp2, &[-4.0], 0.0625),
        (Func::Asin, &[0.0], 0.0),
        (Func::Acos, &[1.0], 0.0),
        (Func::Atan, &[0.0], 0.0),
        (Func::Atan2, &[0.0, 2.0], 0.0),
        (Func::Acosh, &[1.0], 0.0),
        (Func::Pow, &[4.0, 0.5], 2.0),
        (Func::Pow, &[8.0, -1.0 / 3.0 + 1.0 / 3.0], 1.0),
        (Func::Pow, &[0.25, 1.5], 0.125),
        (Func::Pow, &[0.0, 2.5], 0.0),
        (Func::Hypot, &[3.0, 4.0], 5.0),
        (Func::Cbrt, &[-27.0], -3.0),
    ];
    for (f, args, want) in cases {
        let r = reference(*f, args).unwrap();
        assert!(r.exact, "{f:?}{args:?}");
        assert_eq!(
            r.value,
            BigRational::from_float(*want).unwrap(),
            "{f:?}{args:?}"
        );
    }
}

#[test]
fn outside_the_domain() {
    let cases: &[(Func, &[f64])] = &[
        (Func::Log, &[0.0]),
        (Func::Log, &[-1.0]),
        (Func::Log2, &[-0.5]),
        (Func::Log1p, &[-1.0]),
        (Func::Asin, &[1.0000000000000002]),
        (Func::Acos, &[-2.0]),
        (Func::Acosh, &[0.5]),
        (Func::Atanh, &[1.0]),
        (Func::Atan2, &[0.0, 0.0]),
        (Func::Pow, &[-2.0, 0.5]),
        (Func::Pow, &[0.0, -1.5]),
    ];
    for (f, args) in cases {
        assert_eq!(
            reference(*f, args),
            Err(ExactStop::OutsideDomain),
            "{f:?}{args:?}"
        );
    }
    // A domain decided on an enclosure: log of a surely negative irrational.
    let neg = Iv::from_rational(&exact(-2.0), 64);
    let root = Iv::sqrt(&Iv::from_rational(&exact(2.0), 64), 64);
    assert_eq!(
        enclose(Func::Log, Some(&Iv::mul(&neg, &root, 64)), None, 64),
        Err(TStop::Outside)
    );
    // ... and one straddling the boundary: refine.
    let around_one = Iv {
        lo: Dy::from_rational(&exact(0.5), 64, super::interval::Dir::Down),
        hi: Dy::from_rational(&exact(1.5), 64, super::interval::Dir::Up),
    };
    assert_eq!(
        enclose(Func::Asin, Some(&around_one), None, 64),
        Err(TStop::Ambiguous)
    );
}

#[test]
fn special_is_none_for_irrational_values() {
    for f in [Func::Exp, Func::Sin, Func::Log, Func::Atan, Func::Cbrt] {
        assert_eq!(
            special(f, Some(&Rational::from_integer(2)), None),
            None,
            "{f:?}"
        );
    }
    assert_eq!(
        special(
            Func::Pow,
            Some(&Rational::from_integer(2)),
            Some(&exact(0.5))
        ),
        None
    );
}

#[test]
fn large_and_tiny_arguments() {
    // Argument reduction of sin and cos needs pi to the bits of the argument.
    for x in [1e22, 1e300, 5e-324, 1e-300, 710.0, -745.0, 1e15] {
        agrees(Func::Sin, &[x], x.sin()).unwrap();
        agrees(Func::Cos, &[x], x.cos()).unwrap();
        agrees(Func::Atan, &[x], x.atan()).unwrap();
    }
    agrees(Func::Exp, &[-745.0], (-745f64).exp()).unwrap();
    agrees(Func::Exp, &[709.0], 709f64.exp()).unwrap();
    agrees(Func::Expm1, &[1e-300], 1e-300f64.exp_m1()).unwrap();
    agrees(Func::Log1p, &[1e-300], 1e-300f64.ln_1p()).unwrap();
    agrees(Func::Log, &[1.0 + f64::EPSILON], (1.0 + f64::EPSILON).ln()).unwrap();
    agrees(
        Func::Acos,
        &[1.0 - f64::EPSILON],
        (1.0 - f64::EPSILON).acos(),
    )
    .unwrap();
    // Beyond every size limit.
    assert_eq!(reference(Func::Exp, &[1e300]), Err(ExactStop::TooLarge));
}

fn finite(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    prop_oneof![lo..hi, (lo / 1e6)..(hi / 1e6)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn unary_functions_agree_with_libm(x in finite(-700.0, 700.0)) {
        agrees(Func::Exp, &[x], x.exp())?;
        agrees(Func::Exp2, &[x], x.exp2())?;
        agrees(Func::Expm1, &[x], x.exp_m1())?;
        agrees(Func::Sin, &[x], x.sin())?;
        agrees(Func::Cos, &[x], x.cos())?;
        agrees(Func::Tan, &[x], x.tan())?;
        agrees(Func::Atan, &[x], x.atan())?;
        agrees(Func::Sinh, &[x], x.sinh())?;
        agrees(Func::Cosh, &[x], x.cosh())?;
        agrees(Func::Tanh, &[x], x.tanh())?;
        agrees(Func::Asinh, &[x], call_f64(Func::Asinh, x, 0.0))?;
        agrees(Func::Cbrt, &[x], x.cbrt())?;
        if x != 0.0 {
            let a = x.abs();
            agrees(Func::Log, &[a], a.ln())?;
            agrees(Func::Log2, &[a], a.log2())?;
            agrees(Func::Log10, &[a], a.log10())?;
            agrees(Func::Log1p, &[a], a.ln_1p())?;
            agrees(Func::Acosh, &[1.0 + a], call_f64(Func::Acosh, 1.0 + a, 0.0))?;
        }
    }

    #[test]
    fn functions_of_the_unit_interval_agree_with_libm(x in -1.0f64..1.0) {
        agrees(Func::Asin, &[x], x.asin())?;
        agrees(Func::Acos, &[x], x.acos())?;
        agrees(Func::Atanh, &[x], call_f64(Func::Atanh, x, 0.0))?;
    }

    #[test]
    fn binary_functions_agree_with_libm(x in finite(-1e3, 1e3), y in finite(-1e3, 1e3)) {
        agrees(Func::Atan2, &[y, x], y.atan2(x))?;
        agrees(Func::Hypot, &[x, y], x.hypot(y))?;
        let (b, e) = (x.abs(), y / 100.0);
        if b != 0.0 && (b.powf(e)).is_normal() {
            agrees(Func::Pow, &[b, e], b.powf(e))?;
        }
    }

    #[test]
    fn sin_squared_plus_cos_squared_encloses_one(x in finite(-1e6, 1e6), p in 64u64..300) {
        let s = enclose(Func::Sin, Some(&point(x)), None, p).unwrap();
        let c = enclose(Func::Cos, Some(&point(x)), None, p).unwrap();
        let sum = Iv::add(&Iv::mul(&s, &s, p), &Iv::mul(&c, &c, p), p);
        prop_assert!(contains(&sum, &BigRational::from_integer(BigInt::from(1))));
        prop_assert!(width(&sum) < BigRational::new(BigInt::from(1), BigInt::from(2).pow(p as u32 - 8)));
    }

    #[test]
    fn exp_of_log_encloses_the_argument(x in 1e-300f64..1e300, p in 64u64..300) {
        let l = enclose(Func::Log, Some(&point(x)), None, p).unwrap();
        let e = enclose(Func::Exp, Some(&l), None, p).unwrap();
        prop_assert!(contains(&e, &exact(x).to_big_rational()));
    }

    #[test]
    fn tan_of_atan_encloses_the_argument(x in finite(-1e6, 1e6), p in 64u64..300) {
        let a = enclose(Func::Atan, Some(&point(x)), None, p).unwrap();
        let t = enclose(Func::Tan, Some(&a), None, p).unwrap();
        prop_assert!(contains(&t, &exact(x).to_big_rational()));
    }

    #[test]
    fn cbrt_cubed_encloses_the_argument(x in finite(-1e6, 1e6), p in 64u64..300) {
        let r = enclose(Func::Cbrt, Some(&point(x)), None, p).unwrap();
        let cube = Iv::mul(&Iv::mul(&r, &r, p), &r, p);
        prop_assert!(contains(&cube, &exact(x).to_big_rational()));
    }
}

#[test]
fn formulas_call_the_functions_and_pi_is_the_constant() {
    let p = Program::parse("sin(x) + pi * ln(y)", None).unwrap();
    assert_eq!(p.inputs, vec!["x", "y"]);
    assert_eq!(
        p.outputs,
        vec![Node::Add(
            Box::new(Node::Fun(Func::Sin, vec![Node::Input(0)])),
            Box::new(Node::Mul(
                Box::new(Node::Fun(Func::Pi, vec![])),
                Box::new(Node::Fun(Func::Log, vec![Node::Input(1)]))
            ))
        )]
    );
    // The float side is libm, the exact side certified.
    let f = p.eval_f64(&[0.5, 3.0])[0];
    assert_eq!(f, 0.5f64.sin() + std::f64::consts::PI * 3f64.ln());
    let r = p.eval_exact(&[exact(0.5), exact(3.0)]).unwrap();
    assert!(!r[0].exact);
    let rounded = crate::to_f64::rational_to_f64(&r[0].value);
    assert!(ulps(rounded, f) <= 2, "{rounded:e} vs {f:e}");
    // sin(x) on [0, 1]: the reference rounds to libm's value within an ulp.
    let s = Program::parse("sin(x)", Some(&["x".to_string()])).unwrap();
    for i in 1..50 {
        let x = f64::from(i) / 50.0;
        let r = s.eval_exact(&[exact(x)]).unwrap();
        assert!(ulps(crate::to_f64::rational_to_f64(&r[0].value), x.sin()) <= 1);
    }
    // Exact zero: sin(x - x) is decided exactly.
    let z = Program::parse("sin(x - x)", None).unwrap();
    let r = z.eval_exact(&[exact(0.3)]).unwrap();
    assert!(r[0].exact && r[0].value == BigRational::from_integer(0.into()));
}

#[test]
fn formula_calls_are_checked() {
    let err = |t: &str, vars: Option<&[String]>| Program::parse(t, vars).unwrap_err().to_string();
    let e = err("erf(x)", None);
    assert!(
        e.starts_with("unknown function 'erf' at 0: the functions are") && e.contains("exp, exp2"),
        "{e}"
    );
    let e = err("atan2(x)", None);
    assert!(e.contains("it takes 2 arguments, found 1"), "{e}");
    let e = err("x + pi", Some(&["x".to_string(), "pi".to_string()]));
    assert!(
        e.contains("\"pi\" in the variable list is not a variable name"),
        "{e}"
    );
    // The language's own functions are lowered: a derivative is its expansion.
    let d = Program::parse("diff(x^2, x)", None).unwrap();
    assert_eq!(d.inputs, ["x"]);
}

#[test]
fn equal_calls_at_equal_exact_arguments_are_equal_at_once() {
    let vars = ["x".to_string(), "d".to_string()];
    let at = |text: &str, x: f64, d: f64| {
        Program::parse(text, Some(&vars))
            .expect("compiles")
            .eval_exact(&[exact(x), exact(d)])
    };
    // A difference of one call with itself is exactly 0, a quotient exactly 1: no refinement
    // to the precision cap (which would answer `Undecided`).
    for (text, want) in [
        ("sin(x + d) - sin(x)", 0),
        ("exp(x) - exp(x + d*x)", 0),
        ("atan2(x, 2 + d) - atan2(x, 2)", 0),
        ("pi - pi", 0),
        ("log(x + d) / log(x)", 1),
    ] {
        let r = at(text, 0.75, 0.0).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert!(r[0].exact, "{text}");
        assert_eq!(r[0].value, BigRational::from_integer(want.into()), "{text}");
    }
    // Different arguments are different calls: the difference is refined as before.
    let r = at("sin(x + d) - sin(x)", 0.75, 1.0 / 1024.0).expect("defined");
    assert!(!r[0].exact);
    let want = (0.75f64 + 1.0 / 1024.0).sin() - 0.75f64.sin();
    assert!((crate::to_f64::rational_to_f64(&r[0].value) - want).abs() < 1e-15);
    // A comparison of a call with itself is decided: equal.
    let bm = fpcore::parse_file("(FPCore (x d) (if (== (cos x) (cos (+ x d))) 1 0))")
        .expect("parses")
        .remove(0);
    let p = bm.program.expect("compiles");
    let r = p.eval_exact(&[exact(0.5), exact(0.0)]).expect("decided");
    assert_eq!(r[0].value, BigRational::from_integer(1.into()));
}
