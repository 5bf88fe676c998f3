use super::*;
use num_traits::Zero;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("non-zero denominator")
}

fn poly(c: &[i64]) -> UPoly {
    UPoly::from_i64_coeffs(c)
}

/// `t = a u + b`.
fn affine(a: i64, b: i64) -> UPoly {
    poly(&[b, a])
}

fn run(x: &UPoly, y: &UPoly, w: &UPoly) -> SelfIntersections {
    self_intersections(x, y, w, Budget::default()).expect("decided")
}

#[test]
fn divided_difference_times_s_minus_t_is_the_antisymmetric_form() {
    let p = poly(&[3, -1, 0, 5, 2]);
    let w = poly(&[1, 2, 1]);
    let f = Dense::divided_difference(&p, &w);
    for (s, t) in [(q(1, 3), q(2, 7)), (q(-2, 1), q(5, 4)), (q(0, 1), q(9, 2))] {
        let lhs = f.eval(&s, &t) * (s.sub_ref(&t));
        let rhs = p.eval(&s) * w.eval(&t) - p.eval(&t) * w.eval(&s);
        assert_eq!(lhs, rhs);
        assert_eq!(f.eval(&s, &t), f.eval(&t, &s), "symmetric");
    }
    // On the diagonal: p' w - p w'.
    let t = q(3, 5);
    let diag = p.derivative().eval(&t) * w.eval(&t) - p.eval(&t) * w.derivative().eval(&t);
    assert_eq!(f.eval(&t, &t), diag);
}

#[test]
fn resultant_matches_a_hand_computed_one() {
    // F = s + t - 1, G = s - 2t: common root s = 2t, 3t - 1 = 0; Res_s = -(3t - 1) up to sign.
    let f = Dense {
        c: vec![vec![q(-1, 1), q(1, 1)], vec![q(1, 1), q(0, 1)]],
    };
    let g = Dense {
        c: vec![vec![q(0, 1), q(-2, 1)], vec![q(1, 1), q(0, 1)]],
    };
    let r = resultant_s(&f, &g);
    assert_eq!(r.degree(), 1);
    assert!(r.eval(&q(1, 3)).is_zero());
    assert!(!r.eval(&q(1, 2)).is_zero());
}

#[test]
fn tensor_bernstein_sign_is_the_sign_on_the_box() {
    // p = s t - 1/4: positive on [1, 2]^2, negative on [0, 1/4]^2, mixed on [0, 1]^2.
    let p = Dense {
        c: vec![vec![q(-1, 4), q(0, 1)], vec![q(0, 1), q(1, 1)]],
    };
    let (one, two) = (q(1, 1), q(2, 1));
    assert_eq!(p.box_sign((&one, &two), (&one, &two)), Some(Sign::Positive));
    let (z, a) = (q(0, 1), q(1, 4));
    assert_eq!(p.box_sign((&z, &a), (&z, &a)), Some(Sign::Negative));
    assert_eq!(p.box_sign((&z, &one), (&z, &one)), None);
}

#[test]
fn nodal_cubic_with_rational_node_is_exact() {
    // (t^2 - 1, t^3 - t), t = 4u - 2: the node (0, 0) at u = 1/4 and u = 3/4.
    let t = affine(4, -2);
    let x = poly(&[-1, 0, 1]).compose(&t);
    let y = poly(&[0, -1, 0, 1]).compose(&t);
    let found = run(&x, &y, &UPoly::one());
    assert_eq!(found.crossings.len(), 1);
    let c = &found.crossings[0];
    assert_eq!(c.s_interval, RootInterval::exact(q(1, 4)));
    assert_eq!(c.t_interval, RootInterval::exact(q(3, 4)));
    assert_eq!(c.certificate, Certificate::Exact);
    assert_eq!(c.point, [0.0, 0.0]);
    assert!(found.stationary.is_empty());
}

