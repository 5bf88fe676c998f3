//! Exact linear algebra over any [`Field`]: reduced row echelon form, rank, nullspace, linear
//! solve, the determinant over any ring ([`det`]), and the inertia of a symmetric matrix over an [`OrderedField`] (Sylvester's
//! law: the numbers of positive, negative and zero eigenvalues, found by congruence, without
//! eigenvalues). Used for the interpolation system on the sphere and the classification of
//! preimage quadrics.
//!
//! Pivoting picks the first non-zero entry: exact arithmetic needs no numerical pivoting.

use crate::scalar::{Field, OrderedField, Ring, Sign};

/// A dense matrix, row-major.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Matrix<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

/// Errors of the matrix constructors.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MatrixError {
    /// Rows of different lengths.
    Ragged {
        /// Index of the offending row.
        row: usize,
    },
    /// A square matrix was required.
    NotSquare,
    /// A symmetric matrix was required.
    NotSymmetric,
    /// Operand shapes do not fit.
    Shape,
}

impl core::fmt::Display for MatrixError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            MatrixError::Ragged { row } => write!(f, "row {row} has a different length"),
            MatrixError::NotSquare => f.write_str("the matrix is not square"),
            MatrixError::NotSymmetric => f.write_str("the matrix is not symmetric"),
            MatrixError::Shape => f.write_str("the shapes do not fit"),
        }
    }
}

impl std::error::Error for MatrixError {}

impl<T: Field> Matrix<T> {
    /// The matrix with the given rows.
    ///
    /// # Errors
    /// [`MatrixError::Ragged`] when rows differ in length.
    pub fn from_rows(rows: Vec<Vec<T>>) -> Result<Self, MatrixError> {
        let cols = rows.first().map_or(0, Vec::len);
        let n = rows.len();
        let mut data = Vec::with_capacity(n * cols);
        for (i, r) in rows.into_iter().enumerate() {
            if r.len() != cols {
                return Err(MatrixError::Ragged { row: i });
            }
            data.extend(r);
        }
        Ok(Matrix {
            rows: n,
            cols,
            data,
        })
    }

    /// The `rows x cols` zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Self {
        Matrix {
            rows,
            cols,
            data: vec![T::zero(); rows * cols],
        }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry `(i, j)`.
    pub fn get(&self, i: usize, j: usize) -> &T {
        &self.data[i * self.cols + j]
    }

    /// Sets entry `(i, j)`.
    pub fn set(&mut self, i: usize, j: usize, v: T) {
        self.data[i * self.cols + j] = v;
    }

    /// Row `i`.
    pub fn row(&self, i: usize) -> &[T] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    fn swap_rows(&mut self, a: usize, b: usize) {
        if a != b {
            for j in 0..self.cols {
                self.data.swap(a * self.cols + j, b * self.cols + j);
            }
        }
    }

    /// The reduced row echelon form and the pivot columns.
    pub fn rref(&self) -> (Matrix<T>, Vec<usize>) {
        let mut m = self.clone();
        let mut pivots = Vec::new();
        let mut r = 0;
        for c in 0..m.cols {
            if r == m.rows {
                break;
            }
            let Some(p) = (r..m.rows).find(|&i| !m.get(i, c).is_zero()) else {
                continue;
            };
            m.swap_rows(r, p);
            // The pivot is non-zero, so the inverse exists.
            let inv = match m.get(r, c).inv() {
                Ok(v) => v,
                Err(_) => continue,
            };
            for j in c..m.cols {
                let v = m.get(r, j).mul_ref(&inv);
                m.set(r, j, v);
            }
            for i in 0..m.rows {
                if i != r && !m.get(i, c).is_zero() {
                    let f = m.get(i, c).clone();
                    for j in c..m.cols {
                        let v = m.get(i, j).sub_ref(&f.mul_ref(m.get(r, j)));
                        m.set(i, j, v);
                    }
                }
            }
            pivots.push(c);
            r += 1;
        }
        (m, pivots)
    }

    /// The rank.
    pub fn rank(&self) -> usize {
        self.rref().1.len()
    }

    /// A basis of the nullspace `{x : A x = 0}` (one vector per free column).
    pub fn nullspace(&self) -> Vec<Vec<T>> {
        let (r, pivots) = self.rref();
        let free: Vec<usize> = (0..self.cols).filter(|c| !pivots.contains(c)).collect();
        free.iter()
            .map(|&f| {
                let mut x = vec![T::zero(); self.cols];
                x[f] = T::one();
                for (row, &pc) in pivots.iter().enumerate() {
                    x[pc] = r.get(row, f).neg_ref();
                }
                x
            })
            .collect()
    }

