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

/// Random quadratic and cubic `u`, `v` with coefficients of up to 40 digits: every enclosure of
/// the smallest radius is certified by the cusp counts at its two ends (no cusp at `lo`, a cusp
/// at `hi`) and is at most the tolerance wide, and the parameters reported for it bracket a
/// minimum (the radius there is at most `hi`).
#[test]
fn enclosures_of_random_curves_with_large_coefficients_are_certified() {
    let mut rng = exactcheck_core::Rng::new(11);
    let tol = q("1/1048576");
    let mut enclosed = 0;
    for round in 0..16 {
        let digits = 1 + (round % 4) * 13;
        let mut coeff = || -> Rational {
            let mut s = String::new();
            if rng.below(2) == 1 {
                s.push('-');
            }
            s.push(char::from(b'1' + rng.below(9) as u8));
            for _ in 1..digits {
                s.push(char::from(b'0' + rng.below(10) as u8));
            }
            q(&s)
        };
        let n = 3 + round % 2;
        let u: Vec<Rational> = (0..n).map(|_| coeff()).collect();
        let v: Vec<Rational> = (0..n).map(|_| coeff()).collect();
        let c = PhCurve::new(
            Bernstein::new(u),
            Bernstein::new(v),
            Vec3::new(q("0"), q("0"), q("0")),
        )
        .unwrap();
        if !c.speed_zeros().is_empty() {
            continue;
        }
        for side in [Side::Left, Side::Right] {
            let Some(m) = c.min_radius(side, &tol).unwrap() else {
                continue;
            };
            let signed = |x: &Rational| match side {
                Side::Left => x.clone(),
                Side::Right => -x.clone(),
            };
            match m.value {
                RadiusBound::Exact(v) => {
                    assert!(c.is_min_radius(&v, side).unwrap(), "round {round}: {v}");
                }
                RadiusBound::Within(lo, hi) => {
                    enclosed += 1;
                    assert!(hi.clone() - lo.clone() <= tol, "round {round}");
                    assert!(
                        lo <= q("0") || c.offset_cusps(&signed(&lo)).unwrap().is_empty(),
                        "round {round}: a cusp at the lower end {lo}"
                    );
                    assert!(
                        !c.offset_cusps(&signed(&hi)).unwrap().is_empty(),
                        "round {round}: no cusp at the upper end {hi}"
                    );
                    assert!(!m.attained.is_empty(), "round {round}");
                }
            }
        }
    }
    assert!(
        enclosed >= 4,
        "only {enclosed} irrational minima: the test says little"
    );
}
