use super::*;
use crate::expr::parse_poly;
use crate::poly::gcd::prs_gcd;
use crate::poly::Vars;
use crate::Rational;

fn p(text: &str, vars: &mut Vars) -> Poly<Rational> {
    parse_poly(text, vars).unwrap()
}

#[test]
fn gcd_of_products_is_the_common_factor() {
    let mut vars = Vars::from_names(["x", "y", "z"]);
    let common = p("x*y - z^2 + 3", &mut vars);
    let a = common.mul_ref(&p("x + y + 1", &mut vars));
    let b = common
        .mul_ref(&p("x - 2*z", &mut vars))
        .scale(&Rational::from(7));
    assert_eq!(poly_gcd(&a, &b).unwrap(), common.make_monic());
    let one = poly_gcd(&p("x + 1", &mut vars), &p("x - 1", &mut vars)).unwrap();
    assert!(one.is_one());
    // A content in the other variables: gcd(y x + y, y^2 x) = y.
    let g = poly_gcd(&p("y*x + y", &mut vars), &p("y^2*x", &mut vars)).unwrap();
    assert_eq!(g, p("y", &mut vars));
}

#[test]
fn exact_division_and_its_refusal() {
    let mut vars = Vars::from_names(["x", "y"]);
    let a = p("x^3 - y^3", &mut vars);
    let b = p("x - y", &mut vars);
    assert_eq!(div_exact(&a, &b).unwrap(), p("x^2 + x*y + y^2", &mut vars));
    assert!(div_exact(&p("x^2 + 1", &mut vars), &b).is_none());
}

#[test]
fn fractions_cancel_and_differentiate() {
    let mut vars = Vars::from_names(["x"]);
    let x = RatFun::from_poly(p("x", &mut vars));
    let one = RatFun::from_poly(p("1", &mut vars));
    let xm1 = x.add(&one, true).unwrap();
    let f = x
        .mul(&x)
        .unwrap()
        .add(&one, true)
        .unwrap()
        .div(&xm1)
        .unwrap()
        .unwrap();
    assert_eq!(f.numerator(), &p("x + 1", &mut vars));
    assert!(f.denominator().is_one());
    assert_eq!(f.conditions(), &[p("x - 1", &mut vars)]);
    // d/dx 1/(x - 1) = -1/(x - 1)^2.
    let g = one.div(&xm1).unwrap().unwrap().derivative(0).unwrap();
    assert_eq!(g.numerator(), &p("-1", &mut vars));
    assert_eq!(g.denominator(), &p("(x - 1)^2", &mut vars));
    assert!(xm1.add(&xm1, true).unwrap().recip().is_none());
}

#[test]
fn the_coprimality_certificate_decides_the_clear_cases() {
    let mut vars = Vars::from_names(["x", "y", "z"]);
    let a = p("x*y + z + 1", &mut vars);
    let b = p("x - y^2 + 3*z", &mut vars);
    assert_eq!(certified_coprime(&a, &b), Some(true));
    // A planted common factor is never certified away.
    let c = p("x + z^2 - 2", &mut vars);
    assert_eq!(
        certified_coprime(&a.mul_ref(&c), &b.mul_ref(&c)),
        Some(false)
    );
    // Without shared variables the gcd is constant.
    assert_eq!(
        certified_coprime(&p("x + 1", &mut vars), &p("y + 2", &mut vars)),
        Some(true)
    );
    // Other coefficient fields: the test does not apply.
    let r = crate::poly::Poly::<crate::Radical>::one();
    assert_eq!(certified_coprime(&r, &r), None);
}

