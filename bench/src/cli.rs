//! The command line of `exactcheck-bench`: one subcommand per workload, each timed and printed
//! with its check values as text or as the one JSON line the anchor scripts print
//! (`bench/scripts/compare.py` runs them beside the anchors).
//!
//! Each workload's `--n` has a documented maximum ([`MAX_RATIONAL_SUM_EVAL_N`],
//! [`MAX_RATIONAL_SUM_TREE_N`], [`MAX_RATIONAL_SUM_SEQ_N`], [`MAX_SAMPLE_SPHERE_N`]), chosen
//! from measured rates on a 2-core machine (eval about 200,000 parameters/s; tree stores every
//! value and its balanced sum of 10^6 values takes minutes; seq's running sum grows with every
//! step, about 4,000 parameters/s at 2*10^4; `sample-sphere` about 10^8 samples/s with
//! `sin_cos` per sample, about 10^9 with the default `addition` kernel): a larger value is a
//! one-line error naming the flag and the limit, never an allocation or a loop proportional to
//! an unchecked number.

use crate::formula::{self, MAX_FORMULA_N};
use crate::rational_sum::{self, Mode};
use crate::real_roots::{self, RootFamily};
use crate::sample_sphere::{self, Variant};
use crate::{chiang_identity, dense_product};
use clap::{Parser, Subcommand};
use exactcheck::args::{check_count, ScalarChoice};
use exactcheck::Error;
use exactcheck_exact::{PlainRational, Rational};
use std::process::ExitCode;

/// The largest `rational-sum --n` in mode `eval` (about a minute).
pub const MAX_RATIONAL_SUM_EVAL_N: usize = 10_000_000;
/// The largest `rational-sum --n` in mode `tree` (every value is kept; a few minutes).
pub const MAX_RATIONAL_SUM_TREE_N: usize = 1_000_000;
/// The largest `rational-sum --n` in mode `seq` (the running sum grows; minutes).
pub const MAX_RATIONAL_SUM_SEQ_N: usize = 100_000;
/// The largest `sample-sphere --n` (seconds on all cores).
pub const MAX_SAMPLE_SPHERE_N: usize = 1_000_000_000;

/// `exactcheck-bench`: the benchmark workloads of exactcheck, timed, with their check values.
#[derive(Debug, Parser)]
#[command(name = "exactcheck-bench", version)]
pub struct Cli {
    /// Which workload.
    #[command(subcommand)]
    pub workload: Workload,
}

