//! Exact analysis of a cylinder/sphere intersection (Spaeth) for exact input.
//!
//! The input is rational ([`analyze`]) or lies in one real number field ([`analyze_in_field`]);
//! the discriminant is then a [`UPoly`] or a [`FieldUPoly`], and one analysis, written over the
//! [`Discriminant`] trait, serves both.
//!
//! Angles are rational points of the unit circle; the curve parameter is the rational circle
//! parameter `tau` (`cos t = (1 - tau^2)/(1 + tau^2)`, `sin t = 2 tau/(1 + tau^2)`, `tau = infinity`
//! at `t = pi`). Real points exist where `P(tau) = (1 + tau^2)^2 (A^2 - B) >= 0`
//! ([`TrigCoefficients::discriminant_in_tau`](exactcheck_core::cylinder_sphere::TrigCoefficients::discriminant_in_tau)); the set is found by exact real root isolation
//! ([`crate::univariate`]), never by sampling. On it the curve is
//! `x(tau, +-) = point(cos t, sin t, u)`, `u = -A(t) +- sqrt(P(tau))/(1 + tau^2)`: rational functions
//! of tau plus one square root.
//!
//! This is the second, independent decision method; the first is the distance of the centre from
//! the axis ([`CylinderSphere::contact_by_distance`]). The two must agree.
//!
//! The surfaces touch exactly at the multiple roots of the discriminant (module doc of
//! [`exactcheck_core::cylinder_sphere`]: `D = D' = 0` is `F_t = F_u = 0`, parallel normals at a
//! common point). Since `1 + tau^2 > 0`, the multiple real roots of `D` on `t != pi` are the
//! multiple real roots of `P`, found with their multiplicities by the square-free decomposition;
//! `t = pi` (`tau = infinity`) is a multiple root when `P` loses two degrees (`p4 = p3 = 0`, i.e.
//! `s^4 P(1/s)` has a double root at `s = 0`). Whether the discriminant is `<= 0` or `>= 0`
//! around such a root does not matter: an isolated touching point and the crossing point of a
//! figure eight are both found. `P = 0` identically means every point of the curve `u = -A(t)`
//! is a touching point: the touching circle.

