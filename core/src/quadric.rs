//! Rational curves and surfaces on quadrics (Juettler).
//!
//! Homogeneous coordinates throughout. The unit sphere K is `k0^2 = k1^2 + k2^2 + k3^2`
//! (5), the hyperbolic paraboloid H is `h0 h3 = h1 h2` (6). Every map here is division-free, so
//! it runs over any [`Ring`] — over polynomials it proves the identities by expansion.

use crate::bernstein::Bernstein;
use crate::scalar::{Field, Ring};
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

/// The stereographic projection sigma (10) of the plane P (`p3 = 0`) onto K from the centre
/// `z = (1, 0, 0, 1)`: `sigma(p) = (p0^2+p1^2+p2^2, 2 p0 p1, 2 p0 p2, p1^2+p2^2-p0^2)`.
/// (`p3` is ignored: sigma is defined on P.)
pub fn sigma<T: Ring>(p: &Hom4<T>) -> Hom4<T> {
    let [p0, p1, p2, _] = &p.0;
    let (s0, s1, s2) = (p0.square(), p1.square(), p2.square());
    let two = T::from_i64(2);
    Hom4::new(
        s0.add_ref(&s1) + &s2,
        p0.mul_ref(p1) * &two,
        p0.mul_ref(p2) * &two,
        s1 + &s2 - &s0,
    )
}

/// The inverse of sigma as printed: `sigma^-1(k) = (k0 - k3, k1, k2, 0)`.
pub fn sigma_inverse<T: Ring>(k: &Hom4<T>) -> Hom4<T> {
    let [k0, k1, k2, k3] = &k.0;
    Hom4::new(k0.sub_ref(k3), k1.clone(), k2.clone(), T::zero())
}

/// theta (11): `theta(p) = (p0^2+p3^2, p0 p1 - p2 p3, p0 p2 + p1 p3, 0)`; delta = sigma o theta
/// (Satz 3).
pub fn theta<T: Ring>(p: &Hom4<T>) -> Hom4<T> {
    let [p0, p1, p2, p3] = &p.0;
    Hom4::new(
        p0.square() + p3.square(),
        p0.mul_ref(p1) - p2.mul_ref(p3),
        p0.mul_ref(p2) + p1.mul_ref(p3),
        T::zero(),
    )
}

/// The point `lambda (p0, p1, p2, 0) + mu (0, p2, -p1, p0)` of the line (12), the theta-preimage
/// of `p = (p0, p1, p2, 0)` (Lemma 4).
pub fn theta_preimage_point<T: Ring>(p: &Hom4<T>, lambda: &T, mu: &T) -> Hom4<T> {
    let [p0, p1, p2, _] = &p.0;
    Hom4::new(
        lambda.mul_ref(p0),
        lambda.mul_ref(p1) + mu.mul_ref(p2),
        lambda.mul_ref(p2) - mu.mul_ref(p1),
        mu.mul_ref(p0),
    )
}

/// psi (15), the generalized stereographic projection onto H; the same map as [`dietz`].
pub fn psi<T: Ring>(q: &Hom4<T>) -> Hom4<T> {
    dietz(q)
}

/// tau (16), the stereographic projection of the plane R (`q3 = q0`) onto H from
/// `c = (0, 0, 0, 1)`: `tau(q) = (q0^2, q0 q1, q0 q2, q1 q2)`.
pub fn tau<T: Ring>(q: &Hom4<T>) -> Hom4<T> {
    let [q0, q1, q2, _] = &q.0;
    Hom4::new(q0.square(), q0.mul_ref(q1), q0.mul_ref(q2), q1.mul_ref(q2))
}

/// alpha (17): `alpha(q) = (q0 q3, q1 q3, q0 q2, q0 q3)`; psi = tau o alpha (Satz 9).
pub fn alpha<T: Ring>(q: &Hom4<T>) -> Hom4<T> {
    let [q0, q1, q2, q3] = &q.0;
    let q0q3 = q0.mul_ref(q3);
    Hom4::new(q0q3.clone(), q1.mul_ref(q3), q0.mul_ref(q2), q0q3)
}

/// The point `lambda (q0, q1, q2, q0) + mu (q0, q1, 0, 0)` of the line (18), the alpha-preimage
/// of `q = (q0, q1, q2, q0)` (Lemma 10).
pub fn alpha_preimage_point<T: Ring>(q: &Hom4<T>, lambda: &T, mu: &T) -> Hom4<T> {
    let [q0, q1, q2, _] = &q.0;
    let lm = lambda.add_ref(mu);
    Hom4::new(
        lm.mul_ref(q0),
        lm.mul_ref(q1),
        lambda.mul_ref(q2),
        lambda.mul_ref(q0),
    )
}

