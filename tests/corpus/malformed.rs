//! The malformed-input corpus: every file of `tests/malformed/` is fed to the command
//! that reads it, and the answer must be a refusal — exit status 2, exactly one line on standard
//! error (plus clap's hint line for usage errors), equal to the case's `.expect` file, nothing on
//! standard output, no "panicked" anywhere, within the kill-timeout, not the memory backstop, and
//! the named limit for the cases of `LIMITS`.
//!
//! The convention (which command reads which file, the `.args` format, `KNOWN_FAILURES`,
//! blessing) is documented in `tests/malformed/README.md`; [`case_of`] implements it.
//! `EXACTCHECK_BLESS=1 cargo test --test corpus malformed::` rewrites the `.expect` file of every case that
//! refuses as it should from its actual standard error (so messages can be re-pinned after a
//! deliberate change); the `.expect` files of the other cases (hand-written: the line wanted after
//! the fix) are kept, and every other check still applies.

use crate::common::golden;
use crate::timed;

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::OsString;
use std::os::unix::ffi::OsStringExt as _;
use std::path::PathBuf;
use timed::{parallel_map, root, run, Run};

/// The corpus directory, relative to the repository root.
const DIR: &str = "tests/malformed";

/// Files of the corpus directory that are not cases.
const NOT_CASES: &[&str] = &["README.md", "KNOWN_FAILURES", "LIMITS"];

/// Where the temporary directory of a run (`{tmp}` in `.args` files) is shown in `.expect` files.
const TMP: &str = "{tmp}";

/// One case: the file, the command line it is read by and its standard input.
#[derive(Debug)]
struct Case {
    /// The file name, e.g. `solve_bom.json`; also its name in `KNOWN_FAILURES`.
    name: String,
    /// The command line after `exactcheck`, `{tmp}` still unreplaced.
    args: Vec<OsString>,
    /// Standard input, if any.
    stdin: Option<Vec<u8>>,
    /// What reads the input, for the coverage check: `solve`, `verify toml`, `prove --where`, ...
    readers: Vec<String>,
}

fn os(s: &str) -> OsString {
    OsString::from(s)
}

/// The case of the corpus file `name` (the command is chosen by the extension), or an error
/// for a file the convention does not know.
fn case_of(name: &str) -> Result<Case, String> {
    let rel = format!("{DIR}/{name}");
    let file = || os(&rel);
    let simple = |args: Vec<OsString>, reader: &str| Case {
        name: name.to_string(),
        args,
        stdin: None,
        readers: vec![reader.to_string()],
    };
    Ok(if name.ends_with(".args") {
        args_case(name)?
    } else if name.ends_with(".plot.json") {
        simple(
            vec![os("plot"), file(), os("-o"), os(&format!("{TMP}/plot.svg"))],
            "plot",
        )
    } else if name.ends_with(".shard.json") {
        simple(
            vec![
                os("merge"),
                os(&format!("{DIR}/data/shard_1of2.json")),
                file(),
            ],
            "merge",
        )
    } else if name.ends_with(".claims.json") {
        simple(vec![os("verify"), file()], "verify json")
    } else if name.ends_with(".float.json") {
        simple(vec![os("solve"), os("--float"), file()], "solve --float")
    } else if name.ends_with(".json") {
        simple(vec![os("solve"), file()], "solve")
    } else if name.ends_with(".toml") {
        simple(vec![os("verify"), file()], "verify toml")
    } else if name.ends_with(".fpcore") {
        simple(
            vec![
                os("regress"),
                os("--fpcore"),
                file(),
                os("--samples"),
                os("10"),
                os("--quiet"),
            ],
            "regress --fpcore",
        )
    } else {
        return Err(format!(
            "{rel}: not a case (known: .json .float.json .plot.json .shard.json .claims.json \
             .toml .fpcore .args; see {DIR}/README.md)"
        ));
    })
}

