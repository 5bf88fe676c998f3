//! `exactcheck regress`: float code against exact results on seeded inputs, through the one
//! harness sweep of `exactcheck-float`. What is regressed:
//! * a built-in kernel (`regress KERNEL`): a formula of `exactcheck-core` written once, generic
//!   over the scalar, run in f64 and exactly on the same inputs; `plane-plane` ([`planes`])
//!   regresses the published JavaScript port against the exact construction with its own
//!   binned measure, and `ruled-plane` ([`ruled`]) runs the harness on several generators;
//! * a formula as text (`--formula`), or the benchmarks of an FPCore file (`--fpcore`), compiled
//!   to a float program ([`text`]);
//! * with `--program`, the user's own executable as the float side of a formula.
//!
//! Any harness sweep can run as a shard (`--shard I/N`, JSON out) and the shards merge
//! (`exactcheck merge`, [`sweep`]).

pub mod explain;
pub mod near;
pub mod planes;
pub mod predicate;
pub mod sweep;
pub mod text;

use crate::args::{check_count, ScalarChoice};
use crate::Error;
use clap::{Args, ValueEnum};
use std::process::ExitCode;

pub mod ruled;

/// The largest `--samples` of a built-in kernel: the `samples` limit (each sample is evaluated
/// exactly, about 0.8 ms on one core for `cylinder_sphere`: the default of 100,000 is about a
/// minute of work).
pub fn max_samples() -> usize {
    crate::limits::SAMPLES.get_usize()
}

/// The largest number of samples one run evaluates of a `--formula` or `--fpcore` sweep (a
/// float program of a few operations runs at 100,000-300,000 samples/s: minutes of work).
pub const MAX_TEXT_SAMPLES: usize = 100_000_000;

/// The largest `--samples` of a sharded sweep (each shard's own part stays within the per-run
/// limit; the harness keeps bounded summaries, so the total costs no memory).
pub const MAX_SWEEP_SAMPLES: usize = 1_000_000_000_000;
use exactcheck_core::cylinder_sphere::{unit_circle_point, CylinderSphere};
use exactcheck_core::{BezierCurve, OrderedField, Vec3, ZeroDivisor};
use exactcheck_exact::{PlainRational, Rational};
use exactcheck_float::{
    ExactScalar, Formula, Generic, InputGen, Options, Report, Sweep, UniformBox,
};

