//! The user's own executable as the float side of a regression: [`ProgramRunner`].
//!
//! Float code under test is often not Rust: a C kernel, a Python function, a shader ported to a
//! command-line harness. Rather than asking for bindings, exactcheck talks to the program over
//! its standard input and output, one line per sample, and compares what it answers with the
//! exact evaluation of the formula on the same inputs.
//!
//! # Protocol
//! * exactcheck starts the program **once** for the whole run and keeps it running.
//! * For each sample it writes **one line** to the program's stdin: a JSON array of the input
//!   doubles, each in its shortest round-trip decimal form (Rust's `{:?}` of `f64`, e.g.
//!   `[0.5, -0.0, 1e-300, 1.7976931348623157e308]`), so parsing the text back gives the very
//!   double exactcheck holds (`strtod`, `scanf("%lf")`, Python's `float`/`json.loads` all do).
//!   (The harness never sends a non-finite input; if a caller does, it is written `NaN`,
//!   `Infinity` or `-Infinity`, as Python's `json` writes and reads them.)
//! * The program answers each line with **one line** on stdout holding the outputs: a JSON
//!   array, or the numbers separated by white space and/or commas. C's `printf("%.17g\n", y)`
//!   and Python's `print(y)` or `print(json.dumps([y0, y1]))` all qualify. Use 17 significant
//!   digits (or a shortest round-trip form): fewer would add a rounding that is not the code's.
//!   `nan`, `-nan`, `inf`, `-inf`, `NaN`, `Infinity`, `-Infinity` (any case) are read as those
//!   values: the harness counts them as float failures, they are not protocol errors.
//! * The program must **flush** stdout after each answer (`fflush(stdout)` in C,
//!   `print(..., flush=True)` in Python): a pipe is block-buffered by default, and an answer
//!   sitting in the program's buffer is never seen (the run then stops at the timeout). It must
//!   answer each line as it comes, not after reading all of stdin (stdin stays open for the whole
//!   run). Every stdout line is an answer, so diagnostics go to stderr.
//! * The program answers **exactly once** per input line, in order, and prints nothing else: a
//!   banner, an answer printed twice, or a line after the last answer is a protocol error (the
//!   run stops with one line naming what happened; no accuracy figure is reported). So is closing
//!   stdin while samples are still being sent.
//! * At the end exactcheck closes stdin; the program then exits with status 0 without printing
//!   more. A non-zero exit status (or a signal) after the last answer is a protocol error; a
//!   program still running after the timeout is stopped.
//! * Numbered protocol ([`ProgramRunner::echo_index`], `--program-echo-index`): each input line
//!   starts with the sample index and a space (`17 [0.5, 1e-300]`), and the program starts its
//!   answer with the same index (`17 0.25`). An answer to another sample than the one expected is
//!   then caught at once, where the plain protocol notices a duplicated line only by the extra
//!   line it leaves.
//!
//! # The program's processes
//! On Unix the program runs in a process group of its own, and exactcheck stops the whole group
//! (the program and whatever it started) when it stops the program: after an error or a timeout,
//! at the end of the run, when exactcheck's `--timeout` or memory backstop ends the process
//! ([`stop_all`]), and on `SIGINT`, `SIGTERM` or `SIGHUP` (a handler installed with the first
//! program, where the signal's action is the default, stops the groups and then ends exactcheck
//! as the signal would have).
//!
//! # Streaming
//! [`ProgramRunner::eval_batch`] pipelines: a writer thread feeds stdin while a reader thread
//! turns stdout lines into messages on a channel, and the calling thread takes the answers in
//! order, waiting at most the timeout for each. Up to [`WINDOW`] samples are in flight at once,
//! so a run costs a few system calls per hundred samples instead of one round trip per sample,
//! and memory stays bounded however long the batch. A third thread drains stderr and keeps its
//! last [`STDERR_TAIL`] bytes for error messages, so a chatty program never blocks on a full
//! stderr pipe.
//!
//! # The command
//! The command string is split into words as a POSIX shell would (quotes and backslashes, by
//! the `shlex` crate) and executed directly, without `sh -c`: no shell stands between exactcheck
//! and the program, so stopping it after a timeout stops the real process. A program name
//! without a `/` is looked up in `PATH`.
//!
//! # Errors
//! Every failure is a [`ProgramError`] whose `Display` is one line naming the program and, where
//! there is one, the sample (index and inputs): the program could not be started; it exited or
//! was killed by a signal before answering (exit status or signal, and the last line it wrote to
//! stderr; a broken pipe while writing is this case too, since it means the program exited); it
//! did not answer within the timeout (it is stopped; the message asks whether it flushes); its
//! answer is not a list of numbers (quoted, truncated); it answered the wrong number of values.
//! After such an error the program is stopped and the runner refuses further samples
//! ([`ProgramError::Stopped`]), because later answers could no longer be matched to their
//! samples. Nothing here waits without a bound or panics on what the program does. Dropping the
//! runner stops and reaps the program.
//!
//! Hand-written rather than a dependency: the answer format (JSON array or C's `printf` output)
//! is a superset of what a JSON parser accepts and a few lines to read, and the process plumbing
//! is `std` only. Only the shell-like word splitting, where quoting rules are easy to get wrong,
//! comes from a crate.

