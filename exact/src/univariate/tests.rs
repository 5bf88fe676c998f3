//! Unit tests of univariate polynomials and root isolation.

use super::*;
use crate::poly::Poly;
use exactcheck_core::ZeroDivisor;
use std::cmp::Ordering;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

fn int(n: i64) -> Rational {
    Rational::from_integer(n)
}

fn p(c: &[i64]) -> UPoly {
    UPoly::from_i64_coeffs(c)
}

#[test]
fn canonical_and_arithmetic() {
    let a = UPoly::from_coeffs(vec![int(1), int(2), int(0), int(0)]);
    assert_eq!(a.coeffs().len(), 2);
    assert_eq!(a.degree(), 1);
    let b = p(&[-1, 0, 1]);
    assert_eq!(&a + &b, p(&[0, 2, 1]));
    assert_eq!(&a - &a, UPoly::zero());
    assert_eq!(&a * &b, p(&[-1, -2, 1, 2]));
    assert_eq!(-&a, p(&[-1, -2]));
    assert_eq!(a.scale(&q(1, 2)), UPoly::from_coeffs(vec![q(1, 2), int(1)]));
    assert_eq!(b.eval(&int(3)), int(8));
    assert_eq!(b.derivative(), p(&[0, 2]));
    assert_eq!(b.compose(&a), p(&[0, 4, 4]));
    assert_eq!(UPoly::from_roots(&[int(1), int(-1)]), b);
    assert!(UPoly::zero().is_zero());
    assert_eq!(UPoly::zero().degree(), 0);
    assert_eq!(Ring::pow(&a, 2), p(&[1, 4, 4]));
}

#[test]
fn division_and_gcd() {
    let a = p(&[-1, 0, 0, 1]); // x^3 - 1
    let b = p(&[-1, 1]); // x - 1
    let (quo, r) = a.div_rem(&b);
    assert_eq!(quo, p(&[1, 1, 1]));
    assert!(r.is_zero());
    let (quo, r) = a.div_rem(&p(&[1, 2]));
    assert_eq!(&quo * &p(&[1, 2]) + &r, a);
    assert!(r.degree() < 1);
    assert_eq!(a.checked_div_rem(&UPoly::zero()), Err(ZeroDivisor));
    let g = p(&[-1, 0, 1]).gcd(&a);
    assert_eq!(g, b);
    assert_eq!(UPoly::zero().gcd(&UPoly::zero()), UPoly::zero());
    assert_eq!(UPoly::zero().gcd(&p(&[0, 3])), p(&[0, 1]));
}

#[test]
fn content_and_primitive_part() {
    let a = UPoly::from_coeffs(vec![q(-2, 3), q(4, 9), int(2)]);
    assert_eq!(a.content(), q(2, 9));
    assert_eq!(a.primitive_part(), p(&[-3, 2, 9]));
    let n = a.neg_ref();
    assert_eq!(n.primitive_part(), p(&[3, -2, -9]));
}

#[test]
fn square_free() {
    // (x-1)^3 (x+2)^2 (x^2+1)
    let f = Ring::pow(&p(&[-1, 1]), 3) * Ring::pow(&p(&[2, 1]), 2) * p(&[1, 0, 1]);
    let f = f.scale(&q(-3, 2));
    assert_eq!(
        f.square_free_part(),
        p(&[-1, 1]) * p(&[2, 1]) * p(&[1, 0, 1])
    );
    let dec = f.square_free_decomposition();
    assert_eq!(
        dec,
        vec![(p(&[1, 0, 1]), 1), (p(&[2, 1]), 2), (p(&[-1, 1]), 3)]
    );
    let roots = f.roots();
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[0].interval, RootInterval::exact(int(-2)));
    assert_eq!(roots[0].multiplicity, 2);
    assert_eq!(roots[1].interval, RootInterval::exact(int(1)));
    assert_eq!(roots[1].multiplicity, 3);
}