/// Arguments of `exactcheck regress`.
#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("subject").required(true).args(["kernel", "formula", "fpcore"])))]
pub struct RegressArgs {
    /// The built-in kernel to regress (or give --formula or --fpcore).
    #[arg(value_enum)]
    pub kernel: Option<Kernel>,
    /// A formula in the `prove` syntax plus sqrt of any subexpression, e.g.
    /// 'sqrt(x + 1) - sqrt(x)': evaluated in f64 in the order written and exactly. The
    /// functions of the language (det, dot, cross, norm2, bezier, sum, binomial, diff,
    /// integrate, ...) are lowered to arithmetic first (diff and integrate to their expanded
    /// exact result), and both sides evaluate that tree. A vector value (`vec(a, b)`, `[a, b]`)
    /// is one output per coordinate, and --formula may be repeated: the outputs of one program,
    /// with errors reported per output and the worst over them.
    #[arg(long, conflicts_with_all = ["kernel", "fpcore"])]
    pub formula: Vec<String>,
    /// Draw the inputs of --formula / --fpcore near the set where this equation holds, e.g.
    /// '(bx-ax)*(cy-ay) = (by-ay)*(cx-ax)': each sample is moved onto it along one input by
    /// exact-sign bisection and perturbed by a few ulps.
    #[arg(long, value_name = "EXPR = EXPR")]
    pub near: Option<String>,
    /// Count sign errors of the (single-output) formula: the sign of the float result against
    /// the exact sign, as a geometric predicate (orient2d, incircle) is used.
    #[arg(long)]
    pub predicate: bool,
    /// The formula's inputs in order, comma-separated (default: in order of appearance).
    #[arg(long, value_delimiter = ',', requires = "formula")]
    pub vars: Option<Vec<String>>,
    /// The input domain of --formula, e.g. 'x in [1, 1e15], y in (0, inf)'. Both bounds
    /// finite: uniform on the reals; a missing or infinite bound: uniform over the doubles.
    #[arg(long, requires = "formula")]
    pub domain: Option<String>,
    /// The format the --formula float side computes in: `binary64` (f64, the default) or
    /// `binary32` (every operation, literal and library call in f32; inputs sampled among the
    /// binary32 values; errors in binary32 ulps). An FPCore benchmark's own `:precision` decides
    /// for --fpcore.
    #[arg(
        long,
        value_enum,
        value_name = "binary64|binary32",
        requires = "formula"
    )]
    pub precision: Option<PrecisionChoice>,
    /// How --formula and --fpcore inputs are drawn: `floats` uniform over the doubles of every
    /// range (as Herbie samples), `reals` uniform on the reals (every range bounded). Default:
    /// uniform on the reals where both bounds are finite, over the doubles otherwise.
    #[arg(long, value_enum, value_name = "reals|floats")]
    pub sample: Option<SampleChoice>,
    /// An FPCore file: every benchmark in it (or the one --name chooses) is regressed.
    #[arg(long, value_name = "FILE", conflicts_with = "kernel")]
    pub fpcore: Option<String>,
    /// The FPCore benchmark to run (its :name).
    #[arg(long, requires = "fpcore")]
    pub name: Option<String>,
    /// The float side is this executable ('CMD ARGS'): one JSON line of inputs in, one line
    /// of outputs back per sample (see docs/regress.md).
    #[arg(long, value_name = "CMD")]
    pub program: Option<String>,
    /// The numbered protocol of --program: each input line starts with the sample index,
    /// which the program echoes before its answer.
    #[arg(long, requires = "program")]
    pub program_echo_index: bool,
    /// Seconds to wait for each answer of --program.
    #[arg(long, default_value_t = 10.0, value_name = "SECONDS")]
    pub program_timeout: f64,
    /// Run part I of N of the sweep (by sample index) and print its JSON shard report;
    /// `exactcheck merge` combines the shards.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<exactcheck_float::Shard>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Number of random input vectors (at most 1,000,000).
    #[arg(long, default_value_t = 10_000)]
    pub samples: usize,
    /// Seed of the input generator (every reported case is reproducible from it).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// How many worst cases to report (each shrunk to a short reproducible input).
    #[arg(long, default_value_t = 3)]
    pub worst: usize,
    /// The exact scalar of the reference side.
    #[arg(long, value_enum, default_value_t = ScalarChoice::Fast)]
    pub scalar: ScalarChoice,
    /// Print the report(s) as one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
    /// Bin the compared samples of --formula / --fpcore by the exact value of this expression
    /// over the inputs (e.g. a triangle's area) and show the error in each bin.
    #[arg(long, value_name = "EXPR")]
    pub bin: Option<String>,
    /// Write one CSV row per compared sample of --formula / --fpcore (inputs, float result,
    /// exact result rounded, ulps, bits) to FILE.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<String>,
    /// Write an HTML page of the --formula / --fpcore report with a plot of the error against
    /// each input to FILE.
    #[arg(long, value_name = "FILE")]
    pub html: Option<String>,
}

impl RegressArgs {
    /// The sweep these arguments ask for (samples, seed, shard).
    pub fn sweep(&self) -> Sweep {
        Sweep {
            samples: self.samples,
            seed: self.seed,
            shard: self.shard,
        }
    }

    /// The progress bar of this run's part of the sweep (hidden with `--quiet` or `--json`).
    pub fn progress(&self, label: &str) -> sweep::Progress {
        let total = self
            .shard
            .map_or(self.samples, |s| s.range(self.samples).len());
        sweep::Progress::new(total, label, self.quiet || self.json)
    }
}

/// `--sample`: the distribution of the inputs of --formula and --fpcore.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SampleChoice {
    /// Uniform on the reals of each range (both bounds needed).
    Reals,
    /// Uniform over the doubles of each range, as Herbie samples.
    Floats,
}

impl SampleChoice {
    /// The generator's rule.
    pub fn sampling(self) -> exactcheck_float::Sampling {
        match self {
            SampleChoice::Reals => exactcheck_float::Sampling::Reals,
            SampleChoice::Floats => exactcheck_float::Sampling::Floats,
        }
    }
}

