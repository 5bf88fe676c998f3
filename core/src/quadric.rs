//! Rational curves and surfaces on quadrics (Juettler; seed 002, SPEC §1).
//!
//! Homogeneous coordinates throughout (SPEC §0). The unit sphere K is `k0^2 = k1^2 + k2^2 + k3^2`
//! (5), the hyperbolic paraboloid H is `h0 h3 = h1 h2` (6). Every map here is division-free, so
//! it runs over any [`Ring`] — over polynomials it proves the identities by expansion.

use crate::scalar::Ring;
use crate::vector::Hom4;

/// The quadratic form of the unit sphere K (5): `k0^2 - k1^2 - k2^2 - k3^2` (zero on K).
pub fn sphere_form<T: Ring>(k: &Hom4<T>) -> T {
    let [k0, k1, k2, k3] = &k.0;
    k0.square() - k1.square() - k2.square() - k3.square()
}

/// The quadratic form of the hyperbolic paraboloid H (6): `h0 h3 - h1 h2` (zero on H).
pub fn paraboloid_form<T: Ring>(h: &Hom4<T>) -> T {
    let [h0, h1, h2, h3] = &h.0;
    h0.mul_ref(h3) - h1.mul_ref(h2)
}

/// Lebesgue's representation (7), the generalized stereographic projection delta (9) onto K:
/// `k0 = p0^2+p1^2+p2^2+p3^2, k1 = 2p0p1 - 2p2p3, k2 = 2p0p2 + 2p1p3, k3 = p1^2+p2^2-p0^2-p3^2`.
pub fn lebesgue<T: Ring>(p: &Hom4<T>) -> Hom4<T> {
    let [p0, p1, p2, p3] = &p.0;
    let (s0, s1, s2, s3) = (p0.square(), p1.square(), p2.square(), p3.square());
    let two = T::from_i64(2);
    Hom4::new(
        s0.add_ref(&s1) + &s2 + &s3,
        (p0.mul_ref(p1) - p2.mul_ref(p3)) * &two,
        (p0.mul_ref(p2) + p1.mul_ref(p3)) * &two,
        s1 + &s2 - &s0 - &s3,
    )
}

/// Dietz's representation (8) onto H: `h0 = q0 q3, h1 = q1 q3, h2 = q0 q2, h3 = q1 q2`
/// (the map psi of (15)).
pub fn dietz<T: Ring>(q: &Hom4<T>) -> Hom4<T> {
    let [q0, q1, q2, q3] = &q.0;
    Hom4::new(
        q0.mul_ref(q3),
        q1.mul_ref(q3),
        q0.mul_ref(q2),
        q1.mul_ref(q2),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pythagorean_quadruples() {
        for p in [[1.0, 2.0, 3.0, 4.0], [2.0, -1.0, 0.0, 5.0]] {
            let k = lebesgue(&Hom4(p));
            assert_eq!(sphere_form(&k), 0.0);
            assert_eq!(paraboloid_form(&dietz(&Hom4(p))), 0.0);
        }
        // (1,2,3,4) -> (30, -20, 22, -4): 30^2 = 20^2 + 22^2 + 4^2 = 900.
        assert_eq!(
            lebesgue(&Hom4([1.0, 2.0, 3.0, 4.0])),
            Hom4([30.0, -20.0, 22.0, -4.0])
        );
    }
}
