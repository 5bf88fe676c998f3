//! `exactcheck verify [FILE]`: the verdicts of the built-in claim catalogue, or of a claims file
//! ([`crate::claimfile`]), as a table or JSON.

use crate::Error;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `exactcheck verify`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  exactcheck verify                          the built-in catalogue
  exactcheck verify --only spaeth --json     Spaeth's claims as JSON
  exactcheck verify examples/spaeth.toml     the claims of a file (TOML or JSON; see docs/verify.md)

Exit status: 0 when every claim has its expected verdict, 1 otherwise, 2 for a bad file or argument
(a claims file with a claim that cannot be built or decided: that claim's verdict is `error`, the
others are decided and reported, and the status is 2).")]
pub struct VerifyArgs {
    /// A claims file (`.toml` or `.json`): check its claims instead of the built-in catalogue.
    pub file: Option<PathBuf>,
    /// Print a JSON array (objects with id, verdict, method, evidence, ...) instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Print the errata of the failing claims as LaTeX math (a `%` comment line per part, one
    /// line per equation, no `$`) instead of a table.
    #[arg(long, conflicts_with = "json")]
    pub latex: bool,
    /// Only the claims whose id starts with this prefix (e.g. `juttler`).
    #[arg(long)]
    pub only: Option<String>,
}

/// Runs `exactcheck verify`: exit status 0 when every verdict is the expected one, 2 when a
/// claim of the file is bad input (verdict `error`), else 1.
///
/// # Errors
/// [`Error::Usage`] for a prefix no claim has; [`Error::Io`] / [`Error::Input`] for a claims
/// file that cannot be read or is malformed (one line with file, line and key);
/// [`Error::Output`] when standard output fails.
pub fn run(args: &VerifyArgs) -> Result<ExitCode, Error> {
    let rows = match &args.file {
        None => crate::papers::verify_with(args.only.as_deref(), false)?,
        Some(path) => {
            let file = crate::claimfile::load(path)?;
            let rows = crate::claimfile::check_with(&file, args.only.as_deref(), false)?;
            // Warnings about names go with a report, not with a refusal (one line).
            for w in &file.warnings {
                eprintln!("exactcheck: warning: {w}");
            }
            rows
        }
    };
    if args.json {
        let arr: Vec<_> = rows.iter().map(|r| r.to_json()).collect();
        crate::output::println(serde_json::Value::Array(arr))?;
    } else if args.latex {
        crate::output::println(crate::claims::latex::document(&rows).trim_end())?;
    } else {
        crate::output::println(crate::claims::table(&rows))?;
    }
    Ok(if rows.iter().any(|r| r.bad_input) {
        // A claim of the file cannot be built or decided: bad input, though the others were
        // decided and reported.
        ExitCode::from(2)
    } else if rows.iter().all(|r| r.as_expected()) {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
