//! `integrate`, `sum`, `binomial` and `factorial` against independent paths: definite integrals
//! against the antiderivative summed coefficient by coefficient in exact rational arithmetic
//! and against the fundamental theorem (`diff(integrate(E, t, 0, x), x) = E(x)`), sums against
//! their explicit expansion written out as text, binomials against Pascal's rule and the
//! factorial formula; the arc length of a Pythagorean-hodograph cubic.

use exactcheck_core::Ring;
use exactcheck_exact::expr::{parse_expr, parse_poly};
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::Rational;
use proptest::prelude::*;

fn poly(s: &str, vars: &mut Vars) -> Poly<Rational> {
    parse_poly(s, vars).unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn constant(s: &str) -> Rational {
    parse_expr(s)
        .and_then(|e| e.eval_constant::<Rational>())
        .unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

/// `c_0 + c_1 v + ... ` as text, each coefficient `c_i a^(i mod 2)` (a second variable).
fn text(coeffs: &[i64], v: &str) -> String {
    let parts: Vec<String> = coeffs
        .iter()
        .enumerate()
        .map(|(i, c)| format!("({c})*a^{}*{v}^{i}", i % 2))
        .collect();
    parts.join(" + ")
}

fn arb_rational() -> impl Strategy<Value = Rational> {
    (-20i64..=20, 1i64..=6).prop_map(|(n, d)| Rational::new(n, d).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The definite integral of a polynomial with constant coefficients between rational bounds
    /// equals `sum_i c_i (b^(i+1) - a^(i+1)) / (i + 1)`, computed here directly.
    #[test]
    fn integral_matches_the_antiderivative(
        coeffs in prop::collection::vec(-9i64..=9, 1..7),
        a in arb_rational(),
        b in arb_rational(),
    ) {
        let e: Vec<String> = coeffs.iter().enumerate().map(|(i, c)| format!("({c})*t^{i}")).collect();
        let got = constant(&format!("integrate({}, t, {a}, {b})", e.join(" + ")));
        let mut want = Rational::ZERO;
        for (i, &c) in coeffs.iter().enumerate() {
            let k = i as u32 + 1;
            let term = &(&b.pow(k) - &a.pow(k)) * &Rational::new(c, i64::from(k)).unwrap();
            want = &want + &term;
        }
        prop_assert_eq!(got, want);
    }

    /// The fundamental theorem: the derivative in `x` of the integral from 0 to `x` is the
    /// integrand at `x` (coefficients involving another variable `a`).
    #[test]
    fn fundamental_theorem(coeffs in prop::collection::vec(-9i64..=9, 1..8)) {
        let mut vars = Vars::new();
        let lhs = poly(&format!("diff(integrate({}, t, 0, x), x)", text(&coeffs, "t")), &mut vars);
        let rhs = poly(&text(&coeffs, "x"), &mut vars);
        prop_assert_eq!(lhs, rhs);
    }

    /// Integrals are additive in the interval and change sign with it.
    #[test]
    fn additivity(coeffs in prop::collection::vec(-9i64..=9, 1..6), b in arb_rational()) {
        let e = text(&coeffs, "t");
        let mut vars = Vars::new();
        let split = poly(&format!("integrate({e}, t, p, {b}) + integrate({e}, t, {b}, q)"), &mut vars);
        let whole = poly(&format!("integrate({e}, t, p, q)"), &mut vars);
        let reversed = poly(&format!("-integrate({e}, t, q, p)"), &mut vars);
        prop_assert_eq!(&split, &whole);
        prop_assert_eq!(&whole, &reversed);
    }

    /// A sum equals its terms written out, the index replaced by each integer in parentheses.
    #[test]
    fn sum_matches_explicit_expansion(
        from in -4i64..=4,
        len in 0i64..=6,
        coeffs in prop::collection::vec(-5i64..=5, 1..4),
    ) {
        let to = from + len - 1;
        let body = |k: &str| {
            let parts: Vec<String> = coeffs
                .iter()
                .enumerate()
                .map(|(i, c)| format!("({c})*x^{i}*{k}^{}", i + 1))
                .collect();
            format!("({})", parts.join(" + "))
        };
        let mut vars = Vars::new();
        let got = poly(&format!("sum(k, {from}, {to}, {})", body("k")), &mut vars);
        let explicit: Vec<String> = (from..=to).map(|i| body(&format!("({i})"))).collect();
        let want = if explicit.is_empty() {
            poly("0", &mut vars)
        } else {
            poly(&explicit.join(" + "), &mut vars)
        };
        prop_assert_eq!(got, want);
    }

    /// Pascal's rule, and `binomial(n, k) k! (n - k)! = n!`.
    #[test]
    fn binomial_pascal_and_factorials(n in 1u32..120, k in -3i64..125) {
        let lhs = constant(&format!("binomial({n}, {k})"));
        let rhs = constant(&format!("binomial({}, {}) + binomial({}, {k})", n - 1, k - 1, n - 1));
        prop_assert_eq!(&lhs, &rhs);
        if (0..=i64::from(n)).contains(&k) {
            let product = constant(&format!(
                "binomial({n}, {k}) factorial({k}) factorial({})",
                i64::from(n) - k
            ));
            prop_assert_eq!(product, constant(&format!("factorial({n})")));
        }
    }

    /// The Bernstein polynomials of any degree sum to 1.
    #[test]
    fn bernstein_partition_of_unity(n in 0u32..25) {
        let mut vars = Vars::new();
        let p = poly(&format!("sum(i, 0, {n}, binomial({n}, i) t^i (1-t)^({n}-i))"), &mut vars);
        prop_assert_eq!(p, poly("1", &mut vars));
    }
}

/// A Pythagorean-hodograph cubic: `x' = u^2 - v^2`, `y' = 2 u v` with `u`, `v` linear in
/// Bernstein form. Its parametric speed `sigma = u^2 + v^2` is a polynomial (`x'^2 + y'^2 =
/// sigma^2`), so its arc length is the integral of a polynomial:
/// `(u0^2 + u0 u1 + u1^2 + v0^2 + v0 v1 + v1^2) / 3`.
#[test]
fn ph_cubic_arc_length() {
    let u = "(u0*(1-t) + u1 t)";
    let v = "(v0*(1-t) + v1 t)";
    let sigma = format!("({u}^2 + {v}^2)");
    let mut vars = Vars::new();
    assert_eq!(
        poly(&format!("({u}^2 - {v}^2)^2 + (2 {u} {v})^2"), &mut vars),
        poly(&format!("{sigma}^2"), &mut vars),
        "the hodograph is Pythagorean"
    );
    assert_eq!(
        poly(&format!("integrate({sigma}, t, 0, 1)"), &mut vars),
        poly("(u0^2 + u0 u1 + u1^2 + v0^2 + v0 v1 + v1^2)/3", &mut vars)
    );
    // u = 1 + t, v = t: the arc length from 0 to 1 is (1 + 2 + 4 + 0 + 0 + 1)/3 = 8/3.
    assert_eq!(
        constant("integrate((1 + t)^2 + t^2, t, 0, 1)"),
        Rational::new(8, 3).unwrap()
    );
    // The length up to a symbolic parameter s, and its derivative, the speed at s.
    assert_eq!(
        poly(&format!("diff(integrate({sigma}, t, 0, s), s)"), &mut vars),
        poly(&sigma.replace('t', "s"), &mut vars)
    );
}
