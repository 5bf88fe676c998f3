//! Interpolation on the sphere is a linear problem (Juettler §2).
//!
//! Given points `k_j` of the unit sphere K (5) and distinct parameters `t_j`, take the preimage
//! line of each point under the generalized stereographic projection delta — the projecting line
//! (12) through `p_j = sigma^-1(k_j)` (Lemma 4) — and look for a polynomial curve `x(t)` of degree
//! n in projective space that meets line j at `t_j`. "x(t_j) lies on the line spanned by A_j, B_j"
//! is two homogeneous *linear* conditions on the 4(n+1) Bernstein coefficients of x (x(t_j) is
//! orthogonal to a basis of the annihilator of the line), so the curve comes from the nullspace
//! of a 2N x 4(n+1) matrix; its delta-image (Satz 1) is a rational Bezier curve of degree 2n on K
//! through every point. The degree needed grows like N/2 (image degree about N).
//!
//! The comparison: with the plain stereographic projection sigma (10) the preimages are single
//! points of the plane P, and a plane curve of degree m through N points at given parameters
//! needs 3(m+1) - 1 >= 2N, so the image degree 2m grows like 4N/3.
//!
//! Cost: the degrees are tried from 0 up, but the degrees whose system has only the zero
//! solution are found by one elimination in the power basis (`solvable_degrees`) and skipped,
//! so the work is about three eliminations of a 2N x 2N system instead of one per degree.

use crate::bernstein::Bernstein;
use crate::bezier::RationalBezierCurve;
use crate::linalg::Matrix;
use crate::quadric::{lebesgue, lebesgue_curve, sigma, sigma_inverse, sphere_form};
use crate::scalar::Field;
use crate::vector::Hom4;

/// Why an interpolation problem was rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InterpolationError {
    /// No points were given.
    NoPoints,
    /// Points and parameters differ in number.
    LengthMismatch {
        /// Number of points.
        points: usize,
        /// Number of parameters.
        params: usize,
    },
    /// Point `index` does not satisfy `k0^2 = k1^2 + k2^2 + k3^2`, or has `k0 = 0`.
    NotOnSphere {
        /// Index of the point.
        index: usize,
    },
    /// Two parameters are equal.
    RepeatedParameter {
        /// Index of the first.
        first: usize,
        /// Index of the second.
        second: usize,
    },
    /// No curve up to the degree bound passes through the points (a degenerate configuration).
    NoSolution {
        /// The largest preimage degree tried.
        max_degree: usize,
    },
}

impl core::fmt::Display for InterpolationError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            InterpolationError::NoPoints => f.write_str("no points to interpolate"),
            InterpolationError::LengthMismatch { points, params } => {
                write!(f, "{points} points but {params} parameters")
            }
            InterpolationError::NotOnSphere { index } => write!(
                f,
                "points[{index}] is not on the unit sphere (k0^2 = k1^2 + k2^2 + k3^2 with k0 != 0 fails)"
            ),
            InterpolationError::RepeatedParameter { first, second } => {
                write!(f, "params[{first}] and params[{second}] are equal")
            }
            InterpolationError::NoSolution { max_degree } => write!(
                f,
                "no interpolating curve of preimage degree <= {max_degree} (degenerate configuration)"
            ),
        }
    }
}

impl std::error::Error for InterpolationError {}

/// An interpolating curve on K and how it was found.
#[derive(Clone, Debug)]
pub struct SphereInterpolant<T> {
    /// The preimage curve in projective space (degree n), homogeneous Bernstein coordinates.
    pub preimage: [Bernstein<T>; 4],
    /// The rational Bezier curve on K, degree 2n, the delta-image of the preimage.
    pub curve: RationalBezierCurve<T>,
    /// The degree 2n of the curve on K.
    pub degree: usize,
    /// The least image degree the plain stereographic projection sigma needs for the same
    /// points and parameters (by the same linear method), for comparison.
    pub sigma_degree: Option<usize>,
}

