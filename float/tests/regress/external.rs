//! The user's program as the float side ([`ProgramRunner`]), end to end with real processes: a C
//! program compiled here with `gcc` and Python programs run by `python3`, the two docs/regress.md
//! examples among them; and every way a program can fail the protocol, each a one-line error
//! naming the sample, never a hang.

use exactcheck_float::external::{ProgramError, ProgramRunner};
use exactcheck_float::Rng;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// A generous per-answer timeout for programs that do answer (the machine is shared).
const PATIENT: Duration = Duration::from_secs(30);

/// The C example of docs/regress.md, byte for byte (one file, also regressed end to end through the CLI by
/// `tests/regress_text.rs`).
const C_SQRTDIFF: &str = include_str!("../../../tests/regress/cancel.c");

/// The Python example of docs/regress.md, byte for byte (likewise).
const PY_SQRTDIFF: &str = include_str!("../../../tests/regress/cancel.py");

/// A directory of its own for one test, under cargo's scratch directory for integration tests;
/// its name has a space so that commands need quoting.
fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("program tests")
        .join(test);
    fs::create_dir_all(&dir).expect("create the test's scratch directory");
    dir
}

/// `'path'`, quoted for the command line (the scratch paths hold no `'`).
fn q(p: &Path) -> String {
    let s = p.to_str().expect("scratch paths are UTF-8");
    assert!(!s.contains('\''));
    format!("'{s}'")
}

/// Compiles `source` with gcc into `dir/name`; `None` (with a printed note) if gcc is absent.
fn compile_c(dir: &Path, name: &str, source: &str) -> Option<PathBuf> {
    let src = dir.join(format!("{name}.c"));
    let exe = dir.join(name);
    fs::write(&src, source).expect("write the C source");
    let out = match Command::new("gcc")
        .arg("-O2")
        .arg("-o")
        .arg(&exe)
        .arg(&src)
        .arg("-lm")
        .output()
    {
        Ok(out) => out,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            println!("skipping: gcc is not installed");
            return None;
        }
        Err(e) => panic!("running gcc: {e}"),
    };
    assert!(
        out.status.success(),
        "gcc failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(exe)
}

/// Writes a Python script and returns the command running it.
fn python(dir: &Path, name: &str, source: &str) -> String {
    let path = dir.join(format!("{name}.py"));
    fs::write(&path, source).expect("write the Python script");
    format!("python3 {}", q(&path))
}

/// `sqrt(x + 1) - sqrt(x)` in f64, as the C and Python examples compute it.
fn sqrtdiff(x: f64) -> f64 {
    (x + 1.0).sqrt() - x.sqrt()
}

/// Inputs covering the protocol's number forms: zero, tiny, huge, integers, random doubles.
fn sqrtdiff_inputs(n: usize) -> Vec<Vec<f64>> {
    let mut xs = vec![
        0.0,
        1.0,
        0.5,
        1e-300,
        5e-324,
        1e15,
        1e300,
        12345.678,
        0.1 + 0.2,
    ];
    let mut rng = Rng::new(11);
    while xs.len() < n {
        xs.push(rng.uniform(1.0, 1e15));
        xs.push(rng.uniform(0.0, 1.0));
    }
    xs.truncate(n);
    xs.into_iter().map(|x| vec![x]).collect()
}

/// Asserts the program's answers are the f64 values, bit for bit.
fn assert_sqrtdiff(inputs: &[Vec<f64>], answers: &[Vec<f64>]) {
    assert_eq!(inputs.len(), answers.len());
    for (x, y) in inputs.iter().zip(answers) {
        assert_eq!(y.len(), 1);
        assert_eq!(
            y[0].to_bits(),
            sqrtdiff(x[0]).to_bits(),
            "x = {:?}: program {:?}, Rust {:?}",
            x[0],
            y[0],
            sqrtdiff(x[0])
        );
    }
}