#[test]
fn cancellation_divides_out_the_divisors_met() {
    // The curvature pattern: a numerator carrying W^2 over W^5 ends over W^3.
    let mut vars = Vars::from_names(["t", "w"]);
    let w = p("w*t^2 + 2*t + 1", &mut vars);
    let n = p("t^3 - w + 5", &mut vars);
    let num = n.mul_ref(&w).mul_ref(&w);
    let den = w.try_pow(5).unwrap();
    let (got_n, got_d) = cancel(num, den, std::slice::from_ref(&w)).unwrap();
    assert_eq!(got_d, w.try_pow(3).unwrap().make_monic());
    assert_eq!(got_n.mul_ref(&w.try_pow(3).unwrap()), n.mul_ref(&got_d));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Against the remainder sequence: a certified pair has gcd 1 there, and a pair with a
    /// planted non-constant factor is never certified.
    #[test]
    fn certificate_agrees_with_the_remainder_sequence(
        ca in proptest::collection::vec(-3i64..=3, 6),
        cb in proptest::collection::vec(-3i64..=3, 6),
        cc in proptest::collection::vec(-3i64..=3, 3),
    ) {
        let mut vars = Vars::from_names(["x", "y"]);
        let monos = ["1", "x", "y", "x*y", "x^2", "y^2"];
        let build = |cs: &[i64], vars: &mut Vars| {
            let text: Vec<String> = cs.iter().zip(monos).map(|(c, m)| format!("({c})*{m}")).collect();
            p(&text.join(" + "), vars)
        };
        let (a, b) = (build(&ca, &mut vars), build(&cb, &mut vars));
        let c = build(&cc, &mut vars).add_ref(&p("x*y", &mut vars));
        if certified_coprime(&a, &b) == Some(true) && !a.is_constant() && !b.is_constant() {
            let mut budget = usize::MAX;
            proptest::prop_assert!(prs_gcd(&a, &b, &mut budget).unwrap().is_constant());
        }
        if !a.is_zero() && !b.is_zero() {
            proptest::prop_assert_eq!(
                certified_coprime(&a.mul_ref(&c), &b.mul_ref(&c)),
                Some(false)
            );
        }
    }
}

/// `num / den` in lowest terms by the remainder sequence alone, the denominator monic: the
/// reference the fast paths of the operations are checked against.
fn lowest_terms(num: Poly<Rational>, den: Poly<Rational>) -> (Poly<Rational>, Poly<Rational>) {
    if num.is_zero() {
        return (num, Poly::one());
    }
    let g = poly_gcd(&num, &den).unwrap();
    let (n, d) = (div_exact(&num, &g).unwrap(), div_exact(&den, &g).unwrap());
    let lc = d.leading_term().unwrap().1.inv().unwrap();
    (n.scale(&lc), d.scale(&lc))
}

/// The conditions `push_condition` computed the way it was first written: the square-free
/// part by gcds with every partial derivative, then the common factor with every condition
/// listed divided out.
fn reference_push(conditions: &mut Vec<Poly<Rational>>, p: &Poly<Rational>) {
    if p.is_constant() {
        return;
    }
    let mut g = p.clone();
    for v in p.variables() {
        g = poly_gcd(&g, &poly_derivative(p, v)).unwrap();
    }
    let mut q = div_exact(p, &g).unwrap();
    for c in conditions.iter() {
        let common = poly_gcd(&q, c).unwrap();
        if !common.is_constant() {
            q = div_exact(&q, &common).unwrap();
        }
    }
    if !q.is_constant() {
        conditions.push(q.make_monic());
    }
}

#[test]
fn exact_division_with_wide_exponents_uses_vectors_of_exponents() {
    // Five variables of degree 2^31 need 160 bits: the keys are vectors, the result the same.
    let e = 1u32 << 31;
    let big: Vec<(Var, u32)> = (0..5).map(|v| (v, e)).collect();
    let half: Vec<(Var, u32)> = (0..5).map(|v| (v, e / 2)).collect();
    let one = Rational::from(1);
    let a = Poly::from_terms([(big, one.clone()), (vec![], one.neg_ref())]);
    let b = Poly::from_terms([(half.clone(), one.clone()), (vec![], one.neg_ref())]);
    let q = Poly::from_terms([(half, one.clone()), (vec![], one)]);
    assert_eq!(div_exact(&a, &b), Some(q));
    assert_eq!(div_exact(&a.add_ref(&Poly::one()), &b), None);
}

