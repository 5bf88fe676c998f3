//! The two exact decisions of "do the sphere and the cylinder meet" agree on thousands of random
//! exact configurations: the distance of the centre from the axis, and the sign of the
//! discriminant as a polynomial in the circle parameter (exact real root isolation). So do their
//! answers to "where do they touch" (the multiple roots of the discriminant against
//! `delta = r + R`, `delta = |r - R| > 0`, or `delta = 0` with `R = r`), on configurations built to
//! sit on those boundaries: the centre on the axis, `R = r`, `R = r + delta`, `R = delta - r`,
//! `R = r - delta`.

use exactcheck_core::cylinder_sphere::{
    unit_circle_point, Angle, Contact, CylinderSphere, Touching,
};
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

/// The rotated x direction, a unit vector perpendicular to the axis.
fn normal_direction(cs: &CylinderSphere<Rational>) -> exactcheck_core::Vec3<Rational> {
    let probe = |a: Rational| {
        CylinderSphere {
            a,
            b: Rational::ZERO,
            ..cs.clone()
        }
        .axis()
        .0
    };
    &probe(Rational::ONE) - &probe(Rational::ZERO)
}

/// Which sphere radius a boundary configuration takes, for the centre at distance `delta`.
#[derive(Clone, Copy, Debug)]
enum RadiusChoice {
    /// `R = r` (with `delta = 0`: the touching circle).
    EqualRadii,
    /// `R = r + delta`: the figure eight (a point when `delta > 0`).
    RPlusDelta,
    /// `R = delta - r` when positive: touching from outside.
    DeltaMinusR,
    /// `R = r - delta` when positive: touching from inside.
    RMinusDelta,
    /// Any radius.
    Free,
}

/// Configurations on and near the boundaries of the decision: the centre on the axis
/// (`delta = 0`) or at a rational distance `delta` from it (along the rotated x direction), at
/// any height `h` along the axis, with the radius from [`RadiusChoice`].
fn boundary_config() -> impl Strategy<Value = CylinderSphere<Rational>> {
    let choice = prop_oneof![
        Just(RadiusChoice::EqualRadii),
        Just(RadiusChoice::RPlusDelta),
        Just(RadiusChoice::DeltaMinusR),
        Just(RadiusChoice::RMinusDelta),
        Just(RadiusChoice::Free),
    ];
    let delta = prop_oneof![Just(Rational::ZERO), positive()];
    (config(), delta, rat(), choice, positive()).prop_filter_map(
        "the radius must be positive",
        |(mut cs, delta, h, choice, free)| {
            let (q, dir) = cs.axis();
            cs.center = q
                .add_scaled(&delta, &normal_direction(&cs))
                .add_scaled(&h, &dir);
            cs.radius = match choice {
                RadiusChoice::EqualRadii => cs.r.clone(),
                RadiusChoice::RPlusDelta => &cs.r + &delta,
                RadiusChoice::DeltaMinusR => &delta - &cs.r,
                RadiusChoice::RMinusDelta => &cs.r - &delta,
                RadiusChoice::Free => free,
            };
            (cs.radius > Rational::ZERO).then_some(cs)
        },
    )
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
        prop_assert_eq!(a.touching(), Some(cs.touching_by_distance()), "{:?}", cs);
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
        prop_assert_eq!(a.touching(), Some(Touching::Point), "{:?}", cs);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// On the axis, `R = r`, `R = r + delta`, `R = delta - r`, `R = r - delta`: both methods give
    /// the same contact and the same touching set (a point, a circle, or none).
    #[test]
    fn boundary_configurations_agree(cs in boundary_config()) {
        let a = analyze(&cs);
        prop_assert_eq!(a.contact, cs.contact_by_distance(), "{:?}", cs);
        prop_assert_eq!(a.touching(), Some(cs.touching_by_distance()), "{:?}", cs);
        prop_assert_eq!(a.contact == Contact::Disjoint, a.components == 0);
    }
}