fn one_line(e: &ProgramError) -> String {
    let s = e.to_string();
    assert!(!s.contains('\n') && !s.contains('\r'), "not one line: {s}");
    s
}

#[test]
fn readme_c_example_answers_the_f64_values() {
    let dir = scratch("c_sqrtdiff");
    let Some(exe) = compile_c(&dir, "sqrtdiff", C_SQRTDIFF) else {
        return;
    };
    let mut p = ProgramRunner::spawn(&q(&exe), 1, 1, PATIENT).unwrap();
    let inputs = sqrtdiff_inputs(2000);
    let answers = p.eval_batch(0, &inputs).unwrap();
    assert_sqrtdiff(&inputs, &answers);
    // The same long-lived process keeps answering, one sample at a time too.
    let y = p.eval_one(2000, &[3.0]).unwrap();
    assert_eq!(y, vec![sqrtdiff(3.0)]);
    let more = p.eval_batch(2001, &inputs[..10]).unwrap();
    assert_sqrtdiff(&inputs[..10], &more);
}

#[test]
fn readme_python_example_answers_the_f64_values() {
    let dir = scratch("py_sqrtdiff");
    let cmd = python(&dir, "sqrtdiff", PY_SQRTDIFF);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let inputs = sqrtdiff_inputs(500);
    let answers = p.eval_batch(0, &inputs).unwrap();
    assert_sqrtdiff(&inputs, &answers);
}

#[test]
fn several_inputs_and_outputs_in_c_and_python() {
    let dir = scratch("two_by_two");
    // C: comma-separated outputs.
    let c = r#"#include <stdio.h>
int main(void) {
    double x, y;
    while (scanf(" [%lf ,%lf]", &x, &y) == 2) { printf("%.17g, %.17g\n", x * y - 1, x / y); fflush(stdout); }
}
"#;
    // Python: a JSON array, special values included.
    let py = r#"import json, sys
for line in sys.stdin:
    x, y = json.loads(line)
    print(json.dumps([x * y - 1, x / y if y != 0 else float("inf")]), flush=True)
"#;
    let mut rng = Rng::new(5);
    let mut inputs: Vec<Vec<f64>> = (0..300)
        .map(|_| vec![rng.uniform(-1.0, 1.0), rng.uniform(-1e-10, 1e10)])
        .collect();
    inputs.push(vec![-0.0, 1e-300]);
    let expected = |x: &[f64]| vec![x[0] * x[1] - 1.0, x[0] / x[1]];
    let mut commands = vec![python(&dir, "two", py)];
    if let Some(exe) = compile_c(&dir, "two", c) {
        commands.push(q(&exe));
    }
    for cmd in commands {
        let mut p = ProgramRunner::spawn(&cmd, 2, 2, PATIENT).unwrap();
        let answers = p.eval_batch(0, &inputs).unwrap();
        for (x, y) in inputs.iter().zip(&answers) {
            let want = expected(x);
            assert_eq!(y.len(), 2);
            for k in 0..2 {
                assert_eq!(y[k].to_bits(), want[k].to_bits(), "{cmd}: {x:?} -> {y:?}");
            }
        }
        // Division by zero: C prints inf, the Python program writes Infinity; both read as +inf.
        let y = p.eval_one(999, &[1.0, 0.0]).unwrap();
        assert_eq!(y, vec![-1.0, f64::INFINITY], "{cmd}");
    }
}

