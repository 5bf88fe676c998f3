//! The command line: parsing (clap) and dispatch. Every error a user can cause is reported as one
//! line on standard error with exit status 2 (a usage error adds one hint line); nothing a user
//! types makes the tool panic, and a closed standard output ends the run quietly (status 0).
//!
//! This module depends on the commands, never the reverse: each command module exposes its
//! arguments and `run(&Args) -> Result<ExitCode, Error>` ([`crate::verify_cmd`],
//! [`crate::prove_cmd`], [`crate::regress`], [`crate::plot`]); shared argument
//! types live in [`crate::args`], the output writer in [`crate::output`].

use clap::error::ErrorKind;
use clap::{CommandFactory, Parser, Subcommand};
use std::ffi::OsString;
use std::io::Write as _;
use std::process::ExitCode;

pub use crate::args::ScalarChoice;

/// Verify geometry formulas exactly: prove them, check them on exact instances, and regress float
/// code against exact results.
#[derive(Debug, Parser)]
#[command(name = "exactcheck", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
    /// Raise or lower a resource limit for this run, e.g. `--limit depth=1000` (repeatable;
    /// `exactcheck limits` lists every limit with its value).
    #[arg(long = "limit", value_name = "NAME=VALUE", global = true, action = clap::ArgAction::Append)]
    pub limits: Vec<String>,
    /// End the command with an error (exit status 2) when it has not finished after SECONDS.
    #[arg(
        long,
        value_name = "SECONDS",
        global = true,
        allow_negative_numbers = true
    )]
    pub timeout: Option<f64>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check the built-in claim catalogue (every claim of the claim list: juttler.*, spaeth.*, planes.*,
    /// chiang.*) and print each verdict with its method and evidence. Exit 0 when every verdict is
    /// the expected one.
    #[command(after_help = VERIFY_EXAMPLES)]
    Verify(crate::verify_cmd::VerifyArgs),
    /// Prove an identity LHS = RHS of polynomials or rational functions, for all values, modulo
    /// relations or inside domains (`--where`): `proved` (with the divisors that must not
    /// vanish); `fails` with an exact counter-example and what the sides differ by; or
    /// `undecided` when neither is found. Expressions: numbers, variables, + - * / ^,
    /// parentheses, and the functions sqrt(E) (the non-negative root, also of a fraction), a
    /// constant to a rational power (2^(1/3): the real root),
    /// abs(E) (= sqrt(E^2)), diff(E, t) and diff(E, t, k) (the
    /// exact derivative in the variable t, k times), integrate(E, t, a, b) (the definite
    /// integral of a polynomial in t), sum(k, a, b, E) (over the integers k from a to b),
    /// binomial(n, k) and factorial(n) (integer constants), sin, cos and tan of angles (integer
    /// combinations of angle variables plus rational multiples of the constant pi, decided
    /// modulo cos(x)^2 + sin(x)^2 = 1). `--random K`: `holds`/`fails`/`undecided` with a proved
    /// error bound (all of these except square roots of non-constants; no domains).
    #[command(after_help = PROVE_EXAMPLES)]
    Prove(crate::prove_cmd::ProveArgs),
    /// Solve one problem given in JSON (a file, or `-` / nothing for standard input) and print
    /// the answer in JSON. Kinds and fields: see docs/solve.md.
    #[command(after_help = SOLVE_EXAMPLES)]
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
        /// Print the JSON Schema of KIND's problem input (the files of `docs/schema/`) instead
        /// of solving.
        #[arg(long, value_name = "KIND", conflicts_with_all = ["file", "exact", "float", "both"])]
        schema: Option<String>,
    },
    /// Regress float code against exact results on seeded random inputs: a built-in kernel,
    /// a formula (--formula), FPCore benchmarks (--fpcore), or your own executable (--program).
    #[command(after_help = REGRESS_EXAMPLES)]
    Regress(crate::regress::RegressArgs),
    /// Merge the JSON shard reports of `regress --shard I/N` into the report of the whole sweep.
    #[command(after_help = MERGE_EXAMPLES)]
    Merge(crate::regress::sweep::MergeArgs),
    // --- plot (src/plot/) ---
    /// Draw Spaeth's cylinder/sphere intersection as an SVG figure: the t-u diagram (the
    /// paper's Fig. 2 / 3) or a 3D view, for `spaeth --example N` or a `cylinder_sphere` problem
    /// file.
    #[command(after_help = PLOT_EXAMPLES)]
    Plot(crate::plot::PlotArgs),
    // --- end plot ---
    /// Write the verification report, one self-contained HTML page DIR/index.html: the verdict
    /// of every claim, the errata, the figures and the float-vs-exact regressions (e.g.
    /// `exactcheck report -o out`).
    #[command(after_help = "Examples:
  exactcheck report -o out
  exactcheck report -o out --samples 5000 --seed 7
  exactcheck report paper.toml -o paper-report")]
    Report(crate::report::ReportArgs),
    /// List the resource limits (sizes, depths, counts, memory) with their values and defaults;
    /// `--limit NAME=VALUE` before or after any subcommand changes one for that run.
    #[command(after_help = LIMITS_EXAMPLES)]
    Limits {
        /// Print the list as JSON.
        #[arg(long)]
        json: bool,
    },
}

