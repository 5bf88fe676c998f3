//! Unit tests of `integrate`, `sum`, `binomial` and `factorial`.

use super::*;
use crate::poly::{Poly, Vars};
use crate::ratfun::RatFun;

type P = Poly<Rational>;

fn poly(s: &str, vars: &mut Vars) -> P {
    parse_poly(s, vars).unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn ratfun(s: &str, vars: &mut Vars) -> RatFun<Rational> {
    parse_expr(s)
        .and_then(|e| e.to_ratfun::<Rational>(vars))
        .unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn constant(s: &str) -> Rational {
    parse_expr(s)
        .and_then(|e| e.eval_constant::<Rational>())
        .unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

/// The error of converting `s` to a rational function.
fn err(s: &str) -> String {
    match parse_expr(s).and_then(|e| e.to_ratfun::<Rational>(&mut Vars::new())) {
        Ok(f) => panic!("{s:?} converted to {f:?}"),
        Err(e) => e.to_string(),
    }
}

/// Whether `a` and `b` denote the same polynomial.
fn same(a: &str, b: &str) {
    let mut v = Vars::new();
    let (pa, pb) = (poly(a, &mut v), poly(b, &mut v));
    assert_eq!(pa, pb, "{a} != {b}");
}

#[test]
fn definite_integrals_of_polynomials() {
    assert_eq!(constant("integrate(t^2, t, 0, 1)"), q(1, 3));
    assert_eq!(constant("integrate(3 t^2 - 2 t + 1, t, -1, 2)"), q(9, 1));
    assert_eq!(constant("integrate(1, t, 0, 5)"), q(5, 1));
    assert_eq!(constant("integrate(t, t, 1, 1)"), q(0, 1));
    // Reversed bounds change the sign.
    assert_eq!(constant("integrate(t^3, t, 1, 0)"), q(-1, 4));
    // Coefficients in other variables, symbolic bounds.
    same("integrate(a t + b, t, 0, x)", "a x^2/2 + b x");
    same("integrate(t^2, t, x, 2x)", "7 x^3/3");
    same("integrate(x, t, 0, 1)", "x");
    // A `t` in a bound is the caller's t.
    same("integrate(t, t, 0, t)", "t^2/2");
    // Nested integrals: the area of the triangle under y = x on [0, 1].
    assert_eq!(
        constant("integrate(integrate(1, y, 0, x), x, 0, 1)"),
        q(1, 2)
    );
}

#[test]
fn the_integration_variable_stays_out_of_the_table() {
    let mut v = Vars::new();
    let p = poly("integrate(a t^2, t, 0, b)", &mut v);
    assert_eq!(v.names(), ["b", "a"]);
    assert_eq!(p, poly("a b^3/3", &mut v));
    let mut names = Vec::new();
    parse_expr("integrate(a t^2, t, 0, b) + sum(k, 1, 3, k y)")
        .unwrap()
        .collect_variables(&mut names);
    assert_eq!(names, ["b", "a", "y"]);
}

#[test]
fn integrals_of_rational_functions_with_denominators_free_of_t() {
    let mut v = Vars::new();
    let f = ratfun("integrate(t/x, t, 0, 1)", &mut v);
    assert_eq!(f, ratfun("1/(2x)", &mut v));
    // Rational bounds are substituted into the antiderivative.
    let g = ratfun("integrate(2t, t, 0, 1/x)", &mut v);
    assert_eq!(g, ratfun("1/x^2", &mut v));
    assert!(!g.conditions().is_empty());
}

#[test]
fn integrals_of_rational_functions_of_t_are_refused() {
    let e = err("integrate(1/(1+t), t, 0, 1)");
    assert!(
        e.contains("divides by an expression in t") && e.contains("not in general rational"),
        "{e}"
    );
    // A divisor that cancels still involves t: refused too.
    assert!(err("integrate((t^2-1)/(t-1), t, 0, 1)").contains("expression in t"));
}

#[test]
fn bad_integrate_calls() {
    assert_eq!(
        err("integrate(t, t, 0)"),
        "integrate at 0: takes 4 arguments (expression, variable, from, to), not 3"
    );
    assert_eq!(
        err("integrate(t, 2, 0, 1)"),
        "integrate at 13: the second argument must be a variable name, not 2"
    );
}

#[test]
fn sums() {
    assert_eq!(constant("sum(k, 1, 100, k)"), q(5050, 1));
    assert_eq!(
        constant("sum(k, 1, 10, 1/k^2)").to_string(),
        "1968329/1270080"
    );
    assert_eq!(constant("sum(k, 3, 2, k)"), q(0, 1));
    assert_eq!(constant("sum(k, -2, 2, k^3)"), q(0, 1));
    same("sum(i, 0, 3, x^i)", "1 + x + x^2 + x^3");
    same(
        "sum(i, 0, 2, sum(j, 0, i, x^i y^j))",
        "1 + x + x y + x^2 + x^2 y + x^2 y^2",
    );
    // The index shadows an outer variable of the same name in the body only.
    same("sum(k, 1, 2, k) + k", "3 + k");
    same("sum(k, 1, 2, sum(k, 0, 1, k))", "2");
    // Bounds from outer indices.
    assert_eq!(constant("sum(i, 1, 3, sum(j, 1, i, 1))"), q(6, 1));
    let mut v = Vars::new();
    let (f, g) = (
        ratfun("sum(k, 1, 2, 1/(x+k))", &mut v),
        ratfun("(2x+3)/((x+1)(x+2))", &mut v),
    );
    assert_eq!(
        (f.numerator(), f.denominator()),
        (g.numerator(), g.denominator())
    );
    assert_eq!(f.conditions().len(), 2, "x + 1 and x + 2");
}

#[test]
fn bernstein_partition_of_unity_and_binomials() {
    same("sum(i, 0, 3, binomial(3, i) t^i (1-t)^(3-i))", "1");
    same("sum(i, 0, 7, binomial(7, i) t^i (1-t)^(7-i))", "1");
    assert_eq!(constant("binomial(5, 2)"), q(10, 1));
    assert_eq!(constant("binomial(5, 0)"), q(1, 1));
    assert_eq!(constant("binomial(5, 6)"), q(0, 1));
    assert_eq!(constant("binomial(5, -1)"), q(0, 1));
    assert_eq!(constant("binomial(0, 0)"), q(1, 1));
    assert_eq!(constant("factorial(0) + factorial(1)"), q(2, 1));
    assert_eq!(constant("factorial(10)"), q(3_628_800, 1));
    assert_eq!(
        constant("binomial(100, 50)").to_string(),
        "100891344545564193334812497256"
    );
    assert_eq!(constant("binomial(10^30, 1)"), constant("10^30"));
    same("x^binomial(3, 1)", "x^3");
}

#[test]
fn bad_sums_and_integer_functions() {
    assert_eq!(
        err("sum(k, 0, 1/2, k)"),
        "sum at 10: the upper bound must be an integer constant, not 1/2"
    );
    assert!(err("sum(k, 0, n/2, k)").contains("must take integer values"));
    assert!(err("sum(k, 0, sqrt(n), k)").contains("must take integer values"));
    assert!(err("sum(k, 0, n*pi, k)").contains("not an expression in pi"));
    assert_eq!(
        err("sum(2, 0, 1, k)"),
        "sum at 4: the first argument must be a variable name, not 2"
    );
    assert_eq!(
        err("sum(k, 0, 1)"),
        "sum at 0: takes 4 arguments (index, from, to, expression), not 3"
    );
    assert_eq!(
        err("binomial(x, 2)"),
        "binomial at 9: n must be an integer constant, not x (it needs integer constants; \
         inside sum(k, a, b, ...) the index k is replaced by each integer first)"
    );
    assert_eq!(
        err("binomial(1/2, 2)"),
        "binomial at 9: n must be an integer constant, not 1/2"
    );
    assert_eq!(
        err("binomial(-3, 2)"),
        "binomial at 9: n must be a non-negative integer, not -3"
    );
    assert_eq!(
        err("factorial(-1)"),
        "factorial at 10: the factorial of a negative number (-1) is not defined"
    );
    assert_eq!(
        err("factorial(2, 3)"),
        "factorial at 0: takes 1 arguments (n), not 2"
    );
    assert!(err("sum(k, 0, 2, diff(k^2, k))").contains("differentiates by the summation index k"));
}

#[test]
fn limits_of_sums_and_integers() {
    let e = err("sum(k, 1, 10^6, k)");
    assert!(e.contains("exceeds the limit sum-terms = 100000"), "{e}");
    // Nested sums share the budget: 1000 * 1000 terms.
    let e = err("sum(i, 1, 1000, sum(j, 1, 1000, i j))");
    assert!(e.contains("exceeds the limit sum-terms"), "{e}");
    // A side-by-side pair is two budgets.
    assert_eq!(
        constant("sum(i, 1, 60000, 1) + sum(i, 1, 60000, 1)"),
        q(120_000, 1)
    );
    let e = err("factorial(10^6)");
    assert!(e.contains("exceeds the limit constant-bits"), "{e}");
    let e = err("factorial(10^30)");
    assert!(e.contains("exceeds the limit constant-bits"), "{e}");
    let e = err("binomial(10^7, 5*10^6)");
    assert!(e.contains("exceeds the limit constant-bits"), "{e}");
    let e = err("binomial(2^10000, 200)");
    assert!(e.contains("exceeds the limit constant-bits"), "{e}");
}

#[test]
fn factorial_sizes_are_predicted_exactly_from_below() {
    for m in 0..300u64 {
        let exact = calculus::factorial(&BigInt::from(m), 0).unwrap();
        let predicted = calculus::log2_factorial_floor(m);
        let direct: u64 = (2..=m).map(|i| 63 - u64::from(i.leading_zeros())).sum();
        assert_eq!(predicted, direct, "{m}");
        assert!(log2_floor(&exact) >= predicted, "{m}");
    }
    assert_eq!(
        calculus::log2_factorial_floor(u64::MAX),
        u64::MAX,
        "saturates"
    );
}

#[test]
fn power_sums_are_faulhaber_polynomials() {
    let sums = symbolic_sum::power_sums(4);
    // F_j(x) = 1^j + ... + x^j at x = 0..6 against the terms added one by one.
    for (j, f) in sums.iter().enumerate() {
        let mut total = Rational::ZERO;
        for x in 0..=6i64 {
            let xq = Rational::from(x);
            if x > 0 {
                total = &total + &xq.powi(j as i32).unwrap();
            }
            let value = f
                .iter()
                .rev()
                .fold(Rational::ZERO, |acc, c| &(acc * &xq) + c);
            assert_eq!(value, total, "F_{j}({x})");
        }
    }
    // F_3(x) = x^2 (x + 1)^2 / 4.
    assert_eq!(sums[3], [q(0, 1), q(0, 1), q(1, 4), q(1, 2), q(1, 4)]);
}

#[test]
fn sums_to_a_symbolic_bound_are_closed_forms() {
    let cases = [
        ("sum(k, 1, n, k)", "n*(n + 1)/2"),
        ("sum(k, 1, n, k^2)", "n*(n + 1)*(2*n + 1)/6"),
        ("sum(k, 1, n, k^3)", "n^2*(n + 1)^2/4"),
        ("sum(k, 1, n, 2*k - 1)", "n^2"),
        ("sum(k, m, n, k)", "(n - m + 1)*(n + m)/2"),
        ("sum(k, 0, 2*n, x*k)", "x*n*(2*n + 1)"),
        ("sum(k, 1, n, sum(j, 1, k, 1))", "n*(n + 1)/2"),
        ("sum(k, 1, n, sum(j, k, n, 1))", "n*(n + 1)/2"),
    ];
    for (sum, closed) in cases {
        same(sum, closed);
    }
    // With a constant upper bound the closed form is the sum the terms give.
    for n in 0..5 {
        let mut vars = Vars::new();
        let p = poly("sum(k, 1, n, k^4 - 3*k)", &mut vars);
        let nv = vars.get("n").unwrap();
        let at = p.substitute(nv, &P::constant(Rational::from(n as i64)));
        let unrolled = poly(&format!("sum(k, 1, {n}, k^4 - 3*k)"), &mut vars);
        assert_eq!(at, unrolled, "n = {n}");
    }
    // A denominator free of the index.
    let mut vars = Vars::new();
    let f = ratfun("sum(k, 1, n, k/m)", &mut vars);
    let g = ratfun("n*(n + 1)/(2*m)", &mut vars);
    assert_eq!(f, g);
    // A wrong closed form is a different polynomial.
    let mut vars = Vars::new();
    assert_ne!(
        poly("sum(k, 1, n, k^3)", &mut vars),
        poly("n^2*(n + 1)^2/2", &mut vars)
    );
}

#[test]
fn sums_that_are_not_polynomial_in_the_index_are_refused() {
    for (text, says) in [
        (
            "sum(k, 0, n, x^k)",
            "the exponent of x^k depends on the summation index k",
        ),
        (
            "sum(k, 0, n, binomial(k, 2))",
            "binomial(k, 2) depends on the summation index k",
        ),
        ("sum(k, 1, n, 1/k)", "divides by an expression in k"),
        (
            "sum(k, 0, n, sum(j, 2, k, j))",
            "is not shown to be non-empty",
        ),
    ] {
        let e = err(text);
        assert!(e.contains(says), "{text}: {e}");
        assert!(!e.contains('\n'), "{text}: {e}");
    }
}

#[test]
fn a_variable_bound_inside_is_no_variable_to_differentiate_or_integrate_in() {
    for (text, names) in [
        ("diff(sum(k, 1, n, k^2), k)", "k is not a free variable"),
        (
            "diff(integrate(t^2, t, 0, x), t)",
            "the variable of an integral",
        ),
        (
            "diff(sum(j, 1, n, sum(k, 1, j, k)), k)",
            "only the index of a sum",
        ),
        (
            "integrate(sum(k, 1, n, k), k, 0, 1)",
            "k is not a free variable",
        ),
        ("diff(sum(k, 1, 3, k*x), k)", "k is not a free variable"),
    ] {
        let e = err(text);
        assert!(e.contains(names) && !e.contains('\n'), "{text}: {e}");
        assert!(lower(&parse_expr(text).unwrap()).is_err(), "{text}");
    }
    // Free as well as bound: the derivative by the free one.
    let mut v = Vars::new();
    let d = ratfun("diff(k*sum(k, 1, 3, k), k)", &mut v);
    assert_eq!(d, ratfun("6", &mut v));
    // A variable that does not occur at all: the derivative is 0, as before.
    assert_eq!(ratfun("diff(x^2, y)", &mut v), ratfun("0", &mut v));
}
