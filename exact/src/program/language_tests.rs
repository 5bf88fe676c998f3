//! Tests of the formula front end with the whole expression language: the library's functions
//! and the core calls, lowered before compilation.
use super::*;
use crate::expr::library::{self, Val};
use crate::poly::Vars;
use crate::program::ExactStop;
use crate::ratfun::RatFun;
use proptest::prelude::*;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

/// The values of `names` at `point` (by name), in the order of `names`.
fn values_at(names: &[String], point: &[(&str, Rational)]) -> Vec<Rational> {
    names
        .iter()
        .map(|n| {
            point
                .iter()
                .find(|(m, _)| m == n)
                .map(|(_, v)| v.clone())
                .unwrap_or_else(|| panic!("no value for {n}"))
        })
        .collect()
}

/// The value of `text` at `point` (by name) through the `prove` path: resolved by the library,
/// converted to a rational function in lowest terms, numerator and denominator evaluated.
/// `None` at a pole.
fn prove_value(text: &str, point: &[(&str, Rational)]) -> Option<Rational> {
    let Val::Scalar(e) = library::resolve(text).unwrap() else {
        panic!("{text} is not a scalar")
    };
    let mut vars = Vars::new();
    let f: RatFun<Rational> = e.to_ratfun(&mut vars).unwrap();
    let values = values_at(vars.names(), point);
    let num = f.numerator().eval(&values, Clone::clone);
    let den = f.denominator().eval(&values, Clone::clone);
    if den == Rational::ZERO {
        None
    } else {
        Some(num / den)
    }
}

/// The exact value of the compiled program at `point` (by name); `None` outside the domain.
fn program_value(p: &Program, point: &[(&str, Rational)]) -> Option<Rational> {
    let x = values_at(&p.inputs, point);
    match p.eval_exact(&x) {
        Ok(r) => {
            assert!(r[0].exact, "{}: not exact", p.name);
            Some(Rational::from(r[0].value.clone()))
        }
        Err(ExactStop::OutsideDomain) => None,
        Err(e) => panic!("{}: {e:?}", p.name),
    }
}

const FORMULAS: &[&str] = &[
    "diff(t^3/(1+t), t)",
    "diff(x^2 y + y^3, x, 2) - 2 y",
    "sum(k, 0, 4, binomial(4, k) x^k y^(4 - k))",
    "factorial(5) / binomial(6, 2) * x",
    "det([[x, 2], [3, y]])",
    "det([[x, 1, 0], [1, y, 1], [0, 1, x]])",
    "dot([x, y], [y, 1]) + norm2([x - 1, y])",
    "cross([x, y], [1, 2])",
    "dot(cross([x, y, 1], [2, x, y]), [1, 2, 3])",
    "bezier(t, 1, 3, x)",
    "x(bezier(t, [0, 0], [1, 2], [3, x]))",
    "integrate(x t^2 + 1, t, 0, y)",
    "((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2",
    "subs(x^2 + y, x, t + 1)",
    "at(transpose([[1, x], [y, 2]]) * [1, 1], 2)",
];

#[test]
fn library_formulas_compile_to_their_exact_value() {
    let points = [
        [("x", q(3, 2)), ("y", q(-2, 3)), ("t", q(5, 4))],
        [("x", q(-7, 1)), ("y", q(1, 8)), ("t", q(-3, 16))],
    ];
    for text in FORMULAS {
        let p = Program::parse(text, None).unwrap_or_else(|e| panic!("{text}: {e}"));
        for point in &points {
            assert_eq!(
                program_value(&p, point),
                prove_value(text, point),
                "{text} at {point:?}"
            );
        }
    }
}

#[test]
fn the_lowered_tree_is_what_both_sides_evaluate() {
    // The derivative is expanded (3 t^2), the sum unrolled, binomial folded.
    let p = Program::parse("diff(t^3, t) + sum(k, 1, 2, k t) + binomial(4, 2)", None).unwrap();
    assert_eq!(p.inputs, vec!["t".to_string()]);
    assert_eq!(p.eval_f64(&[2.0]), vec![12.0 + 6.0 + 6.0]);
    // A user-written division stays a division (1/3 is not folded).
    let p = Program::parse("det([[x, 1], [1, 3]]) / 3", None).unwrap();
    assert_eq!(p.eval_f64(&[1.0]), vec![(1.0 * 3.0 - 1.0) / 3.0]);
}

#[test]
fn the_inputs_are_the_variables_as_written() {
    for (text, inputs) in [
        ("diff(x^2, y) + z", &["x", "y", "z"][..]),
        ("sum(k, 1, 3, k x)", &["x"]),
        ("det([[a, b], [c, d]])", &["a", "b", "c", "d"]),
        ("subs(x^2 + y, x, t + 1)", &["y", "t"]),
    ] {
        let p = Program::parse(text, None).unwrap();
        assert_eq!(p.inputs, inputs, "{text}");
    }
    let p = Program::parse("diff(x^2, y) + z", None).unwrap();
    assert_eq!(p.eval_f64(&[1.0, 2.0, 3.0]), vec![3.0]);
}