/// A `.args` case: one argument per line (bytes, so invalid UTF-8 can be written), `# ` lines
/// are comments, a line `<PATH` gives standard input from a file.
fn args_case(name: &str) -> Result<Case, String> {
    let path = root().join(DIR).join(name);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let body = bytes.strip_suffix(b"\n").unwrap_or(&bytes);
    let mut args = Vec::new();
    let mut stdin = None;
    for line in body.split(|&b| b == b'\n') {
        if line.starts_with(b"# ") || line == b"#" {
            continue;
        }
        if let Some(input) = line.strip_prefix(b"<") {
            let input = String::from_utf8(input.to_vec())
                .map_err(|_| format!("{name}: the path after `<` is not UTF-8"))?;
            let data = std::fs::read(root().join(&input))
                .map_err(|e| format!("{name}: standard input {input}: {e}"))?;
            stdin = Some(data);
            continue;
        }
        args.push(OsString::from_vec(line.to_vec()));
    }
    let first = args
        .first()
        .ok_or_else(|| format!("{name}: no arguments"))?
        .to_string_lossy()
        .into_owned();
    // The reader: the subcommand (or the first argument, for a bad global option) and the
    // options that carry input text.
    let mut readers = vec![first.clone()];
    for a in &args {
        let a = a.to_string_lossy();
        for flag in [
            "--where",
            "--domain",
            "--formula",
            "--limit",
            "--timeout",
            "--program",
            "--random",
            "--samples",
            "--n",
        ] {
            if a == flag || a.starts_with(&format!("{flag}=")) {
                readers.push(format!("{first} {flag}"));
                readers.push(flag.to_string());
            }
        }
    }
    if stdin.is_some() {
        readers.push(format!("{first} stdin"));
    }
    Ok(Case {
        name: name.to_string(),
        args,
        stdin,
        readers,
    })
}

/// Every case of the corpus, sorted by name.
fn corpus() -> Vec<Case> {
    let mut names: Vec<String> = std::fs::read_dir(root().join(DIR))
        .expect("read tests/malformed")
        .map(|e| e.expect("directory entry"))
        .filter(|e| e.file_type().expect("file type").is_file())
        .map(|e| e.file_name().into_string().expect("UTF-8 file name"))
        .filter(|n| !n.ends_with(".expect") && !NOT_CASES.contains(&n.as_str()))
        .collect();
    names.sort();
    names
        .iter()
        .map(|n| case_of(n).unwrap_or_else(|e| panic!("{e}")))
        .collect()
}

/// `KNOWN_FAILURES`: case name -> reason (`NAME  # reason` lines; blank and `#` lines skipped).
fn known_failures() -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(root().join(DIR).join("KNOWN_FAILURES"))
        .expect("read tests/malformed/KNOWN_FAILURES");
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let (name, reason) = l.split_once('#').unwrap_or((l, ""));
            (name.trim().to_string(), reason.trim().to_string())
        })
        .collect()
}

fn expect_path(name: &str) -> PathBuf {
    // NAME.EXT -> NAME.expect, the extension being everything after the first dot.
    let stem = name.split_once('.').map_or(name, |(stem, _)| stem);
    root().join(DIR).join(format!("{stem}.expect"))
}

/// Runs a case in its own temporary directory; standard error with the directory shown as
/// `{tmp}`.
fn run_case(case: &Case, hang: bool) -> (Run, String) {
    let tmp = std::env::temp_dir().join(format!(
        "exactcheck-malformed-{}-{}",
        std::process::id(),
        case.name
    ));
    std::fs::create_dir_all(&tmp).expect("create temp dir");
    let tmp_text = tmp.to_str().expect("UTF-8 temp dir").to_string();
    let watchdog = [os("--timeout"), os(HANG_TIMEOUT)];
    let args: Vec<OsString> = watchdog[..if hang { 2 } else { 0 }]
        .iter()
        .chain(&case.args)
        .map(|a| match a.to_str() {
            Some(s) => OsString::from(s.replace(TMP, &tmp_text)),
            None => a.clone(),
        })
        .collect();
    let r = run(&args, case.stdin.as_deref());
    let _ = std::fs::remove_dir_all(&tmp);
    let stderr = r.stderr_text().replace(&tmp_text, TMP);
    (r, stderr)
}

/// The one line of a refusal: `Some(error line)` when standard error is one newline-terminated
/// line, optionally followed by clap's `exactcheck: hint: ...` line (the contract asks for usage
/// errors as one line plus a hint); `None` for anything else.
fn error_line(stderr: &str) -> Option<&str> {
    let body = stderr.strip_suffix('\n')?;
    match body.split_once('\n') {
        None => Some(body),
        Some((line, hint)) if hint.starts_with(HINT) && !hint.contains('\n') => Some(line),
        Some(_) => None,
    }
}

/// The start of the optional second line of a usage error.
const HINT: &str = "exactcheck: hint: ";