#[test]
fn display_and_poly_round_trip() {
    let a = UPoly::from_coeffs(vec![int(1), q(-1, 2), int(3)]);
    assert_eq!(a.to_string(), "3*x^2 - 1/2*x + 1");
    assert_eq!(p(&[0, -1, 0, 1]).display("tau").to_string(), "tau^3 - tau");
    assert_eq!(p(&[-5]).to_string(), "-5");
    assert_eq!(UPoly::zero().to_string(), "0");
    let mut vars = crate::poly::Vars::new();
    let parsed: Poly<Rational> =
        crate::expr::parse_poly(&a.display("t").to_string(), &mut vars).unwrap();
    let t = vars.get("t").unwrap();
    assert_eq!(UPoly::from_poly(&parsed, t).unwrap(), a);
    assert_eq!(a.to_poly(t), parsed);
    let two: Poly<Rational> = crate::expr::parse_poly("t*s + 1", &mut vars).unwrap();
    let s = vars.get("s").unwrap();
    assert_eq!(
        UPoly::from_poly(&two, t),
        Err(FromPolyError::OtherVariable(s))
    );
    let c: Poly<Rational> = crate::expr::parse_poly("7/3", &mut vars).unwrap();
    assert_eq!(UPoly::from_poly(&c, s).unwrap(), UPoly::constant(q(7, 3)));
}

#[test]
fn sturm_counts() {
    // x^2 - 2: roots +-sqrt 2.
    let f = p(&[-2, 0, 1]);
    let seq = f.sturm_sequence();
    assert_eq!(seq.len(), 3);
    assert_eq!(f.count_real_roots(), 2);
    assert_eq!(f.count_roots(&int(0), &int(2)), 1);
    assert_eq!(f.count_roots(&int(-2), &int(2)), 2);
    assert_eq!(f.count_roots(&int(2), &int(-2)), 0);
    // Half-open: (x-1)(x-2) on (1, 2] counts 2 only, on (0, 1] counts 1.
    let g = p(&[2, -3, 1]);
    assert_eq!(g.count_roots(&int(1), &int(2)), 1);
    assert_eq!(g.count_roots(&int(0), &int(1)), 1);
    assert_eq!(g.count_roots(&int(0), &int(2)), 2);
    assert_eq!(p(&[1, 0, 1]).count_real_roots(), 0);
    assert_eq!(p(&[3]).count_real_roots(), 0);
    assert_eq!(UPoly::zero().count_real_roots(), 0);
}

#[test]
fn isolation_and_refinement() {
    // (x^2 - 2)(3x - 1)(x + 5)^2
    let f = p(&[-2, 0, 1]) * p(&[-1, 3]) * Ring::pow(&p(&[5, 1]), 2);
    let roots = f.isolate_roots();
    assert_eq!(roots.len(), 4);
    assert_eq!(roots[0], RootInterval::exact(int(-5)));
    assert!(!roots[1].is_exact());
    assert_eq!(roots[2], RootInterval::exact(q(1, 3)));
    assert!(!roots[3].is_exact());
    let w = q(1, 1000000);
    let r = f.refine(&roots[3], &w);
    assert!(r.width() <= w);
    assert!(r.lo.square() < int(2) && r.hi.square() > int(2) && r.lo > int(0));
    assert!((r.to_f64() - std::f64::consts::SQRT_2).abs() < 1e-6);
    assert_eq!(f.multiplicity(&roots[0]), 2);
    assert_eq!(f.multiplicity(&roots[1]), 1);
    assert_eq!(f.multiplicity(&RootInterval::exact(int(7))), 0);
    assert_eq!(f.compare_with_root(&roots[3], &q(141, 100)), Ordering::Less);
    assert_eq!(
        f.compare_with_root(&roots[3], &q(142, 100)),
        Ordering::Greater
    );
}

#[test]
fn rational_roots_with_awkward_denominators_are_exact() {
    let rs = [q(1, 3), q(-7, 5), q(22, 7), q(1, 97)];
    let f = UPoly::from_roots(&rs).scale(&q(-4, 9));
    let got: Vec<Rational> = f
        .isolate_roots()
        .iter()
        .map(|r| r.exact_value().cloned().unwrap())
        .collect();
    let mut want = rs.to_vec();
    want.sort();
    assert_eq!(got, want);
}