    /// A solution of `A x = b`, or `None` when the system is inconsistent. When it is
    /// under-determined the free unknowns are set to zero (see [`Matrix::nullspace`] for the rest).
    ///
    /// # Errors
    /// [`MatrixError::Shape`] when `b` has the wrong length.
    pub fn solve(&self, b: &[T]) -> Result<Option<Vec<T>>, MatrixError> {
        if b.len() != self.rows {
            return Err(MatrixError::Shape);
        }
        let mut aug = Matrix::zeros(self.rows, self.cols + 1);
        for (i, bi) in b.iter().enumerate() {
            for j in 0..self.cols {
                aug.set(i, j, self.get(i, j).clone());
            }
            aug.set(i, self.cols, bi.clone());
        }
        let (r, pivots) = aug.rref();
        if pivots.last() == Some(&self.cols) {
            return Ok(None);
        }
        let mut x = vec![T::zero(); self.cols];
        for (row, &pc) in pivots.iter().enumerate() {
            x[pc] = r.get(row, self.cols).clone();
        }
        Ok(Some(x))
    }

    /// The determinant by Gaussian elimination: the tests' independent reference for [`det`].
    ///
    /// # Errors
    /// [`MatrixError::NotSquare`].
    #[cfg(test)]
    pub(crate) fn determinant(&self) -> Result<T, MatrixError> {
        if self.rows != self.cols {
            return Err(MatrixError::NotSquare);
        }
        let mut m = self.clone();
        let mut det = T::one();
        for c in 0..m.cols {
            let Some(p) = (c..m.rows).find(|&i| !m.get(i, c).is_zero()) else {
                return Ok(T::zero());
            };
            if p != c {
                m.swap_rows(c, p);
                det = det.neg_ref();
            }
            let piv = m.get(c, c).clone();
            det *= &piv;
            let inv = match piv.inv() {
                Ok(v) => v,
                Err(_) => return Ok(T::zero()),
            };
            for i in c + 1..m.rows {
                if !m.get(i, c).is_zero() {
                    let f = m.get(i, c).mul_ref(&inv);
                    for j in c..m.cols {
                        let v = m.get(i, j).sub_ref(&f.mul_ref(m.get(c, j)));
                        m.set(i, j, v);
                    }
                }
            }
        }
        Ok(det)
    }
}

/// The determinant of a small square matrix over any ring: Laplace expansion along the first
/// row, ring operations only (no division), so it runs over polynomial rings too; it costs
/// `O(n!)` and is meant for matrices up to 4x4 (quadrics, lines of projective 3-space). The
/// workspace's one determinant. The empty matrix has determinant 1.
///
/// # Panics
/// If a row is shorter than the number of rows (the matrix must be square).
pub fn det<T: Ring>(m: &[Vec<T>]) -> T {
    match m.len() {
        0 => T::one(),
        1 => m[0][0].clone(),
        n => {
            let mut acc = T::zero();
            for j in 0..n {
                if m[0][j].is_zero() {
                    continue;
                }
                let minor: Vec<Vec<T>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|&(k, _)| k != j)
                            .map(|(_, x)| x.clone())
                            .collect()
                    })
                    .collect();
                let t = m[0][j].mul_ref(&det(&minor));
                if j % 2 == 0 {
                    acc += t;
                } else {
                    acc -= t;
                }
            }
            acc
        }
    }
}

/// The inertia of a symmetric matrix: counts of positive, negative and zero eigenvalues.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Inertia {
    /// Positive eigenvalues.
    pub positive: usize,
    /// Negative eigenvalues.
    pub negative: usize,
    /// Zero eigenvalues (the nullity).
    pub zero: usize,
}

