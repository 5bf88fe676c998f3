//! What exact rational scalars share beyond the ladder: conversion to and from num-rational's
//! `BigRational`, the public big-number base.

use exactcheck_core::OrderedField;
use num_rational::BigRational;

/// An exact rational scalar: an [`OrderedField`] that converts losslessly to and from
/// `BigRational`. Implemented by [`crate::Rational`] (fast) and [`crate::PlainRational`]
/// (num-rational itself, the baseline); code generic over it can compare the two.
pub trait RationalScalar: OrderedField {
    /// The value as a `BigRational`.
    fn to_big_rational(&self) -> BigRational;
    /// The value of a `BigRational`.
    fn from_big_rational(q: &BigRational) -> Self;
}

impl RationalScalar for crate::Rational {
    fn to_big_rational(&self) -> BigRational {
        crate::Rational::to_big_rational(self)
    }
    fn from_big_rational(q: &BigRational) -> Self {
        crate::Rational::from(q)
    }
}

impl RationalScalar for crate::PlainRational {
    fn to_big_rational(&self) -> BigRational {
        self.0.clone()
    }
    fn from_big_rational(q: &BigRational) -> Self {
        crate::PlainRational(q.clone())
    }
}