#[test]
fn midpoint_roots_leave_no_root_endpoints() {
    // x^3 - 2x: the first bisection point 0 is a root.
    let f = p(&[0, -2, 0, 1]);
    let roots = f.isolate_roots();
    assert_eq!(roots.len(), 3);
    assert_eq!(roots[1], RootInterval::exact(int(0)));
    for r in [&roots[0], &roots[2]] {
        assert_ne!(f.sign_at(&r.lo), Sign::Zero);
        assert_ne!(f.sign_at(&r.hi), Sign::Zero);
        let fine = f.refine(r, &q(1, 1 << 20));
        assert!(fine.width() <= q(1, 1 << 20));
    }
    // Roots at dyadic points, hit by bisection at several levels.
    let g = UPoly::from_roots(&[int(0), int(2), int(-3), q(1, 2), q(3, 4)]) * p(&[-3, 0, 1]);
    let roots = g.isolate_roots();
    assert_eq!(roots.len(), 7);
    assert_eq!(roots.iter().filter(|r| r.is_exact()).count(), 5);
    for r in roots.iter().filter(|r| !r.is_exact()) {
        assert_ne!(g.sign_at(&r.lo), Sign::Zero);
        assert_ne!(g.sign_at(&r.hi), Sign::Zero);
    }
}

#[test]
fn wilkinson_and_close_roots() {
    // Wilkinson's polynomial of degree 20: all roots integers, found exactly.
    let rs: Vec<Rational> = (1..=20).map(int).collect();
    let w = UPoly::from_roots(&rs);
    let got: Vec<Rational> = w
        .isolate_roots()
        .iter()
        .map(|r| r.exact_value().cloned().unwrap())
        .collect();
    assert_eq!(got, rs);
    // Clustered roots 1/1000, 1/1001, 1/1002 and an irrational pair sqrt(10^-6 + 1/7).
    let f = UPoly::from_roots(&[q(1, 1000), q(1, 1001), q(1, 1002)])
        * UPoly::from_coeffs(vec![-(q(1, 1000000) + q(1, 7)), int(0), int(1)]);
    let roots = f.isolate_roots();
    assert_eq!(roots.len(), 5);
    assert_eq!(roots[1], RootInterval::exact(q(1, 1002)));
    assert_eq!(roots[2], RootInterval::exact(q(1, 1001)));
    assert_eq!(roots[3], RootInterval::exact(q(1, 1000)));
    assert!(!roots[0].is_exact() && !roots[4].is_exact());
}

#[test]
#[should_panic(expected = "not an isolating interval")]
fn refine_rejects_non_isolating_intervals() {
    p(&[-2, 0, 1]).refine(
        &RootInterval {
            lo: int(-2),
            hi: int(2),
        },
        &q(1, 10),
    );
}

/// The discriminant `D(tau)` of the claim list for the unit-parameter cylinder `x = 5 cos t`,
/// `y = 5 sin t`, `z = u` and the sphere with centre `(d, e, f)` and radius `rr`:
/// `u^2 - 2 f u + f^2 + (5c - d)^2 + (5s - e)^2 - rr^2 = 0`, so
/// `A^2 - B = rr^2 - (5c - d)^2 - (5s - e)^2`, times `(1 + tau^2)^2`.
fn cylinder_sphere_disc(d: i64, e: i64, rr: i64) -> UPoly {
    let one_plus = p(&[1, 0, 1]);
    let c_num = p(&[1, 0, -1]); // (1 - tau^2)
    let s_num = p(&[0, 2]); // 2 tau
    let x = c_num.scale(&int(5)) - one_plus.scale(&int(d));
    let y = s_num.scale(&int(5)) - one_plus.scale(&int(e));
    one_plus.square().scale(&int(rr * rr)) - x.square() - y.square()
}

