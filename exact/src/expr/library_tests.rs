//! Tests of the function library: definitions, functions with parameters, vectors, matrices.

use super::*;
use crate::poly::Vars;
use proptest::prelude::*;

fn defs(list: &[(&str, &str)]) -> Defs {
    Defs::new(
        list.iter()
            .map(|(n, t)| {
                let text = if let Some(inner) = t.strip_prefix('{') {
                    DefText::Vector(
                        inner
                            .trim_end_matches('}')
                            .split(';')
                            .map(str::to_string)
                            .collect(),
                    )
                } else {
                    DefText::Scalar(t.to_string())
                };
                (n.to_string(), text)
            })
            .collect(),
    )
    .unwrap()
}

fn poly(d: &mut Defs, text: &str) -> String {
    let e = d.resolve_scalar(text).unwrap();
    let mut vars = Vars::new();
    let p = e.to_poly::<Rational>(&mut vars).unwrap();
    p.display(&vars).to_string()
}

/// Whether `a` and `b` resolve to the same polynomial (variables named alike).
fn same(d: &mut Defs, a: &str, b: &str) -> bool {
    let (a, b) = (d.resolve_scalar(a).unwrap(), d.resolve_scalar(b).unwrap());
    let mut vars = Vars::new();
    let pa = a.to_poly::<Rational>(&mut vars).unwrap();
    let pb = b.to_poly::<Rational>(&mut vars).unwrap();
    pa == pb
}

fn message(d: &mut Defs, text: &str) -> String {
    d.resolve_text(text).unwrap_err().message
}

#[test]
fn vectors_and_functions() {
    let mut d = defs(&[
        ("u", "{1;2;3}"),
        ("v", "{x0;y0;z0}"),
        ("w", "cross(u, v)"),
        ("A", "2*B"),
        ("B", "t + 1"),
    ]);
    assert_eq!(poly(&mut d, "dot(u, v)"), poly(&mut d, "x0 + 2*y0 + 3*z0"));
    assert_eq!(poly(&mut d, "dot(w, u)"), "0");
    assert_eq!(poly(&mut d, "dot(w, v)"), "0");
    assert_eq!(poly(&mut d, "norm2(u)"), "14");
    assert_eq!(poly(&mut d, "at(2*u - v, 3) + z(v)"), "6");
    assert_eq!(poly(&mut d, "A"), poly(&mut d, "2*t + 2"));
    assert_eq!(poly(&mut d, "subs(A, t, 3)"), "8");
    assert!(same(&mut d, "bezier(s, 0, 1, 1)", "2*s - s^2"));
    assert!(same(&mut d, "bernstein(1, 3, s)", "3*s*(1 - s)^2"));
    let b = d.resolve_text("bezier(s, u, v)").unwrap();
    assert_eq!(b.components().len(), 3);
}

#[test]
fn the_library_without_definitions() {
    let mut d = Defs::default();
    assert!(same(&mut d, "dot(vec(a, b), vec(a, b))", "a^2 + b^2"));
    assert!(same(
        &mut d,
        "norm2(bezier(t, vec(1, 0), vec(1, 1), vec(0, 1)))",
        "(1 - t^2)^2 + (2*t - t^2)^2"
    ));
    assert!(same(&mut d, "cross([a, b], [c, e])", "a*e - b*c"));
    assert!(same(&mut d, "norm2([a, b, c])", "a^2 + b^2 + c^2"));
    assert!(matches!(resolve("[1, 2]").unwrap(), Val::Vector(v) if v.len() == 2));
}