#[test]
fn a_power_of_a_listed_condition_adds_nothing() {
    let mut vars = Vars::from_names(["t", "w"]);
    let w = p("w*t^2 + 2*t + 1", &mut vars);
    let mut conditions = vec![w.clone()];
    push_condition(
        &mut conditions,
        &w.try_pow(3).unwrap().scale(&Rational::from(5)),
    );
    assert_eq!(conditions, vec![w.clone()]);
    // A new factor next to a listed one is added alone, square-free and monic.
    let other = p("t - w", &mut vars);
    push_condition(&mut conditions, &w.mul_ref(&other).mul_ref(&other));
    assert_eq!(conditions, vec![w, other.make_monic()]);
}

#[test]
fn the_derivative_over_a_power_of_a_condition_is_in_lowest_terms() {
    // d/dt (t^3 - w) / W^2 over W^3, and again over W^4: each equal to the quotient rule
    // reduced by the remainder sequence.
    let mut vars = Vars::from_names(["t", "w"]);
    let w = p("w*t^2 + 2*t + 1", &mut vars);
    let n = p("t^3 - w", &mut vars);
    let f = RatFun::from_poly(n)
        .div(&RatFun::from_poly(w.try_pow(2).unwrap()))
        .unwrap()
        .unwrap();
    assert_eq!(f.conditions(), std::slice::from_ref(&w));
    let mut g = f;
    for k in 3..=4 {
        let (num, den) = (g.numerator().clone(), g.denominator().clone());
        g = g.derivative(0).unwrap();
        let want = lowest_terms(
            poly_derivative(&num, 0)
                .mul_ref(&den)
                .sub_ref(&num.mul_ref(&poly_derivative(&den, 0))),
            den.mul_ref(&den),
        );
        assert_eq!((g.numerator(), g.denominator()), (&want.0, &want.1));
        assert_eq!(g.denominator(), &w.try_pow(k).unwrap());
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

    /// Sums, products, quotients and derivatives of random fractions against the same operations
    /// reduced by the remainder sequence alone, and the conditions against the gcd-only
    /// computation.
    #[test]
    fn operations_agree_with_the_remainder_sequence(
        ca in proptest::collection::vec(-3i64..=3, 6),
        cb in proptest::collection::vec(-3i64..=3, 6),
        ch in proptest::collection::vec(-3i64..=3, 3),
        k in 1u32..=3,
    ) {
        let mut vars = Vars::from_names(["x", "y"]);
        let monos = ["1", "x", "y", "x*y", "x^2", "y^2"];
        let build = |cs: &[i64], vars: &mut Vars| {
            let text: Vec<String> =
                cs.iter().zip(monos).map(|(c, m)| format!("({c})*{m}")).collect();
            p(&text.join(" + "), vars)
        };
        let (a, b) = (build(&ca, &mut vars), build(&cb, &mut vars));
        let h = build(&ch, &mut vars).add_ref(&p("x*y + x", &mut vars));
        proptest::prop_assume!(!b.is_zero() && !h.is_zero());
        // f = a / h^k, g = b / h.
        let f = RatFun::from_poly(a.clone())
            .div(&RatFun::from_poly(h.try_pow(k).unwrap()))
            .unwrap()
            .unwrap();
        let g = RatFun::from_poly(b.clone())
            .div(&RatFun::from_poly(h.clone()))
            .unwrap()
            .unwrap();
        let hk = h.try_pow(k).unwrap();
        let fg = f.mul(&g).unwrap();
        let want = lowest_terms(a.mul_ref(&b), hk.mul_ref(&h));
        proptest::prop_assert_eq!((fg.numerator(), fg.denominator()), (&want.0, &want.1));
        // Exact division, and its refusal when the remainder is not zero.
        if !h.is_constant() {
            proptest::prop_assert_eq!(div_exact(&a.mul_ref(&h), &h), Some(a.clone()));
            proptest::prop_assert_eq!(div_exact(&a.mul_ref(&h).add_ref(&Poly::one()), &h), None);
        }
        let sum = f.add(&g, false).unwrap();
        let want = lowest_terms(a.add_ref(&b.mul_ref(&h.try_pow(k - 1).unwrap())), hk.clone());
        proptest::prop_assert_eq!((sum.numerator(), sum.denominator()), (&want.0, &want.1));
        let q = f.div(&g).unwrap();
        if let Some(q) = q {
            let want = lowest_terms(a.mul_ref(&h), hk.mul_ref(&b));
            proptest::prop_assert_eq!((q.numerator(), q.denominator()), (&want.0, &want.1));
        }
        for v in [0, 1] {
            let d = f.derivative(v).unwrap();
            let (n0, d0) = (f.numerator(), f.denominator());
            let want = lowest_terms(
                poly_derivative(n0, v).mul_ref(d0).sub_ref(&n0.mul_ref(&poly_derivative(d0, v))),
                d0.mul_ref(d0),
            );
            proptest::prop_assert_eq!((d.numerator(), d.denominator()), (&want.0, &want.1));
        }
        let mut fast = Vec::new();
        let mut slow = Vec::new();
        for c in [&h, &a, &hk, &b.mul_ref(&h), &a.mul_ref(&a)] {
            push_condition(&mut fast, c);
            reference_push(&mut slow, c);
        }
        proptest::prop_assert_eq!(fast, slow);
    }
}

#[test]
fn the_square_free_certificate_decides_the_clear_cases() {
    let mut vars = Vars::from_names(["x", "y", "t"]);
    assert_eq!(
        certified_square_free(&p("x^2 + y^2 + 1", &mut vars)),
        Some(true)
    );
    assert_eq!(certified_square_free(&p("t^2 + 1", &mut vars)), Some(true));
    // A square, also one free of a variable of the polynomial, is never certified.
    assert_eq!(
        certified_square_free(&p("(x + y)^2 (x + 1)", &mut vars)),
        Some(false)
    );
    assert_eq!(
        certified_square_free(&p("y^2 (x + 1)", &mut vars)),
        Some(false)
    );
    let r = crate::poly::Poly::<crate::Radical>::one();
    assert_eq!(certified_square_free(&r), None);
    // Square-free with a factor free of x, which divides the derivative in x.
    assert_eq!(
        certified_square_free(&p("(1 + y) (1 + x - 3 y)", &mut vars)),
        Some(true)
    );
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// Against the derivative gcds: a certified polynomial has a constant gcd with all its
    /// partial derivatives together (a square-free polynomial may share a factor free of `v`
    /// with its derivative in `v`, as `(1 + y)(1 + x - 3y)` does with `1 + y`; a repeated
    /// factor divides every partial derivative), and one with a planted square factor is never
    /// certified.
    #[test]
    fn square_free_certificate_agrees_with_the_derivative_gcds(
        ca in proptest::collection::vec(-3i64..=3, 6),
        cf in proptest::collection::vec(-3i64..=3, 3),
    ) {
        let mut vars = Vars::from_names(["x", "y"]);
        let monos = ["1", "x", "y", "x*y", "x^2", "y^2"];
        let text: Vec<String> = ca.iter().zip(monos).map(|(c, m)| format!("({c})*{m}")).collect();
        let a = p(&text.join(" + "), &mut vars);
        let f = p(&format!("({})*x + ({})*y + ({})", cf[0], cf[1], cf[2]), &mut vars);
        if certified_square_free(&a) == Some(true) {
            let mut g = a.clone();
            for v in a.variables() {
                g = poly_gcd(&g, &poly_derivative(&a, v)).unwrap();
            }
            proptest::prop_assert!(g.is_constant(), "{} shares {} with its derivatives", text.join(" + "), g.display(&vars));
        }
        if !a.is_zero() && !f.is_constant() {
            proptest::prop_assert_eq!(certified_square_free(&a.mul_ref(&f).mul_ref(&f)), Some(false));
        }
    }
}