use std::collections::VecDeque;
use std::fmt;
use std::fmt::Write as _;
use std::io::{self, BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::{Duration, Instant};

/// How many bytes of the program's stderr are kept for error messages.
pub const STDERR_TAIL: usize = 2048;

/// The most samples written to the program ahead of the answers read back.
pub const WINDOW: usize = 4096;

/// Lines per write to the program's stdin.
const CHUNK: usize = 256;

/// Answer lines longer than this are cut (and then reported as not a list of numbers if the
/// cut matters); a program writing without newlines cannot exhaust memory.
const MAX_LINE: usize = 1 << 20;

/// How many characters of a bad answer or a stderr line an error message quotes.
const QUOTE: usize = 120;

/// How many inputs of a sample an error message shows.
const SHOW_INPUTS: usize = 8;

/// How long to wait for the stderr thread to collect a finished program's last words.
const STDERR_GRACE: Duration = Duration::from_millis(500);

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
fn show_inputs(xs: &[f64]) -> String {
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
fn quote(s: &str) -> String {
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

/// Appends `x` in the protocol's form: shortest round-trip decimal, valid JSON for finite `x`.
fn push_number(s: &mut String, x: f64) {
    if x.is_nan() {
        s.push_str("NaN");
    } else if x.is_infinite() {
        s.push_str(if x > 0.0 { "Infinity" } else { "-Infinity" });
    } else {
        // `{:?}` of a finite f64 is the shortest decimal that reads back as the same double,
        // always with a digit before any `.` and an optional `e` exponent: JSON's number grammar.
        let _ = write!(s, "{x:?}");
    }
}

/// The line written to the program for the inputs `xs`: a JSON array and a newline.
pub fn input_line(xs: &[f64]) -> String {
    let mut s = String::with_capacity(2 + 24 * xs.len());
    push_line(&mut s, xs);
    s
}

fn push_line(s: &mut String, xs: &[f64]) {
    s.push('[');
    for (i, &x) in xs.iter().enumerate() {
        if i > 0 {
            s.push_str(", ");
        }
        push_number(s, x);
    }
    s.push_str("]\n");
}

/// Reads one answer line: an optional `[` ... `]` around numbers separated by white space and/or
/// commas. Special values (`nan`, `inf`, `Infinity`, ... in any case, with a sign) are accepted.
///
/// # Errors
/// A short reason when the line is not of that form (an unmatched bracket, a token that is not
/// a number).
pub fn parse_answer(line: &str) -> Result<Vec<f64>, String> {
    let mut body = line.trim();
    if let Some(rest) = body.strip_prefix('[') {
        body = rest
            .trim_end()
            .strip_suffix(']')
            .ok_or_else(|| "'[' without a closing ']'".to_string())?;
    } else if body.ends_with(']') {
        return Err("']' without an opening '['".into());
    }
    body.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| {
            // Rust's float parser reads decimal and exponent forms, `inf`, `infinity` and `nan`
            // in any case with an optional sign; nothing else (no hex, no `_`).
            t.parse::<f64>()
                .map_err(|_| format!("{} is not a number", quote(t)))
        })
        .collect()
}

/// What the reader and writer threads send: a line of stdout, a read error, the end of stdout,
/// or that writing to stdin failed after `written` complete lines (the program closed it, or
/// exited).
enum Event {
    Line(String),
    Failed(String),
    Eof,
    StdinClosed { written: usize },
}

/// The last [`STDERR_TAIL`] bytes of the program's stderr.
#[derive(Default)]
struct Tail(VecDeque<u8>);

impl Tail {
    fn push(&mut self, bytes: &[u8]) {
        self.0.extend(bytes);
        let excess = self.0.len().saturating_sub(STDERR_TAIL);
        self.0.drain(..excess);
    }

    /// The last non-empty line, if any.
    fn last_line(&self) -> Option<String> {
        let bytes: Vec<u8> = self.0.iter().copied().collect();
        let text = String::from_utf8_lossy(&bytes);
        text.lines()
            .map(str::trim)
            .rfind(|l| !l.is_empty())
            .map(str::to_string)
    }
}

/// Reads one line of at most [`MAX_LINE`] bytes (the rest of a longer line is skipped).
/// `Ok(None)` at end of file; a last line without a newline still counts as a line.
fn read_capped_line(r: &mut impl BufRead) -> io::Result<Option<String>> {
    let mut buf = Vec::new();
    let mut any = false;
    loop {
        let avail = match r.fill_buf() {
            Ok(a) => a,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if avail.is_empty() {
            return Ok(any.then(|| String::from_utf8_lossy(&buf).into_owned()));
        }
        any = true;
        let (take, used, done) = match avail.iter().position(|&b| b == b'\n') {
            Some(i) => (i, i + 1, true),
            None => (avail.len(), avail.len(), false),
        };
        let room = MAX_LINE.saturating_sub(buf.len());
        buf.extend_from_slice(&avail[..take.min(room)]);
        r.consume(used);
        if done {
            return Ok(Some(String::from_utf8_lossy(&buf).into_owned()));
        }
    }
}

/// `exit status N` or `killed by signal N (SIGNAME)`.
fn describe_status(status: ExitStatus) -> String {
    if let Some(code) = status.code() {
        return format!("exit status {code}");
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            // The numbers POSIX systems share; others are shown by number alone.
            let name = match sig {
                1 => Some("SIGHUP"),
                2 => Some("SIGINT"),
                3 => Some("SIGQUIT"),
                4 => Some("SIGILL"),
                5 => Some("SIGTRAP"),
                6 => Some("SIGABRT"),
                8 => Some("SIGFPE"),
                9 => Some("SIGKILL"),
                11 => Some("SIGSEGV"),
                13 => Some("SIGPIPE"),
                14 => Some("SIGALRM"),
                15 => Some("SIGTERM"),
                _ => None,
            };
            return match name {
                Some(n) => format!("killed by signal {sig} ({n})"),
                None => format!("killed by signal {sig}"),
            };
        }
    }
    format!("ended ({status})")
}

/// The user's program, running, as the float side of a regression. See the [module
/// documentation](self) for the protocol.
///
/// # Example
/// ```no_run
/// use exactcheck_float::program::ProgramRunner;
/// use std::time::Duration;
///
/// let mut p = ProgramRunner::spawn("./sqrtdiff", 1, 1, Duration::from_secs(10))?;
/// let ys = p.eval_batch(0, &[vec![1.0], vec![1e15]])?;
/// assert_eq!(ys.len(), 2);
/// # Ok::<(), exactcheck_float::program::ProgramError>(())
/// ```
pub struct ProgramRunner {
    command: String,
    arity: usize,
    outputs: usize,
    timeout: Duration,
    child: Child,
    /// Chunks of input lines (and how many lines each holds) for the writer thread; `None` once
    /// stdin is closed.
    to_stdin: Option<Sender<(Vec<u8>, usize)>>,
    answers: Receiver<Event>,
    /// Whether input lines carry the sample index, to be echoed ([`ProgramRunner::echo_index`]).
    numbered: bool,
    /// Input lines queued for the program, and answers read, over the runner's life.
    sent: usize,
    answered: usize,
    /// The sample label of the last answer read.
    last_index: Option<usize>,
    /// How many complete lines reached stdin before writing to it failed.
    stdin_closed: Option<usize>,
    /// Whether stdout has ended.
    eof: bool,
    stderr: Arc<Mutex<Tail>>,
    stderr_done: Receiver<()>,
    /// The message of the error that stopped the program.
    failed: Option<String>,
}

impl fmt::Debug for ProgramRunner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ProgramRunner")
            .field("command", &self.command)
            .field("arity", &self.arity)
            .field("outputs", &self.outputs)
            .field("timeout", &self.timeout)
            .field("pid", &self.child.id())
            .field("failed", &self.failed)
            .finish()
    }
}