#[test]
fn c_program_crashing_with_abort_names_the_sample_and_the_signal() {
    let dir = scratch("c_abort");
    let c = r#"#include <stdio.h>
#include <stdlib.h>
int main(void) {
    double x; int n = 0;
    while (scanf(" [%lf]", &x) == 1) {
        if (++n == 3) { fprintf(stderr, "giving up on %g\n", x); abort(); }
        printf("%.17g\n", x); fflush(stdout);
    }
}
"#;
    let Some(exe) = compile_c(&dir, "aborts", c) else {
        return;
    };
    let mut p = ProgramRunner::spawn(&q(&exe), 1, 1, PATIENT).unwrap();
    let inputs: Vec<Vec<f64>> = (0..5).map(|i| vec![f64::from(i) + 0.5]).collect();
    let e = p.eval_batch(10, &inputs).unwrap_err();
    let s = one_line(&e);
    assert_eq!(e.sample_index(), Some(12), "{s}");
    assert!(s.contains("before answering sample 12 [2.5]"), "{s}");
    assert!(s.contains("killed by signal 6 (SIGABRT)"), "{s}");
    assert!(s.contains("last stderr line: \"giving up on 2.5\""), "{s}");
    // The runner is stopped: no later sample can be matched to a wrong answer.
    let again = p.eval_one(20, &[1.0]).unwrap_err();
    assert!(matches!(again, ProgramError::Stopped { .. }), "{again}");
    assert!(one_line(&again).contains("sample 12"), "{again}");
}

#[test]
fn python_program_exiting_names_the_sample_and_the_status() {
    let dir = scratch("py_exit");
    let py = r#"import sys
for n, line in enumerate(sys.stdin):
    if n == 2:
        print("cannot handle", line.strip(), file=sys.stderr)
        sys.exit(3)
    print(line.strip()[1:-1], flush=True)
"#;
    let cmd = python(&dir, "exits", py);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    assert_eq!(p.eval_one(0, &[0.25]).unwrap(), vec![0.25]);
    assert_eq!(
        p.eval_one(1, &[-0.0]).unwrap()[0].to_bits(),
        (-0.0f64).to_bits()
    );
    let e = p.eval_one(2, &[1e-300]).unwrap_err();
    let s = one_line(&e);
    assert!(s.contains("before answering sample 2 [1e-300]"), "{s}");
    assert!(s.contains("exit status 3"), "{s}");
    assert!(s.contains("\"cannot handle [1e-300]\""), "{s}");
}

#[test]
fn a_program_that_exits_at_once_is_a_crash_not_a_hang_or_a_broken_pipe() {
    let dir = scratch("exits_at_once");
    let cmd = python(&dir, "quits", "import sys\nsys.exit(0)\n");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    // Far more than a pipe holds: the writer meets a broken pipe, the error is the exit.
    let inputs: Vec<Vec<f64>> = (0..50_000).map(|i| vec![f64::from(i)]).collect();
    let t = Instant::now();
    let e = p.eval_batch(0, &inputs).unwrap_err();
    let s = one_line(&e);
    assert!(
        s.contains("before answering sample 0 [0.0]: exit status 0"),
        "{s}"
    );
    assert!(t.elapsed() < Duration::from_secs(20), "{s}");
}

#[test]
fn python_syntax_error_is_reported_with_its_stderr() {
    let dir = scratch("py_syntax");
    let cmd = python(&dir, "broken", "for line in sys.stdin\n    print(line)\n");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let s = one_line(&p.eval_one(0, &[1.0]).unwrap_err());
    assert!(s.contains("exit status 1"), "{s}");
    assert!(s.contains("SyntaxError"), "{s}");
}

/// Whether process `pid` is gone (reaped), on Linux.
#[cfg(target_os = "linux")]
fn gone(pid: u32) -> bool {
    !Path::new(&format!("/proc/{pid}")).exists()
}

