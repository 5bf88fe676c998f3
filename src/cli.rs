//! The command line: parsing (clap) and dispatch. Every error a user can cause is reported as one
//! line on standard error with exit status 2; nothing a user types makes the tool panic.

use crate::w2;
use clap::{Parser, Subcommand, ValueEnum};
use exactcheck_exact::{PlainRational, Rational, RationalScalar};
use std::process::ExitCode;

/// Verify geometry formulas exactly: prove them, check them on exact instances, and regress float
/// code against exact results.
#[derive(Debug, Parser)]
#[command(name = "exactcheck", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check the built-in claim catalogue (the juttler.* and spaeth.* claims of SPEC §6; planes.*
    /// and chiang.* are not implemented yet) and print each verdict with its method and
    /// evidence. Exit 0 when every verdict is the expected one.
    Verify {
        /// Print a JSON array (objects with id, verdict, method, evidence, ...) instead of a table.
        #[arg(long)]
        json: bool,
        /// Only the claims whose id starts with this prefix (e.g. `juttler`).
        #[arg(long)]
        only: Option<String>,
    },
    /// Prove a polynomial identity LHS = RHS, for all values or modulo relations (`--where`):
    /// `proved`, or `fails` with an exact counter-example and what the sides differ by.
    Prove(crate::prove_cmd::ProveArgs),
    /// Solve one problem given in JSON (a file, or `-` / nothing for standard input) and print
    /// the answer in JSON. Kinds and fields: see the README.
    Solve {
        /// The problem file; `-` or absent: standard input.
        file: Option<String>,
        /// Exact arithmetic (the default); JSON floating-point literals are refused.
        #[arg(long, conflicts_with_all = ["float", "both"])]
        exact: bool,
        /// f64 arithmetic (JSON floating-point literals accepted), where the kind allows it.
        #[arg(long, conflicts_with = "both")]
        float: bool,
        /// Exact and f64 side by side, where the kind allows it.
        #[arg(long)]
        both: bool,
    },
    /// Run a benchmark workload and print its check values and time.
    Bench {
        /// Which workload.
        #[command(subcommand)]
        workload: Workload,
    },
    /// Regress a built-in f64 kernel against exact results on seeded random inputs.
    Regress(crate::regress::RegressArgs),
    // --- plot (src/plot.rs) ---
    /// Draw Spaeth's cylinder/sphere intersection as an SVG figure: the t-u diagram (the
    /// paper's Fig. 2 / 3) or a 3D view, for `spaeth --example N` or a `cylinder_sphere` problem
    /// file.
    Plot(crate::plot::PlotArgs),
    // --- end plot ---
}

/// The benchmark workloads (see `../shared/anchors` for the same workloads in other tools).
#[derive(Debug, Subcommand)]
pub enum Workload {
    /// W2: the exact Spaeth discriminant at N rational parameters.
    W2 {
        /// Number of parameters T_k = k/1000 - 50, k = 0..N-1.
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
    /// W3: f64 sampling of the Spaeth discriminant on the grid t_i = i 2 pi / N.
    W3 {
        /// Number of samples.
        #[arg(long, default_value_t = 10_000_000)]
        n: usize,
        /// How the samples are evaluated.
        #[arg(long, value_enum, default_value_t = W3Variant::Coef)]
        variant: W3Variant,
        /// Print one JSON line instead of text.
        #[arg(long)]
        json: bool,
    },
}

/// The variants of W3.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum W3Variant {
    /// Precomputed trigonometric coefficients, all cores.
    Coef,
    /// Precomputed coefficients, one thread.
    CoefSerial,
    /// The derived formulas evaluated per sample with `sin_cos`, one thread (the baseline).
    Direct,
}

/// The exact rational types a benchmark can run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScalarChoice {
    /// exactcheck's `Rational` (inline tier, Knuth/Henrici arithmetic, Lehmer gcd).
    Fast,
    /// num-rational's `BigRational`, unchanged (the baseline).
    Plain,
}

/// Parses the command line, runs it, and maps errors to exit status 2.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("exactcheck: error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Runs a parsed command line.
pub fn run(cli: Cli) -> Result<ExitCode, crate::Error> {
    match cli.command {
        Command::Verify { json, only } => {
            let rows = crate::claims::verify(only.as_deref())?;
            if json {
                let arr: Vec<_> = rows.iter().map(|r| r.to_json()).collect();
                println!("{}", serde_json::Value::Array(arr));
            } else {
                println!("{}", crate::claims::table(&rows));
            }
            Ok(if rows.iter().all(|r| r.as_expected()) {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            })
        }
        Command::Bench {
            workload: Workload::W3 { n, variant, json },
        } => {
            if n == 0 {
                return Err(crate::Error::Usage("--n must be at least 1".into()));
            }
            println!("{}", crate::w2::bench_w3(n, variant, json));
            Ok(ExitCode::SUCCESS)
        }
        Command::Bench {
            workload:
                Workload::W2 {
                    n,
                    mode,
                    scalar,
                    json,
                },
        } => {
            let text = match scalar {
                ScalarChoice::Fast => bench_w2::<Rational>(n, mode, "fast", json),
                ScalarChoice::Plain => bench_w2::<PlainRational>(n, mode, "plain", json),
            };
            println!("{text}");
            Ok(ExitCode::SUCCESS)
        }
        Command::Solve {
            file,
            exact: _,
            float,
            both,
        } => {
            let mode = if both {
                crate::solve::Mode::Both
            } else if float {
                crate::solve::Mode::Float
            } else {
                crate::solve::Mode::Exact
            };
            let text = crate::solve::read_problem(file.as_deref())?;
            let answer = crate::solve::solve(&text, mode)?;
            println!("{answer:#}");
            Ok(ExitCode::SUCCESS)
        }
        Command::Prove(args) => crate::prove_cmd::run(&args),
        Command::Regress(args) => crate::regress::run(&args).map(|()| ExitCode::SUCCESS),
        // --- plot (src/plot.rs) ---
        Command::Plot(args) => crate::plot::run(&args).map(|()| ExitCode::SUCCESS),
        // --- end plot ---
    }
}

fn bench_w2<T: RationalScalar>(n: usize, mode: w2::Mode, scalar: &str, json: bool) -> String {
    let out = w2::run::<T>(n, mode);
    let checks = out.sum.as_ref().map(w2::check_values);
    let mode_name = format!("{mode:?}").to_lowercase();
    if json {
        let mut s = format!(
            "{{\"tool\": \"exactcheck\", \"scalar\": \"{scalar}\", \"mode\": \"{mode_name}\", \"N\": {n}, \"seconds\": {}, \"samples_per_s\": {}, \"count_nonneg\": {}",
            out.seconds,
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
