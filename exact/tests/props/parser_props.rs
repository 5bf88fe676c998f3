//! The one grammar (`exactcheck_exact::expr`) as every entry point sees it: `parse_expr` with
//! `to_poly` (prove, the catalogue), `eval_constant`, and the `FromStr` of `Rational`, `Radical`
//! and `ComplexRadical` (every number string of `solve`) must agree on every input, print and
//! parse back, and refuse the same inputs with the same errors. Regression tests pin the old wrong
//! behaviours of the two former grammars.

use exactcheck_core::Ring;
use exactcheck_exact::expr::{parse_expr, parse_poly, AddOp, Expr, ExprError, ExprKind, MulOp};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::{ComplexRadical, Radical, Rational};
use num_bigint::BigInt;
use proptest::prelude::*;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

/// The constant value of `text` through the polynomial path of `prove` (over `Radical`).
fn via_poly(text: &str) -> Result<Radical, ExprError> {
    let mut vars = Vars::new();
    let p: Poly<Radical> = parse_poly(text, &mut vars)?;
    assert!(vars.is_empty(), "{text:?} has variables {vars:?}");
    Ok(p.constant_value().expect("no variables, so constant"))
}

// ------------------------------------------------------------------------ regressions

#[test]
fn scientific_notation_is_a_number_not_a_variable() {
    // Old: `prove '1e3' '1000'` read the variable e3 and answered `fails`.
    let mut vars = Vars::new();
    let p: Poly<Rational> = parse_poly("1e3", &mut vars).unwrap();
    assert!(vars.is_empty(), "read as variables {vars:?}");
    assert_eq!(p, Poly::constant(q(1000, 1)));
    // Old: `solve` rejected "5e0"; Rational had no exponents.
    assert_eq!("5e0".parse::<Radical>().unwrap(), Radical::from_i64(5));
    assert_eq!("2.5e-3".parse::<Rational>().unwrap(), q(1, 400));
    assert_eq!(
        "1E+5".parse::<ComplexRadical>().unwrap(),
        ComplexRadical::from_i64(100_000)
    );
    // `2e` without exponent digits stays the product 2*e.
    let mut vars = Vars::new();
    let p: Poly<Rational> = parse_poly("2e", &mut vars).unwrap();
    assert_eq!(vars.len(), 1);
    assert_eq!(p, Poly::var(0).scale_i64(2));
}

#[test]
fn juxtaposition_is_read_by_every_entry_point() {
    // Old: `prove` accepted `2 sqrt(4) x`, but `solve` rejected "2 sqrt(4)".
    assert_eq!(
        "2 sqrt(4)".parse::<Radical>().unwrap(),
        Radical::from_i64(4)
    );
    assert_eq!("2 sqrt(4)".parse::<Rational>().unwrap(), q(4, 1));
    assert_eq!(via_poly("2 sqrt(4)").unwrap(), Radical::from_i64(4));
    assert_eq!(
        "2(1 + i) i".parse::<ComplexRadical>().unwrap(),
        "-2 + 2*i".parse().unwrap()
    );
}

#[test]
fn unknown_functions_are_errors_everywhere() {
    // Old: `prove 'sin(x)' 'x'` multiplied a variable `sin` by x and answered `fails`.
    let msg = "unknown function 'exp' at 0: the functions are sqrt, abs, diff, integrate, sum, \
               binomial, factorial, sin, cos, tan (write 'exp*(...)' for a product)";
    assert_eq!(
        parse_poly::<Rational>("exp(x)", &mut Vars::new())
            .unwrap_err()
            .to_string(),
        msg
    );
    assert_eq!("exp(1)".parse::<Radical>().unwrap_err().to_string(), msg);
    assert_eq!("exp(1)".parse::<Rational>().unwrap_err().to_string(), msg);
    assert!(matches!(
        "log(1)".parse::<ComplexRadical>(),
        Err(ExprError::UnknownFunction { pos: 0, .. })
    ));
}