#[test]
fn a_hanging_program_times_out_is_stopped_and_named() {
    let dir = scratch("hang");
    let pid_file = dir.join("pid");
    let py = format!(
        r#"import os, sys, time
open({:?}, "w").write(str(os.getpid()))
for line in sys.stdin:
    time.sleep(1000)
"#,
        pid_file.to_str().unwrap()
    );
    let cmd = python(&dir, "sleeps", &py);
    let mut p = ProgramRunner::spawn(&cmd, 2, 1, Duration::from_secs(1)).unwrap();
    let t = Instant::now();
    let e = p
        .eval_batch(7, &[vec![1.0, 2.0], vec![3.0, 4.0]])
        .unwrap_err();
    let elapsed = t.elapsed();
    let s = one_line(&e);
    assert!(
        elapsed < Duration::from_secs(5),
        "took {elapsed:?} for a 1 s timeout"
    );
    assert!(matches!(e, ProgramError::Timeout { index: 7, .. }), "{s}");
    assert!(
        s.contains("no answer to sample 7 [1.0, 2.0] within 1 s"),
        "{s}"
    );
    assert!(
        s.contains("fflush(stdout)") && s.contains("flush=True"),
        "{s}"
    );
    #[cfg(target_os = "linux")]
    {
        // (No pid file: on a very loaded machine Python was stopped before it got that far.)
        if let Ok(pid) = fs::read_to_string(&pid_file) {
            let pid: u32 = pid.trim().parse().unwrap();
            assert!(gone(pid), "the timed-out program {pid} still exists");
        }
    }
}

#[test]
fn a_program_that_does_not_flush_times_out_with_the_hint() {
    let dir = scratch("no_flush");
    // C's stdout is block-buffered on a pipe: without fflush the answer stays in its buffer.
    let c = r#"#include <stdio.h>
int main(void) {
    double x;
    while (scanf(" [%lf]", &x) == 1) printf("%.17g\n", x);
}
"#;
    let Some(exe) = compile_c(&dir, "noflush", c) else {
        return;
    };
    let mut p = ProgramRunner::spawn(&q(&exe), 1, 1, Duration::from_secs(1)).unwrap();
    let s = one_line(&p.eval_one(0, &[0.5]).unwrap_err());
    assert!(
        s.contains("sample 0 [0.5]") && s.contains("does it flush after each line?"),
        "{s}"
    );
}

#[test]
fn a_program_closing_stdout_but_running_on_is_stopped() {
    let dir = scratch("closes_stdout");
    let py = "import os, sys, time\nsys.stdin.readline()\nos.close(1)\ntime.sleep(1000)\n";
    let cmd = python(&dir, "closes", py);
    // The timeout covers Python's start on a loaded machine; once stdout has ended, the runner
    // waits that long for an exit before stopping the program.
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, Duration::from_secs(3)).unwrap();
    let t = Instant::now();
    let s = one_line(&p.eval_one(4, &[2.0]).unwrap_err());
    assert!(t.elapsed() < Duration::from_secs(10));
    assert!(
        s.contains("sample 4 [2.0]") && s.contains("closed its standard output"),
        "{s}"
    );
}

#[test]
fn garbage_answers_are_quoted_and_name_the_sample() {
    let dir = scratch("garbage");
    let py = r#"import sys
for n, line in enumerate(sys.stdin):
    print("1.5" if n < 3 else "result: 42", flush=True)
"#;
    let cmd = python(&dir, "garbage", py);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let inputs: Vec<Vec<f64>> = (0..10).map(|i| vec![f64::from(i)]).collect();
    let e = p.eval_batch(100, &inputs).unwrap_err();
    let s = one_line(&e);
    assert!(
        matches!(e, ProgramError::NotNumbers { index: 103, .. }),
        "{s}"
    );
    assert!(
        s.contains("sample 103 [3.0] is not a list of numbers"),
        "{s}"
    );
    assert!(s.contains("\"result: 42\""), "{s}");
}

#[test]
fn a_long_garbage_line_is_truncated_in_the_message() {
    let dir = scratch("long_garbage");
    let py = "import sys\nfor line in sys.stdin:\n    print('x' * 100000, flush=True)\n";
    let cmd = python(&dir, "long", py);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let s = one_line(&p.eval_one(0, &[1.0]).unwrap_err());
    assert!(s.contains("sample 0 [1.0]") && s.contains("...\""), "{s}");
    assert!(s.len() < 600, "{} characters: {s}", s.len());
}

