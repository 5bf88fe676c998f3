//! `exactcheck report [FILE] -o DIR`: the verification report as one self-contained HTML page,
//! `DIR/index.html`, to send to a colleague or an editor.
//!
//! The page ([`html`]) holds, in order:
//! * a header: what was checked, the command line, the date (UTC), exactcheck's version, the
//!   git commit and rustc it was built with, the num-bigint and num-rational versions the build
//!   locked (`build.rs`), the machine ([`meta`]);
//! * the verdict table of every claim (`#verdicts`, rows with `data-source`/`data-verdict`,
//!   filterable by source and verdict with a small inline script; without JavaScript every row
//!   shows);
//! * the errata (`#errata`): every claim whose check found the printed statement false, with
//!   the printed and the correct form, the exact counter-example and the residual there from
//!   the check's [`crate::claims::Erratum`] (or its evidence when the check gives none);
//! * for the built-in catalogue, every figure of [`crate::papers::figures`] inline as
//!   SVG, ids and style rules isolated per figure ([`inline_svg`]), and the float-vs-exact
//!   regression summaries of the four built-in kernels on `--samples` seeded samples
//!   ([`regress`]);
//! * with `--regress FILE`, the saved `regress --json` run: each formula's table and its worst
//!   samples explained (local error per operation, conditioning), as `regress` printed them.
//!
//! Nothing is loaded from the network: the style sheet and the script are inline, the fonts
//! are the system's, and the page's content security policy forbids every other load.

pub mod html;
pub mod inline_svg;
pub mod meta;
pub mod regress;

use crate::claims::Checked;
use crate::Error;
use clap::Args;
use std::path::Path;
use std::process::ExitCode;

/// The largest `--samples` of `report` (the regressions are its slowest part: the ruled-plane
/// kernel runs 12 sweeps of this many samples).
pub const MAX_REPORT_SAMPLES: usize = 200_000;

/// Arguments of `exactcheck report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    /// A claims file (TOML or JSON) to check instead of the built-in catalogue.
    pub file: Option<String>,
    /// The directory to write `index.html` into (created when missing, once the page is
    /// complete; not empty and not `-`: the page is a file in a directory, not standard output).
    #[arg(short = 'o', long = "output", value_name = "DIR")]
    pub output: String,
    /// Samples of each float-vs-exact regression (of each shape and regime for ruled-plane),
    /// at most 200,000. The whole report takes 3.2 s with the default on an idle 2-core machine.
    #[arg(long, default_value_t = 1000)]
    pub samples: usize,
    /// Seed of the regressions' inputs.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// A saved run of `exactcheck regress --formula/--fpcore ... --json` (or of `merge`) to
    /// add to the page: each formula's table and its worst samples with the local error of
    /// each operation and the conditioning there.
    #[arg(long, value_name = "FILE")]
    pub regress: Option<String>,
    /// No progress bar (it is shown only when standard error is a terminal).
    #[arg(long)]
    pub quiet: bool,
}

/// The claims of `file` checked, or of the built-in catalogue when `None`.
///
/// # Errors
/// [`Error::Input`] for a claims file until the claims-file reader is merged; the catalogue's
/// own errors otherwise.
pub fn checked_claims(file: Option<&str>) -> Result<Vec<Checked>, Error> {
    match file {
        None => crate::papers::verify(None),
        Some(path) => {
            let file = crate::claimfile::load(Path::new(path))?;
            crate::claimfile::check(&file, None)
        }
    }
}

