//! Sparse polynomials and polynomial expressions: arithmetic cross-checked against evaluation at
//! random rational points and against a naive product, ring laws, canonical form after every
//! operation, parser/printer round trips, parser robustness on random input; and the identities
//! the workspace proves with them (the claim list Lebesgue (7) and Dietz (8), the claim list unit-circle
//! reduction; Chiang's theorem is the benchmark `chiang-identity`, tested in `bench/`).

use exactcheck_core::{Ring, Rng};
use exactcheck_exact::expr::{
    parse_expr, parse_poly, to_latex, AddOp, Expr, ExprKind, MulOp, Notation,
};
use exactcheck_exact::poly::{groebner, unit_circle_relation, Poly, Var, Vars};
use exactcheck_exact::Rational;
use proptest::prelude::*;

type P = Poly<Rational>;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

fn int(n: i64) -> Rational {
    Rational::from_integer(n)
}

/// Number of variables the random polynomials use (spans several words at 8 bits).
const NV: u32 = 24;

fn arb_rational() -> impl Strategy<Value = Rational> {
    (-30i64..=30, 1i64..=6).prop_map(|(n, d)| q(n, d))
}

/// A random monomial: a few variables, mostly low exponents, sometimes a large one (to force
/// wider exponent fields), sometimes a high variable index (several words).
fn arb_monomial() -> impl Strategy<Value = Vec<(Var, u32)>> {
    prop::collection::vec(
        (
            prop_oneof![4 => 0u32..4, 1 => 0u32..NV],
            prop_oneof![8 => 0u32..4, 1 => 60u32..90],
        ),
        0..4,
    )
}

fn arb_poly() -> impl Strategy<Value = P> {
    prop::collection::vec((arb_monomial(), arb_rational()), 0..7).prop_map(P::from_terms)
}

/// Low exponents only (for substitution, where `deg_v(a)` powers of `b` are formed).
fn arb_small_poly() -> impl Strategy<Value = P> {
    prop::collection::vec(
        (
            prop::collection::vec((0u32..NV, 0u32..3), 0..3),
            arb_rational(),
        ),
        0..6,
    )
    .prop_map(P::from_terms)
}

fn arb_point() -> impl Strategy<Value = Vec<Rational>> {
    prop::collection::vec(
        (-3i64..=3, 1i64..=3).prop_map(|(n, d)| q(n, d)),
        NV as usize,
    )
}

fn ev(p: &P, x: &[Rational]) -> Rational {
    p.eval(x, Clone::clone)
}

/// The product by the naive method: all pairwise products, sorted and combined by
/// `from_terms` (an independent path through the code).
fn naive_mul(a: &P, b: &P) -> P {
    let mut terms = Vec::new();
    for (ma, ca) in a.terms() {
        for (mb, cb) in b.terms() {
            let mut m = ma.exponents();
            m.extend(mb.exponents());
            terms.push((m, ca.mul_ref(cb)));
        }
    }
    P::from_terms(terms)
}

/// A pseudo-random sparse polynomial: `n` terms over `nvars` variables, `per` variables per
/// term with exponents below `emax`.
fn sparse(seed: u64, n: usize, nvars: u32, per: usize, emax: u32) -> P {
    let mut rng = Rng::new(seed);
    let terms: Vec<(Vec<(Var, u32)>, Rational)> = (0..n)
        .map(|_| {
            let m = (0..per)
                .map(|_| {
                    (
                        rng.below(nvars.into()) as Var,
                        rng.below(emax.into()) as u32,
                    )
                })
                .collect();
            (m, int(rng.below(19) as i64 - 9))
        })
        .collect();
    P::from_terms(terms)
}

#[test]
fn every_multiplication_kernel_agrees_with_the_naive_product() {
    let dense = (P::var(0) + P::var(1) + P::from_i64(2)).pow(5);
    let cases = [
        // Dense box.
        (dense.clone(), (P::var(0) - P::var(1) + P::one()).pow(4)),
        // Sparse, one-word keys.
        (sparse(1, 30, 40, 3, 2), sparse(2, 25, 40, 3, 2)),
        // Two-word keys.
        (sparse(3, 30, 40, 4, 4), sparse(4, 30, 40, 4, 4)),
        // Many key words (run-time width).
        (sparse(5, 20, 60, 8, 60), sparse(6, 20, 60, 8, 60)),
        // 16-bit fields.
        (sparse(7, 10, 9, 3, 300), sparse(8, 12, 9, 3, 300)),
    ];
    for (a, b) in &cases {
        let fast = a * b;
        assert!(fast.is_canonical());
        assert_eq!(fast, naive_mul(a, b));
        assert_eq!(a.square(), naive_mul(a, a));
        assert_eq!(a.square(), a * a);
    }
}