#[test]
fn a_wrong_number_of_outputs_names_the_sample() {
    let dir = scratch("count");
    let c = r#"#include <stdio.h>
int main(void) {
    double x;
    while (scanf(" [%lf]", &x) == 1) { printf("%.17g %.17g\n", x, -x); fflush(stdout); }
}
"#;
    let Some(exe) = compile_c(&dir, "two_outputs", c) else {
        return;
    };
    let mut p = ProgramRunner::spawn(&q(&exe), 1, 1, PATIENT).unwrap();
    let e = p.eval_one(41, &[0.125]).unwrap_err();
    let s = one_line(&e);
    assert!(
        s.contains("answered 2 numbers to sample 41 [0.125], expected 1"),
        "{s}"
    );
}

#[test]
fn a_missing_executable_is_named() {
    let e = ProgramRunner::spawn("/nonexistent/dir/prog --flag", 1, 1, PATIENT).unwrap_err();
    let s = one_line(&e);
    assert!(matches!(e, ProgramError::Start { .. }), "{s}");
    assert!(
        s.contains("could not start program \"/nonexistent/dir/prog --flag\""),
        "{s}"
    );
    let e = ProgramRunner::spawn("exactcheck-no-such-program-on-path", 1, 1, PATIENT).unwrap_err();
    assert!(one_line(&e).contains("exactcheck-no-such-program-on-path"));
    assert_eq!(
        ProgramRunner::spawn("", 1, 1, PATIENT).unwrap_err(),
        ProgramError::EmptyCommand
    );
}

#[test]
fn a_chatty_stderr_does_not_block_the_program() {
    let dir = scratch("chatty");
    // 64 KiB of stderr per sample: far more than a pipe buffer over the run.
    let py = r#"import sys
for line in sys.stdin:
    sys.stderr.write("noise " * 10922 + "\n")
    sys.stderr.flush()
    print(line.strip()[1:-1], flush=True)
"#;
    let cmd = python(&dir, "chatty", py);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let inputs: Vec<Vec<f64>> = (0..64).map(|i| vec![f64::from(i)]).collect();
    let answers = p.eval_batch(0, &inputs).unwrap();
    assert_eq!(answers, inputs);
}

#[test]
fn wrong_arity_is_refused_before_sending_and_the_program_runs_on() {
    let dir = scratch("arity");
    let cmd = python(&dir, "echo", PY_SQRTDIFF);
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let e = p.eval_batch(5, &[vec![1.0], vec![1.0, 2.0]]).unwrap_err();
    let s = one_line(&e);
    assert!(
        s.contains("sample 6 [1.0, 2.0]") && s.contains("expected 1"),
        "{s}"
    );
    assert_eq!(p.eval_one(7, &[3.0]).unwrap(), vec![sqrtdiff(3.0)]);
}

#[test]
fn dropping_a_runner_stops_a_program_that_never_reads() {
    let t = Instant::now();
    let p = ProgramRunner::spawn("sleep 1000", 1, 1, PATIENT).unwrap();
    drop(p);
    assert!(t.elapsed() < Duration::from_secs(5));
}

/// Pipelined throughput of the C example: many samples per second, not one round trip each.
#[test]
fn c_program_throughput_through_eval_batch() {
    let dir = scratch("c_throughput");
    let Some(exe) = compile_c(&dir, "sqrtdiff", C_SQRTDIFF) else {
        return;
    };
    let mut p = ProgramRunner::spawn(&q(&exe), 1, 1, PATIENT).unwrap();
    let n = 100_000;
    let mut rng = Rng::new(3);
    let inputs: Vec<Vec<f64>> = (0..n).map(|_| vec![rng.uniform(1.0, 1e15)]).collect();
    let t = Instant::now();
    let answers = p.eval_batch(0, &inputs).unwrap();
    let secs = t.elapsed().as_secs_f64();
    assert_sqrtdiff(&inputs, &answers);
    println!(
        "C sqrtdiff through eval_batch: {n} samples in {secs:.3} s = {:.0} samples/s",
        n as f64 / secs
    );
}