/// `--precision`: the format of the --formula float side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum PrecisionChoice {
    /// IEEE binary64 (`f64`).
    Binary64,
    /// IEEE binary32 (`f32`).
    Binary32,
}

impl PrecisionChoice {
    /// The program's format.
    pub fn format(self) -> exactcheck_exact::program::Format {
        match self {
            PrecisionChoice::Binary64 => exactcheck_exact::program::Format::Binary64,
            PrecisionChoice::Binary32 => exactcheck_exact::program::Format::Binary32,
        }
    }
}

/// The built-in kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kernel {
    /// Spaeth's cylinder/sphere coefficients A(t), B(t) and the discriminant A^2 - B,
    /// plus the signs of the discriminant near tangency.
    #[value(alias = "cylinder_sphere")]
    CylinderSphere,
    /// De Casteljau evaluation of a cubic Bezier curve in space.
    #[value(alias = "bezier_cubic")]
    BezierCubic,
    /// The published JavaScript `InterctionLineOf2Areas` against the exact two-plane
    /// construction, binned by the angle between the normals (90 degrees down to 1e-12 rad).
    #[value(alias = "plane_plane")]
    PlanePlane,
    /// Chiang's plane section of a ruled surface (weights and control points) for
    /// (m, n) = (1, 2), (2, 3), (3, 5), on random and near-degenerate surfaces
    /// ([`ruled`]).
    #[value(alias = "ruled_plane")]
    RuledPlane,
}

/// The cylinder/sphere kernel. Inputs: axis point `a, b`, radius `r`, the rotations as rational
/// circle parameters `tau_beta, tau_gamma`, sphere centre `d, e, f` and radius `R`, and the
/// curve parameter `tau`; outputs `A, B, A^2 - B`.
pub struct CylinderSphereKernel;

impl Formula for CylinderSphereKernel {
    fn name(&self) -> String {
        "cylinder_sphere: A(t), B(t), A^2 - B".into()
    }
    fn arity(&self) -> usize {
        10
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let cs = CylinderSphere {
            a: x[0].clone(),
            b: x[1].clone(),
            r: x[2].clone(),
            beta: unit_circle_point(&x[3])?,
            gamma: unit_circle_point(&x[4])?,
            center: Vec3::new(x[5].clone(), x[6].clone(), x[7].clone()),
            radius: x[8].clone(),
        };
        let t = unit_circle_point(&x[9])?;
        let (a, b) = cs.coefficients_at(&t.cos, &t.sin);
        let disc = a.square() - &b;
        Ok(vec![a, b, disc])
    }
}

/// A cubic Bezier curve in space evaluated by de Casteljau. Inputs: the 12 coordinates of the
/// control points and `t`; outputs the point.
pub struct BezierCubicKernel;

impl Formula for BezierCubicKernel {
    fn name(&self) -> String {
        "bezier_cubic: de Casteljau evaluation".into()
    }
    fn arity(&self) -> usize {
        13
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let points = (0..4)
            .map(|i| Vec3::new(x[3 * i].clone(), x[3 * i + 1].clone(), x[3 * i + 2].clone()))
            .collect();
        let curve = BezierCurve::new(points);
        Ok(curve.eval(&x[12]).into_array().to_vec())
    }
}

/// The input box of a uniform-box kernel (`cylinder-sphere`, `bezier-cubic`); the report's
/// regression summaries sample the same inputs.
///
/// # Errors
/// [`Error::Usage`] for `plane-plane` and `ruled-plane`, which have their own generators.
pub fn generator(kernel: Kernel) -> Result<UniformBox, Error> {
    let gen = match kernel {
        Kernel::CylinderSphere => UniformBox::new(
            vec![
                -10.0, -10.0, 0.5, -3.0, -3.0, -10.0, -10.0, -10.0, 0.5, -50.0,
            ],
            vec![10.0, 10.0, 10.0, 3.0, 3.0, 10.0, 10.0, 10.0, 15.0, 50.0],
        ),
        Kernel::PlanePlane => {
            return Err(Error::Usage(
                "plane-plane has its own sweep (regress::planes), not a uniform box".into(),
            ))
        }
        Kernel::BezierCubic => {
            let mut lo = vec![-10.0; 12];
            let mut hi = vec![10.0; 12];
            lo.push(0.0);
            hi.push(1.0);
            UniformBox::new(lo, hi)
        }
        Kernel::RuledPlane => {
            return Err(Error::Usage(
                "ruled-plane draws from its own generators (regress::ruled)".into(),
            ))
        }
    };
    gen.map_err(|e| Error::Usage(format!("input generator: {e}")))
}