#[test]
fn large_sums_agree_with_repeated_addition() {
    for (nvars, per, emax) in [(40, 3, 2), (60, 8, 60)] {
        let parts: Vec<P> = (0..7).map(|i| sparse(i, 80, nvars, per, emax)).collect();
        let folded = parts.iter().fold(P::zero(), |a, b| a + b);
        let mut with_cancellation = parts.clone();
        with_cancellation.push(-parts[3].clone());
        let s = P::sum(parts);
        assert!(s.is_canonical());
        assert_eq!(s, folded);
        let c = P::sum(with_cancellation);
        assert!(c.is_canonical());
        assert_eq!(c, &folded - &sparse(3, 80, nvars, per, emax));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn arithmetic_agrees_with_evaluation(a in arb_poly(), b in arb_poly(), x in arb_point()) {
        let (va, vb) = (ev(&a, &x), ev(&b, &x));
        let sum = &a + &b;
        let diff = &a - &b;
        let prod = &a * &b;
        let neg = -&a;
        prop_assert_eq!(ev(&sum, &x), &va + &vb);
        prop_assert_eq!(ev(&diff, &x), &va - &vb);
        prop_assert_eq!(ev(&prod, &x), &va * &vb);
        prop_assert_eq!(ev(&neg, &x), -&va);
        for p in [&sum, &diff, &prod, &neg] {
            prop_assert!(p.is_canonical(), "not canonical: {:?}", p);
        }
    }

    #[test]
    fn product_agrees_with_naive_product(a in arb_poly(), b in arb_poly()) {
        let fast = a.mul_ref(&b);
        prop_assert!(fast.is_canonical());
        prop_assert_eq!(&fast, &naive_mul(&a, &b));
        let sq = a.square();
        prop_assert!(sq.is_canonical());
        prop_assert_eq!(sq, naive_mul(&a, &a));
    }

    #[test]
    fn powers_agree_with_evaluation(a in arb_poly(), k in 0u32..5, x in arb_point()) {
        let p = a.pow(k);
        prop_assert!(p.is_canonical());
        prop_assert_eq!(ev(&p, &x), Ring::pow(&ev(&a, &x), k));
        let mut r = P::one();
        for _ in 0..k {
            r *= &a;
        }
        prop_assert_eq!(p, r);
    }

    #[test]
    fn substitution_agrees_with_evaluation(
        a in arb_small_poly(), b in arb_poly(), v in 0u32..4, x in arb_point()
    ) {
        let s = a.substitute(v, &b);
        prop_assert!(s.is_canonical());
        let mut y = x.clone();
        y[v as usize] = ev(&b, &x);
        prop_assert_eq!(ev(&s, &x), ev(&a, &y));
    }

    #[test]
    fn ring_laws(a in arb_poly(), b in arb_poly(), c in arb_poly()) {
        prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
        prop_assert_eq!(&a + &b, &b + &a);
        prop_assert_eq!(&a * &b, &b * &a);
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
        prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
        prop_assert!((&a - &a).is_zero());
        prop_assert_eq!(&a + &P::zero(), a.clone());
        prop_assert_eq!(&a * &P::one(), a.clone());
        prop_assert!((&a * &P::zero()).is_zero());
        // Owned, borrowed and assigning forms agree.
        let mut s = a.clone();
        s += &b;
        prop_assert_eq!(&s, &(a.clone() + b.clone()));
        let mut d = a.clone();
        d -= b.clone();
        prop_assert_eq!(&d, &(&a - b.clone()));
        let mut m = a.clone();
        m *= &b;
        prop_assert_eq!(&m, &(a.clone() * b.clone()));
        prop_assert_eq!(a.add_ref(&b), s);
        prop_assert_eq!(a.sub_ref(&b), d);
        prop_assert_eq!(P::sum(vec![a.clone(), b.clone(), c.clone()]), &(&a + &b) + &c);
    }

    #[test]
    fn unit_circle_normal_form(a in arb_poly(), tau in (-5i64..=5, 1i64..=4)) {
        // c = x0, s = x1 on the rational point of the unit circle given by tau.
        let r = a.reduce(&[unit_circle_relation(0, 1)]);
        prop_assert!(r.is_canonical());
        prop_assert!(r.degree_in(1) <= 1);
        prop_assert_eq!(&r, &a.reduce_unit_circle(&[(0, 1)]));
        let t = q(tau.0, tau.1);
        let den = Rational::one() + t.square();
        let mut x = vec![Rational::zero(); NV as usize];
        x[0] = (Rational::one() - t.square()) / &den;
        x[1] = (int(2) * &t) / &den;
        for (k, v) in x.iter_mut().enumerate().skip(2) {
            *v = int(k as i64 - 5);
        }
        prop_assert_eq!(ev(&r, &x), ev(&a, &x));
        // Reduction is idempotent and linear.
        prop_assert_eq!(r.reduce(&[unit_circle_relation(0, 1)]), r.clone());
    }

    #[test]
    fn groebner_normal_forms(
        g1 in prop::collection::vec((prop::collection::vec((0u32..2, 0u32..3), 0..3), arb_rational()), 1..4),
        g2 in prop::collection::vec((prop::collection::vec((0u32..2, 0u32..3), 0..3), arb_rational()), 1..4),
        f in prop::collection::vec((prop::collection::vec((0u32..3, 0u32..4), 0..3), arb_rational()), 0..5),
        h in prop::collection::vec((prop::collection::vec((0u32..3, 0u32..3), 0..3), arb_rational()), 0..4),
    ) {
        let (g1, g2, f, h) = (P::from_terms(g1), P::from_terms(g2), P::from_terms(f), P::from_terms(h));
        let gb = groebner(&[g1.clone(), g2.clone()]).unwrap();
        for g in [&g1, &g2] {
            prop_assert!(g.reduce(&gb).is_zero(), "generator does not reduce to zero");
        }
        for g in &gb {
            prop_assert!(g.is_canonical());
            prop_assert!(g.leading_term().is_none_or(|(_, c)| c.is_one()));
        }
        // Normal forms are canonical: f and f + (ideal element) have the same one.
        let nf = f.reduce(&gb);
        let shifted = &f + &(&(&h * &g1) - &(&f * &g2));
        prop_assert_eq!(shifted.reduce(&gb), nf.clone());
        prop_assert_eq!(nf.reduce(&gb), nf);
    }
}

// ------------------------------------------------------------------------ parser and printer

/// A random expression tree over x, y, z, w (divisions only by non-zero numbers), with calls
/// of `sum`, `diff` and `integrate`.
fn arb_expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (0i64..20, 1i64..4).prop_map(|(n, d)| Expr::new(ExprKind::Number(q(n, d)))),
        arb_var().prop_map(var),
    ];
    leaf.prop_recursive(4, 24, 4, |inner| {
        prop_oneof![
            inner
                .clone()
                .prop_map(|e| Expr::new(ExprKind::Neg(Box::new(e)))),
            prop::collection::vec((any::<bool>(), inner.clone()), 1..4).prop_map(|v| {
                Expr::new(ExprKind::Sum(
                    v.into_iter()
                        .map(|(m, e)| (if m { AddOp::Minus } else { AddOp::Plus }, e))
                        .collect(),
                ))
            }),
            // Products written with `*`, `\cdot` or `\times` (between scalars all the product).
            (
                prop::collection::vec(
                    (
                        prop::sample::select(vec![MulOp::Times, MulOp::Dot, MulOp::Cross]),
                        inner.clone()
                    ),
                    1..3
                ),
                prop::option::of(1i64..5)
            )
                .prop_map(|(v, div)| {
                    let mut items: Vec<(MulOp, Expr)> = v;
                    if let Some(d) = div {
                        items.push((MulOp::Divide, Expr::new(ExprKind::Number(int(d)))));
                    }
                    Expr::new(ExprKind::Product(items))
                }),
            (inner.clone(), 0i64..4).prop_map(|(b, k)| Expr::new(ExprKind::Pow(
                Box::new(b),
                Box::new(Expr::new(ExprKind::Number(int(k))))
            ))),
            // sum(k, a, b, E k^j) with a symbolic or a constant upper bound.
            (inner.clone(), 0i64..3, 0i64..2, arb_bound()).prop_map(|(e, j, a, b)| call(
                "sum",
                vec![var("k"), Expr::number(int(a)), b, times_power(e, "k", j)]
            )),
            (inner.clone(), arb_var()).prop_map(|(e, t)| call("diff", vec![e, var(t)])),
            // integrate(E t^j, t, 0, b)
            (inner.clone(), 0i64..3, arb_bound()).prop_map(|(e, j, b)| call(
                "integrate",
                vec![times_power(e, "t", j), var("t"), Expr::number(int(0)), b]
            )),
        ]
    })
}