#[test]
fn matrices() {
    let mut d = defs(&[("M", "[[a, b], [c, e]]"), ("N", "[[p, q], [r, s]]")]);
    assert!(same(&mut d, "det(M)", "a*e - b*c"));
    assert!(same(&mut d, "det(M*N)", "det(M)*det(N)"));
    assert!(same(&mut d, "det(transpose(M))", "det(M)"));
    assert!(same(&mut d, "det(2*M)", "4*det(M)"));
    assert!(same(&mut d, "at(M*[1, 0], 2)", "c"));
    assert!(same(&mut d, "det(M + N - N)", "det(M)"));
    assert!(same(&mut d, "det(M/2)", "det(M)/4"));
    assert!(same(
        &mut d,
        "det([[1, 2, 3], [4, 5, 6], [7, 8, 10]])",
        "-3"
    ));
    assert!(same(&mut d, "det([[0, 0], [0, 0]])", "0"));
    let mt = d.resolve_text("transpose([[1, 2, 3], [4, 5, 6]])").unwrap();
    assert_eq!(mt.shape(), "a 3x2 matrix");
    let p = d
        .resolve_text("[[1, 2, 3], [4, 5, 6]] * [[1], [2], [3]]")
        .unwrap();
    assert_eq!(p.shape(), "a 2x1 matrix");
    assert_eq!(
        d.resolve_text("[[1, 2], [3, 4]] * [x, y]").unwrap().shape(),
        "a vector of 2"
    );
}

#[test]
fn shape_errors_name_both_shapes() {
    let mut d = Defs::default();
    let m = |t: &str| message(&mut Defs::default(), t);
    assert!(m("det([[1, 2, 3], [4, 5, 6]])")
        .contains("det at 0 takes a square matrix, not a 2x3 matrix"));
    assert!(m("[[1, 2], [3, 4]] * [1, 2, 3]").contains(
        "a product of a 2x2 matrix at 0 and a vector of 3 at 19: the sizes do not match"
    ));
    assert!(m("[[1, 2], [3, 4]] + [[1, 2, 3], [4, 5, 6]]")
        .contains("a 2x3 matrix at 19 added to a 2x2 matrix"));
    assert!(m("[[1, 2], [3]]")
        .contains("row 2 of the matrix at 0 (at 9) is a vector of 1, row 1 a vector of 2"));
    assert!(m("[1, [2, 3]]").contains("a vector of 2 at 4 in a list of scalars"));
    assert!(m("det([1, 2])").contains("a vector of 2 at 4 where a matrix is expected"));
    assert!(m("cross([1, 2], [1, 2, 3])").contains("not vectors of 2 and 3"));
    assert!(m("[1, 2] * [[1, 2], [3, 4]]").contains("write transpose(M)*v"));
    assert!(m("1 / [[1, 2], [3, 4]]").contains("division by a 2x2 matrix at 4"));
    assert!(d
        .resolve_scalar("[[1]]")
        .unwrap_err()
        .message
        .contains("a 1x1 matrix where a scalar is expected"));
    assert!(m("[1, 2").contains("unexpected end of input at 5: expected an operator, ',' or ']'"));
    // The grammar without calls has no lists.
    assert!(crate::expr::parse_expr("[1]").is_err());
}

#[test]
fn a_huge_determinant_is_refused_before_it_is_built() {
    let n = 12;
    let rows: Vec<String> = (0..n)
        .map(|i| {
            let r: Vec<String> = (0..n).map(|j| format!("a{i}_{j}")).collect();
            format!("[{}]", r.join(", "))
        })
        .collect();
    let text = format!("det([{}])", rows.join(", "));
    let e = message(&mut Defs::default(), &text);
    assert!(
        e.contains("det at 0 of a 12x12 matrix") && e.contains("MAX_NODES"),
        "{e}"
    );
}

#[test]
fn functions_with_parameters() {
    let mut d = defs(&[
        ("f(t)", "t^2 + c"),
        ("cross2(u, v)", "x(u)*y(v) - y(u)*x(v)"),
        ("g(t)", "f(t) + f(2*t)"),
        ("P(t)", "bezier(t, vec(0, 0), vec(1, 2), vec(3, 3))"),
        ("c", "5"),
        ("t", "100"),
        ("area(M)", "det(M)/2"),
    ]);
    d.resolve_all().unwrap();
    assert!(same(&mut d, "f(s)", "s^2 + 5"));
    // The parameter t shadows the definition t = 100; outside f it is that definition.
    assert!(same(&mut d, "f(1)", "6"));
    assert!(same(&mut d, "f(t)", "10005"));
    assert!(same(&mut d, "g(s)", "5*s^2 + 10"));
    assert!(same(&mut d, "cross2(vec(a, b), vec(p, q))", "a*q - b*p"));
    assert!(same(&mut d, "cross2(P(s), P(s))", "0"));
    assert!(same(&mut d, "area([[2, 0], [0, 3]])", "3"));
    assert!(same(&mut d, "f(f(1))", "41"));
    assert_eq!(d.resolve_text("P(s)").unwrap().shape(), "a vector of 2");
}

