//! `exactcheck bench`: the benchmark workloads W1 (Chiang's theorem proved by expansion, and
//! the dense product `f (f + 1)`; [`w1`]), W2 (the exact Spaeth discriminant at N rational
//! parameters, [`crate::w2`]), W3 (f64 sampling of the same discriminant) and W4 (real roots
//! of integer polynomials isolated to width 2^-53; [`w4`]), timed and printed with their check
//! values as text or as the one JSON line the anchor scripts print (`scripts/compare.py` runs
//! them beside the anchors).
//!
//! Each workload's `--n` has a documented maximum ([`MAX_W2_EVAL_N`], [`MAX_W2_TREE_N`],
//! [`MAX_W2_SEQ_N`], [`MAX_W3_N`]), chosen from measured rates on a 2-core machine (eval about
//! 200,000 parameters/s; tree stores every value and its balanced sum of 10^6 values takes
//! minutes; seq's running sum grows with every step, about 4,000 parameters/s at 2*10^4; W3
//! about 10^8 samples/s with `sin_cos` per sample, about 10^9 with the default `addition`
//! kernel): a larger value is a one-line error naming the flag and the limit,
//! never an allocation or a loop proportional to an unchecked number.

use crate::args::{check_count, ScalarChoice};
use crate::w2;
use crate::Error;
use clap::{Args, Subcommand, ValueEnum};
use exactcheck_exact::{PlainRational, Rational, RationalScalar};
use exactcheck_float::sampler::{sweep_direct, DiscSampler};
use std::process::ExitCode;

mod stopwatch;
pub mod w1;
pub mod w4;

pub use stopwatch::{process_cpu_seconds, Elapsed, Stopwatch};

/// The largest `bench w2 --n` in mode `eval` (about a minute).
pub const MAX_W2_EVAL_N: usize = 10_000_000;
/// The largest `bench w2 --n` in mode `tree` (every value is kept; a few minutes).
pub const MAX_W2_TREE_N: usize = 1_000_000;
/// The largest `bench w2 --n` in mode `seq` (the running sum grows; minutes).
pub const MAX_W2_SEQ_N: usize = 100_000;
/// The largest `bench w3 --n` (seconds on all cores).
pub const MAX_W3_N: usize = 1_000_000_000;

/// The largest `--n` of `bench formula` (about 300,000 exact evaluations/s per core).
pub const MAX_FORMULA_N: usize = 10_000_000;

/// The formula of `bench formula` and `scripts/regress_baseline.py`: 11 operations.
pub const BASELINE_FORMULA: &str = "((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y";

/// Arguments of `exactcheck bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Which workload.
    #[command(subcommand)]
    pub workload: Workload,
}

