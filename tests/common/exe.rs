//! The binary under test: every test that runs the command line starts it through
//! [`exactcheck`] (or passes [`EXACTCHECK`] to a shell that execs it).

use std::process::Command;

/// The path of the `exactcheck` binary that cargo built for these tests.
#[allow(dead_code)] // not every test crate runs the binary through a shell
pub const EXACTCHECK: &str = env!("CARGO_BIN_EXE_exactcheck");

/// A command that runs the binary under test; add arguments, input, a working directory or
/// environment to it.
#[allow(dead_code)] // not every test crate that includes this module runs the binary itself
pub fn exactcheck() -> Command {
    Command::new(EXACTCHECK)
}