/// `sh -c SCRIPT` as a command line (the scripts hold no `'`).
fn sh(script: &str) -> String {
    assert!(!script.contains('\''));
    format!("sh -c '{script}'")
}

/// A shell loop answering each input line `[x]` (or `INDEX [x]` in the numbered protocol) with
/// `x` (`INDEX x`), `times` times; `after` runs once stdin has ended.
fn echo_program(times: usize, numbered: bool, after: &str) -> String {
    let answer = if numbered {
        "echo \"$i $x\"; "
    } else {
        "echo \"$x\"; "
    };
    let read = if numbered { "read -r i x" } else { "read -r x" };
    sh(&format!(
        "while {read}; do x=${{x#[}}; x=${{x%]}}; {}done; {after}",
        answer.repeat(times)
    ))
}

fn samples(n: usize) -> Vec<Vec<f64>> {
    (0..n).map(|i| vec![f64::from(i as u32) + 0.5]).collect()
}

/// The batch and then the end of the run, as the harness does them: the first error.
fn run_to_the_end(
    p: &mut ProgramRunner,
    inputs: &[Vec<f64>],
) -> Result<Vec<Vec<f64>>, ProgramError> {
    let out = p.eval_batch(0, inputs)?;
    p.finish()?;
    Ok(out)
}

#[test]
fn a_program_keeping_the_protocol_ends_cleanly() {
    for numbered in [false, true] {
        let mut p = ProgramRunner::spawn(&echo_program(1, numbered, ""), 1, 1, PATIENT).unwrap();
        if numbered {
            p = p.echo_index();
        }
        let inputs = samples(300);
        assert_eq!(run_to_the_end(&mut p, &inputs).unwrap(), inputs);
        // Once finished, the runner takes no more samples.
        let e = p.eval_one(300, &[1.0]).unwrap_err();
        assert!(matches!(e, ProgramError::Stopped { .. }), "{e}");
    }
}

#[test]
fn each_answer_printed_twice_is_a_protocol_error() {
    let mut p = ProgramRunner::spawn(&echo_program(2, false, ""), 1, 1, PATIENT).unwrap();
    let e = run_to_the_end(&mut p, &samples(5)).unwrap_err();
    let s = one_line(&e);
    assert!(matches!(e, ProgramError::Extra { .. }), "{s}");
    assert!(s.contains("protocol error"), "{s}");
    // Numbered: the duplicate is caught at the very next sample.
    let mut p = ProgramRunner::spawn(&echo_program(2, true, ""), 1, 1, PATIENT)
        .unwrap()
        .echo_index();
    let e = run_to_the_end(&mut p, &samples(5)).unwrap_err();
    let s = one_line(&e);
    assert!(
        matches!(e, ProgramError::WrongIndex { index: 1, .. }),
        "{s}"
    );
    assert!(
        s.contains("sample 1 [1.5] does not start with the index 1") && s.contains("\"0 0.5\""),
        "{s}"
    );
}

#[test]
fn a_banner_line_is_a_protocol_error() {
    // A banner that is not a number is not an answer.
    let cmd = sh("echo ready; while read -r x; do echo 1; done");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let s = one_line(&run_to_the_end(&mut p, &samples(3)).unwrap_err());
    assert!(
        s.contains("sample 0 [0.5]") && s.contains("\"ready\""),
        "{s}"
    );
    // A banner that reads as a number shifts every answer by one: the last one is left over.
    let cmd = sh("echo 2.5; while read -r x; do x=${x#[}; echo \"${x%]}\"; done");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let e = run_to_the_end(&mut p, &samples(3)).unwrap_err();
    let s = one_line(&e);
    assert!(matches!(e, ProgramError::Extra { .. }), "{s}");
    assert!(s.contains("\"2.5\""), "{s}");
}

