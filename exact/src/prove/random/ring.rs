//! The values an expression tree is evaluated in by the randomized identity test, and the one
//! evaluator ([`eval`]) for all of them:
//! * residues modulo the random prime `p` ([`PrimeField`]), for identities over Q;
//! * the quotient ring `F_p[c]/(m mod p)` ([`QuotientRing`]) when the identity has algebraic
//!   constants, `m` the minimal polynomial of the primitive element `c` of their field: the
//!   image of `Z[c]/(m)` modulo `p`, defined for every prime not dividing the leading
//!   coefficient of `m`, whether or not `m` has a root modulo `p`;
//! * the number field `Q(theta)` itself ([`ExactField`]) or Q ([`Rationals`]), to confirm a
//!   counter-example exactly at a rational point.
//!
//! The quotient ring's arithmetic (products reduced modulo the monic image of `m`, inverses by
//! the extended Euclidean algorithm over `F_p`) is a few loops over `u64` coefficient vectors,
//! written here because the workspace's polynomial types are over Q and the test needs residues
//! of a modulus drawn at run time.

use crate::algebraic::NumberField;
use crate::expr::{AddOp, Expr, ExprKind, MulOp};
use crate::modp::PrimeField;
use crate::univariate::UPoly;
use crate::Rational;
use exactcheck_core::Ring;
use num_bigint::BigInt;
use std::collections::HashMap;

/// A commutative ring a tree is evaluated in.
pub(crate) trait Values {
    /// An element.
    type V: Clone;
    /// The image of a rational number; `None` when its denominator is not invertible.
    fn number(&self, q: &Rational) -> Option<Self::V>;
    /// `a + b`.
    fn add(&self, a: &Self::V, b: &Self::V) -> Self::V;
    /// `a - b`.
    fn sub(&self, a: &Self::V, b: &Self::V) -> Self::V;
    /// `a b`.
    fn mul(&self, a: &Self::V, b: &Self::V) -> Self::V;
    /// `-a`.
    fn neg(&self, a: &Self::V) -> Self::V;
    /// `a^-1`, `None` when `a` is not a unit.
    fn inv(&self, a: &Self::V) -> Option<Self::V>;
    /// Whether `a` is zero.
    fn is_zero(&self, a: &Self::V) -> bool;
    /// `a^k`, by repeated squaring.
    fn pow(&self, a: &Self::V, mut k: u64) -> Self::V {
        let mut acc = self.number(&Rational::ONE).expect("1 is a unit");
        let mut base = a.clone();
        while k > 0 {
            if k & 1 == 1 {
                acc = self.mul(&acc, &base);
            }
            k >>= 1;
            if k > 0 {
                base = self.mul(&base, &base);
            }
        }
        acc
    }
}

impl Values for PrimeField {
    type V = u64;
    fn number(&self, q: &Rational) -> Option<u64> {
        self.from_rational(q).ok()
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        PrimeField::add(self, *a, *b)
    }
    fn sub(&self, a: &u64, b: &u64) -> u64 {
        PrimeField::sub(self, *a, *b)
    }
    fn mul(&self, a: &u64, b: &u64) -> u64 {
        PrimeField::mul(self, *a, *b)
    }
    fn neg(&self, a: &u64) -> u64 {
        PrimeField::neg(self, *a)
    }
    fn inv(&self, a: &u64) -> Option<u64> {
        PrimeField::inv(self, *a).ok()
    }
    fn is_zero(&self, a: &u64) -> bool {
        *a == 0
    }
    fn pow(&self, a: &u64, k: u64) -> u64 {
        PrimeField::pow(self, *a, k)
    }
}

/// `F_p[c]/(m)` for a monic `m` of degree `n >= 1` over `F_p`; elements are coefficient vectors
/// of length `n` (the residues of `1, c, ..., c^{n-1}`).
#[derive(Clone, Debug)]
pub(crate) struct QuotientRing {
    /// The prime field.
    pub field: PrimeField,
    /// The monic modulus, `n + 1` coefficients (constant first, the last one 1).
    modulus: Vec<u64>,
}

impl QuotientRing {
    /// The ring of the integer polynomial `m` (constant first) modulo `p`; `None` when `p`
    /// divides its leading coefficient.
    pub fn new(field: PrimeField, m: &[BigInt]) -> Option<QuotientRing> {
        let residues: Vec<u64> = m.iter().map(|a| field.from_bigint(a)).collect();
        let lead = field.inv(*residues.last()?).ok()?;
        let modulus = residues.iter().map(|&a| field.mul(a, lead)).collect();
        Some(QuotientRing { field, modulus })
    }

    fn degree(&self) -> usize {
        self.modulus.len() - 1
    }

    /// The class of `c`.
    pub fn generator(&self) -> Vec<u64> {
        let mut x = vec![0, 1];
        self.reduce(&mut x);
        x
    }