fn arb_var() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec!["x", "y", "z", "w"])
}

/// A bound of a sum or an integral: a variable, a variable plus one, or a small integer.
fn arb_bound() -> impl Strategy<Value = Expr> {
    prop_oneof![
        arb_var().prop_map(var),
        arb_var().prop_map(|v| parse_expr(&format!("{v} + 1")).unwrap()),
        (0i64..4).prop_map(|n| Expr::number(int(n))),
    ]
}

fn var(name: &str) -> Expr {
    Expr::new(ExprKind::Var(name.to_string()))
}

fn call(name: &str, args: Vec<Expr>) -> Expr {
    Expr::new(ExprKind::Call(name.to_string(), args))
}

/// `e * v^j`: the bound variable `v` occurs in the body.
fn times_power(e: Expr, v: &str, j: i64) -> Expr {
    Expr::new(ExprKind::Product(vec![
        (MulOp::Times, e),
        (
            MulOp::Times,
            Expr::new(ExprKind::Pow(
                Box::new(var(v)),
                Box::new(Expr::number(int(j))),
            )),
        ),
    ]))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn expression_print_parse_round_trip(e in arb_expr()) {
        let mut v1 = Vars::from_names(["x", "y", "z", "w"]);
        let p: P = e.to_poly(&mut v1).unwrap();
        prop_assert!(p.is_canonical());
        let text = e.to_string();
        let mut v2 = v1.clone();
        let back: P = parse_poly(&text, &mut v2).map_err(|err| {
            TestCaseError::fail(format!("{text:?}: {err}"))
        })?;
        prop_assert_eq!(&back, &p, "{}", text);
        // The polynomial printer round-trips too.
        let printed = p.display(&v1).to_string();
        let again: P = parse_poly(&printed, &mut v2).map_err(|err| {
            TestCaseError::fail(format!("{printed:?}: {err}"))
        })?;
        prop_assert_eq!(again, p, "{}", printed);
    }

    #[test]
    fn latex_print_parse_round_trip(e in arb_expr()) {
        // The LaTeX printer's output, read by the parser's LaTeX input, is the same polynomial.
        let mut v1 = Vars::from_names(["x", "y", "z", "w"]);
        let p: P = e.to_poly(&mut v1).unwrap();
        let text = to_latex(&e, &Notation::new());
        let mut v2 = v1.clone();
        let back: P = parse_poly(&text, &mut v2).map_err(|err| {
            TestCaseError::fail(format!("{text:?}: {err}"))
        })?;
        prop_assert_eq!(&back, &p, "{}", text);
        prop_assert_eq!(v2.len(), v1.len(), "{}", text);
    }

    #[test]
    fn random_polynomials_print_and_parse_back(a in arb_poly()) {
        let mut vars = Vars::new();
        for i in 0..NV {
            vars.var(&format!("v{i}"));
        }
        let text = a.display(&vars).to_string();
        let back: P = parse_poly(&text, &mut vars).unwrap();
        prop_assert_eq!(back, a);
    }

    #[test]
    fn parser_never_panics_on_token_soup(
        s in prop::collection::vec(
            prop::sample::select(vec![
                "x", "y1", "_a", "sqrt", "(", ")", "+", "-", "*", "/", "^", "0", "1", "2",
                "3.5", "0.", ".", " ", "\t", "9", "#", "é", "^(", "(1-x)", "1/0", "99",
            ]),
            0..24,
        )
    ) {
        let text: String = s.concat();
        match parse_poly::<Rational>(&text, &mut Vars::new()) {
            Ok(p) => prop_assert!(p.is_canonical()),
            Err(e) => {
                prop_assert!(e.position() <= text.len());
                prop_assert!(!e.to_string().is_empty());
            }
        }
    }

    #[test]
    fn parser_never_panics_on_arbitrary_text(text in ".{0,40}") {
        let _ = parse_expr(&text);
        if let Err(e) = parse_poly::<Rational>(&text, &mut Vars::new()) {
            prop_assert!(e.position() <= text.len());
        }
    }
}

