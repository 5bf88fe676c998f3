//! Rational functions and `diff` against independent paths: expressions with fractions
//! converted by `Expr::to_ratfun` against their value computed term by term in exact rational
//! arithmetic at random points off the poles; identities between fractions decided by
//! `prove::decide_fraction` against the same evaluation; derivatives against the formal
//! derivative of `univariate::UPoly`; the polynomial gcd against `UPoly::gcd`.

use exactcheck_core::Ring;
use exactcheck_exact::expr::parse_expr;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::prove::{decide_fraction, Decision, FractionIdentity};
use exactcheck_exact::ratfun::{poly_gcd, RatFun};
use exactcheck_exact::univariate::UPoly;
use exactcheck_exact::{Radical, Rational};
use proptest::prelude::*;

/// A polynomial in x and y of degree at most 2 in each, as `(i, j, c)` for `c x^i y^j`.
type Terms = Vec<(u32, u32, i64)>;

fn arb_terms() -> impl Strategy<Value = Terms> {
    prop::collection::vec((0u32..3, 0u32..3, -5i64..=5), 1..4)
}

fn text(t: &Terms) -> String {
    let parts: Vec<String> = t
        .iter()
        .map(|&(i, j, c)| format!("({c})*x^{i}*y^{j}"))
        .collect();
    format!("({})", parts.join(" + "))
}

/// The value at `(x, y)`, term by term.
fn value(t: &Terms, x: &Rational, y: &Rational) -> Rational {
    t.iter().fold(Rational::ZERO, |acc, &(i, j, c)| {
        &acc + &(&Rational::from(c) * &(&x.pow(i) * &y.pow(j)))
    })
}

fn arb_point() -> impl Strategy<Value = (Rational, Rational)> {
    ((-9i64..=9, 1i64..=4), (-9i64..=9, 1i64..=4))
        .prop_map(|((a, b), (c, d))| (Rational::new(a, b).unwrap(), Rational::new(c, d).unwrap()))
}

fn div(a: &Rational, b: &Rational) -> Rational {
    a * &b.recip().unwrap()
}

/// Templates of four polynomials `A, B, C, D`: the expression, the divisors (indices) that must
/// not vanish, the value from the four values, and the same function written over a common
/// denominator by hand.
type Value4 = fn(&[Rational; 4]) -> Rational;
const TEMPLATES: [(&str, &[usize], Value4, &str); 5] = [
    (
        "A/B + C/D",
        &[1, 3],
        |v| &div(&v[0], &v[1]) + &div(&v[2], &v[3]),
        "(A*D + C*B)/(B*D)",
    ),
    (
        "A/B * (C/D)",
        &[1, 3],
        |v| &div(&v[0], &v[1]) * &div(&v[2], &v[3]),
        "(A*C)/(B*D)",
    ),
    (
        "(A/B) / (C/D)",
        &[1, 2, 3],
        |v| div(&div(&v[0], &v[1]), &div(&v[2], &v[3])),
        "(A*D)/(B*C)",
    ),
    (
        "A*B^-2 - C/D",
        &[1, 3],
        |v| &div(&v[0], &v[1].pow(2)) - &div(&v[2], &v[3]),
        "(A*D - C*B^2)/(B^2*D)",
    ),
    (
        "(A/B - C)/D",
        &[1, 3],
        |v| div(&(&div(&v[0], &v[1]) - &v[2]), &v[3]),
        "(A - C*B)/(B*D)",
    ),
];

fn fill(template: &str, ts: &[Terms; 4]) -> String {
    template
        .replace('A', &text(&ts[0]))
        .replace('B', &text(&ts[1]))
        .replace('C', &text(&ts[2]))
        .replace('D', &text(&ts[3]))
}

fn at(p: &Poly<Rational>, vars: &Vars, x: &Rational, y: &Rational) -> Rational {
    let point: Vec<Rational> = vars
        .names()
        .iter()
        .map(|n| if n == "x" { x.clone() } else { y.clone() })
        .collect();
    p.eval(&point, Rational::clone)
}

