//! # exactcheck-core
//!
//! The mathematics of exactcheck, written once and generic over the scalar: the scalar ladder
//! ([`scalar`]), vectors ([`vector`]), the Bernstein/Bezier toolkit ([`bernstein`], [`bezier`])
//! and the constructions of the source papers. This crate knows no number type beyond the
//! primitive `f64` instantiation of the ladder; exact and symbolic scalars live in
//! `exactcheck-exact`, fast float kernels in `exactcheck-float`.
#![warn(missing_docs)]

pub mod bernstein;
pub mod bezier;
pub mod conic;
pub mod cylinder_sphere;
pub mod inertia;
pub mod limits;
pub mod linalg;
pub mod miquel;
pub mod ops;
pub mod ph;
pub mod planes;
pub mod quadric;
pub mod rational_angle;
pub mod rng;
pub mod roots;
pub mod ruled;
pub mod scalar;
pub mod sphere_interpolation;
#[cfg(test)]
mod test_support;
pub mod vector;

pub use bernstein::{Bernstein, ShapeError};
pub use bezier::{BezierCurve, RationalBezierCurve, TensorPatch};
pub use rng::Rng;
pub use scalar::{
    binomial, pairwise_sum, Field, OrderedField, QAlgebra, Ring, Sign, Sqrt, ZeroDivisor,
};
pub use vector::{det4, proportional, Hom4, Vec3};
