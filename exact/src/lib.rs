//! # exactcheck-exact
//!
//! Exact scalars for exactcheck and the procedures built on them:
//! * [`Rational`], the fast exact rational field, and [`PlainRational`], the unoptimised
//!   num-rational baseline it is measured and cross-checked against;
//! * [`Radical`], square-root extensions of Q with exact sign, and [`ComplexRadical`] with
//!   `sqrt(-1)`;
//! * [`ModP`], integers modulo the Mersenne prime 2^61 - 1, and [`modp::PrimeField`], integers
//!   modulo a prime chosen at run time (randomized identity tests, [`prove::random`]);
//! * sparse multivariate polynomials ([`poly`]) and their expression syntax ([`expr`]).
#![warn(missing_docs)]

/// `Ring` for a type whose arithmetic is its inherent `add_impl`, `sub_impl`, `mul_impl` and
/// `neg_impl`: the constants and the zero test as given, the four operations delegated.
macro_rules! ring_by_impls {
    (
        $t:ty;
        zero: $zero:expr;
        one: $one:expr;
        from_i64: |$n:ident| $from:expr;
        is_zero: |$s:ident| $is_zero:expr;
    ) => {
        impl exactcheck_core::Ring for $t {
            fn zero() -> Self {
                $zero
            }
            fn one() -> Self {
                $one
            }
            fn from_i64($n: i64) -> Self {
                $from
            }
            fn is_zero(&self) -> bool {
                let $s = self;
                $is_zero
            }
            fn add_ref(&self, rhs: &Self) -> Self {
                self.add_impl(rhs)
            }
            fn sub_ref(&self, rhs: &Self) -> Self {
                self.sub_impl(rhs)
            }
            fn mul_ref(&self, rhs: &Self) -> Self {
                self.mul_impl(rhs)
            }
            fn neg_ref(&self) -> Self {
                self.neg_impl()
            }
        }
    };
}

pub mod algebraic;
pub mod bigint;
pub mod coefficient;
pub mod cylinder_sphere;
pub mod expr;
pub mod gcd;
pub mod modp;
pub mod pi;
pub mod plain;
pub mod planar;
pub mod poly;
pub mod program;
pub mod prove;
pub mod radical;
pub mod random_plane;
pub mod ratfun;
pub mod rational;
pub mod real_constant;
pub mod symbolic;
pub mod to_f64;
pub mod traits;
pub mod univariate;

pub use algebraic::Algebraic;
pub use expr::{ParseRadicalError, ParseRationalError};
pub use modp::ModP;
pub use plain::PlainRational;
pub use radical::{ComplexRadical, Radical, Radicand};
pub use rational::Rational;
pub use traits::RationalScalar;
