//! Miquel's configuration of a biquadratic patch on the unit sphere K (Satz 7).
//!
//! Every biquadratic rational patch on K is the delta-image (Lebesgue's map (7)) of a bilinear
//! patch of projective 3-space (Satz 1). Its four boundary curves are conics on K, i.e. circles:
//! plane sections of K. Adjacent boundary circles meet at the corner `p_i` of the patch and at a
//! second point `q_i`; Satz 7 states that `p1, q2, p3, q4` lie on one circle (and, by symmetry,
//! `q1, p2, q3, p4`).
//!
//! # Numbering
//! The corners are numbered cyclically around the parameter square, as
//! [`TensorPatch::corners`] returns them: `p1 = y(0,0)`, `p2 = y(1,0)`, `p3 = y(1,1)`,
//! `p4 = y(0,1)` (index `i - 1` in the arrays below). The boundary circles are numbered as
//! [`TensorPatch::boundary_curves`] returns them: circle 0 is `y(u,0)` (through `p1, p2`),
//! circle 1 is `y(1,v)` (`p2, p3`), circle 2 is `y(u,1)` (`p3, p4`), circle 3 is `y(0,v)`
//! (`p4, p1`). So corner `i` (0-based) lies on circles `(i + 3) % 4` and `i`, and `q_i` is the
//! second common point of exactly those two circles.
//!
//! Everything but the Bernstein product-rule factors of [`lebesgue_patch`] is division-free
//! (a [`Ring`]): planes are generalized cross products, the line of two planes is met with a
//! coordinate plane, and the second point of a line through a point `p` of K is found by Vieta's
//! rule — on `p + t d` the quadratic `S(p + t d) = 2 t B(p, d) + t^2 S(d)` has the known root
//! `t = 0`, so the other point is `S(d) p - 2 B(p, d) d`.

use crate::bernstein::phi_value;
use crate::bezier::{RationalBezierCurve, TensorPatch};
use crate::quadric::sphere_form;
use crate::scalar::{Field, Ring};
use crate::vector::{det4, Hom4};

/// Why a Miquel configuration could not be built (a degenerate patch).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Degeneracy {
    /// The patch is not of degree (2, 2).
    NotBiquadratic {
        /// The degrees `(m, n)` found.
        degrees: (usize, usize),
    },
    /// Boundary curve `circle` does not span a plane (its control vectors have rank < 3: the
    /// curve is a point or a doubly covered segment, not a circle).
    NotAConic {
        /// The index of the boundary curve (see the module documentation).
        circle: usize,
    },
    /// A corner is the zero vector or does not lie on K and on both of its circles' planes.
    CornerOffCircles {
        /// The corner index (0-based).
        corner: usize,
    },
    /// The two circles through the corner lie in one plane (they coincide).
    SameCircle {
        /// The corner index (0-based).
        corner: usize,
    },
    /// The two circles through the corner touch there: their planes meet in a tangent of K,
    /// so the second intersection is the corner itself.
    Tangent {
        /// The corner index (0-based).
        corner: usize,
    },
}

impl core::fmt::Display for Degeneracy {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Degeneracy::NotBiquadratic { degrees } => {
                write!(f, "the patch has degrees {degrees:?}, not (2, 2)")
            }
            Degeneracy::NotAConic { circle } => {
                write!(f, "boundary curve {circle} spans no plane (not a circle)")
            }
            Degeneracy::CornerOffCircles { corner } => {
                write!(f, "corner {corner} is not on K and its two circles")
            }
            Degeneracy::SameCircle { corner } => {
                write!(f, "the two circles through corner {corner} coincide")
            }
            Degeneracy::Tangent { corner } => {
                write!(
                    f,
                    "the two circles through corner {corner} are tangent there"
                )
            }
        }
    }
}

impl std::error::Error for Degeneracy {}