/// The two points spanning the delta-preimage line of a point k of K: (12) through
/// `p = sigma^-1(k)`, or the line `p0 = p3 = 0` for the centre `z = (1, 0, 0, 1)`.
pub fn preimage_line<T: Field>(k: &Hom4<T>) -> [Hom4<T>; 2] {
    let p = sigma_inverse(k);
    if p.is_zero() {
        return [
            Hom4::new(T::zero(), T::one(), T::zero(), T::zero()),
            Hom4::new(T::zero(), T::zero(), T::one(), T::zero()),
        ];
    }
    let [p0, p1, p2, _] = &p.0;
    [
        p.clone(),
        Hom4::new(T::zero(), p2.clone(), p1.neg_ref(), p0.clone()),
    ]
}

fn validate<T: Field>(points: &[Hom4<T>], params: &[T]) -> Result<(), InterpolationError> {
    if points.is_empty() {
        return Err(InterpolationError::NoPoints);
    }
    if points.len() != params.len() {
        return Err(InterpolationError::LengthMismatch {
            points: points.len(),
            params: params.len(),
        });
    }
    for (i, k) in points.iter().enumerate() {
        if !sphere_form(k).is_zero() || k.0[0].is_zero() {
            return Err(InterpolationError::NotOnSphere { index: i });
        }
    }
    for i in 0..params.len() {
        for j in 0..i {
            if params[i] == params[j] {
                return Err(InterpolationError::RepeatedParameter {
                    first: j,
                    second: i,
                });
            }
        }
    }
    Ok(())
}

/// The rows `u . x(t_j) = 0` for each `u` in a basis of the annihilator of `span`, over the
/// Bernstein coefficients of a curve in `dim` homogeneous coordinates of degree n.
fn conditions<T: Field>(rows: &mut Vec<Vec<T>>, span: &[Vec<T>], t: &T, n: usize) {
    let dim = span[0].len();
    let Ok(m) = Matrix::from_rows(span.to_vec()) else {
        return;
    };
    let basis: Vec<T> = (0..=n)
        .map(|i| Bernstein::<T>::basis(n, i).eval(t))
        .collect();
    for u in m.nullspace() {
        let mut row = vec![T::zero(); dim * (n + 1)];
        for (i, b) in basis.iter().enumerate() {
            for a in 0..dim {
                row[i * dim + a] = b.mul_ref(&u[a]);
            }
        }
        rows.push(row);
    }
}

/// For each degree `n < bound`, whether the conditions of degree `n` have a non-zero solution;
/// from `bound` on they always do (more unknowns than conditions). `lines` are the spans of the
/// lines (rows of `dim` coordinates) with their parameters.
///
/// A solution of degree `n` is a curve `x(t)` of degree `<= n` meeting every line at its
/// parameter; whether one exists does not depend on the basis. In the power basis the unknowns
/// of degree `n` are the first `dim (n + 1)` columns of those of any higher degree (the
/// coefficients of `1, t, ..., t^n`), and Gauss-Jordan elimination chooses its pivots column by
/// column from the left, so the pivots of one elimination of the widest matrix give the rank of
/// every degree at once: degree `n` has a solution iff fewer than `dim (n + 1)` pivots lie in
/// its columns. One elimination replaces one per degree (the cost was about N^6 for N points:
/// N/2 degrees, each an elimination of a 2N x 2N system with growing rationals).
fn solvable_degrees<T: Field>(lines: &[(Vec<Vec<T>>, &T)], dim: usize) -> (Vec<bool>, usize) {
    let mut rows: Vec<(Vec<T>, &T)> = Vec::new();
    for (span, t) in lines {
        let Ok(m) = Matrix::from_rows(span.clone()) else {
            continue;
        };
        for u in m.nullspace() {
            rows.push((u, t));
        }
    }
    // From degree `bound` on, dim (n + 1) > rows: a non-zero solution always exists.
    let bound = rows.len() / dim;
    if bound == 0 {
        return (Vec::new(), 0);
    }
    let cols = dim * bound;
    let matrix: Vec<Vec<T>> = rows
        .iter()
        .map(|(u, t)| {
            let mut row = Vec::with_capacity(cols);
            let mut power = T::one();
            for _ in 0..bound {
                row.extend(u.iter().map(|ua| ua.mul_ref(&power)));
                power = power.mul_ref(t);
            }
            row
        })
        .collect();
    let pivots = Matrix::from_rows(matrix)
        .map(|m| m.rref().1)
        .unwrap_or_default();
    let solvable = (0..bound)
        .map(|n| pivots.iter().filter(|&&c| c < dim * (n + 1)).count() < dim * (n + 1))
        .collect();
    (solvable, bound)
}