// The examples of every subcommand's `--help` (a test parses each `exactcheck ...` line).
const VERIFY_EXAMPLES: &str = "Examples:
  exactcheck verify
  exactcheck verify --only spaeth --json";
const PROVE_EXAMPLES: &str = "Examples:
  exactcheck prove '(a+b)^2' 'a^2 + 2 a b + b^2'
  exactcheck prove 'c^2 x^3 + s^2 x^3 - x' 'x^3 - x' --where 'c^2 + s^2 = 1'
  exactcheck prove 'x^2 + 1' '2 x' --where 'x >= 0'
  exactcheck prove '((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2' 1
  exactcheck prove 'diff(t^3/(1+t), t)' '(2*t^3+3*t^2)/(1+t)^2'
  exactcheck prove 'sum(i, 0, 3, binomial(3, i) t^i (1-t)^(3-i))' 1
  exactcheck prove 'integrate((1+t)^2 + t^2, t, 0, 1)' 8/3
  exactcheck prove 'sin(3x)' '3 sin(x) - 4 sin(x)^3'
  exactcheck prove 'tan(x + pi/4)' '(1 + tan(x))/(1 - tan(x))'
  exactcheck prove '(x+y)^20' '(y+x)^20' --random 20 --seed 7";
const SOLVE_EXAMPLES: &str = "Examples:
  exactcheck solve tests/solve_golden/cs_example1.json
  exactcheck solve --both tests/solve_golden/conic_table1_ellipse.json
  exactcheck solve --schema cylinder_sphere";
const REGRESS_EXAMPLES: &str = "Examples:
  exactcheck regress cylinder-sphere --samples 100000
  exactcheck regress --formula 'sqrt(x+1) - sqrt(x)' --domain 'x in [1, 1e15]'
  exactcheck regress --fpcore tests/regress/suite.fpcore
  exactcheck regress --formula 'sqrt(x+1) - sqrt(x)' --domain 'x in [1, 1e15]' --program 'python3 tests/regress/cancel.py'
  exactcheck regress --formula 'x*x - 1' --samples 1000000 --shard 1/4 > shard1.json";
const LIMITS_EXAMPLES: &str = "Examples:
  exactcheck limits
  exactcheck limits --limit depth=1000 --json
  exactcheck prove '(x+y)^3000' 0 --limit terms=5000 --timeout 10";
const MERGE_EXAMPLES: &str = "Examples:
  exactcheck merge shard1.json shard2.json shard3.json shard4.json";
