//! Cylinder / sphere intersection (Spaeth 2003; docs/papers/spaeth.md).
//!
//! A cylinder of radius `r` about the z axis through `(a, b, 0)` is rotated by `beta` in the x-z
//! plane and then by `gamma` in the y-z plane: its points are
//! `R_x(gamma) R_y(beta) (a + r cos t, b + r sin t, u)` ([`CylinderSphere::point`]; this is (5)
//! multiplied out, the order the paper's (7)-(11) use). The paper's (4) prints the product the
//! other way round, `R_y(beta) R_x(gamma)`; that order is kept only as
//! [`CylinderSphere::point_printed_order`] for the catalogue's `spaeth.eq5` claim.
//! Substituting the point into the sphere `|x - (d,e,f)|^2 = R^2` (6) gives the monic quadratic
//! `u^2 + 2 A(t) u + B(t) = 0` (8); real points exist where the discriminant `D(t) = A(t)^2 - B(t)`
//! is non-negative (11).
//!
//! Angles enter as points `(cos, sin)` of the unit circle, never as radians, so the formulas are
//! polynomial and run exactly over any [`Ring`]; [`unit_circle_point`] gives the rational points.
//!
//! The coefficients below are the ones obtained by multiplying out the rotation product, with
//! `u` collected: this is *not* the printed (9), whose last term has the opposite sign (the
//! catalogue's `spaeth.eq9` claim decides that).
//!
//! **Tangency.** Write `F(t, u) = |x(t, u) - c|^2 - R^2 = u^2 + 2 A u + B`. The cylinder
//! parametrization is regular (`r > 0`) and the sphere's gradient `2 (x - c)` does not vanish on
//! it (`R > 0`), so the surfaces touch at a common point exactly when the sphere's normal is
//! orthogonal to both tangents `x_t`, `x_u`, i.e. when `F_t = F_u = 0` there: the point is a
//! singular point of the curve `F = 0` in the `(t, u)` plane. `F_u = 0` gives `u = -A(t)`, and
//! then `F = 0` and `F_t = 0` say `D(t) = 0` and `D'(t) = 0`: **the touching points are the
//! multiple roots of the discriminant**, one point `u = -A(t)` each, and if `D` vanishes
//! identically the surfaces touch along the whole curve `u = -A(t)`. Geometrically the sphere's
//! normal line at a touching point is the cylinder's normal line, which meets the axis at a right
//! angle; so
//! * `delta = r + R` (outside) or `delta = r - R > 0` (inside the cylinder): one touching point,
//!   and nothing else in common;
//! * `delta = R - r > 0`: the curve is a figure eight whose two loops cross at one touching point;
//! * `delta = 0` and `R = r`: the sphere touches along the whole circle of the axis height of its
//!   centre ([`Touching::Circle`]);
//!
//! where `delta` is the distance of the centre from the axis. [`CylinderSphere::touching_by_distance`]
//! decides this from `delta`; the exact analysis in `exactcheck-exact` finds the same points from the
//! multiple roots of the discriminant, and a property test compares the two.

use crate::scalar::{Field, OrderedField, Ring, Sign, ZeroDivisor};
use crate::vector::Vec3;

/// A point `(cos, sin)` of the unit circle standing for an angle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Angle<T> {
    /// The cosine.
    pub cos: T,
    /// The sine.
    pub sin: T,
}

/// The rational point `((1 - tau^2)/(1 + tau^2), 2 tau/(1 + tau^2))` of the unit circle.
///
/// # Errors
/// [`ZeroDivisor`] when `1 + tau^2 = 0` (impossible over an ordered field).
pub fn unit_circle_point<T: Field>(tau: &T) -> Result<Angle<T>, ZeroDivisor> {
    let t2 = tau.square();
    let inv = (T::one() + &t2).inv()?;
    Ok(Angle {
        cos: (T::one() - &t2) * &inv,
        sin: tau.scale_i64(2) * &inv,
    })
}