/// The nodal cubic `(t^2 - 2, t^3 - 2t)`, `t = 4u - 2`: the node at `u = (2 -+ sqrt 2) / 4`.
fn irrational_node() -> (UPoly, UPoly) {
    let t = affine(4, -2);
    (
        poly(&[-2, 0, 1]).compose(&t),
        poly(&[0, -2, 0, 1]).compose(&t),
    )
}

#[test]
fn nodal_cubic_with_irrational_node_is_certified_by_poincare_miranda() {
    let (x, y) = irrational_node();
    let found = run(&x, &y, &UPoly::one());
    assert_eq!(found.crossings.len(), 1);
    let c = &found.crossings[0];
    assert_eq!(c.certificate, Certificate::PoincareMiranda);
    // (4u - 2)^2 - 2 changes sign across each interval: the true parameters are inside.
    for ri in [&c.s_interval, &c.t_interval] {
        assert!(!ri.is_exact());
        assert_eq!(x.sign_at(&ri.lo) * x.sign_at(&ri.hi), Sign::Negative);
    }
    assert!(c.s_interval.hi < q(1, 2) && c.t_interval.lo > q(1, 2));
    let s = (2.0 - 2f64.sqrt()) / 4.0;
    assert!((c.s - s).abs() < 1e-15 && (c.t - (1.0 - s)).abs() < 1e-15);
    assert!(c.point[0].abs() < 1e-12 && c.point[1].abs() < 1e-12);
}

#[test]
fn a_tangential_self_contact_is_undecided_not_a_guess() {
    // (t^2 - 2, t (t^2 - 2)^2), t = 4u - 2: C(-sqrt 2) = C(sqrt 2) = (0, 0) with both tangents
    // horizontal, so the Jacobian of (F, G) is singular there and Poincare-Miranda cannot
    // succeed; no other pair repeats (x(s) = x(t) forces s = -t, then y forces t = 0).
    let t = affine(4, -2);
    let x = poly(&[-2, 0, 1]).compose(&t);
    let y = poly(&[0, 4, 0, -4, 0, 1]).compose(&t);
    let budget = Budget { max_bisections: 24 };
    match self_intersections(&x, &y, &UPoly::one(), budget) {
        Err(PlanarError::Undecided { s, t, bisections }) => {
            assert_eq!(bisections, 24);
            // The undecided box is the contact.
            assert_eq!(x.sign_at(&s.lo) * x.sign_at(&s.hi), Sign::Negative);
            assert_eq!(x.sign_at(&t.lo) * x.sign_at(&t.hi), Sign::Negative);
        }
        other => panic!("expected Undecided, got {other:?}"),
    }
}

#[test]
fn parabola_arc_is_simple() {
    let found = run(&poly(&[0, 1]), &poly(&[0, 0, 1]), &UPoly::one());
    assert!(found.crossings.is_empty());
    assert!(found.stationary.is_empty());
}

#[test]
fn circle_arcs_are_simple() {
    // (1 - tau^2, 2 tau) / (1 + tau^2): tau in [0, 1] is a quarter circle, tau = 4u - 2 sweeps
    // about 253 degrees; neither closes.
    for t in [affine(1, 0), affine(4, -2)] {
        let x = poly(&[1, 0, -1]).compose(&t);
        let y = poly(&[0, 2]).compose(&t);
        let w = poly(&[1, 0, 1]).compose(&t);
        let found = run(&x, &y, &w);
        assert!(found.crossings.is_empty(), "{found:?}");
        assert!(found.stationary.is_empty());
    }
}

#[test]
fn cuspidal_cubic_has_a_stationary_point_and_no_crossing() {
    let t = affine(2, -1);
    let x = poly(&[0, 0, 1]).compose(&t);
    let y = poly(&[0, 0, 0, 1]).compose(&t);
    let found = run(&x, &y, &UPoly::one());
    assert!(found.crossings.is_empty());
    assert_eq!(found.stationary, vec![RootInterval::exact(q(1, 2))]);
}

