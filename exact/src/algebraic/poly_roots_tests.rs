//! Tests of real root isolation over a number field ([`FieldUPoly`]): against the rational
//! isolator on rational polynomials taken into a field, and against products of linear and
//! quadratic factors whose roots are known elements of the field.

use super::poly_roots::*;
use super::{FieldElement, NumberField};
use crate::univariate::*;
use crate::{Algebraic, Rational};
use exactcheck_core::Ring;
use exactcheck_core::Sign;
use std::sync::Arc;

fn field() -> Arc<NumberField> {
    let c: Algebraic = "cos(pi/8)".parse().unwrap();
    Arc::new(NumberField::new(c).unwrap())
}

fn q(n: i64, d: i64) -> FieldElement {
    FieldElement::rational(Rational::new(n, d).unwrap())
}

/// `cos(pi/8)` and `sqrt(2) = 4 cos(pi/8)^2 - 2` in the field.
fn c_and_sqrt2(f: &Arc<NumberField>) -> (FieldElement, FieldElement) {
    let c = FieldElement::generator(f);
    let s2 = c.square().scale_i64(4) - q(2, 1);
    (c, s2)
}

fn linear(root: &FieldElement) -> FieldUPoly {
    FieldUPoly::from_coeffs(vec![root.neg_ref(), FieldElement::one()])
}

fn product(factors: &[FieldUPoly]) -> FieldUPoly {
    factors.iter().fold(
        FieldUPoly::from_coeffs(vec![FieldElement::one()]),
        |a, b| a.mul(b),
    )
}

/// Whether the known root `x` lies in the isolating interval `ri`, compared exactly in the
/// field.
fn inside(x: &FieldElement, ri: &RootInterval) -> bool {
    let (lo, hi) = (
        FieldElement::rational(ri.lo.clone()),
        FieldElement::rational(ri.hi.clone()),
    );
    if ri.is_exact() {
        return *x == lo;
    }
    (x.clone() - &lo).signum() == Sign::Positive && (hi - x).signum() == Sign::Positive
}

#[test]
fn a_product_of_known_factors_has_its_roots_isolated_with_multiplicities() {
    let f = field();
    let (c, s2) = c_and_sqrt2(&f);
    // (t - sqrt 2)^2 (t - 1/3) (t^2 - 3) (t + cos(pi/8)): the roots -sqrt 3, -cos(pi/8), 1/3,
    // sqrt 2 (double), sqrt 3.
    let t2_minus_3 = FieldUPoly::from_coeffs(vec![q(-3, 1), q(0, 1), q(1, 1)]);
    let p = product(&[
        linear(&s2),
        linear(&s2),
        linear(&q(1, 3)),
        t2_minus_3,
        linear(&c.neg_ref()),
    ]);
    let roots = p.roots();
    let want = [
        -(3f64.sqrt()),
        -(std::f64::consts::PI / 8.0).cos(),
        1.0 / 3.0,
    ];
    assert_eq!(roots.len(), 5, "{roots:?}");
    let exact: Vec<bool> = roots.iter().map(|r| r.interval.is_exact()).collect();
    assert_eq!(exact, [false, false, true, false, false]);
    let mult: Vec<u32> = roots.iter().map(|r| r.multiplicity).collect();
    assert_eq!(mult, [1, 1, 1, 2, 1]);
    assert_eq!(
        roots[2].interval.exact_value(),
        Some(&Rational::new(1, 3).unwrap())
    );
    assert!(inside(&c.neg_ref(), &roots[1].interval));
    assert!(inside(&s2, &roots[3].interval));
    let width = Rational::new(1, 1 << 50).unwrap();
    for (r, w) in roots.iter().zip(want) {
        let fine = p.try_refine(&r.interval, &width).unwrap();
        assert!(fine.width() <= width);
        assert!((fine.to_f64() - w).abs() < 1e-12, "{fine:?} vs {w}");
    }
    let fine = p.try_refine(&roots[4].interval, &width).unwrap();
    assert!((fine.to_f64() - 3f64.sqrt()).abs() < 1e-12);
    // Signs: negative leading sign below -sqrt 3 for degree 6 with a positive leading
    // coefficient is positive; the double root does not change the sign.
    let chart = p.sign_chart();
    assert_eq!(
        chart.gaps,
        [
            Sign::Positive,
            Sign::Negative,
            Sign::Positive,
            Sign::Negative,
            Sign::Negative,
            Sign::Positive
        ]
    );
    assert!(p.positive_somewhere());
}