fn run_kernel<E: ExactScalar>(
    kernel: Kernel,
    gen: &impl InputGen,
    args: &RegressArgs,
    options: &Options,
) -> Result<Report, Error> {
    let sweep = args.sweep();
    let progress = args.progress("regress");
    let tick = |done: usize| progress.update(done);
    let report = match kernel {
        Kernel::CylinderSphere => exactcheck_float::run(
            &Generic::<_, E>::new(&CylinderSphereKernel),
            gen,
            sweep,
            options,
            &tick,
        ),
        Kernel::BezierCubic => exactcheck_float::run(
            &Generic::<_, E>::new(&BezierCubicKernel),
            gen,
            sweep,
            options,
            &tick,
        ),
        Kernel::PlanePlane => {
            return Err(Error::Usage(
                "plane-plane is not a harness formula (see regress::planes)".into(),
            ))
        }
        Kernel::RuledPlane => {
            return Err(Error::Usage(
                "ruled-plane runs several generators (regress::ruled::rows)".into(),
            ))
        }
    };
    report.map_err(|e| Error::Usage(e.to_string()))
}

/// Runs `exactcheck regress` and prints the report.
///
/// # Errors
/// [`Error::Limit`] for a kernel's `--samples` past the `samples` limit; [`Error::Usage`] for
/// `--samples` outside `1..=max_samples()` (`MAX_TEXT_SAMPLES` for a
/// formula or FPCore; with `--shard`, `MAX_SWEEP_SAMPLES` in all and the per-run limit per shard); [`Error::Output`] when standard
/// output fails.
pub fn run(args: &RegressArgs) -> Result<ExitCode, Error> {
    // Options of one subject given without it would be ignored: refused instead.
    let needs = [
        (
            "--name",
            args.name.is_some(),
            "--fpcore FILE",
            args.fpcore.is_some(),
        ),
        (
            "--vars",
            args.vars.is_some(),
            "--formula EXPR",
            !args.formula.is_empty(),
        ),
        (
            "--domain",
            args.domain.is_some(),
            "--formula EXPR",
            !args.formula.is_empty(),
        ),
    ];
    for (flag, given, subject, present) in needs {
        if given && !present {
            return Err(Error::Usage(format!(
                "{flag} applies to {subject} only; give {subject} or leave {flag} out"
            )));
        }
    }
    let text = !args.formula.is_empty() || args.fpcore.is_some();
    if !text && args.shard.is_none() && args.samples > max_samples() {
        return Err(Error::Limit(
            crate::limits::SAMPLES.exceeded(args.samples.to_string()),
        ));
    }
    let per_run = if text {
        MAX_TEXT_SAMPLES
    } else {
        max_samples()
    };
    match args.shard {
        None => {
            let context = if per_run == MAX_TEXT_SAMPLES {
                format!(" in one run (with --shard I/N up to {MAX_SWEEP_SAMPLES} in all)")
            } else {
                String::new()
            };
            check_count("--samples", args.samples, per_run, &context)?;
        }
        Some(s) => {
            check_count(
                "--samples",
                args.samples,
                MAX_SWEEP_SAMPLES,
                " with --shard",
            )?;
            let n = s.range(args.samples).len();
            if n > per_run {
                return Err(Error::Usage(format!(
                    "shard {s} of {} samples has {n}, more than the {per_run} one run evaluates: use more shards",
                    args.samples
                )));
            }
        }
    }
    if !(args.program_timeout.is_finite()
        && args.program_timeout > 0.0
        && args.program_timeout <= 86_400.0)
    {
        return Err(Error::Usage(format!(
            "--program-timeout must be between 0 and 86400 seconds (got {})",
            args.program_timeout
        )));
    }
    let kernel = match (&args.kernel, args.formula.is_empty(), &args.fpcore) {
        (Some(k), true, None) => *k,
        (None, false, None) => return text_run(args, None),
        (None, true, Some(path)) => return text_run(args, Some(path)),
        _ => {
            return Err(Error::Usage(
                "regress needs one of: a KERNEL (cylinder-sphere, bezier-cubic, plane-plane, ruled-plane), --formula EXPR, --fpcore FILE".into(),
            ))
        }
    };
    if args.program.is_some() {
        return Err(Error::Usage(
            "--program is the float side of --formula or --fpcore, not of a built-in kernel".into(),
        ));
    }
    for (flag, given) in [
        ("--near", args.near.is_some()),
        ("--predicate", args.predicate),
        ("--bin", args.bin.is_some()),
        ("--csv", args.csv.is_some()),
        ("--html", args.html.is_some()),
    ] {
        if given {
            return Err(Error::Usage(format!(
                "{flag} applies to --formula and --fpcore, not to a built-in kernel"
            )));
        }
    }
    if args.sample.is_some() {
        return Err(Error::Usage(
            "--sample applies to --formula and --fpcore; a built-in kernel has its own generator"
                .into(),
        ));
    }
    if args.shard.is_some() && matches!(kernel, Kernel::PlanePlane | Kernel::RuledPlane) {
        return Err(Error::Usage(format!(
            "--shard applies to harness sweeps (--formula, --fpcore, cylinder-sphere, bezier-cubic); {} has its own sweep",
            kernel.to_possible_value().map_or_else(String::new, |v| v.get_name().to_string())
        )));
    }
    if kernel == Kernel::PlanePlane {
        if args.scalar != ScalarChoice::Fast {
            return Err(Error::Usage(
                "regress plane-plane runs on the fast exact rationals only (--scalar fast)".into(),
            ));
        }
        let report = planes::run(args.samples, args.seed, args.worst);
        if args.json {
            crate::output::println(
                serde_json::to_string_pretty(&report.to_json()).expect("a report is plain JSON"),
            )?;
        } else {
            crate::output::println(report)?;
        }
        return Ok(ExitCode::SUCCESS);
    }
    let options = Options {
        worst: args.worst,
        ..Options::default()
    };
    if kernel == Kernel::RuledPlane {
        let rows = match args.scalar {
            ScalarChoice::Fast => ruled::rows::<Rational>(args.samples, args.seed, &options)?,
            ScalarChoice::Plain => ruled::rows::<PlainRational>(args.samples, args.seed, &options)?,
        };
        if args.json {
            crate::output::println(format_args!("{:#}", ruled::rows_json(&rows)))?;
        } else {
            crate::output::println(ruled::text(&rows, args.seed))?;
        }
        return Ok(ExitCode::SUCCESS);
    }
    let gen = generator(kernel)?;
    let report = match args.scalar {
        ScalarChoice::Fast => run_kernel::<Rational>(kernel, &gen, args, &options)?,
        ScalarChoice::Plain => run_kernel::<PlainRational>(kernel, &gen, args, &options)?,
    };
    if args.shard.is_some() {
        let entry = sweep::Entry {
            name: report.formula.clone(),
            line: None,
            outcome: Ok(report),
            bins: None,
            predicate: None,
        };
        sweep::print(&[entry], true)?;
        return Ok(ExitCode::SUCCESS);
    }
    if args.json {
        let mut doc = serde_json::json!({ "report": report.to_json() });
        if kernel == Kernel::CylinderSphere {
            let r = root_errors(&gen, args.samples, args.seed);
            let s = sign_errors(args.samples, args.seed);
            doc["roots"] = serde_json::json!({
                "compared": r.compared,
                "max_ulps": r.max_ulps,
                "median_ulps": r.median_ulps,
                "worst": r.worst,
            });
            doc["signs_near_tangency"] = serde_json::json!({
                "samples": s.samples,
                "false_real": s.false_real,
                "false_empty": s.false_empty,
                "exact_zero": s.exact_zero,
            });
        }
        crate::output::println(format_args!("{doc:#}"))?;
        return Ok(ExitCode::SUCCESS);
    }
    // Printed once every part is computed: an error or `--timeout` in the root or sign sweep
    // must not leave the first part on standard output as if it were the whole report.
    let mut text = crate::output::Text::new();
    text.line(report);
    if kernel == Kernel::CylinderSphere {
        text.line(root_errors(&gen, args.samples, args.seed).text());
        text.line(sign_errors_near_tangency(args.samples, args.seed));
    }
    text.print()?;
    Ok(ExitCode::SUCCESS)
}