/// Runs `exactcheck report`: checks the claims, draws the figures, runs the regressions,
/// writes `DIR/index.html` and prints one summary line. Exit status 0 once the page is written
/// (the page itself says which verdicts are not the expected ones). The output directory is
/// checked first and created last, once the page is complete; the page replaces
/// `DIR/index.html` whole ([`crate::output::write_file`]).
///
/// # Errors
/// [`Error::Usage`] for `--samples` out of range or an output directory that is empty, `-` or
/// a file; the claims file's errors; [`Error::Write`] when the directory or the page cannot be
/// written; [`Error::Output`] when standard output fails.
pub fn run(args: &ReportArgs) -> Result<ExitCode, Error> {
    crate::args::check_count("--samples", args.samples, MAX_REPORT_SAMPLES, "")?;
    crate::output::check_output_dir(&args.output)?;
    let argv: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let meta = meta::Meta::now(&argv);
    let catalogue = args.file.is_none();
    let steps = crate::output::Steps::new(
        if catalogue {
            2 + regress::KERNELS.len() as u64
        } else {
            1
        },
        args.quiet,
    );

    steps.start(match &args.file {
        None => "checking the built-in catalogue",
        Some(_) => "checking the claims file",
    });
    let rows = checked_claims(args.file.as_deref())?;
    steps.done();

    let (figures, regressions, subject, note) = if catalogue {
        steps.start("drawing the figures");
        let figures = crate::papers::figures()?;
        steps.done();
        let mut summaries = Vec::new();
        for kernel in regress::KERNELS {
            steps.start(&format!("regress {kernel} ({} samples)", args.samples));
            summaries.push(regress::summary(kernel, args.samples, args.seed)?);
            steps.done();
        }
        let mut sources: Vec<&str> = Vec::new();
        for r in &rows {
            if !sources.contains(&r.source.as_str()) {
                sources.push(&r.source);
            }
        }
        (
            figures,
            summaries,
            format!("the built-in claim catalogue ({})", sources.join(", ")),
            None,
        )
    } else {
        let path = args.file.as_deref().unwrap_or_default();
        let mut papers: Vec<&str> = Vec::new();
        for r in &rows {
            if !papers.contains(&r.source.as_str()) {
                papers.push(&r.source);
            }
        }
        (
            Vec::new(),
            Vec::new(),
            format!("the claims file {path} (paper: {})", papers.join(", ")),
            Some(
                "Figures and float-vs-exact regressions belong to the built-in catalogue (run `exactcheck report` without FILE)."
                    .to_string(),
            ),
        )
    };
    drop(steps);
    let (mut regressions, mut note) = (regressions, note);
    if let Some(path) = &args.regress {
        let text = crate::solve::read_problem(Some(path))?;
        let entries = crate::regress::sweep::read_document(&text, path)?;
        regressions.extend(entries.iter().map(|e| regress::saved_summary(e, path)));
        note = None;
    }

    let page = html::page(&html::Page {
        subject,
        meta: &meta,
        rows: &rows,
        figures: &figures,
        regressions: &regressions,
        note,
    })?;
    let index = Path::new(&args.output).join("index.html");
    let inputs: Vec<&Path> = args
        .file
        .iter()
        .chain(args.regress.iter())
        .map(Path::new)
        .collect();
    let created = crate::output::create_dirs(&args.output)?;
    let written = crate::output::write_file(&index.to_string_lossy(), page.as_bytes(), &inputs);
    if written.is_err() {
        crate::output::remove_created_dirs(&created);
    }
    written?;
    let errata = rows.iter().filter(|r| html::is_erratum(r)).count();
    crate::output::println(format_args!(
        "wrote {}: {} claims ({errata} errata), {} figures, {} regression summaries",
        index.display(),
        rows.len(),
        figures.len(),
        regressions.len()
    ))?;
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_claims_file_is_checked_by_the_claims_file_reader() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/mypaper.toml");
        let rows = checked_claims(Some(path)).expect("the example file checks");
        assert_eq!(rows.len(), 5);
        assert!(rows.iter().all(|r| r.source == "mypaper"));
        let Err(e) = checked_claims(Some("no/such/paper.toml")) else {
            panic!("a missing file is an error");
        };
        assert!(e.to_string().contains("no/such/paper.toml"), "{e}");
    }
}
