//! The two exact decisions of "do the sphere and the cylinder meet" agree on thousands of random
//! exact configurations: the distance of the centre from the axis, and the sign of the
//! discriminant as a polynomial in the circle parameter (exact real root isolation).

use exactcheck_core::cylinder_sphere::{unit_circle_point, Angle, Contact, CylinderSphere};
use exactcheck_core::Vec3;
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::Rational;
use proptest::prelude::*;

fn rat() -> impl Strategy<Value = Rational> {
    (-40i64..40, 1i64..8).prop_map(|(n, d)| Rational::new(n, d).unwrap())
}

fn positive() -> impl Strategy<Value = Rational> {
    (1i64..40, 1i64..6).prop_map(|(n, d)| Rational::new(n, d).unwrap())
}

fn angle() -> impl Strategy<Value = Angle<Rational>> {
    prop_oneof![
        Just(Angle {
            cos: Rational::ONE,
            sin: Rational::ZERO
        }),
        rat().prop_map(|tau| unit_circle_point(&tau).unwrap()),
    ]
}

fn config() -> impl Strategy<Value = CylinderSphere<Rational>> {
    (
        rat(),
        rat(),
        positive(),
        angle(),
        angle(),
        (rat(), rat(), rat()),
        positive(),
    )
        .prop_map(|(a, b, r, beta, gamma, (d, e, f), radius)| CylinderSphere {
            a,
            b,
            r,
            beta,
            gamma,
            center: Vec3::new(d, e, f),
            radius,
        })
}

/// A configuration whose sphere touches the cylinder: the centre at a rational distance delta
/// from the axis (along the rotated x direction, which is perpendicular to it), `R = |delta - r|`.
fn tangent_config() -> impl Strategy<Value = CylinderSphere<Rational>> {
    (config(), positive(), rat()).prop_filter_map("delta != r", |(mut cs, delta, h)| {
        if delta == cs.r {
            return None;
        }
        let (q, dir) = cs.axis();
        let e1 = {
            let probe = CylinderSphere {
                a: Rational::ONE,
                b: Rational::ZERO,
                ..cs.clone()
            };
            let (q1, _) = probe.axis();
            let probe0 = CylinderSphere {
                a: Rational::ZERO,
                b: Rational::ZERO,
                ..cs.clone()
            };
            let (q0, _) = probe0.axis();
            &q1 - &q0
        };
        cs.center = q.add_scaled(&delta, &e1).add_scaled(&h, &dir);
        cs.radius = if delta > cs.r {
            &delta - &cs.r
        } else {
            &cs.r - &delta
        };
        Some(cs)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn the_two_decisions_agree(cs in config()) {
        let a = analyze(&cs);
        prop_assert_eq!(a.contact, cs.contact_by_distance(), "{:?}", cs);
        prop_assert_eq!(a.contact == Contact::Disjoint, a.components == 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn tangent_configurations_are_tangent_both_ways(cs in tangent_config()) {
        prop_assert_eq!(cs.contact_by_distance(), Contact::Tangent, "{:?}", cs);
        let a = analyze(&cs);
        prop_assert_eq!(a.contact, Contact::Tangent, "{:?}", cs);
    }
}