    /// `a` reduced in place modulo the monic modulus, then padded to length `n`.
    fn reduce(&self, a: &mut Vec<u64>) {
        let (f, n) = (&self.field, self.degree());
        while a.len() > n {
            let t = a.pop().expect("longer than n");
            if t != 0 {
                let base = a.len() - n;
                for (j, &mj) in self.modulus[..n].iter().enumerate() {
                    a[base + j] = f.sub(a[base + j], f.mul(t, mj));
                }
            }
        }
        a.resize(n, 0);
    }
}

/// Drops the zero leading coefficients.
fn trim(a: &mut Vec<u64>) {
    while a.last() == Some(&0) {
        a.pop();
    }
}

/// `a mod b` and the quotient over `F_p`, `b` trimmed and non-zero.
fn div_rem(f: &PrimeField, a: &[u64], b: &[u64]) -> (Vec<u64>, Vec<u64>) {
    let mut r = a.to_vec();
    trim(&mut r);
    let lead = f
        .inv(*b.last().expect("b is not zero"))
        .expect("a non-zero lead");
    let mut q = vec![0; r.len().saturating_sub(b.len() - 1)];
    while r.len() >= b.len() {
        let t = f.mul(*r.last().expect("not empty"), lead);
        let shift = r.len() - b.len();
        q[shift] = t;
        for (j, &bj) in b.iter().enumerate() {
            r[shift + j] = f.sub(r[shift + j], f.mul(t, bj));
        }
        trim(&mut r);
    }
    (q, r)
}

/// `a - q b` over `F_p`.
fn sub_mul(f: &PrimeField, a: &[u64], q: &[u64], b: &[u64]) -> Vec<u64> {
    let mut out = a.to_vec();
    out.resize(a.len().max(q.len() + b.len()), 0);
    for (i, &qi) in q.iter().enumerate() {
        for (j, &bj) in b.iter().enumerate() {
            out[i + j] = f.sub(out[i + j], f.mul(qi, bj));
        }
    }
    trim(&mut out);
    out
}

impl Values for QuotientRing {
    type V = Vec<u64>;
    fn number(&self, q: &Rational) -> Option<Vec<u64>> {
        let mut v = vec![0; self.degree()];
        v[0] = self.field.from_rational(q).ok()?;
        Some(v)
    }
    fn add(&self, a: &Vec<u64>, b: &Vec<u64>) -> Vec<u64> {
        a.iter()
            .zip(b)
            .map(|(x, y)| self.field.add(*x, *y))
            .collect()
    }
    fn sub(&self, a: &Vec<u64>, b: &Vec<u64>) -> Vec<u64> {
        a.iter()
            .zip(b)
            .map(|(x, y)| self.field.sub(*x, *y))
            .collect()
    }
    fn mul(&self, a: &Vec<u64>, b: &Vec<u64>) -> Vec<u64> {
        let f = &self.field;
        let mut out = vec![0; a.len() + b.len() - 1];
        for (i, &x) in a.iter().enumerate().filter(|(_, x)| **x != 0) {
            for (j, &y) in b.iter().enumerate() {
                out[i + j] = f.add(out[i + j], f.mul(x, y));
            }
        }
        self.reduce(&mut out);
        out
    }
    fn neg(&self, a: &Vec<u64>) -> Vec<u64> {
        a.iter().map(|x| self.field.neg(*x)).collect()
    }
    /// The extended Euclidean algorithm on `a` and the modulus: a unit exactly when their gcd
    /// is a non-zero constant.
    fn inv(&self, a: &Vec<u64>) -> Option<Vec<u64>> {
        let f = &self.field;
        let mut r1 = a.clone();
        trim(&mut r1);
        if r1.is_empty() {
            return None;
        }
        // Invariants: r_i = s_i a (mod m).
        let (mut r0, mut s0, mut s1) = (self.modulus.clone(), Vec::new(), vec![1]);
        while !r1.is_empty() {
            let (q, r) = div_rem(f, &r0, &r1);
            let s = sub_mul(f, &s0, &q, &s1);
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
        }
        if r0.len() != 1 {
            return None;
        }
        let scale = f.inv(r0[0]).ok()?;
        let mut out: Vec<u64> = s0.iter().map(|&x| f.mul(x, scale)).collect();
        self.reduce(&mut out);
        Some(out)
    }
    fn is_zero(&self, a: &Vec<u64>) -> bool {
        a.iter().all(|x| *x == 0)
    }
}

/// The number field `Q(theta)`, elements as polynomials in `theta` reduced modulo its minimal
/// polynomial.
pub(crate) struct ExactField<'a>(pub &'a NumberField);

