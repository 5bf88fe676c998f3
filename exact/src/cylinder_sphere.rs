//! Exact analysis of a cylinder/sphere intersection (Spaeth, SPEC §2) for exact input.
//!
//! Angles are rational points of the unit circle; the curve parameter is the rational circle
//! parameter `tau` (`cos t = (1 - tau^2)/(1 + tau^2)`, `sin t = 2 tau/(1 + tau^2)`, `tau = infinity`
//! at `t = pi`). Real points exist where `P(tau) = (1 + tau^2)^2 (A^2 - B) >= 0`
//! ([`TrigCoefficients::discriminant_in_tau`]); the set is found by exact real root isolation
//! ([`crate::univariate`]), never by sampling. On it the curve is
//! `x(tau, +-) = point(cos t, sin t, u)`, `u = -A(t) +- sqrt(P(tau))/(1 + tau^2)`: rational functions
//! of tau plus one square root.
//!
//! This is the second, independent decision method; the first is the distance of the centre from
//! the axis ([`CylinderSphere::contact_by_distance`]). The two must agree.

use crate::univariate::{Bound, Interval, RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::cylinder_sphere::{Contact, CylinderSphere};
use exactcheck_core::{OrderedField, Sign};

/// What the exact analysis found.
#[derive(Clone, Debug)]
pub struct Analysis {
    /// `P(tau) = (1 + tau^2)^2 (A^2 - B)`.
    pub discriminant: UPoly,
    /// The sign of the discriminant at `t = pi` (`tau = infinity`).
    pub sign_at_pi: Sign,
    /// The closed tau-intervals where `P >= 0` (unbounded ends included).
    pub nonnegative: Vec<Interval>,
    /// The decision from the discriminant.
    pub contact: Contact,
    /// Connected components of the intersection curve (a touching point counts as one).
    pub components: usize,
    /// Parameters of isolated touching points (`P = 0` with `P < 0` around), as root intervals;
    /// `None` in the list stands for `t = pi`.
    pub tangent_params: Vec<Option<RootInterval>>,
}

/// Analyzes the intersection exactly.
pub fn analyze(cs: &CylinderSphere<Rational>) -> Analysis {
    let coeffs = cs.trig_coefficients();
    let p = UPoly::from_coeffs(coeffs.discriminant_in_tau().to_vec());
    let at_pi = cs.discriminant_at(&Rational::from_integer(-1), &Rational::ZERO);
    let sign_at_pi = at_pi.sign();
    if p.is_zero() {
        // A^2 = B everywhere: the sphere touches along the whole circle of t (degenerate).
        return Analysis {
            discriminant: p,
            sign_at_pi,
            nonnegative: vec![Interval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            }],
            contact: Contact::Tangent,
            components: 1,
            tangent_params: Vec::new(),
        };
    }
    let nonnegative = p.nonnegative_set();
    let touching = p.touching_points();
    let mut tangent_params: Vec<Option<RootInterval>> =
        touching.iter().map(|r| Some(r.interval.clone())).collect();
    // t = pi: the tau^4 coefficient; it is an isolated touching point when the discriminant is 0
    // there and negative on both sides (i.e. for large |tau|).
    let ends_negative =
        p.sign_at_pos_inf() == Sign::Negative && p.sign_at_neg_inf() == Sign::Negative;
    if sign_at_pi == Sign::Zero && (p.degree() < 4) && ends_negative {
        tangent_params.push(None);
    }
    let positive = p.positive_somewhere() || sign_at_pi == Sign::Positive;
    let touches = !tangent_params.is_empty() || !nonnegative.is_empty() || sign_at_pi == Sign::Zero;
    let contact = if positive {
        Contact::Crossing
    } else if touches {
        Contact::Tangent
    } else {
        Contact::Disjoint
    };
    // Components on the circle: the tau-intervals, with the two unbounded ones joined through
    // t = pi when the discriminant is >= 0 there.
    let mut arcs = nonnegative.len();
    let unbounded_lo = nonnegative
        .first()
        .is_some_and(|i| matches!(i.lo, Bound::NegInf));
    let unbounded_hi = nonnegative
        .last()
        .is_some_and(|i| matches!(i.hi, Bound::PosInf));
    let whole_line = arcs == 1 && unbounded_lo && unbounded_hi;
    if arcs >= 2 && unbounded_lo && unbounded_hi && sign_at_pi != Sign::Negative {
        arcs -= 1;
    }
    if arcs == 0 && sign_at_pi == Sign::Zero {
        arcs = 1;
    }
    // Over an arc the two branches u1 <= u2 close up into one loop; over the whole circle with
    // no zero they are two separate closed curves (Example 1), joined where P touches 0.
    let components = if whole_line && sign_at_pi == Sign::Positive && p.count_real_roots() == 0 {
        2
    } else {
        arcs
    };
    Analysis {
        discriminant: p,
        sign_at_pi,
        nonnegative,
        contact,
        components,
        tangent_params,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::cylinder_sphere::Angle;
    use exactcheck_core::Vec3;

    fn q(n: i64) -> Rational {
        Rational::from_integer(n)
    }

    fn axis_aligned(center: (i64, i64, i64), radius: i64) -> CylinderSphere<Rational> {
        let zero = Angle {
            cos: q(1),
            sin: q(0),
        };
        CylinderSphere {
            a: q(0),
            b: q(0),
            r: q(5),
            beta: zero.clone(),
            gamma: zero,
            center: Vec3::new(q(center.0), q(center.1), q(center.2)),
            radius: q(radius),
        }
    }

    #[test]
    fn spaeth_examples_1_and_3() {
        let e1 = analyze(&axis_aligned((1, 0, 0), 7));
        assert_eq!(e1.contact, Contact::Crossing);
        assert_eq!(e1.components, 2);
        let e3 = analyze(&axis_aligned((6, 7, 8), 1));
        assert_eq!(e3.contact, Contact::Disjoint);
        assert_eq!(e3.components, 0);
    }

    #[test]
    fn touching_from_outside_is_one_point() {
        let a = analyze(&axis_aligned((8, 0, 3), 3));
        assert_eq!(a.contact, Contact::Tangent);
        assert_eq!(a.tangent_params.len(), 1);
        assert_eq!(a.components, 1);
        // At t = 0 (tau = 0): the point (5, 0, 3).
        assert_eq!(
            a.tangent_params[0]
                .as_ref()
                .and_then(|r| r.exact_value().cloned()),
            Some(Rational::ZERO)
        );
        // Touching at t = pi: centre (-8, 0, 3).
        let b = analyze(&axis_aligned((-8, 0, 3), 3));
        assert_eq!(b.contact, Contact::Tangent);
        assert_eq!(b.tangent_params, vec![None]);
    }

    #[test]
    fn agrees_with_the_distance_method_on_the_examples() {
        for (c, r) in [
            ((1, 0, 0), 7),
            ((6, 7, 8), 1),
            ((8, 0, 3), 3),
            ((2, 0, 0), 3),
            ((1, 0, 0), 3),
            ((4, 4, 0), 2),
        ] {
            let cs = axis_aligned(c, r);
            assert_eq!(analyze(&cs).contact, cs.contact_by_distance(), "{c:?} {r}");
        }
    }
}
