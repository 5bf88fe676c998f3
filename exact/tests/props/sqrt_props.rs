//! Square roots of expressions and hypotheses in proofs, against an independent path: an
//! identity the engine proves with `sqrt` (a variable `y`, `y^2 = E`, `y >= 0`) is evaluated
//! directly, the root taken by `Rational`'s exact square root, at random rational points where
//! the radicand is a perfect square; identities false on one branch are rejected with a point
//! where the root really is the non-negative one.

use exactcheck_core::Ring;
use exactcheck_exact::expr::parse_expr;
use exactcheck_exact::poly::{Poly, Vars};
use exactcheck_exact::prove::{
    decide_where, square_roots, Decision, Hypothesis, SquareRoot, VarDomain,
};
use exactcheck_exact::Rational;
use proptest::prelude::*;

/// A polynomial in x and y as `(i, j, c)` for `c x^i y^j`.
type Terms = Vec<(u32, u32, i64)>;

fn arb_terms() -> impl Strategy<Value = Terms> {
    prop::collection::vec((0u32..3, 0u32..3, -4i64..=4), 1..4)
}

/// The polynomial with `x` and `y` written as the given texts.
fn text(t: &Terms, x: &str, y: &str) -> String {
    let parts: Vec<String> = t
        .iter()
        .map(|&(i, j, c)| format!("({c})*{x}^{i}*{y}^{j}"))
        .collect();
    format!("({})", parts.join(" + "))
}

/// Decides `lhs = rhs` with the roots given their relations and sign conditions, and `domains`
/// by variable name.
fn decide(lhs: &str, rhs: &str, domains: &[(&str, VarDomain)]) -> Decision<Rational> {
    let mut vars = Vars::new();
    vars.allow_roots();
    let l: Poly<Rational> = parse_expr(lhs).unwrap().to_poly(&mut vars).unwrap();
    let r: Poly<Rational> = parse_expr(rhs).unwrap().to_poly(&mut vars).unwrap();
    let roots = square_roots::<Rational>(&mut vars).unwrap();
    let rels: Vec<Poly<Rational>> = roots.iter().map(SquareRoot::cleared_relation).collect();
    let mut doms: Vec<(u32, VarDomain)> = domains
        .iter()
        .map(|(n, d)| (vars.get(n).unwrap(), d.clone()))
        .collect();
    doms.extend(
        roots
            .iter()
            .map(|r| (r.var, SquareRoot::<Rational>::domain())),
    );
    decide_where(&(l - r), &rels, &[], &doms, vars.len()).unwrap()
}

fn value(text: &str) -> Option<Rational> {
    parse_expr(text).unwrap().eval_constant::<Rational>().ok()
}

fn at_least(lo: i64) -> VarDomain {
    VarDomain {
        lower: Some((Rational::from_integer(lo), false)),
        upper: None,
        integer: false,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// `(a + b sqrt(E))^2 = a^2 + b^2 E + 2 a b sqrt(E)` holds for both roots: proved, and true
    /// at every rational point where `E` is a square.
    #[test]
    fn both_branch_identities_are_proved_and_hold_at_square_points(
        a in arb_terms(), b in arb_terms(), k in 0i64..5, xs in prop::collection::vec((-6i64..=6, 1i64..4, -6i64..=6), 4),
    ) {
        let e = |x: &str, y: &str| format!("({x}^2 + {k}*{y}^2)");
        let side = |x: &str, y: &str| {
            let (a, b, e) = (text(&a, x, y), text(&b, x, y), e(x, y));
            (
                format!("({a} + {b}*sqrt({e}))^2"),
                format!("{a}^2 + {b}^2*{e} + 2*{a}*{b}*sqrt({e})"),
            )
        };
        let (l, r) = side("x", "y");
        let proved = matches!(decide(&l, &r, &[]), Decision::Proved { .. });
        prop_assert!(proved, "{} = {}", l, r);
        for (n, d, m) in xs {
            // x = n/d, y = m: x^2 + k y^2 is a square when k = 0 or y = 0, or by chance.
            let (x, y) = (format!("({n}/{d})"), format!("({m})"));
            let (l, r) = side(&x, &y);
            if let (Some(lv), Some(rv)) = (value(&l), value(&r)) {
                prop_assert_eq!(lv, rv, "{} at x = {}, y = {}", l, x, y);
            }
            let (l, r) = side(&x, "0");
            prop_assert_eq!(value(&l).unwrap(), value(&r).unwrap());
        }
    }

    /// `sqrt(p^2) = p` for `p = a x + c` with `a > 0` and `c >= 0`: proved on `x >= 0` using
    /// the domain; without it, it fails at an exact point with `p < 0` where the root is `-p`.
    #[test]
    fn the_branch_is_chosen_by_the_domain(a in 1i64..5, c in 0i64..5) {
        let p = format!("({a}*x + {c})");
        let l = format!("sqrt({p}^2)");
        match decide(&l, &p, &[("x", at_least(0))]) {
            Decision::Proved { hypotheses, .. } => prop_assert!(hypotheses.contains(&Hypothesis::Domain(0))),
            other => prop_assert!(false, "{:?}", other),
        }
        match decide(&l, &p, &[]) {
            Decision::Fails { point, .. } => {
                let x = point[0].1.to_rational().unwrap();
                let root = point[1].1.to_rational().unwrap();
                let pv = Rational::from_integer(a) * &x + &Rational::from_integer(c);
                prop_assert!(pv < Rational::ZERO);
                prop_assert_eq!(root, -pv);
            }
            other => prop_assert!(false, "{:?}", other),
        }
    }

    /// `w0 X = c (x1 - x0)` from `w0^2 X = c w0 (x1 - x0)` needs `w0 != 0`: proved with the
    /// hypothesis (and only it reported), refused without it at `w0 = 0`.
    #[test]
    fn a_non_zero_hypothesis_is_used_and_reported(c in 1i64..6, extra in 0usize..3) {
        let mut vars = Vars::from_names(["w0", "X", "x1", "x0"]);
        let rel: Poly<Rational> = parse_expr(&format!("w0^2*X - {c}*w0*(x1 - x0)")).unwrap().to_poly(&mut vars).unwrap();
        let res: Poly<Rational> = parse_expr(&format!("w0*X - {c}*(x1 - x0)")).unwrap().to_poly(&mut vars).unwrap();
        let w0: Poly<Rational> = Poly::var(0);
        // Hypotheses the proof does not need come first.
        let mut nonzero: Vec<Poly<Rational>> = (0..extra).map(|i| Poly::var(2).sub_ref(&Poly::constant(Rational::from_integer(i as i64)))).collect();
        nonzero.push(w0);
        match decide_where(&res, std::slice::from_ref(&rel), &nonzero, &[], 4).unwrap() {
            Decision::Proved { hypotheses, .. } => prop_assert_eq!(hypotheses, vec![Hypothesis::NonZero(extra)]),
            other => prop_assert!(false, "{:?}", other),
        }
        match decide_where(&res, &[rel], &[], &[], 4).unwrap() {
            Decision::Fails { point, .. } => prop_assert!(point[0].1.is_zero()),
            other => prop_assert!(false, "{:?}", other),
        }
    }
}
