//! The command line under hostile use: a closed or full standard output, counts far
//! out of range, usage errors, invalid UTF-8 in arguments, `plot -o -`. Each case pins the old
//! failure (a panic, an abort, minutes of silence, a 3-16 line message, a file named `-`).

use crate::common;

use std::io::Write as _;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn bin() -> Command {
    common::exactcheck()
}

fn exactcheck(args: &[&str]) -> Output {
    bin().args(args).output().expect("run exactcheck")
}

/// A fresh directory under the system temp dir, removed when dropped.
struct TempDir(PathBuf);

impl TempDir {
    fn new(tag: &str) -> TempDir {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        let dir = std::env::temp_dir().join(format!(
            "exactcheck-robust-{tag}-{}-{nanos}",
            std::process::id()
        ));
        std::fs::create_dir_all(&dir).expect("create temp dir");
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const PROBLEM: &str = r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":[8,0,3],"radius":3}}"#;

/// Every command this crate's CLI writes standard output for (prove's output is written in
/// `prove_cmd`), with the standard input it reads.
fn commands() -> Vec<(Vec<&'static str>, &'static str)> {
    vec![
        (vec!["verify", "--only", "spaeth"], ""),
        (vec!["verify", "--only", "spaeth", "--json"], ""),
        (vec!["regress", "cylinder-sphere", "--samples", "20"], ""),
        (vec!["plot", "spaeth", "--example", "2", "-o", "-"], ""),
        (vec!["solve", "-"], PROBLEM),
        (vec!["prove", "(x+y)^2", "x^2 + 2x y + y^2"], ""),
        (vec!["prove", "x", "x", "--random", "3", "--json"], ""),
    ]
}

/// Runs `args` with standard output connected to `stdout`, feeding `input`.
fn run_with_stdout(args: &[&str], input: &str, stdout: Stdio) -> std::process::Child {
    let mut child = bin()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn exactcheck");
    let mut stdin = child.stdin.take().expect("stdin");
    stdin.write_all(input.as_bytes()).expect("write stdin");
    drop(stdin);
    child
}

#[test]
fn a_closed_stdout_ends_quietly_with_status_0() {
    // Old: "failed printing to stdout: Broken pipe", a panic (status 101).
    for (args, input) in commands() {
        let mut child = run_with_stdout(&args, input, Stdio::piped());
        // The reader goes away before anything is written, as `head -1` does after one line.
        drop(child.stdout.take());
        let o = child.wait_with_output().expect("wait");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
        assert!(!err.contains("error"), "{args:?}: {err}");
    }
}

#[test]
fn verify_piped_into_head_reads_one_line_and_exits_0() {
    let mut child = run_with_stdout(&["verify"], "", Stdio::piped());
    let mut out = child.stdout.take().expect("stdout");
    let mut first = Vec::new();
    let mut byte = [0u8; 1];
    while std::io::Read::read(&mut out, &mut byte).expect("read") == 1 && byte[0] != b'\n' {
        first.push(byte[0]);
    }
    drop(out);
    let o = child.wait_with_output().expect("wait");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        String::from_utf8_lossy(&first).starts_with("id "),
        "{first:?}"
    );
    assert!(!err.contains("panicked"), "{err}");
    // The table is written in one piece: it either fit into the pipe (exit 0 or 1 by the
    // verdicts) or hit the closed pipe (exit 0); never the panic's 101 or an error line.
    assert!(
        matches!(o.status.code(), Some(0 | 1)),
        "{:?}: {err}",
        o.status
    );
}

#[cfg(target_os = "linux")]
#[test]
fn a_full_stdout_is_one_line_and_status_2() {
    // Old: a panic, "failed printing to stdout: No space left on device".
    for (args, input) in commands() {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full");
        let child = run_with_stdout(&args, input, Stdio::from(full));
        let o = child.wait_with_output().expect("wait");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        // plot -o - also reports what it wrote on standard error; the error is the last line.
        assert_eq!(
            err.lines().last(),
            Some("exactcheck: error: cannot write standard output: No space left on device"),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn counts_out_of_range_are_one_line_naming_flag_and_limit() {
    for (args, message) in [
        (
            &["regress", "cylinder-sphere", "--samples", "1000000000000"][..],
            "number of samples exceeds the limit samples = 100000 (found 1000000000000; raise it with --limit samples=N)",
        ),
        (
            &["regress", "bezier-cubic", "--samples", "0"][..],
            "--samples must be between 1 and 100000 (got 0)",
        ),
    ] {
        let start = Instant::now();
        let o = exactcheck(args);
        assert!(start.elapsed() < Duration::from_secs(10), "{args:?}");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&o.stderr),
            format!("exactcheck: error: {message}\n"),
            "{args:?}"
        );
        assert!(o.stdout.is_empty());
    }
}

#[test]
fn usage_errors_are_one_line_plus_a_hint_for_every_subcommand() {
    // Old: 3-16 lines (usage, help pointer, lists).
    for args in [
        &["frobnicate"][..],
        &[][..],
        &["verify", "--nope"][..],
        &["verify", "--only"][..],
        &["prove", "x", "x", "--random", "many"][..],
        &["prove"][..],
        &["solve", "--float", "--both"][..],
        &["solve", "a", "b"][..],
        &["regress", "--samples", "-3"][..],
        &["regress", "--samples", "18446744073709551616"][..],
        &["regress"][..],
        &["regress", "no-such-kernel"][..],
        &["regress", "bezier-cubic", "--seed", "x"][..],
        &["plot"][..],
        &["plot", "spaeth", "--view", "4d", "-o", "x.svg"][..],
        &["plot", "spaeth", "--example", "2"][..],
    ] {
        let o = exactcheck(args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 2, "{args:?}: {err}");
        assert!(
            lines[0].starts_with("exactcheck: error: "),
            "{args:?}: {err}"
        );
        assert!(
            lines[1].starts_with("exactcheck: hint: "),
            "{args:?}: {err}"
        );
        assert!(lines[1].contains("--help`"), "{args:?}: {err}");
        assert!(o.stdout.is_empty(), "{args:?}");
    }
    let o = exactcheck(&["regress", "--bogus"]);
    assert_eq!(
        String::from_utf8_lossy(&o.stderr).lines().next(),
        Some("exactcheck: error: unexpected argument '--bogus' found")
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("see `exactcheck regress --help`"));
    // Help is not an error: standard output, status 0.
    let o = exactcheck(&["regress", "--help"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&o.stdout).contains("Usage:"));
}

#[cfg(unix)]
#[test]
fn invalid_utf8_in_an_argument_names_it() {
    use std::os::unix::ffi::OsStrExt;
    let bad = std::ffi::OsStr::from_bytes(b"caf\xe9");
    // Old: "invalid UTF-8 was detected in one or more arguments" and the usage.
    let o = bin()
        .args(["verify", "--only"])
        .arg(bad)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(
        err.lines().next(),
        Some("exactcheck: error: the value of --only is not valid UTF-8: \"caf\\u{FFFD}\"")
    );
    let o = bin().args(["plot"]).arg(bad).output().expect("run");
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr)
        .starts_with("exactcheck: error: argument 2 is not valid UTF-8"));
}