/// `regress --formula` / `regress --fpcore FILE` (`fpcore`: the file).
fn text_run(args: &RegressArgs, fpcore: Option<&str>) -> Result<ExitCode, Error> {
    if args.scalar != ScalarChoice::Fast {
        return Err(Error::Usage(
            "--scalar plain applies to the built-in kernels; formulas are evaluated exactly in exactcheck's Rational".into(),
        ));
    }
    let entries = match fpcore {
        Some(path) => text::fpcore_entries(args, path)?,
        None => text::formula_entries(args, &args.formula)?,
    };
    sweep::print(&entries, args.json || args.shard.is_some())?;
    // A shard is a part of a sweep: `merge` judges the whole.
    if args.shard.is_some() {
        return Ok(ExitCode::SUCCESS);
    }
    // An entry that compared nothing because its loops ran past a limit on the work of one
    // sample measured nothing for want of a larger limit: after its report, the run is an error
    // naming the limit (the first by name of those its samples stopped at).
    let stopped: Vec<&sweep::Entry> = entries
        .iter()
        .filter(|e| matches!(&e.outcome, Ok(r) if r.compared == 0 && r.limit_stops > 0))
        .collect();
    if let Some(first) = stopped.first() {
        let limit = match &first.outcome {
            Ok(r) => r
                .limit_stop
                .first()
                .and_then(|s| crate::limits::find(&s.limit)),
            Err(_) => None,
        }
        .unwrap_or(&exactcheck_core::limits::LOOP_ITERATIONS);
        let others = match stopped.len() {
            1 => String::new(),
            2 => " and of 1 other entry".to_string(),
            n => format!(" and of {} other entries", n - 1),
        };
        return Err(Error::Limit(limit.exceeded(format!(
            "more than {} in every stopped sample of '{}'{others}, which compared no sample",
            limit.get(),
            first.name
        ))));
    }
    Ok(sweep::exit_code(&entries))
}