/// The benchmark workloads (see `bench/scripts/anchors` for the same workloads in other tools).
#[derive(Debug, Subcommand)]
pub enum Workload {
    /// Chiang's ruled-surface/plane theorem at degrees (m, n), built and expanded as
    /// `bench/scripts/anchors/chiang_identity.py` does, both residuals tested for zero (a sparse
    /// polynomial identity).
    ChiangIdentity {
        /// Degree of the directrix curve V (at least 1; m + n at most 48).
        #[arg(long, default_value_t = 8)]
        m: u32,
        /// Degree of the curve B (at least 1; m + n at most 48).
        #[arg(long, default_value_t = 13)]
        n: u32,
        /// Perturb phi(0, 0) by 1/7, as `chiang_identity.py --negative`: must not prove.
        #[arg(long)]
        negative: bool,
        /// Print one JSON line (as the anchor scripts do) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The dense product f (f + 1), f = (1 + x1 + ... + xV)^K (Fateman's benchmark).
    DenseProduct {
        /// The power K (at most 30).
        #[arg(long, default_value_t = 8)]
        k: usize,
        /// The number of variables V (at most 8).
        #[arg(long, default_value_t = 4)]
        vars: usize,
        /// Print one JSON line instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The exact Spaeth discriminant at N rational parameters, counted and summed exactly.
    RationalSum {
        /// Number of parameters T_k = k/1000 - 50, k = 0..N-1 (at most 10,000,000 with
        /// `eval`, 1,000,000 with `tree`, 100,000 with `seq`).
        #[arg(long, default_value_t = 100_000)]
        n: usize,
        /// eval: evaluate only; tree: plus a pairwise exact sum; seq: plus a sequential exact sum.
        #[arg(long, value_enum, default_value_t = Mode::Eval)]
        mode: Mode,
        /// The exact rational type: the fast `Rational`, or num-rational's plain `BigRational`.
        #[arg(long, value_enum, default_value_t = ScalarChoice::Fast)]
        scalar: ScalarChoice,
        /// Print one JSON line (as the anchor scripts do) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The exact side of `exactcheck regress --formula` alone: the 11-operation formula of
    /// `scripts/regress_baseline.py` evaluated exactly on its inputs (the same seeded doubles),
    /// with the same check values.
    Formula {
        /// Number of samples (at most 10,000,000).
        #[arg(long, default_value_t = 100_000)]
        n: usize,
        /// The seed of the inputs (as `exactcheck regress --seed`).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Evaluate on one core only (default: all cores, as `regress` does).
        #[arg(long)]
        serial: bool,
    },
    /// f64 sampling of the Spaeth cylinder/sphere discriminant on the grid t_i = i 2 pi / N
    /// (default variant `addition`: angle addition per block and vectorized lanes, no libm
    /// call per sample; `coef`, `coef-serial`, `direct` call `sin_cos` per sample).
    SampleSphere {
        /// Number of samples (at most 1,000,000,000).
        #[arg(long, default_value_t = 10_000_000)]
        n: usize,
        /// How the samples are evaluated.
        #[arg(long, value_enum, default_value_t = Variant::Addition)]
        variant: Variant,
        /// Print one JSON line instead of text.
        #[arg(long)]
        json: bool,
    },
    /// All real roots of an integer polynomial isolated to width 2^-53 (Descartes' rule).
    RealRoots {
        /// The family of polynomials.
        #[arg(long, value_enum)]
        family: RootFamily,
        /// The degree (at least 1, at most 2000).
        #[arg(long)]
        degree: usize,
        /// Print one JSON line (as `bench/scripts/anchors/real_roots.py`) instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// The largest `rational-sum --n` in `mode`, and how the error names it.
pub fn max_rational_sum_n(mode: Mode) -> (usize, &'static str) {
    match mode {
        Mode::Eval => (MAX_RATIONAL_SUM_EVAL_N, " with --mode eval"),
        Mode::Tree => (MAX_RATIONAL_SUM_TREE_N, " with --mode tree"),
        Mode::Seq => (MAX_RATIONAL_SUM_SEQ_N, " with --mode seq"),
    }
}

/// Runs one workload and prints the result.
///
/// # Errors
/// [`Error::Usage`] for `--n` outside its range; [`Error::Output`] when standard output fails.
pub fn run(cli: &Cli) -> Result<ExitCode, Error> {
    let text = match cli.workload {
        Workload::ChiangIdentity {
            m,
            n,
            negative,
            json,
        } => chiang_identity::run(m, n, negative, json)?,
        Workload::DenseProduct { k, vars, json } => dense_product::run(k, vars, json)?,
        Workload::RealRoots {
            family,
            degree,
            json,
        } => real_roots::run(family, degree, json)?,
        Workload::Formula { n, seed, serial } => {
            let n = check_count("--n", n, MAX_FORMULA_N, "")?;
            formula::run(n, seed, serial)
        }
        Workload::SampleSphere { n, variant, json } => {
            let n = check_count("--n", n, MAX_SAMPLE_SPHERE_N, "")?;
            sample_sphere::run(n, variant, json)
        }
        Workload::RationalSum {
            n,
            mode,
            scalar,
            json,
        } => {
            let (max, context) = max_rational_sum_n(mode);
            let n = check_count("--n", n, max, context)?;
            match scalar {
                ScalarChoice::Fast => rational_sum::report::<Rational>(n, mode, "fast", json),
                ScalarChoice::Plain => {
                    rational_sum::report::<PlainRational>(n, mode, "plain", json)
                }
            }
        }
    };
    exactcheck::output::println(text)?;
    Ok(ExitCode::SUCCESS)
}

/// Parses the command line and runs it: help on standard output; a usage error or a refused
/// value as one line `exactcheck-bench: error: ...` (plus a hint line for usage errors) on
/// standard error with exit status 2.
pub fn main() -> ExitCode {
    exactcheck::budget::keep_freed_memory();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return usage_error(&e),
    };
    match run(&cli) {
        Ok(code) => code,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("exactcheck-bench: error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Prints clap's help or version text, or its error shortened to one line plus a hint.
fn usage_error(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    let text = e.render().to_string();
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        print!("{text}");
        return ExitCode::SUCCESS;
    }
    let message = if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        "a workload is needed".to_string()
    } else {
        exactcheck::cli::one_line(&text, e.kind())
    };
    eprintln!("exactcheck-bench: error: {message}");
    eprintln!("exactcheck-bench: hint: see `exactcheck-bench --help`");
    ExitCode::from(2)
}
