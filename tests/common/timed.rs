//! Running the `exactcheck` binary under a kill-timeout, many runs in parallel: the engine of
//! the malformed-input corpus (`tests/corpus/malformed.rs`) and of the limits stress test
//! (`tests/corpus/limits_stress.rs`) and of the `prove` tests, whose test binaries include this
//! file with `#[path = "../common/timed.rs"] mod timed;` beside `tests/common` itself.
//!
//! A hostile input may make the binary hang; a test must still end. So the child is polled
//! (`try_wait`) until a deadline and killed past it, while two threads drain its standard output
//! and standard error (a child blocked on a full pipe would otherwise never end), and a third
//! feeds its standard input. The working directory is the repository root, so that the paths in
//! the cases are relative to it.

#![allow(dead_code)]

use crate::common::exactcheck;

use std::ffi::OsString;
use std::io::{Read, Write};
use std::path::Path;
use std::process::Stdio;
use std::sync::Mutex;
use std::thread;
use std::time::{Duration, Instant};

/// The kill-timeout of one run: far above what any case should need, so that only a hang
/// reaches it.
pub const KILL_AFTER: Duration = Duration::from_secs(20);

/// What one run of the binary did.
#[derive(Debug)]
pub struct Run {
    /// The exit status; `None` when a signal ended the process (or it was killed).
    pub status: Option<i32>,
    /// Everything written to standard output.
    pub stdout: Vec<u8>,
    /// Everything written to standard error.
    pub stderr: Vec<u8>,
    /// Whether the run was killed at the timeout.
    pub timed_out: bool,
}

impl Run {
    /// Standard error as text (invalid UTF-8 replaced).
    pub fn stderr_text(&self) -> String {
        String::from_utf8_lossy(&self.stderr).into_owned()
    }

    /// Standard output as text (invalid UTF-8 replaced).
    pub fn stdout_text(&self) -> String {
        String::from_utf8_lossy(&self.stdout).into_owned()
    }

    /// Whether "panicked" occurs in standard output or standard error.
    pub fn panicked(&self) -> bool {
        self.stdout_text().contains("panicked") || self.stderr_text().contains("panicked")
    }

    /// The one line of standard error (without its newline), or `None` when standard error is
    /// not exactly one newline-terminated line.
    pub fn one_stderr_line(&self) -> Option<String> {
        let text = self.stderr_text();
        let line = text.strip_suffix('\n')?;
        (!line.contains('\n')).then(|| line.to_string())
    }

    /// A short description for failure messages: status and the start of standard error.
    pub fn describe(&self) -> String {
        let status = if self.timed_out {
            format!("killed after {} s", KILL_AFTER.as_secs())
        } else {
            match self.status {
                Some(code) => format!("exit status {code}"),
                None => "ended by a signal".to_string(),
            }
        };
        let err = self.stderr_text();
        let shown: String = err.chars().take(600).collect();
        let more = if err.chars().count() > 600 {
            " ..."
        } else {
            ""
        };
        format!(
            "{status}, {} line(s) on stderr: {shown:?}{more}",
            err.lines().count()
        )
    }
}

/// The repository root (the working directory of every run).
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `exactcheck ARGS...` in the repository root with `stdin` on standard input (empty when
/// `None`), killing it after [`KILL_AFTER`].
pub fn run(args: &[OsString], stdin: Option<&[u8]>) -> Run {
    run_with_env(args, stdin, &[])
}

/// [`run`] with environment variables set for the run.
pub fn run_with_env(args: &[OsString], stdin: Option<&[u8]>, env: &[(String, String)]) -> Run {
    let mut child = exactcheck()
        .args(args)
        .envs(env.iter().map(|(k, v)| (k, v)))
        .current_dir(root())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn exactcheck");
    let mut input = child.stdin.take().expect("piped stdin");
    let bytes = stdin.unwrap_or_default().to_vec();
    // A write error means the child stopped reading (it may not read its input at all).
    let feeder = thread::spawn(move || {
        let _ = input.write_all(&bytes);
    });
    let mut out = child.stdout.take().expect("piped stdout");
    let mut err = child.stderr.take().expect("piped stderr");
    let out_reader = thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = out.read_to_end(&mut buf);
        buf
    });
    let err_reader = thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = err.read_to_end(&mut buf);
        buf
    });
    let deadline = Instant::now() + KILL_AFTER;
    let mut timed_out = false;
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for exactcheck") {
            break status;
        }
        if Instant::now() >= deadline {
            timed_out = true;
            let _ = child.kill();
            break child.wait().expect("wait for the killed exactcheck");
        }
        thread::sleep(Duration::from_millis(5));
    };
    let _ = feeder.join();
    Run {
        status: status.code(),
        stdout: out_reader.join().expect("stdout reader"),
        stderr: err_reader.join().expect("stderr reader"),
        timed_out,
    }
}

/// Exit status, standard output and standard error of `exactcheck ARGS` under the
/// kill-timeout: a hang fails the calling test (no time is asserted).
pub fn run_text(args: &[&str]) -> (i32, String, String) {
    let os: Vec<OsString> = args.iter().map(Into::into).collect();
    let r = run(&os, None);
    assert!(!r.timed_out, "exactcheck {args:?}: {}", r.describe());
    (r.status.unwrap_or(-1), r.stdout_text(), r.stderr_text())
}

/// `f` applied to every item on a few threads (the runs are mostly separate processes); the
/// results in the order of `items`.
pub fn parallel_map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let threads = thread::available_parallelism()
        .map_or(2, |n| n.get())
        .clamp(2, 8)
        .min(items.len().max(1));
    let next = Mutex::new(0usize);
    let results: Mutex<Vec<Option<R>>> = Mutex::new((0..items.len()).map(|_| None).collect());
    thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let i = {
                    let mut next = next.lock().expect("work counter");
                    let i = *next;
                    *next += 1;
                    i
                };
                let Some(item) = items.get(i) else { break };
                let r = f(item);
                results.lock().expect("results")[i] = Some(r);
            });
        }
    });
    results
        .into_inner()
        .expect("results")
        .into_iter()
        .map(|r| r.expect("every item was run"))
        .collect()
}

/// [`prove_json`] with the verdict (`"proved"`, `"fails"`, ...) taken out: exit status, verdict
/// and the JSON.
pub fn prove_verdict(args: &[&str]) -> (i32, String, serde_json::Value) {
    let (code, j) = prove_json(args);
    let v = j["verdict"].as_str().unwrap_or("?").to_string();
    (code, v, j)
}

/// Runs `exactcheck prove ARGS... --json`, which must print nothing on standard error: its exit
/// status and the one JSON object it prints.
pub fn prove_json(args: &[&str]) -> (i32, serde_json::Value) {
    let mut all = vec!["prove"];
    all.extend_from_slice(args);
    all.push("--json");
    let (code, out, err) = run_text(&all);
    assert!(err.is_empty(), "{args:?}: {err}");
    (code, serde_json::from_str(&out).expect("one JSON object"))
}