/// A cylinder (axis point `(a, b)` before rotation, radius `r`, rotations `beta`, `gamma`) and a
/// sphere (centre, radius), the claim list.
#[derive(Clone, Debug, PartialEq)]
pub struct CylinderSphere<T> {
    /// x of the axis point before rotation.
    pub a: T,
    /// y of the axis point before rotation.
    pub b: T,
    /// Cylinder radius.
    pub r: T,
    /// Rotation in the x-z plane.
    pub beta: Angle<T>,
    /// Rotation in the y-z plane.
    pub gamma: Angle<T>,
    /// Sphere centre `(d, e, f)`.
    pub center: Vec3<T>,
    /// Sphere radius.
    pub radius: T,
}

impl<T> Angle<T> {
    /// The same angle with each coordinate converted by `f`.
    pub fn map<U>(&self, mut f: impl FnMut(&T) -> U) -> Angle<U> {
        Angle {
            cos: f(&self.cos),
            sin: f(&self.sin),
        }
    }
}

impl<T> CylinderSphere<T> {
    /// The same configuration with every number converted by `f` (e.g. `Rational` to `f64`, or
    /// into the radical field or a polynomial ring): the one place that lists the fields.
    pub fn map<U>(&self, mut f: impl FnMut(&T) -> U) -> CylinderSphere<U> {
        CylinderSphere {
            a: f(&self.a),
            b: f(&self.b),
            r: f(&self.r),
            beta: self.beta.map(&mut f),
            gamma: self.gamma.map(&mut f),
            center: self.center.map(&mut f),
            radius: f(&self.radius),
        }
    }
}

impl<T: Ring> CylinderSphere<T> {
    /// `(A(t), B(t))` of `u^2 + 2 A u + B = 0` at the circle point `(cos t, sin t)`.
    pub fn coefficients_at(&self, cos_t: &T, sin_t: &T) -> (T, T) {
        let (cb, sb) = (&self.beta.cos, &self.beta.sin);
        let (cg, sg) = (&self.gamma.cos, &self.gamma.sin);
        let x = self.a.add_ref(&self.r.mul_ref(cos_t));
        let y = self.b.add_ref(&self.r.mul_ref(sin_t));
        let sgsb = sg.mul_ref(sb);
        let cgsb = cg.mul_ref(sb);
        let u = cb.mul_ref(&x) - &self.center.x;
        let v = cg.mul_ref(&y) - sgsb.mul_ref(&x) - &self.center.y;
        let w = sg.mul_ref(&y) + cgsb.mul_ref(&x) + &self.center.z;
        let a = sb.mul_ref(&u) + sg.mul_ref(cb).mul_ref(&v) - cg.mul_ref(cb).mul_ref(&w);
        let b = u.square() + v.square() + w.square() - self.radius.square();
        (a, b)
    }

    /// The discriminant `A(t)^2 - B(t)` at `(cos t, sin t)`: real points exist where it is `>= 0`.
    pub fn discriminant_at(&self, cos_t: &T, sin_t: &T) -> T {
        let (a, b) = self.coefficients_at(cos_t, sin_t);
        a.square() - b
    }
}

/// `R_y(beta) v` with `R_y = [[cos b, 0, sin b], [0, 1, 0], [-sin b, 0, cos b]]` (4).
pub fn rotate_y<T: Ring>(beta: &Angle<T>, v: &Vec3<T>) -> Vec3<T> {
    Vec3::new(
        beta.cos.mul_ref(&v.x) + beta.sin.mul_ref(&v.z),
        v.y.clone(),
        beta.cos.mul_ref(&v.z) - beta.sin.mul_ref(&v.x),
    )
}

/// `R_x(gamma) v` with `R_x = [[1, 0, 0], [0, cos g, sin g], [0, -sin g, cos g]]` (4).
pub fn rotate_x<T: Ring>(gamma: &Angle<T>, v: &Vec3<T>) -> Vec3<T> {
    Vec3::new(
        v.x.clone(),
        gamma.cos.mul_ref(&v.y) + gamma.sin.mul_ref(&v.z),
        gamma.cos.mul_ref(&v.z) - gamma.sin.mul_ref(&v.y),
    )
}

impl<T: Ring> CylinderSphere<T> {
    /// The unrotated cylinder point `(a + r cos t, b + r sin t, u)` (3).
    pub fn base_point(&self, cos_t: &T, sin_t: &T, u: &T) -> Vec3<T> {
        Vec3::new(
            self.a.add_ref(&self.r.mul_ref(cos_t)),
            self.b.add_ref(&self.r.mul_ref(sin_t)),
            u.clone(),
        )
    }

