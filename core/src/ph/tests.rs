use super::*;
use crate::test_support::Q;

fn q(n: i128, d: i128) -> Q {
    Q::new(n, d)
}

fn qi(n: i128) -> Q {
    Q::new(n, 1)
}

/// Chiang's worked example: `u = (10, -1)`, `v = (1, 10)` in Bernstein form, from the origin.
fn example() -> PhCurve<Q> {
    PhCurve::new(
        Bernstein::new(vec![qi(10), qi(-1)]),
        Bernstein::new(vec![qi(1), qi(10)]),
        Vec3::new(qi(0), qi(0), qi(0)),
    )
    .expect("same degree, not zero")
}

fn xy(points: &[Vec3<Q>]) -> Vec<(Q, Q)> {
    points.iter().map(|p| (p.x, p.y)).collect()
}

#[test]
fn example_control_points_and_normal_field() {
    let c = example();
    assert_eq!(c.degree(), 3);
    assert_eq!(
        xy(c.base().control_points()),
        vec![
            (qi(0), qi(0)),
            (qi(33), q(20, 3)),
            (q(79, 3), q(119, 3)),
            (q(-20, 3), qi(33))
        ]
    );
    let v = c.rotated_normal();
    let got: Vec<[Q; 3]> = v.control_points().iter().map(|p| [p.x, p.y, p.z]).collect();
    assert_eq!(
        got,
        vec![
            [qi(-20), qi(99), qi(101)],
            [qi(-99), qi(-20), qi(0)],
            [qi(20), qi(-99), qi(101)]
        ]
    );
}

#[test]
fn offset_points_are_at_distance_r_along_the_normal() {
    let c = example();
    let r = q(63, 5);
    let off = c.offset(&r);
    assert_eq!(off.degree(), 5);
    assert_eq!(off.weights()[0], qi(101));
    assert_eq!(off.control(), c.offset_control(&r).as_slice());
    let base = c.base();
    let [hx, hy] = c.hodograph();
    for k in 0..=12 {
        let t = q(k, 12);
        let p = off.eval(&t).unwrap();
        let b = base.eval(&t);
        let d = Vec3::new(p.x - b.x, p.y - b.y, p.z - b.z);
        assert_eq!(d.z, r);
        assert_eq!(d.x * d.x + d.y * d.y, r * r);
        // perpendicular to the tangent, on the left
        assert_eq!(d.x * hx.eval(&t) + d.y * hy.eval(&t), qi(0));
        assert!(hx.eval(&t) * d.y - hy.eval(&t) * d.x > qi(0));
    }
}

#[test]
fn example_curvature_radius_and_cusps() {
    let c = example();
    // w = u v' - u' v = 101, sigma(1/2) = 101/2: rho_min = (101/2)^2 / 202 = 101/8 at t = 1/2.
    assert_eq!(c.radius_at(&q(1, 2)), Some(q(101, 8)));
    let m = c.min_radius(Side::Left, &q(1, 1000)).unwrap().unwrap();
    assert_eq!(m.value, RadiusBound::Exact(q(101, 8)));
    assert_eq!(m.attained, vec![IsolatedRoot::Exact(q(1, 2))]);
    assert!(c.is_min_radius(&q(101, 8), Side::Left).unwrap());
    assert!(!c.is_min_radius(&q(63, 5), Side::Left).unwrap());
    assert_eq!(c.min_radius(Side::Right, &q(1, 1000)).unwrap(), None);
    let count = |r: Q| c.offset_cusps(&r).unwrap();
    assert!(count(qi(3)).is_empty());
    assert!(count(q(63, 5)).is_empty(), "12.6 < 101/8: no cusp");
    let one = count(q(101, 8));
    assert_eq!(one.len(), 1);
    assert_eq!(one[0].multiplicity, 2);
    let two = count(qi(15));
    assert_eq!(two.len(), 2);
    assert!(two.iter().all(|c| c.multiplicity == 1));
}

#[test]
fn offset_derivative_vanishes_at_the_cusps() {
    // At r = 101/8 the cusp is at t = 1/2 exactly: the derivative of the rational offset
    // (quotient rule numerators W X' - X W') vanishes there.
    let c = example();
    let off = c.offset(&q(101, 8));
    let h = off.hom_coordinates();
    let t = q(1, 2);
    let w = h[0].eval(&t);
    let dw = h[0].derivative().eval(&t);
    for coordinate in &h[1..=2] {
        let x = coordinate.eval(&t);
        let dx = coordinate.derivative().eval(&t);
        assert_eq!(w * dx - x * dw, qi(0));
    }
}

#[test]
fn degenerate_inputs_are_named() {
    let z = Vec3::new(qi(0), qi(0), qi(0));
    assert_eq!(
        PhCurve::new(
            Bernstein::new(vec![qi(0), qi(0)]),
            Bernstein::new(vec![qi(0), qi(0)]),
            z.clone()
        )
        .unwrap_err(),
        PhError::ZeroPreimage
    );
    assert_eq!(
        PhCurve::new(
            Bernstein::new(vec![qi(1)]),
            Bernstein::new(vec![qi(0), qi(0)]),
            z.clone()
        )
        .unwrap_err(),
        PhError::DegreeMismatch { u: 1, v: 2 }
    );
    // u = v = 1 - 2t vanish together at t = 1/2: the speed is zero there.
    let c = PhCurve::new(
        Bernstein::new(vec![qi(1), qi(-1)]),
        Bernstein::new(vec![qi(1), qi(-1)]),
        z.clone(),
    )
    .unwrap();
    assert_eq!(
        c.offset_cusps(&qi(1)).unwrap_err(),
        PhError::SpeedVanishes(vec![IsolatedRoot::Exact(q(1, 2))])
    );
    // A line (k = 0): no curvature, no radius, the offset is a parallel line of degree 1.
    let line = PhCurve::new(Bernstein::new(vec![qi(2)]), Bernstein::new(vec![qi(1)]), z).unwrap();
    assert_eq!(line.min_radius(Side::Left, &q(1, 8)).unwrap(), None);
    assert_eq!(line.offset(&qi(5)).degree(), 1);
    assert_eq!(line.offset(&qi(5)).weights(), vec![qi(5), qi(5)]);
    assert!(line.offset_cusps(&qi(5)).unwrap().is_empty());
}

#[test]
fn subdivision_decides_the_sign() {
    let power = |a: &[Q]| Bernstein::from_power(a).unwrap();
    // (t - 1/2)^2 + 1/100 > 0 on [0, 1]
    assert_eq!(
        nonpositive_somewhere(&power(&[q(26, 100), qi(-1), qi(1)])),
        Some(false)
    );
    // (t - 1/2)^2 - 1/100 < 0 near 1/2, positive at the ends
    assert_eq!(
        nonpositive_somewhere(&power(&[q(24, 100), qi(-1), qi(1)])),
        Some(true)
    );
    // negative at an end
    assert_eq!(nonpositive_somewhere(&power(&[qi(-1), qi(3)])), Some(true));
}
