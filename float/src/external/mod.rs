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

mod error;
#[cfg(unix)]
mod groups;
mod protocol;
#[cfg(test)]
mod tests;

use error::quote;
pub use error::ProgramError;
pub use protocol::{input_line, parse_answer};
use protocol::{push_line, push_number};

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
/// use exactcheck_float::external::ProgramRunner;
/// use std::time::Duration;
///
/// let mut p = ProgramRunner::spawn("./sqrtdiff", 1, 1, Duration::from_secs(10))?;
/// let ys = p.eval_batch(0, &[vec![1.0], vec![1e15]])?;
/// assert_eq!(ys.len(), 2);
/// # Ok::<(), exactcheck_float::external::ProgramError>(())
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

impl Drop for ProgramRunner {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Kills the process groups of every program running as a float side, allocating nothing and
/// taking no lock (safe in a signal handler, and where the process is about to `_exit`).
pub fn stop_all() {
    #[cfg(unix)]
    groups::kill_all();
}
