//! The same generic code, three scalars: the Bezier toolkit of `exactcheck-core` gives identical
//! results over the fast `Rational` and num-rational's plain `BigRational`, and f64 results within
//! a stated ulps bound of the exact ones on well-conditioned inputs.

use exactcheck_core::{Bernstein, BezierCurve, Field, RationalBezierCurve, Vec3};
use exactcheck_exact::{PlainRational, Rational, RationalScalar};
use exactcheck_float::{f64_to_rational, ulps_error};
use num_rational::BigRational;
use proptest::prelude::*;

/// A small rational `n/d` as the pair the strategies produce.
type Frac = (i64, i64);

fn frac() -> impl Strategy<Value = Frac> {
    (-50i64..50, 1i64..40)
}

fn param() -> impl Strategy<Value = Frac> {
    (0i64..=16).prop_map(|k| (k, 16))
}

fn to<T: Field>(f: Frac) -> T {
    T::from_ratio(f.0, f.1).expect("non-zero denominator")
}

/// Runs a pipeline of toolkit operations and returns every number it produced, as BigRational.
fn pipeline<T: RationalScalar>(pts: &[[Frac; 3]], ws: &[Frac], t: Frac) -> Vec<BigRational> {
    let points: Vec<Vec3<T>> = pts
        .iter()
        .map(|p| Vec3::new(to(p[0]), to(p[1]), to(p[2])))
        .collect();
    let t: T = to(t);
    let mut out: Vec<T> = Vec::new();
    let curve = BezierCurve::new(points.clone());
    out.extend(curve.eval(&t).into_array());
    let (left, right) = curve.split(&t);
    for c in [&left, &right] {
        for p in c.control_points() {
            out.extend(p.clone().into_array());
        }
    }
    out.extend(curve.elevate().eval(&t).into_array());
    out.extend(curve.hodograph().eval(&t).into_array());
    let x = curve.coordinate(0);
    let y = curve.coordinate(1);
    out.extend(x.mul(&y).coeffs().iter().cloned());
    out.extend(x.to_power());
    let weights: Vec<T> = ws.iter().map(|w| to(*w)).collect();
    let rational =
        RationalBezierCurve::from_weights_points(&weights, &points).expect("same length");
    out.extend(rational.eval_hom(&t).0);
    if let Ok(p) = rational.eval(&t) {
        out.extend(p.into_array());
    }
    let back = Bernstein::<T>::from_power(&x.to_power()).expect("non-empty");
    assert_eq!(back, x);
    out.iter().map(|v| v.to_big_rational()).collect()
}

fn curve_data() -> impl Strategy<Value = (Vec<[Frac; 3]>, Vec<Frac>, Frac)> {
    (1usize..7).prop_flat_map(|n| {
        (
            proptest::collection::vec([frac(), frac(), frac()], n + 1),
            proptest::collection::vec(frac(), n + 1),
            param(),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn fast_and_plain_rationals_give_identical_results((pts, ws, t) in curve_data()) {
        prop_assert_eq!(pipeline::<Rational>(&pts, &ws, t), pipeline::<PlainRational>(&pts, &ws, t));
    }

    /// f64 de Casteljau on well-conditioned data — positive control coordinates in [1, 2],
    /// t in [0, 1] — stays within `3n + 1` ulps of the exact value (n the degree): every level
    /// computes `(1 - t) b_i + t b_(i+1)` from non-negative terms, three roundings a level plus
    /// one for `1 - t`, each of relative size at most 2^-53, and without cancellation relative
    /// errors add; an error of k 2^-53 relative is at most k ulps.
    #[test]
    fn f64_de_casteljau_within_bound(
        n in 1usize..8,
        seed in proptest::collection::vec(0u64..(1 << 52), 24),
        tbits in 0u64..(1 << 52),
    ) {
        let coord = |k: usize| 1.0 + (seed[k % seed.len()] as f64) / (1u64 << 52) as f64;
        let t = tbits as f64 / (1u64 << 52) as f64;
        let pts_f: Vec<Vec3<f64>> = (0..=n).map(|i| Vec3::new(coord(3 * i), coord(3 * i + 1), coord(3 * i + 2))).collect();
        let exact = |x: f64| Rational::from(f64_to_rational(x).expect("finite"));
        let pts_q: Vec<Vec3<Rational>> = pts_f.iter().map(|p| p.map(|c| exact(*c))).collect();
        let vf = BezierCurve::new(pts_f).eval(&t).into_array();
        let vq = BezierCurve::new(pts_q).eval(&exact(t)).into_array();
        for (f, q) in vf.iter().zip(vq.iter()) {
            let ulps = ulps_error(*f, &q.to_big_rational());
            prop_assert!(ulps <= (3 * n + 1) as f64, "degree {n}: {ulps} ulps");
        }
    }
}