#[test]
fn an_integral_with_a_root_in_a_bound_is_lowered_by_its_antiderivative() {
    let p = Program::parse("integrate(t^2, t, 0, sqrt(x))", None).unwrap();
    assert_eq!(program_value(&p, &[("x", q(4, 1))]), Some(q(8, 3)));
    let v = p.eval_f64(&[2.0])[0];
    assert!((v - 2f64.sqrt() * 2.0 / 3.0).abs() < 1e-15, "{v}");
}

#[test]
fn a_vector_value_is_one_output_per_coordinate() {
    let p = Program::parse("[x - y, x*y]", None).unwrap();
    assert_eq!(p.inputs, ["x", "y"]);
    assert_eq!(p.outputs.len(), 2);
    assert_eq!(p.eval_f64(&[3.0, 2.0]), vec![1.0, 6.0]);
    let p = Program::parse("cross([x, y, 1], [1, 2, 3])", None).unwrap();
    assert_eq!(p.eval_f64(&[1.0, 1.0]), vec![1.0, -2.0, 1.0]);
    let e = Program::parse("transpose([[x]])", None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the formula is a 1x1 matrix; a regressed formula has a scalar value or a vector of \
         outputs (take a row, e.g. at(M, 1), or give each output as its own --formula)"
    );
    assert!(matches!(e, CompileError::NotScalar { .. }), "{e}");
}

#[test]
fn several_formulas_are_the_outputs_of_one_program() {
    let texts = ["a*b".to_string(), "vec(b - c, a)".to_string()];
    let p = Program::parse_outputs(&texts, None).unwrap();
    assert_eq!(p.inputs, ["a", "b", "c"]);
    assert_eq!(p.name, "a*b; vec(b - c, a)");
    assert_eq!(p.eval_f64(&[2.0, 3.0, 5.0]), vec![6.0, -2.0, 2.0]);
    let vars = ["c".to_string(), "b".to_string(), "a".to_string()];
    let p = Program::parse_outputs(&texts, Some(&vars)).unwrap();
    assert_eq!(p.eval_f64(&[5.0, 3.0, 2.0]), vec![6.0, -2.0, 2.0]);
    // An error names the formula it is in.
    let bad = ["x".to_string(), "y +".to_string()];
    let e = Program::parse_outputs(&bad, None).unwrap_err();
    assert!(e.starts_with("formula 2: "), "{e}");
}

#[test]
fn constants_are_not_variables() {
    for (text, name, pos) in [("x + e", "e", 4), ("i*x", "i", 0)] {
        let e = Program::parse(text, None).unwrap_err();
        assert!(
            matches!(&e, CompileError::Reserved { name: n, pos: p, .. } if n == name && *p == pos),
            "{text}: {e}"
        );
        assert!(!e.to_string().contains('\n'));
    }
    let e = Program::parse("pi", Some(&["pi".to_string()])).unwrap_err();
    assert_eq!(
        e.to_string(),
        "\"pi\" in the variable list is not a variable name"
    );
    // pi is the constant: not an input, also inside a derivative, whose expansion keeps it
    for text in ["2 pi x", "diff(pi x^2, x)"] {
        let p = Program::parse(text, None).unwrap();
        assert_eq!(p.inputs, ["x"], "{text}");
    }
    assert!(Program::parse("pi", None).unwrap().inputs.is_empty());
    // the elementary functions pass the library's resolution as calls
    let p = Program::parse("exp(x) + log(y) + atan2(x, y)", None).unwrap();
    assert_eq!(p.inputs, ["x", "y"]);
}

#[test]
fn bad_calls_are_one_line_errors() {
    for (text, needle) in [
        ("integrate(sqrt(t), t, 0, x)", "which changes with t"),
        ("integrate(1/t, t, 1, 2)", "divides by an expression in t"),
        ("sum(k, 0, 1/2, k)", "must be an integer constant"),
        ("binomial(x, 2)", "must be an integer constant"),
        ("diff(x^2, 2)", "must be a variable name"),
        ("det([[1, 2, 3], [4, 5, 6]])", "det"),
        ("nosuch(x)", "nosuch"),
        ("1/(x - x) + diff(1/(y - y), y)", "identically zero"),
    ] {
        let e = Program::parse(text, None).unwrap_err().to_string();
        assert!(e.contains(needle), "{text}: {e}");
        assert!(!e.contains('\n'), "{text}: {e}");
    }
}

#[test]
fn a_sum_beyond_the_node_bound_is_refused() {
    let e = Program::parse(
        "sum(i, 1, 300, sum(j, 1, 300, (x + i)^2 * (y + j)^2))",
        None,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("more than"), "{e}");
}

