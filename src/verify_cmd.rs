//! `exactcheck verify`: the claim catalogue's verdicts as a table or JSON.

use crate::Error;
use clap::Args;
use std::process::ExitCode;

/// Arguments of `exactcheck verify`.
#[derive(Debug, Args)]
pub struct VerifyArgs {
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

/// Runs `exactcheck verify`: exit status 0 when every verdict is the expected one, else 1.
///
/// # Errors
/// [`Error::Usage`] for a prefix no claim has; [`Error::Output`] when standard output fails.
pub fn run(args: &VerifyArgs) -> Result<ExitCode, Error> {
    let rows = crate::claims::verify(args.only.as_deref())?;
    if args.json {
        let arr: Vec<_> = rows.iter().map(|r| r.to_json()).collect();
        crate::output::println(serde_json::Value::Array(arr))?;
    } else if args.latex {
        crate::output::println(crate::claims::latex::document(&rows).trim_end())?;
    } else {
        crate::output::println(crate::claims::table(&rows))?;
    }
    Ok(if rows.iter().all(|r| r.as_expected()) {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
