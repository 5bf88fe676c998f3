//! The multi-quadratic field: [`Radical`], its canonical form, field operations, exact sign with
//! a floating-point filter, square roots by denesting, and printing (the algorithms are explained
//! in the documentation of the parent module).

use super::radicand::{
    independent_count, integer_u64, mul_keys, square_free_big, square_free_u64, Rd,
};
use super::Radicand;
use crate::rational::Rational;
use exactcheck_core::limits::{self, LimitError};
use exactcheck_core::{Field, OrderedField, Ring, Sign, Sqrt, ZeroDivisor};
use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_rational::BigRational;
use num_traits::One;
use std::cmp::Ordering;
use std::fmt;

// ====================================================================== the number type

/// A term `c sqrt(m)`.
pub(super) type Term = (Radicand, Rational);

/// An exact multi-quadratic number `sum_m c_m sqrt(m)` (see the module documentation for the
/// canonical form). A real, totally ordered field with exact sign and square roots of the
/// elements whose roots are multi-quadratic.
///
/// ```
/// use exactcheck_core::{Field, Sqrt};
/// use exactcheck_exact::radical::Radical;
///
/// let x: Radical = "1/sqrt(2)".parse().unwrap();
/// assert_eq!(x.to_string(), "sqrt(2)/2");
/// let y: Radical = "sqrt(2) * sqrt(6)".parse().unwrap();
/// assert_eq!(y, Radical::sqrt_of(12));
/// let one_plus: Radical = "1 + sqrt(2)".parse().unwrap();
/// assert_eq!(one_plus.inv().unwrap().to_string(), "-1 + sqrt(2)");
/// let nested: Radical = "3 - 2*sqrt(2)".parse().unwrap();
/// assert_eq!(nested.sqrt().unwrap().to_string(), "-1 + sqrt(2)");
/// // An exact decision where f64 rounds both sides to the same double:
/// let s: Radical = "sqrt(2) + sqrt(3)".parse().unwrap();
/// assert!(s < "3.1462643699419726".parse().unwrap());
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Radical {
    pub(super) terms: Vec<Term>,
}

impl Radical {
    /// `sqrt(m)` for a non-negative integer, in canonical form (`sqrt(12) = 2 sqrt(3)`,
    /// `sqrt(0) = 0`). Always succeeds: every `u64` is factored completely.
    pub fn sqrt_of(m: u64) -> Radical {
        if m == 0 {
            return Radical::default();
        }
        let (s, f) = square_free_u64(m);
        Radical {
            terms: vec![(Radicand(Rd::Small(f)), integer_u64(s))],
        }
    }

    /// The non-negative square root of a rational, `sqrt(n/d) = sqrt(n d)/d`.
    ///
    /// `None` for a negative argument, and when the square-free part of the numerator or the
    /// denominator cannot be certified: a cofactor above 2^64 with no prime factor below 2^20
    /// (2^14 beyond 512 bits) that is not a perfect square. Every 64-bit value is factored
    /// completely (Miller–Rabin and Pollard's rho).
    pub fn sqrt_rational(q: &Rational) -> Option<Radical> {
        match q.signum() {
            Sign::Negative => return None,
            Sign::Zero => return Some(Radical::default()),
            Sign::Positive => {}
        }
        let n = q.numer().into_parts().1;
        let d = q.denom().into_parts().1;
        let (sn, fnum) = square_free_big(&n)?;
        let (sd, fden) = if d.is_one() {
            (BigUint::one(), Radicand::ONE)
        } else {
            square_free_big(&d)?
        };
        // sqrt(n/d) = sn sqrt(fn) / (sd sqrt(fd)) = sn sqrt(fn fd) / (sd fd); fn, fd coprime.
        let den = sd * fden.to_biguint();
        let coef = Rational::from(BigRational::new_raw(
            BigInt::from_biguint(BigSign::Plus, sn),
            BigInt::from_biguint(BigSign::Plus, den),
        ));
        Some(Radical {
            terms: vec![(fnum.mul_coprime(&fden), coef)],
        })
    }

    /// The rational coefficient of `sqrt(1)` (zero if absent).
    pub fn rational_part(&self) -> Rational {
        match self.terms.first() {
            Some((m, c)) if m.is_one() => c.clone(),
            _ => Rational::ZERO,
        }
    }