// ------------------------------------------------------------------------ identities

/// Lebesgue's representation (the claim list (7)), written once over any ring.
fn lebesgue<T: Ring>(p: &[T; 4]) -> [T; 4] {
    let two = T::from_i64(2);
    let [p0, p1, p2, p3] = p;
    [
        p0.square() + p1.square() + p2.square() + p3.square(),
        two.mul_ref(&p0.mul_ref(p1)) - two.mul_ref(&p2.mul_ref(p3)),
        two.mul_ref(&p0.mul_ref(p2)) + two.mul_ref(&p1.mul_ref(p3)),
        p1.square() + p2.square() - p0.square() - p3.square(),
    ]
}

#[test]
fn lebesgue_identity_is_proved() {
    let mut vars = Vars::new();
    let p: [P; 4] = ["p0", "p1", "p2", "p3"].map(|n| vars.poly(n));
    let [k0, k1, k2, k3] = lebesgue(&p);
    let residual = k0.square() - (k1.square() + k2.square() + k3.square());
    assert!(residual.is_zero(), "{}", residual.display(&vars));
    // The same code over rationals, at a point.
    let k = lebesgue(&[int(1), int(2), int(3), int(4)]);
    assert_eq!(k[0].square(), k[1].square() + k[2].square() + k[3].square());
    // And the printed form says the same.
    let text = "(p0^2+p1^2+p2^2+p3^2)^2 - (2*p0*p1 - 2*p2*p3)^2 - (2*p0*p2 + 2*p1*p3)^2 \
                - (p1^2+p2^2-p0^2-p3^2)^2";
    assert!(parse_poly::<Rational>(text, &mut vars).unwrap().is_zero());
}