impl Values for ExactField<'_> {
    type V = UPoly;
    fn number(&self, q: &Rational) -> Option<UPoly> {
        Some(UPoly::constant(q.clone()))
    }
    fn add(&self, a: &UPoly, b: &UPoly) -> UPoly {
        a.add_ref(b)
    }
    fn sub(&self, a: &UPoly, b: &UPoly) -> UPoly {
        a.sub_ref(b)
    }
    fn mul(&self, a: &UPoly, b: &UPoly) -> UPoly {
        self.0.mul(a, b)
    }
    fn neg(&self, a: &UPoly) -> UPoly {
        a.neg_ref()
    }
    fn inv(&self, a: &UPoly) -> Option<UPoly> {
        self.0.inverse(a)
    }
    fn is_zero(&self, a: &UPoly) -> bool {
        self.0.reduce(a).is_zero()
    }
}

/// The rational numbers.
pub(crate) struct Rationals;

impl Values for Rationals {
    type V = Rational;
    fn number(&self, q: &Rational) -> Option<Rational> {
        Some(q.clone())
    }
    fn add(&self, a: &Rational, b: &Rational) -> Rational {
        a.add_ref(b)
    }
    fn sub(&self, a: &Rational, b: &Rational) -> Rational {
        a.sub_ref(b)
    }
    fn mul(&self, a: &Rational, b: &Rational) -> Rational {
        a.mul_ref(b)
    }
    fn neg(&self, a: &Rational) -> Rational {
        a.neg_ref()
    }
    fn inv(&self, a: &Rational) -> Option<Rational> {
        a.recip().ok()
    }
    fn is_zero(&self, a: &Rational) -> bool {
        Ring::is_zero(a)
    }
}

/// Why an evaluation stopped.
pub(crate) enum EvalError {
    /// A divisor without variables (only numbers and constants) is not a unit: modulo `p`, `p`
    /// divides it.
    NotInvertible,
    /// A divisor with a variable is not a unit at the point (a pole).
    Pole,
    /// A malformed expression (message).
    Input(String),
}

/// `e` with the exponent of every power written as the integer it evaluates to, and a power
/// with a negative exponent `b^(-k)` written as the division `1/b^k` (a rational function, as
/// the exact conversion reads it). An exponent that is not an integer constant is kept, and
/// refused where the power is evaluated.
pub(crate) fn powers_as_divisions(e: &Expr) -> Expr {
    let e = e.map_children(powers_as_divisions);
    let ExprKind::Pow(base, x) = &e.kind else {
        return e;
    };
    let Ok(k) = x.eval_constant::<Rational>() else {
        return e;
    };
    if !k.is_integer() {
        return e;
    }
    let power = |k: Rational| Expr {
        kind: ExprKind::Pow(
            base.clone(),
            Box::new(Expr {
                kind: ExprKind::Number(k),
                pos: x.pos,
            }),
        ),
        pos: e.pos,
    };
    if k.signum() != exactcheck_core::Sign::Negative {
        return power(k);
    }
    Expr {
        kind: ExprKind::Product(vec![
            (
                MulOp::Times,
                Expr {
                    kind: ExprKind::Number(Rational::ONE),
                    pos: e.pos,
                },
            ),
            (MulOp::Divide, power(k.neg_ref())),
        ]),
        pos: e.pos,
    }
}

/// The exponent of a power, a non-negative integer literal.
pub(crate) fn constant_exponent(e: &Expr) -> Option<u64> {
    match &e.kind {
        ExprKind::Number(q) if q.is_integer() => q.numer().try_into().ok(),
        _ => None,
    }
}

/// Whether a variable that is not a constant (`constant(name)`) occurs in the tree.
fn has_variable(e: &Expr, constant: &dyn Fn(&str) -> bool) -> bool {
    match &e.kind {
        ExprKind::Number(_) => false,
        ExprKind::Var(v) => !constant(v),
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => has_variable(x, constant),
        ExprKind::Pow(a, b) => has_variable(a, constant) || has_variable(b, constant),
        ExprKind::Sum(ts) => ts.iter().any(|(_, t)| has_variable(t, constant)),
        ExprKind::Product(fs) => fs.iter().any(|(_, f)| has_variable(f, constant)),
        ExprKind::Call(_, args) => args.iter().any(|a| has_variable(a, constant)),
    }
}