/// Whether degree `n` may have a non-zero solution (see [`solvable_degrees`]).
fn may_solve((solvable, bound): &(Vec<bool>, usize), n: usize) -> bool {
    n >= *bound || solvable[n]
}

/// The curve of degree n from a coefficient vector of length dim (n+1).
fn curve_of<T: Field>(v: &[T], dim: usize, n: usize) -> Vec<Bernstein<T>> {
    (0..dim)
        .map(|a| Bernstein::new((0..=n).map(|i| v[i * dim + a].clone()).collect()))
        .collect()
}

/// Candidate solutions from a nullspace basis: each basis vector, then sums of pairs.
fn candidates<T: Field>(ns: &[Vec<T>]) -> Vec<Vec<T>> {
    let mut out: Vec<Vec<T>> = ns.to_vec();
    for i in 0..ns.len() {
        for j in i + 1..ns.len() {
            out.push(
                ns[i]
                    .iter()
                    .zip(&ns[j])
                    .map(|(a, b)| a.add_ref(b))
                    .collect(),
            );
        }
    }
    out
}

/// Interpolates the points `k_j` of K at the parameters `t_j` by a rational Bezier curve on K of
/// the lowest degree the linear method allows (see the module documentation).
///
/// # Errors
/// [`InterpolationError`] for no points, mismatched lengths, points off K, repeated parameters,
/// or no solution up to preimage degree N.
pub fn interpolate<T: Field>(
    points: &[Hom4<T>],
    params: &[T],
) -> Result<SphereInterpolant<T>, InterpolationError> {
    validate(points, params)?;
    let lines: Vec<[Hom4<T>; 2]> = points.iter().map(preimage_line).collect();
    let max_degree = points.len();
    let spans: Vec<(Vec<Vec<T>>, &T)> = lines
        .iter()
        .zip(params)
        .map(|(line, t)| (vec![line[0].0.to_vec(), line[1].0.to_vec()], t))
        .collect();
    let solvable = solvable_degrees(&spans, 4);
    for n in 0..=max_degree {
        if !may_solve(&solvable, n) {
            // Only the zero curve meets every line: no candidate (as the nullspace would say).
            continue;
        }
        let mut rows = Vec::new();
        for (line, t) in lines.iter().zip(params) {
            conditions(&mut rows, &[line[0].0.to_vec(), line[1].0.to_vec()], t, n);
        }
        let ns = Matrix::from_rows(rows)
            .map(|m| m.nullspace())
            .unwrap_or_default();
        let ns = if ns.is_empty() && lines.is_empty() {
            vec![]
        } else {
            ns
        };
        for v in candidates(&ns) {
            let x = curve_of(&v, 4, n);
            let x: [Bernstein<T>; 4] = [x[0].clone(), x[1].clone(), x[2].clone(), x[3].clone()];
            let ok = points.iter().zip(params).all(|(k, t)| {
                let xt = Hom4::new(x[0].eval(t), x[1].eval(t), x[2].eval(t), x[3].eval(t));
                !xt.is_zero() && lebesgue(&xt).proj_eq(k)
            });
            if !ok {
                continue;
            }
            let image = lebesgue_curve(&x);
            let Ok(curve) = RationalBezierCurve::from_hom_coordinates(&image) else {
                continue;
            };
            return Ok(SphereInterpolant {
                preimage: x,
                degree: 2 * n,
                curve,
                sigma_degree: sigma_degree(points, params),
            });
        }
    }
    Err(InterpolationError::NoSolution { max_degree })
}

