//! Formulas given as text (`--formula`), FPCore benchmarks (`--fpcore`) and the user's own
//! executable as the float side (`--program`): each becomes a [`Subject`] of the one harness
//! sweep ([`exactcheck_float::run`]).
//!
//! The exact side is [`Program::eval_exact`] (the true real value, irrational roots refined far
//! beyond double precision); the float side is [`Program::eval_f64`] (the operations in f64 in
//! the order written) or, with `--program`, the user's executable fed through
//! [`exactcheck_float::external::ProgramRunner`].

use super::explain;
use super::sweep::Entry;
use super::RegressArgs;
use crate::Error;
use exactcheck_exact::program::fpcore;
use exactcheck_exact::program::{ExactStop, Format, Program};
use exactcheck_exact::Rational;
use exactcheck_float::domain::{parse_domain, SampleDomain, Sampling};
use exactcheck_float::external::ProgramRunner;
use exactcheck_float::{
    CaseError, ExactScalar, ExactValue, FloatSideError, InputGen, Options, Subject,
};
use std::sync::Mutex;
use std::time::Duration;

/// A float program as a harness subject: exact against f64 (or against an external program).
pub struct TextSubject<'a> {
    program: &'a Program,
    runner: Option<Mutex<ProgramRunner>>,
}

impl<'a> TextSubject<'a> {
    /// The program in f64 against its exact value.
    pub fn new(program: &'a Program) -> TextSubject<'a> {
        TextSubject {
            program,
            runner: None,
        }
    }

    /// The external program `command` against the exact value of `program`.
    ///
    /// # Errors
    /// The command cannot be started (one line naming it).
    pub fn with_program(
        program: &'a Program,
        command: &str,
        timeout: Duration,
        echo_index: bool,
    ) -> Result<TextSubject<'a>, Error> {
        let mut runner = ProgramRunner::spawn(
            command,
            program.inputs.len(),
            program.outputs.len(),
            timeout,
        )
        .map_err(|e| Error::Input(e.to_string()))?;
        if echo_index {
            runner = runner.echo_index();
        }
        Ok(TextSubject {
            program,
            runner: Some(Mutex::new(runner)),
        })
    }
}

impl Subject for TextSubject<'_> {
    fn name(&self) -> String {
        self.program.name.clone()
    }
    fn arity(&self) -> usize {
        self.program.inputs.len()
    }
    fn float_side(&self) -> String {
        match &self.runner {
            None => format!("formula {}", self.program.name),
            Some(r) => format!(
                "program {}",
                r.lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner)
                    .command()
            ),
        }
    }
    fn exact(&self, x: &[f64]) -> Result<Vec<ExactValue>, CaseError> {
        // Both sides must take the same inputs: a binary32 input takes binary32 values.
        if !x
            .iter()
            .enumerate()
            .all(|(i, &v)| self.program.input_format(i).holds(v))
        {
            return Err(CaseError::InvalidInputs);
        }
        let exact_in: Vec<Rational> = x
            .iter()
            .map(|&v| Rational::from_f64_exact(v))
            .collect::<Option<_>>()
            .ok_or(CaseError::InvalidInputs)?;
        match self.program.eval_exact(&exact_in) {
            Ok(refs) => Ok(refs
                .into_iter()
                .map(|r| ExactValue {
                    value: r.value,
                    exact: r.exact,
                })
                .collect()),
            Err(ExactStop::OutsideDomain) => Err(CaseError::OutsideDomain),
            // Undecided at the precision cap, or an intermediate beyond the constant-bits limit: no
            // reference either way, counted as undecided (never guessed).
            Err(ExactStop::Undecided | ExactStop::TooLarge) => Err(CaseError::Undecided),
            Err(stop @ (ExactStop::LoopLimit | ExactStop::LoopValueLimit)) => {
                let limit = stop.limit().expect("a stop at a limit");
                Err(CaseError::LimitExceeded {
                    limit: limit.name(),
                    value: limit.get(),
                })
            }
        }
    }
    fn float(&self, index: usize, x: &[f64]) -> Result<Option<Vec<f64>>, FloatSideError> {
        match &self.runner {
            None => Ok(Some(self.program.eval_f64(x))),
            Some(r) => r
                .lock()
                .expect("the runner is used from the sweep's thread only")
                .eval_one(index, x)
                .map(Some)
                .map_err(|e| FloatSideError(e.to_string())),
        }
    }
    fn format(&self) -> Format {
        self.program.precision
    }
    fn finish(&self) -> Result<(), FloatSideError> {
        match &self.runner {
            None => Ok(()),
            Some(r) => r
                .lock()
                .expect("the runner is used from the sweep's thread only")
                .finish()
                .map_err(|e| FloatSideError(e.to_string())),
        }
    }
    fn float_batch(
        &self,
        first: usize,
        xs: &[Vec<f64>],
    ) -> Result<Vec<Option<Vec<f64>>>, FloatSideError> {
        match &self.runner {
            None => Ok(xs.iter().map(|x| Some(self.program.eval_f64(x))).collect()),
            Some(r) => Ok(r
                .lock()
                .expect("the runner is used from the sweep's thread only")
                .eval_batch(first, xs)
                .map_err(|e| FloatSideError(e.to_string()))?
                .into_iter()
                .map(Some)
                .collect()),
        }
    }
}