impl ProgramRunner {
    /// Starts `command` (split into words like a shell does, executed directly) for samples of
    /// `arity` inputs answered by `outputs` numbers, waiting at most `timeout` for each answer.
    ///
    /// # Errors
    /// [`ProgramError::EmptyCommand`]; [`ProgramError::Setup`] for an unsplittable command,
    /// `outputs == 0` or a zero timeout; [`ProgramError::Start`] when the program cannot be
    /// started.
    pub fn spawn(
        command: &str,
        arity: usize,
        outputs: usize,
        timeout: Duration,
    ) -> Result<ProgramRunner, ProgramError> {
        let setup = |reason: &str| ProgramError::Setup {
            command: command.to_string(),
            reason: reason.to_string(),
        };
        let words = shlex::split(command)
            .ok_or_else(|| setup("cannot split the command into words (an unclosed quote?)"))?;
        let Some((program, args)) = words.split_first() else {
            return Err(ProgramError::EmptyCommand);
        };
        if outputs == 0 {
            return Err(setup("a program must answer at least one output"));
        }
        if timeout.is_zero() {
            return Err(setup("the timeout must be positive"));
        }
        let mut cmd = Command::new(program);
        cmd.args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        #[cfg(unix)]
        {
            use std::os::unix::process::CommandExt;
            groups::install_signal_handlers();
            cmd.process_group(0);
        }
        let mut child = cmd.spawn().map_err(|e| ProgramError::Start {
            command: command.to_string(),
            reason: e.to_string(),
        })?;
        #[cfg(unix)]
        groups::register(child.id());
        let stdin = child.stdin.take().expect("stdin was configured as a pipe");
        let stdout = child
            .stdout
            .take()
            .expect("stdout was configured as a pipe");
        let stderr = child
            .stderr
            .take()
            .expect("stderr was configured as a pipe");

        let (events, answers) = mpsc::channel();
        let (to_stdin, chunks) = mpsc::channel::<(Vec<u8>, usize)>();
        let tail = Arc::new(Mutex::new(Tail::default()));
        let (done, stderr_done) = mpsc::channel();
        let started = {
            let to_events = events.clone();
            let tail = Arc::clone(&tail);
            helper("writer", move || write_chunks(stdin, chunks, &to_events))
                .and_then(|()| helper("reader", move || read_lines(stdout, &events)))
                .and_then(|()| helper("stderr", move || drain_stderr(stderr, &tail, &done)))
        };
        if let Err(e) = started {
            #[cfg(unix)]
            groups::kill(child.id());
            let _ = child.kill();
            let _ = child.wait();
            #[cfg(unix)]
            groups::unregister(child.id());
            return Err(ProgramError::Start {
                command: command.to_string(),
                reason: format!("cannot start a thread to talk to it: {e}"),
            });
        }

        Ok(ProgramRunner {
            command: command.to_string(),
            arity,
            outputs,
            timeout,
            child,
            to_stdin: Some(to_stdin),
            answers,
            numbered: false,
            sent: 0,
            answered: 0,
            last_index: None,
            stdin_closed: None,
            eof: false,
            stderr: tail,
            stderr_done,
            failed: None,
        })
    }

