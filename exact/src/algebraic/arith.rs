//! Arithmetic of [`Algebraic`] numbers: resultants for sums and products, substitutions for
//! Moebius maps and square roots, and the selection of the root the result is among the roots
//! of the new polynomial.

use super::Algebraic;
use crate::univariate::{RootInterval, UPoly};
use crate::Rational;
use exactcheck_core::{Ring, Sign};
use num_bigint::BigInt;

// ------------------------------------------------------------------------------ intervals

/// A closed rational interval `[lo, hi]`.
pub(super) type Iv = (Rational, Rational);

pub(super) fn iv_add(a: &Iv, b: &Iv) -> Iv {
    (a.0.add_ref(&b.0), a.1.add_ref(&b.1))
}

pub(super) fn iv_mul(a: &Iv, b: &Iv) -> Iv {
    let p = [
        a.0.mul_ref(&b.0),
        a.0.mul_ref(&b.1),
        a.1.mul_ref(&b.0),
        a.1.mul_ref(&b.1),
    ];
    let lo = p.iter().min().expect("four products").clone();
    let hi = p.iter().max().expect("four products").clone();
    (lo, hi)
}

/// Rational bounds `l <= q^(1/n) <= u` of a non-negative `q` with `u - l <= 2^-bits` (times
/// the denominator's effect, as [`sqrt_bounds`]); `(0, 0)` for `q <= 0`.
fn nth_root_bounds(q: &Rational, n: u32, bits: u32) -> Iv {
    if q.signum() != Sign::Positive {
        return (Rational::ZERO, Rational::ZERO);
    }
    // (a/d)^(1/n) = (a d^(n-1) 2^(n bits))^(1/n) / (d 2^bits)
    let (a, d) = (q.numer(), q.denom());
    let scaled: BigInt = (&a * num_traits::Pow::pow(&d, n - 1)) << (n as usize * bits as usize);
    let r = scaled.nth_root(n);
    let den = Rational::from(d << bits as usize)
        .recip()
        .expect("a denominator is not zero");
    let lo = Rational::from(r.clone()) * &den;
    let hi = if num_traits::Pow::pow(&r, n) == scaled {
        lo.clone()
    } else {
        Rational::from(r + 1) * &den
    };
    (lo, hi)
}

/// `1/[lo, hi]`, `None` when the interval contains 0.
fn iv_inv(a: &Iv) -> Option<Iv> {
    if a.0.signum() == Sign::Positive || a.1.signum() == Sign::Negative {
        Some((a.1.recip().ok()?, a.0.recip().ok()?))
    } else {
        None
    }
}

/// Rational bounds `l <= sqrt(q) <= u` with `u - l <= 2^-bits * (1 + 1/denominator)`.
fn sqrt_bounds(q: &Rational, bits: u32) -> Iv {
    if q.signum() != Sign::Positive {
        return (Rational::ZERO, Rational::ZERO.max(q.clone()));
    }
    // sqrt(n/d) = sqrt(n d 4^bits) / (d 2^bits)
    let (n, d) = (q.numer(), q.denom());
    let scaled: BigInt = (&n * &d) << (2 * bits as usize);
    let r = scaled.sqrt();
    let den = Rational::from(d << bits as usize)
        .recip()
        .expect("a denominator is not zero");
    let lo = Rational::from(r.clone()) * &den;
    let hi = if &r * &r == scaled {
        lo.clone()
    } else {
        Rational::from(r + 1) * &den
    };
    (lo, hi)
}

// ------------------------------------------------------------------------------ polynomials

/// The rational roots of the square-free `f` divided out, keeping the other roots.
fn without_rational_roots(f: &UPoly, roots: &[RootInterval]) -> UPoly {
    let mut g = f.clone();
    for r in roots.iter().filter(|r| r.is_exact()) {
        g = g
            .div_rem(&UPoly::from_coeffs(vec![-r.lo.clone(), Rational::ONE]))
            .0;
    }
    g.primitive_part()
}