/// The function of `text` in lowest terms, or `None` when a divisor is identically zero.
fn ratfun(text: &str, vars: &mut Vars) -> Option<RatFun<Rational>> {
    parse_expr(text).unwrap().to_ratfun::<Rational>(vars).ok()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 120, ..ProptestConfig::default() })]

    #[test]
    fn fractions_evaluate_like_their_terms(
        k in 0usize..TEMPLATES.len(),
        a in arb_terms(), b in arb_terms(), c in arb_terms(), d in arb_terms(),
        (x, y) in arb_point(),
    ) {
        let ts = [a, b, c, d];
        let (template, divisors, value4, _) = TEMPLATES[k];
        let mut vars = Vars::from_names(["x", "y"]);
        let f = ratfun(&fill(template, &ts), &mut vars);
        prop_assume!(f.is_some());
        let f = f.unwrap();
        let v: [Rational; 4] = std::array::from_fn(|i| value(&ts[i], &x, &y));
        prop_assume!(divisors.iter().all(|&i| !v[i].is_zero()));
        let den = at(f.denominator(), &vars, &x, &y);
        prop_assert!(!den.is_zero());
        prop_assert_eq!(div(&at(f.numerator(), &vars, &x, &y), &den), value4(&v));
        // Off the divisors, no condition vanishes.
        for p in f.conditions() {
            prop_assert!(!at(p, &vars, &x, &y).is_zero());
        }
    }

    #[test]
    fn identities_between_fractions_are_decided_like_their_values(
        k in 0usize..TEMPLATES.len(),
        a in arb_terms(), b in arb_terms(), c in arb_terms(), d in arb_terms(),
    ) {
        let ts = [a, b, c, d];
        let (template, divisors, _, common) = TEMPLATES[k];
        let mut vars = Vars::from_names(["x", "y"]);
        let (Some(l), Some(r)) = (
            ratfun(&fill(template, &ts), &mut vars),
            ratfun(&fill(common, &ts), &mut vars),
        ) else {
            return Ok(());
        };
        let id = FractionIdentity::new(&l, &r).unwrap();
        let proved = matches!(
            decide_fraction(&id, &[], &[], &[], vars.len()).unwrap(),
            Decision::Proved { .. }
        );
        prop_assert!(proved);
        // Off by x: a counter-example off every divisor, with the value of LHS - RHS there.
        let wrong = ratfun(&format!("{} + x", fill(common, &ts)), &mut vars).unwrap();
        let id = FractionIdentity::new(&l, &wrong).unwrap();
        match decide_fraction(&id, &[], &[], &[], vars.len()).unwrap() {
            Decision::Fails { point, value: diff, .. } => {
                let get = |name: &str| {
                    let v = vars.get(name).unwrap();
                    point.iter().find(|(w, _)| *w == v).unwrap().1.to_rational().unwrap()
                };
                let (x, y) = (get("x"), get("y"));
                let v: [Rational; 4] = std::array::from_fn(|i| value(&ts[i], &x, &y));
                prop_assert!(divisors.iter().all(|&i| !v[i].is_zero()));
                prop_assert_eq!(diff, Radical::from(-x));
            }
            other => prop_assert!(false, "not a counter-example: {:?}", other),
        }
    }

    #[test]
    fn derivatives_of_polynomials_are_the_formal_derivative(
        coeffs in prop::collection::vec(-20i64..=20, 1..8),
        order in 0u32..4,
    ) {
        let p = UPoly::from_i64_coeffs(&coeffs);
        let t = format!("diff({}, t, {order})", upoly_text(&p));
        let mut vars = Vars::from_names(["t"]);
        let f = ratfun(&t, &mut vars).unwrap();
        let mut expected = p;
        for _ in 0..order {
            expected = expected.derivative();
        }
        prop_assert!(f.denominator().is_one());
        let got = UPoly::from_coeffs(
            (0..=expected.degree())
                .map(|k| f.numerator().coefficient(&if k == 0 { vec![] } else { vec![(0, k as u32)] }))
                .collect(),
        );
        prop_assert_eq!(got, expected);
    }

    #[test]
    fn the_derivative_of_a_quotient_satisfies_the_quotient_rule(
        pc in prop::collection::vec(-9i64..=9, 1..5),
        qc in prop::collection::vec(-9i64..=9, 2..5),
        t in (-9i64..=9, 1i64..=4),
    ) {
        let (p, q) = (UPoly::from_i64_coeffs(&pc), UPoly::from_i64_coeffs(&qc));
        prop_assume!(!q.is_zero());
        let t = Rational::new(t.0, t.1).unwrap();
        prop_assume!(!q.eval(&t).is_zero());
        let mut vars = Vars::from_names(["t"]);
        let f = ratfun(&format!("diff({}/{}, t)", upoly_text(&p), upoly_text(&q)), &mut vars).unwrap();
        // f * Q^2 = P'Q - PQ' at t, with P' and Q' from UPoly.
        let point = [t.clone()];
        let ft = div(&f.numerator().eval(&point, Rational::clone), &f.denominator().eval(&point, Rational::clone));
        let lhs = &ft * &q.eval(&t).pow(2);
        let rhs = &(&p.derivative().eval(&t) * &q.eval(&t)) - &(&p.eval(&t) * &q.derivative().eval(&t));
        prop_assert_eq!(lhs, rhs);
    }

    #[test]
    fn the_gcd_of_univariate_polynomials_is_that_of_upoly(
        ac in prop::collection::vec(-9i64..=9, 1..4),
        bc in prop::collection::vec(-9i64..=9, 1..4),
        gc in prop::collection::vec(-9i64..=9, 1..4),
    ) {
        let (a, b, g) = (UPoly::from_i64_coeffs(&ac), UPoly::from_i64_coeffs(&bc), UPoly::from_i64_coeffs(&gc));
        prop_assume!(!a.is_zero() && !b.is_zero() && !g.is_zero());
        let (ag, bg) = (a.mul_ref(&g), b.mul_ref(&g));
        let mut vars = Vars::from_names(["t"]);
        let to_poly = |u: &UPoly, vars: &mut Vars| {
            exactcheck_exact::expr::parse_poly::<Rational>(&upoly_text(u), vars).unwrap()
        };
        let got = poly_gcd(&to_poly(&ag, &mut vars), &to_poly(&bg, &mut vars)).unwrap();
        let expected = to_poly(&ag.gcd(&bg).monic(), &mut vars);
        prop_assert_eq!(got, expected);
    }
}

/// `u` as text in `t`.
fn upoly_text(u: &UPoly) -> String {
    let parts: Vec<String> = u
        .coeffs()
        .iter()
        .enumerate()
        .map(|(k, c)| format!("({c})*t^{k}"))
        .collect();
    if parts.is_empty() {
        "(0)".into()
    } else {
        format!("({})", parts.join(" + "))
    }
}