const PLOT_EXAMPLES: &str = "Examples:
  exactcheck plot spaeth --example 2 --view 3d -o spaeth2.svg
  exactcheck plot conics -o conics.svg
  exactcheck plot tests/solve_golden/cs_example1.json -o cs.svg";

/// Parses the command line, runs it, and maps errors to exit status 2 (a broken pipe on
/// standard output to status 0, silently).
pub fn main() -> ExitCode {
    crate::budget::keep_freed_memory();
    crate::output::ignore_sigxfsz();
    let args: Vec<OsString> = std::env::args_os().collect();
    let cli = match parse(&args) {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    let result = run(cli);
    crate::budget::defer_to_ending();
    match result {
        Ok(code) => code,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            crate::budget::clear_progress();
            report(&[format!("exactcheck: error: {e}")]);
            ExitCode::from(2)
        }
    }
}

/// Writes lines to standard error; a failing standard error has nowhere to be reported.
fn report(lines: &[String]) {
    let mut err = std::io::stderr().lock();
    for l in lines {
        let _ = writeln!(err, "{l}");
    }
}

/// What a command line that does not parse produces.
#[derive(Debug, PartialEq, Eq)]
pub enum ParseFailure {
    /// Help or version text to print on standard output (exit status 0).
    Text(String),
    /// A usage error: one line naming what is wrong and one hint line (exit status 2).
    Usage {
        /// What is wrong (clap's first line, without its `error: ` prefix).
        message: String,
        /// What to do: clap's tip if it has one, else where the help is.
        hint: String,
    },
}

/// Parses `args` (the program name first) without printing anything.
///
/// # Errors
/// [`ParseFailure`]: help or version text, or a usage error shortened to one line plus a hint
/// (clap's own messages are 3-16 lines with the usage and a help pointer). An argument that is
/// not valid UTF-8 is named: by the option it is the value of, or by its position.
pub fn try_parse(args: &[OsString]) -> Result<Cli, ParseFailure> {
    if let Some(message) = non_utf8_argument(args) {
        return Err(ParseFailure::Usage {
            hint: "arguments must be valid UTF-8".into(),
            message,
        });
    }
    let e = match Cli::try_parse_from(args) {
        Ok(cli) => return Ok(cli),
        Err(e) => e,
    };
    let text = e.render().to_string();
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        return Err(ParseFailure::Text(text));
    }
    let path = subcommand_path(args);
    let help = format!("see `exactcheck{} --help`", path.concat());
    let message = if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        format!("`exactcheck{}` needs a subcommand", path.concat())
    } else {
        one_line(&text, e.kind())
    };
    let hint = text
        .lines()
        .map(str::trim)
        .find_map(|l| l.strip_prefix("tip: "))
        .map_or(help.clone(), |tip| format!("{tip}; {help}"));
    Err(ParseFailure::Usage { message, hint })
}

/// clap's rendered error `text` on one line: its first paragraph (a list such as the missing
/// arguments follows its heading on the next lines) without the `error: ` prefix.
pub fn one_line(text: &str, kind: ErrorKind) -> String {
    let first: Vec<&str> = text
        .lines()
        .map(str::trim)
        .skip_while(|l| l.is_empty())
        .take_while(|l| !l.is_empty())
        .collect();
    let first = first.join(" ");
    match first.strip_prefix("error: ") {
        Some(rest) => rest.to_string(),
        None if first.is_empty() => format!("invalid command line ({kind})"),
        None => first,
    }
}

/// [`try_parse`], printing help or a usage error; `Err` holds the exit status.
fn parse(args: &[OsString]) -> Result<Cli, ExitCode> {
    match try_parse(args) {
        Ok(cli) => Ok(cli),
        Err(ParseFailure::Text(text)) => match crate::output::print(text) {
            Err(e) if !e.is_broken_pipe() => {
                report(&[format!("exactcheck: error: {e}")]);
                Err(ExitCode::from(2))
            }
            _ => Err(ExitCode::SUCCESS),
        },
        Err(ParseFailure::Usage { message, hint }) => {
            let e = crate::Error::Usage(message);
            report(&[
                format!("exactcheck: error: {e}"),
                format!("exactcheck: hint: {hint}"),
            ]);
            Err(ExitCode::from(2))
        }
    }
}

