//! Determinants, principal minors and inertia over any ring: the pieces of Sylvester's law of
//! inertia that the catalogue uses on *symbolic* symmetric matrices (entries polynomials), where
//! Gaussian elimination (`linalg::Matrix::inertia`) is not available because the entries cannot
//! be divided or compared.
//!
//! * [`det`] (from [`crate::linalg`]): the determinant by Laplace expansion along the first
//!   row, with ring operations only, so it works over polynomial rings.
//! * [`principal`]: the principal submatrix on an index list (`D_k` of Jacobi's rule is the
//!   determinant of the leading `k x k` principal submatrix in a chosen order).
//! * [`jacobi_inertia`]: Jacobi's rule. If the leading principal minors `D_1, ..., D_n` of a
//!   real symmetric matrix are all non-zero, the number of negative eigenvalues equals the number
//!   of sign changes in the sequence `1, D_1, ..., D_n` (and there is no zero eigenvalue, since
//!   `D_n = det != 0`). Proof sketch: symmetric Gaussian elimination without pivoting succeeds
//!   and gives the pivots `D_k / D_{k-1}`, a diagonal matrix congruent to the original; by
//!   Sylvester the signs of the pivots are the signs of the eigenvalues.
//! * [`polarized`]: the matrix of a quadratic function in a basis, by polarization
//!   (`M_ii = q(b_i)`, `M_ij = (q(b_i + b_j) - q(b_i) - q(b_j)) / 2`); congruent to the standard
//!   matrix when the vectors form a basis, so it has the same inertia.
//!
//! Hand-written because the symbolic use needs division-free algorithms over our own `Ring`
//! trait; no linear-algebra crate works over a user-defined polynomial ring.

pub use crate::linalg::det;
use crate::linalg::Inertia;
use crate::scalar::{Field, Sign};
use crate::vector::Hom4;

/// The principal submatrix of `m` on the index list `idx` (rows and columns `idx`, in order).
pub fn principal<T: Clone>(m: &[Vec<T>], idx: &[usize]) -> Vec<Vec<T>> {
    idx.iter()
        .map(|&i| idx.iter().map(|&j| m[i][j].clone()).collect())
        .collect()
}

/// The inertia from the signs of the leading principal minors `D_1..D_n` by Jacobi's rule (see
/// the module documentation); `None` when some `D_k` is zero, where the rule says nothing.
pub fn jacobi_inertia(signs: &[Sign]) -> Option<Inertia> {
    if signs.contains(&Sign::Zero) {
        return None;
    }
    let mut prev = Sign::Positive;
    let mut changes = 0;
    for &s in signs {
        if s != prev {
            changes += 1;
        }
        prev = s;
    }
    Some(Inertia {
        positive: signs.len() - changes,
        negative: changes,
        zero: 0,
    })
}

/// The matrix of the quadratic function `f` in the vectors `basis`, by polarization.
///
/// # Errors
/// Never for a field of characteristic other than 2; the division by 2 is reported as
/// [`crate::ZeroDivisor`] otherwise.
pub fn polarized<T: Field>(
    f: &dyn Fn(&Hom4<T>) -> T,
    basis: &[Hom4<T>],
) -> Result<Vec<Vec<T>>, crate::ZeroDivisor> {
    let half = T::from_ratio(1, 2)?;
    let d: Vec<T> = basis.iter().map(f).collect();
    let n = basis.len();
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut row = Vec::with_capacity(n);
        for j in 0..n {
            row.push(if i == j {
                d[i].clone()
            } else {
                (f(&basis[i].add(&basis[j])) - d[i].clone() - d[j].clone()).mul_ref(&half)
            });
        }
        out.push(row);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::Matrix;
    use Sign::{Negative as N, Positive as Pos};

    fn m(rows: &[&[f64]]) -> Vec<Vec<f64>> {
        rows.iter().map(|r| r.to_vec()).collect()
    }

    #[test]
    fn laplace_matches_elimination() {
        let a = m(&[
            &[2.0, -1.0, 0.0, 3.0],
            &[1.0, 4.0, -2.0, 0.0],
            &[0.0, 5.0, 1.0, -1.0],
            &[3.0, 0.0, 2.0, 1.0],
        ]);
        let by_elimination = Matrix::from_rows(a.clone()).unwrap().determinant().unwrap();
        assert!((det(&a) - by_elimination).abs() < 1e-9);
        assert_eq!(det::<f64>(&[]), 1.0);
        assert_eq!(det(&m(&[&[1.0, 2.0], &[3.0, 4.0]])), -2.0);
    }

    #[test]
    fn principal_picks_rows_and_columns() {
        let a = m(&[&[1.0, 2.0, 3.0], &[4.0, 5.0, 6.0], &[7.0, 8.0, 9.0]]);
        assert_eq!(principal(&a, &[2, 0]), m(&[&[9.0, 7.0], &[3.0, 1.0]]));
    }

    #[test]
    fn jacobi_counts_sign_changes() {
        let i = jacobi_inertia(&[Pos, Pos, N, Pos]).unwrap();
        assert_eq!((i.positive, i.negative, i.zero), (2, 2, 0));
        let i = jacobi_inertia(&[Pos, Pos, N]).unwrap();
        assert_eq!((i.positive, i.negative), (2, 1));
        let i = jacobi_inertia(&[N, Pos]).unwrap();
        assert_eq!((i.positive, i.negative), (0, 2));
        // A zero minor: the rule does not apply (formerly counted as a sign change).
        assert_eq!(jacobi_inertia(&[Pos, Sign::Zero, Pos]), None);
    }

    #[test]
    fn jacobi_agrees_with_elimination() {
        // diag-like matrix with leading minors 1, -1, 1: inertia (1, 2, 0).
        let a = m(&[&[1.0, 1.0, 0.0], &[1.0, 0.0, 1.0], &[0.0, 1.0, 0.0]]);
        let signs: Vec<Sign> = (1..=3)
            .map(|k| {
                let d = det(&principal(&a, &(0..k).collect::<Vec<_>>()));
                if d > 0.0 {
                    Pos
                } else if d < 0.0 {
                    N
                } else {
                    Sign::Zero
                }
            })
            .collect();
        let by_elimination = Matrix::from_rows(a).unwrap().inertia().unwrap();
        assert_eq!(jacobi_inertia(&signs), Some(by_elimination));
    }

    #[test]
    fn polarization_recovers_the_matrix() {
        // q(x) = x0^2 - x3^2 + 4 x1 x2 in the standard basis.
        let q = |x: &Hom4<f64>| x.0[0] * x.0[0] - x.0[3] * x.0[3] + 4.0 * x.0[1] * x.0[2];
        let e = |i: usize| Hom4(core::array::from_fn(|j| if i == j { 1.0 } else { 0.0 }));
        let basis = [e(0), e(1), e(2), e(3)];
        let mq = polarized(&q, &basis).unwrap();
        assert_eq!(
            mq,
            m(&[
                &[1.0, 0.0, 0.0, 0.0],
                &[0.0, 0.0, 2.0, 0.0],
                &[0.0, 2.0, 0.0, 0.0],
                &[0.0, 0.0, 0.0, -1.0],
            ])
        );
    }
}
