//! The standard traits of [`Poly`]: equality, default, conversion, [`Ring`] and the operators.

use super::*;

impl<C: Ring> PartialEq for Poly<C> {
    fn eq(&self, other: &Self) -> bool {
        if self.len() != other.len() || self.coeffs != other.coeffs {
            return false;
        }
        if self.shape == other.shape {
            return self.exps == other.exps;
        }
        let s = self.common_shape(other);
        self.exps_in(s) == other.exps_in(s)
    }
}

impl<C: Ring + Eq> Eq for Poly<C> {}

impl<C: Ring> Default for Poly<C> {
    fn default() -> Self {
        Poly::zero()
    }
}

impl<C: Ring> From<C> for Poly<C> {
    fn from(c: C) -> Self {
        Poly::constant(c)
    }
}

impl<C: exactcheck_core::QAlgebra> exactcheck_core::QAlgebra for Poly<C> {
    fn inv_u64(n: u64) -> Result<Self, exactcheck_core::ZeroDivisor> {
        C::inv_u64(n).map(Poly::constant)
    }
}

impl<C: Ring> Ring for Poly<C> {
    fn zero() -> Self {
        Poly::zero()
    }
    fn one() -> Self {
        Poly::constant(C::one())
    }
    fn from_i64(n: i64) -> Self {
        Poly::constant(C::from_i64(n))
    }
    fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
    fn is_one(&self) -> bool {
        self.is_constant() && self.coeffs.first().is_some_and(Ring::is_one)
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, false)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs, true)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
    fn neg_ref(&self) -> Self {
        self.neg_impl()
    }
    fn square(&self) -> Self {
        self.square_impl()
    }
    fn pow(&self, e: u32) -> Self {
        self.pow_u64(e as u64)
    }
    fn scale_i64(&self, n: i64) -> Self {
        self.scale(&C::from_i64(n))
    }
}

exactcheck_core::ring_ops! {
    impl[C: Ring] Poly<C>;
    Neg::neg: |a| a.neg_impl(), owned |a| a.neg_owned();
    Add::add, AddAssign::add_assign: |a, b| a.add_impl(b, false),
        owned |a, b| a.add_left_owned(b, false),
        by_value |a, b| a.add_owned(b, false);
    Sub::sub, SubAssign::sub_assign: |a, b| a.add_impl(b, true),
        owned |a, b| a.add_left_owned(b, true),
        by_value |a, b| a.add_owned(b, true);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_impl(b);
}