#[test]
fn spaeth_examples() {
    // Example 1: centre (1,0,0), R = 7: real for every t.
    let d1 = cylinder_sphere_disc(1, 0, 7);
    assert_eq!(d1, p(&[33, 0, 46, 0, 13]));
    assert_eq!(
        d1.nonnegative_set(),
        vec![RootBoundedInterval {
            lo: Bound::NegInf,
            hi: Bound::PosInf
        }]
    );
    assert!(d1.positive_somewhere());
    // Example 3: centre (6,7,8), R = 1: no intersection.
    let d3 = cylinder_sphere_disc(6, 7, 1);
    assert!(!d3.nonnegative_somewhere());
    assert!(!d3.positive_somewhere());
    assert!(d3.nonnegative_set().is_empty());
    // Tangency: centre (6,0,0), R = 1 touches the cylinder at t = 0 (tau = 0) only.
    let dt = cylinder_sphere_disc(6, 0, 1);
    assert_eq!(dt, p(&[0, 0, -120, 0, -120]));
    assert!(dt.nonnegative_somewhere());
    assert!(!dt.positive_somewhere());
    let zero = RootInterval::exact(int(0));
    assert_eq!(
        dt.nonnegative_set(),
        vec![RootBoundedInterval {
            lo: Bound::Root(zero.clone()),
            hi: Bound::Root(zero.clone())
        }]
    );
    let touching = dt.touching_points();
    assert_eq!(touching.len(), 1);
    assert_eq!(touching[0].interval, zero);
    assert_eq!(touching[0].multiplicity, 2);
    // A genuine crossing: centre (5,0,0), R = 2: an arc around t = 0.
    let dc = cylinder_sphere_disc(5, 0, 2);
    let set = dc.nonnegative_set();
    assert_eq!(set.len(), 1);
    assert!(set[0].contains(&dc, &int(0)));
    assert!(!set[0].contains(&dc, &int(1)));
    assert!(dc.touching_points().is_empty());
}

#[test]
fn nonnegative_sets_of_simple_shapes() {
    // -(x-1)^2 (x-3): >= 0 on (-inf, 3], with 1 inside.
    let f = Ring::pow(&p(&[-1, 1]), 2) * p(&[3, -1]);
    let set = f.nonnegative_set();
    assert_eq!(set.len(), 1);
    assert_eq!(set[0].lo, Bound::NegInf);
    assert_eq!(set[0].hi, Bound::Root(RootInterval::exact(int(3))));
    // (x^2 - 2)(x - 5): [-sqrt2, sqrt2] and [5, inf).
    let g = p(&[-2, 0, 1]) * p(&[-5, 1]);
    let set = g.nonnegative_set();
    assert_eq!(set.len(), 2);
    assert!(set[0].contains(&g, &int(0)));
    assert!(!set[0].contains(&g, &int(2)));
    assert!(set[1].contains(&g, &int(5)) && set[1].contains(&g, &int(500)));
    assert_eq!(set[1].to_string(), "[5, +inf]");
    // Constants and zero.
    assert_eq!(UPoly::zero().nonnegative_set().len(), 1);
    assert_eq!(p(&[2]).nonnegative_set().len(), 1);
    assert!(p(&[-2]).nonnegative_set().is_empty());
    assert!(!p(&[-2]).nonnegative_somewhere());
    assert!(UPoly::zero().nonnegative_somewhere());
    assert!(!UPoly::zero().positive_somewhere());
    // Odd degree, negative leading coefficient: positive somewhere.
    assert!(p(&[0, 0, 0, -1]).positive_somewhere());
    // -(x^2+1)^2 (x-1)^2: nowhere >= 0 except x = 1.
    let h = -(Ring::pow(&p(&[1, 0, 1]), 2) * Ring::pow(&p(&[-1, 1]), 2));
    assert!(!h.positive_somewhere());
    assert!(h.nonnegative_somewhere());
    assert_eq!(h.touching_points().len(), 1);
}

#[test]
fn sign_chart_gaps() {
    // x^3 (x - 2)^2 (x + 1): roots -1, 0, 2.
    let f = Ring::pow(&p(&[0, 1]), 3) * Ring::pow(&p(&[-2, 1]), 2) * p(&[1, 1]);
    let chart = f.sign_chart();
    assert_eq!(
        chart.gaps,
        vec![
            Sign::Positive,
            Sign::Negative,
            Sign::Positive,
            Sign::Positive
        ]
    );
    for (i, x) in [int(-2), q(-1, 2), int(1), int(3)].iter().enumerate() {
        assert_eq!(f.sign_at(x), chart.gaps[i]);
    }
    assert_eq!(UPoly::zero().sign_chart().gaps, vec![Sign::Zero]);
}

#[test]
fn large_coefficients() {
    // Roots 10^30 + 1/3 and -1/(10^25), plus x^2 - 3.
    let big = Rational::from(num_bigint::BigInt::from(10u32).pow(30)) + q(1, 3);
    let tiny = Rational::from(num_bigint::BigInt::from(10u32).pow(25))
        .recip()
        .unwrap()
        .neg_ref();
    let f = UPoly::from_roots(&[big.clone(), tiny.clone()]) * p(&[-3, 0, 1]);
    let roots = f.isolate_roots();
    assert_eq!(roots.len(), 4);
    assert_eq!(roots[1], RootInterval::exact(tiny));
    assert_eq!(roots[3], RootInterval::exact(big));
}

