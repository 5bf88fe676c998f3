//! The scalar ladder: [`Ring`] ⊂ [`Field`] ⊂ [`OrderedField`], and [`Sqrt`].
//!
//! Each rung is only as strong as an algorithm needs (after nalgebra/simba, without the big
//! `RealField`): no `Copy`, no trigonometry, no square root in the base traits. Every formula of the
//! workspace is written once against these traits and instantiated with exact rationals,
//! square-root fields, polynomials, integers modulo a prime and `f64`.
//!
//! The operator bounds live here once, as supertraits, so generic code reads
//! `T: Ring` and nothing more. Binary operators take the left operand by value and the right one
//! by value or by reference (`a * &b`); where both operands are borrowed and a big number would
//! otherwise be cloned, use the `*_ref` methods (`a.mul_ref(b)`), which implementations on big
//! numbers override to avoid the copy.
//!
//! # Laws
//! `Ring`: `+` and `*` are associative and commutative, `*` distributes over `+`, `zero` and
//! `one` are neutral, `a + (-a) = 0`. Floating-point implementations satisfy them only
//! approximately. `Field`: every non-zero `a` has `a * a.inv() = 1`. `OrderedField`: the order is
//! total and compatible with `+` and with `*` by positive elements.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// The error of a division by zero (an inverse of zero was asked for).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ZeroDivisor;

impl core::fmt::Display for ZeroDivisor {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("division by zero")
    }
}

impl std::error::Error for ZeroDivisor {}

/// A commutative ring with one.
///
/// Enough for every statement in homogeneous (projective) form; division-free code written
/// against `Ring` can be instantiated with a polynomial ring, which is what makes a proof symbolic.
///
/// Every ring is `'static` (owns its data): kernels generic over `Ring` may then recognise a
/// concrete type by its `TypeId` and take a faster specialised path (the polynomial products of
/// `exactcheck_exact::poly` do so for machine-word coefficients), with no number-type detail here.
pub trait Ring:
    'static
    + Clone
    + PartialEq
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
{
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The image of an integer.
    fn from_i64(n: i64) -> Self;
    /// Whether `self` is the additive identity (exactly, for exact types).
    fn is_zero(&self) -> bool;

    /// Whether `self` is the multiplicative identity.
    fn is_one(&self) -> bool {
        *self == Self::one()
    }
    /// `self + rhs` with both operands borrowed.
    fn add_ref(&self, rhs: &Self) -> Self {
        self.clone() + rhs
    }
    /// `self - rhs` with both operands borrowed.
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.clone() - rhs
    }
    /// `self * rhs` with both operands borrowed.
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.clone() * rhs
    }
    /// `-self` with the operand borrowed.
    fn neg_ref(&self) -> Self {
        -self.clone()
    }
    /// `self * self`.
    fn square(&self) -> Self {
        self.mul_ref(self)
    }
    /// `self^e` by binary powering (`self^0 = 1`).
    fn pow(&self, mut e: u32) -> Self {
        let mut acc = Self::one();
        if e == 0 {
            return acc;
        }
        let mut base = self.clone();
        loop {
            if e & 1 == 1 {
                acc *= &base;
            }
            e >>= 1;
            if e == 0 {
                return acc;
            }
            base = base.square();
        }
    }
    /// `n * self` for an integer `n`.
    fn scale_i64(&self, n: i64) -> Self {
        self.mul_ref(&Self::from_i64(n))
    }
}

/// A ring containing the rationals (a Q-algebra): every [`Field`] (blanket implementation) and the
/// polynomial rings over one. Constructions that divide only by integers (integrating a
/// hodograph, the `1/C(n,k)` of a Bernstein product) are written once over it, so the same code
/// runs on numbers and, for symbolic proofs, on polynomials.
pub trait QAlgebra: Ring {
    /// `1/n`, or [`ZeroDivisor`] when `n` is not invertible (zero, or a multiple of a finite
    /// characteristic).
    fn inv_u64(n: u64) -> Result<Self, ZeroDivisor>;
}

impl<T: Field> QAlgebra for T {
    fn inv_u64(n: u64) -> Result<Self, ZeroDivisor> {
        from_u64::<T>(n).inv()
    }
}

/// A field: a [`Ring`] in which every non-zero element has an inverse.
///
/// The `/` operator may panic on a zero divisor, as the number types it is implemented for do;
/// code that handles user input calls [`Field::inv`] or [`Field::checked_div`], which report it.
pub trait Field:
    Ring
    + Div<Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + DivAssign
    + for<'a> DivAssign<&'a Self>
{
    /// The multiplicative inverse, or [`ZeroDivisor`] for zero.
    fn inv(&self) -> Result<Self, ZeroDivisor>;

    /// `self / rhs`, or [`ZeroDivisor`] when `rhs` is zero.
    fn checked_div(&self, rhs: &Self) -> Result<Self, ZeroDivisor> {
        if rhs.is_zero() {
            Err(ZeroDivisor)
        } else {
            Ok(self.clone() / rhs)
        }
    }

    /// The fraction `num / den` of two integers, or [`ZeroDivisor`] when `den == 0`.
    fn from_ratio(num: i64, den: i64) -> Result<Self, ZeroDivisor> {
        Self::from_i64(num).checked_div(&Self::from_i64(den))
    }
}

/// The sign of an element of an ordered field.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sign {
    /// Less than zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Greater than zero.
    Positive,
}

