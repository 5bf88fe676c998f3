//! Claims files (`exactcheck verify FILE`): the example of Spaeth's paper gives the built-in
//! catalogue's verdicts, a misprinted copy fails with a counter-example and an erratum, and
//! every class of bad file is one line naming the file, the line and the key (exit status 2).

use crate::common;

use exactcheck::claimfile;
use exactcheck::claims::Verdict;
use exactcheck_exact::Rational;
use std::collections::HashMap;
use std::path::Path;
use std::process::Output;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .current_dir(root())
        .output()
        .expect("the binary runs")
}

fn verdicts(path: &str) -> Vec<(String, Option<Verdict>)> {
    let file = claimfile::load(&root().join(path)).expect("the file loads");
    claimfile::check(&file, None)
        .expect("the file checks")
        .into_iter()
        .map(|r| (r.id, r.outcome.ok().map(|o| o.verdict)))
        .collect()
}

#[test]
fn the_spaeth_file_reproduces_the_catalogue() {
    let file = verdicts("examples/spaeth.toml");
    let catalogue: HashMap<String, Option<Verdict>> = exactcheck::papers::verify(Some("spaeth"))
        .unwrap()
        .into_iter()
        .map(|r| (r.id, r.outcome.ok().map(|o| o.verdict)))
        .collect();
    for id in [
        "spaeth.eq5",
        "spaeth.eq7",
        "spaeth.eq8",
        "spaeth.eq9",
        "spaeth.eq10",
        "spaeth.eq11",
        "spaeth.example1",
        "spaeth.example2",
        "spaeth.example3",
    ] {
        assert!(file.iter().any(|(i, _)| i == id), "{id} is in the file");
    }
    for (id, verdict) in &file {
        let expected = catalogue
            .get(id)
            .unwrap_or_else(|| panic!("{id} is a catalogue id"));
        assert!(verdict.is_some(), "{id} has a verdict");
        assert_eq!(verdict, expected, "{id}: file vs catalogue");
    }
    let out = exactcheck(&["verify", "examples/spaeth.toml"]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(table.contains(&format!(
        "{} claims, {} as expected",
        file.len(),
        file.len()
    )));
}

#[test]
fn the_small_examples_hold() {
    for path in ["examples/mypaper.toml", "tests/claims_file/mypaper.json"] {
        let out = common::verify_json(path, 0);
        // Standard error is a pipe here: no progress bar, nothing at all.
        assert!(out.stderr.is_empty(), "{path}: {}", out.stderr);
        for r in &out.rows {
            assert_eq!(r["as_expected"], true, "{r}");
            for key in ["id", "verdict", "method", "evidence"] {
                assert!(r[key].is_string(), "{key} in {r}");
            }
        }
    }
    let v = verdicts("tests/claims_file/mypaper.json");
    let got: Vec<Option<Verdict>> = v.into_iter().map(|(_, v)| v).collect();
    use Verdict::*;
    assert_eq!(got, [Some(Proved), Some(Fails), Some(Fails), Some(Fails)]);
    let only = exactcheck(&["verify", "examples/mypaper.toml", "--only", "mypaper.eq3"]);
    assert_eq!(only.status.code(), Some(0));
    assert!(String::from_utf8(only.stdout)
        .unwrap()
        .contains("1 claims, 1 as expected"));
    let none = exactcheck(&["verify", "examples/mypaper.toml", "--only", "nope"]);
    assert_eq!(none.status.code(), Some(2));
}

#[test]
fn fractions_and_derivatives_as_printed_are_decided() {
    // Old: every claim of this file was refused ("division by a non-constant expression",
    // "unknown function 'diff'").
    let out = common::verify_json("tests/claims_file/fractions.toml", 0);
    let row = |id: &str| out.row(id);
    for r in &out.rows {
        assert_eq!(r["as_expected"], true, "{r}");
    }
    for id in ["fractions.circle", "fractions.tangent"] {
        assert_eq!(row(id)["verdict"], "proved");
        assert!(
            row(id)["evidence"]
                .as_str()
                .unwrap()
                .ends_with("where t^2 + 1 != 0 (no real zero): no real point is excluded"),
            "{}",
            row(id)
        );
    }
    let slope = row("fractions.slope");
    assert_eq!(slope["verdict"], "proved");
    assert!(
        slope["evidence"]
            .as_str()
            .unwrap()
            .ends_with("modulo m = y/x, where x != 0"),
        "{slope}"
    );
    let misprint = row("fractions.misprint");
    assert_eq!(misprint["verdict"], "fails");
    let evidence = misprint["evidence"].as_str().unwrap();
    // The counter-example is off the poles x = 1 and x = -1.
    assert!(evidence.starts_with("at x = "), "{evidence}");
    assert!(!evidence.starts_with("at x = 1 ") && !evidence.starts_with("at x = -1 "));
    assert!(evidence.ends_with("where x^2 - 1 != 0"), "{evidence}");
}

#[test]
fn functions_matrices_and_vector_values_are_decided() {
    let v = verdicts("tests/claims_file/functions.toml");
    let want = [
        ("functions.even", Verdict::Proved),
        ("functions.area", Verdict::Proved),
        ("functions.hodograph", Verdict::Proved),
        ("functions.rotation", Verdict::Proved),
        ("functions.rotation_det", Verdict::Proved),
        ("functions.midpoint", Verdict::Proved),
        ("functions.unit_vector", Verdict::Holds),
        ("functions.misprinted_point", Verdict::Fails),
    ];
    assert_eq!(v.len(), want.len());
    for ((id, got), (wid, wv)) in v.iter().zip(want) {
        assert_eq!(id, wid);
        assert_eq!(*got, Some(wv), "{id}");
    }
    let out = exactcheck(&["verify", "tests/claims_file/functions.toml", "--json"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{text}");
    // The misprinted point: the first coordinate is wrong, the second correctly rounded.
    assert!(
        text.contains("component 1: exact value 9/16") && text.contains("0.63: wrong"),
        "{text}"
    );
    assert!(
        text.contains("component 2: exact value 13/16")
            && text.contains("0.81: correctly rounded to 2 places"),
        "{text}"
    );
}

#[test]
fn vector_and_matrix_identities_are_decided_component_by_component() {
    // The shape mismatch is a bad claim: the file exits 2, every other claim is decided.
    let out = common::verify_json("tests/claims_file/vectors.toml", 2);
    let rows = &out.rows;
    let verdicts: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r["id"].as_str().unwrap(), r["verdict"].as_str().unwrap()))
        .collect();
    assert_eq!(
        verdicts,
        [
            ("vectors.hodograph", "proved"),
            ("vectors.orthogonal", "proved"),
            ("vectors.misprinted_hodograph", "fails"),
            ("vectors.shapes", "error"),
            ("vectors.derivative_at_a_point", "holds"),
            ("vectors.sum_of_squares", "holds"),
            ("vectors.bound_names", "holds"),
        ],
        "{rows:?}"
    );
    // The failure names its component and the counter-example inside the domain.
    let misprint = rows[2]["evidence"].as_str().unwrap();
    assert!(
        misprint.starts_with("in component 2 (y): at t = 1/2"),
        "{misprint}"
    );
    let shapes = rows[3]["evidence"].as_str().unwrap();
    assert!(
        shapes.contains("key rhs: a 2x2 matrix but lhs is a vector of 4"),
        "{shapes}"
    );
}

#[test]
fn a_misprint_fails_with_a_counter_example_and_an_erratum() {
    let example = std::fs::read_to_string(root().join("examples/spaeth.toml")).unwrap();
    let fixture =
        std::fs::read_to_string(root().join("tests/claims_file/spaeth_misprint.toml")).unwrap();
    // The fixture is the example with one misprint (and a header saying so).
    let printed = "(-sg*(b + r*st) + cg*(-sb*(a + r*ct) + u*cb) - f)^2 - R^2\"";
    let misprint = "(-sg*(b + r*st) + cg*(-sb*(a + r*ct) + u*cb) - f)^2 + R^2\"";
    assert_eq!(example.matches(printed).count(), 1);
    let body = fixture
        .split_once("# Spaeth's cylinder/sphere paper")
        .map(|(_, b)| format!("# Spaeth's cylinder/sphere paper{b}"))
        .unwrap();
    assert_eq!(body, example.replace(printed, misprint));

    let file = claimfile::load(&root().join("tests/claims_file/spaeth_misprint.toml")).unwrap();
    let rows = claimfile::check(&file, Some("spaeth.eq7")).unwrap();
    let o = rows[0].outcome.as_ref().unwrap();
    // Old answer (as printed in the paper): proved.
    assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    assert!(!rows[0].as_expected());
    assert!(o.evidence.starts_with("at "), "{}", o.evidence);
    let e = o.erratum.as_ref().expect("a failing claim has an erratum");
    assert!(!e.printed.is_empty());
    assert!(!e.counter_example.is_empty());
    assert_eq!(e.residual.len(), 1);
    assert!(e.correction.contains("R^2"), "{}", e.correction);
    assert!(e
        .notation
        .iter()
        .any(|(n, l)| n == "cb" && l == "\\cos\\beta"));
    // The residual's value is the printed one minus the derivation, 2 R^2, at the point.
    let r = e
        .counter_example
        .iter()
        .find(|q| q.lhs.to_string() == "R")
        .expect("R is in the counter-example");
    let r: Rational = r.rhs.to_string().parse().unwrap();
    let value: Rational = e.residual[0].rhs.to_string().parse().unwrap();
    assert_eq!(value, Rational::from_integer(2) * r.clone() * r);

    let out = common::verify_json("tests/claims_file/spaeth_misprint.toml", 1);
    let eq7 = out.row("spaeth.eq7");
    assert_eq!(eq7["verdict"], "fails");
    assert_eq!(eq7["as_expected"], false);
}

#[test]
fn bad_files_are_one_line_with_file_line_and_key() {
    let cases = [
        (
            "syntax_error.toml",
            4,
            "claim \"bad.syntax\": key lhs: unexpected ')' at 13",
        ),
        ("toml_syntax.toml", 4, "TOML: "),
        (
            "unknown_key.toml",
            5,
            "claim \"bad.key\": key rsh: unknown field `rsh`",
        ),
        (
            "missing_key.toml",
            1,
            "claim \"bad.missing\": key lhs: missing",
        ),
        (
            "duplicate_id.toml",
            8,
            "claim \"bad.dup\": key id: duplicate id (first at line 2)",
        ),
        (
            "unknown_kind.toml",
            3,
            "claim \"bad.kind\": key kind: unknown kind \"theorem\"",
        ),
        (
            "wrong_key_for_kind.toml",
            6,
            "claim \"bad.kindkey\": key rhs: kind value does not take",
        ),
        (
            "unknown_function.toml",
            4,
            "claim \"bad.function\": key lhs: unknown function 'exp' at 0",
        ),
        (
            "wrong_arity.toml",
            7,
            "claim \"bad.arity\": key lhs: cross at 0 takes 2 arguments, not 1",
        ),
        (
            "vector_for_scalar.toml",
            8,
            "claim \"bad.vector\": key printed: 1 printed value for a vector of 3",
        ),
        (
            "function_arity.toml",
            11,
            "claim \"bad.function_arity\": key lhs: cross2 at 0 takes 2 arguments, not 3",
        ),
        (
            "cycle.toml",
            2,
            "define: key A: the definitions refer to themselves: A -> B -> C -> A",
        ),
        (
            "inconsistent.toml",
            6,
            "claim \"bad.relations\": key where: the relations",
        ),
        (
            "unknown_key.json",
            7,
            "claim \"bad.json\": key printd: unknown field `printd`",
        ),
        (
            "bad_expression.json",
            6,
            "claim \"bad.json_expr\": key expr: unexpected end of input",
        ),
        ("json_syntax.json", 4, "claim #1: JSON: expected `,` or `}`"),
        (
            "e_variable.toml",
            4,
            "claim \"growth\": key lhs: e is the constant e (Euler's number), not a variable",
        ),
        (
            "bad_latex.toml",
            7,
            "claim \"bad.latex\": key latex.s: notation s = \"\\\\input{/etc/passwd}\": the command \\input is not accepted",
        ),
    ];
    for (name, line, what) in cases {
        let path = format!("tests/claims_file/{name}");
        let out = exactcheck(&["verify", &path]);
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(out.stdout.is_empty(), "{name}");
        assert!(!err.contains("panicked"), "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        let prefix = format!("exactcheck: error: {path}:{line}: {what}");
        assert!(err.starts_with(&prefix), "{name}:\n{err}\nwanted {prefix}");
    }
    let out = exactcheck(&["verify", "tests/claims_file/no_such_file.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8(out.stderr)
        .unwrap()
        .contains("cannot read"));
}

/// Runs `f` on a rayon pool of `threads` threads (the claims and their instances are checked on
/// the pool the caller runs in).
fn on_threads<R: Send>(threads: usize, f: impl FnOnce() -> R + Send) -> R {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(f)
}

/// Claims are checked in parallel; a claim with a fault found while checking is a row with the
/// verdict `error` and its one-line message (the first faulty instance of the claim named),
/// the others are decided, whatever the number of threads. When no chosen claim can be
/// decided, the file is refused with the first claim's message.
#[test]
fn faults_found_while_checking_are_error_rows_on_any_number_of_threads() {
    let text = r#"
[[claim]]
id = "a"
kind = "identity"
lhs = "(x + y)^2"
rhs = "x^2 + 2*x*y + y^2"

[[claim]]
id = "b"
kind = "instances"
lhs = "x + y"
rhs = "y + x"
at = [{ x = 1, y = 2 }, { x = 1 }, { y = 3 }]

[[claim]]
id = "c"
kind = "identity"
lhs = "(x + y)^8"
rhs = "(y + x)^8"

[[claim]]
id = "d"
kind = "instances"
lhs = "c"
rhs = "c"
where = ["c^2 + s^2 = 1"]
at = [{ c = 1, s = 1 }]
"#;
    let file = claimfile::parse(text, "p.toml", "p").expect("the file loads");
    for threads in [1, 2, 4, 8] {
        for _ in 0..3 {
            let rows = on_threads(threads, || claimfile::check(&file, None)).expect("rows");
            let shown: Vec<(String, String, bool)> = rows
                .iter()
                .map(|r| {
                    let j = r.to_json();
                    (
                        j["verdict"].as_str().unwrap().to_string(),
                        j["evidence"].as_str().unwrap().to_string(),
                        r.bad_input,
                    )
                })
                .collect();
            assert_eq!(shown[0].0, "proved", "{threads} threads");
            assert_eq!(
                (shown[1].0.as_str(), shown[1].1.as_str(), shown[1].2),
                (
                    "error",
                    "p.toml:13: claim \"b\": key at: instance 2 gives no value to y",
                    true
                ),
                "{threads} threads"
            );
            assert_eq!(shown[2].0, "proved", "{threads} threads");
            assert_eq!(shown[3].0, "error", "{threads} threads");
            assert!(shown[3]
                .1
                .contains("claim \"d\": key at: instance 1 does not satisfy"));
        }
    }
    // Only d: nothing can be decided, so the file is refused with d's message.
    let e = on_threads(4, || claimfile::check(&file, Some("d")))
        .err()
        .expect("a fault of the file");
    assert!(
        e.to_string()
            .contains("claim \"d\": key at: instance 1 does not satisfy"),
        "{e}"
    );
}

/// A claim that cannot be built does not sink the file: it is the row `error` with its
/// one-line message, the other claims are decided, and the exit status is 2.
#[test]
fn one_bad_claim_does_not_sink_the_file() {
    let out = common::verify_json("tests/claims_file/one_broken.toml", 2);
    let rows = &out.rows;
    assert_eq!(out.verdicts(), ["proved", "error", "holds"]);
    let message = rows[1]["evidence"].as_str().unwrap();
    assert!(
        message.starts_with(
            "tests/claims_file/one_broken.toml:16: claim \"bad.formula\": key lhs: unexpected ')' at 11"
        ),
        "{message}"
    );
    assert_eq!(rows[1]["as_expected"], false);
    let out = exactcheck(&["verify", "tests/claims_file/one_broken.toml"]);
    assert_eq!(out.status.code(), Some(2));
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains("bad.formula  error"), "{table}");
    assert!(
        table.contains("3 claims, 2 as expected, 1 proved, 1 holds, 0 fails, 0 undecided, 1 error"),
        "{table}"
    );
}

/// A corrected form that is not proved equal to `rhs` makes the claim not as expected, even
/// when its verdict is the expected one.
#[test]
fn a_wrong_correction_makes_the_claim_not_as_expected() {
    let out = common::verify_json("tests/claims_file/corrected_wrong.toml", 1);
    let row = &out.rows[0];
    assert_eq!(row["verdict"], "fails");
    assert_eq!(row["expected"], "fails");
    assert_eq!(row["as_expected"], false);
    let problem = row["problem"].as_str().expect("a problem");
    assert!(problem.starts_with("it differs from RHS by "), "{problem}");
    assert!(row["evidence"]
        .as_str()
        .unwrap()
        .contains("(The given correction does not match RHS either: it differs from RHS by"));
    let out = exactcheck(&["verify", "tests/claims_file/corrected_wrong.toml"]);
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(
        table.contains("<< not as expected: it differs from RHS by"),
        "{table}"
    );
}

/// Near misses of defined and declared names are warned about (standard error), the claims
/// are still decided.
#[test]
fn near_miss_names_are_warned_about() {
    let out = exactcheck(&["verify", "tests/claims_file/near_miss.toml"]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    let warnings: Vec<&str> = err.lines().filter(|l| l.contains("warning")).collect();
    assert_eq!(
        warnings,
        [
            "exactcheck: warning: tests/claims_file/near_miss.toml:9: claim \"typo.define\": Aa is neither defined nor a declared variable; did you mean A (defined)?",
            "exactcheck: warning: tests/claims_file/near_miss.toml:15: claim \"typo.declared\": thetaa is neither defined nor a declared variable; did you mean theta (a declared variable)?",
        ]
    );
}

/// The rows of a claims file, as JSON without the times, on 1 and on several threads.
#[test]
fn claims_file_rows_do_not_depend_on_the_number_of_threads() {
    let file = claimfile::load(&root().join("examples/spaeth.toml")).expect("the file loads");
    let rows = |threads: usize| -> Vec<serde_json::Value> {
        on_threads(threads, || claimfile::check(&file, None))
            .expect("the file checks")
            .iter()
            .map(|r| {
                let mut v = r.to_json();
                v.as_object_mut().expect("an object").remove("seconds");
                v
            })
            .collect()
    };
    let one = rows(1);
    assert!(one.len() >= 9);
    assert_eq!(one, rows(4));
}

#[test]
fn a_chosen_seed_gives_no_bound_and_cannot_be_aimed_at_its_prime() {
    let file = claimfile::load(&root().join("tests/claims_file/chosen_seed.toml")).unwrap();
    let rows = claimfile::check(&file, None).unwrap();
    let outcome = |id: &str| {
        rows.iter()
            .find(|r| r.id == id)
            .and_then(|r| r.outcome.as_ref().ok())
            .unwrap_or_else(|| panic!("{id}"))
    };
    // Seed 7 alone gave the prime 7294315414320791317, which divides the coefficient: the old
    // answer was `holds` with "probability <= 2^-55.9".
    let crafted = outcome("seed.crafted");
    assert_eq!(crafted.verdict, Verdict::Fails, "{}", crafted.evidence);
    assert!(
        !crafted.method.contains("7294315414320791317"),
        "{}",
        crafted.method
    );
    // A true identity with a chosen seed: zero at every point, no probability bound claimed.
    let binomial = outcome("seed.binomial");
    assert_eq!(binomial.verdict, Verdict::Holds, "{}", binomial.evidence);
    assert!(
        binomial.evidence.contains("no probability bound"),
        "{}",
        binomial.evidence
    );
    assert!(
        !binomial.evidence.contains("probability <="),
        "{}",
        binomial.evidence
    );
    assert!(
        binomial.method.contains("seed 7, chosen"),
        "{}",
        binomial.method
    );
}

/// Writes `text` to a fresh file `name` under the system temp dir and runs `verify` on it with
/// `extra` arguments; returns the output.
fn verify_generated(name: &str, text: &str, extra: &[&str]) -> Output {
    let dir = std::env::temp_dir().join(format!("exactcheck-claims-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write the claims file");
    let mut args = vec!["verify", path.to_str().expect("UTF-8 temp path")];
    args.extend_from_slice(extra);
    let out = exactcheck(&args);
    let _ = std::fs::remove_dir_all(&dir);
    out
}

/// The one line of a refused run (exit status 2, nothing on standard output).
fn refusal(out: &Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
    err
}

/// `a0 = "x"`, `a1 = "a0 + 1"`, ..., `aN = "a(N-1) + 1"`, listed last first when `reversed`
/// (then resolving `aN` resolves every other inside it), and one claim on `aN`.
fn chain_file(n: usize, reversed: bool) -> String {
    let mut defs: Vec<String> = (1..=n)
        .map(|k| format!("a{k} = \"a{} + 1\"\n", k - 1))
        .collect();
    defs.insert(0, "a0 = \"x\"\n".into());
    if reversed {
        defs.reverse();
    }
    format!(
        "[define]\n{}[[claim]]\nid = \"chain\"\nkind = \"identity\"\nlhs = \"a{n}\"\nrhs = \"x + {n}\"\n",
        defs.concat()
    )
}

#[test]
fn a_long_chain_of_definitions_is_refused_at_the_depth_limit() {
    for reversed in [false, true] {
        let out = verify_generated("chain.toml", &chain_file(3000, reversed), &[]);
        let err = refusal(&out);
        assert!(
            err.contains("exceeds the limit depth = 256 levels") && err.contains("--limit depth=N"),
            "{err}"
        );
    }
    // A short chain resolves, and a raised limit lets the long one through.
    let out = verify_generated("short.toml", &chain_file(50, true), &[]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let out = verify_generated(
        "raised.toml",
        &chain_file(3000, true),
        &["--limit", "depth=7000"],
    );
    assert_eq!(out.status.code(), Some(0), "{out:?}");
}

#[test]
fn a_long_cycle_of_definitions_is_named_not_a_stack_overflow() {
    let n = 5000;
    let defs: String = (0..n)
        .map(|k| format!("a{k} = \"a{} + 1\"\n", (k + 1) % n))
        .collect();
    let text =
        format!("[define]\n{defs}[[claim]]\nid = \"cycle\"\nkind = \"identity\"\nlhs = \"a0\"\n");
    let err = refusal(&verify_generated("cycle.toml", &text, &[]));
    assert!(
        err.contains("define: key a0: the definitions refer to themselves: a0 -> a1 -> ")
            && err.contains(" -> a4999 -> a0 (a cycle of 5000 definitions)"),
        "{err}"
    );
}

#[test]
fn twenty_thousand_claims_are_read_in_linear_time() {
    // Each key's line was counted from the start of the text and each id compared with every
    // earlier one: 20,000 claims took 15 s before any was checked.
    let n = 20_000;
    let text: String = (0..n)
        .map(|k| {
            format!(
                "[[claim]]\nid = \"c{k}\"\nkind = \"identity\"\nlhs = \"(x + {k})^2\"\nrhs = \"x^2 + {}*x + {}\"\n",
                2 * k,
                k * k
            )
        })
        .collect();
    let file = claimfile::parse(&text, "many.toml", "many").expect("the file loads");
    assert_eq!(file.claims.len(), n);
    assert_eq!(file.claims[n - 1].line, 5 * (n - 1) + 2);
    // A duplicate id at the end is still found, with the line of the first.
    let dup =
        format!("{text}[[claim]]\nid = \"c7\"\nkind = \"identity\"\nlhs = \"x\"\nrhs = \"x\"\n");
    let e = claimfile::parse(&dup, "many.toml", "many")
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("duplicate id (first at line 37)"), "{e}");
    let out = verify_generated("many.toml", &text, &[]);
    let table = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{table}");
    assert!(
        table.contains(&format!("{n} claims, {n} as expected")),
        "{table}"
    );
}

#[test]
fn integrals_sums_and_binomials_as_printed_are_decided() {
    let out = common::verify_json("tests/claims_file/calculus.toml", 0);
    assert_eq!(out.rows.len(), 2);
    for r in &out.rows {
        assert_eq!(r["verdict"], "proved", "{r}");
    }
}

#[test]
fn angles_and_pi_as_printed_are_decided() {
    // The weight cos(theta/2) of a circle arc's rational Bezier form at theta = 90, 120 and 60
    // degrees (theta a rational multiple of pi), a double-angle identity and its misprint, pi.
    let out = common::verify_json("tests/claims_file/angles.toml", 0);
    let row = |id: &str| out.row(id);
    for r in &out.rows {
        assert_eq!(r["as_expected"], true, "{r}");
    }
    let evidence = |id: &str| out.evidence(id);
    assert_eq!(row("angles.w90")["verdict"], "holds");
    assert!(evidence("angles.w90").starts_with("exact value sqrt(2)/2"));
    assert_eq!(row("angles.w120")["verdict"], "proved");
    assert_eq!(row("angles.w60")["verdict"], "fails");
    assert!(evidence("angles.w60").contains("it is 0.8660"));
    assert_eq!(row("angles.half")["verdict"], "proved");
    assert_eq!(row("angles.misprint")["verdict"], "fails");
    assert!(evidence("angles.misprint").starts_with("at t = angle with cos t = "));
    assert_eq!(row("angles.pi")["verdict"], "fails");
    assert!(evidence("angles.pi").contains("pi is transcendental"));
}

#[test]
fn the_curvature_of_a_rational_quadratic_from_derivatives_of_fractions_is_proved() {
    let out = common::verify_json("tests/claims_file/rational_curvature.toml", 0);
    let row = &out.rows[0];
    assert_eq!(row["verdict"], "proved", "{row}");
    assert!(
        row["evidence"]
            .as_str()
            .unwrap()
            .contains("with the denominators cleared"),
        "{row}"
    );
}

#[test]
fn arc_weights_printed_with_angles_pi_and_nested_radicals_get_exact_verdicts() {
    let v: HashMap<String, Option<Verdict>> = verdicts("tests/claims_file/arc_weights.toml")
        .into_iter()
        .collect();
    let want = [
        ("arc.w90", Verdict::Holds),
        ("arc.w45", Verdict::Holds),
        ("arc.w45_radical", Verdict::Holds),
        ("arc.w120", Verdict::Fails),
        ("arc.w120_exact", Verdict::Proved),
        ("arc.control45", Verdict::Holds),
        ("arc.control120", Verdict::Holds),
        ("arc.t60", Verdict::Fails),
        ("arc.length120", Verdict::Holds),
    ];
    assert_eq!(v.len(), want.len());
    for (id, verdict) in want {
        assert_eq!(v[id], Some(verdict), "{id}");
    }
    let out = exactcheck(&["verify", "tests/claims_file/arc_weights.toml", "--json"]);
    assert_eq!(out.status.code(), Some(0), "every verdict is as expected");
    let text = String::from_utf8(out.stdout).unwrap();
    // The exact value printed as radicals, its correct rounding, the misprint's closed form.
    for needle in [
        "exact value 2 - sqrt(3)",
        "correctly rounded to 4 places it is 0.2679",
        "exact value sqrt(2 + sqrt(2))/2",
        "the printed 0.866 is the rounding of sqrt(3)/2",
        "exact value 2/3*pi",
        "certified enclosure of pi",
    ] {
        assert!(text.contains(needle), "{needle} in {text}");
    }
}

#[test]
fn algebraic_constants_next_to_variables_are_decided_as_prove_decides_them() {
    let out = exactcheck(&[
        "--limit",
        "algebraic-degree=4",
        "verify",
        "tests/claims_file/constants.toml",
        "--json",
    ]);
    // The claim past the limit is an error row; the others are decided.
    assert_eq!(out.status.code(), Some(2));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON rows");
    let row = |id: &str| {
        rows.as_array()
            .unwrap()
            .iter()
            .find(|r| r["id"] == id)
            .unwrap_or_else(|| panic!("row {id}"))
            .clone()
    };
    for (id, verdict) in [
        ("k.cos36", "proved"),
        ("k.nested", "proved"),
        ("k.heptagon", "fails"),
        ("k.vector", "fails"),
        ("k.instances", "holds"),
        ("k.too_large", "error"),
    ] {
        assert_eq!(row(id)["verdict"], verdict, "{id}: {}", row(id));
    }
    // The field is named as `prove` names it.
    let cos36 = row("k.cos36")["evidence"].as_str().unwrap().to_string();
    assert!(
        cos36.contains("with c = cos(pi/5), 4*c^2 - 2*c - 1 = 0, sqrt(5) = 4*c - 1"),
        "{cos36}"
    );
    // The exact counter-example, its Root written in a variable that is not the claim's x,
    // and the same text as `prove` gives.
    let heptagon = row("k.heptagon");
    let evidence = heptagon["evidence"].as_str().unwrap();
    assert!(
        evidence.starts_with("at x = 1: LHS - RHS = Root(8*z^3 + 16*z^2 + 6*z - 1, 1/16, 1/8)"),
        "{evidence}"
    );
    let prove = exactcheck(&["prove", "x*cos(2*pi/7)", "x/2"]);
    assert_eq!(prove.status.code(), Some(1));
    let prove_text = String::from_utf8(prove.stdout).unwrap();
    assert_eq!(prove_text.trim(), format!("fails: {evidence}"));
    assert_eq!(heptagon["erratum"]["counter_example"][0]["text"], "x = 1");
    assert_eq!(
        heptagon["erratum"]["residual"][0]["text"],
        "x*cos(2*pi/7) - x/2 = 1*cos(2*pi/7) - 1/2"
    );
    // A vector side fails in the component that differs, with a radical value.
    let vector = row("k.vector")["evidence"].as_str().unwrap().to_string();
    assert!(
        vector.starts_with("in component 2 (y): at x = 0, y = 1: LHS - RHS = (-1 + sqrt(5))/4"),
        "{vector}"
    );
    // The limit's one line, naming the constants.
    let too_large = row("k.too_large")["evidence"].as_str().unwrap().to_string();
    assert!(
        too_large.contains(
            "the field of the constants cos(2*pi/7), sqrt(2): degree of an algebraic number exceeds the limit algebraic-degree = 4"
        ),
        "{too_large}"
    );
    // Without the lowered limit the same claim is proved.
    let out = exactcheck(&[
        "verify",
        "tests/claims_file/constants.toml",
        "--only",
        "k.too",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// One identity reads the same from `prove` and from a claims file's `identity` claim: both
/// word the engine's report with one formatter, failing, proved with side conditions,
/// undecided, modulo relations, with angles, square roots, components, constants. The row of
/// `verify --json` carries every field of `prove --json` with the same value (verdict, method,
/// evidence, residual terms, point, value, normal form, conditions, components...).
#[test]
fn prove_and_claims_files_word_an_identity_alike() {
    let cases: &[(&str, &str, &[&str])] = &[
        ("(a+b)^3", "a^3 + 3*a^2*b + 3*a*b^2", &[]),
        ("(x^2-1)/(x-1)", "x+1", &[]),
        ("((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2", "1", &[]),
        ("x*y", "y", &["x^2 = 1"]),
        ("c^2", "1 - s^2 + c", &["c^2 + s^2 = 1"]),
        ("sin(2*x)", "2*sin(x)", &[]),
        ("sqrt(x^2)", "x", &[]),
        ("vec(x, y, z)", "vec(x, 2*y, z)", &[]),
        ("1/w", "2", &["w > 0"]),
        ("x", "0", &["x^2 = -1"]),
        ("x*cos(2*pi/7)", "x/2", &[]),
        ("x*y/y", "x", &["y > 0"]),
        ("sqrt(x^2)", "x", &["x >= 0"]),
    ];
    let mut verdicts = Vec::new();
    for (lhs, rhs, conditions) in cases {
        let mut args = vec!["prove", lhs, rhs, "--json"];
        for c in conditions.iter() {
            args.extend(["--where", c]);
        }
        let out = exactcheck(&args);
        let prove: serde_json::Value = serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("{lhs} = {rhs}: {e}: {out:?}"));
        let quoted: Vec<String> = conditions.iter().map(|c| format!("{c:?}")).collect();
        let file = format!(
            "[paper]\nname = \"alike\"\n\n[[claim]]\nid = \"alike.one\"\nkind = \"identity\"\nlhs = {lhs:?}\nrhs = {rhs:?}\nwhere = [{}]\n",
            quoted.join(", ")
        );
        let out = verify_generated("alike.toml", &file, &["--json"]);
        let rows: serde_json::Value = serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("{lhs} = {rhs}: {e}: {out:?}"));
        let row = &rows[0];
        let fields = prove.as_object().expect("prove --json prints an object");
        assert!(fields.contains_key("residual_terms"), "{prove}");
        for (key, value) in fields {
            assert_eq!(&row[key], value, "{lhs} = {rhs}: {key}");
        }
        verdicts.push(prove["verdict"].as_str().unwrap_or("").to_string());
    }
    for verdict in ["proved", "fails", "undecided"] {
        assert!(verdicts.iter().any(|v| v == verdict), "{verdicts:?}");
    }
}

/// A claims file's `instances` claim with `random` and `seed` carries the fields of
/// `prove --random K --seed S --json` on the same identity: the seed, the prime, each
/// component's verdict and prime, the error bound.
#[test]
fn random_instances_carry_the_fields_of_prove_random() {
    let cases: &[(&str, &str)] = &[
        ("(x+y)^3", "(y+x)^3"),
        ("vec(x+y, x)", "vec(y+x, 2*x)"),
        ("x+y", "y+x+1/1000000000000"),
    ];
    for (lhs, rhs) in cases {
        let out = exactcheck(&["prove", lhs, rhs, "--random", "20", "--seed", "7", "--json"]);
        let prove: serde_json::Value = serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("{lhs} = {rhs}: {e}: {out:?}"));
        let file = format!(
            "[paper]\nname = \"alike\"\n\n[[claim]]\nid = \"alike.random\"\nkind = \"instances\"\nlhs = {lhs:?}\nrhs = {rhs:?}\nrandom = 20\nseed = 7\n"
        );
        let out = verify_generated("random.toml", &file, &["--json"]);
        let rows: serde_json::Value = serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("{lhs} = {rhs}: {e}: {out:?}"));
        let row = &rows[0];
        assert_eq!(row["seed"], 7, "{row}");
        // The verdict and the advice of the evidence are worded for each front end.
        for (key, value) in prove.as_object().expect("an object") {
            if !["verdict", "evidence"].contains(&key.as_str()) {
                assert_eq!(&row[key], value, "{lhs} = {rhs}: {key}");
            }
        }
    }
}