#[test]
fn huge_constants_are_refused_before_computing() {
    // Old: `prove '((2^10000)^10000)^10000'` aborted allocating; in a solve string
    // "((2^1024)^1024)^1024" aborted after 13 s.
    let too_large = "size of a constant exceeds the limit constant-bits = 1000000 bits (found at \
                     least ";
    for text in [
        "((2^10000)^10000)^10000",
        "((2^1024)^1024)^1024",
        "(2^10000)^10000",
    ] {
        let start = std::time::Instant::now();
        assert!(via_poly(text).unwrap_err().to_string().contains(too_large));
        assert!(text
            .parse::<Radical>()
            .unwrap_err()
            .to_string()
            .contains(too_large));
        assert!(text
            .parse::<Rational>()
            .unwrap_err()
            .to_string()
            .contains(too_large));
        assert!(
            start.elapsed().as_secs() < 5,
            "{text}: {:?}",
            start.elapsed()
        );
    }
    // Radicals and complex numbers are limited too.
    assert!(matches!(
        "(sqrt(2)*2^1000)^10000".parse::<Radical>(),
        Err(ExprError::Limit { error, .. }) if error.limit.name() == "constant-bits"
    ));
    assert!(matches!(
        "(2^1000 i)^10000".parse::<ComplexRadical>(),
        Err(ExprError::Limit { error, .. }) if error.limit.name() == "constant-bits"
    ));
}

// ------------------------------------------------------------------------ properties

/// A random constant expression: numbers written in several notations, `sqrt` of small
/// integers, sums, products (divisions by non-zero numbers), small powers with signed exponents.
fn arb_constant() -> impl Strategy<Value = String> {
    let number = prop_oneof![
        (0u32..1000).prop_map(|n| n.to_string()),
        (0u32..100, 1u32..1000).prop_map(|(i, f)| format!("{i}.{f:03}")),
        (1u32..100, -6i32..6).prop_map(|(m, e)| format!("{m}e{e}")),
        (1u32..100, 0u32..100, 0i32..4).prop_map(|(i, f, e)| format!("{i}.{f}E+{e}")),
        (0u32..60).prop_map(|k| format!("sqrt({k})")),
    ];
    number.prop_recursive(4, 24, 3, |inner| {
        prop_oneof![
            inner.clone().prop_map(|e| format!("-({e})")),
            (inner.clone(), inner.clone(), any::<bool>())
                .prop_map(|(a, b, m)| format!("({a}) {} ({b})", if m { '-' } else { '+' })),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a})*({b})")),
            // Juxtaposition: a factor in parentheses after a number or a product.
            (1u32..9, inner.clone()).prop_map(|(k, a)| format!("{k} ({a})")),
            (inner.clone(), 1u32..9).prop_map(|(a, d)| format!("({a})/{d}")),
            (inner.clone(), -3i32..4).prop_map(|(a, k)| format!("(1 + ({a})^2)^{k}")),
        ]
    })
}