    /// Whether the value is rational (no radical term).
    pub fn is_rational(&self) -> bool {
        match self.terms.as_slice() {
            [] => true,
            [(m, _)] => m.is_one(),
            _ => false,
        }
    }

    /// The value as a rational, if it is one.
    pub fn to_rational(&self) -> Option<Rational> {
        match self.terms.as_slice() {
            [] => Some(Rational::ZERO),
            [(m, c)] if m.is_one() => Some(c.clone()),
            _ => None,
        }
    }

    /// The non-zero rational value, borrowed, if the value is a non-zero rational.
    pub(super) fn as_nonzero_rational(&self) -> Option<&Rational> {
        match self.terms.as_slice() {
            [(m, c)] if m.is_one() => Some(c),
            _ => None,
        }
    }

    /// The terms `(m, c_m)`, meaning `c_m sqrt(m)`, sorted by increasing `m`, no `c_m` zero.
    pub fn terms(&self) -> &[(Radicand, Rational)] {
        &self.terms
    }

    /// An `f64` approximation, for display only: each term is rounded and the rounded terms are
    /// summed, so the result may be far from correctly rounded (and even of the wrong sign) when
    /// terms cancel. Use [`OrderedField::sign`] and comparisons for decisions.
    ///
    /// Never NaN: a rational is correctly rounded ([`Rational::to_f64`]); otherwise the terms go
    /// through [`crate::to_f64::sum_of_roots_to_f64`], so a value beyond f64's range is `±inf`
    /// with its sign and one below it rounds towards `0` (instead of `inf - inf` or `0 * inf`).
    pub fn to_f64(&self) -> f64 {
        if let Some(q) = self.to_rational() {
            return q.to_f64();
        }
        let terms: Vec<(BigRational, BigRational)> = self
            .terms
            .iter()
            .map(|(m, c)| {
                let m = BigInt::from_biguint(BigSign::Plus, m.to_biguint());
                (c.to_big_rational(), BigRational::from_integer(m))
            })
            .collect();
        crate::to_f64::sum_of_roots_to_f64(&terms)
    }

    /// `c · self` for a rational `c`.
    pub fn scale(&self, c: &Rational) -> Radical {
        if c.is_zero() {
            return Radical::default();
        }
        if c.is_one() {
            return self.clone();
        }
        Radical {
            terms: self.terms.iter().map(|(m, x)| (m.clone(), x * c)).collect(),
        }
    }

    /// Whether the representation is canonical: radicands strictly increasing and square-free
    /// (certified for radicands below 2^64), coefficients non-zero and canonical. Always true
    /// for values built through the public API; used by the property tests.
    pub fn is_canonical(&self) -> bool {
        self.terms.windows(2).all(|w| w[0].0 < w[1].0)
            && self
                .terms
                .iter()
                .all(|(m, c)| !c.is_zero() && c.is_canonical() && m.is_square_free())
    }

    /// The number `k` of independent square roots in the value: the field generated by the
    /// square roots of its radicands has dimension `2^k` over Q (`sqrt(2) + sqrt(3) + sqrt(6)`
    /// has 2, `sqrt(6)` has 1, a rational 0). Every product of two values of counts `k1`, `k2`
    /// has at most `2^(k1 + k2)` terms, which is what [`limits::RADICANDS`] bounds.
    pub fn independent_radicals(&self) -> usize {
        independent_count(self.terms.iter().map(|(m, _)| m))
    }

    /// `Ok` when the value has at most [`limits::RADICANDS`] independent square roots
    /// ([`Radical::independent_radicals`]); cheap when it has at most that many terms.
    ///
    /// # Errors
    /// The [`LimitError`] of `radicands`.
    pub fn check_radicands(&self) -> Result<(), LimitError> {
        let max = limits::RADICANDS.get_usize();
        // At most `max` irrational terms cannot span more than `max`.
        let irrational = self.terms.iter().filter(|(m, _)| !m.is_one()).count();
        if irrational <= max {
            return Ok(());
        }
        limits::RADICANDS.check_usize(self.independent_radicals())
    }