#[test]
fn one_rational_and_one_irrational_parameter() {
    // x = u^3 - 2u, y = u x (proper: u = y / x): C(0) = C(sqrt 2) = (0, 0), and nothing else
    // repeats (x(s) = x(t) != 0 forces s = t). With u = 2v: v = 0 and v = sqrt(2) / 2.
    let u = affine(2, 0);
    let x = poly(&[0, -2, 0, 1]).compose(&u);
    let y = poly(&[0, 0, -2, 0, 1]).compose(&u);
    let found = run(&x, &y, &UPoly::one());
    assert_eq!(found.crossings.len(), 1, "{found:?}");
    let c = &found.crossings[0];
    assert_eq!(c.certificate, Certificate::RationalParameter);
    assert_eq!(c.s_interval, RootInterval::exact(q(0, 1)));
    // 2 v^2 - 1 changes sign across the t interval.
    let half_sqrt2 = poly(&[-1, 0, 2]);
    assert_eq!(
        half_sqrt2.sign_at(&c.t_interval.lo) * half_sqrt2.sign_at(&c.t_interval.hi),
        Sign::Negative
    );
    assert!((c.t - 0.5f64.sqrt()).abs() < 1e-15);
}

#[test]
fn an_improper_parametrization_is_a_common_component() {
    // (t^2 - 1, t^3 - t) at t = u^2 + u - 1: u and -1 - u give the same point, so F and G share
    // the factor s + t + 1 (no real zero in [0, 1]^2, but the method does not decide that).
    let t = poly(&[-1, 1, 1]);
    let x = poly(&[-1, 0, 1]).compose(&t);
    let y = poly(&[0, -1, 0, 1]).compose(&t);
    assert_eq!(
        self_intersections(&x, &y, &UPoly::one(), Budget::default()),
        Err(PlanarError::CommonComponent)
    );
}

#[test]
fn weight_vanishing_on_the_interval_is_refused() {
    let w = poly(&[-1, 2]); // zero at 1/2
    match self_intersections(&poly(&[0, 1]), &poly(&[1]), &w, Budget::default()) {
        Err(PlanarError::WeightVanishes(r)) => assert_eq!(r, RootInterval::exact(q(1, 2))),
        other => panic!("{other:?}"),
    }
    assert_eq!(
        self_intersections(
            &poly(&[0, 1]),
            &poly(&[1]),
            &UPoly::zero(),
            Budget::default()
        ),
        Err(PlanarError::ZeroWeight)
    );
}

#[test]
fn a_curve_on_a_line_is_a_common_component() {
    // A segment traversed back and forth: (2u - 1)^2 on the x-axis.
    let x = poly(&[0, 0, 1]).compose(&affine(2, -1));
    assert_eq!(
        self_intersections(&x, &UPoly::zero(), &UPoly::one(), Budget::default()),
        Err(PlanarError::CommonComponent)
    );
}

#[test]
fn hom_and_bezier_constructors_agree_with_the_power_form() {
    let t = affine(4, -2);
    let x = poly(&[-1, 0, 1]).compose(&t);
    let y = poly(&[0, -1, 0, 1]).compose(&t);
    let w = poly(&[2, 0, 1]); // positive
    let (xw, yw) = (x * w.clone(), y * w.clone());
    let d = xw.degree().max(yw.degree());
    let lift = |p: &UPoly| Bernstein::from_power(&padded(p, d)).expect("non-empty");
    let hom = [lift(&w), lift(&xw), lift(&yw)];
    let direct = run(&xw, &yw, &w);
    let via_hom = self_intersections_hom(&hom, Budget::default()).expect("decided");
    assert_eq!(direct, via_hom);
    let zero = Bernstein::new(vec![Rational::ZERO; d + 1]);
    let curve = RationalBezierCurve::from_hom_coordinates(&[
        hom[0].clone(),
        hom[1].clone(),
        hom[2].clone(),
        zero,
    ])
    .expect("same lengths");
    assert_eq!(
        self_intersections_xy(&curve, Budget::default()).expect("decided"),
        direct
    );
    assert_eq!(direct.crossings.len(), 1);
}