/// `p` made primitive with a positive leading coefficient.
pub(super) fn normalise(p: &UPoly) -> UPoly {
    let p = p.primitive_part();
    if p.leading_coefficient().signum() == Sign::Negative {
        -p
    } else {
        p
    }
}

/// The polynomial whose roots are the squares of the roots of `f` (Graeffe's step:
/// `f(x) f(-x) = h(x^2)`).
fn graeffe(f: &UPoly) -> UPoly {
    let minus_x = UPoly::from_coeffs(vec![Rational::ZERO, -Rational::ONE]);
    let prod = f.mul_ref(&f.compose(&minus_x));
    UPoly::from_coeffs(prod.coeffs().iter().step_by(2).cloned().collect())
}

/// The non-negative rational square root of `q`, if `q` is the square of a rational.
pub(super) fn rational_sqrt(q: &Rational) -> Option<Rational> {
    crate::coefficient::Coefficient::try_sqrt(q)
}

impl Algebraic {
    /// The number isolated by `ri` among the roots of the square-free `f` (whose isolated real
    /// roots are `roots`, exact exactly for the rational ones): rational roots divided out and,
    /// unless `f` is known to be irreducible, `f` replaced by its one irreducible factor with a
    /// root in the interval (the interval isolates one root of `f`, so exactly one factor has
    /// it), which is then the minimal polynomial. When factoring gives up (a recombination past
    /// the `factor-combinations` limit) `f` stays, square-free and marked not minimal: every
    /// later decision is exact all the same, and a number field over it is refused
    /// ([`Algebraic::checked_minimal_polynomial`]).
    pub(super) fn from_isolated(
        f: UPoly,
        ri: RootInterval,
        roots: &[RootInterval],
        minimal: bool,
    ) -> Algebraic {
        if ri.is_exact() {
            return Algebraic::from_rational(ri.lo);
        }
        let mut f = normalise(&without_rational_roots(&f, roots));
        let mut minimal = minimal || f.degree() <= 3;
        if !minimal {
            if let Ok(factors) = f.irreducible_factors() {
                f = factors
                    .into_iter()
                    .find(|g| super::has_root_in(g, &ri))
                    .map(|g| normalise(&g))
                    .expect("one irreducible factor has the isolated root");
                minimal = true;
            }
        }
        Algebraic {
            poly: f,
            iv: ri,
            minimal,
        }
    }

    /// The root of the non-zero `f` that lies in every enclosure `enclose(bits)` (each a closed
    /// interval containing it, shrinking to it as `bits` grows; `None` when the enclosure at that
    /// precision is not available, e.g. a divisor interval containing 0).
    pub(super) fn select(
        f: &UPoly,
        minimal: bool,
        mut enclose: impl FnMut(u32) -> Option<Iv>,
    ) -> Algebraic {
        let f = normalise(&f.square_free_part());
        let roots = f.isolate_roots();
        let mut bits = 8;
        loop {
            if let Some((lo, hi)) = enclose(bits) {
                let mut meets = roots.iter().filter(|r| {
                    if r.is_exact() {
                        lo <= r.lo && r.lo <= hi
                    } else {
                        r.lo < hi && lo < r.hi
                    }
                });
                let first = meets.next();
                if let (Some(r), None) = (first, meets.next()) {
                    return Algebraic::from_isolated(f.clone(), r.clone(), &roots, minimal);
                }
                // No candidate cannot happen for a true enclosure of a root of f.
                debug_assert!(first.is_some(), "the enclosure misses every root");
            }
            bits = bits.saturating_mul(2);
        }
    }

    /// `-self`: the polynomial `f(-x)`.
    pub(super) fn neg_impl(&self) -> Algebraic {
        if let Some(q) = self.to_rational() {
            return Algebraic::from_rational(-q.clone());
        }
        let minus_x = UPoly::from_coeffs(vec![Rational::ZERO, -Rational::ONE]);
        Algebraic {
            poly: normalise(&self.poly.compose(&minus_x)),
            iv: RootInterval {
                lo: -self.iv.hi.clone(),
                hi: -self.iv.lo.clone(),
            },
            minimal: self.minimal,
        }
    }