/// The refusal contract for one run: `Ok` or what is wrong. `limit`: the registry limit the
/// line must name (from `LIMITS`). With `ignore_message`, the line is not compared with the
/// `.expect` file (blessing asks whether the case may be re-pinned).
fn judge(
    case: &Case,
    r: &Run,
    stderr: &str,
    limit: Option<&str>,
    ignore_message: bool,
) -> Result<(), String> {
    if r.timed_out {
        return Err(format!("no answer: {}", r.describe()));
    }
    if r.panicked() {
        return Err(format!("\"panicked\" in the output: {}", r.describe()));
    }
    if r.status != Some(2) {
        return Err(format!("exit status is not 2: {}", r.describe()));
    }
    let Some(line) = error_line(stderr) else {
        return Err(format!("not one line on stderr: {}", r.describe()));
    };
    if !r.stdout.is_empty() {
        return Err(format!(
            "a refusal printed to stdout: {}",
            shorten(&r.stdout_text())
        ));
    }
    // The allocator's memory cap is a backstop (the limits contract): an input that reaches it
    // has escaped the named limits, unless the case lowers the cap on purpose.
    let sets_memory = case
        .args
        .iter()
        .any(|a| a.to_string_lossy().starts_with("memory="));
    if line.contains("the limit memory =") && !sets_memory {
        return Err(format!(
            "stopped by the memory backstop, not by a named limit: {line}"
        ));
    }
    if let Some(limit) = limit {
        // `a|b`: either limit may be the one reached first.
        let named = limit
            .split('|')
            .any(|l| line.contains(&format!("exceeds the limit {l} = ")));
        if !named {
            return Err(format!(
                "the line does not name the limit {limit} (LIMITS): {}",
                shorten(line)
            ));
        }
    }
    if ignore_message {
        return Ok(());
    }
    let path = expect_path(&case.name);
    let expected = std::fs::read_to_string(&path).map_err(|e| {
        format!(
            "{}: {e} (EXACTCHECK_BLESS=1 cargo test --test corpus malformed:: writes it)",
            path.display()
        )
    })?;
    if stderr != expected {
        return Err(format!(
            "stderr differs from {}:\n      got: {}\n expected: {}",
            path.file_name().unwrap_or_default().to_string_lossy(),
            shorten(stderr.trim_end()),
            shorten(expected.trim_end())
        ));
    }
    Ok(())
}

/// At most 400 characters of `text`, for failure messages (some inputs are echoed whole).
fn shorten(text: &str) -> String {
    let short: String = text.chars().take(400).collect();
    if short.len() < text.len() {
        format!("{short} ...")
    } else {
        short
    }
}

/// `LIMITS`: case name -> the registry limit its line must name (`NAME  limit` lines; `a|b` for
/// either of two).
fn limit_cases() -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(root().join(DIR).join("LIMITS"))
        .expect("read tests/malformed/LIMITS");
    text.lines()
        .map(|l| l.split_once('#').map_or(l, |(l, _)| l).trim())
        .filter(|l| !l.is_empty())
        .map(|l| {
            let mut words = l.split_whitespace();
            let name = words.next().expect("a case name").to_string();
            let limit = words
                .next()
                .unwrap_or_else(|| panic!("LIMITS: `{l}` names no limit"))
                .to_string();
            (name, limit)
        })
        .collect()
}

/// Whether a `KNOWN_FAILURES` reason marks a hang: such a case is run with `--timeout`
/// [`HANG_TIMEOUT`] so that the product's own watchdog ends it (and the test stays short).
fn is_hang(reason: &str) -> bool {
    reason.starts_with("hang")
}

/// The `--timeout` given to a case listed as a hang.
const HANG_TIMEOUT: &str = "5";