#[test]
fn plot_to_dash_writes_standard_output_not_a_file() {
    // Old: wrote a file named `-`.
    let dir = TempDir::new("dash");
    let o = bin()
        .args(["plot", "spaeth", "--example", "1", "-o", "-"])
        .current_dir(&dir.0)
        .output()
        .expect("run");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8_lossy(&o.stdout);
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(!dir.0.join("-").exists(), "a file named - was written");
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("wrote standard output: t-u diagram"));
}

/// The one line on standard error of a run that must fail with status 2.
fn one_error_line(o: &Output) -> String {
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(!err.contains("panicked"), "{err}");
    err.trim_end().to_string()
}

#[test]
fn limit_flags_are_checked_and_listed() {
    let e = one_error_line(&exactcheck(&["prove", "x", "x", "--limit", "nope=3"]));
    assert!(
        e.starts_with("exactcheck: error: --limit: no limit named `nope` (limits: file-size, "),
        "{e}"
    );
    let e = one_error_line(&exactcheck(&["--limit", "depth=deep", "prove", "x", "x"]));
    assert_eq!(
        e,
        "exactcheck: error: --limit depth: `deep` is not a non-negative integer"
    );
    let e = one_error_line(&exactcheck(&["prove", "x", "x", "--limit", "depth"]));
    assert!(e.contains("--limit takes NAME=VALUE"), "{e}");
    // `limits` lists every limit of the registry, with a value changed by --limit.
    let o = exactcheck(&["limits", "--json", "--limit", "depth=1_000"]);
    assert!(o.status.success());
    let list: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let list = list.as_array().expect("an array");
    assert_eq!(list.len(), exactcheck::limits::all().len());
    for (entry, limit) in list.iter().zip(exactcheck::limits::all()) {
        assert_eq!(entry["name"], limit.name());
        assert_eq!(entry["default"], limit.default_value());
        let value = if limit.name() == "depth" {
            1000
        } else {
            limit.default_value()
        };
        assert_eq!(entry["value"], value, "{}", limit.name());
    }
}