/// The polar (symmetric bilinear) form of Lebesgue's map (7): `Phi(x, y)` with
/// `Phi(x, x) = lebesgue(x)`, i.e.
/// `(x.y, x0y1 + x1y0 - x2y3 - x3y2, x0y2 + x2y0 + x1y3 + x3y1, x1y1 + x2y2 - x0y0 - x3y3)`.
pub fn lebesgue_polar<T: Ring>(x: &Hom4<T>, y: &Hom4<T>) -> Hom4<T> {
    let [x0, x1, x2, x3] = &x.0;
    let [y0, y1, y2, y3] = &y.0;
    Hom4::new(
        x.dot(y),
        x0.mul_ref(y1) + x1.mul_ref(y0) - x2.mul_ref(y3) - x3.mul_ref(y2),
        x0.mul_ref(y2) + x2.mul_ref(y0) + x1.mul_ref(y3) + x3.mul_ref(y1),
        x1.mul_ref(y1) + x2.mul_ref(y2) - x0.mul_ref(y0) - x3.mul_ref(y3),
    )
}

/// The polar form of the sphere (5): `B(x, y) = x0 y0 - x1 y1 - x2 y2 - x3 y3`, with
/// `B(x, x) = sphere_form(x)`.
pub fn sphere_polar<T: Ring>(x: &Hom4<T>, y: &Hom4<T>) -> T {
    let [x0, x1, x2, x3] = &x.0;
    let [y0, y1, y2, y3] = &y.0;
    x0.mul_ref(y0) - x1.mul_ref(y1) - x2.mul_ref(y2) - x3.mul_ref(y3)
}

/// The generalized cross product of three 4-vectors: the vector `n` with
/// `n . x = det4(a, b, c, x)` for every `x`. For three points it is the plane through them (zero
/// when they are dependent); for three planes, their common point.
pub fn cross3<T: Ring>(a: &Hom4<T>, b: &Hom4<T>, c: &Hom4<T>) -> Hom4<T> {
    Hom4(core::array::from_fn(|i| det4(a, b, c, &unit(i))))
}

/// The unit vector `e_i`.
fn unit<T: Ring>(i: usize) -> Hom4<T> {
    Hom4(core::array::from_fn(|j| {
        if j == i {
            T::one()
        } else {
            T::zero()
        }
    }))
}

/// The bilinear patch with these corners, given in the order of [`TensorPatch::corners`]:
/// `[x(0,0), x(1,0), x(1,1), x(0,1)]` (net rows `[x00, x01]`, `[x10, x11]`).
pub fn bilinear_patch<T: Ring>(corners: &[Hom4<T>; 4]) -> TensorPatch<T> {
    let [c00, c10, c11, c01] = corners.clone();
    TensorPatch::new(vec![vec![c00, c01], vec![c10, c11]])
}

/// The delta-image (Lebesgue's map (7)) of a tensor patch of degree `(m, n)`: a patch of degree
/// `(2m, 2n)` on K (Satz 1). By the product rule,
/// `c_ab = sum_{i+k=a, j+l=b} phi(m,m,i,k) phi(n,n,j,l) Phi(b_ij, b_kl)` with `Phi` the
/// [`lebesgue_polar`] form; its boundary curves are the [`crate::quadric::lebesgue_curve`]
/// images of the boundary curves of `patch`.
pub fn lebesgue_patch<T: Field>(patch: &TensorPatch<T>) -> TensorPatch<T> {
    let (m, n) = patch.degrees();
    let zero = || Hom4::new(T::zero(), T::zero(), T::zero(), T::zero());
    let mut net = vec![vec![zero(); 2 * n + 1]; 2 * m + 1];
    for i in 0..=m {
        for k in 0..=m {
            let fu: T = phi_value(m, m, i, k);
            for j in 0..=n {
                for l in 0..=n {
                    let f = fu.mul_ref(&phi_value(n, n, j, l));
                    let term = lebesgue_polar(patch.control(i, j), patch.control(k, l)).scale(&f);
                    let cell = &mut net[i + k][j + l];
                    *cell = cell.add(&term);
                }
            }
        }
    }
    TensorPatch::new(net)
}

/// The plane of a conic given as a quadratic rational Bezier curve: the plane through its three
/// control vectors ([`cross3`]), or `None` when they are dependent (rank < 3: no conic).
///
/// # Panics
/// When the curve is not of degree 2.
pub fn conic_plane<T: Ring>(curve: &RationalBezierCurve<T>) -> Option<Hom4<T>> {
    assert_eq!(curve.degree(), 2, "conic_plane needs a quadratic curve");
    let c = curve.control();
    let n = cross3(&c[0], &c[1], &c[2]);
    (!n.is_zero()).then_some(n)
}