/// Errors of the f64 roots `u = -A +- sqrt(A^2 - B)` against the exact roots.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RootErrors {
    /// Samples where both the f64 and the exact discriminant are >= 0.
    pub compared: usize,
    /// Largest error in ulps over both roots.
    pub max_ulps: f64,
    /// Median (over samples) of the larger of the two roots' errors.
    pub median_ulps: f64,
    /// The inputs of the worst sample.
    pub worst: Vec<f64>,
}

impl RootErrors {
    fn text(&self) -> String {
        format!(
            "roots u = -A +- sqrt(A^2 - B), f64 vs exact (sqrt to 256 bits) on {} samples with real roots:\n  max {:.3} ulps, median {:.3} ulps; worst inputs {:?}",
            self.compared, self.max_ulps, self.median_ulps, self.worst
        )
    }
}

/// `sqrt(q)` for a rational `q >= 0` to 256 fractional bits (an error far below an f64 ulp of
/// the roots): `floor(sqrt(n d 2^512)) / (d 2^256)`.
fn sqrt_256(q: &num_rational::BigRational) -> num_rational::BigRational {
    use num_bigint::BigInt;
    let scale = BigInt::from(1) << 512u32;
    let root = (q.numer() * q.denom() * scale).sqrt();
    num_rational::BigRational::new(root, q.denom() * (BigInt::from(1) << 256u32))
}

/// The f64 roots of the cylinder/sphere quadratic against the exact roots, on the samples of
/// the regression's generator (same seed, same inputs).
///
/// The samples are independent (each is drawn from the seed and its index): measured in
/// parallel, then folded in index order, so the worst sample (the first of the largest error)
/// and the median do not depend on the number of threads.
pub fn root_errors(gen: &(impl InputGen + Sync), samples: usize, seed: u64) -> RootErrors {
    use rayon::prelude::*;
    let measured: Vec<Option<(f64, Vec<f64>)>> = (0..samples)
        .into_par_iter()
        .map(|i| root_error(gen, seed, i))
        .collect();
    let mut per_sample = Vec::new();
    let mut out = RootErrors::default();
    for (worst_here, inputs) in measured.into_iter().flatten() {
        if worst_here > out.max_ulps {
            out.max_ulps = worst_here;
            out.worst = inputs;
        }
        per_sample.push(worst_here);
        out.compared += 1;
    }
    per_sample.sort_by(f64::total_cmp);
    out.median_ulps = per_sample.get(per_sample.len() / 2).copied().unwrap_or(0.0);
    out
}

