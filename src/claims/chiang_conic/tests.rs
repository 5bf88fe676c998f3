//! Tests of the conic claims' internals.

use super::*;

/// The homogeneous point test against the affine reference, on Table 1 and on planes of
/// every generator (through the apex and not), and on planes the curves do not lie in.
#[test]
fn homogeneous_points_agree_with_the_affine_reference() {
    let mut rng = Rng::new(7);
    let through = Vec3::new(Radical::one(), Radical::one(), Radical::one());
    let mut planes: Vec<Plane<Radical>> = TABLE1
        .iter()
        .map(|col| {
            let n = vec3(&col.normal).expect("Table 1 parses");
            let d = n.dot(&through).neg_ref();
            Plane::new(n.x, n.y, n.z, d)
        })
        .collect();
    for i in 0..140 {
        let kind = PlaneKind::ALL[i % PlaneKind::ALL.len()];
        planes.push(random_plane(&mut rng, kind, i % 4 == 3));
    }
    for plane in &planes {
        let fast = check_section(plane).expect("non-zero normal");
        let reference = check_section_reference(plane).expect("non-zero normal");
        assert_eq!(fast, reference, "{}", plane_text(plane));
    }
}

#[test]
fn scaled_hom_is_d_to_the_degree_times_the_point() {
    let mut rng = Rng::new(11);
    for i in 0..30 {
        let plane = random_plane(&mut rng, PlaneKind::ALL[i % 7], false);
        let section = ConeSection::new(plane, &inv_sqrt2()).expect("non-zero normal");
        for piece in &section.pieces {
            let deg = piece.curve.control().len() as u32 - 1;
            for (n, d) in SAMPLE_T {
                let t = Radical::from_ratio(n, d).expect("d != 0");
                let scale = Radical::from(Rational::from_integer(d).pow(deg));
                let expected = Hom4(piece.curve.eval_hom(&t).0.map(|x| x.mul_ref(&scale)));
                assert_eq!(scaled_hom(&piece.curve, n, d), expected, "t = {n}/{d}");
            }
        }
    }
}

/// A point test that finds every point off reports the affine point, as the reference
/// would print it (the failure text is made from `eval`, not from the scaled point).
#[test]
fn off_points_are_printed_affine() {
    let plane = Plane::new(
        Radical::zero(),
        Radical::zero(),
        Radical::one(),
        Radical::from(-1i64),
    );
    let r = check_section_with(&plane, |_, _, _, _| Some((true, false))).unwrap();
    assert_eq!(r.off.len(), r.points_checked);
    assert!(
        r.off[0].starts_with("C+(0/1) = (1, 0, 1) is off the cone"),
        "{}",
        r.off[0]
    );
    assert!(!r.agrees());
}