/// A formula of the library with small integer coefficients and no division: its value at a
/// small integer point is an integer far below 2^53, so every f64 operation is exact.
fn integer_formula() -> impl Strategy<Value = String> {
    let c = || -9i64..=9;
    prop_oneof![
        (c(), 0u32..5)
            .prop_map(|(a, n)| format!("sum(k, 0, {n}, binomial({n}, k) x^k * ({a})^({n} - k))")),
        (c(), c(), c(), c(), c()).prop_map(|(a, b, cc, d, e)| format!(
            "det([[{a} x + {b}, {cc}], [{d}, x^2 + ({e}) y]])"
        )),
        (c(), c(), c())
            .prop_map(|(a, b, cc)| format!("dot([x, {a}], [y, ({b}) x]) + norm2([x - ({cc}), y])")),
        (c(), c()).prop_map(|(a, b)| format!(
            "dot(cross([x, y, {a}], [{b}, x, y]), [1, 2, 3]) + cross([x, 1], [y, {a}])"
        )),
        (c(), c(), c()).prop_map(|(a, b, cc)| format!("bezier(x, {a}, {b}, {cc}) * y")),
        (c(), c(), 0u32..4)
            .prop_map(|(a, b, k)| format!("diff(({a}) x^4 + ({b}) x^2 y + x y^3, x, {k})")),
        (c(), c()).prop_map(|(a, b)| format!(
            "factorial(4) x - binomial(6, 3) ({a}) y + integrate(2 ({b}) t, t, 0, x)"
        )),
    ]
}

/// A formula of the library that may divide by a non-constant.
fn rational_formula() -> impl Strategy<Value = String> {
    let c = || -9i64..=9;
    prop_oneof![
        integer_formula(),
        (c(), c(), c()).prop_map(|(a, b, cc)| format!(
            "diff((({a}) x^3 + ({b}) x y) / (({cc})^2 + 1 + x^2), x)"
        )),
        (c(), c())
            .prop_map(|(a, b)| format!("integrate(({a}) t^2 + ({b}) x t / (1 + y^2), t, x, y)")),
        (c(), c(), 1u32..4)
            .prop_map(|(a, b, n)| format!("sum(k, 1, {n}, ({a}) x^k / (k + ({b})^2 + y^2))")),
        (c(), c()).prop_map(|(a, b)| format!(
            "det([[1/(x^2 + 1), {a}], [{b}, y]]) - diff(x/(y^2 + 2), y, 2)"
        )),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The f64 side evaluates the lowered tree: at integer points where every operation is
    /// exact in f64 it equals the exact value (computed by the independent `prove` path).
    #[test]
    fn float_side_of_integer_formulas_is_exact(
        text in integer_formula(),
        x in -5i64..=5,
        y in -5i64..=5,
    ) {
        let p = Program::parse(&text, None).unwrap();
        let point = [("x", q(x, 1)), ("y", q(y, 1))];
        let exact = prove_value(&text, &point).unwrap();
        let args: Vec<f64> = p
            .inputs
            .iter()
            .map(|n| if n == "x" { x as f64 } else { y as f64 })
            .collect();
        let float = p.eval_f64(&args)[0];
        prop_assert!(float.is_finite(), "{}", text);
        let float = Rational::from(num_rational::BigRational::from_float(float).expect("finite"));
        prop_assert_eq!(float, exact, "{}", text);
    }

    /// The exact side of every lowered formula is its value through the `prove` path, at
    /// dyadic points (the inputs of a regression); a pole is a pole on both.
    #[test]
    fn exact_side_is_the_prove_value(
        text in rational_formula(),
        x in -1000i64..=1000,
        y in -1000i64..=1000,
        shift in 0u32..6,
    ) {
        let p = Program::parse(&text, None).unwrap();
        let point = [("x", q(x, 1 << shift)), ("y", q(y, 1 << (5 - shift)))];
        prop_assert_eq!(program_value(&p, &point), prove_value(&text, &point), "{}", text);
    }

    /// The lowered derivative of a root against the chain rule written by hand, at the points
    /// `x = (m^2 - 1)/(2m)` where `sqrt(1 + x^2) = (m^2 + 1)/(2m)` is rational, so the exact side
    /// of the program is a rational number.
    #[test]
    fn exact_side_of_a_lowered_root_derivative_is_the_chain_rule(
        a in -9i64..=9,
        b in -9i64..=9,
        c in -9i64..=9,
        m in 2i64..=40,
    ) {
        let text = format!("diff(({a} x + {b}) sqrt(1 + x^2) + {c} x^2, x)");
        let p = Program::parse(&text, None).unwrap();
        let x = q(m * m - 1, 2 * m);
        let root = q(m * m + 1, 2 * m);
        // d/dx (a x + b) s = a s + (a x + b) x / s, d/dx c x^2 = 2 c x.
        let by_hand = q(a, 1) * root.clone()
            + (q(a, 1) * x.clone() + q(b, 1)) * x.clone() / root
            + q(2 * c, 1) * x.clone();
        prop_assert_eq!(program_value(&p, &[("x", x)]), Some(by_hand), "{}", text);
    }
}