    /// The command as given to [`ProgramRunner::spawn`].
    pub fn command(&self) -> &str {
        &self.command
    }

    /// The number of inputs of a sample.
    pub fn arity(&self) -> usize {
        self.arity
    }

    /// The number of outputs of an answer.
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// Switches to the numbered protocol (see the module documentation): each input line starts
    /// with the sample index, and each answer must start with it too. Call before the first
    /// sample.
    #[must_use]
    pub fn echo_index(mut self) -> ProgramRunner {
        self.numbered = true;
        self
    }

    /// The program's answers to `inputs`, sample `k` of which is labelled `first_index + k` in
    /// errors. The samples are streamed (see the module documentation).
    ///
    /// # Errors
    /// A [`ProgramError`] naming the first sample that went wrong; the program is then stopped
    /// and later calls return [`ProgramError::Stopped`]. A sample of the wrong arity is refused
    /// before anything is sent ([`ProgramError::Arity`], the program keeps running).
    pub fn eval_batch(
        &mut self,
        first_index: usize,
        inputs: &[Vec<f64>],
    ) -> Result<Vec<Vec<f64>>, ProgramError> {
        self.eval_slices(first_index, inputs)
    }

    /// The program's answer to the one sample `x`, labelled `index` in errors.
    ///
    /// # Errors
    /// As [`ProgramRunner::eval_batch`].
    pub fn eval_one(&mut self, index: usize, x: &[f64]) -> Result<Vec<f64>, ProgramError> {
        let mut out = self.eval_slices(index, &[x])?;
        Ok(out.pop().expect("one answer per sample"))
    }

    fn eval_slices<S: AsRef<[f64]>>(
        &mut self,
        first_index: usize,
        inputs: &[S],
    ) -> Result<Vec<Vec<f64>>, ProgramError> {
        if let Some(first) = &self.failed {
            return Err(ProgramError::Stopped {
                command: self.command.clone(),
                first: first.clone(),
            });
        }
        if let Some(k) = inputs.iter().position(|x| x.as_ref().len() != self.arity) {
            return Err(ProgramError::Arity {
                command: self.command.clone(),
                index: first_index + k,
                inputs: inputs[k].as_ref().to_vec(),
                expected: self.arity,
            });
        }
        let n = inputs.len();
        let mut out = Vec::with_capacity(n);
        let mut sent = 0;
        while out.len() < n {
            while sent < n && sent - out.len() < WINDOW {
                let end = n.min(sent + CHUNK).min(out.len() + WINDOW);
                let mut chunk = String::with_capacity((end - sent) * (24 + 24 * self.arity));
                for (k, x) in inputs[sent..end].iter().enumerate() {
                    if self.numbered {
                        let _ = write!(chunk, "{} ", first_index + sent + k);
                    }
                    push_line(&mut chunk, x.as_ref());
                }
                // A closed channel means the writer met a broken pipe, which it has reported
                // on the answers' channel (the receiving below names it).
                if let Some(tx) = &self.to_stdin {
                    let _ = tx.send((chunk.into_bytes(), end - sent));
                }
                self.sent += end - sent;
                sent = end;
            }
            let k = out.len();
            match self.receive(first_index + k, inputs[k].as_ref()) {
                Ok(y) => {
                    out.push(y);
                    self.answered += 1;
                    self.last_index = Some(first_index + k);
                }
                Err(e) => return Err(self.fail(e)),
            }
        }
        // Every line sent is answered: a line already waiting is one too many.
        if let Err(e) = self.no_pending_line() {
            return Err(self.fail(e));
        }
        Ok(out)
    }

