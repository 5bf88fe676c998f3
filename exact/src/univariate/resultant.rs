//! Resultants of univariate polynomials and interpolation: the elimination step of algebraic
//! number arithmetic ([`crate::algebraic`]), where the polynomial of `alpha + beta` is
//! `Res_y(f(y), g(x - y))`, a polynomial in `x` found by evaluating the resultant at integer
//! points and interpolating.

use super::UPoly;
use crate::Rational;
use exactcheck_core::Ring;

impl UPoly {
    /// The resultant `Res(self, other) = lc(self)^n * prod other(a_i)` over the roots `a_i` of
    /// `self` (degree `m`; `n` the degree of `other`), computed by the Euclidean algorithm over Q
    /// with `Res(A, B) = (-1)^(mn) lc(B)^(m - r) Res(B, A mod B)` (`r` the degree of the
    /// remainder). Zero when either polynomial is zero or they have a common root; for a
    /// non-zero constant `c`, `Res(A, c) = c^m` and `Res(c, B) = c^n`.
    pub fn resultant(&self, other: &UPoly) -> Rational {
        if self.is_zero() || other.is_zero() {
            return Rational::ZERO;
        }
        let (mut a, mut b) = (self.clone(), other.clone());
        let mut acc = Rational::ONE;
        loop {
            let (m, n) = (a.degree(), b.degree());
            if n == 0 {
                return acc * b.leading_coefficient().pow(m as u32);
            }
            if m == 0 {
                return acc * a.leading_coefficient().pow(n as u32);
            }
            let r = a.rem(&b);
            if r.is_zero() {
                return Rational::ZERO;
            }
            let lb = b.leading_coefficient().pow((m - r.degree()) as u32);
            acc = if (m * n) % 2 == 1 {
                -(acc * lb)
            } else {
                acc * lb
            };
            a = b;
            b = r;
        }
    }

    /// The polynomial of degree below `points.len()` through the given points (distinct
    /// abscissae), by Newton's divided differences.
    ///
    /// # Panics
    /// When two abscissae are equal.
    pub fn interpolate(points: &[(Rational, Rational)]) -> UPoly {
        let n = points.len();
        let mut dd: Vec<Rational> = points.iter().map(|(_, y)| y.clone()).collect();
        for j in 1..n {
            for i in (j..n).rev() {
                let num = dd[i].sub_ref(&dd[i - 1]);
                let den = points[i].0.sub_ref(&points[i - j].0);
                dd[i] = num
                    .checked_div(&den)
                    .expect("interpolation needs distinct abscissae");
            }
        }
        let mut acc = UPoly::zero();
        for i in (0..n).rev() {
            let factor = UPoly::from_coeffs(vec![-points[i].0.clone(), Rational::ONE]);
            acc = acc
                .mul_impl(&factor)
                .add_impl(&UPoly::constant(dd[i].clone()));
        }
        acc
    }

    /// The reversed polynomial `x^m self(1/x)` (`m` the degree): its roots are the inverses of
    /// the non-zero roots of `self`.
    pub fn reversed(&self) -> UPoly {
        let mut c = self.coeffs.clone();
        c.reverse();
        UPoly::from_coeffs(c)
    }
}
