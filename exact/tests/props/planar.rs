//! Self-intersections of the offsets of Chiang's PH example (the claim list). By the paper,
//! r = 3 gives none and r = 15 a self-intersection with two cusps; the smallest radius of
//! curvature is exactly 101/8 (at t = 1/2), so 63/5 (12.6 as printed) is still below it and
//! 101/8 itself has a single degenerate cusp and no crossing.

use exactcheck_core::ph::PhCurve;
use exactcheck_core::{Bernstein, Vec3};
use exactcheck_exact::planar::{self_intersections_xy, Budget, Certificate, SelfIntersections};
use exactcheck_exact::univariate::RootInterval;
use exactcheck_exact::Rational;
use std::time::{Duration, Instant};

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("non-zero denominator")
}

/// Chiang's worked example: `u = (10, -1)`, `v = (1, 10)` in Bernstein form, from the origin.
fn chiang_example() -> PhCurve<Rational> {
    let i = |k: i64| q(k, 1);
    PhCurve::new(
        Bernstein::new(vec![i(10), i(-1)]),
        Bernstein::new(vec![i(1), i(10)]),
        Vec3::new(i(0), i(0), i(0)),
    )
    .expect("same degree, not zero")
}

/// The self-intersections of the r-offset, with the time taken, after checking that the
/// stationary points found here are as many as the cusps `exactcheck_core::ph` counts (zeros of
/// `sigma^2 - 2 r w`): two independent computations.
fn offset_crossings(r: Rational) -> (SelfIntersections, Duration) {
    let ph = chiang_example();
    let curve = ph.offset(&r);
    let start = Instant::now();
    let found = self_intersections_xy(&curve, Budget::default()).expect("decided");
    let took = start.elapsed();
    let cusps = ph.offset_cusps(&r).expect("regular base curve");
    assert_eq!(found.stationary.len(), cusps.len(), "r = {r}");
    (found, took)
}

/// Generous for release builds (each case takes a few milliseconds); catches a blow-up.
const SLOW: Duration = Duration::from_secs(20);

#[test]
fn chiang_offset_r3_is_simple() {
    let (found, took) = offset_crossings(q(3, 1));
    assert!(found.crossings.is_empty(), "{found:?}");
    assert!(
        found.stationary.is_empty(),
        "no cusp below the minimum radius"
    );
    assert!(took < SLOW);
}

#[test]
fn chiang_offset_r15_crosses_itself_once_symmetrically() {
    let (found, took) = offset_crossings(q(15, 1));
    assert_eq!(found.crossings.len(), 1, "{found:?}");
    let c = &found.crossings[0];
    assert_eq!(c.certificate, Certificate::PoincareMiranda);
    // The curve is symmetric under t -> 1 - t (a test check only; the algorithm does not use
    // it): 1 - t must lie in the s interval.
    let one = Rational::ONE;
    let (lo, hi) = (&one - &c.t_interval.hi, &one - &c.t_interval.lo);
    assert!(lo <= c.s_interval.hi && c.s_interval.lo <= hi, "{c:?}");
    assert!((c.s + c.t - 1.0).abs() < 1e-15);
    assert!((c.s - 0.208_466_555_295_625_8).abs() < 1e-12, "{}", c.s);
    // The reported point is the offset at both parameters (the exact offset evaluated at the
    // midpoints of the intervals, rounded).
    let curve = chiang_example().offset(&q(15, 1));
    for t in [&c.s_interval, &c.t_interval] {
        let p = curve.eval(&t.midpoint()).expect("w != 0");
        assert!((p.x.to_f64() - c.point[0]).abs() < 1e-9);
        assert!((p.y.to_f64() - c.point[1]).abs() < 1e-9);
    }
    // Two cusps, between the parameters of the crossing (the swallowtail).
    assert_eq!(found.stationary.len(), 2);
    for cusp in &found.stationary {
        assert!(c.s_interval.hi < cusp.lo && cusp.hi < c.t_interval.lo);
    }
    assert!(took < SLOW);
}

#[test]
fn chiang_offset_at_the_printed_cusp_radius_is_simple() {
    let (found, took) = offset_crossings(q(63, 5));
    assert!(found.crossings.is_empty(), "{found:?}");
    assert!(found.stationary.is_empty(), "63/5 < 101/8: no cusp yet");
    assert!(took < SLOW);
}

#[test]
fn chiang_offset_at_the_minimum_radius_has_one_cusp_and_no_crossing() {
    let (found, took) = offset_crossings(q(101, 8));
    assert!(found.crossings.is_empty(), "{found:?}");
    assert_eq!(found.stationary, vec![RootInterval::exact(q(1, 2))]);
    assert!(took < SLOW);
}