    /// The Moebius image `(a x + b) / (c x + d)` of `x = self`, for `ad - bc != 0` and
    /// `c x + d != 0`: the polynomial `(c t - a)^n f((b - d t)/(c t - a))` (of the same degree,
    /// irreducible when `f` is), and the root selected by interval arithmetic.
    ///
    /// # Panics
    /// When `ad - bc = 0` or `c self + d = 0`.
    pub fn mobius(&self, a: &Rational, b: &Rational, c: &Rational, d: &Rational) -> Algebraic {
        assert!(
            a.mul_ref(d) != b.mul_ref(c),
            "a Moebius map needs ad - bc != 0"
        );
        if let Some(q) = self.to_rational() {
            let den = c.mul_ref(q).add_ref(d);
            let num = a.mul_ref(q).add_ref(b);
            return Algebraic::from_rational(
                num.checked_div(&den)
                    .expect("the Moebius map is defined at the number"),
            );
        }
        // t = (a x + b)/(c x + d)  <=>  x = (b - d t)/(c t - a).
        let num = UPoly::from_coeffs(vec![b.clone(), -d.clone()]);
        let den = UPoly::from_coeffs(vec![-a.clone(), c.clone()]);
        let n = self.poly.degree();
        let mut g = UPoly::zero();
        let mut num_pow = UPoly::one();
        let mut den_pows = vec![UPoly::one()];
        for _ in 0..n {
            let next = den_pows.last().expect("non-empty").mul_ref(&den);
            den_pows.push(next);
        }
        for k in 0..=n {
            g = g.add_ref(&(num_pow.mul_ref(&den_pows[n - k]) * &self.poly.coeff(k)));
            num_pow = num_pow.mul_ref(&num);
        }
        let (a, b, c, d) = (a.clone(), b.clone(), c.clone(), d.clone());
        Algebraic::select(&g, self.minimal, |bits| {
            let x = self.enclosure(bits);
            let numer = iv_add(
                &iv_mul(&(a.clone(), a.clone()), &x),
                &(b.clone(), b.clone()),
            );
            let denom = iv_add(
                &iv_mul(&(c.clone(), c.clone()), &x),
                &(d.clone(), d.clone()),
            );
            Some(iv_mul(&numer, &iv_inv(&denom)?))
        })
    }

    /// `self + rhs`: `Res_t(f(t), g(x - t))`.
    pub(super) fn add_impl(&self, rhs: &Algebraic) -> Algebraic {
        let one = Rational::ONE;
        let zero = Rational::ZERO;
        match (self.to_rational(), rhs.to_rational()) {
            (Some(p), Some(q)) => return Algebraic::from_rational(p.add_ref(q)),
            (Some(q), None) => return rhs.mobius(&one, q, &zero, &one),
            (None, Some(q)) => return self.mobius(&one, q, &zero, &one),
            (None, None) if self.poly == rhs.poly && self.iv == rhs.iv => {
                let two = Rational::from_integer(2);
                return self.mobius(&two, &zero, &zero, &one);
            }
            (None, None) => {}
        }
        let n = self.poly.degree() * rhs.poly.degree();
        let points: Vec<(Rational, Rational)> = (0..=n as i64)
            .map(|c| {
                // g(c - t) as a polynomial in t.
                let c = Rational::from_integer(c);
                let shifted = rhs
                    .poly
                    .compose(&UPoly::from_coeffs(vec![c.clone(), -Rational::ONE]));
                (c, self.poly.resultant(&shifted))
            })
            .collect();
        let r = UPoly::interpolate(&points);
        Algebraic::select(&r, false, |bits| {
            Some(iv_add(&self.enclosure(bits), &rhs.enclosure(bits)))
        })
    }