/// The larger error of the two f64 roots of sample `i` in ulps, with its inputs; `None` for a
/// sample that is skipped (outside the domain, or no real roots in f64 or exactly).
fn root_error(gen: &impl InputGen, seed: u64, i: usize) -> Option<(f64, Vec<f64>)> {
    use num_traits::Signed;
    let inputs = exactcheck_float::sample_inputs(gen, seed, i);
    let f = CylinderSphereKernel.eval::<f64>(&inputs).ok()?;
    let exact_in: Vec<Rational> = inputs
        .iter()
        .map(|x| Rational::from_f64_exact(*x))
        .collect::<Option<_>>()?;
    let e = CylinderSphereKernel.eval::<Rational>(&exact_in).ok()?;
    let (a_e, d_e) = (e[0].to_big_rational(), e[2].to_big_rational());
    if f[2] < 0.0 || d_e.is_negative() {
        return None;
    }
    let root = sqrt_256(&d_e);
    let sf = f[2].sqrt();
    let mut worst_here: f64 = 0.0;
    for sign in [-1.0, 1.0] {
        let u_f = -f[0] + sign * sf;
        let u_e = if sign < 0.0 {
            -&a_e - &root
        } else {
            -&a_e + &root
        };
        worst_here = worst_here.max(exactcheck_float::ulps_error(u_f, &u_e));
    }
    Some((worst_here, inputs))
}

/// Counts of the sign experiment near tangency.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SignErrors {
    /// Configurations tried.
    pub samples: usize,
    /// f64 says real points (disc >= 0) where the exact disc is negative.
    pub false_real: usize,
    /// f64 says no real point (disc < 0) where the exact disc is >= 0.
    pub false_empty: usize,
    /// Samples whose exact discriminant is exactly 0.
    pub exact_zero: usize,
}

/// Nearly tangent configurations: the sphere centre at distance `delta` from the axis (along
/// the rotated x direction, so the touching parameter is near tau = 0), `R = delta - r + eps`
/// with `|eps|` log-uniform in `[1e-15, 1e-6]`, and tau log-uniform near 0. The f64 discriminant's sign is compared with the exact
/// one on the same f64 inputs.
pub fn sign_errors(samples: usize, seed: u64) -> SignErrors {
    use rayon::prelude::*;
    let mut rng = exactcheck_float::Rng::new(seed ^ 0x7A46);
    // The configurations are drawn in order from the one generator (every draw of a sample is
    // made before anything can skip it), then compared in parallel and counted.
    let drawn: Vec<[f64; 9]> = (0..samples)
        .map(|_| {
            let a = rng.uniform(-5.0, 5.0);
            let b = rng.uniform(-5.0, 5.0);
            let r = rng.uniform(1.0, 6.0);
            let (tb, tg) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
            let delta = r + rng.uniform(0.5, 5.0);
            let h = rng.uniform(-3.0, 3.0);
            // Log-uniform scales, so the exact discriminant ranges down to where f64 error
            // competes.
            let eps = 10f64.powf(-rng.uniform(6.0, 15.0)) * rng.uniform(-1.0, 1.0);
            let tau = 10f64.powf(-rng.uniform(2.0, 8.0)) * rng.uniform(-1.0, 1.0);
            [a, b, r, tb, tg, delta, h, eps, tau]
        })
        .collect();
    let counts: Vec<[usize; 3]> = drawn.par_iter().map(sign_error).collect();
    let mut out = SignErrors {
        samples,
        ..SignErrors::default()
    };
    for [zero, real, empty] in counts {
        out.exact_zero += zero;
        out.false_real += real;
        out.false_empty += empty;
    }
    out
}

