//! `exactcheck`: the command-line tool. See the README and docs/ for the commands.

use std::process::ExitCode;

/// Counts the bytes in use against the `memory` limit (see `exactcheck::budget`).
#[global_allocator]
static ALLOCATOR: exactcheck::budget::Accounting = exactcheck::budget::Accounting;

fn main() -> ExitCode {
    exactcheck::cli::main()
}