/// The value of `e` in `ring` at `point`; the variables for which `constant` holds (the
/// generator of the constants' field) make no divisor a pole. `refused` words a node the test
/// does not evaluate (a square root, a function call).
pub(crate) fn eval<R: Values>(
    e: &Expr,
    ring: &R,
    point: &HashMap<String, R::V>,
    constant: &dyn Fn(&str) -> bool,
    refused: &dyn Fn(&Expr) -> String,
) -> Result<R::V, EvalError> {
    let go = |x: &Expr| eval(x, ring, point, constant, refused);
    Ok(match &e.kind {
        ExprKind::Number(q) => ring.number(q).ok_or(EvalError::NotInvertible)?,
        ExprKind::Var(v) => point
            .get(v)
            .cloned()
            .ok_or_else(|| EvalError::Input(format!("no value for {v}")))?,
        ExprKind::Neg(x) => ring.neg(&go(x)?),
        ExprKind::Sum(ts) => {
            let mut acc = ring.number(&Rational::ZERO).expect("0 maps");
            for (op, t) in ts {
                let v = go(t)?;
                acc = match op {
                    AddOp::Plus => ring.add(&acc, &v),
                    AddOp::Minus => ring.sub(&acc, &v),
                };
            }
            acc
        }
        ExprKind::Product(fs) => {
            let mut acc = ring.number(&Rational::ONE).expect("1 maps");
            for (op, x) in fs {
                let v = go(x)?;
                acc = match op {
                    MulOp::Times | MulOp::Dot | MulOp::Cross => ring.mul(&acc, &v),
                    MulOp::Divide => ring.mul(
                        &acc,
                        &ring.inv(&v).ok_or_else(|| {
                            if has_variable(x, constant) {
                                EvalError::Pole
                            } else {
                                EvalError::NotInvertible
                            }
                        })?,
                    ),
                };
            }
            acc
        }
        ExprKind::Pow(b, x) => {
            let k = constant_exponent(x).ok_or_else(|| {
                EvalError::Input("exponents must be non-negative integer numbers".into())
            })?;
            ring.pow(&go(b)?, k)
        }
        ExprKind::Call(..) | ExprKind::Sqrt(_) => return Err(EvalError::Input(refused(e))),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;

    /// The quotient ring against the number field: `(a b) mod (p, m)` is the image of
    /// `a b mod m` over Q, and an inverse multiplies back to 1.
    #[test]
    fn quotient_ring_agrees_with_the_number_field() {
        let mut rng = Rng::new(11);
        let f = PrimeField::random_62(&mut rng);
        // m = 8 c^3 + 4 c^2 - 4 c - 1 (cos(2 pi/7)), not monic.
        let m: Vec<BigInt> = [-1, -4, 4, 8].iter().map(|&a| BigInt::from(a)).collect();
        let ring = QuotientRing::new(f, &m).unwrap();
        let monic = UPoly::from_i64_coeffs(&[-1, -4, 4, 8]).monic();
        let image = |u: &UPoly| -> Vec<u64> {
            let mut v: Vec<u64> = (0..3)
                .map(|k| f.from_rational(&u.coeff(k)).unwrap())
                .collect();
            v.resize(3, 0);
            v
        };
        for _ in 0..20 {
            let a: Vec<i64> = (0..3).map(|_| rng.below(19) as i64 - 9).collect();
            let b: Vec<i64> = (0..3).map(|_| rng.below(19) as i64 - 9).collect();
            let (ua, ub) = (UPoly::from_i64_coeffs(&a), UPoly::from_i64_coeffs(&b));
            let want = image(&ua.mul_ref(&ub).rem(&monic));
            assert_eq!(ring.mul(&image(&ua), &image(&ub)), want);
            if !ua.is_zero() {
                let inv = ring.inv(&image(&ua)).unwrap();
                assert_eq!(ring.mul(&inv, &image(&ua)), image(&UPoly::one()));
            }
        }
        assert_eq!(ring.inv(&vec![0, 0, 0]), None);
        // The generator satisfies m.
        let c = ring.generator();
        let c3 = ring.pow(&c, 3);
        let lhs = ring.add(
            &ring.mul(&ring.number(&8.into()).unwrap(), &c3),
            &ring.pow(&c, 0),
        );
        let rhs = ring.sub(
            &ring.add(
                &ring.mul(&ring.number(&4.into()).unwrap(), &c),
                &ring.number(&2.into()).unwrap(),
            ),
            &ring.mul(&ring.number(&4.into()).unwrap(), &ring.mul(&c, &c)),
        );
        assert_eq!(lhs, rhs);
        // A prime dividing the leading coefficient has no quotient ring.
        let two = PrimeField::new(3).unwrap();
        assert!(QuotientRing::new(two, &[BigInt::from(1), BigInt::from(3)]).is_none());
    }

    /// A zero divisor is not a unit: modulo 7, c^2 - 2 = (c - 3)(c + 3).
    #[test]
    fn zero_divisors_have_no_inverse() {
        let f = PrimeField::new(7).unwrap();
        let ring =
            QuotientRing::new(f, &[BigInt::from(-2), BigInt::from(0), BigInt::from(1)]).unwrap();
        assert_eq!(ring.inv(&vec![4, 1]), None);
        assert!(ring.inv(&vec![1, 1]).is_some());
    }
}
