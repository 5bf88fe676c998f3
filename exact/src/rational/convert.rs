//! Conversions of [`Rational`] from and to integers and num-rational's `BigRational`, its
//! printing, and its parsing by the one grammar of [`crate::expr`].

use super::*;
use std::fmt;

impl From<i64> for Rational {
    fn from(n: i64) -> Self {
        Rational::from_integer(n)
    }
}

impl From<i32> for Rational {
    fn from(n: i32) -> Self {
        Rational::from_integer(n as i64)
    }
}

impl From<BigInt> for Rational {
    fn from(n: BigInt) -> Self {
        let (sign, mag) = n.into_parts();
        Rational::from_coprime(BigInt::from_biguint(sign, mag), BigUint::one())
    }
}

impl From<&BigRational> for Rational {
    fn from(q: &BigRational) -> Self {
        // num-rational keeps its values reduced, but `new_raw` can build others: reduce.
        Rational::from_big_parts(q.numer().clone(), q.denom().clone())
    }
}

impl From<BigRational> for Rational {
    fn from(q: BigRational) -> Self {
        let (n, d) = q.into_raw();
        Rational::from_big_parts(n, d)
    }
}

impl From<&Rational> for BigRational {
    fn from(q: &Rational) -> Self {
        q.to_big_rational()
    }
}

impl From<Rational> for BigRational {
    fn from(q: Rational) -> Self {
        q.to_big_rational()
    }
}

impl fmt::Display for Rational {
    /// `n` for integers, `n/d` otherwise (the exact number syntax).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small(n, 1) => write!(f, "{n}"),
            Repr::Small(n, d) => write!(f, "{n}/{d}"),
            Repr::Big(b) if b.den.is_one() => write!(f, "{}", b.num),
            Repr::Big(b) => write!(f, "{}/{}", b.num, b.den),
        }
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