/// The subcommands named in `args` (e.g. `[" plot"]`), each with a leading space.
fn subcommand_path(args: &[OsString]) -> Vec<String> {
    let mut cmd = Cli::command();
    let mut path = Vec::new();
    for a in args.iter().skip(1) {
        let a = a.to_string_lossy();
        if a.starts_with('-') {
            continue;
        }
        let Some(sub) = cmd.find_subcommand(a.as_ref()).cloned() else {
            break;
        };
        path.push(format!(" {}", sub.get_name()));
        cmd = sub;
    }
    path
}

/// The first argument that is not valid UTF-8, named: "the value of --only" when it follows
/// (or is joined by `=` to) an option that takes a value, else "argument N".
fn non_utf8_argument(args: &[OsString]) -> Option<String> {
    let i = (1..args.len()).find(|&i| args[i].to_str().is_none())?;
    let lossy = args[i].to_string_lossy();
    let shown = format!("{lossy:?}").replace('\u{FFFD}', "\\u{FFFD}");
    let joined = lossy
        .strip_prefix("--")
        .and_then(|l| l.split_once('='))
        .map(|(name, _)| format!("--{name}"));
    let previous = (i > 1)
        .then(|| args[i - 1].to_str())
        .flatten()
        .filter(|p| p.starts_with('-') && !p.contains('=') && option_takes_value(args, p))
        .map(str::to_string);
    Some(match joined.or(previous) {
        Some(opt) => format!("the value of {opt} is not valid UTF-8: {shown}"),
        None => format!("argument {i} is not valid UTF-8: {shown}"),
    })
}

/// Whether `opt` (`--name` or `-x`) is an option taking a value of the subcommand in `args`.
fn option_takes_value(args: &[OsString], opt: &str) -> bool {
    let mut cmd = Cli::command();
    for name in subcommand_path(args) {
        match cmd.find_subcommand(name.trim()).cloned() {
            Some(sub) => cmd = sub,
            None => break,
        }
    }
    let found = cmd.get_arguments().any(|a| {
        let named = match opt.strip_prefix("--") {
            Some(long) => a.get_long() == Some(long),
            None => opt.len() == 2 && a.get_short() == opt.chars().nth(1),
        };
        named && a.get_action().takes_values()
    });
    found
}

/// Runs a parsed command line.
///
/// # Errors
/// The command's error; [`crate::Error::Output`] when standard output fails.
pub fn run(cli: Cli) -> Result<ExitCode, crate::Error> {
    for arg in &cli.limits {
        crate::limits::set_from_str(arg).map_err(crate::Error::Usage)?;
    }
    let Some(stack) = stack_for_depth()? else {
        // The default depth: the main thread's stack and rayon's defaults are enough, so the
        // command stays on the main thread.
        return run_command(cli, None);
    };
    // Rayon's workers check claims and samples, which walk expressions too: they get the
    // command thread's stack.
    let worker = std::thread::Builder::new()
        .name("exactcheck".into())
        .stack_size(stack)
        .spawn(move || run_command(cli, Some(stack)))
        .map_err(|e| {
            crate::Error::Usage(format!(
                "cannot reserve {} MiB of stack for --limit depth={} ({e}); lower the depth limit",
                stack >> 20,
                exactcheck_core::limits::DEPTH.get()
            ))
        })?;
    match worker.join() {
        Ok(result) => result,
        Err(panic) => std::panic::resume_unwind(panic),
    }
}

/// The largest value of the `depth` limit: every nesting level of an expression or document
/// costs stack in the recursive parser, evaluator and destructor, and the stack is reserved
/// for the whole limit up front ([`STACK_PER_LEVEL`]).
pub const MAX_DEPTH: u64 = 65_536;

