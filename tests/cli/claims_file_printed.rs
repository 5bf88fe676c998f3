//! Value claims whose printed decimals are long (20 to 60 places, 20 integer digits): judged
//! with exact rationals at any length. Each case pins an old wrong answer of 64-bit arithmetic:
//! a wrong digit that held, a correct rounding that failed, garbage evidence, a run that never
//! finished and a panic.

use crate::common;

use exactcheck::claimfile;
use exactcheck::claims::{Outcome, Verdict};
use std::path::Path;
use std::time::{Duration, Instant};

const FILE: &str = "tests/claims_file/printed_long.toml";

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn outcomes() -> Vec<(String, Outcome)> {
    let file = claimfile::load(&root().join(FILE)).expect("the file loads");
    claimfile::check(&file, None)
        .expect("the file checks")
        .into_iter()
        .map(|r| (r.id.clone(), r.outcome.expect("a verdict")))
        .collect()
}

fn outcome<'a>(all: &'a [(String, Outcome)], id: &str) -> &'a Outcome {
    &all.iter().find(|(i, _)| i == id).expect("the claim").1
}

#[test]
fn long_printed_decimals_get_exact_verdicts_quickly() {
    let start = Instant::now();
    let all = outcomes();
    assert!(
        start.elapsed() < Duration::from_secs(20),
        "{:?}",
        start.elapsed()
    );
    let verdict = |id| outcome(&all, id).verdict;
    // Wrong from the 20th place: 1/3 - 0.33333333333333333334 < 0.
    assert_eq!(verdict("printed.third_wrong_at_20"), Verdict::Fails);
    let e = &outcome(&all, "printed.third_wrong_at_20").evidence;
    assert!(
        e.contains("correctly rounded to 37 places it is 0.3333333333333333333333333333333333333 "),
        "{e}"
    );
    // printed - exact = 0.3333333333333333333400000000000000000 - 1/3 = 2/3 10^-20.
    assert!(
        e.contains("(printed - exact = +0.00000000000000000000667)"),
        "{e}"
    );
    // 40 and 60 threes are the correct roundings of 1/3.
    assert_eq!(verdict("printed.third_40"), Verdict::Holds);
    assert_eq!(verdict("printed.third_60"), Verdict::Holds);
    let e = &outcome(&all, "printed.third_60").evidence;
    assert!(
        e.starts_with(&format!("exact value 1/3 = 0.{}...", "3".repeat(64))),
        "{e}"
    );
    // 1/200 = 0.005 exactly: the printed value is 10^-17 above it.
    assert_eq!(verdict("printed.two_hundredth"), Verdict::Fails);
    let e = &outcome(&all, "printed.two_hundredth").evidence;
    assert!(
        e.starts_with("exact value 1/200 = 0.005000000000000000000..."),
        "{e}"
    );
    assert!(
        e.contains("(printed - exact = +0.0000000000000000100)"),
        "{e}"
    );
    // sqrt(2) = 1.41421356237309504880...: 1.414213562373095 is its rounding to 15 places.
    assert_eq!(verdict("printed.sqrt2_15"), Verdict::Holds);
    let e = &outcome(&all, "printed.sqrt2_15").evidence;
    assert!(e.contains("= 1.4142135623730950488..."), "{e}");
    // 10^19 is printed exactly.
    assert_eq!(verdict("printed.ten_to_19"), Verdict::Proved);
    let e = &outcome(&all, "printed.ten_to_19").evidence;
    assert!(
        e.starts_with("exact value 10000000000000000000 = 10000000000000000000.0000..."),
        "{e}"
    );
}

/// The erratum of a wrong printed decimal quotes the decimal as printed (digits and trailing
/// zeros), not the fraction it denotes, in text and LaTeX.
#[test]
fn errata_show_the_decimals_as_printed() {
    let all = outcomes();
    let o = outcome(&all, "printed.third_wrong_at_20");
    let e = o
        .erratum
        .as_ref()
        .expect("a failing value claim has an erratum");
    let printed = "0.3333333333333333333400000000000000000";
    assert_eq!(e.printed[0].rhs.to_string(), printed);
    assert_eq!(
        e.corrected[0].rhs.to_string(),
        "0.3333333333333333333333333333333333333"
    );
    assert!(e.residual[0].lhs.to_string().starts_with(printed));
    let tex = e.printed[0].latex(&e.notation());
    assert!(tex.ends_with(&format!("= {printed}")), "{tex}");
    // The text parses back to the number it denotes.
    let back: exactcheck_exact::Rational = printed.parse().unwrap();
    assert_eq!(
        e.printed[0]
            .rhs
            .to_string()
            .parse::<exactcheck_exact::Rational>()
            .unwrap(),
        back
    );
}

#[test]
fn the_command_line_reports_the_long_printed_file_as_expected() {
    let out = common::exactcheck()
        .args(["verify", FILE, "--json"])
        .current_dir(root())
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let rows = rows.as_array().expect("rows");
    assert_eq!(rows.len(), 6);
    for r in rows {
        assert_eq!(r["as_expected"], true, "{r}");
    }
}