#[test]
fn the_file_size_limit_is_one_line_before_reading_the_rest() {
    let dir = TempDir::new("size");
    let path = dir.0.join("big.json");
    std::fs::write(&path, vec![b' '; 5000]).expect("write");
    let p = path.to_str().expect("UTF-8 temp path");
    let e = one_error_line(&exactcheck(&["solve", p, "--limit", "file-size=4096"]));
    assert!(
        e.contains("input size exceeds the limit file-size = 4096 bytes")
            && e.contains("raise it with --limit file-size=N"),
        "{e}"
    );
    // At the limit the file is read (and refused for what it holds, not for its size).
    let e = one_error_line(&exactcheck(&["solve", p, "--limit", "file-size=5000"]));
    assert!(!e.contains("file-size"), "{e}");
}

#[test]
fn the_memory_limit_ends_the_run_with_one_line_instead_of_an_abort() {
    // The allocator's backstop, where no size is predicted: the whole catalogue in 2 MB.
    let e = one_error_line(&exactcheck(&["--limit", "memory=2", "verify"]));
    assert_eq!(
        e,
        "exactcheck: error: memory in use exceeds the limit memory = 2 MB (raise it with --limit memory=N)"
    );
    // (x0 + ... + x29)^6 has C(35, 6) = 1,623,160 terms: far more than 20 MB.
    let vars: Vec<String> = (0..30).map(|i| format!("x{i}")).collect();
    let lhs = format!("({})^6", vars.join("+"));
    let e = one_error_line(&exactcheck(&[
        "prove",
        &lhs,
        "0",
        "--limit",
        "memory=20",
        "--limit",
        "terms=100000000",
    ]));
    // The expansion predicts its size against a quarter of the limit and stops first; the
    // allocator's backstop would end the run with the same limit named.
    assert!(
        e.starts_with("exactcheck: error: ")
            && e.contains("memory in use exceeds the limit memory = 20 MB")
            && e.contains("raise it with --limit memory=N"),
        "{e}"
    );
}

/// Runs `exactcheck ARGS...` with its address space bounded to `kib` KiB (`ulimit -v`).
#[cfg(target_os = "linux")]
fn with_address_space(kib: u64, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(common::EXACTCHECK)
        .args(args)
        .output()
        .expect("run sh")
}