    /// `Ok` when all of `values` together have at most [`limits::RADICANDS`] independent
    /// square roots: the size of the field a computation combining them works in (each value
    /// may be within the limit while their sum or product is not).
    ///
    /// # Errors
    /// The [`LimitError`] of `radicands`.
    pub fn check_radicands_together<'a>(
        values: impl IntoIterator<Item = &'a Radical>,
    ) -> Result<(), LimitError> {
        let all = distinct_irrational(values);
        if all.len() <= limits::RADICANDS.get_usize() {
            return Ok(());
        }
        limits::RADICANDS.check_usize(independent_count(all.into_iter()))
    }

    /// The number `k` of independent square roots of all of `values` together: a computation
    /// combining them works in a field of dimension `2^k` over Q.
    pub fn independent_radicals_together<'a>(
        values: impl IntoIterator<Item = &'a Radical>,
    ) -> usize {
        independent_count(distinct_irrational(values).into_iter())
    }

    /// The sign, decided exactly without the floating-point filter (for tests and benchmarks;
    /// [`OrderedField::sign`] gives the same answer, usually faster).
    pub fn sign_exact(&self) -> Sign {
        self.sign_rec(false)
    }

    // ------------------------------------------------------------------ kernels

    /// Canonical form of an unsorted list of terms (sorts, merges equal radicands, drops zeros).
    pub(super) fn from_unsorted(mut v: Vec<Term>) -> Radical {
        v.sort_by(|a, b| a.0.cmp(&b.0));
        let mut out: Vec<Term> = Vec::with_capacity(v.len());
        for (m, c) in v {
            match out.last_mut() {
                Some((lm, lc)) if *lm == m => *lc += c,
                _ => out.push((m, c)),
            }
        }
        out.retain(|(_, c)| !c.is_zero());
        Radical { terms: out }
    }

    /// `lhs ± rhs` by merging the sorted term lists; `lhs` is consumed (its terms are moved).
    pub(super) fn add_terms(lhs: Vec<Term>, rhs: &[Term], negate: bool) -> Radical {
        let signed = |c: &Rational| if negate { -c } else { c.clone() };
        if rhs.is_empty() {
            return Radical { terms: lhs };
        }
        let mut out = Vec::with_capacity(lhs.len() + rhs.len());
        let mut left = lhs.into_iter();
        let mut a = left.next();
        let mut j = 0;
        while let Some((am, ac)) = a.take() {
            let Some((bm, bc)) = rhs.get(j) else {
                out.push((am, ac));
                break;
            };
            match am.cmp(bm) {
                Ordering::Less => {
                    out.push((am, ac));
                    a = left.next();
                }
                Ordering::Greater => {
                    out.push((bm.clone(), signed(bc)));
                    j += 1;
                    a = Some((am, ac));
                }
                Ordering::Equal => {
                    let s = if negate { ac - bc } else { ac + bc };
                    if !s.is_zero() {
                        out.push((am, s));
                    }
                    j += 1;
                    a = left.next();
                }
            }
        }
        out.extend(left);
        out.extend(rhs[j..].iter().map(|(m, c)| (m.clone(), signed(c))));
        Radical { terms: out }
    }

    pub(super) fn mul_impl(&self, rhs: &Radical) -> Radical {
        if self.terms.is_empty() || rhs.terms.is_empty() {
            return Radical::default();
        }
        if let Some(c) = rhs.as_nonzero_rational() {
            return self.scale(c);
        }
        if let Some(c) = self.as_nonzero_rational() {
            return rhs.scale(c);
        }
        let mut v = Vec::with_capacity(self.terms.len() * rhs.terms.len());
        for (m1, c1) in &self.terms {
            for (m2, c2) in &rhs.terms {
                let (g, m) = mul_keys(m1, m2);
                let c = c1 * c2;
                v.push((m, if g.is_one() { c } else { c * g.to_rational() }));
            }
        }
        Radical::from_unsorted(v)
    }

    pub(super) fn square_impl(&self) -> Radical {
        if let Some(c) = self.as_nonzero_rational() {
            return Radical::from(c.square());
        }
        let t = &self.terms;
        let mut v = Vec::with_capacity(t.len() * (t.len() + 1) / 2);
        let two = Rational::from_integer(2);
        for (i, (m1, c1)) in t.iter().enumerate() {
            // (c sqrt m)^2 = c^2 m
            v.push((Radicand::ONE, c1.square() * m1.to_rational()));
            for (m2, c2) in &t[i + 1..] {
                let (g, m) = mul_keys(m1, m2);
                let c = c1 * c2 * &two;
                v.push((m, if g.is_one() { c } else { c * g.to_rational() }));
            }
        }
        Radical::from_unsorted(v)
    }

    /// An integer `q > 1` that divides or is coprime to every radicand present (`None` for a
    /// rational value). It divides at least one radicand.
    pub(super) fn pick_generator(&self) -> Option<Radicand> {
        let mut q = self
            .terms
            .iter()
            .map(|t| &t.0)
            .find(|m| !m.is_one())?
            .clone();
        'refine: loop {
            for (m, _) in &self.terms {
                if m.is_one() {
                    continue;
                }
                let g = q.gcd(m);
                if !g.is_one() && g != q {
                    q = g;
                    continue 'refine;
                }
            }
            return Some(q);
        }
    }

    /// `self = a + b sqrt(q)` with `a`, `b` free of `sqrt(q)` (for `q` from `pick_generator`).
    pub(super) fn split(&self, q: &Radicand) -> (Radical, Radical) {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for (m, c) in &self.terms {
            if q.divides(m) {
                b.push((m.div_exact(q), c.clone()));
            } else {
                a.push((m.clone(), c.clone()));
            }
        }
        // Division by a common divisor keeps the order: both lists stay sorted.
        (Radical { terms: a }, Radical { terms: b })
    }

    /// `self · sqrt(q)` for a `self` whose radicands are all coprime to `q`.
    pub(super) fn mul_sqrt_coprime(mut self, q: &Radicand) -> Radical {
        for (m, _) in &mut self.terms {
            *m = m.mul_coprime(q);
        }
        // Multiplication by a common factor keeps the order.
        self
    }

    /// The norm `a^2 - q b^2` of `a + b sqrt q`.
    pub(super) fn norm(a: &Radical, b: &Radical, q: &Radicand) -> Radical {
        a.square_impl() - b.square_impl().scale(&q.to_rational())
    }

    pub(super) fn inv_impl(&self) -> Result<Radical, ZeroDivisor> {
        match self.terms.as_slice() {
            [] => Err(ZeroDivisor),
            // 1/(c sqrt m) = sqrt(m) / (c m)
            [(m, c)] => Ok(Radical {
                terms: vec![(m.clone(), (c * m.to_rational()).recip()?)],
            }),
            _ => {
                let q = self.pick_generator().ok_or(ZeroDivisor)?;
                let (a, b) = self.split(&q);
                let n_inv = Radical::norm(&a, &b, &q).inv_impl()?;
                let conj = a - b.mul_sqrt_coprime(&q);
                Ok(conj.mul_impl(&n_inv))
            }
        }
    }

    /// A floating-point sign filter: `Some(sign)` when the f64 evaluation is farther from zero
    /// than a rigorous bound on its error, `None` when it cannot decide.
    ///
    /// Each term `c sqrt(m)` is evaluated from correctly rounded conversions of the numerator,
    /// denominator and radicand (all below 2^1000, so no overflow or underflow), then a
    /// division, a square root and a product: a relative error below `8 u` (`u = 2^-53`), bounded
    /// here by `2^-48`. Summing `k` terms adds at most `k u` times the sum of their magnitudes.
    /// The decision threshold `(2^-46 + k 2^-51) sum |t_i|` is four times larger than that.
    pub(super) fn sign_filter(&self) -> Option<Sign> {
        let (mut sum, mut mag) = (0.0f64, 0.0f64);
        for (m, c) in &self.terms {
            // Correctly rounded (no allocation for inline values); a huge or tiny value is
            // rejected below as not normal.
            let cf = c.to_f64();
            let t = if m.is_one() {
                cf
            } else {
                cf * m.to_f64_checked()?.sqrt()
            };
            if !t.is_normal() {
                return None;
            }
            sum += t;
            mag += t.abs();
        }
        let k = self.terms.len() as f64;
        let err = (2f64.powi(-46) + k * 2f64.powi(-51)) * mag;
        if sum > err {
            Some(Sign::Positive)
        } else if sum < -err {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    pub(super) fn sign_rec(&self, filtered: bool) -> Sign {
        let first = match self.terms.as_slice() {
            [] => return Sign::Zero,
            [(_, c)] => return c.signum(),
            [(_, c), ..] => c.signum(),
        };
        if self.terms.iter().all(|(_, c)| c.signum() == first) {
            return first;
        }
        if filtered {
            if let Some(s) = self.sign_filter() {
                return s;
            }
        }
        let Some(q) = self.pick_generator() else {
            return first; // unreachable: two or more terms include an irrational one
        };
        let (a, b) = self.split(&q);
        let (sa, sb) = (a.sign_rec(filtered), b.sign_rec(filtered));
        match (sa, sb) {
            (_, Sign::Zero) => sa,
            (Sign::Zero, _) => sb,
            _ if sa == sb => sa,
            // a and b sqrt q of opposite signs: |a| vs |b| sqrt q is decided by a^2 vs q b^2.
            _ => Radical::norm(&a, &b, &q).sign_rec(filtered) * sa,
        }
    }

    pub(super) fn sqrt_impl(&self) -> Option<Radical> {
        if self.terms.is_empty() {
            return Some(Radical::default());
        }
        if let Some(c) = self.as_nonzero_rational() {
            return Radical::sqrt_rational(c);
        }
        if self.sign_rec(true) != Sign::Positive {
            return None;
        }
        let q = self.pick_generator()?;
        let (a, b) = self.split(&q);
        let n = Radical::norm(&a, &b, &q).sqrt_impl()?;
        // The root of the norm must lie in the field of a and b (radicands built from their
        // primes only); otherwise sqrt(self) is not multi-quadratic (see the module docs).
        let mut l = Radicand::ONE;
        for (m, _) in a.terms.iter().chain(b.terms.iter()) {
            let g = l.gcd(m);
            l = l.mul_coprime(&m.div_exact(&g));
        }
        if !n.terms.iter().all(|(k, _)| k.divides(&l)) {
            return None;
        }
        let half = Rational::new(1, 2).ok()?;
        let u = (&a + &n).scale(&half).sqrt_impl()?;
        let v = (&a - &n).scale(&half).sqrt_impl()?;
        let y = if b.sign_rec(true) == Sign::Negative {
            u - v
        } else {
            u + v
        };
        (y.sign_rec(true) != Sign::Negative && y.square_impl() == *self).then_some(y)
    }

    // ------------------------------------------------------------------ operator bodies

    pub(super) fn add_owned(self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms, &rhs.terms, false)
    }
    pub(super) fn add_borrowed(&self, rhs: &Radical) -> Radical {
        if self.terms.len() < rhs.terms.len() {
            Radical::add_terms(rhs.terms.clone(), &self.terms, false)
        } else {
            Radical::add_terms(self.terms.clone(), &rhs.terms, false)
        }
    }
    pub(super) fn sub_owned(self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms, &rhs.terms, true)
    }
    pub(super) fn sub_borrowed(&self, rhs: &Radical) -> Radical {
        Radical::add_terms(self.terms.clone(), &rhs.terms, true)
    }
    pub(super) fn mul_owned(self, rhs: &Radical) -> Radical {
        self.mul_impl(rhs)
    }
    pub(super) fn mul_borrowed(&self, rhs: &Radical) -> Radical {
        self.mul_impl(rhs)
    }
    pub(super) fn div_owned(self, rhs: &Radical) -> Radical {
        self.div_borrowed(rhs)
    }
    pub(super) fn div_borrowed(&self, rhs: &Radical) -> Radical {
        match rhs.inv_impl() {
            Ok(r) => self.mul_impl(&r),
            Err(_) => panic!("Radical division by zero (use Field::checked_div to handle it)"),
        }
    }
    pub(super) fn neg_borrowed(&self) -> Radical {
        Radical {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }
    pub(super) fn neg_in_place(mut self) -> Radical {
        for (_, c) in &mut self.terms {
            *c = -std::mem::take(c);
        }
        self
    }
}