    /// The cylinder point of (4) as printed: `R_y(beta) R_x(gamma) (a + r cos t, b + r sin t, u)`.
    pub fn point_printed_order(&self, cos_t: &T, sin_t: &T, u: &T) -> Vec3<T> {
        rotate_y(
            &self.beta,
            &rotate_x(&self.gamma, &self.base_point(cos_t, sin_t, u)),
        )
    }

    /// The cylinder point with the rotations in the other order,
    /// `R_x(gamma) R_y(beta) (a + r cos t, b + r sin t, u)`: the parametrization the rest of the
    /// paper ((5), (7)-(11)) and [`CylinderSphere::coefficients_at`] use.
    pub fn point(&self, cos_t: &T, sin_t: &T, u: &T) -> Vec3<T> {
        rotate_x(
            &self.gamma,
            &rotate_y(&self.beta, &self.base_point(cos_t, sin_t, u)),
        )
    }

    /// `F(t, u) = |x(t, u) - (d, e, f)|^2 - R^2` for the cylinder point [`CylinderSphere::point`].
    pub fn sphere_residual(&self, cos_t: &T, sin_t: &T, u: &T) -> T {
        let x = self.point(cos_t, sin_t, u);
        (&x - &self.center).norm_squared() - self.radius.square()
    }
}

/// `A(t)` and `B(t)` as trigonometric polynomials:
/// `A = a0 + a1 cos t + a2 sin t`,
/// `B = b0 + b1 cos t + b2 sin t + b3 cos^2 t + b4 cos t sin t + b5 sin^2 t`.
#[derive(Clone, Debug, PartialEq)]
pub struct TrigCoefficients<T> {
    /// `a0, a1, a2`.
    pub a: [T; 3],
    /// `b0 .. b5`.
    pub b: [T; 6],
}

impl<T: Field> CylinderSphere<T> {
    /// The coefficients of `A` and `B` in `(cos t, sin t)`, obtained exactly from
    /// [`CylinderSphere::coefficients_at`] by evaluation at six points (A and B are polynomials of
    /// degree 1 and 2 in `(c, s)`, so six values determine them; the points need not lie on the
    /// circle). The same code gives exact coefficients over an exact field and f64 ones over f64.
    pub fn trig_coefficients(&self) -> TrigCoefficients<T> {
        let v = |c: i64, s: i64| self.coefficients_at(&T::from_i64(c), &T::from_i64(s));
        let ((a00, b00), (a10, b10), (a01, b01)) = (v(0, 0), v(1, 0), v(0, 1));
        let ((_, bm0), (_, b0m), (_, b11)) = (v(-1, 0), v(0, -1), v(1, 1));
        let half = T::from_i64(2)
            .inv()
            .expect("trig_coefficients needs a field where 2 is invertible");
        let b1 = (b10.sub_ref(&bm0)).mul_ref(&half);
        let b3 = (b10.add_ref(&bm0)).mul_ref(&half) - &b00;
        let b2 = (b01.sub_ref(&b0m)).mul_ref(&half);
        let b5 = (b01.add_ref(&b0m)).mul_ref(&half) - &b00;
        let b4 = b11 - &b00 - &b1 - &b2 - &b3 - &b5;
        TrigCoefficients {
            a: [a00.clone(), a10 - &a00, a01 - &a00],
            b: [b00, b1, b2, b3, b4, b5],
        }
    }
}

impl<T: Ring> TrigCoefficients<T> {
    /// `(A, B)` at `(cos t, sin t)`.
    pub fn eval(&self, c: &T, s: &T) -> (T, T) {
        let a = self.a[0].add_ref(&self.a[1].mul_ref(c)) + self.a[2].mul_ref(s);
        let b = self.b[0].add_ref(&self.b[1].mul_ref(c))
            + self.b[2].mul_ref(s)
            + self.b[3].mul_ref(&c.square())
            + self.b[4].mul_ref(&c.mul_ref(s))
            + self.b[5].mul_ref(&s.square());
        (a, b)
    }
}