#[test]
fn candidate_roots_are_those_of_the_square_free_part_in_the_unit_interval() {
    // (x - 1/3)^2 (x^2 - 1/2) (x - 3/4)^3 (x - 2): roots 1/3, sqrt(1/2), 3/4 in [0, 1].
    let base = UPoly::from_roots(&[q(1, 3), q(3, 4), q(2, 1)]) * poly(&[-1, 0, 2]);
    let repeated = base.clone() * UPoly::from_roots(&[q(1, 3), q(3, 4), q(3, 4)]);
    let sqf = repeated.primitive_square_free_part();
    assert_eq!(sqf, base.primitive_part());
    let roots = unit_roots(&sqf);
    assert_eq!(roots.len(), 3);
    assert_eq!(roots[0].exact_value(), Some(&q(1, 3)));
    assert_eq!(roots[2].exact_value(), Some(&q(3, 4)));
    let half = poly(&[-1, 0, 2]);
    assert_eq!(
        half.sign_at(&roots[1].lo) * half.sign_at(&roots[1].hi),
        Sign::Negative
    );
    assert!(descartes_one(&sqf, &roots[1].lo, &roots[1].hi));
    // Counting one root on an interval: sqrt(1/2) alone in [2/3, 0.72]; three roots in [0, 1].
    assert!(descartes_one(&sqf, &q(2, 3), &q(72, 100)));
    assert!(!descartes_one(&sqf, &q(0, 1), &q(1, 1)));
    // An end that is a root is refused.
    assert!(!descartes_one(&sqf, &q(1, 3), &q(1, 2)));
}

#[test]
fn bareiss_determinants() {
    use super::resultant::bareiss;
    let m = |rows: &[&[i64]]| -> Vec<Vec<BigInt>> {
        rows.iter()
            .map(|r| r.iter().map(|&v| BigInt::from(v)).collect())
            .collect()
    };
    // A zero first pivot (one swap); by cofactors along the first row: -2 (1 - 6) + (1 - 2) = 9.
    assert_eq!(
        bareiss(m(&[&[0, 2, 1], &[1, 1, 3], &[2, 1, 1]])),
        BigInt::from(9)
    );
    assert_eq!(bareiss(m(&[&[2, 4], &[1, 2]])), BigInt::zero());
    assert_eq!(bareiss(m(&[&[5]])), BigInt::from(5));
    assert_eq!(bareiss(Vec::new()), BigInt::one());
}

#[test]
fn modular_resultant_agrees_with_bareiss_on_random_offsets() {
    use super::resultant::resultant_s_bareiss;
    let mut rng = exactcheck_core::Rng::new(7);
    for round in 0..12 {
        let deg = 1 + round % 4;
        let digits = 1 + 10 * (round % 3) as u32;
        let big = BigInt::from(10).pow(digits);
        let mut r = |n: usize| -> UPoly {
            UPoly::from_coeffs(
                (0..=n)
                    .map(|_| {
                        let x = BigInt::from(rng.below(2_000_001) as i64 - 1_000_000) * &big
                            + BigInt::from(rng.below(2001) as i64 - 1000);
                        Rational::from(x) / Rational::from(BigInt::from(1 + rng.below(7)))
                    })
                    .collect(),
            )
        };
        let (x, y, w) = (r(deg + 1), r(deg + 1), r(deg));
        let f = Dense::divided_difference(&x, &w);
        let g = Dense::divided_difference(&y, &w);
        assert_eq!(
            resultant_s(&f, &g),
            resultant_s_bareiss(&f, &g),
            "round {round}"
        );
    }
}