// ====================================================================== scalar traits

impl Ring for Radical {
    fn zero() -> Self {
        Radical::default()
    }
    fn one() -> Self {
        Radical::from(Rational::ONE)
    }
    fn from_i64(n: i64) -> Self {
        Radical::from(Rational::from_integer(n))
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    fn is_one(&self) -> bool {
        self.as_nonzero_rational().is_some_and(|c| c.is_one())
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_borrowed(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_borrowed(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        -self
    }
    fn square(&self) -> Self {
        self.square_impl()
    }
}

impl Field for Radical {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        self.inv_impl()
    }
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        Ok(self.mul_impl(&rhs.inv_impl()?))
    }
}

impl OrderedField for Radical {
    fn sign(&self) -> Sign {
        self.sign_rec(true)
    }
}

impl PartialOrd for Radical {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Radical {
    /// The exact numeric order (the sign of the difference).
    fn cmp(&self, other: &Self) -> Ordering {
        if let (Some(a), Some(b)) = (self.to_rational(), other.to_rational()) {
            return a.cmp(&b);
        }
        match self.sub_borrowed(other).sign_rec(true) {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }
}

impl Sqrt for Radical {
    /// The non-negative square root when it is multi-quadratic: `sqrt(8) = 2 sqrt(2)`,
    /// `sqrt(3 - 2 sqrt(2)) = sqrt(2) - 1`, `sqrt(2 + sqrt(3)) = (sqrt(2) + sqrt(6))/2`; `None`
    /// for negative values, for values such as `sqrt(2)` whose root is not multi-quadratic, and
    /// for rationals whose factorization is out of reach (see [`Radical::sqrt_rational`]).
    fn sqrt(&self) -> Option<Self> {
        self.sqrt_impl()
    }
}

impl From<Rational> for Radical {
    fn from(q: Rational) -> Self {
        if q.is_zero() {
            Radical::default()
        } else {
            Radical {
                terms: vec![(Radicand::ONE, q)],
            }
        }
    }
}

impl From<&Rational> for Radical {
    fn from(q: &Rational) -> Self {
        Radical::from(q.clone())
    }
}

impl From<i64> for Radical {
    fn from(n: i64) -> Self {
        Radical::from(Rational::from_integer(n))
    }
}

// ====================================================================== printing

/// Writes `|c| sqrt(m)` as `n`, `n/d`, `sqrt(m)`, `n*sqrt(m)`, `sqrt(m)/d` or `n*sqrt(m)/d`.
pub(super) fn write_abs_term(
    f: &mut fmt::Formatter<'_>,
    m: &Radicand,
    c: &Rational,
) -> fmt::Result {
    let n = c.numer().into_parts().1;
    let d = c.denom().into_parts().1;
    if m.is_one() {
        write!(f, "{n}")?;
    } else {
        if !n.is_one() {
            write!(f, "{n}*")?;
        }
        m.write_sqrt(f)?;
    }
    if !d.is_one() {
        write!(f, "/{d}")?;
    }
    Ok(())
}

impl fmt::Display for Radical {
    /// The exact number syntax (docs/solve.md), terms by increasing radicand:
    /// `1/2 + 3*sqrt(2) - sqrt(6)/3`; `0` for zero. [`FromStr`](std::str::FromStr) reads it back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return f.write_str("0");
        }
        for (i, (m, c)) in self.terms.iter().enumerate() {
            let negative = c.signum() == Sign::Negative;
            match (i, negative) {
                (0, true) => f.write_str("-")?,
                (0, false) => {}
                (_, true) => f.write_str(" - ")?,
                (_, false) => f.write_str(" + ")?,
            }
            write_abs_term(f, m, c)?;
        }
        Ok(())
    }
}

impl Radical {
    /// The number over one common denominator: `(2*sqrt(2) + sqrt(6))/3` where `Display` writes
    /// `2*sqrt(2)/3 + sqrt(6)/3`. The denominator `D` is the lcm of the coefficients'
    /// denominators; with one term, or `D = 1`, this is `Display`. Parses back to the same value.
    pub fn to_string_over_common_denominator(&self) -> String {
        use num_integer::Integer;
        if self.terms.len() < 2 {
            return self.to_string();
        }
        let d = self
            .terms
            .iter()
            .fold(BigInt::one(), |acc, (_, c)| acc.lcm(&c.denom()));
        if d.is_one() {
            return self.to_string();
        }
        format!("({})/{d}", self.scale(&Rational::from(d.clone())))
    }
}

impl fmt::Debug for Radical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// The distinct irrational radicands of the terms of `values`, sorted.
fn distinct_irrational<'a>(values: impl IntoIterator<Item = &'a Radical>) -> Vec<&'a Radicand> {
    let mut all: Vec<&Radicand> = values
        .into_iter()
        .flat_map(|v| v.terms.iter().map(|(m, _)| m))
        .filter(|m| !m.is_one())
        .collect();
    all.sort();
    all.dedup();
    all
}