#[cfg(target_os = "linux")]
#[test]
fn a_memory_limit_above_the_address_space_is_one_line_not_an_allocation_abort() {
    // (x0 + ... + x29)^6 needs far more than 300 MB; the system refused an allocation before
    // the count reached the limit, and the runtime aborted (exit status 134).
    let vars: Vec<String> = (0..30).map(|i| format!("x{i}")).collect();
    let lhs = format!("({})^6", vars.join("+"));
    for memory in ["memory=100000", "memory=1536"] {
        let out = with_address_space(
            300_000,
            &[
                "prove",
                &lhs,
                "0",
                "--limit",
                memory,
                "--limit",
                "terms=100000000",
            ],
        );
        let e = one_error_line(&out);
        assert!(
            e.starts_with("exactcheck: error: ") && e.contains("memory"),
            "{memory}: {e}"
        );
    }
}

#[test]
fn timeout_ends_a_long_run_with_one_line_and_leaves_a_short_one_alone() {
    let start = Instant::now();
    let e = one_error_line(&exactcheck(&[
        "prove",
        "(x+y+z)^1000",
        "0",
        "--timeout",
        "0.5",
    ]));
    assert_eq!(
        e,
        "exactcheck: error: the command did not finish within --timeout 0.5 s"
    );
    assert!(start.elapsed() < Duration::from_secs(60));
    let o = exactcheck(&["prove", "(a+b)^2", "a^2+2a b+b^2", "--timeout", "60"]);
    assert!(o.status.success(), "{o:?}");
    for bad in ["0", "-1", "nan", "inf"] {
        let flag = format!("--timeout={bad}");
        let e = one_error_line(&exactcheck(&["prove", "x", "x", &flag]));
        assert!(e.contains("--timeout"), "{e}");
    }
}

/// The table of limits in docs/limits.md lists every limit of the registry with its default (so the
/// documentation cannot drift from the code).
#[test]
fn the_limits_page_lists_every_limit_with_its_default() {
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/limits.md"))
        .expect("read docs/limits.md");
    let section = page
        .split("## Resource limits")
        .nth(1)
        .expect("a Resource limits section");
    let rows: Vec<(String, u64)> = section
        .lines()
        .take_while(|l| !l.starts_with("## "))
        .filter_map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            let name = cells.get(1)?.strip_prefix('`')?.strip_suffix('`')?;
            let digits: String = cells
                .get(2)?
                .split(['(', ' '])
                .next()?
                .chars()
                .filter(|c| *c != ',')
                .collect();
            let value = if name == "file-size" {
                8 << 20
            } else {
                digits.parse().ok()?
            };
            Some((name.to_string(), value))
        })
        .collect();
    let expected: Vec<(String, u64)> = exactcheck::limits::all()
        .iter()
        .map(|l| (l.name().to_string(), l.default_value()))
        .collect();
    assert_eq!(rows, expected);
    assert!(section.contains("| `file-size` | 8 MiB (8,388,608 bytes) |"));
}