/// Stack reserved per level of the `depth` limit, on top of `BASE_STACK`. Nested parentheses
/// in `prove` (parse, expand, drop) need at most about 1 KiB per level: the main thread's 8 MiB
/// held 4,000 of them (8,000 levels) and overflowed at 8,000. This is sixteen times that;
/// `tests/cli/robust_cli.rs` runs `prove` and a claims file (parentheses and signs) at
/// [`MAX_DEPTH`].
pub const STACK_PER_LEVEL: usize = 16 << 10;

/// Stack of the command's thread and of rayon's workers below any depth (the main thread's
/// usual 8 MiB).
const BASE_STACK: usize = 8 << 20;

/// The stack the `depth` limit in force needs (only reserved address space: pages are
/// committed as they are touched); `None` at or below the default depth, for which the main
/// thread's and rayon's usual stacks suffice.
///
/// # Errors
/// [`crate::Error::Usage`] when the limit is above [`MAX_DEPTH`]: deeper nesting would
/// overflow the stack, which aborts the process instead of answering with an error.
fn stack_for_depth() -> Result<Option<usize>, crate::Error> {
    let limit = &exactcheck_core::limits::DEPTH;
    let depth = limit.get();
    if depth > MAX_DEPTH {
        return Err(crate::Error::Usage(format!(
            "--limit depth: at most {MAX_DEPTH} levels (found {depth}): every level needs stack"
        )));
    }
    if depth <= limit.default_value() {
        return Ok(None);
    }
    // At most 65,536 * 16 KiB = 1 GiB, which fits a usize on every supported target.
    Ok(Some(BASE_STACK + depth as usize * STACK_PER_LEVEL))
}