    /// Records the error that stops the program, and stops it.
    fn fail(&mut self, e: ProgramError) -> ProgramError {
        self.failed = Some(e.to_string());
        self.stop();
        e
    }

    /// Takes what the threads have sent without waiting: an error for a line (no answer is due),
    /// and notes of the end of stdout or of a closed stdin.
    fn no_pending_line(&mut self) -> Result<(), ProgramError> {
        loop {
            match self.answers.try_recv() {
                Ok(Event::Line(line)) => {
                    return Err(ProgramError::Extra {
                        command: self.command.clone(),
                        after: self.last_index,
                        line,
                    })
                }
                Ok(Event::StdinClosed { written }) => self.stdin_closed = Some(written),
                Ok(Event::Eof) | Err(mpsc::TryRecvError::Disconnected) => {
                    self.eof = true;
                    return Ok(());
                }
                Ok(Event::Failed(_)) | Err(mpsc::TryRecvError::Empty) => return Ok(()),
            }
        }
    }

    /// Ends the run: closes stdin, waits at most the timeout for stdout to end and the program
    /// to exit, and stops its process group. The program has kept the protocol if it printed
    /// nothing more and exited with status 0 (or was still running at the timeout).
    ///
    /// # Errors
    /// [`ProgramError::Extra`] for a line printed after the last answer,
    /// [`ProgramError::ExitedAfter`] for a non-zero exit status or a signal, or the error that
    /// stopped the program earlier ([`ProgramError::Stopped`]).
    pub fn finish(&mut self) -> Result<(), ProgramError> {
        if let Some(first) = &self.failed {
            return Err(ProgramError::Stopped {
                command: self.command.clone(),
                first: first.clone(),
            });
        }
        self.to_stdin = None;
        let deadline = Instant::now() + self.timeout;
        while !self.eof {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.answers.recv_timeout(left) {
                Ok(Event::Line(line)) => {
                    let e = ProgramError::Extra {
                        command: self.command.clone(),
                        after: self.last_index,
                        line,
                    };
                    return Err(self.fail(e));
                }
                Ok(Event::Eof) | Err(RecvTimeoutError::Disconnected) => self.eof = true,
                Ok(Event::StdinClosed { .. } | Event::Failed(_)) => {}
                // Still running with stdout open after the timeout: nothing more was printed.
                Err(RecvTimeoutError::Timeout) => break,
            }
        }
        let mut pause = Duration::from_millis(1);
        let status = loop {
            match self.child.try_wait() {
                Ok(Some(status)) => break Some(status),
                Ok(None) if Instant::now() < deadline => {
                    thread::sleep(pause);
                    pause = (pause * 2).min(Duration::from_millis(50));
                }
                _ => break None,
            }
        };
        let error = status
            .filter(|s| !s.success())
            .map(|s| ProgramError::ExitedAfter {
                command: self.command.clone(),
                status: describe_status(s),
                stderr: self.last_stderr_line(),
            });
        self.failed = Some(match &error {
            Some(e) => e.to_string(),
            None => "the run had ended".into(),
        });
        self.stop();
        error.map_or(Ok(()), Err)
    }

    /// Waits for the next answer line and reads it as the answer to sample `index`.
    fn receive(&mut self, index: usize, x: &[f64]) -> Result<Vec<f64>, ProgramError> {
        loop {
            if self
                .stdin_closed
                .is_some_and(|written| self.answered >= written)
            {
                // This sample's line never reached the program: it closed stdin, or exited.
                return Err(self.closed_stdin(index, x));
            }
            match self.answers.recv_timeout(self.timeout) {
                Ok(Event::StdinClosed { written }) => self.stdin_closed = Some(written),
                Ok(Event::Line(line)) if self.numbered => {
                    let rest = line
                        .trim_start()
                        .strip_prefix(&index.to_string())
                        .filter(|r| r.starts_with(char::is_whitespace));
                    return match rest {
                        Some(rest) => self.read_answer(index, x, rest.to_string()),
                        None => Err(ProgramError::WrongIndex {
                            command: self.command.clone(),
                            index,
                            inputs: x.to_vec(),
                            line,
                        }),
                    };
                }
                Ok(Event::Line(line)) => return self.read_answer(index, x, line),
                other => return Err(self.no_answer(index, x, other)),
            }
        }
    }