/// Raising `depth` used to abort the process on deep input ("thread 'main' has overflowed its
/// stack", status 134 at 8,000 nested parentheses with `--limit depth=30000`): the command now
/// runs on a stack reserved for the limit in force, and the limit has a maximum.
#[test]
fn deep_input_at_the_largest_depth_limit_answers_instead_of_overflowing_the_stack() {
    let max = exactcheck::cli::MAX_DEPTH;
    let depth = format!("depth={max}");
    // Each parenthesis is two levels (the group and its expression).
    let n = (max as usize - 2) / 2;
    let deep = format!("{}x{}", "(".repeat(n), ")".repeat(n));
    let o = exactcheck(&["prove", &deep, "x", "--limit", &depth]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stdout).contains("proved"));
    // A claims file, checked on rayon's workers.
    let dir = TempDir::new("deep");
    let file = dir.0.join("deep.toml");
    let negs = "-".repeat(2000);
    std::fs::write(
        &file,
        format!(
            "[paper]\nname = \"p\"\ntitle = \"t\"\n[[claim]]\nid = \"p.a\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"{deep}\"\nrhs = \"x\"\n[[claim]]\nid = \"p.b\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"{negs}x\"\nrhs = \"x\"\n"
        ),
    )
    .expect("write the claims file");
    let o = exactcheck(&[
        "verify",
        file.to_str().expect("UTF-8 path"),
        "--limit",
        &depth,
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(out.contains("2 claims, 2 as expected, 2 proved"), "{out}");
    // Above the maximum: one line, before anything is read.
    let e = one_error_line(&exactcheck(&[
        "prove",
        "x",
        "x",
        "--limit",
        &format!("depth={}", max + 1),
    ]));
    assert_eq!(
        e,
        format!("exactcheck: error: --limit depth: at most {max} levels (found {}): every level needs stack", max + 1)
    );
}

/// Runs `exactcheck ARGS` under `ulimit -f BLOCKS` (512-byte blocks in POSIX `sh`) in `dir`,
/// with standard output to the file `stdout_file` there when given.
#[cfg(unix)]
fn under_file_size_limit(
    blocks: u32,
    dir: &std::path::Path,
    stdout_file: Option<&str>,
    args: &[&str],
) -> Output {
    let redirect = stdout_file.map_or(String::new(), |f| format!(" > '{f}'"));
    Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -f {blocks} && exec \"$0\" \"$@\"{redirect}"
        ))
        .arg(common::EXACTCHECK)
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run sh")
}

#[cfg(unix)]
#[test]
fn the_file_size_limit_keeps_the_old_output_and_is_one_line() {
    // Old: SIGXFSZ killed the process (no message, no exit status) after truncating the old
    // file and writing its first bytes.
    let dir = TempDir::new("ulimit");
    let old = "<svg>the old figure</svg>\n";
    std::fs::write(dir.0.join("fig.svg"), old).unwrap();
    let o = under_file_size_limit(
        2,
        &dir.0,
        None,
        &["plot", "spaeth", "--example", "1", "-o", "fig.svg"],
    );
    assert_eq!(
        one_error_line(&o),
        "exactcheck: error: cannot write fig.svg: File too large"
    );
    assert_eq!(std::fs::read_to_string(dir.0.join("fig.svg")).unwrap(), old);

    let paper = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/mypaper.toml");
    std::fs::create_dir(dir.0.join("out")).unwrap();
    std::fs::write(dir.0.join("out/index.html"), "the old page").unwrap();
    let o = under_file_size_limit(4, &dir.0, None, &["report", paper, "-o", "out", "--quiet"]);
    assert_eq!(
        one_error_line(&o),
        "exactcheck: error: cannot write out/index.html: File too large"
    );
    assert_eq!(
        std::fs::read_to_string(dir.0.join("out/index.html")).unwrap(),
        "the old page"
    );
    // A directory the report created for a page it could not write is removed again.
    let o = under_file_size_limit(4, &dir.0, None, &["report", paper, "-o", "new/dir"]);
    one_error_line(&o);
    assert!(!dir.0.join("new").exists());

    // Standard output redirected to a file: one line too.
    let o = under_file_size_limit(
        1,
        &dir.0,
        Some("r.txt"),
        &["regress", "cylinder-sphere", "--samples", "20", "--quiet"],
    );
    assert_eq!(
        one_error_line(&o),
        "exactcheck: error: cannot write standard output: File too large"
    );
    let left: Vec<String> = std::fs::read_dir(&dir.0)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "temporary files left: {left:?}");
}