/// One configuration of [`sign_errors`]: `[exact zero, false real, false empty]` as 0 or 1.
fn sign_error(&[a, b, r, tb, tg, delta, h, eps, tau]: &[f64; 9]) -> [usize; 3] {
    use num_traits::Signed;
    let radius = delta - r + eps;
    let Ok(beta) = unit_circle_point(&tb) else {
        return [0; 3];
    };
    let Ok(gamma) = unit_circle_point(&tg) else {
        return [0; 3];
    };
    let base = CylinderSphere {
        a,
        b,
        r,
        beta,
        gamma,
        center: Vec3::new(0.0, 0.0, 0.0),
        radius,
    };
    let (q, dir) = base.axis();
    let e1 = CylinderSphere {
        a: 1.0,
        b: 0.0,
        ..base.clone()
    }
    .axis()
    .0 - CylinderSphere {
        a: 0.0,
        b: 0.0,
        ..base.clone()
    }
    .axis()
    .0;
    let c = Vec3::new(
        q.x + delta * e1.x + h * dir.x,
        q.y + delta * e1.y + h * dir.y,
        q.z + delta * e1.z + h * dir.z,
    );
    let inputs = [a, b, r, tb, tg, c.x, c.y, c.z, radius, tau];
    let Ok(float) = CylinderSphereKernel.eval::<f64>(&inputs) else {
        return [0; 3];
    };
    let exact_in: Option<Vec<Rational>> = inputs
        .iter()
        .map(|x| Rational::from_f64_exact(*x))
        .collect();
    let Some(exact_in) = exact_in else {
        return [0; 3];
    };
    let Ok(exact) = CylinderSphereKernel.eval::<Rational>(&exact_in) else {
        return [0; 3];
    };
    let (fd, ed) = (float[2], exact[2].to_big_rational());
    [
        usize::from(ed.is_zero_value()),
        usize::from(fd >= 0.0 && ed.is_negative()),
        usize::from(fd < 0.0 && !ed.is_negative()),
    ]
}

trait ZeroValue {
    fn is_zero_value(&self) -> bool;
}

impl ZeroValue for num_rational::BigRational {
    fn is_zero_value(&self) -> bool {
        num_traits::Zero::is_zero(self)
    }
}

fn sign_errors_near_tangency(samples: usize, seed: u64) -> String {
    let s = sign_errors(samples, seed);
    format!(
        "signs of A^2 - B near tangency ({} nearly tangent configurations, R - (delta - r) log-uniform in +-[1e-15, 1e-6], tau in +-[1e-8, 1e-2], seed {seed}):\n  f64 says real where exact says none: {}\n  f64 says none where exact says real: {}\n  exactly zero: {}",
        s.samples, s.false_real, s.false_empty, s.exact_zero
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_errors_are_measured() {
        let gen = generator(Kernel::CylinderSphere).unwrap();
        let r = root_errors(&gen, 500, 3);
        assert!(r.compared > 20, "{r:?}");
        assert!(r.max_ulps >= r.median_ulps && r.median_ulps >= 0.0);
        // Roots of well-separated quadratics are accurate to a few ulps in most samples.
        assert!(r.median_ulps < 16.0, "{r:?}");
        assert_eq!(r, root_errors(&gen, 500, 3));
    }

    /// The samples are measured in parallel: one thread and several give the same counts,
    /// worst sample and median.
    #[test]
    fn root_and_sign_errors_do_not_depend_on_the_number_of_threads() {
        let gen = generator(Kernel::CylinderSphere).unwrap();
        let on = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| (root_errors(&gen, 700, 9), sign_errors(3000, 9)))
        };
        let one = on(1);
        assert!(one.0.compared > 20 && one.1.samples == 3000, "{one:?}");
        assert_eq!(one, on(4));
    }

    #[test]
    fn sqrt_to_256_bits() {
        use num_traits::Signed;
        let two = num_rational::BigRational::from_integer(2.into());
        let s = sqrt_256(&two);
        let err = (&s * &s - &two).abs();
        assert!(
            err < num_rational::BigRational::new(1.into(), num_bigint::BigInt::from(1) << 250u32)
        );
        let nine_quarters = num_rational::BigRational::new(9.into(), 4.into());
        assert_eq!(
            sqrt_256(&nine_quarters),
            num_rational::BigRational::new(3.into(), 2.into())
        );
    }

    #[test]
    fn sign_errors_near_tangency_are_found_deterministically() {
        let a = sign_errors(5000, 1);
        assert_eq!(a, sign_errors(5000, 1));
        // f64 decides the wrong side of tangency in some of these configurations.
        assert!(a.false_real + a.false_empty > 0, "{a:?}");
        assert!(a.false_real + a.false_empty < a.samples / 10, "{a:?}");
    }
}
