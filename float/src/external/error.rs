//! [`ProgramError`]: every way the user's program can fail as the float side, each one line.
use super::*;

/// Why the user's program could not serve as the float side.
///
/// `Display` is one line that names the program and, where there is one, the sample: its index
/// and its inputs as they were written to the program.
#[derive(Clone, Debug, PartialEq)]
pub enum ProgramError {
    /// The command is empty or white space only.
    EmptyCommand,
    /// The runner was asked for something impossible: a command that cannot be split into words
    /// (an unclosed quote), zero outputs, or a zero timeout.
    Setup {
        /// The command as given.
        command: String,
        /// What is wrong.
        reason: String,
    },
    /// The program could not be started (not found, not executable, ...).
    Start {
        /// The command as given.
        command: String,
        /// The operating system's reason.
        reason: String,
    },
    /// A sample with the wrong number of inputs was passed to the runner (nothing was sent).
    Arity {
        /// The command as given.
        command: String,
        /// The sample's index.
        index: usize,
        /// The sample's inputs.
        inputs: Vec<f64>,
        /// The arity the runner was created with.
        expected: usize,
    },
    /// The program exited, was killed by a signal, or closed its stdout before answering.
    Exited {
        /// The command as given.
        command: String,
        /// The sample left unanswered.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// `exit status N`, `killed by signal N (SIGNAME)`, or what else ended the answers.
        status: String,
        /// The last non-empty line the program wrote to stderr, if any.
        stderr: Option<String>,
    },
    /// No answer within the timeout; the program has been stopped.
    Timeout {
        /// The command as given.
        command: String,
        /// The sample left unanswered.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// The timeout.
        timeout: Duration,
        /// The last non-empty line the program wrote to stderr, if any.
        stderr: Option<String>,
    },
    /// The answer line is not a list of numbers.
    NotNumbers {
        /// The command as given.
        command: String,
        /// The sample answered.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// The answer line (cut at 1 MiB).
        line: String,
        /// What in it is not a number.
        reason: String,
    },
    /// The answer holds the wrong number of values.
    Count {
        /// The command as given.
        command: String,
        /// The sample answered.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// How many numbers the answer held.
        got: usize,
        /// How many outputs the runner was created with.
        expected: usize,
    },
    /// Reading the program's stdout failed for a reason other than its end.
    Io {
        /// The command as given.
        command: String,
        /// The sample left unanswered.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// The operating system's reason.
        reason: String,
    },
    /// The program printed a line where no answer was due: after its answer to the last sample
    /// sent (a banner, an answer printed twice, trailing output).
    Extra {
        /// The command as given.
        command: String,
        /// The last sample answered (`None`: before any).
        after: Option<usize>,
        /// The line (cut at 1 MiB).
        line: String,
    },
    /// The program closed its standard input while samples were still to be sent to it.
    ClosedStdin {
        /// The command as given.
        command: String,
        /// The first sample it could not have read.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
    },
    /// After its last answer, once its stdin was closed, the program exited with a non-zero
    /// status or was killed by a signal.
    ExitedAfter {
        /// The command as given.
        command: String,
        /// `exit status N` or `killed by signal N (SIGNAME)`.
        status: String,
        /// The last non-empty line the program wrote to stderr, if any.
        stderr: Option<String>,
    },
    /// In the numbered protocol, an answer that does not start with the expected sample index.
    WrongIndex {
        /// The command as given.
        command: String,
        /// The sample expected.
        index: usize,
        /// Its inputs.
        inputs: Vec<f64>,
        /// The answer line (cut at 1 MiB).
        line: String,
    },
    /// An earlier error stopped the program; the runner takes no more samples.
    Stopped {
        /// The command as given.
        command: String,
        /// The earlier error's message.
        first: String,
    },
}

impl ProgramError {
    /// The index of the sample the error is about, if it is about one.
    pub fn sample_index(&self) -> Option<usize> {
        match self {
            ProgramError::Arity { index, .. }
            | ProgramError::Exited { index, .. }
            | ProgramError::Timeout { index, .. }
            | ProgramError::NotNumbers { index, .. }
            | ProgramError::Count { index, .. }
            | ProgramError::Io { index, .. }
            | ProgramError::ClosedStdin { index, .. }
            | ProgramError::WrongIndex { index, .. } => Some(*index),
            _ => None,
        }
    }
}

