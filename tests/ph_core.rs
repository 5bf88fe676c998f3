//! `exactcheck_core::ph` over the exact rationals: the smallest radius of curvature of a curve
//! whose minimum is irrational is enclosed, and the enclosure is certified by the cusp count of
//! the offsets at its two ends.

use exactcheck_core::ph::{PhCurve, RadiusBound, Side};
use exactcheck_core::{Bernstein, Vec3};
use exactcheck_exact::Rational;

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

#[test]
fn a_quintic_with_an_irrational_minimum_is_enclosed() {
    // u = (1, 0, 1), v = (0, 1, 1): k = 2, a quintic PH curve; its offsets have degree 9.
    let c = PhCurve::new(
        Bernstein::new(vec![q("1"), q("0"), q("1")]),
        Bernstein::new(vec![q("0"), q("1"), q("1")]),
        Vec3::new(q("0"), q("0"), q("0")),
    )
    .unwrap();
    assert_eq!(c.offset(&q("1")).degree(), 9);
    let tol = q("1/1000000");
    let mut seen = 0;
    for side in [Side::Left, Side::Right] {
        let Some(m) = c.min_radius(side, &tol).unwrap() else {
            continue;
        };
        seen += 1;
        let signed = |x: &Rational| match side {
            Side::Left => x.clone(),
            Side::Right => -x.clone(),
        };
        match m.value {
            RadiusBound::Exact(v) => panic!("{side:?}: the minimum is irrational, got {v}"),
            RadiusBound::Within(lo, hi) => {
                assert!(hi.clone() - lo.clone() <= tol);
                assert!(c.offset_cusps(&signed(&lo)).unwrap().is_empty());
                assert!(!c.offset_cusps(&signed(&hi)).unwrap().is_empty());
                assert!(!c.is_min_radius(&hi, side).unwrap() || lo == hi);
            }
        }
    }
    assert_eq!(seen, 2, "w changes sign: both sides are curved");
}
