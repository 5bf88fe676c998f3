//! `exactcheck_core::conic` over `Q(sqrt 2)` (`Radical`): Table 1's planes, the degenerate
//! planes through the apex, the half-ellipse case `w1 = 0`, and random planes with both type
//! rules agreeing.

use exactcheck::claims::chiang_conic::table1_planes;
use exactcheck_core::conic::{
    angle_rule, bezier_type, cone_surface, ConePiece, ConeSection, ConicType, DegenerateConic,
    SectionType,
};
use exactcheck_core::ruled::Plane;
use exactcheck_core::{Field, Ring, Rng, Vec3};
use exactcheck_exact::Radical;

fn r(s: &str) -> Radical {
    s.parse().unwrap()
}

fn inv_sqrt2() -> Radical {
    r("1/sqrt(2)")
}

fn section(a: &str, b: &str, c: &str, d: &str) -> ConeSection<Radical> {
    ConeSection::new(Plane::new(r(a), r(b), r(c), r(d)), &inv_sqrt2()).unwrap()
}

#[test]
fn the_direction_fields_lie_on_the_cone() {
    for piece in ConePiece::BOTH {
        let s = cone_surface(piece, &inv_sqrt2());
        for k in 0..=8 {
            let t = Radical::from_ratio(k, 8).unwrap();
            let v = s.directions().eval(&t);
            assert_eq!(
                v.x.square() + v.y.square(),
                v.z.square(),
                "{piece:?} t = {k}/8"
            );
            assert!(v.z > Radical::default());
        }
    }
}

#[test]
fn table1_types_by_both_rules() {
    let expected = [
        ConicType::Circle,
        ConicType::Ellipse,
        ConicType::Parabola,
        ConicType::Hyperbola,
    ];
    for (plane, want) in table1_planes().into_iter().zip(expected) {
        let s = ConeSection::new(plane, &inv_sqrt2()).unwrap();
        let check = s.check_types();
        assert_eq!(check.angle_rule, SectionType::Conic(want));
        assert!(check.agree(), "{check:?}");
    }
}

#[test]
fn table1_circle_weights_points_and_hyperbola_poles() {
    let s = section("0", "0", "1", "-1");
    let plus = &s.pieces[0].curve;
    assert_eq!(plus.weights(), vec![r("1"), r("1/sqrt(2)"), r("1")]);
    let pts: Vec<Vec3<Radical>> = plus.points().into_iter().map(Option::unwrap).collect();
    assert_eq!(
        pts,
        vec![
            Vec3::new(r("1"), r("0"), r("1")),
            Vec3::new(r("1"), r("1"), r("1")),
            Vec3::new(r("0"), r("1"), r("1"))
        ]
    );
    let h = section("1", "1", "0", "-2");
    assert!(h.pieces[0].poles.is_empty());
    // C-(t) = infinity at t = 1 - 1/sqrt2 and 1/sqrt2: isolated, not exact (irrational).
    let poles = &h.pieces[1].poles;
    assert_eq!(poles.len(), 2);
    let (a, b) = (r("1 - 1/sqrt(2)"), r("1/sqrt(2)"));
    assert!(poles[0].lo() < &a && &a < poles[0].hi());
    assert!(poles[1].lo() < &b && &b < poles[1].hi());
    let p = section("1", "1", "sqrt(2)", "-2 - sqrt(2)");
    assert_eq!(p.pieces[1].poles.len(), 1);
    assert_eq!(p.pieces[1].poles[0].exact(), Some(&r("1/2")));
}

#[test]
fn planes_through_the_apex_are_named() {
    let cases = [
        (("0", "0", "1"), DegenerateConic::Point),
        (("1", "2", "5"), DegenerateConic::Point),
        (("1", "0", "1"), DegenerateConic::DoubleLine),
        (("3", "4", "-5"), DegenerateConic::DoubleLine),
        (("1", "1", "0"), DegenerateConic::LinePair),
        (("1", "1", "1"), DegenerateConic::LinePair),
    ];
    for ((a, b, c), want) in cases {
        let s = section(a, b, c, "0");
        let check = s.check_types();
        assert_eq!(
            check.angle_rule,
            SectionType::Degenerate(want),
            "({a},{b},{c})"
        );
        assert!(check.agree(), "({a},{b},{c}): {check:?}");
    }
    assert!(ConeSection::new(Plane::new(r("0"), r("0"), r("0"), r("1")), &inv_sqrt2()).is_err());
    assert!(angle_rule(&Plane::new(r("0"), r("0"), r("0"), r("1"))).is_err());
}

#[test]
fn a_half_ellipse_piece_with_zero_middle_weight() {
    // a + b + c = 0 makes w1 = 0; (1, 1, -2) is steep: an ellipse, not a circle.
    let s = section("1", "1", "-2", "3");
    assert!(s.pieces[0].curve.weights()[1].is_zero());
    let check = s.check_types();
    assert_eq!(check.angle_rule, SectionType::Conic(ConicType::Ellipse));
    assert!(check.agree(), "{check:?}");
    assert_eq!(
        bezier_type(&s.pieces[1].curve),
        Some(SectionType::Conic(ConicType::Ellipse))
    );
}

#[test]
fn random_planes_agree_and_their_points_are_on_plane_and_cone() {
    let mut rng = Rng::new(10);
    let small = |rng: &mut Rng| Radical::from(rng.below(13) as i64 - 6);
    for i in 0..300 {
        let (a, b, c) = (small(&mut rng), small(&mut rng), small(&mut rng));
        let d = if i % 10 == 0 {
            Radical::default()
        } else {
            small(&mut rng)
        };
        let plane = Plane::new(a, b, c, d);
        let Ok(s) = ConeSection::new(plane.clone(), &inv_sqrt2()) else {
            assert!(plane.normal.is_zero());
            continue;
        };
        let check = s.check_types();
        assert!(check.agree(), "{plane:?}: {check:?}");
        for piece in &s.pieces {
            for k in 0..=6 {
                let t = Radical::from_ratio(k, 6).unwrap();
                if let Ok(p) = piece.curve.eval(&t) {
                    assert!(plane.value(&p).is_zero());
                    assert_eq!(p.x.square() + p.y.square(), p.z.square());
                }
            }
        }
    }
}
