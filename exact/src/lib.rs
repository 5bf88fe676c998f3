//! # exactcheck-exact
//!
//! Exact scalars for exactcheck and the procedures built on them: [`PlainRational`], the
//! unoptimised num-rational baseline; [`Rational`], the fast exact rational field; and (later) square-root
//! fields, polynomials, finite fields and the proof engines.
#![warn(missing_docs)]

pub mod expr;
pub mod gcd;
pub mod modp;
pub mod plain;
pub mod poly;
pub mod radical;
pub mod rational;
pub mod traits;

pub use plain::PlainRational;
pub use rational::{sum_pairwise, ParseRationalError, Rational};
pub use traits::RationalScalar;