#[test]
fn every_malformed_input_is_refused_with_one_line_and_status_2() {
    let cases = corpus();
    let known = known_failures();
    let limits = limit_cases();
    let bless = golden::blessing();
    let names: BTreeSet<&str> = cases.iter().map(|c| c.name.as_str()).collect();
    let mut problems = Vec::new();
    for (file, listed) in [("KNOWN_FAILURES", &known), ("LIMITS", &limits)] {
        for name in listed.keys() {
            if !names.contains(name.as_str()) {
                problems.push(format!(
                    "{name}: listed in {file} but not a case of the corpus"
                ));
            }
        }
    }
    let registry: BTreeSet<&str> = exactcheck::limits::all().iter().map(|l| l.name()).collect();
    for (name, limit) in &limits {
        if !limit.split('|').all(|l| registry.contains(l)) {
            problems.push(format!(
                "{name}: LIMITS names `{limit}`, not a limit of the registry"
            ));
        }
    }
    let results = parallel_map(&cases, |case| {
        let hang = known.get(&case.name).is_some_and(|r| is_hang(r));
        let (r, stderr) = run_case(case, hang);
        let limit = limits.get(&case.name).map(String::as_str);
        // Blessing re-pins the message of a case that refuses as it should; it keeps the
        // `.expect` of one that does not (the line wanted after the fix, written by hand), and of
        // a hang (whose line is the watchdog's).
        if bless && !hang && judge(case, &r, &stderr, limit, true).is_ok() {
            std::fs::write(expect_path(&case.name), &stderr).expect("write .expect");
        }
        (r.timed_out, judge(case, &r, &stderr, limit, false))
    });
    let mut known_seen = 0;
    for (case, (timed_out, verdict)) in cases.iter().zip(results) {
        match (known.get(&case.name), verdict) {
            (None, Ok(())) => {}
            (None, Err(why)) => problems.push(format!("{}: {why}", case.name)),
            (Some(_), Ok(())) => problems.push(format!(
                "{}: passes now; remove it from tests/malformed/KNOWN_FAILURES",
                case.name
            )),
            (Some(_), Err(why)) if timed_out => problems.push(format!(
                "{}: a known failure must still end within the kill-timeout: {why}",
                case.name
            )),
            (Some(reason), Err(why)) => {
                known_seen += 1;
                eprintln!("known failure {} ({reason}): {why}", case.name);
            }
        }
    }
    eprintln!(
        "{} cases, {known_seen} known failures, {} problems",
        cases.len(),
        problems.len()
    );
    assert!(
        problems.is_empty(),
        "{} problem(s) in the malformed corpus:\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
}

#[test]
fn the_corpus_covers_every_solve_kind_and_every_reading_command() {
    let cases = corpus();
    assert!(
        cases.len() >= 40,
        "the corpus has {} cases; the corpus needs at least 40",
        cases.len()
    );
    let readers: BTreeSet<&str> = cases
        .iter()
        .flat_map(|c| c.readers.iter().map(String::as_str))
        .collect();
    let required = [
        "solve",
        "solve --float",
        "solve stdin",
        "verify toml",
        "verify json",
        "regress --fpcore",
        "regress --formula",
        "regress --domain",
        "regress --program",
        "merge",
        "plot",
        "prove",
        "prove --where",
        "prove --random",
        "--limit",
        "--timeout",
    ];
    let missing: Vec<&str> = required
        .iter()
        .copied()
        .filter(|r| !readers.contains(r))
        .collect();
    assert!(
        missing.is_empty(),
        "no case of the corpus reads input through: {missing:?}"
    );
    // Every kind of `solve` has at least one broken problem file that names it.
    let solve_texts: Vec<String> = cases
        .iter()
        .filter(|c| c.readers.iter().any(|r| r.starts_with("solve")))
        .filter_map(|c| std::fs::read(root().join(DIR).join(&c.name)).ok())
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .collect();
    let unnamed: Vec<&str> = exactcheck::solve::kinds()
        .iter()
        .map(|k| k.name)
        .filter(|k| !solve_texts.iter().any(|t| t.contains(&format!("\"{k}\""))))
        .collect();
    assert!(
        unnamed.is_empty(),
        "no solve case of the corpus is of kind {unnamed:?}"
    );
}

#[test]
fn every_case_has_its_expected_line_and_nothing_else_lies_around() {
    let cases = corpus();
    let mut problems = Vec::new();
    for case in &cases {
        let path = expect_path(&case.name);
        match std::fs::read_to_string(&path) {
            Err(e) => problems.push(format!("{}: {e}", path.display())),
            Ok(text) if text.trim().is_empty() => {
                problems.push(format!("{}: empty", path.display()))
            }
            Ok(_) => {}
        }
    }
    // An `.expect` file without its case is left over from a renamed or removed case.
    let stems: BTreeSet<PathBuf> = cases.iter().map(|c| expect_path(&c.name)).collect();
    for entry in std::fs::read_dir(root().join(DIR)).expect("read tests/malformed") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "expect") && !stems.contains(&path) {
            problems.push(format!("{}: no case for it", path.display()));
        }
    }
    // Two cases may not share a stem (they would share an `.expect` file).
    let mut seen = BTreeMap::new();
    for case in &cases {
        if let Some(other) = seen.insert(expect_path(&case.name), &case.name) {
            problems.push(format!("{} and {other} share an .expect file", case.name));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
