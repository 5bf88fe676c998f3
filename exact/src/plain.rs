//! `PlainRational`: num-rational's `BigRational` on the scalar ladder, unchanged.
//!
//! The orphan rule forbids implementing `exactcheck-core`'s traits for `BigRational` itself, so
//! this is a transparent newtype. It is the baseline the fast [`crate::Rational`] is measured and
//! cross-checked against: every operation is num-rational's own (a full gcd normalisation after
//! each addition and multiplication).

use exactcheck_core::{Field, OrderedField, Ring, ZeroDivisor};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// num-rational's `BigRational` as a scalar of the ladder (the unoptimised baseline).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct PlainRational(pub BigRational);

impl From<BigRational> for PlainRational {
    fn from(q: BigRational) -> Self {
        PlainRational(q)
    }
}

impl From<PlainRational> for BigRational {
    fn from(q: PlainRational) -> Self {
        q.0
    }
}

impl std::fmt::Display for PlainRational {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(&self.0, f)
    }
}

// The num-rational operators in all their forms (owned ones reuse storage), as the baseline does.
exactcheck_core::ring_ops! {
    impl[] PlainRational;
    Neg::neg: |a| PlainRational(-&a.0), owned |a| PlainRational(-a.0);
    Add::add, AddAssign::add_assign: |a, b| PlainRational(&a.0 + &b.0),
        owned |a, b| PlainRational(a.0 + &b.0),
        by_value |a, b| PlainRational(a.0 + b.0);
    Sub::sub, SubAssign::sub_assign: |a, b| PlainRational(&a.0 - &b.0),
        owned |a, b| PlainRational(a.0 - &b.0),
        by_value |a, b| PlainRational(a.0 - b.0);
    Mul::mul, MulAssign::mul_assign: |a, b| PlainRational(&a.0 * &b.0),
        owned |a, b| PlainRational(a.0 * &b.0),
        by_value |a, b| PlainRational(a.0 * b.0);
    Div::div, DivAssign::div_assign: |a, b| PlainRational(&a.0 / &b.0),
        owned |a, b| PlainRational(a.0 / &b.0),
        by_value |a, b| PlainRational(a.0 / b.0);
}

impl Ring for PlainRational {
    fn zero() -> Self {
        PlainRational(BigRational::zero())
    }
    fn one() -> Self {
        PlainRational(BigRational::one())
    }
    fn from_i64(n: i64) -> Self {
        PlainRational(BigRational::from_integer(BigInt::from(n)))
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        PlainRational(&self.0 + &rhs.0)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        PlainRational(&self.0 - &rhs.0)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        PlainRational(&self.0 * &rhs.0)
    }
    fn neg_ref(&self) -> Self {
        PlainRational(-&self.0)
    }
}

impl Field for PlainRational {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        if self.0.is_zero() {
            Err(ZeroDivisor)
        } else {
            Ok(PlainRational(self.0.recip()))
        }
    }
}

impl OrderedField for PlainRational {
    fn sign(&self) -> exactcheck_core::Sign {
        if self.0.is_positive() {
            exactcheck_core::Sign::Positive
        } else if self.0.is_negative() {
            exactcheck_core::Sign::Negative
        } else {
            exactcheck_core::Sign::Zero
        }
    }
}