use crate::algebraic::FieldElement;
use crate::algebraic::FieldUPoly;
use crate::univariate::{Bound, Root, RootBoundedInterval, RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::cylinder_sphere::{Angle, Contact, CylinderSphere, Touching};
use exactcheck_core::limits::LimitError;
use exactcheck_core::{OrderedField, Ring, Sign};

/// The rational point of the unit circle nearest (by a convergent of `tan(theta/2)` with
/// denominator at most `max_den`) to an angle in radians, with its parameter `tau` and its
/// deviation from `theta` in radians: how exact code takes an angle printed in radians. The
/// fallible generic form is [`exactcheck_core::rational_angle::rational_angle`].
///
/// # Panics
/// When `theta` is not finite or `max_den < 1` (callers pass finite angles, checked where they
/// come from user input, and constant bounds).
pub fn rational_angle(theta: f64, max_den: i64) -> (Angle<Rational>, Rational, f64) {
    let r = exactcheck_core::rational_angle::rational_angle::<Rational>(theta, max_den)
        .expect("rational_angle needs a finite angle and max_den >= 1");
    (r.angle, r.tau_value, r.deviation)
}

/// The discriminant polynomial `P(tau)` as the analysis and its answer need it: its real roots,
/// signs and low coefficients, the refinement of its root intervals and its printed form, for
/// rational coefficients ([`UPoly`]) and for coefficients in a real number field
/// ([`FieldUPoly`]), both answered by the real-root API of [`crate::univariate`] (the second
/// through its norm).
pub trait Discriminant: Clone + std::fmt::Debug {
    /// Whether `P` is the zero polynomial.
    fn vanishes(&self) -> bool;
    /// Whether the coefficient of `tau^k` is zero.
    fn coefficient_vanishes(&self, k: usize) -> bool;
    /// The distinct real roots with multiplicities, increasing.
    fn real_roots(&self) -> Vec<Root>;
    /// The closed sets where `P >= 0`.
    fn nonnegative(&self) -> Vec<RootBoundedInterval>;
    /// Whether `P > 0` somewhere.
    fn positive_anywhere(&self) -> bool;
    /// The number of distinct real roots.
    fn real_root_count(&self) -> usize;
    /// The interval `ri` of one of the real roots refined to width at most `width`.
    ///
    /// # Errors
    /// A [`LimitError`] of `bisection` when more halvings than the limit would be needed.
    fn refine_root(&self, ri: &RootInterval, width: &Rational) -> Result<RootInterval, LimitError>;
    /// `P` printed as a polynomial in `var`.
    fn text(&self, var: &str) -> String;
}

/// The [`Discriminant`] impl of a polynomial type: [`UPoly`] and [`FieldUPoly`] share no trait,
/// but have inherent methods of the same names and meaning, which each trait method calls.
macro_rules! discriminant_by_inherent_methods {
    ($($poly:ty),*) => {$(
        impl Discriminant for $poly {
            fn vanishes(&self) -> bool {
                self.is_zero()
            }
            fn coefficient_vanishes(&self, k: usize) -> bool {
                self.coeff(k).is_zero()
            }
            fn real_roots(&self) -> Vec<Root> {
                self.roots()
            }
            fn nonnegative(&self) -> Vec<RootBoundedInterval> {
                self.nonnegative_set()
            }
            fn positive_anywhere(&self) -> bool {
                self.positive_somewhere()
            }
            fn real_root_count(&self) -> usize {
                self.count_real_roots()
            }
            fn refine_root(
                &self,
                ri: &RootInterval,
                width: &Rational,
            ) -> Result<RootInterval, LimitError> {
                self.try_refine(ri, width)
            }
            fn text(&self, var: &str) -> String {
                self.display(var).to_string()
            }
        }
    )*};
}

discriminant_by_inherent_methods!(UPoly, FieldUPoly);

/// What the exact analysis found; `P` is the discriminant's polynomial type ([`UPoly`] for
/// rational input, [`FieldUPoly`] for input in a number field).
#[derive(Clone, Debug)]
pub struct Analysis<P = UPoly> {
    /// `P(tau) = (1 + tau^2)^2 (A^2 - B)`.
    pub discriminant: P,
    /// The sign of the discriminant at `t = pi` (`tau = infinity`).
    pub sign_at_pi: Sign,
    /// The closed tau-intervals where `P >= 0` (unbounded ends included).
    pub nonnegative: Vec<RootBoundedInterval>,
    /// The decision from the discriminant.
    pub contact: Contact,
    /// Connected components of the intersection curve (a touching point counts as one).
    pub components: usize,
    /// Parameters of every touching point (the multiple roots of `P`, whether the curve is
    /// isolated there or crosses itself), as root intervals; `None` in the list stands for
    /// `t = pi`. Empty when the surfaces touch along a circle ([`Analysis::touching_circle`]).
    pub tangent_params: Vec<Option<RootInterval>>,
    /// The discriminant vanishes identically: the surfaces touch along the whole circle
    /// `u = -A(t)`.
    pub touching_circle: bool,
}

impl<P> Analysis<P> {
    /// Where the surfaces touch, by this method (to compare with
    /// [`CylinderSphere::touching_by_distance`]): a circle, or as many points as
    /// [`Analysis::tangent_params`] lists (`Point` for one; the geometry allows at most one).
    pub fn touching(&self) -> Option<Touching> {
        match (self.touching_circle, self.tangent_params.len()) {
            (true, 0) => Some(Touching::Circle),
            (false, 0) => Some(Touching::None),
            (false, 1) => Some(Touching::Point),
            _ => None,
        }
    }
}

/// Analyzes the intersection exactly.
pub fn analyze(cs: &CylinderSphere<Rational>) -> Analysis {
    analyze_with(cs, |c| UPoly::from_coeffs(c.to_vec()))
}

/// Analyzes the intersection exactly for input in a real number field (the numbers and angles
/// of `cs` in one field `Q(theta)`): the discriminant has coefficients in the field and its
/// real roots are isolated by [`FieldUPoly`].
pub fn analyze_in_field(cs: &CylinderSphere<FieldElement>) -> Analysis<FieldUPoly> {
    analyze_with(cs, |c| FieldUPoly::from_coeffs(c.to_vec()))
}

/// The analysis over any exact ordered field, the discriminant built by `make` from its
/// coefficients.
fn analyze_with<T: OrderedField, P: Discriminant>(
    cs: &CylinderSphere<T>,
    make: impl Fn(&[T; 5]) -> P,
) -> Analysis<P> {
    let coeffs = cs.trig_coefficients();
    let p = make(&coeffs.discriminant_in_tau());
    let at_pi = cs.discriminant_at(&T::from_i64(-1), &T::zero());
    let sign_at_pi = at_pi.sign();
    if p.vanishes() {
        // A^2 = B everywhere: the sphere touches along the whole circle of t (degenerate).
        return Analysis {
            discriminant: p,
            sign_at_pi,
            nonnegative: vec![RootBoundedInterval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            }],
            contact: Contact::Tangent,
            components: 1,
            tangent_params: Vec::new(),
            touching_circle: true,
        };
    }
    let nonnegative = p.nonnegative();
    // Every multiple root of P is a touching point (D = D' = 0), isolated or not.
    let mut tangent_params: Vec<Option<RootInterval>> = p
        .real_roots()
        .into_iter()
        .filter(|r| r.multiplicity >= 2)
        .map(|r| Some(r.interval))
        .collect();
    // t = pi is a multiple root when s^4 P(1/s) has a double root at s = 0: p4 = p3 = 0.
    if p.coefficient_vanishes(4) && p.coefficient_vanishes(3) {
        tangent_params.push(None);
    }
    let positive = p.positive_anywhere() || sign_at_pi == Sign::Positive;
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
    let components = if whole_line && sign_at_pi == Sign::Positive && p.real_root_count() == 0 {
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
        touching_circle: false,
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
    fn rational_angle_is_on_the_unit_circle_and_near() {
        for theta in [1.0, -1.0, 0.3, 2.5f64.to_radians()] {
            let (angle, tau, deviation) = rational_angle(theta, 1000);
            assert_eq!(angle.cos.square() + &angle.sin.square(), q(1));
            assert!(deviation.abs() < 1e-4, "{theta}: {deviation}");
            let on_circle = exactcheck_core::cylinder_sphere::unit_circle_point(&tau);
            assert_eq!(on_circle.expect("1 + tau^2 > 0"), angle);
        }
    }

    #[test]
    fn spaeth_examples_1_and_3() {
        // Spaeth's Examples 1 and 3: the cylinder r = 5 about the z axis, not rotated.
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
    fn touching_is_reported_completely() {
        // centre (0,0,3) on the axis, R = r = 5. The discriminant vanishes identically:
        // the surfaces touch along the circle u = 3 (the old answer listed no touching at all).
        let circle = analyze(&axis_aligned((0, 0, 3), 5));
        assert_eq!(circle.contact, Contact::Tangent);
        assert!(circle.touching_circle);
        assert_eq!(circle.touching(), Some(Touching::Circle));
        // R = r + delta (centre (-2,0,0), R = 7): u^2 = 20 (1 - cos t), a figure eight whose
        // crossing point (5, 0, 0), at t = 0, is a touching point (P = 40 tau^2 (1 + tau^2) >= 0
        // on both sides of the double root; the old code listed only roots with P < 0 around and
        // so reported none).
        let eight = analyze(&axis_aligned((-2, 0, 0), 7));
        assert_eq!(eight.contact, Contact::Crossing);
        assert_eq!(eight.components, 1);
        assert_eq!(eight.tangent_params.len(), 1);
        assert_eq!(
            eight.tangent_params[0]
                .as_ref()
                .and_then(|r| r.exact_value().cloned()),
            Some(Rational::ZERO)
        );
        // The same at t = pi (the example, centre (2,0,0): touching at (-5, 0, 0)).
        let eight_pi = analyze(&axis_aligned((2, 0, 0), 7));
        assert_eq!(eight_pi.tangent_params, vec![None]);
        // A plain crossing and a disjoint pair have none.
        assert!(analyze(&axis_aligned((1, 0, 0), 7))
            .tangent_params
            .is_empty());
        assert!(analyze(&axis_aligned((6, 7, 8), 1))
            .tangent_params
            .is_empty());
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
            ((0, 0, 3), 5),
            ((2, 0, 0), 7),
            ((0, 0, 0), 7),
            ((0, 0, 0), 3),
        ] {
            let cs = axis_aligned(c, r);
            let a = analyze(&cs);
            assert_eq!(a.contact, cs.contact_by_distance(), "{c:?} {r}");
            assert_eq!(a.touching(), Some(cs.touching_by_distance()), "{c:?} {r}");
        }
    }

    #[test]
    fn the_field_analysis_agrees_with_the_distance_method() {
        use crate::algebraic::{Algebraic, NumberField};
        use exactcheck_core::Field;
        use std::sync::Arc;
        let theta: Algebraic = "cos(pi/8)".parse().unwrap();
        let f = Arc::new(NumberField::new(theta).unwrap());
        let lift = |x: &Rational| FieldElement::new(&f, &UPoly::constant(x.clone()));
        for (c, r) in [
            ((1, 0, 0), 7),
            ((6, 7, 8), 1),
            ((8, 0, 3), 3),
            ((0, 0, 3), 5),
            ((2, 0, 0), 7),
        ] {
            let cs = axis_aligned(c, r).map(lift);
            let a = analyze_in_field(&cs);
            assert_eq!(a.contact, cs.contact_by_distance(), "{c:?} {r}");
            assert_eq!(a.touching(), Some(cs.touching_by_distance()), "{c:?} {r}");
        }
        // Centre at distance 6 = r + R in the direction t = pi/8 (cos, sin in the field):
        // the surfaces touch at the irrational tau = tan(pi/16).
        let cos = FieldElement::generator(&f);
        let sqrt2 = cos.square().scale_i64(4) - FieldElement::from_i64(2);
        let sin = sqrt2 * &cos.scale_i64(4).inv().unwrap();
        let mut cs = axis_aligned((0, 0, 0), 1).map(lift);
        cs.center = Vec3::new(cos.scale_i64(6), sin.scale_i64(6), FieldElement::zero());
        let a = analyze_in_field(&cs);
        assert_eq!(a.contact, Contact::Tangent);
        assert_eq!(a.touching(), Some(cs.touching_by_distance()));
        let tau = a.tangent_params[0].clone().expect("not at t = pi");
        assert!(!tau.is_exact());
        let fine = a
            .discriminant
            .try_refine(&tau, &Rational::new(1, 1 << 40).unwrap())
            .unwrap();
        assert!((fine.to_f64() - (std::f64::consts::PI / 16.0).tan()).abs() < 1e-10);
    }
}