    /// `self * rhs`: `Res_t(f(t), t^n g(x / t))`.
    pub(super) fn mul_impl(&self, rhs: &Algebraic) -> Algebraic {
        let zero = Rational::ZERO;
        let one = Rational::ONE;
        match (self.to_rational(), rhs.to_rational()) {
            (Some(p), Some(q)) => return Algebraic::from_rational(p.mul_ref(q)),
            (Some(q), None) | (None, Some(q)) if q.is_zero() => return Algebraic::zero(),
            (Some(q), None) => return rhs.mobius(q, &zero, &zero, &one),
            (None, Some(q)) => return self.mobius(q, &zero, &zero, &one),
            (None, None) if self.poly == rhs.poly && self.iv == rhs.iv => {
                return self.square_impl()
            }
            (None, None) => {}
        }
        let m = rhs.poly.degree();
        let n = self.poly.degree() * m;
        let points: Vec<(Rational, Rational)> = (0..=n as i64)
            .map(|c| {
                let c = Rational::from_integer(c);
                // sum_k g_k c^k t^(m - k)
                let mut coeffs = vec![Rational::ZERO; m + 1];
                let mut cp = Rational::ONE;
                for (k, slot) in (0..=m).zip(coeffs.iter_mut().rev()) {
                    *slot = rhs.poly.coeff(k).mul_ref(&cp);
                    cp = cp.mul_ref(&c);
                }
                (c.clone(), self.poly.resultant(&UPoly::from_coeffs(coeffs)))
            })
            .collect();
        let r = UPoly::interpolate(&points);
        Algebraic::select(&r, false, |bits| {
            Some(iv_mul(&self.enclosure(bits), &rhs.enclosure(bits)))
        })
    }

    /// `self^2` by Graeffe's step (the degree does not grow, unlike a product by resultant).
    pub(super) fn square_impl(&self) -> Algebraic {
        if let Some(q) = self.to_rational() {
            return Algebraic::from_rational(q.mul_ref(q));
        }
        Algebraic::select(&graeffe(&self.poly), false, |bits| {
            Some(self.square_enclosure(bits))
        })
    }

    /// An interval containing `self^2`, from the enclosure of `self` at `bits`.
    pub(super) fn square_enclosure(&self, bits: u32) -> Iv {
        let (lo, hi) = self.enclosure(bits);
        let (l2, h2) = (lo.mul_ref(&lo), hi.mul_ref(&hi));
        if lo.signum() == Sign::Positive {
            (l2, h2)
        } else if hi.signum() == Sign::Negative {
            (h2, l2)
        } else {
            (Rational::ZERO, l2.max(h2))
        }
    }

    /// The positive root of index `n` of the positive irrational (or not perfect-power)
    /// `self`: the positive root of `f(x^n)`, selected by the bounds of the root of index `n` of
    /// the enclosure.
    pub(super) fn nth_root_positive(&self, n: u32) -> Algebraic {
        let mut coeffs = vec![Rational::ZERO; n as usize + 1];
        coeffs[n as usize] = Rational::ONE;
        let g = self.poly.compose(&UPoly::from_coeffs(coeffs));
        Algebraic::select(&g, false, |bits| {
            let (lo, hi) = self.enclosure(bits);
            let l = nth_root_bounds(&lo, n, bits / n + 2).0;
            let h = nth_root_bounds(&hi, n, bits / n + 2).1;
            Some((l, h))
        })
    }

    /// The positive square root of the positive `self`: the positive root of `f(x^2)`.
    pub(super) fn sqrt_positive(&self) -> Algebraic {
        if let Some(q) = self.to_rational() {
            if let Some(r) = rational_sqrt(q) {
                return Algebraic::from_rational(r);
            }
        }
        let x2 = UPoly::from_coeffs(vec![Rational::ZERO, Rational::ZERO, Rational::ONE]);
        let g = self.poly.compose(&x2);
        Algebraic::select(&g, false, |bits| {
            let (lo, hi) = self.enclosure(bits);
            let l = sqrt_bounds(&lo, bits / 2 + 1).0;
            let h = sqrt_bounds(&hi, bits / 2 + 1).1;
            Some((l, h))
        })
    }
}