/// The exact value of a number written `{int}.{frac}e{exp}`, computed independently.
fn decimal_value(int: u64, frac: &str, exp: i32) -> Rational {
    let digits: BigInt = format!("{int}{frac}").parse().unwrap();
    let scale = i64::from(exp) - frac.len() as i64;
    let ten = BigInt::from(10u32).pow(scale.unsigned_abs() as u32);
    let m = Rational::from(digits);
    if scale >= 0 {
        m * Rational::from(ten)
    } else {
        m / Rational::from(ten)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// `Radical::from_str`, `parse_expr` + `eval_constant`, and `parse_poly` (the `prove` path)
    /// give the same value; the value prints and parses back; the expression prints and parses
    /// back to the same value.
    #[test]
    fn every_entry_point_agrees(text in arb_constant()) {
        let e = parse_expr(&text).map_err(|err| TestCaseError::fail(format!("{text:?}: {err}")))?;
        let by_eval = e.eval_constant::<Radical>();
        let by_from_str = text.parse::<Radical>();
        let by_poly = via_poly(&text);
        prop_assert_eq!(&by_from_str, &by_eval, "{}", text);
        prop_assert_eq!(&by_poly, &by_eval, "{}", text);
        if let Ok(x) = by_eval {
            let printed = x.to_string();
            prop_assert_eq!(printed.parse::<Radical>(), Ok(x.clone()), "{}", printed);
            let reprinted = e.to_string();
            prop_assert_eq!(reprinted.parse::<Radical>(), Ok(x.clone()), "{}", reprinted);
            // After one round the printed form is a fixed point.
            let again = parse_expr(&reprinted).unwrap().to_string();
            prop_assert_eq!(parse_expr(&again).unwrap().to_string(), again.clone());
            prop_assert_eq!(again.parse::<Radical>(), Ok(x.clone()), "{}", again);
            // The complex type reads the same real numbers.
            prop_assert_eq!(
                text.parse::<ComplexRadical>(),
                Ok(ComplexRadical::from(x.clone()))
            );
            // Rational agrees whenever it can evaluate the text (not through irrational roots),
            // and an irrational value is never read as a rational.
            match text.parse::<Rational>() {
                Ok(r) => prop_assert_eq!(Radical::from(r), x),
                Err(err) => prop_assert!(
                    matches!(err, ExprError::NoSqrt { .. }),
                    "{}: {}", text, err
                ),
            }
        }
    }

    /// Scientific notation is exact: `{int}.{frac}e{exp}` is `int.frac * 10^exp`.
    #[test]
    fn scientific_notation_is_exact(
        int in 0u64..1_000_000,
        frac in "[0-9]{1,8}",
        exp in -40i32..40,
        upper in any::<bool>(),
        plus in any::<bool>(),
    ) {
        let e = if upper { 'E' } else { 'e' };
        let sign = if exp >= 0 && plus { "+" } else { "" };
        let text = format!("{int}.{frac}{e}{sign}{exp}");
        let want = decimal_value(int, &frac, exp);
        prop_assert_eq!(text.parse::<Rational>(), Ok(want.clone()), "{}", text);
        prop_assert_eq!(text.parse::<Radical>(), Ok(Radical::from(want.clone())), "{}", text);
        let neg = format!("-{text}");
        prop_assert_eq!(neg.parse::<Rational>(), Ok(-want), "{}", neg);
    }

    /// Gaussian numbers `a + b i` print and parse back.
    #[test]
    fn complex_print_parse_round_trip(a in -50i64..50, b in -50i64..50, d in 1i64..9, k in 0u64..12) {
        let re = Radical::sqrt_of(k).scale(&q(a, d));
        let z = ComplexRadical::new(re, Radical::from(q(b, d)));
        let s = z.to_string();
        prop_assert_eq!(s.parse::<ComplexRadical>(), Ok(z), "{}", s);
    }

    /// No input panics any entry point; errors point into the input.
    #[test]
    fn no_entry_point_panics(
        s in prop::collection::vec(
            prop::sample::select(vec![
                "1e3", "2.5e-3", "e", "E", "1E", "e+", "-", "+", "5", "0", "x", "i", "sin(",
                "sqrt(", "(", ")", "^", "*", "/", " ", "2^", "1e99999999", ".", "9.", "i(",
            ]),
            0..16,
        )
    ) {
        let text: String = s.concat();
        for err in [
            text.parse::<Rational>().err(),
            text.parse::<Radical>().err(),
            text.parse::<ComplexRadical>().err(),
            parse_poly::<Radical>(&text, &mut Vars::new()).err(),
        ]
        .into_iter()
        .flatten()
        {
            prop_assert!(err.position() <= text.len(), "{}: {}", text, err);
            prop_assert!(!err.to_string().contains('\n'));
        }
    }
}

/// A hand-built expression tree (not from the parser) evaluates like its printed text.
#[test]
fn built_trees_evaluate_like_their_text() {
    let num = |n: i64| Expr::new(ExprKind::Number(q(n, 1)));
    let e = Expr::new(ExprKind::Sum(vec![
        (AddOp::Minus, num(3)),
        (
            AddOp::Plus,
            Expr::new(ExprKind::Product(vec![
                (MulOp::Divide, num(4)),
                (MulOp::Times, Expr::new(ExprKind::Sqrt(Box::new(num(8))))),
            ])),
        ),
    ]));
    let v: Radical = e.eval_constant().unwrap();
    assert_eq!(v, "-3 + sqrt(2)/2".parse().unwrap());
    assert_eq!(e.to_string().parse::<Radical>(), Ok(v));
}