/// The least image degree 2m for which a plane curve of degree m through the points
/// `sigma^-1(k_j)` of P at the parameters `t_j` exists whose sigma-image passes through every
/// `k_j` (None if there is none up to m = N).
pub fn sigma_degree<T: Field>(points: &[Hom4<T>], params: &[T]) -> Option<usize> {
    let pre: Vec<Hom4<T>> = points.iter().map(sigma_inverse).collect();
    let spans: Vec<(Vec<Vec<T>>, &T)> = pre
        .iter()
        .zip(params)
        .map(|(p, t)| {
            let (o, z) = (T::one(), T::zero());
            let span = if p.is_zero() {
                vec![vec![z.clone(), o.clone(), z.clone()], vec![z.clone(), z, o]]
            } else {
                vec![vec![p.0[0].clone(), p.0[1].clone(), p.0[2].clone()]]
            };
            (span, t)
        })
        .collect();
    let solvable = solvable_degrees(&spans, 3);
    for m in 0..=points.len() {
        if !may_solve(&solvable, m) {
            continue;
        }
        let mut rows = Vec::new();
        for (p, t) in pre.iter().zip(params) {
            if p.is_zero() {
                // k = z, the centre: its sigma-preimage is the line at infinity x0 = 0 of P.
                let (o, z) = (T::one(), T::zero());
                conditions(
                    &mut rows,
                    &[vec![z.clone(), o.clone(), z.clone()], vec![z.clone(), z, o]],
                    t,
                    m,
                );
            } else {
                conditions(
                    &mut rows,
                    &[vec![p.0[0].clone(), p.0[1].clone(), p.0[2].clone()]],
                    t,
                    m,
                );
            }
        }
        let ns = Matrix::from_rows(rows)
            .map(|m| m.nullspace())
            .unwrap_or_default();
        for v in candidates(&ns) {
            let x = curve_of(&v, 3, m);
            let ok = points.iter().zip(params).all(|(k, t)| {
                let xt = Hom4::new(x[0].eval(t), x[1].eval(t), x[2].eval(t), T::zero());
                !xt.is_zero() && sigma(&xt).proj_eq(k)
            });
            if ok {
                return Some(2 * m);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Ring;
    use crate::test_support::Q;

    fn q(n: i128) -> Q {
        Q::new(n, 1)
    }

    #[test]
    fn interpolates_lebesgue_points() {
        let seeds = [
            [1, 2, 3, 4],
            [2, -1, 0, 5],
            [3, 1, -2, 1],
            [1, 1, 1, -3],
            [0, 2, 5, 1],
        ];
        for count in 1..=seeds.len() {
            let points: Vec<Hom4<Q>> = seeds[..count]
                .iter()
                .map(|p| lebesgue(&Hom4::new(q(p[0]), q(p[1]), q(p[2]), q(p[3]))))
                .collect();
            let params: Vec<Q> = (0..count as i128)
                .map(|j| Q::new(j, count as i128))
                .collect();
            let r = interpolate(&points, &params).expect("solvable");
            for (k, t) in points.iter().zip(&params) {
                assert!(r.curve.eval_hom(t).proj_eq(k));
            }
            // The curve lies on K: k0^2 - k1^2 - k2^2 - k3^2 vanishes identically.
            let k = r.curve.hom_coordinates();
            let form = k[0].mul(&k[0]).checked_sub(&k[1].mul(&k[1])).unwrap();
            let form = form
                .checked_sub(&k[2].mul(&k[2]))
                .unwrap()
                .checked_sub(&k[3].mul(&k[3]))
                .unwrap();
            assert!(form.coeffs().iter().all(|c| c.is_zero()));
            assert!(
                r.degree <= 2 * count.div_ceil(2),
                "degree {} for {count} points",
                r.degree
            );
            if let Some(sd) = r.sigma_degree {
                assert!(r.degree <= sd, "delta {} vs sigma {}", r.degree, sd);
            }
        }
    }

    #[test]
    fn rejects_bad_input() {
        let k = lebesgue(&Hom4::new(q(1), q(2), q(3), q(4)));
        assert_eq!(
            interpolate::<Q>(&[], &[]).unwrap_err(),
            InterpolationError::NoPoints
        );
        let off = Hom4::new(q(1), q(1), q(1), q(1));
        assert_eq!(
            interpolate(&[off], &[q(0)]).unwrap_err(),
            InterpolationError::NotOnSphere { index: 0 }
        );
        assert_eq!(
            interpolate(&[k.clone(), k.clone()], &[q(0), q(0)]).unwrap_err(),
            InterpolationError::RepeatedParameter {
                first: 0,
                second: 1
            }
        );
    }
}