#[test]
fn function_errors() {
    let mut d = defs(&[
        ("f(t)", "t^2"),
        ("loop(t)", "back(t) + 1"),
        ("back(t)", "loop(t)"),
        ("A", "3"),
        ("h(v)", "v^2"),
    ]);
    assert!(message(&mut d, "f(1, 2)").contains("f at 0 takes 1 argument, not 2"));
    assert!(message(&mut d, "f + 1").contains("f at 0 is a function: call it with 1 argument"));
    assert!(message(&mut d, "A(2)").contains("A at 0 is a defined name without parameters"));
    let e = d.resolve_text("loop(1)").unwrap_err();
    assert_eq!(e.def.as_deref(), Some("loop"));
    assert!(e.message.contains("loop -> back -> loop"), "{}", e.message);
    let e = d.resolve_text("h([1, 2])").unwrap_err();
    assert_eq!(e.def.as_deref(), Some("h"));
    assert!(
        e.message.starts_with("in h (called at 0): a vector of 2"),
        "{}",
        e.message
    );
    let bad = |head: &str| {
        Defs::new(vec![(head.to_string(), DefText::Scalar("1".into()))])
            .err()
            .unwrap()
            .1
    };
    assert!(bad("dot(u, v)").contains("dot is a function of the language"));
    assert!(bad("diff(u)").contains("diff is a function of the language"));
    assert!(bad("f(t, t)").contains("the parameter t appears twice"));
    assert!(bad("f(t").contains("is not a name"));
    assert!(bad("f()").contains("is not a name"));
    assert!(bad("2f(t)").contains("is not a name"));
    assert!(bad("sqrt").contains("square root"));
    let twice = Defs::new(vec![
        ("f".to_string(), DefText::Scalar("1".into())),
        ("f(t)".to_string(), DefText::Scalar("t".into())),
    ]);
    assert!(twice.err().unwrap().1.contains("f is defined twice"));
}

#[test]
fn errors_name_what_is_wrong() {
    let mut d = defs(&[("u", "{1;2;3}"), ("P", "Q + 1"), ("Q", "2*P")]);
    assert!(message(&mut d, "exp(x)").contains("unknown function 'exp' at 0"));
    assert!(message(&mut d, "dot(u)").contains("dot at 0 takes 2 arguments, not 1"));
    assert!(message(&mut d, "u*u").contains("product of two vectors"));
    assert!(d
        .resolve_scalar("u + u")
        .unwrap_err()
        .message
        .contains("a vector of 3 where a scalar is expected"));
    assert!(message(&mut d, "1 + u").contains("a scalar at 0 added to a vector of 3"));
    let e = d.resolve_text("P").unwrap_err();
    assert_eq!(e.def.as_deref(), Some("P"));
    assert!(e.message.contains("P -> Q -> P"), "{}", e.message);
}

#[test]
fn expansion_is_bounded() {
    let mut list = vec![("a0".to_string(), DefText::Scalar("x".into()))];
    for k in 1..30 {
        list.push((
            format!("a{k}"),
            DefText::Scalar(format!("a{0} + a{0}", k - 1)),
        ));
    }
    let mut d = Defs::new(list).unwrap();
    let e = d.resolve_text("a29").unwrap_err();
    assert!(e.message.contains("MAX_NODES"), "{}", e.message);
}

#[test]
fn a_list_prints_as_written() {
    let e = crate::expr::parse_expr_with_calls("[[a, b], [c, 1]]").unwrap();
    assert_eq!(e.to_string(), "[[a, b], [c, 1]]");
}