impl<T: Ring> TrigCoefficients<T> {
    /// The discriminant in the rational circle parameter: with `cos t = (1 - tau^2)/(1 + tau^2)`,
    /// `sin t = 2 tau/(1 + tau^2)`, `P(tau) = (1 + tau^2)^2 (A^2 - B)` is a polynomial of degree
    /// at most 4; its coefficients, lowest first. `P` has the sign of the discriminant at every
    /// `t != pi`; its `tau^4` coefficient is the discriminant at `t = pi` (`tau -> infinity`).
    pub fn discriminant_in_tau(&self) -> [T; 5] {
        // (1 + tau^2) A = at + 2 a2 tau + bt tau^2 with at = a0 + a1, bt = a0 - a1.
        let [a0, a1, a2] = &self.a;
        let at = [a0.add_ref(a1), a2.scale_i64(2), a0.sub_ref(a1)];
        // (1 + tau^2)^2 B, from (1+tau^2)^2, (1-tau^2)(1+tau^2), 2tau(1+tau^2), (1-tau^2)^2,
        // 2tau(1-tau^2), 4tau^2.
        let basis: [[i64; 5]; 6] = [
            [1, 0, 2, 0, 1],
            [1, 0, 0, 0, -1],
            [0, 2, 0, 2, 0],
            [1, 0, -2, 0, 1],
            [0, 2, 0, -2, 0],
            [0, 0, 4, 0, 0],
        ];
        let mut p: [T; 5] = core::array::from_fn(|_| T::zero());
        for (coef, row) in self.b.iter().zip(basis.iter()) {
            for (k, m) in row.iter().enumerate() {
                if *m != 0 {
                    p[k] -= coef.scale_i64(*m);
                }
            }
        }
        for i in 0..3 {
            for j in 0..3 {
                p[i + j] += at[i].mul_ref(&at[j]);
            }
        }
        p
    }
}

impl<T: Ring> CylinderSphere<T> {
    /// The axis point and unit direction as in [`CylinderSphere::axis`], for any ring (no order
    /// needed; e.g. over polynomials).
    pub fn axis_polynomial(&self) -> (Vec3<T>, Vec3<T>) {
        let p = rotate_x(
            &self.gamma,
            &rotate_y(
                &self.beta,
                &Vec3::new(self.a.clone(), self.b.clone(), T::zero()),
            ),
        );
        let d = rotate_x(
            &self.gamma,
            &rotate_y(&self.beta, &Vec3::new(T::zero(), T::zero(), T::one())),
        );
        (p, d)
    }
}

/// How a sphere and a cylinder surface lie to each other.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// No common point.
    Disjoint,
    /// They touch without crossing: `|delta - r| = R` with `delta != R - r` (delta the distance
    /// of the centre from the axis; one point), or `delta = 0` and `R = r` (a whole circle).
    Tangent,
    /// They cross along a curve.
    Crossing,
}

impl<T: OrderedField> CylinderSphere<T> {
    /// The axis of the rotated cylinder: its point `Rx(gamma) Ry(beta) (a, b, 0)` and its unit
    /// direction `Rx(gamma) Ry(beta) (0, 0, 1)` (the parametrization of (5)).
    pub fn axis(&self) -> (Vec3<T>, Vec3<T>) {
        self.axis_polynomial()
    }

    /// `delta^2`, the squared distance of the sphere centre from the cylinder axis
    /// (`|(c - q) x a|^2` with the axis direction `a` of unit length, as in (2)).
    pub fn axis_distance_squared(&self) -> T {
        let (q, a) = self.axis();
        (&self.center - &q).cross(&a).norm_squared()
    }