/// The command itself, on the thread [`run`] gives it; rayon's workers get `stack` bytes of
/// stack (their default when `None`).
fn run_command(cli: Cli, stack: Option<usize>) -> Result<ExitCode, crate::Error> {
    crate::budget::enforce_memory_limit();
    crate::budget::start_thread_pool(stack)?;
    if let Some(seconds) = cli.timeout {
        crate::budget::start_timeout(seconds)?;
    }
    match &cli.command {
        Command::Prove(_) => crate::budget::start_progress("prove"),
        Command::Solve { .. } => crate::budget::start_progress("solve"),
        _ => {}
    }
    match cli.command {
        Command::Limits { json } => print_limits(json),
        Command::Verify(args) => crate::verify_cmd::run(&args),
        Command::Solve {
            file,
            exact: _,
            float,
            both,
            schema,
        } => {
            if let Some(kind) = schema {
                crate::output::print(crate::solve::schema(&kind)?)?;
                return Ok(ExitCode::SUCCESS);
            }
            let mode = if both {
                crate::solve::Mode::Both
            } else if float {
                crate::solve::Mode::Float
            } else {
                crate::solve::Mode::Exact
            };
            let text = crate::solve::read_problem(file.as_deref())?;
            let answer = crate::solve::solve(&text, mode)?;
            crate::output::println(format_args!("{answer:#}"))?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Prove(args) => crate::prove_cmd::run(&args),
        Command::Regress(args) => crate::regress::run(&args),
        Command::Merge(args) => crate::regress::sweep::merge_cmd(&args),
        // --- plot (src/plot/) ---
        Command::Plot(args) => crate::plot::run(&args),
        // --- end plot ---
        Command::Report(args) => crate::report::run(&args),
    }
}

/// `exactcheck limits`: every limit, its value in force, its default and what it bounds.
fn print_limits(json: bool) -> Result<ExitCode, crate::Error> {
    let all = crate::limits::all();
    if json {
        let list: Vec<serde_json::Value> = all
            .iter()
            .map(|l| {
                serde_json::json!({
                    "name": l.name(), "value": l.get(), "default": l.default_value(),
                    "unit": l.unit(), "what": l.what(),
                })
            })
            .collect();
        crate::output::println(serde_json::Value::Array(list))?;
    } else {
        let mut text = format!("{:<16} {:>12} {:>12}  what\n", "limit", "value", "default");
        for l in all {
            let unit = if l.unit().is_empty() {
                String::new()
            } else {
                format!(" ({})", l.unit())
            };
            text.push_str(&format!(
                "{:<16} {:>12} {:>12}  {}{unit}\n",
                l.name(),
                l.get(),
                l.default_value(),
                l.what()
            ));
        }
        crate::output::print(text)?;
    }
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(a: &[&str]) -> Vec<OsString> {
        std::iter::once("exactcheck")
            .chain(a.iter().copied())
            .map(OsString::from)
            .collect()
    }

    #[test]
    fn usage_errors_are_one_line_and_a_hint() {
        let Err(ParseFailure::Usage { message, hint }) = try_parse(&args(&["verify", "--nope"]))
        else {
            panic!("a usage error");
        };
        assert_eq!(message, "unexpected argument '--nope' found");
        assert!(!message.contains('\n') && !hint.contains('\n'));
        assert!(hint.ends_with("see `exactcheck verify --help`"), "{hint}");
        assert!(matches!(
            try_parse(&args(&["--help"])),
            Err(ParseFailure::Text(t)) if t.contains("Usage:")
        ));
        assert!(try_parse(&args(&["regress", "cylinder-sphere", "--samples", "7"])).is_ok());
        let Err(ParseFailure::Usage { message, .. }) =
            try_parse(&args(&["regress", "cylinder-sphere", "--formula", "x"]))
        else {
            panic!("a usage error");
        };
        assert!(message.contains("cannot be used with"), "{message}");
        assert!(try_parse(&args(&["regress", "--shard", "0/2"])).is_err());
        assert!(try_parse(&args(&["merge"])).is_err());
    }

    /// Every `exactcheck ...` line of every subcommand's `--help` examples is a valid command
    /// line (so an example cannot rot when an option is renamed).
    #[test]
    fn help_examples_parse() {
        let mut seen = 0;
        for sub in Cli::command().get_subcommands() {
            let help = sub
                .get_after_help()
                .unwrap_or_else(|| panic!("`{}` has no examples", sub.get_name()))
                .to_string();
            for line in help.lines().map(str::trim) {
                let Some(rest) = line.strip_prefix("exactcheck ") else {
                    continue;
                };
                let rest = rest.split(" > ").next().expect("split yields one piece");
                let words = shlex::split(rest).unwrap_or_else(|| panic!("{line}: quoting"));
                let words: Vec<&str> = words.iter().map(String::as_str).collect();
                if let Err(e) = try_parse(&args(&words)) {
                    panic!("the example `{line}` does not parse: {e:?}");
                }
                seen += 1;
            }
        }
        assert!(seen >= 20, "{seen} examples");
    }

    #[cfg(unix)]
    #[test]
    fn invalid_utf8_names_the_argument() {
        use std::os::unix::ffi::OsStringExt;
        let bad = OsString::from_vec(b"caf\xe9".to_vec());
        let mut a = args(&["verify", "--only"]);
        a.push(bad.clone());
        assert_eq!(
            non_utf8_argument(&a).unwrap(),
            "the value of --only is not valid UTF-8: \"caf\\u{FFFD}\""
        );
        let mut a = args(&["plot"]);
        a.push(bad);
        assert_eq!(
            non_utf8_argument(&a).unwrap(),
            "argument 2 is not valid UTF-8: \"caf\\u{FFFD}\""
        );
        let mut a = args(&["verify"]);
        a.push(OsString::from_vec(b"--only=\xff".to_vec()));
        assert!(non_utf8_argument(&a)
            .unwrap()
            .starts_with("the value of --only is not valid UTF-8"));
    }
}