/// The sampling rule of `--sample` (the mixed default without it).
fn sampling(args: &RegressArgs) -> Sampling {
    args.sample
        .map_or(Sampling::Mixed, super::SampleChoice::sampling)
}

/// The harness options of a run.
fn options(args: &RegressArgs) -> Options {
    Options {
        worst: args.worst,
        ..Options::default()
    }
}

/// One sweep of a program over a domain (or near the `--near` set inside it), as an entry.
fn sweep_entry(
    args: &RegressArgs,
    program: &Program,
    gen: &impl InputGen,
    line: Option<usize>,
) -> Result<Entry, Error> {
    if args.predicate && program.outputs.len() != 1 {
        return Err(Error::Usage(format!(
            "--predicate judges the sign of one value: {} has {} outputs",
            program.name,
            program.outputs.len()
        )));
    }
    match &args.near {
        None => sweep_on(args, program, gen, line),
        Some(_) if program.precision != Format::Binary64 => Err(Error::Usage(format!(
            "--near moves samples by double ulps: not available for {}, a {} program",
            program.name,
            program.precision.name()
        ))),
        Some(_) if program.mixes_input_precisions() => Err(Error::Usage(format!(
            "--near moves samples by double ulps: not available for {}, which has inputs of another precision",
            program.name
        ))),
        Some(eq) => {
            let near = super::near::generator(eq, &program.inputs, gen, args.seed)?;
            sweep_on(args, program, &near, line)
        }
    }
}

/// One sweep of a program on inputs from `gen`, as an entry: the report with its worst cases
/// explained, the `--bin` table, the `--predicate` counts, and the `--csv` and `--html` files
/// written.
fn sweep_on(
    args: &RegressArgs,
    program: &Program,
    gen: &impl InputGen,
    line: Option<usize>,
) -> Result<Entry, Error> {
    let subject = match &args.program {
        None => TextSubject::new(program),
        Some(cmd) => TextSubject::with_program(
            program,
            cmd,
            Duration::from_secs_f64(args.program_timeout),
            args.program_echo_index,
        )?,
    };
    let mut bins = args
        .bin
        .as_deref()
        .map(|b| explain::Bins::new(b, program))
        .transpose()?;
    let mut csv = args.csv.as_ref().map(|_| explain::Csv::new(program));
    let run_samples = args
        .shard
        .map_or(args.samples, |s| s.range(args.samples).len());
    let mut points = args
        .html
        .as_ref()
        .map(|_| explain::Points::new(run_samples));
    let mut predicate = args
        .predicate
        .then(|| super::predicate::Predicate::new(args.worst, args.near.clone()));
    let progress = args.progress(&program.name);
    let mut observe = |s: &exactcheck_float::Observed<'_>| {
        if let Some(p) = &mut predicate {
            p.add(s);
        }
        if let Some(b) = &mut bins {
            b.add(s)?;
        }
        if let Some(c) = &mut csv {
            c.add(s);
        }
        if let Some(p) = &mut points {
            p.add(s);
        }
        Ok(())
    };
    let result = exactcheck_float::run_observed(
        &subject,
        gen,
        args.sweep(),
        &options(args),
        &|done| progress.update(done),
        &mut observe,
    );
    let mut report = match result {
        Ok(r) => r,
        Err(exactcheck_float::RegressError::Observer(why)) => return Err(Error::Input(why)),
        Err(e) => return Err(Error::Input(e.to_string())),
    };
    explain::explain_report(program, &mut report, args.program.is_some());
    if let (Some(path), Some(c)) = (&args.csv, &csv) {
        crate::output::write_file(path, c.contents().as_bytes(), &[])?;
    }
    if let (Some(path), Some(p)) = (&args.html, &points) {
        let mut text = report.to_string();
        if let Some(b) = &bins {
            text.push('\n');
            text.push_str(&b.text());
        }
        let page = explain::html(program, &text, p)?;
        crate::output::write_file(path, page.as_bytes(), &[])?;
    }
    Ok(Entry {
        name: program.name.clone(),
        line,
        outcome: Ok(report),
        bins,
        predicate,
    })
}

