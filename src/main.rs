//! `exactcheck`: the command-line tool. See the README for the commands.

use std::process::ExitCode;

fn main() -> ExitCode {
    exactcheck::cli::main()
}