    /// Sample `index` could not be sent: how the program ended, if it did (a crash is named as
    /// one), else that it closed stdin.
    fn closed_stdin(&mut self, index: usize, x: &[f64]) -> ProgramError {
        let deadline = Instant::now() + STDERR_GRACE;
        while Instant::now() < deadline {
            if let Ok(Some(status)) = self.child.try_wait() {
                return ProgramError::Exited {
                    command: self.command.clone(),
                    index,
                    inputs: x.to_vec(),
                    status: describe_status(status),
                    stderr: self.last_stderr_line(),
                };
            }
            thread::sleep(Duration::from_millis(5));
        }
        ProgramError::ClosedStdin {
            command: self.command.clone(),
            index,
            inputs: x.to_vec(),
        }
    }

    /// Reads `line` as the answer to sample `index`.
    fn read_answer(&self, index: usize, x: &[f64], line: String) -> Result<Vec<f64>, ProgramError> {
        match parse_answer(&line) {
            Ok(y) if y.len() == self.outputs => Ok(y),
            Ok(y) => Err(ProgramError::Count {
                command: self.command.clone(),
                index,
                inputs: x.to_vec(),
                got: y.len(),
                expected: self.outputs,
            }),
            Err(reason) => Err(ProgramError::NotNumbers {
                command: self.command.clone(),
                index,
                inputs: x.to_vec(),
                line,
                reason,
            }),
        }
    }

    /// The error for sample `index` when something other than an answer line came.
    fn no_answer(
        &mut self,
        index: usize,
        x: &[f64],
        event: Result<Event, RecvTimeoutError>,
    ) -> ProgramError {
        match event {
            Ok(Event::Line(_) | Event::StdinClosed { .. }) => {
                unreachable!("answer lines and a closed stdin are handled by the caller")
            }
            Ok(Event::Failed(reason)) => ProgramError::Io {
                command: self.command.clone(),
                index,
                inputs: x.to_vec(),
                reason,
            },
            Err(RecvTimeoutError::Timeout) => {
                self.stop();
                ProgramError::Timeout {
                    command: self.command.clone(),
                    index,
                    inputs: x.to_vec(),
                    timeout: self.timeout,
                    stderr: self.last_stderr_line(),
                }
            }
            Ok(Event::Eof) | Err(RecvTimeoutError::Disconnected) => {
                self.eof = true;
                let status = self.status_after_eof();
                ProgramError::Exited {
                    command: self.command.clone(),
                    index,
                    inputs: x.to_vec(),
                    status,
                    stderr: self.last_stderr_line(),
                }
            }
        }
    }

    /// Once stdout has ended: how the program ended, waiting at most the timeout for it to
    /// exit (a program that closed stdout and runs on is stopped).
    fn status_after_eof(&mut self) -> String {
        let deadline = Instant::now() + self.timeout;
        let mut pause = Duration::from_millis(1);
        loop {
            match self.child.try_wait() {
                Ok(Some(status)) => return describe_status(status),
                Ok(None) if Instant::now() < deadline => {
                    thread::sleep(pause);
                    pause = (pause * 2).min(Duration::from_millis(50));
                }
                Ok(None) => {
                    self.stop();
                    return "it closed its standard output but kept running (stopped it)".into();
                }
                Err(e) => return format!("its status could not be read: {e}"),
            }
        }
    }

    /// The last non-empty stderr line, after giving the stderr thread a moment to read what a
    /// finished program wrote last.
    fn last_stderr_line(&self) -> Option<String> {
        let _ = self.stderr_done.recv_timeout(STDERR_GRACE);
        self.stderr
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .last_line()
    }

    /// Closes stdin, kills the program (on Unix its whole process group) and reaps it.
    fn stop(&mut self) {
        self.to_stdin = None;
        #[cfg(unix)]
        groups::kill(self.child.id());
        // `kill` fails only when the process has already been reaped; `wait` then returns the
        // status it already has. Neither failure leaves anything to clean up.
        let _ = self.child.kill();
        let _ = self.child.wait();
        #[cfg(unix)]
        groups::unregister(self.child.id());
    }
}

/// Kills the process groups of every program running as a float side, allocating nothing and
/// taking no lock (safe in a signal handler, and where the process is about to `_exit`).
pub fn stop_all() {
    #[cfg(unix)]
    groups::kill_all();
}

/// The process groups of the running programs, for [`stop_all`] and the signal handler.
#[cfg(unix)]
mod groups {
    use std::sync::atomic::{AtomicI32, Ordering};
    use std::sync::Once;

    /// Room for this many programs running at once; a group that finds no slot is still
    /// stopped with its runner, only not by [`kill_all`].
    const SLOTS: usize = 64;

    /// Process group ids (the programs' pids) in use; 0 marks a free slot.
    static LIVE: [AtomicI32; SLOTS] = [const { AtomicI32::new(0) }; SLOTS];