    /// The exact decision from the distance of the centre to the axis: the surfaces meet iff the
    /// distance of the centre from the cylinder surface, `|delta - r|`, is at most `R`; they touch
    /// without crossing when it equals `R` (`delta = r + R`, `delta = r - R > 0`) or when the
    /// sphere sits on the axis with `R = r` (touching along a circle). Decided with squares only
    /// (`delta` itself may be irrational): `delta <= r + R` iff `delta^2 <= (r + R)^2`, and
    /// `delta >= r - R` iff `r <= R` or `delta^2 >= (r - R)^2`.
    /// Assumes `r > 0`, `R > 0` and `(cos, sin)` on the unit circle for both angles.
    pub fn contact_by_distance(&self) -> Contact {
        let d2 = self.axis_distance_squared();
        let (r, big_r) = (self.r.abs(), self.radius.abs());
        let outer = r.add_ref(&big_r).square();
        let inner = r.sub_ref(&big_r);
        match d2.sub_ref(&outer).sign() {
            Sign::Positive => return Contact::Disjoint,
            Sign::Zero => return Contact::Tangent,
            Sign::Negative => {}
        }
        match inner.sign() {
            // R > r: the cylinder passes through the sphere.
            Sign::Negative => Contact::Crossing,
            // R = r: crossing unless the centre is on the axis, where the equator touches.
            Sign::Zero => match d2.sign() {
                Sign::Zero => Contact::Tangent,
                _ => Contact::Crossing,
            },
            Sign::Positive => match d2.sub_ref(&inner.square()).sign() {
                Sign::Negative => Contact::Disjoint,
                Sign::Zero => Contact::Tangent,
                Sign::Positive => Contact::Crossing,
            },
        }
    }

    /// Where the surfaces touch (have parallel normals at a common point), from `delta` alone
    /// (see the module doc): one point when `delta^2 = (r + R)^2`, or `delta^2 = (r - R)^2 > 0`;
    /// a whole circle when `delta = 0` and `R = r`; otherwise none.
    pub fn touching_by_distance(&self) -> Touching {
        let d2 = self.axis_distance_squared();
        let (r, big_r) = (self.r.abs(), self.radius.abs());
        let outer = r.add_ref(&big_r).square();
        let inner = r.sub_ref(&big_r).square();
        if d2.is_zero() && inner.is_zero() {
            Touching::Circle
        } else if d2 == outer || (d2 == inner && !d2.is_zero()) {
            Touching::Point
        } else {
            Touching::None
        }
    }
}