/// The determinant by Gaussian elimination over the rationals: an independent path.
fn det_by_elimination(m: &[Vec<i64>]) -> Rational {
    let n = m.len();
    let mut a: Vec<Vec<Rational>> = m
        .iter()
        .map(|r| r.iter().map(|&x| Rational::from_integer(x)).collect())
        .collect();
    let mut det = Rational::from_integer(1);
    for k in 0..n {
        let Some(p) = (k..n).find(|&i| a[i][k] != Rational::ZERO) else {
            return Rational::ZERO;
        };
        if p != k {
            a.swap(p, k);
            det = -det;
        }
        let pivot = a[k][k].clone();
        det *= pivot.clone();
        let row_k = a[k].clone();
        for row in a.iter_mut().skip(k + 1) {
            let f = row[k].clone() / pivot.clone();
            for (x, y) in row.iter_mut().zip(&row_k).skip(k) {
                *x = x.clone() - y.clone() * f.clone();
            }
        }
    }
    det
}

fn matrix_text(m: &[Vec<i64>]) -> String {
    let rows: Vec<String> = m
        .iter()
        .map(|r| {
            let r: Vec<String> = r.iter().map(i64::to_string).collect();
            format!("[{}]", r.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

fn square(max_n: usize) -> impl Strategy<Value = Vec<Vec<i64>>> {
    (1..=max_n)
        .prop_flat_map(|n| proptest::collection::vec(proptest::collection::vec(-9i64..=9, n), n))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// `det` (cofactor expansion) agrees with elimination over Q on small integer matrices,
    /// with zeros frequent enough to exercise the skipped entries.
    #[test]
    fn det_agrees_with_elimination(m in square(5)) {
        let e = resolve(&format!("det({})", matrix_text(&m))).unwrap();
        let Val::Scalar(e) = e else { panic!("det is a scalar") };
        prop_assert_eq!(e.eval_constant::<Rational>().unwrap(), det_by_elimination(&m));
    }

    /// det(A B) = det(A) det(B) and det(A^T) = det(A) through the library's products.
    #[test]
    fn det_is_multiplicative((a, b) in (1..=4usize).prop_flat_map(|n| {
        let m = proptest::collection::vec(proptest::collection::vec(-9i64..=9, n), n);
        (m.clone(), m)
    })) {
        let (ta, tb) = (matrix_text(&a), matrix_text(&b));
        let q = |t: String| match resolve(&t).unwrap() {
            Val::Scalar(e) => e.eval_constant::<Rational>().unwrap(),
            v => panic!("{}", v.shape()),
        };
        prop_assert_eq!(
            q(format!("det({ta}*{tb})")),
            det_by_elimination(&a) * det_by_elimination(&b)
        );
        prop_assert_eq!(q(format!("det(transpose({ta}))")), det_by_elimination(&a));
    }
}

/// The rational function `text` resolves to, as `numerator / denominator` (named alike).
fn fraction(d: &mut Defs, text: &str) -> String {
    let e = d.resolve_scalar(text).unwrap();
    let mut vars = Vars::new();
    let f = e.to_ratfun::<Rational>(&mut vars).unwrap();
    format!(
        "{} / {}",
        f.numerator().display(&vars),
        f.denominator().display(&vars)
    )
}

#[test]
fn subs_differentiates_before_substituting() {
    let mut d = defs(&[]);
    assert_eq!(poly(&mut d, "subs(diff(t^3 + a*t^2 + b*t, t), t, 0)"), "b");
    assert!(same(
        &mut d,
        "subs(diff(t^3 + a*t^2 + b*t, t, 2), t, 2)",
        "12 + 2*a"
    ));
    assert_eq!(
        fraction(&mut d, "subs(diff(1/(1 + t), t), t, 1)"),
        "-1/4 / 1"
    );
    // A value that mentions the variable of diff: d/dt (x t^2) = 2 x t, then x = t.
    assert!(same(&mut d, "subs(diff(x*t^2, t), x, t)", "2*t^2"));
    // Another variable: the substitution commutes with diff.
    assert!(same(&mut d, "subs(diff(x*t^2, t), x, 3)", "6*t"));
}

#[test]
fn subs_respects_bound_variables() {
    let mut d = defs(&[]);
    // The index of sum is bound: subs(..., k, 5) leaves it; the value k is not captured.
    assert!(same(&mut d, "subs(sum(k, 1, 3, k*x), k, 5)", "6*x"));
    assert!(same(&mut d, "subs(sum(k, 1, 3, k*x), x, k)", "6*k"));
    assert!(same(&mut d, "subs(sum(k, 1, n, k), n, 4)", "10"));
    // The variable of integrate is bound; its bounds are not.
    assert!(same(
        &mut d,
        "subs(integrate(t*x, t, 0, b), t, 7)",
        "x*b^2/2"
    ));
    assert!(same(&mut d, "subs(integrate(t*x, t, 0, b), b, 2)", "2*x"));
    assert!(same(&mut d, "subs(integrate(x, t, 0, 1), x, t)", "t"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// `subs(diff(E, t, k), t, a)` against the independent path: `E` converted, differentiated
    /// `k` times as a polynomial, then evaluated at `t = a`.
    #[test]
    fn subs_of_diff_is_the_derivative_at_the_value(
        coeffs in proptest::collection::vec(-5i64..=5, 9),
        k in 1u32..=2,
        (an, ad) in (-6i64..=6, 1i64..=4),
    ) {
        let terms: Vec<String> = coeffs
            .iter()
            .enumerate()
            .map(|(i, c)| format!("({c})*t^{}*x^{}", i / 3, i % 3))
            .collect();
        let e = terms.join(" + ");
        let mut d = defs(&[]);
        let got = d
            .resolve_scalar(&format!("subs(diff({e}, t, {k}), t, {an}/{ad})"))
            .unwrap();
        let mut vars = Vars::from_names(["t", "x"]);
        let got = got.to_poly::<Rational>(&mut vars).unwrap();
        let mut p = crate::expr::parse_expr(&e).unwrap().to_poly::<Rational>(&mut vars).unwrap();
        for _ in 0..k {
            p = crate::ratfun::poly_derivative(&p, 0);
        }
        let a = Rational::new(an, ad).unwrap();
        let want = p.substitute(0, &crate::poly::Poly::constant(a));
        prop_assert_eq!(got, want);
    }
}

#[test]
fn calculus_of_a_vector_or_matrix_is_taken_per_component() {
    let texts = |v: &Val| -> Vec<String> { v.components().iter().map(|e| e.to_string()).collect() };
    let d = resolve("diff([t^2, t^3], t)").unwrap();
    assert_eq!(d.dims(), Shape::Vector(2));
    assert_eq!(
        texts(&d),
        texts(&resolve("[diff(t^2, t), diff(t^3, t)]").unwrap())
    );
    let i = resolve("integrate([[1, t], [t^2, 0]], t, 0, u)").unwrap();
    assert_eq!(i.dims(), Shape::Matrix(2, 2));
    assert_eq!(
        texts(&i)[2],
        resolve("integrate(t^2, t, 0, u)").unwrap().components()[0].to_string()
    );
    let s = resolve("sum(k, 0, 2, [k, k^2, 1])").unwrap();
    assert_eq!(s.dims(), Shape::Vector(3));
    // Only the body may be a vector: the variable and the bounds are scalars.
    let e = resolve("integrate(t, t, 0, [1, 2])").unwrap_err();
    assert!(e.message.contains("a vector of 2"), "{}", e.message);
    assert!(resolve("binomial([1, 2], 1)").is_err());
}

#[test]
fn components_are_named_by_their_shape() {
    assert_eq!(Shape::Scalar.component(0), "");
    assert_eq!(Shape::Vector(2).component(1), "component 2 (y)");
    assert_eq!(Shape::Vector(3).component(2), "component 3 (z)");
    assert_eq!(Shape::Vector(4).component(3), "component 4");
    assert_eq!(Shape::Matrix(2, 3).component(4), "entry (2, 2)");
    assert_eq!(Shape::Matrix(2, 3).len(), 6);
    assert_eq!(Shape::Matrix(2, 3).to_string(), "a 2x3 matrix");
    assert_eq!(
        resolve("[[1, 2], [3, 4]]").unwrap().dims(),
        Shape::Matrix(2, 2)
    );
}
