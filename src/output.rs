//! Writing a command's standard output without panicking.
//!
//! `println!` panics when standard output is closed or full ("failed printing to stdout"). The
//! commands write through [`println()`] / [`print()`] instead, which return the failure as
//! [`Error::Output`]: [`crate::cli::main`] ends quietly with exit status 0 on a broken pipe
//! (the reader, e.g. `head -1`, has what it wanted; Rust ignores `SIGPIPE`, so the write returns
//! `EPIPE`) and reports any other failure as one line, "cannot write standard output: No space
//! left on device", with exit status 2. Every write is flushed at once, so a failure is seen
//! by the command that caused it and not later by the runtime's exit-time flush (which would
//! ignore it).

use crate::Error;
use std::fmt::Display;
use std::io::{self, Write};

/// Writes `text` and a newline to standard output and flushes it.
///
/// # Errors
/// [`Error::Output`] when the write or the flush fails (test it with
/// [`Error::is_broken_pipe`]).
pub fn println(text: impl Display) -> Result<(), Error> {
    crate::budget::clear_progress();
    write_line(&mut io::stdout().lock(), text)
}

/// Writes `text` (no newline added) to standard output and flushes it.
///
/// # Errors
/// As [`println()`].
pub fn print(text: impl Display) -> Result<(), Error> {
    crate::budget::clear_progress();
    let mut out = io::stdout().lock();
    write!(out, "{text}")
        .and_then(|()| out.flush())
        .map_err(Error::Output)
}

/// Writes `text` and a newline to any writer and flushes it, mapping a failure to
/// [`Error::Output`] (the writer stands for standard output).
///
/// # Errors
/// As [`println()`].
pub fn write_line(out: &mut impl Write, text: impl Display) -> Result<(), Error> {
    writeln!(out, "{text}")
        .and_then(|()| out.flush())
        .map_err(Error::Output)
}

/// The progress of a command's steps (claims checked, figures drawn, sweeps run) on standard
/// error: a bar on a terminal, nothing when standard error is piped or `quiet` is set.
pub struct Steps {
    bar: Option<indicatif::ProgressBar>,
}

impl Steps {
    /// A bar of `count` steps; hidden when `quiet` or when standard error is not a terminal.
    pub fn new(count: u64, quiet: bool) -> Steps {
        let bar = (!quiet && io::IsTerminal::is_terminal(&io::stderr())).then(|| {
            let bar = indicatif::ProgressBar::new(count);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:24}] {pos}/{len} {msg} ({elapsed})",
            ) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.enable_steady_tick(std::time::Duration::from_millis(120));
            bar
        });
        Steps { bar }
    }

    /// Starts the step described by `what`.
    pub fn start(&self, what: &str) {
        if let Some(bar) = &self.bar {
            bar.set_message(what.to_string());
        }
    }

    /// Ends the current step.
    pub fn done(&self) {
        if let Some(bar) = &self.bar {
            bar.inc(1);
        }
    }
}

impl Drop for Steps {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A writer that fails every write with the given error kind.
    struct Failing(io::ErrorKind);

    impl Write for Failing {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::Error::from(self.0))
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn failures_become_errors_not_panics() {
        let e = write_line(&mut Failing(io::ErrorKind::BrokenPipe), "x").unwrap_err();
        assert!(e.is_broken_pipe());
        let e = write_line(&mut Failing(io::ErrorKind::Other), "x").unwrap_err();
        assert!(!e.is_broken_pipe());
        assert!(
            e.to_string().starts_with("cannot write standard output: "),
            "{e}"
        );
        let full = Error::Output(io::Error::from_raw_os_error(28));
        #[cfg(target_os = "linux")]
        assert_eq!(
            full.to_string(),
            "cannot write standard output: No space left on device"
        );
        let mut buf = Vec::new();
        write_line(&mut buf, 42).unwrap();
        assert_eq!(buf, b"42\n");
    }
}