/// Where a sphere and a cylinder touch (normals parallel at a common point).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Touching {
    /// Nowhere.
    None,
    /// At exactly one point (`delta = r + R`, `delta = |r - R| > 0`).
    Point,
    /// Along the whole circle of the cylinder at the height of the centre (`delta = 0`, `R = r`).
    Circle,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_aligned_cylinder_through_sphere_centre() {
        // beta = gamma = 0, cylinder x^2 + y^2 = 25, sphere centre (1,0,0), R = 7 (Example 1):
        // A = 0 and B = (5 cos t - 1)^2 + 25 sin^2 t - 49 = -23 - 10 cos t.
        let cs = CylinderSphere {
            a: 0.0,
            b: 0.0,
            r: 5.0,
            beta: Angle { cos: 1.0, sin: 0.0 },
            gamma: Angle { cos: 1.0, sin: 0.0 },
            center: Vec3::new(1.0, 0.0, 0.0),
            radius: 7.0,
        };
        for (c, s) in [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.6, 0.8)] {
            let (a, b) = cs.coefficients_at(&c, &s);
            assert_eq!(a, 0.0);
            assert_eq!(b, -23.0 - 10.0 * c);
        }
    }

    /// The r = 5 cylinder about the z axis and a sphere of radius `radius` at `c`.
    fn cs(c: (f64, f64, f64), radius: f64) -> CylinderSphere<f64> {
        let one = Angle { cos: 1.0, sin: 0.0 };
        CylinderSphere {
            a: 0.0,
            b: 0.0,
            r: 5.0,
            beta: one.clone(),
            gamma: one,
            center: Vec3::new(c.0, c.1, c.2),
            radius,
        }
    }

    #[test]
    fn contact_cases() {
        // Spaeth's examples 1 and 3.
        assert_eq!(
            cs((1.0, 0.0, 0.0), 7.0).contact_by_distance(),
            Contact::Crossing
        );
        assert_eq!(
            cs((6.0, 7.0, 8.0), 1.0).contact_by_distance(),
            Contact::Disjoint
        );
        // Touching from outside (delta = 8 = r + R) and from inside (delta = 2 = r - R).
        assert_eq!(
            cs((8.0, 0.0, 3.0), 3.0).contact_by_distance(),
            Contact::Tangent
        );
        assert_eq!(
            cs((2.0, 0.0, 0.0), 3.0).contact_by_distance(),
            Contact::Tangent
        );
        assert_eq!(
            cs((1.0, 0.0, 0.0), 3.0).contact_by_distance(),
            Contact::Disjoint
        );
    }

    #[test]
    fn on_the_axis_with_equal_radii_the_surfaces_touch_along_a_circle() {
        // centre (0,0,3) on the axis of the r = 5 cylinder, R = 5. The old decision
        // answered Crossing (it took r - R <= 0 as "the cylinder passes through the sphere").
        let on_axis = cs((0.0, 0.0, 3.0), 5.0);
        assert_ne!(on_axis.contact_by_distance(), Contact::Crossing);
        assert_eq!(on_axis.contact_by_distance(), Contact::Tangent);
        assert_eq!(on_axis.touching_by_distance(), Touching::Circle);
        // Off the axis with R = r: a crossing, no touching.
        assert_eq!(
            cs((1.0, 0.0, 3.0), 5.0).contact_by_distance(),
            Contact::Crossing
        );
        assert_eq!(
            cs((1.0, 0.0, 3.0), 5.0).touching_by_distance(),
            Touching::None
        );
        // R = r + delta: crossing, and the figure eight touches at its crossing point.
        let eight = cs((2.0, 0.0, 0.0), 7.0);
        assert_eq!(eight.contact_by_distance(), Contact::Crossing);
        assert_eq!(eight.touching_by_distance(), Touching::Point);
        // R = delta - r (outside) and R = r - delta (inside): one point.
        assert_eq!(
            cs((8.0, 0.0, 3.0), 3.0).touching_by_distance(),
            Touching::Point
        );
        assert_eq!(
            cs((2.0, 0.0, 0.0), 3.0).touching_by_distance(),
            Touching::Point
        );
        // On the axis with R != r: no touching (R > r crosses in two circles, R < r is inside).
        assert_eq!(
            cs((0.0, 0.0, 0.0), 7.0).touching_by_distance(),
            Touching::None
        );
        assert_eq!(
            cs((0.0, 0.0, 0.0), 3.0).contact_by_distance(),
            Contact::Disjoint
        );
    }

    #[test]
    fn map_converts_every_field() {
        let cs = CylinderSphere {
            a: 0.0,
            b: 0.0,
            r: 5.0,
            beta: Angle {
                cos: 1f64.cos(),
                sin: 1f64.sin(),
            },
            gamma: Angle {
                cos: (-1f64).cos(),
                sin: (-1f64).sin(),
            },
            center: Vec3::new(1.0, 2.0, 4.0),
            radius: 5.0,
        };
        let doubled = cs.map(|x| 2.0 * x);
        assert_eq!(doubled.center, Vec3::new(2.0, 4.0, 8.0));
        assert_eq!(doubled.gamma.sin, 2.0 * (-1f64).sin());
        assert_eq!(doubled.beta.cos, 2.0 * 1f64.cos());
        assert_eq!((doubled.a, doubled.r, doubled.radius), (0.0, 10.0, 10.0));
    }

    #[test]
    fn discriminant_polynomial_matches_pointwise() {
        let cs = CylinderSphere {
            a: 0.5,
            b: -0.25,
            r: 5.0,
            beta: Angle { cos: 0.6, sin: 0.8 },
            gamma: Angle {
                cos: 0.8,
                sin: -0.6,
            },
            center: Vec3::new(1.0, 2.0, 4.0),
            radius: 5.0,
        };
        let p = cs.trig_coefficients().discriminant_in_tau();
        for tau in [-3.0, -0.5, 0.0, 0.25, 2.0] {
            let pt = unit_circle_point(&tau).unwrap();
            let d = cs.discriminant_at(&pt.cos, &pt.sin);
            let w = (1.0 + tau * tau) * (1.0 + tau * tau);
            let poly: f64 = p.iter().rev().fold(0.0, |acc, c| acc * tau + c);
            assert!(
                (poly - w * d).abs() < 1e-9 * (1.0 + poly.abs()),
                "{tau}: {poly} vs {}",
                w * d
            );
        }
        assert!((p[4] - cs.discriminant_at(&-1.0, &0.0)).abs() < 1e-9);
    }

    #[test]
    fn rational_circle_points() {
        let p = unit_circle_point(&0.5f64).unwrap();
        assert!((p.cos - 0.6).abs() < 1e-15 && (p.sin - 0.8).abs() < 1e-15);
        assert!(unit_circle_point(&0.0f64).is_ok());
    }
}
