//! The published JavaScript `InterctionLineOf2Areas` (walter.bislins.ch, "Schnittlinie zweier
//! Ebenen", 2022), ported to `f64` operation for operation.
//!
//! **This is the code under test and is deliberately not improved.** Every JavaScript operation
//! has its counterpart here in the same order: `V3.Length` (`Math.sqrt` of `x*x + y*y + z*z`
//! summed left to right; `f64::sqrt` is correctly rounded like `Math.sqrt`), `V3.Scale`
//! (multiplication by the scale factor, so normalisation multiplies by `1/ql` rather than
//! dividing), `V3.Add`, `V3.ScalarProd`, `V3.Mult` (the cross product), the exact test
//! `ql == 0`, and `s1 = (d1 - r*d2) / (1 - r*r)`, `s2 = (d2 - r*d1) / (1 - r*r)`. Rust does not
//! contract `a*b + c` into fused multiply-adds, and JavaScript numbers are IEEE binary64, so the
//! port computes the same doubles as the published function.
//!
//! The function requires unit normals (its comment says so) and uses the orientation
//! `q = n2 x n1`. `exactcheck regress plane-plane` measures how far its point and direction stray
//! from the exact construction of `exactcheck_core::planes` as the planes approach parallel.

/// A JavaScript `V3`: an array of three numbers.
pub type V3 = [f64; 3];

/// `V3.Length`.
pub fn length(v: &V3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// `V3.Scale`.
pub fn scale(v: &V3, s: f64) -> V3 {
    [v[0] * s, v[1] * s, v[2] * s]
}

/// `V3.Add`.
pub fn add(a: &V3, b: &V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `V3.ScalarProd`.
pub fn scalar_prod(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `V3.Mult` (the cross product `a x b`).
pub fn mult(a: &V3, b: &V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `InterctionLineOf2Areas(P1, n1, P2, n2)`: the line `x = Q + lambda q` of the planes
/// `n1 . x = n1 . P1` and `n2 . x = n2 . P2` as `Some((Q, q))`, `q` the normalised `n2 x n1`;
/// `None` (the JavaScript `null`) when `|n2 x n1|` evaluates to exactly 0. Requires unit
/// normals, as published; nothing is checked, as published.
#[allow(clippy::float_cmp)]
pub fn interction_line_of_2_areas(p1: &V3, n1: &V3, p2: &V3, n2: &V3) -> Option<(V3, V3)> {
    let q = mult(n2, n1);
    let ql = length(&q);
    if ql == 0.0 {
        // areas are parallel -> no solution
        return None;
    }
    // normalize q
    let q = scale(&q, 1.0 / ql);

    let r = scalar_prod(n1, n2);
    // assert r < 1
    let d1 = scalar_prod(p1, n1);
    let d2 = scalar_prod(p2, n2);
    let s1 = (d1 - r * d2) / (1.0 - r * r);
    let s2 = (d2 - r * d1) / (1.0 - r * r);

    let big_q = add(&scale(n1, s1), &scale(n2, s2));
    Some((big_q, q))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orthogonal_unit_planes() {
        // x = 1 and y = 2 meet in the line (1, 2, 0) + lambda (0, 0, -1) (q = n2 x n1).
        let (q_point, q) = interction_line_of_2_areas(
            &[1.0, 5.0, 7.0],
            &[1.0, 0.0, 0.0],
            &[3.0, 2.0, -1.0],
            &[0.0, 1.0, 0.0],
        )
        .expect("not parallel");
        assert_eq!(q_point, [1.0, 2.0, 0.0]);
        assert_eq!(q, [0.0, 0.0, -1.0]);
    }

    #[test]
    fn parallel_is_null_and_non_unit_normals_are_not_handled() {
        assert_eq!(
            interction_line_of_2_areas(
                &[0.0; 3],
                &[0.0, 0.0, 1.0],
                &[0.0, 0.0, 1.0],
                &[0.0, 0.0, 1.0]
            ),
            None
        );
        // x = 1 written with the normal (2, 0, 0) and y = 2: the published s1, s2 assume unit
        // normals, so Q = (4, 2, 0) is not on the first plane. The port keeps that behaviour.
        let (q_point, _) = interction_line_of_2_areas(
            &[1.0, 0.0, 0.0],
            &[2.0, 0.0, 0.0],
            &[0.0, 2.0, 0.0],
            &[0.0, 1.0, 0.0],
        )
        .expect("not parallel");
        assert_eq!(q_point, [4.0, 2.0, 0.0]);
    }
}