impl<T: OrderedField> Matrix<T> {
    /// The inertia by symmetric Gaussian elimination (congruence `P^T A P`): a non-zero diagonal
    /// pivot eliminates its row and column; when every remaining diagonal entry is zero but some
    /// `a_ij` is not, adding row and column `j` to `i` makes `a_ii = 2 a_ij` non-zero.
    ///
    /// # Errors
    /// [`MatrixError::NotSquare`] or [`MatrixError::NotSymmetric`].
    pub fn inertia(&self) -> Result<Inertia, MatrixError> {
        if self.rows != self.cols {
            return Err(MatrixError::NotSquare);
        }
        let n = self.rows;
        for i in 0..n {
            for j in 0..i {
                if self.get(i, j) != self.get(j, i) {
                    return Err(MatrixError::NotSymmetric);
                }
            }
        }
        let mut m = self.clone();
        let mut active: Vec<usize> = (0..n).collect();
        let mut inertia = Inertia {
            positive: 0,
            negative: 0,
            zero: 0,
        };
        while !active.is_empty() {
            let pivot = active.iter().copied().find(|&i| !m.get(i, i).is_zero());
            let k = match pivot {
                Some(k) => k,
                None => {
                    let pair = active.iter().copied().find_map(|i| {
                        active
                            .iter()
                            .copied()
                            .find(|&j| j != i && !m.get(i, j).is_zero())
                            .map(|j| (i, j))
                    });
                    let Some((i, j)) = pair else {
                        inertia.zero += active.len();
                        break;
                    };
                    // row_i += row_j, then col_i += col_j (a congruence).
                    for c in 0..n {
                        let v = m.get(i, c).add_ref(m.get(j, c));
                        m.set(i, c, v);
                    }
                    for r in 0..n {
                        let v = m.get(r, i).add_ref(m.get(r, j));
                        m.set(r, i, v);
                    }
                    i
                }
            };
            let piv = m.get(k, k).clone();
            match piv.sign() {
                Sign::Positive => inertia.positive += 1,
                Sign::Negative => inertia.negative += 1,
                Sign::Zero => unreachable!("the pivot is non-zero"),
            }
            let inv = piv.inv().map_err(|_| MatrixError::Shape)?;
            active.retain(|&i| i != k);
            for &i in &active {
                if m.get(i, k).is_zero() {
                    continue;
                }
                let f = m.get(i, k).mul_ref(&inv);
                for &j in &active {
                    let v = m.get(i, j).sub_ref(&f.mul_ref(m.get(k, j)));
                    m.set(i, j, v);
                }
                m.set(i, k, crate::scalar::Ring::zero());
            }
            for &j in &active {
                m.set(k, j, crate::scalar::Ring::zero());
            }
        }
        Ok(inertia)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(rows: &[&[f64]]) -> Matrix<f64> {
        Matrix::from_rows(rows.iter().map(|r| r.to_vec()).collect()).unwrap()
    }

    #[test]
    fn solve_and_nullspace() {
        let a = m(&[&[1.0, 2.0, 3.0], &[2.0, 4.0, 6.0], &[1.0, 0.0, 1.0]]);
        assert_eq!(a.rank(), 2);
        let ns = a.nullspace();
        assert_eq!(ns.len(), 1);
        for i in 0..3 {
            let dot: f64 = (0..3).map(|j| a.get(i, j) * ns[0][j]).sum();
            assert_eq!(dot, 0.0);
        }
        assert_eq!(
            a.solve(&[1.0, 2.0, 1.0]).unwrap(),
            Some(vec![1.0, 0.0, 0.0])
        );
        assert_eq!(a.solve(&[1.0, 3.0, 1.0]).unwrap(), None);
        assert_eq!(a.determinant().unwrap(), 0.0);
        assert_eq!(m(&[&[2.0, 1.0], &[1.0, 3.0]]).determinant().unwrap(), 5.0);
        assert_eq!(m(&[&[0.0, 1.0], &[1.0, 0.0]]).determinant().unwrap(), -1.0);
    }

    #[test]
    fn inertia_by_congruence() {
        // x^2 + y^2 - z^2 - w^2 style forms, and a zero-diagonal hyperbolic form.
        let i = m(&[&[1.0, 0.0, 0.0], &[0.0, -2.0, 0.0], &[0.0, 0.0, 0.0]])
            .inertia()
            .unwrap();
        assert_eq!((i.positive, i.negative, i.zero), (1, 1, 1));
        let h = m(&[&[0.0, 1.0], &[1.0, 0.0]]).inertia().unwrap();
        assert_eq!((h.positive, h.negative, h.zero), (1, 1, 0));
        let d = m(&[&[2.0, 1.0], &[1.0, 2.0]]).inertia().unwrap();
        assert_eq!((d.positive, d.negative, d.zero), (2, 0, 0));
        assert_eq!(
            m(&[&[1.0, 2.0], &[3.0, 1.0]]).inertia(),
            Err(MatrixError::NotSymmetric)
        );
    }
}
