//! Helpers shared by the CLI end-to-end tests (each `tests/*.rs` file is its own crate and
//! includes this module with `mod common;`).

use std::process::{Command, Output, Stdio};

/// Runs `exactcheck solve EXTRA...` with `problem` on standard input.
pub fn solve_stdin(problem: impl AsRef<[u8]>, extra: &[&str]) -> Output {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .arg("solve")
        .args(extra)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(problem.as_ref())
        .expect("write");
    child.wait_with_output().expect("finishes")
}