#[test]
fn dietz_identity_is_proved() {
    let mut vars = Vars::new();
    let [q0, q1, q2, q3]: [P; 4] = ["q0", "q1", "q2", "q3"].map(|n| vars.poly(n));
    let (h0, h1, h2, h3) = (&q0 * &q3, &q1 * &q3, &q0 * &q2, &q1 * &q2);
    assert!((h0 * h3 - h1 * h2).is_zero());
}

#[test]
fn unit_circle_reduction_example() {
    let mut vars = Vars::from_names(["c", "s", "x"]);
    let f: P = parse_poly("c^2*x^3 + s^2*x^3 - x", &mut vars).unwrap();
    let want: P = parse_poly("x^3 - x", &mut vars).unwrap();
    let rel = unit_circle_relation(0, 1);
    assert_eq!(rel.display(&vars).to_string(), "s^2 + c^2 - 1");
    assert_eq!(f.reduce(&[rel]), want);
}

#[test]
fn trigonometric_identities_modulo_the_unit_circle() {
    // Angles a = (c1, s1), b = (c2, s2); cos and sin of a + b; double angles.
    let mut vars = Vars::from_names(["c1", "s1", "c2", "s2"]);
    let rels = [unit_circle_relation(0, 1), unit_circle_relation(2, 3)];
    let nf =
        |text: &str, vars: &mut Vars| parse_poly::<Rational>(text, vars).unwrap().reduce(&rels);
    assert!(nf("(c1*c2 - s1*s2)^2 + (s1*c2 + c1*s2)^2 - 1", &mut vars).is_zero());
    assert!(nf("c1^2 - s1^2 - (2*c1^2 - 1)", &mut vars).is_zero());
    assert!(nf("(c1^2 - s1^2)^2 + (2*s1*c1)^2 - 1", &mut vars).is_zero());
    // A false identity keeps a non-zero normal form.
    assert!(!nf("c1^2 - s1^2 - (2*c1^2 + 1)", &mut vars).is_zero());
    // Through the general Buchberger path the basis is the relations themselves, monic.
    let gb = groebner(&rels).unwrap();
    assert_eq!(gb.len(), 2);
    assert!(gb.iter().all(|g| rels.contains(g)));
}

#[test]
fn buchberger_by_hand() {
    // x = x0 < y = x1 (lex, y larger). <y^2 + x^2 - 1, y - x>:
    // S(g1, g2) = g1 - y g2 = x y + x^2 - 1 -> (y -> x) 2 x^2 - 1, so the reduced basis is
    // {x^2 - 1/2, y - x}, sorted by increasing leading monomial (x^2 < y).
    let mut vars = Vars::from_names(["x", "y"]);
    let g1: P = parse_poly("y^2 + x^2 - 1", &mut vars).unwrap();
    let g2: P = parse_poly("y - x", &mut vars).unwrap();
    let gb = groebner(&[g1, g2]).unwrap();
    let want: Vec<P> = ["x^2 - 1/2", "y - x"]
        .iter()
        .map(|t| parse_poly(t, &mut vars).unwrap())
        .collect();
    assert_eq!(gb, want);
    let y3: P = parse_poly("y^3", &mut vars).unwrap();
    assert_eq!(y3.reduce(&gb).display(&vars).to_string(), "1/2*x");
}