#[test]
fn a_timeout_leaves_no_partial_text_report() {
    // Old: the first part of the cylinder-sphere report was printed before the root and sign
    // sweeps ran, so a timeout during them left a report that looked complete but was not.
    let args = [
        "regress",
        "cylinder-sphere",
        "--samples",
        "10000",
        "--quiet",
    ];
    let start = Instant::now();
    let full = exactcheck(&args);
    let whole = start.elapsed().as_secs_f64();
    assert!(full.status.success(), "{full:?}");
    let text = String::from_utf8_lossy(&full.stdout);
    assert!(text.contains("signs of A^2 - B near tangency"), "{text}");
    // The first part used to appear at about a third of the run: stop the run at 60% of it.
    let timeout = format!("{:.3}", whole * 0.6);
    let mut all = vec!["--timeout", timeout.as_str()];
    all.extend_from_slice(&args);
    let o = exactcheck(&all);
    match o.status.code() {
        Some(2) => {
            let e = one_error_line(&o);
            assert!(
                e.starts_with("exactcheck: error: the command did not finish within --timeout"),
                "{e}"
            );
            assert!(
                o.stdout.is_empty(),
                "part of a report: {}",
                String::from_utf8_lossy(&o.stdout)
            );
        }
        // The second run was faster than 60% of the first: then the report is whole.
        Some(0) => assert!(String::from_utf8_lossy(&o.stdout).contains("near tangency")),
        _ => panic!("{o:?}"),
    }
}

/// `RAYON_NUM_THREADS=100000` used to start (or try to start) 100,000 threads, for minutes; it is
/// past the `threads` limit now, refused with one line before any thread starts.
#[test]
fn a_huge_rayon_num_threads_is_refused_with_one_line() {
    let o = bin()
        .args(["regress", "--formula", "x*x", "--samples", "10", "--quiet"])
        .env("RAYON_NUM_THREADS", "100000")
        .output()
        .expect("run exactcheck");
    let e = one_error_line(&o);
    assert_eq!(
        e,
        "exactcheck: error: worker threads (RAYON_NUM_THREADS) exceeds the limit threads = 1024 (found 100000; raise it with --limit threads=N)"
    );
    assert!(o.stdout.is_empty());
}

/// When the system refuses rayon's worker threads, the command runs on one thread with one
/// warning line, instead of panicking ("The global thread pool has not been initialized") or
/// refusing. The threads are refused here by an address-space limit (`ulimit -v`, which binds
/// root too, unlike `ulimit -u`): eight workers of a gigabyte of stack each at the largest depth
/// limit do not fit in 3 GB.
#[cfg(target_os = "linux")]
#[test]
fn a_thread_pool_that_cannot_start_falls_back_to_one_thread() {
    let exe = common::EXACTCHECK;
    let depth = format!("depth={}", exactcheck::cli::MAX_DEPTH);
    let script = format!(
        "ulimit -v 3000000 && exec \"{exe}\" --limit {depth} regress --formula 'x*x' --samples 600 --quiet"
    );
    let o = Command::new("sh")
        .args(["-c", &script])
        .env("RAYON_NUM_THREADS", "8")
        .output()
        .expect("run sh");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("exactcheck: warning: cannot start 8 worker threads (")
            && err.ends_with("); running on one thread\n"),
        "{err}"
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("600 compared"), "{out}");
    // The same run with threads it can start prints the same report.
    let o = exactcheck(&["regress", "--formula", "x*x", "--samples", "600", "--quiet"]);
    assert_eq!(String::from_utf8_lossy(&o.stdout), out);
}

#[test]
fn a_limit_error_quoting_a_file_name_with_a_newline_stays_one_line() {
    let dir = TempDir::new("newline-name");
    let path = dir.0.join("big\nname.json");
    std::fs::write(&path, vec![b' '; 5000]).expect("write");
    let p = path.to_str().expect("UTF-8 temp path");
    let e = one_error_line(&exactcheck(&["solve", p, "--limit", "file-size=4096"]));
    assert!(
        e.contains("big\\nname.json: more than 4096 bytes") && e.contains("file-size = 4096"),
        "{e}"
    );
}

