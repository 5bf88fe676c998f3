//! # exactcheck-float
//!
//! The `f64` side of exactcheck and the float-vs-exact regression harness.
//!
//! * [`convert`] — exact `f64 -> BigRational`, correctly rounded `BigRational -> f64`, [`ulp`],
//!   and the error measures [`ulps_error`] and [`rel_error`], all computed exactly.
//! * [`scalar`] — [`ExactScalar`], what the harness needs of an exact number type, implemented
//!   for [`exactcheck_exact::PlainRational`].
//! * [`gen`] — the input generators, drawing from the workspace's one generator [`Rng`]
//!   ([`UniformBox`], [`LogUniform`], [`NearDegenerate`] around [`Fixed`] or [`Diagonal`] points).
//! * [`near`] — [`NearSet`]: inputs moved onto a degenerate set `g = 0` by exact-sign bisection
//!   and perturbed by a few ulps.
//! * [`domain`] — [`SampleDomain`]: inputs sampled inside exact [`Range`]s (FPCore's `:pre`,
//!   `--domain` text read by [`parse_domain`]), one-sided ranges uniformly over the doubles.
//! * [`harness`] — [`regress`]: a [`Formula`] written once generic over the scalar is run in
//!   `f64` and exactly on the same random inputs; the [`Report`] gives max/median/mean errors in
//!   ulps and relative terms, threshold counts, and the worst inputs, shrunk to short
//!   reproducible cases. This is the model of CGAL's `Kernel_checker`: two kernels, every
//!   disagreement reported with its inputs.
//!
//! * [`external`] — [`ProgramRunner`]: the user's own executable (any language) as the float
//!   side, fed one JSON line of inputs per sample and answering one line of outputs.
//! * [`wabis`] — the published JavaScript `InterctionLineOf2Areas` ported to `f64`
//!   operation for operation: the float code under test of `regress plane-plane`.
//!
//! Tolerances live here and only here: the exact crates decide, this crate measures how far
//! float code strays from their decisions.
#![warn(missing_docs)]

pub mod convert;
pub mod domain;
pub mod external;
pub mod gen;
pub mod harness;
pub mod json;
pub mod near;
pub mod report;
pub mod sampler;
pub mod scalar;
pub mod shard;
pub mod summary;
pub mod wabis;

pub use convert::{
    binary_exponent, f64_to_rational, pow2, rational_to_f64, rel_error, round_to_bits,
    significant_bits, ulp, ulps_error,
};
pub use domain::{parse_domain, Bound, Range, SampleDomain, Sampling};
pub use exactcheck_core::rng::{self, Rng};
pub use external::{ProgramError, ProgramRunner};
pub use gen::{Diagonal, Fixed, GenError, InputGen, LogUniform, NearDegenerate, UniformBox};
pub use harness::{
    check, check_consistent, check_subject, merge, regress, run, run_observed, sample_inputs,
    CaseError, ExactValue, FloatSideError, Formula, Generic, MergeError, Observed, Options,
    RegressError, Subject,
};
pub use near::NearSet;
pub use report::{
    Case, Explanation, LimitStop, OperationError, Report, Summary, ThresholdCount, WorstCase,
};
pub use scalar::ExactScalar;
pub use shard::{Shard, Sweep};
