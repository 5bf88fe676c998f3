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
//! * At the end exactcheck closes stdin and stops the program.
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
            | ProgramError::Io { index, .. } => Some(*index),
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

/// What the reader thread sends: a line of stdout (and whether it was cut), or a read error.
/// The channel closing means end of file.
enum Event {
    Line(String),
    Failed(String),
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
    /// Chunks of input lines for the writer thread; `None` once the runner has stopped.
    to_stdin: Option<Sender<Vec<u8>>>,
    answers: Receiver<Event>,
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
        let mut child = Command::new(program)
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| ProgramError::Start {
                command: command.to_string(),
                reason: e.to_string(),
            })?;
        let stdin = child.stdin.take().expect("stdin was configured as a pipe");
        let stdout = child
            .stdout
            .take()
            .expect("stdout was configured as a pipe");
        let stderr = child
            .stderr
            .take()
            .expect("stderr was configured as a pipe");

        let (to_stdin, chunks) = mpsc::channel::<Vec<u8>>();
        thread::spawn(move || write_chunks(stdin, chunks));

        let (events, answers) = mpsc::channel();
        thread::spawn(move || {
            let mut r = BufReader::with_capacity(1 << 16, stdout);
            loop {
                match read_capped_line(&mut r) {
                    Ok(Some(line)) => {
                        if events.send(Event::Line(line)).is_err() {
                            return;
                        }
                    }
                    Ok(None) => return,
                    Err(e) => {
                        let _ = events.send(Event::Failed(e.to_string()));
                        return;
                    }
                }
            }
        });

        let tail = Arc::new(Mutex::new(Tail::default()));
        let (done, stderr_done) = mpsc::channel();
        {
            let tail = Arc::clone(&tail);
            thread::spawn(move || drain_stderr(stderr, &tail, &done));
        }

        Ok(ProgramRunner {
            command: command.to_string(),
            arity,
            outputs,
            timeout,
            child,
            to_stdin: Some(to_stdin),
            answers,
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
                let mut chunk = String::with_capacity((end - sent) * (4 + 24 * self.arity));
                for x in &inputs[sent..end] {
                    push_line(&mut chunk, x.as_ref());
                }
                // A closed channel means the writer met a broken pipe: the program has exited,
                // which the answers' end of file reports with its exit status below.
                if let Some(tx) = &self.to_stdin {
                    let _ = tx.send(chunk.into_bytes());
                }
                sent = end;
            }
            let k = out.len();
            match self.receive(first_index + k, inputs[k].as_ref()) {
                Ok(y) => out.push(y),
                Err(e) => {
                    self.failed = Some(e.to_string());
                    self.stop();
                    return Err(e);
                }
            }
        }
        Ok(out)
    }

    /// Waits for the next answer line and reads it as the answer to sample `index`.
    fn receive(&mut self, index: usize, x: &[f64]) -> Result<Vec<f64>, ProgramError> {
        match self.answers.recv_timeout(self.timeout) {
            Ok(Event::Line(line)) => match parse_answer(&line) {
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
            },
            Ok(Event::Failed(reason)) => Err(ProgramError::Io {
                command: self.command.clone(),
                index,
                inputs: x.to_vec(),
                reason,
            }),
            Err(RecvTimeoutError::Timeout) => {
                self.stop();
                Err(ProgramError::Timeout {
                    command: self.command.clone(),
                    index,
                    inputs: x.to_vec(),
                    timeout: self.timeout,
                    stderr: self.last_stderr_line(),
                })
            }
            Err(RecvTimeoutError::Disconnected) => {
                let status = self.status_after_eof();
                Err(ProgramError::Exited {
                    command: self.command.clone(),
                    index,
                    inputs: x.to_vec(),
                    status,
                    stderr: self.last_stderr_line(),
                })
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

    /// Closes stdin, kills the program and reaps it.
    fn stop(&mut self) {
        self.to_stdin = None;
        // `kill` fails only when the process has already been reaped; `wait` then returns the
        // status it already has. Neither failure leaves anything to clean up.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for ProgramRunner {
    fn drop(&mut self) {
        self.stop();
    }
}

/// The writer thread: copies chunks of input lines to the program's stdin until the runner
/// hangs up or the pipe breaks (the program exited; the reader side reports it).
fn write_chunks(mut stdin: ChildStdin, chunks: Receiver<Vec<u8>>) {
    for chunk in chunks {
        if stdin.write_all(&chunk).is_err() {
            return;
        }
        // ChildStdin is unbuffered: each chunk is already on its way; flush is for form.
        if stdin.flush().is_err() {
            return;
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