#[test]
fn sub_millisecond_timeouts_are_refused_in_one_short_line() {
    let start = Instant::now();
    for bad in ["1e-300", "0.0009"] {
        let flag = format!("--timeout={bad}");
        let e = one_error_line(&exactcheck(&["prove", "x", "x", &flag]));
        assert_eq!(
            e,
            format!(
                "exactcheck: error: --timeout must be a number of seconds between 0.001 and 1e9 (got {bad})"
            )
        );
    }
    assert!(start.elapsed() < Duration::from_secs(30));
    let o = exactcheck(&["prove", "x", "x", "--timeout", "0.001"]);
    // A millisecond is accepted: the run answers or the timer ends it, in one line either way.
    assert!(matches!(o.status.code(), Some(0 | 2)), "{o:?}");
}

#[test]
fn formula_variable_lists_and_subject_options_are_checked() {
    let e = one_error_line(&exactcheck(&[
        "regress",
        "--formula",
        "x + y",
        "--vars",
        "x,,y",
        "--samples",
        "5",
    ]));
    assert_eq!(
        e,
        "exactcheck: error: --formula: \"\" in the variable list is not a variable name"
    );
    let o = exactcheck(&[
        "regress",
        "cylinder-sphere",
        "--name",
        "foo",
        "--samples",
        "5",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    assert!(o.stdout.is_empty(), "{o:?}");
    assert!(
        err.lines().next().is_some_and(|l| l
            == "exactcheck: error: --name applies to --fpcore FILE only; give --fpcore FILE or leave --name out"),
        "{err}"
    );
    // The exponent cap of a regressed formula is the limit formula-exponent.
    let e = one_error_line(&exactcheck(&[
        "regress",
        "--formula",
        "x^1025",
        "--samples",
        "5",
    ]));
    assert!(
        e.contains("exceeds the limit formula-exponent = 1024 (found 1025; raise it with --limit formula-exponent=N)"),
        "{e}"
    );
}

#[test]
fn a_deeply_nested_shard_names_the_depth_limit() {
    let dir = TempDir::new("deep-shard");
    let path = dir.0.join("shard.json");
    let deep = format!(
        "{{\"exactcheck\": {}{}}}",
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    std::fs::write(&path, deep).expect("write");
    let p = path.to_str().expect("UTF-8 temp path");
    let e = one_error_line(&exactcheck(&["merge", p, p]));
    assert!(
        e.contains("nesting depth exceeds the limit depth = 256 levels")
            && e.contains("shard.json")
            && !e.contains("recursion limit"),
        "{e}"
    );
}

#[test]
fn fpcore_names_with_newlines_and_runs_without_samples() {
    let dir = TempDir::new("fpcore");
    let path = dir.0.join("names.fpcore");
    std::fs::write(
        &path,
        "(FPCore (x) :name \"two\nlines\" (+ x 1))\n(FPCore (x) :name \"never\" :pre (< x x) x)\n",
    )
    .expect("write");
    let p = path.to_str().expect("UTF-8 temp path");
    let o = exactcheck(&["regress", "--fpcore", p, "--samples", "20"]);
    let out = String::from_utf8_lossy(&o.stdout);
    // The name is escaped in the table and the report: no line starts with its second half.
    assert!(out.contains("two\\nlines"), "{out}");
    assert!(!out.lines().any(|l| l.starts_with("lines")), "{out}");
    // `never` compares no sample: said so, no "max 0 ulps", exit status 1.
    assert!(out.contains("no sample was compared"), "{out}");
    assert!(
        !out.contains("error in ulps: max 0,"),
        "a run without samples reports an error of 0:\n{out}"
    );
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        p,
        "--name",
        "never",
        "--samples",
        "20",
    ]);
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    let o = exactcheck(&[
        "regress",
        "--fpcore",
        p,
        "--name",
        "two\nlines",
        "--samples",
        "20",
    ]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
}