/// The second point in which two circles of K through the point `p` of K meet, the circles
/// given by their planes `e` and `f` (both through `p`): the line `e ∩ f` passes through `p` and
/// meets K once more, at `S(d) p - 2 B(p, d) d` for any other point `d` of the line (Vieta).
///
/// # Errors
/// [`Degeneracy::CornerOffCircles`] when `p` is zero or not on K and both planes,
/// [`Degeneracy::SameCircle`] when the planes are proportional, [`Degeneracy::Tangent`] when
/// the line touches K at `p` (the circles are tangent; the second point would be `p`). The
/// `corner` field is 0; [`miquel_configuration`] fills in the corner index.
pub fn second_intersection<T: Ring>(
    p: &Hom4<T>,
    e: &Hom4<T>,
    f: &Hom4<T>,
) -> Result<Hom4<T>, Degeneracy> {
    if p.is_zero() || !sphere_form(p).is_zero() || !e.dot(p).is_zero() || !f.dot(p).is_zero() {
        return Err(Degeneracy::CornerOffCircles { corner: 0 });
    }
    // A point d != p of the line e ∩ f: its meet with a coordinate plane x_j = 0 that does not
    // contain p (p_j != 0), so d is not p; d is zero only if the planes are dependent.
    let j = (0..4)
        .find(|&j| !p.0[j].is_zero())
        .ok_or(Degeneracy::CornerOffCircles { corner: 0 })?;
    let d = cross3(e, f, &unit(j));
    if d.is_zero() {
        return Err(Degeneracy::SameCircle { corner: 0 });
    }
    let b = sphere_polar(p, &d);
    if b.is_zero() {
        return Err(Degeneracy::Tangent { corner: 0 });
    }
    let two_b = b.mul_ref(&T::from_i64(2));
    Ok(Hom4(core::array::from_fn(|i| {
        sphere_form(&d).mul_ref(&p.0[i]) - two_b.mul_ref(&d.0[i])
    })))
}

/// The eight points and four circles of Satz 7 for a biquadratic patch (numbering in the module
/// documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MiquelConfiguration<T> {
    /// The corners `p1..p4` (index 0..3): `y(0,0), y(1,0), y(1,1), y(0,1)`.
    pub corners: [Hom4<T>; 4],
    /// The planes of the boundary circles `y(u,0), y(1,v), y(u,1), y(0,v)` (index 0..3).
    pub circles: [Hom4<T>; 4],
    /// The second intersections `q1..q4` (index 0..3): `q_i` is the second common point of the
    /// two boundary circles through `p_i`.
    pub second: [Hom4<T>; 4],
}

impl<T> MiquelConfiguration<T> {
    /// The indices of the two boundary circles through corner `i` (0-based): `((i+3) % 4, i)`.
    pub fn circles_at(i: usize) -> (usize, usize) {
        ((i + 3) % 4, i % 4)
    }
}

impl<T: Ring> MiquelConfiguration<T> {
    /// The two determinants of Satz 7, `det4(p1, q2, p3, q4)` and `det4(q1, p2, q3, p4)`: both
    /// zero exactly when each quadruple (of points of K) is coplanar, i.e. concyclic on K.
    pub fn miquel_determinants(&self) -> [T; 2] {
        let (p, q) = (&self.corners, &self.second);
        [
            det4(&p[0], &q[1], &p[2], &q[3]),
            det4(&q[0], &p[1], &q[2], &p[3]),
        ]
    }
}

