//! # exactcheck
//!
//! The command-line tool and the claim catalogue of exactcheck. The mathematics lives in
//! `exactcheck-core` (generic over the scalar), the exact scalars in `exactcheck-exact`, the f64
//! side and the float-vs-exact harness in `exactcheck-float`.
#![warn(missing_docs)]

pub mod args;
pub mod budget;
pub mod claimfile;
pub mod claims;
pub mod cli;
pub mod error;
pub mod limits;
pub mod output;
pub mod papers;
pub mod phrase;
pub mod plot;
pub mod progress;
pub mod prove_cmd;
pub mod regress;
pub mod report;
pub mod solve;
pub mod verify_cmd;

pub use error::Error;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The Rust examples of the library guide, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/library.md")]
pub struct LibraryGuideDoctests;

/// The Rust example of the `regress` guide (a `Formula` of your own), compiled and run as a
/// doctest.
#[cfg(doctest)]
#[doc = include_str!("../docs/regress.md")]
pub struct RegressGuideDoctests;