#[test]
fn a_line_after_the_last_answer_is_a_protocol_error() {
    let mut p = ProgramRunner::spawn(&echo_program(1, false, "echo 0"), 1, 1, PATIENT).unwrap();
    let e = run_to_the_end(&mut p, &samples(4)).unwrap_err();
    let s = one_line(&e);
    assert!(
        s.contains("printed a line after its answer to sample 3, the last one sent"),
        "{s}"
    );
    assert!(s.contains("protocol error") && s.ends_with("\"0\""), "{s}");
}

#[test]
fn a_nonzero_exit_after_the_last_answer_is_a_protocol_error() {
    let cmd = echo_program(1, false, "echo giving up >&2; exit 3");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let e = run_to_the_end(&mut p, &samples(4)).unwrap_err();
    let s = one_line(&e);
    assert!(matches!(e, ProgramError::ExitedAfter { .. }), "{s}");
    assert!(
        s.contains("ended with exit status 3 after its last answer (protocol error"),
        "{s}"
    );
    assert!(s.contains("\"giving up\""), "{s}");
    let cmd = echo_program(1, false, "kill -9 $$");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let s = one_line(&run_to_the_end(&mut p, &samples(2)).unwrap_err());
    assert!(
        s.contains("killed by signal 9 (SIGKILL) after its last answer"),
        "{s}"
    );
}

#[test]
fn closing_stdin_while_answering_is_a_protocol_error() {
    // Reads one line, closes stdin, and answers on without reading: answers to samples it never
    // saw. More samples than fit in the pipe and the in-flight window, so some are written after
    // the close.
    let cmd = sh("read -r x; exec 0<&-; while :; do echo 1; done");
    let mut p = ProgramRunner::spawn(&cmd, 1, 1, PATIENT).unwrap();
    let e = run_to_the_end(&mut p, &samples(20_000)).unwrap_err();
    let s = one_line(&e);
    assert!(matches!(e, ProgramError::ClosedStdin { .. }), "{s}");
    assert!(
        s.contains("closed its standard input before reading sample"),
        "{s}"
    );
}

/// Whether process `pid` is gone: no such process, or a zombie (killed, waiting to be reaped by
/// whichever process adopted it).
#[cfg(target_os = "linux")]
fn dead(pid: u32) -> bool {
    match fs::read_to_string(format!("/proc/{pid}/stat")) {
        Err(_) => true,
        // The state follows the command name in parentheses.
        Ok(stat) => stat
            .rsplit_once(") ")
            .is_some_and(|(_, rest)| rest.starts_with('Z') || rest.starts_with('X')),
    }
}

/// Waits up to 20 s for a file to hold a pid.
fn read_pid(path: &Path) -> u32 {
    let t = Instant::now();
    loop {
        if let Ok(text) = fs::read_to_string(path) {
            if let Ok(pid) = text.trim().parse() {
                return pid;
            }
        }
        assert!(t.elapsed() < Duration::from_secs(20), "no pid in {path:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[cfg(target_os = "linux")]
#[test]
fn a_timeout_stops_the_program_and_what_it_started() {
    let dir = scratch("grandchild");
    let pid_file = dir.join("sleep.pid");
    let _ = fs::remove_file(&pid_file);
    let script = format!(
        "sleep 1000 & echo $! > {}; while read -r x; do :; done",
        q(&pid_file)
    );
    let script = script.replace('\'', "\"");
    let mut p = ProgramRunner::spawn(&sh(&script), 1, 1, Duration::from_secs(1)).unwrap();
    let grandchild = read_pid(&pid_file);
    assert!(!dead(grandchild));
    let e = p.eval_one(0, &[1.0]).unwrap_err();
    assert!(matches!(e, ProgramError::Timeout { .. }), "{e}");
    let t = Instant::now();
    while !dead(grandchild) && t.elapsed() < Duration::from_secs(5) {
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(
        dead(grandchild),
        "the program's child {grandchild} outlived the timeout"
    );
}