/// The Miquel configuration of a biquadratic patch on K: corners, boundary-circle planes and
/// second intersections.
///
/// # Errors
/// A [`Degeneracy`] when the patch is not biquadratic, a boundary curve is not a conic, or two
/// adjacent circles coincide or touch at their corner.
pub fn miquel_configuration<T: Ring>(
    patch: &TensorPatch<T>,
) -> Result<MiquelConfiguration<T>, Degeneracy> {
    let degrees = patch.degrees();
    if degrees != (2, 2) {
        return Err(Degeneracy::NotBiquadratic { degrees });
    }
    let corners: [Hom4<T>; 4] = patch.corners().map(Hom4::clone);
    let curves = patch.boundary_curves();
    let mut circles = Vec::with_capacity(4);
    for (i, c) in curves.iter().enumerate() {
        circles.push(conic_plane(c).ok_or(Degeneracy::NotAConic { circle: i })?);
    }
    let circles: [Hom4<T>; 4] = core::array::from_fn(|i| circles[i].clone());
    let mut second = Vec::with_capacity(4);
    for (i, p) in corners.iter().enumerate() {
        let (a, b) = MiquelConfiguration::<T>::circles_at(i);
        let q = second_intersection(p, &circles[a], &circles[b]).map_err(|e| match e {
            Degeneracy::CornerOffCircles { .. } => Degeneracy::CornerOffCircles { corner: i },
            Degeneracy::SameCircle { .. } => Degeneracy::SameCircle { corner: i },
            Degeneracy::Tangent { .. } => Degeneracy::Tangent { corner: i },
            other => other,
        })?;
        second.push(q);
    }
    let second: [Hom4<T>; 4] = core::array::from_fn(|i| second[i].clone());
    Ok(MiquelConfiguration {
        corners,
        circles,
        second,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quadric::{lebesgue, lebesgue_curve};
    use crate::test_support::{Rng, Q};

    fn h(v: [i64; 4]) -> Hom4<Q> {
        Hom4(v.map(Q::int))
    }

    #[test]
    fn polar_forms_polarize() {
        let x = h([1, -2, 3, 4]);
        let y = h([2, 0, -1, 5]);
        assert_eq!(lebesgue_polar(&x, &x), lebesgue(&x));
        assert_eq!(sphere_polar(&x, &x), sphere_form(&x));
        // Phi(x + y, x + y) = Phi(x, x) + 2 Phi(x, y) + Phi(y, y).
        let s = x.add(&y);
        let two = Q::int(2);
        assert_eq!(
            lebesgue(&s),
            lebesgue(&x)
                .add(&lebesgue_polar(&x, &y).scale(&two))
                .add(&lebesgue(&y))
        );
    }

    #[test]
    fn cross_product_is_the_plane() {
        let (a, b, c) = (h([1, 0, 0, 0]), h([0, 1, 0, 0]), h([0, 0, 1, 0]));
        // The plane x3 = 0, with the sign of det4(e0, e1, e2, e3) = 1.
        assert_eq!(cross3(&a, &b, &c), h([0, 0, 0, 1]));
        let (a, b, c) = (h([1, 2, 3, 4]), h([0, 1, -1, 2]), h([3, 0, 1, 1]));
        let n = cross3(&a, &b, &c);
        for p in [&a, &b, &c] {
            assert!(n.dot(p).is_zero());
        }
        assert!(cross3(&a, &b, &a.add(&b)).is_zero());
    }

    #[test]
    fn second_point_by_hand() {
        // The circles x = 0 and y = 0 of K through the pole z = (1, 0, 0, 1) meet again at
        // the other pole (1, 0, 0, -1).
        let p = h([1, 0, 0, 1]);
        let q = second_intersection(&p, &h([0, 1, 0, 0]), &h([0, 0, 1, 0])).unwrap();
        assert!(q.proj_eq(&h([1, 0, 0, -1])));
        // The circles x = 0 and x + z = 1 (planes (0,1,0,0), (-1,1,0,1)) through the pole meet
        // along the tangent x = 0, z = 1 there: tangent circles.
        assert_eq!(
            second_intersection(&p, &h([0, 1, 0, 0]), &h([-1, 1, 0, 1])),
            Err(Degeneracy::Tangent { corner: 0 })
        );
        // Equal planes, and a point off K.
        let e = h([0, 1, 0, 0]);
        assert_eq!(
            second_intersection(&p, &e, &e.scale(&Q::int(3))),
            Err(Degeneracy::SameCircle { corner: 0 })
        );
        assert_eq!(
            second_intersection(&h([1, 0, 0, 0]), &e, &h([0, 0, 1, 0])),
            Err(Degeneracy::CornerOffCircles { corner: 0 })
        );
        // The equator z = 0 and the meridian x = 0 meet at (0, +-1, 0).
        let q = second_intersection(&h([1, 0, 1, 0]), &h([0, 0, 0, 1]), &h([0, 1, 0, 0]));
        assert!(q.unwrap().proj_eq(&h([1, 0, -1, 0])));
    }

    #[test]
    fn sphere_patch_matches_the_curve_images() {
        let corners = [
            h([1, 0, 0, 0]),
            h([1, 1, 0, 0]),
            h([1, 1, 1, 1]),
            h([2, 0, 1, -1]),
        ];
        let bil = bilinear_patch(&corners);
        assert_eq!(bil.corners().map(Hom4::clone), corners);
        let sph = lebesgue_patch(&bil);
        assert_eq!(sph.degrees(), (2, 2));
        for (i, c) in sph.corners().iter().enumerate() {
            assert_eq!(**c, lebesgue(&corners[i]));
        }
        for (a, b) in bil.boundary_curves().iter().zip(sph.boundary_curves()) {
            let image = lebesgue_curve(&a.hom_coordinates());
            assert_eq!(
                RationalBezierCurve::from_hom_coordinates(&image).unwrap(),
                b
            );
        }
        // The patch lies on K, and is the delta-image pointwise.
        for (u, v) in [(Q::new(1, 3), Q::new(2, 5)), (Q::new(-1, 2), Q::int(3))] {
            let y = sph.eval_hom(&u, &v);
            assert!(sphere_form(&y).is_zero());
            assert_eq!(y, lebesgue(&bil.eval_hom(&u, &v)));
        }
    }

    #[test]
    fn miquel_by_hand() {
        // The bilinear patch on the unit square of the plane p3 = 0 maps by sigma (Satz 2): its
        // boundary lines are lines of P, whose images are circles through the pole z.
        let corners = [
            h([1, 0, 0, 0]),
            h([1, 1, 0, 0]),
            h([1, 1, 1, 0]),
            h([1, 0, 1, 0]),
        ];
        let conf = miquel_configuration(&lebesgue_patch(&bilinear_patch(&corners))).unwrap();
        // Every boundary circle passes through z, so every second point is z = (1, 0, 0, 1).
        for q in &conf.second {
            assert!(q.proj_eq(&h([1, 0, 0, 1])));
        }
        // Corner images: sigma(1,0,0) = (1,0,0,-1), sigma(1,1,0) = (2,2,0,0) ~ (1,1,0,0).
        assert!(conf.corners[0].proj_eq(&h([1, 0, 0, -1])));
        assert!(conf.corners[1].proj_eq(&h([1, 1, 0, 0])));
        // The circle y(u,0) is the image of the line x2 = 0 of P: the plane y = 0.
        assert!(conf.circles[0].proj_eq(&h([0, 0, 1, 0])));
        assert_eq!(conf.miquel_determinants(), [Q::int(0), Q::int(0)]);
    }

    #[test]
    fn miquel_on_random_patches_and_a_broken_one() {
        let mut rng = Rng::new(7);
        let mut checked = 0;
        for _ in 0..40 {
            let corners: [Hom4<Q>; 4] =
                core::array::from_fn(|_| Hom4(core::array::from_fn(|_| Q::int(rng.int(-2, 2)))));
            let Ok(conf) = miquel_configuration(&lebesgue_patch(&bilinear_patch(&corners))) else {
                continue;
            };
            for (i, q) in conf.second.iter().enumerate() {
                let (a, b) = MiquelConfiguration::<Q>::circles_at(i);
                assert!(sphere_form(q).is_zero());
                assert!(conf.circles[a].dot(q).is_zero() && conf.circles[b].dot(q).is_zero());
                assert!(!q.proj_eq(&conf.corners[i]));
            }
            assert_eq!(conf.miquel_determinants(), [Q::int(0), Q::int(0)]);
            // A wrong pairing, p1, q1, p3, q3 (not a face of Miquel's cube), is not concyclic
            // in general; count how often it is detected.
            let (p, q) = (&conf.corners, &conf.second);
            if !det4(&p[0], &q[0], &p[2], &q[2]).is_zero() {
                checked += 1;
            }
        }
        assert!(
            checked >= 10,
            "only {checked} non-degenerate random patches"
        );
    }
}