#[test]
fn refinement_to_ten_thousand_bits_is_quadratic_and_correct() {
    // x^2 - 2: the positive root refined to 2^-10240 (bisection took 10,240 sign evaluations of
    // ever longer numbers; quadratic interval refinement takes a few dozen).
    let f = p(&[-2, 0, 1]);
    let roots = f.isolate_roots();
    let r = &roots[1];
    let w = Rational::ONE / Rational::from_integer(2).pow(10_240);
    let fine = f.refine(r, &w);
    assert!(fine.width() <= w);
    let two = Rational::from_integer(2);
    assert!(fine.lo.mul_ref(&fine.lo) < two && fine.hi.mul_ref(&fine.hi) > two);
    // The limit is checked before the work: 2^-200000 asks more halvings than the default.
    let tiny = Rational::ONE / Rational::from_integer(2).pow(200_000);
    let e = f.try_refine(r, &tiny).unwrap_err();
    assert!(e.to_string().contains("the limit bisection"), "{e}");
}

#[test]
fn isolation_with_a_huge_leading_coefficient_makes_rational_roots_exact() {
    // (10^600 x - 1)(x^2 - 3): making the rational root 10^-600 exact bisected about 2,000
    // times below 1/l; the refinement now narrows the interval quadratically.
    let big = Rational::from_integer(10).pow(600);
    let f =
        UPoly::from_coeffs(vec![Rational::from_integer(-1), big.clone()]).mul_ref(&p(&[-3, 0, 1]));
    let roots = f.isolate_roots();
    assert_eq!(roots.len(), 3);
    assert_eq!(roots[1].exact_value(), Some(&(Rational::ONE / big)));
    assert!(!roots[0].is_exact() && !roots[2].is_exact());
}

/// The production paths (the bisection shape from the Descartes isolator, the Descartes counts)
/// against the Sturm reference, on products of small factors with multiplicities up to 3 (so
/// rational roots, repeated roots and roots at bisection midpoints such as 0 are frequent).
mod against_sturm {
    use super::super::sturm::SquareFree;
    use super::*;
    use proptest::prelude::*;

    fn arb_poly() -> impl Strategy<Value = UPoly> {
        proptest::collection::vec(
            (proptest::collection::vec(-9i64..=9, 2..=4), 1u32..=3),
            1..=4,
        )
        .prop_map(|fs| {
            fs.iter()
                .map(|(c, m)| (p(c), *m))
                .filter(|(f, _)| !f.is_zero())
                .fold(UPoly::one(), |acc, (f, m)| acc * Ring::pow(&f, m))
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]
        #[test]
        fn bisection_shape_and_counts_are_the_sturm_references(
            f in arb_poly(),
            a in -64i64..=64,
            w in 1i64..=64,
        ) {
            let sturm = isolate_real_roots_sturm(&f);
            prop_assert_eq!(f.isolate_roots(), sturm.clone());
            if f.is_constant() {
                prop_assert_eq!(f.count_real_roots(), 0);
                return Ok(());
            }
            let sf = SquareFree::new(&f);
            prop_assert_eq!(f.count_real_roots(), sf.count_all());
            prop_assert_eq!(f.count_real_roots(), sturm.len());
            let (lo, hi) = (q(a, 8), q(a + w, 8));
            prop_assert_eq!(f.count_roots(&lo, &hi), sf.count(&lo, &hi));
            prop_assert_eq!(f.count_roots(&hi, &lo), 0);
            // The production isolator's intervals hold the reference's roots, one each.
            let fast = isolate_real_roots(&f);
            prop_assert_eq!(fast.len(), sturm.len());
            for (x, s) in fast.iter().zip(&sturm) {
                prop_assert_eq!(x.is_exact(), s.is_exact());
                if x.is_exact() {
                    prop_assert_eq!(x, s);
                } else {
                    let (l, h) = (x.lo.clone().max(s.lo.clone()), x.hi.clone().min(s.hi.clone()));
                    prop_assert!(l < h, "{x:?} and {s:?} are disjoint");
                    prop_assert_eq!(sf.count(&l, &h), 1);
                }
            }
        }
    }
}