    fn pgid(pid: u32) -> i32 {
        i32::try_from(pid).unwrap_or(0)
    }

    pub(super) fn register(pid: u32) {
        let g = pgid(pid);
        for slot in &LIVE {
            if slot
                .compare_exchange(0, g, Ordering::SeqCst, Ordering::SeqCst)
                .is_ok()
            {
                return;
            }
        }
    }

    pub(super) fn unregister(pid: u32) {
        let g = pgid(pid);
        for slot in &LIVE {
            let _ = slot.compare_exchange(g, 0, Ordering::SeqCst, Ordering::SeqCst);
        }
    }

    /// Kills the group led by `pid`.
    pub(super) fn kill(pid: u32) {
        let g = pgid(pid);
        if g > 0 {
            // SAFETY: `kill` takes plain integers; a group that is gone gives ESRCH, harmless.
            unsafe {
                libc::kill(-g, libc::SIGKILL);
            }
        }
    }

    pub(super) fn kill_all() {
        for slot in &LIVE {
            let g = slot.load(Ordering::SeqCst);
            if g > 0 {
                // SAFETY: as in `kill`; `kill` is async-signal-safe.
                unsafe {
                    libc::kill(-g, libc::SIGKILL);
                }
            }
        }
    }

    extern "C" fn on_signal(sig: libc::c_int) {
        kill_all();
        // SAFETY: `signal` and `raise` are async-signal-safe; with the default action restored,
        // the signal ends the process as it would have without the handler.
        unsafe {
            libc::signal(sig, libc::SIG_DFL);
            libc::raise(sig);
        }
    }

    /// Installs [`on_signal`] for SIGINT, SIGTERM and SIGHUP where their action is the default
    /// (an ignored signal stays ignored), once per process.
    pub(super) fn install_signal_handlers() {
        static ONCE: Once = Once::new();
        ONCE.call_once(|| {
            for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
                // SAFETY: `sigaction` reads and writes the structs given; a zeroed `sigaction`
                // is a valid value (no flags, empty mask), then filled in.
                unsafe {
                    let mut old: libc::sigaction = std::mem::zeroed();
                    if libc::sigaction(sig, std::ptr::null(), &mut old) != 0
                        || old.sa_sigaction != libc::SIG_DFL
                    {
                        continue;
                    }
                    let mut new: libc::sigaction = std::mem::zeroed();
                    new.sa_sigaction = on_signal as extern "C" fn(libc::c_int) as usize;
                    libc::sigemptyset(&mut new.sa_mask);
                    new.sa_flags = libc::SA_RESTART;
                    libc::sigaction(sig, &new, std::ptr::null_mut());
                }
            }
        });
    }
}

impl Drop for ProgramRunner {
    fn drop(&mut self) {
        self.stop();
    }
}

/// The writer thread: copies chunks of input lines to the program's stdin until the runner
/// hangs up, or the pipe breaks (the program closed stdin or exited), which it reports with the
/// number of lines written whole before.
fn write_chunks(mut stdin: ChildStdin, chunks: Receiver<(Vec<u8>, usize)>, events: &Sender<Event>) {
    let mut written = 0;
    for (chunk, lines) in chunks {
        // ChildStdin is unbuffered: each chunk is already on its way; flush is for form.
        if stdin
            .write_all(&chunk)
            .and_then(|()| stdin.flush())
            .is_err()
        {
            let _ = events.send(Event::StdinClosed { written });
            return;
        }
        written += lines;
    }
}

/// Starts one of the threads that talk to the program.
fn helper(name: &str, f: impl FnOnce() + Send + 'static) -> io::Result<()> {
    thread::Builder::new()
        .name(format!("program {name}"))
        .spawn(f)
        .map(drop)
}

/// The reader thread: sends each line of the program's stdout, then the end or a read error.
fn read_lines(stdout: impl Read, events: &Sender<Event>) {
    let mut r = BufReader::with_capacity(1 << 16, stdout);
    loop {
        match read_capped_line(&mut r) {
            Ok(Some(line)) => {
                if events.send(Event::Line(line)).is_err() {
                    return;
                }
            }
            Ok(None) => {
                let _ = events.send(Event::Eof);
                return;
            }
            Err(e) => {
                let _ = events.send(Event::Failed(e.to_string()));
                return;
            }
        }
    }
}