/// The benchmark workloads (see `scripts/anchors` for the same workloads in other tools).
#[derive(Debug, Subcommand)]
pub enum Workload {
    /// W1: Chiang's ruled-surface/plane theorem at degrees (m, n), built and expanded as
    /// `scripts/anchors/w1_identity.py` does, both residuals tested for zero.
    W1 {
        /// Degree of the directrix curve V (at least 1; m + n at most 48).
        #[arg(long, default_value_t = 8)]
        m: u32,
        /// Degree of the curve B (at least 1; m + n at most 48).
        #[arg(long, default_value_t = 13)]
        n: u32,
        /// Perturb phi(0, 0) by 1/7, as `w1_identity.py --negative`: must not prove.
        #[arg(long)]
        negative: bool,
        /// Print one JSON line (as the anchor scripts do) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The dense product f (f + 1), f = (1 + x1 + ... + xV)^K (Fateman's benchmark).
    Dense {
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
    /// W2: the exact Spaeth discriminant at N rational parameters.
    W2 {
        /// Number of parameters T_k = k/1000 - 50, k = 0..N-1 (at most 10,000,000 with
        /// `eval`, 1,000,000 with `tree`, 100,000 with `seq`).
        #[arg(long, default_value_t = 100_000)]
        n: usize,
        /// eval: evaluate only; tree: plus a pairwise exact sum; seq: plus a sequential exact sum.
        #[arg(long, value_enum, default_value_t = w2::Mode::Eval)]
        mode: w2::Mode,
        /// The exact rational type: the fast `Rational`, or num-rational's plain `BigRational`.
        #[arg(long, value_enum, default_value_t = ScalarChoice::Fast)]
        scalar: ScalarChoice,
        /// Print one JSON line (as the anchor scripts do) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The exact side of `regress --formula` alone: the 11-operation formula of
    /// `scripts/regress_baseline.py` evaluated exactly on its inputs (the same seeded doubles),
    /// with the same check values.
    Formula {
        /// Number of samples (at most 10,000,000).
        #[arg(long, default_value_t = 100_000)]
        n: usize,
        /// The seed of the inputs (as `regress --seed`).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Evaluate on one core only (default: all cores, as `regress` does).
        #[arg(long)]
        serial: bool,
    },
    /// W3: f64 sampling of the Spaeth discriminant on the grid t_i = i 2 pi / N (default
    /// variant `addition`: angle addition per block and vectorized lanes, no libm call per
    /// sample; `coef`, `coef-serial`, `direct` call `sin_cos` per sample).
    W3 {
        /// Number of samples (at most 1,000,000,000).
        #[arg(long, default_value_t = 10_000_000)]
        n: usize,
        /// How the samples are evaluated.
        #[arg(long, value_enum, default_value_t = W3Variant::Addition)]
        variant: W3Variant,
        /// Print one JSON line instead of text.
        #[arg(long)]
        json: bool,
    },
    /// W4: all real roots of an integer polynomial isolated to width 2^-53 (Descartes' rule).
    W4 {
        /// The family of polynomials.
        #[arg(long, value_enum)]
        family: w4::W4Family,
        /// The degree (at least 1, at most 2000).
        #[arg(long)]
        degree: usize,
        /// Print one JSON line (as `scripts/anchors/w4_roots.py`) instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// The variants of W3.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum W3Variant {
    /// Angle addition per block of 512 samples (one `sin_cos` per block), the discriminant
    /// summed in vectorized lanes, all cores (within 19 u of `sin_cos` per sample).
    Addition,
    /// The angle-addition kernel on one thread (the same result bit for bit).
    AdditionSerial,
    /// Precomputed trigonometric coefficients, all cores.
    Coef,
    /// Precomputed coefficients, one thread.
    CoefSerial,
    /// The derived formulas evaluated per sample with `sin_cos`, one thread (the baseline).
    Direct,
}

/// The largest `--n` of W2 in `mode`, and how the error names it.
pub fn max_w2_n(mode: w2::Mode) -> (usize, &'static str) {
    match mode {
        w2::Mode::Eval => (MAX_W2_EVAL_N, " with --mode eval"),
        w2::Mode::Tree => (MAX_W2_TREE_N, " with --mode tree"),
        w2::Mode::Seq => (MAX_W2_SEQ_N, " with --mode seq"),
    }
}

/// Runs `exactcheck bench` and prints the result.
///
/// # Errors
/// [`Error::Usage`] for `--n` outside its range; [`Error::Output`] when standard output fails.
pub fn run(args: &BenchArgs) -> Result<ExitCode, Error> {
    let text = match args.workload {
        Workload::W1 {
            m,
            n,
            negative,
            json,
        } => w1::bench_w1(m, n, negative, json)?,
        Workload::Dense { k, vars, json } => w1::bench_dense(k, vars, json)?,
        Workload::W4 {
            family,
            degree,
            json,
        } => w4::bench_w4(family, degree, json)?,
        Workload::Formula { n, seed, serial } => {
            let n = check_count("--n", n, MAX_FORMULA_N, "")?;
            bench_formula(n, seed, serial)
        }
        Workload::W3 { n, variant, json } => {
            let n = check_count("--n", n, MAX_W3_N, "")?;
            bench_w3(n, variant, json)
        }
        Workload::W2 {
            n,
            mode,
            scalar,
            json,
        } => {
            let (max, context) = max_w2_n(mode);
            let n = check_count("--n", n, max, context)?;
            match scalar {
                ScalarChoice::Fast => bench_w2::<Rational>(n, mode, "fast", json),
                ScalarChoice::Plain => bench_w2::<PlainRational>(n, mode, "plain", json),
            }
        }
    };
    crate::output::println(text)?;
    Ok(ExitCode::SUCCESS)
}

/// Runs W3 (f64 sampling of the same configuration as W2, on the grid `t_i = i 2 pi / n`) and
/// formats the result like `w3_numpy.py` (one JSON line) or as text.
///
/// The timed region covers what the anchor's does: from the configuration to the check values
/// (coefficients, the angle table, the sweep). Starting rayon's worker threads is process set-up
/// (as the Python interpreter's start is for numpy) and happens before it.
pub fn bench_w3(n: usize, variant: W3Variant, json: bool) -> String {
    let cs = w2::problem::<f64>();
    rayon::broadcast(|_| ());
    let watch = Stopwatch::start();
    let summary = match variant {
        W3Variant::Addition => DiscSampler::new(&cs).sweep_addition(n),
        W3Variant::AdditionSerial => DiscSampler::new(&cs).sweep_addition_serial(n),
        W3Variant::Coef => DiscSampler::new(&cs).sweep(n),
        W3Variant::CoefSerial => DiscSampler::new(&cs).sweep_serial(n),
        W3Variant::Direct => sweep_direct(&cs, n),
    };
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    let value = variant
        .to_possible_value()
        .expect("no W3 variant is skipped");
    let name = value.get_name();
    if json {
        format!(
            "{{\"tool\": \"exactcheck\", \"variant\": \"{name}\", \"N\": {n}, \"seconds\": {seconds}, \"cpu_seconds\": {cpu}, \"samples_per_s\": {}, \"count_nonneg\": {}, \"sum_sqrt\": \"{:?}\", \"threads\": {}}}",
            n as f64 / seconds,
            summary.count_nonneg,
            summary.sum_sqrt,
            match variant {
                W3Variant::Addition | W3Variant::Coef => rayon::current_num_threads(),
                _ => 1,
            }
        )
    } else {
        format!(
            "W3 (f64 Spaeth discriminant), N = {n}, variant {name}\n  samples with disc >= 0: {}\n  sum of sqrt(disc): {:?}\n  time: {seconds:.4} s ({:.1} M samples/s)",
            summary.count_nonneg,
            summary.sum_sqrt,
            n as f64 / seconds / 1e6
        )
    }
}

/// Runs W2 with `n` parameters over the scalar `T` and formats it like `w2_rational.py` (one
/// JSON line) or as text.
pub fn bench_w2<T: RationalScalar>(n: usize, mode: w2::Mode, scalar: &str, json: bool) -> String {
    let out = w2::run::<T>(n, mode);
    let checks = out.sum.as_ref().map(w2::check_values);
    let mode_name = format!("{mode:?}").to_lowercase();
    if json {
        let mut s = format!(
            "{{\"tool\": \"exactcheck\", \"scalar\": \"{scalar}\", \"mode\": \"{mode_name}\", \"N\": {n}, \"seconds\": {}, \"cpu_seconds\": {}, \"samples_per_s\": {}, \"count_nonneg\": {}",
            out.seconds,
            out.cpu_seconds,
            n as f64 / out.seconds,
            out.count_nonneg
        );
        if let Some(c) = &checks {
            s += &format!(
                ", \"sum_num_digits\": {}, \"sum_den_digits\": {}, \"sum_num_mod_p\": {}, \"sum_den_mod_p\": {}, \"sum_approx\": {:?}",
                c.num_digits, c.den_digits, c.num_mod_p, c.den_mod_p, c.approx
            );
        }
        s + "}"
    } else {
        let mut s = format!(
            "W2 (exact Spaeth discriminant), N = {n}, mode {mode_name}, scalar {scalar}\n  parameters with disc >= 0: {}\n",
            out.count_nonneg
        );
        if let Some(c) = &checks {
            s += &format!(
                "  exact sum: numerator {} digits, denominator {} digits\n  numerator mod 1e9+7 = {}, denominator mod 1e9+7 = {}\n  value ~ {:?}\n",
                c.num_digits, c.den_digits, c.num_mod_p, c.den_mod_p, c.approx
            );
        }
        s + &format!(
            "  time: {:.3} s ({:.0} parameters/s)",
            out.seconds,
            n as f64 / out.seconds
        )
    }
}

/// `bench formula`: the exact side of [`BASELINE_FORMULA`] on `n` samples of four doubles
/// uniform in [-1, 1] (`sample_inputs(UniformBox::cube(4, -1, 1), seed, i)`, the inputs of
/// `regress --formula ... --domain 'x in [-1, 1], ...'` and of the Python baseline), timed
/// (inputs drawn outside the timed region), with the baseline's check values: the sums of the
/// results' numerators and denominators mod `2^61 - 1`, and the correctly rounded sum of their
/// correctly rounded doubles.
pub fn bench_formula(n: usize, seed: u64, serial: bool) -> String {
    use exactcheck_exact::program::Program;
    use exactcheck_float::{sample_inputs, ExactScalar, UniformBox};
    use num_bigint::BigInt;
    use num_traits::{ToPrimitive, Zero};
    use rayon::prelude::*;
    let vars: Vec<String> = ["x", "y", "z", "w"].map(String::from).to_vec();
    let program = Program::parse(BASELINE_FORMULA, Some(&vars)).expect("the formula parses");
    let gen = UniformBox::cube(4, -1.0, 1.0).expect("a valid box");
    let inputs: Vec<Vec<Rational>> = (0..n)
        .map(|i| {
            sample_inputs(&gen, seed, i)
                .iter()
                .map(|&v| Rational::from_f64_exact(v).expect("finite"))
                .collect()
        })
        .collect();
    let eval = |x: &Vec<Rational>| {
        program
            .eval_exact(x)
            .ok()
            .and_then(|r| r.into_iter().next())
    };
    let watch = Stopwatch::start();
    let values: Vec<_> = if serial {
        inputs.iter().map(eval).collect()
    } else {
        inputs.par_iter().map(eval).collect()
    };
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    let p = BigInt::from((1u64 << 61) - 1);
    let (mut num, mut den) = (BigInt::zero(), BigInt::zero());
    let mut doubles = Vec::with_capacity(n);
    let mut defined = 0usize;
    for v in values.into_iter().flatten() {
        defined += 1;
        num = (num + v.value.numer()) % &p;
        den = (den + v.value.denom()) % &p;
        doubles.push(exactcheck_float::rational_to_f64(&v.value));
    }
    let modp = |x: BigInt| ((x % &p + &p) % &p).to_u64().expect("below p");
    format!(
        "formula {BASELINE_FORMULA}: {n} samples ({defined} defined) in {seconds:.3} s = {:.0} samples/s on {} thread(s), {cpu:.3} s CPU; sum_num_mod_p {}, sum_den_mod_p {}, fsum {:?}",
        n as f64 / seconds,
        if serial { 1 } else { rayon::current_num_threads() },
        modp(num),
        modp(den),
        exactcheck_float::convert::fsum(&doubles)
    )
}