/// `[x0, x1, ...]` as written to the program, cut after [`SHOW_INPUTS`] values.
pub(super) fn show_inputs(xs: &[f64]) -> String {
    let mut s = String::from("[");
    for (i, &x) in xs.iter().take(SHOW_INPUTS).enumerate() {
        if i > 0 {
            s.push_str(", ");
        }
        push_number(&mut s, x);
    }
    if xs.len() > SHOW_INPUTS {
        let _ = write!(s, ", ... ({} inputs)", xs.len());
    }
    s.push(']');
    s
}

/// `s` cut to [`QUOTE`] characters and quoted with escapes, so it stays on one line.
pub(super) fn quote(s: &str) -> String {
    let mut cut: String = s.chars().take(QUOTE).collect();
    if cut.len() < s.len() {
        cut.push_str("...");
    }
    format!("{cut:?}")
}

/// `1 s`, `0.25 s`.
fn seconds(d: Duration) -> String {
    format!("{} s", d.as_secs_f64())
}

fn stderr_suffix(stderr: &Option<String>) -> String {
    match stderr {
        Some(line) => format!("; last stderr line: {}", quote(line)),
        None => String::new(),
    }
}

impl fmt::Display for ProgramError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProgramError::EmptyCommand => write!(f, "the program command is empty"),
            ProgramError::Setup { command, reason } => {
                write!(f, "program {}: {reason}", quote(command))
            }
            ProgramError::Start { command, reason } => {
                write!(f, "could not start program {}: {reason}", quote(command))
            }
            ProgramError::Arity {
                command,
                index,
                inputs,
                expected,
            } => write!(
                f,
                "sample {index} {} for program {} has {} inputs, expected {expected}",
                show_inputs(inputs),
                quote(command),
                inputs.len()
            ),
            ProgramError::Exited {
                command,
                index,
                inputs,
                status,
                stderr,
            } => write!(
                f,
                "program {} ended before answering sample {index} {}: {status}{}",
                quote(command),
                show_inputs(inputs),
                stderr_suffix(stderr)
            ),
            ProgramError::Timeout {
                command,
                index,
                inputs,
                timeout,
                stderr,
            } => write!(
                f,
                "program {} gave no answer to sample {index} {} within {} (stopped it){}; \
                 does it flush after each line? Python: print(..., flush=True); C: fflush(stdout)",
                quote(command),
                show_inputs(inputs),
                seconds(*timeout),
                stderr_suffix(stderr)
            ),
            ProgramError::NotNumbers {
                command,
                index,
                inputs,
                line,
                reason,
            } => write!(
                f,
                "answer of program {} to sample {index} {} is not a list of numbers ({reason}): {}",
                quote(command),
                show_inputs(inputs),
                quote(line)
            ),
            ProgramError::Count {
                command,
                index,
                inputs,
                got,
                expected,
            } => write!(
                f,
                "program {} answered {got} number{} to sample {index} {}, expected {expected}",
                quote(command),
                if *got == 1 { "" } else { "s" },
                show_inputs(inputs)
            ),
            ProgramError::Io {
                command,
                index,
                inputs,
                reason,
            } => write!(
                f,
                "reading the answer of program {} to sample {index} {} failed: {reason}",
                quote(command),
                show_inputs(inputs)
            ),
            ProgramError::Extra {
                command,
                after,
                line,
            } => write!(
                f,
                "program {} printed a line {} (protocol error: one answer line per input line, \
                 nothing else on stdout): {}",
                quote(command),
                match after {
                    Some(i) => format!("after its answer to sample {i}, the last one sent"),
                    None => "before any sample was sent".to_string(),
                },
                quote(line)
            ),
            ProgramError::ClosedStdin {
                command,
                index,
                inputs,
            } => write!(
                f,
                "program {} closed its standard input before reading sample {index} {} \
                 (protocol error: it must read every line)",
                quote(command),
                show_inputs(inputs)
            ),
            ProgramError::ExitedAfter {
                command,
                status,
                stderr,
            } => write!(
                f,
                "program {} ended with {status} after its last answer (protocol error: it must \
                 exit with status 0 when its input ends){}",
                quote(command),
                stderr_suffix(stderr)
            ),
            ProgramError::WrongIndex {
                command,
                index,
                inputs,
                line,
            } => write!(
                f,
                "answer of program {} to sample {index} {} does not start with the index {index} \
                 (protocol error; --program-echo-index): {}",
                quote(command),
                show_inputs(inputs),
                quote(line)
            ),
            ProgramError::Stopped { command, first } => write!(
                f,
                "program {} was stopped by an earlier error: {first}",
                quote(command)
            ),
        }
    }
}

impl std::error::Error for ProgramError {}