impl Mul for Sign {
    type Output = Sign;
    /// The sign of a product of elements with these signs.
    fn mul(self, other: Sign) -> Sign {
        match (self, other) {
            (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
            (a, b) if a == b => Sign::Positive,
            _ => Sign::Negative,
        }
    }
}

/// A [`Field`] with a total order compatible with its arithmetic (exact sign and comparison).
pub trait OrderedField: Field + PartialOrd {
    /// The sign of `self`.
    fn sign(&self) -> Sign {
        let z = Self::zero();
        if *self > z {
            Sign::Positive
        } else if *self < z {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }
    /// `|self|`.
    fn abs(&self) -> Self {
        if self.sign() == Sign::Negative {
            self.neg_ref()
        } else {
            self.clone()
        }
    }
}

/// Square roots, where they exist in the type.
pub trait Sqrt: Sized {
    /// The non-negative square root of `self` if it lies in the type (always for `f64 >= 0`),
    /// `None` otherwise.
    fn sqrt(&self) -> Option<Self>;
}

/// `sum_i a_i` over an iterator of borrowed elements.
pub fn sum<'a, T: Ring + 'a>(items: impl IntoIterator<Item = &'a T>) -> T {
    let mut acc = T::zero();
    for x in items {
        acc += x;
    }
    acc
}

/// `sum_i a_i` by pairwise (balanced) summation: the operands of each addition stay of similar
/// size, which keeps exact sums of many rationals fast (the big gcds then cost about as much as
/// one at the top level). Zero for an empty list.
pub fn pairwise_sum<T: Ring>(mut values: Vec<T>) -> T {
    while values.len() > 1 {
        let mut next = Vec::with_capacity(values.len().div_ceil(2));
        let mut it = values.into_iter();
        while let Some(x) = it.next() {
            next.push(match it.next() {
                Some(y) => x + y,
                None => x,
            });
        }
        values = next;
    }
    values.pop().unwrap_or_else(T::zero)
}

/// The binomial coefficient `C(n, k)` as an integer (0 when `k > n`).
///
/// # Panics
/// When the result does not fit in a `u64` (not before `n = 67`).
pub fn binomial(n: u32, k: u32) -> u64 {
    if k > n {
        return 0;
    }
    let k = k.min(n - k) as u64;
    let n = n as u64;
    let mut c: u128 = 1;
    for i in 0..k {
        c = c * (n - i) as u128 / (i + 1) as u128;
    }
    u64::try_from(c).expect("binomial coefficient overflows u64")
}

/// `C(n, k)` for `usize` arguments (0 when `k > n`).
pub(crate) fn binom(n: usize, k: usize) -> u64 {
    if k > n {
        return 0;
    }
    let n = u32::try_from(n).expect("degree does not fit in u32");
    binomial(n, k as u32)
}

/// The image of a non-negative integer in the ring (exact for the whole `u64` range).
pub(crate) fn from_u64<T: Ring>(n: u64) -> T {
    match i64::try_from(n) {
        Ok(v) => T::from_i64(v),
        // n < 2^64, so n >> 1 fits in an i64.
        Err(_) => T::from_i64((n >> 1) as i64).scale_i64(2) + T::from_i64((n & 1) as i64),
    }
}

/// Implements [`Ring`], [`Field`] and [`OrderedField`] for a primitive float type.
macro_rules! float_ladder {
    ($t:ty) => {
        impl Ring for $t {
            fn zero() -> Self {
                0.0
            }
            fn one() -> Self {
                1.0
            }
            fn from_i64(n: i64) -> Self {
                n as $t
            }
            fn is_zero(&self) -> bool {
                *self == 0.0
            }
            fn add_ref(&self, rhs: &Self) -> Self {
                self + rhs
            }
            fn sub_ref(&self, rhs: &Self) -> Self {
                self - rhs
            }
            fn mul_ref(&self, rhs: &Self) -> Self {
                self * rhs
            }
            fn neg_ref(&self) -> Self {
                -self
            }
        }
        impl Field for $t {
            fn inv(&self) -> Result<Self, ZeroDivisor> {
                if *self == 0.0 {
                    Err(ZeroDivisor)
                } else {
                    Ok(1.0 / self)
                }
            }
        }
        impl OrderedField for $t {}
        impl Sqrt for $t {
            fn sqrt(&self) -> Option<Self> {
                if *self >= 0.0 {
                    Some(<$t>::sqrt(*self))
                } else {
                    None
                }
            }
        }
    };
}

// The f64 instantiation lives with the primitive type (orphan rule); the float crate holds what
// goes beyond the ladder (ulps, exact conversion, the regression harness).
float_ladder!(f64);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials() {
        assert_eq!(binomial(5, 2), 10);
        assert_eq!(binomial(5, 6), 0);
        assert_eq!(binomial(60, 30), 118264581564861424);
    }

    #[test]
    fn pow_by_squaring() {
        assert_eq!(3.0f64.pow(5), 243.0);
        assert_eq!(2.0f64.pow(0), 1.0);
    }

    #[test]
    fn sign_product() {
        assert_eq!(Sign::Negative * Sign::Negative, Sign::Positive);
        assert_eq!(Sign::Zero * Sign::Negative, Sign::Zero);
        assert_eq!(Sign::Positive * Sign::Negative, Sign::Negative);
    }

    #[test]
    fn float_inverse_reports_zero() {
        assert_eq!(0.0f64.inv(), Err(ZeroDivisor));
        assert_eq!(4.0f64.inv(), Ok(0.25));
        assert_eq!(Sqrt::sqrt(&-1.0f64), None);
    }
}