#[test]
fn a_double_irrational_root_is_a_touching_point() {
    let f = field();
    let (_, s2) = c_and_sqrt2(&f);
    // -(t - sqrt 2)^2 (t^2 + 1) is >= 0 only at sqrt 2.
    let p = product(&[
        linear(&s2),
        linear(&s2),
        FieldUPoly::from_coeffs(vec![q(-1, 1), q(0, 1), q(-1, 1)]),
    ]);
    let set = p.nonnegative_set();
    assert_eq!(set.len(), 1);
    match (&set[0].lo, &set[0].hi) {
        (Bound::Root(a), Bound::Root(b)) => {
            assert_eq!(a, b);
            assert!(inside(&s2, a));
        }
        other => panic!("{other:?}"),
    }
    assert!(!p.positive_somewhere());
    assert_eq!(p.count_real_roots(), 1);
    assert_eq!(p.roots()[0].multiplicity, 2);
}

#[test]
fn constants_and_zero_have_no_roots() {
    let f = field();
    let (c, _) = c_and_sqrt2(&f);
    let k = FieldUPoly::from_coeffs(vec![c.clone()]);
    assert!(k.roots().is_empty());
    assert!(k.positive_somewhere());
    assert_eq!(k.nonnegative_set().len(), 1);
    let z = FieldUPoly::from_coeffs(vec![FieldElement::zero(), FieldElement::zero()]);
    assert!(z.is_zero());
    assert_eq!(z.nonnegative_set().len(), 1);
    assert_eq!(
        FieldUPoly::from_coeffs(vec![q(-1, 2), c])
            .display("tau")
            .to_string(),
        "(sqrt(2 + sqrt(2))/2)*tau - 1/2"
    );
}

mod props {
    use super::*;
    use proptest::prelude::*;

    /// A field element `a + b cos(pi/8) + d sqrt 2` with small rational parts.
    fn element(f: &Arc<NumberField>, (a, b, d): (i64, i64, i64)) -> FieldElement {
        let (c, s2) = c_and_sqrt2(f);
        q(a, 3) + c.scale_i64(b) + s2.scale_i64(d)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// A rational polynomial taken into the field has the rational isolator's roots:
        /// the same intervals (the norm is a power of the polynomial, with the same
        /// square-free part) and multiplicities.
        #[test]
        fn rational_polynomials_in_a_field_agree_with_the_rational_isolator(
            factors in proptest::collection::vec(
                (proptest::collection::vec(-6i64..=6, 2..=3), 1u32..=2), 1..=3)
        ) {
            let f = field();
            let mut p = UPoly::one();
            for (c, e) in &factors {
                let g = UPoly::from_i64_coeffs(c);
                prop_assume!(!g.is_zero());
                for _ in 0..*e {
                    p = &p * &g;
                }
            }
            prop_assume!(!p.is_constant());
            let lifted = FieldUPoly::lift(&p, &f);
            prop_assert_eq!(lifted.roots(), p.roots());
            prop_assert_eq!(lifted.nonnegative_set(), p.nonnegative_set());
            prop_assert_eq!(lifted.positive_somewhere(), p.positive_somewhere());
        }

        /// A product of linear factors with known roots in the field (some repeated) and a
        /// factor without real roots: every known root is in exactly one interval, with its
        /// multiplicity, and there are no other roots.
        #[test]
        fn products_of_known_factors_have_exactly_their_roots(
            parts in proptest::collection::vec(((-4i64..=4, -2i64..=2, -2i64..=2), 1u32..=2), 1..=3),
            lead in (-3i64..=3, -1i64..=1, 0i64..=1),
        ) {
            let f = field();
            let mut distinct: Vec<(FieldElement, u32)> = Vec::new();
            for (abc, e) in &parts {
                let x = element(&f, *abc);
                match distinct.iter_mut().find(|(y, _)| *y == x) {
                    Some(entry) => entry.1 += e,
                    None => distinct.push((x, *e)),
                }
            }
            let lc = element(&f, lead);
            prop_assume!(!lc.is_zero());
            // (t^2 + lc^2 + 1) has no real root.
            let mut factors = vec![
                FieldUPoly::from_coeffs(vec![lc.clone()]),
                FieldUPoly::from_coeffs(vec![lc.square() + q(1, 1), q(0, 1), q(1, 1)]),
            ];
            for (x, e) in &distinct {
                for _ in 0..*e {
                    factors.push(linear(x));
                }
            }
            let p = product(&factors);
            let roots = p.roots();
            prop_assert_eq!(roots.len(), distinct.len());
            for (x, e) in &distinct {
                let holding: Vec<&Root> =
                    roots.iter().filter(|r| inside(x, &r.interval)).collect();
                prop_assert_eq!(holding.len(), 1);
                prop_assert_eq!(holding[0].multiplicity, *e);
                prop_assert_eq!(holding[0].interval.is_exact(), x.is_rational());
            }
            for w in roots.windows(2) {
                prop_assert!(w[0].interval.hi <= w[1].interval.lo);
            }
        }
    }
}