/// The stderr thread: keeps the tail of what the program writes, then signals the end.
fn drain_stderr(mut stderr: impl Read, tail: &Mutex<Tail>, done: &Sender<()>) {
    let mut buf = [0u8; 4096];
    loop {
        match stderr.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => tail
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner)
                .push(&buf[..n]),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(_) => break,
        }
    }
    let _ = done.send(());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn input_lines_are_json_with_round_trip_numbers() {
        let xs = [
            1.0,
            -0.0,
            1e-300,
            1e16,
            0.1 + 0.2,
            5e-324,
            f64::MAX,
            -1.5e-7,
        ];
        let line = input_line(&xs);
        assert_eq!(
            line,
            "[1.0, -0.0, 1e-300, 1e16, 0.30000000000000004, 5e-324, \
             1.7976931348623157e308, -1.5e-7]\n"
        );
        // Reading the numbers back gives the same doubles, bit for bit (the sign of zero too).
        let back = parse_answer(&line).unwrap();
        assert_eq!(back.len(), xs.len());
        for (a, b) in xs.iter().zip(&back) {
            assert_eq!(a.to_bits(), b.to_bits());
        }
        assert_eq!(
            input_line(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]),
            "[NaN, Infinity, -Infinity]\n"
        );
        assert_eq!(input_line(&[]), "[]\n");
    }

    #[test]
    fn answers_in_every_accepted_form() {
        assert_eq!(parse_answer("0.5\n").unwrap(), vec![0.5]);
        assert_eq!(parse_answer("[1.5, -2]").unwrap(), vec![1.5, -2.0]);
        assert_eq!(parse_answer("  1 2\t3  ").unwrap(), vec![1.0, 2.0, 3.0]);
        assert_eq!(parse_answer("1,2 , 3\r\n").unwrap(), vec![1.0, 2.0, 3.0]);
        assert_eq!(parse_answer("[ ]").unwrap(), Vec::<f64>::new());
        assert_eq!(
            parse_answer("0.10000000000000001").unwrap(),
            vec![0.1],
            "C's %.17g"
        );
        let special = parse_answer("nan -nan inf -inf NaN Infinity -Infinity INF").unwrap();
        assert!(special[0].is_nan() && special[1].is_nan() && special[4].is_nan());
        assert_eq!(
            special[2..4].to_vec(),
            vec![f64::INFINITY, f64::NEG_INFINITY]
        );
        assert_eq!(
            special[5..].to_vec(),
            vec![f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY]
        );
    }

    #[test]
    fn garbage_answers_are_refused_with_a_reason() {
        for bad in [
            "hello", "[1, 2", "1, 2]", "[[1, 2]]", "0x1p3", "1e", "1_000", "None", "null",
        ] {
            let e = parse_answer(bad).unwrap_err();
            assert!(!e.is_empty(), "{bad}");
        }
        assert_eq!(
            parse_answer("1 two 3").unwrap_err(),
            "\"two\" is not a number"
        );
    }

    #[test]
    fn stderr_tail_keeps_the_last_line_within_bounds() {
        let mut t = Tail::default();
        assert_eq!(t.last_line(), None);
        for i in 0..1000 {
            t.push(format!("line {i}\n").as_bytes());
        }
        t.push(b"\n  \n");
        assert!(t.0.len() <= STDERR_TAIL);
        assert_eq!(t.last_line().as_deref(), Some("line 999"));
    }

    #[test]
    fn capped_lines_and_a_last_line_without_newline() {
        let mut long = vec![b'7'; MAX_LINE + 10];
        long.extend_from_slice(b"\n1 2\n3");
        let mut r = io::Cursor::new(long);
        assert_eq!(read_capped_line(&mut r).unwrap().unwrap().len(), MAX_LINE);
        assert_eq!(read_capped_line(&mut r).unwrap().as_deref(), Some("1 2"));
        assert_eq!(read_capped_line(&mut r).unwrap().as_deref(), Some("3"));
        assert_eq!(read_capped_line(&mut r).unwrap(), None);
    }

    #[test]
    fn messages_are_one_line_and_name_the_sample() {
        let e = ProgramError::NotNumbers {
            command: "./prog --flag".into(),
            index: 17,
            inputs: vec![0.5, 1e-300],
            line: "oops\nmore".into(),
            reason: "\"oops\" is not a number".into(),
        };
        let s = e.to_string();
        assert!(!s.contains('\n'), "{s}");
        assert!(s.contains("sample 17 [0.5, 1e-300]"), "{s}");
        assert_eq!(e.sample_index(), Some(17));
        let many = show_inputs(&[1.0; 20]);
        assert!(many.ends_with("... (20 inputs)]"), "{many}");
    }

    #[test]
    fn setup_errors() {
        let t = Duration::from_secs(1);
        assert_eq!(
            ProgramRunner::spawn("   ", 1, 1, t).unwrap_err(),
            ProgramError::EmptyCommand
        );
        assert!(matches!(
            ProgramRunner::spawn("prog 'unclosed", 1, 1, t).unwrap_err(),
            ProgramError::Setup { .. }
        ));
        assert!(matches!(
            ProgramRunner::spawn("cat", 1, 0, t).unwrap_err(),
            ProgramError::Setup { .. }
        ));
        assert!(matches!(
            ProgramRunner::spawn("cat", 1, 1, Duration::ZERO).unwrap_err(),
            ProgramError::Setup { .. }
        ));
    }
}