/// The delta-image (Satz 1) of a rational curve given by the Bernstein forms of its four
/// homogeneous coordinates, all of degree n: the four coordinates of degree 2n of the image on
/// K, by the product rule.
///
/// # Panics
/// When the four inputs differ in degree (callers build them with one degree).
pub fn lebesgue_curve<T: Field>(x: &[Bernstein<T>; 4]) -> [Bernstein<T>; 4] {
    let sq: Vec<Bernstein<T>> = x.iter().map(|c| c.mul(c)).collect();
    let prod = |a: usize, b: usize| x[a].mul(&x[b]).scale(&T::from_i64(2));
    let add = |a: &Bernstein<T>, b: &Bernstein<T>| a.checked_add(b).expect("equal degrees");
    let sub = |a: &Bernstein<T>, b: &Bernstein<T>| a.checked_sub(b).expect("equal degrees");
    [
        add(&add(&sq[0], &sq[1]), &add(&sq[2], &sq[3])),
        sub(&prod(0, 1), &prod(2, 3)),
        add(&prod(0, 2), &prod(1, 3)),
        sub(&add(&sq[1], &sq[2]), &add(&sq[0], &sq[3])),
    ]
}

/// The delta-image of a curve (Satz 1), division-free: for homogeneous Bernstein coordinates
/// `x_a` of degree n, the *scaled* coefficients `e_k = C(2n, k) * (k-th Bernstein coefficient)`
/// of the four image coordinates (see [`Bernstein::mul_scaled`]). Runs over any [`Ring`], so it
/// also runs over polynomials (a symbolic proof of Satz 1).
pub fn lebesgue_curve_scaled<T: Ring>(x: &[Bernstein<T>; 4]) -> [Vec<T>; 4] {
    let prod = |a: usize, b: usize| x[a].mul_scaled(&x[b]);
    let combine = |terms: &[(i64, Vec<T>)]| -> Vec<T> {
        let n = terms[0].1.len();
        (0..n)
            .map(|k| {
                let mut acc = T::zero();
                for (c, v) in terms {
                    acc += v[k].scale_i64(*c);
                }
                acc
            })
            .collect()
    };
    let (s0, s1, s2, s3) = (prod(0, 0), prod(1, 1), prod(2, 2), prod(3, 3));
    [
        combine(&[
            (1, s0.clone()),
            (1, s1.clone()),
            (1, s2.clone()),
            (1, s3.clone()),
        ]),
        combine(&[(2, prod(0, 1)), (-2, prod(2, 3))]),
        combine(&[(2, prod(0, 2)), (2, prod(1, 3))]),
        combine(&[(1, s1), (1, s2), (-1, s0), (-1, s3)]),
    ]
}

/// The delta-image of a tensor-product patch of degree (m, n) given by its net of homogeneous
/// control vectors `net[i][j]` (Satz 1 for surfaces), division-free: the net of degree (2m, 2n)
/// scaled by `C(2m, k) C(2n, l)` at `(k, l)`.
pub fn lebesgue_patch_scaled<T: Ring>(net: &[Vec<Hom4<T>>]) -> Vec<Vec<Hom4<T>>> {
    let m = net.len().saturating_sub(1);
    let n = net.first().map_or(0, |r| r.len().saturating_sub(1));
    let c = |n: usize, k: usize| crate::scalar::binomial(n as u32, k as u32) as i64;
    // Products of coordinates a, b of the net, scaled: sum over i+i'=k, j+j'=l.
    let prod = |a: usize, b: usize| -> Vec<Vec<T>> {
        let mut out = vec![vec![T::zero(); 2 * n + 1]; 2 * m + 1];
        for i in 0..=m {
            for j in 0..=n {
                for i2 in 0..=m {
                    for j2 in 0..=n {
                        let w = c(m, i) * c(m, i2) * c(n, j) * c(n, j2);
                        let t = net[i][j].0[a].mul_ref(&net[i2][j2].0[b]).scale_i64(w);
                        out[i + i2][j + j2] += t;
                    }
                }
            }
        }
        out
    };
    let p: Vec<Vec<Vec<Vec<T>>>> = (0..4)
        .map(|a| (0..4).map(|b| prod(a, b)).collect())
        .collect();
    (0..=2 * m)
        .map(|k| {
            (0..=2 * n)
                .map(|l| {
                    let e = |a: usize, b: usize| p[a][b][k][l].clone();
                    Hom4::new(
                        e(0, 0) + e(1, 1) + e(2, 2) + e(3, 3),
                        (e(0, 1) - e(2, 3)).scale_i64(2),
                        (e(0, 2) + e(1, 3)).scale_i64(2),
                        e(1, 1) + e(2, 2) - e(0, 0) - e(3, 3),
                    )
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_on_a_sample_point() {
        let p = Hom4([1.0, 2.0, 3.0, 0.0]);
        // Satz 2 at one point: delta on p3 = 0 is sigma.
        assert_eq!(sigma(&p), lebesgue(&p));
        assert!(sigma_inverse(&sigma(&p)).proj_eq(&p));
        let q = Hom4([2.0, -1.0, 3.0, 5.0]);
        assert!(sigma(&theta(&q)).proj_eq(&lebesgue(&q)));
        assert!(tau(&alpha(&q)).proj_eq(&psi(&q)));
    }

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