/// Checks `--bin`, `--csv` and `--html` before any sweep: the output paths, and options that
/// a shard or several benchmarks cannot take.
fn check_outputs(args: &RegressArgs, benchmarks: usize) -> Result<(), Error> {
    for (flag, path) in [("--csv", &args.csv), ("--html", &args.html)] {
        if let Some(p) = path {
            explain::check_output(flag, p)?;
            if benchmarks > 1 {
                return Err(Error::Usage(format!(
                    "{flag} writes one benchmark's file: the FPCore file has {benchmarks}, choose one with --name"
                )));
            }
        }
    }
    if args.shard.is_some() {
        for (flag, given) in [
            ("--bin", args.bin.is_some()),
            ("--html", args.html.is_some()),
            ("--predicate", args.predicate),
        ] {
            if given {
                return Err(Error::Usage(format!(
                    "{flag} needs the whole sweep; `merge` does not combine it: leave out --shard"
                )));
            }
        }
    }
    if args.csv.is_some() && args.csv == args.html {
        return Err(Error::Usage("--csv and --html name the same file".into()));
    }
    Ok(())
}

/// `regress --formula EXPR [--formula EXPR ...] [--vars ...] [--domain ...]`: the formulas are
/// the outputs of one program.
///
/// # Errors
/// The formula or the domain does not parse, or the sweep fails (an external program).
pub fn formula_entries(args: &RegressArgs, texts: &[String]) -> Result<Vec<Entry>, Error> {
    let mut program = Program::parse_outputs(texts, args.vars.as_deref())
        .map_err(|e| Error::Input(format!("--formula: {e}")))?;
    if let Some(p) = args.precision {
        program.precision = p.format();
    }
    check_outputs(args, 1)?;
    if let Some(b) = &args.bin {
        explain::Bins::new(b, &program)?;
    }
    // No --domain: every input over all finite doubles.
    let domain = parse_domain(args.domain.as_deref().unwrap_or(""), &program.inputs)
        .map_err(|e| Error::Input(format!("--domain: {e}")))?;
    let gen = SampleDomain::named(domain, &program.inputs)
        .and_then(|d| d.with_format(program.precision))
        .and_then(|d| d.with_sampling(sampling(args)))
        .map_err(|e| Error::Input(format!("--domain: {e}")))?;
    Ok(vec![sweep_entry(args, &program, &gen, None)?])
}

/// `regress --fpcore FILE [--name NAME]`: every benchmark of the file (or the one named).
///
/// # Errors
/// The file cannot be read or has a syntax error; `--name` names no benchmark; `--program`
/// with more than one benchmark; a sweep fails (an external program).
pub fn fpcore_entries(args: &RegressArgs, path: &str) -> Result<Vec<Entry>, Error> {
    let text = crate::solve::read_problem(Some(path))?;
    let all = fpcore::parse_file(&text).map_err(|e| Error::Input(format!("{path}: {e}")))?;
    // A `:name` may hold any character: escaped, so a name stays on its line of the table.
    let label = |b: &fpcore::Benchmark| crate::error::escape_breaks(&b.display_name()).into_owned();
    let chosen: Vec<&fpcore::Benchmark> = match &args.name {
        None => all.iter().collect(),
        Some(n) => {
            let c: Vec<_> = all
                .iter()
                .filter(|b| b.name.as_deref() == Some(n))
                .collect();
            if c.is_empty() {
                let names: Vec<String> = all.iter().map(label).collect();
                return Err(Error::Usage(format!(
                    "{path} has no FPCore named '{n}' (names: {})",
                    names.join(", ")
                )));
            }
            c
        }
    };
    if chosen.is_empty() {
        return Err(Error::Input(format!("{path} contains no FPCore")));
    }
    check_outputs(args, chosen.len())?;
    if args.near.is_some() && chosen.len() > 1 {
        return Err(Error::Usage(format!(
            "--near names the inputs of one benchmark: {path} has {}, choose one with --name",
            chosen.len()
        )));
    }
    if args.program.is_some() && chosen.len() > 1 {
        return Err(Error::Usage(format!(
            "--program runs one benchmark: {path} has {}, choose one with --name",
            chosen.len()
        )));
    }
    let mut out = Vec::new();
    for b in chosen {
        let name = label(b);
        let entry = match &b.program {
            Err(unsupported) => Entry {
                name,
                line: Some(b.line),
                outcome: Err(unsupported.to_string()),
                bins: None,
                predicate: None,
            },
            Ok(program) => {
                let mut program = program.clone();
                program.name = name.clone();
                let formats: Vec<Format> = (0..program.arity())
                    .map(|i| program.input_format(i))
                    .collect();
                match SampleDomain::named(b.domain.clone(), &b.args)
                    .and_then(|d| d.with_formats(program.precision, &formats))
                    .and_then(|d| d.with_sampling(sampling(args)))
                {
                    Err(e) => Entry {
                        name,
                        line: Some(b.line),
                        outcome: Err(format!("no input to sample: {e}")),
                        bins: None,
                        predicate: None,
                    },
                    Ok(gen) => sweep_entry(args, &program, &gen, Some(b.line))?,
                }
            }
        };
        out.push(entry);
    }
    Ok(out)
}
