//! The claim catalogue reproduces its verdicts, and `verify` / `prove` keep their CLI contracts.

use crate::common;

use exactcheck::claims::Verdict;
use exactcheck::papers::verify;

/// The ids of the claim list that the catalogue implements (all `juttler.*` and `spaeth.*` ids,
/// `planes.wabis`, the ruled-surface and conic `chiang.*` ids and the PH ids `chiang.offset`,
/// `chiang.ph_*`: every id of the claim list).
const SPEC_IDS: [&str; 45] = [
    "juttler.lebesgue",
    "juttler.dietz",
    "juttler.satz1",
    "juttler.satz2",
    "juttler.sigma_inverse",
    "juttler.satz3",
    "juttler.lemma4",
    "juttler.satz5",
    "juttler.focal_absolute",
    "juttler.circle_preimage",
    "juttler.line_preimage",
    "juttler.line_image",
    "juttler.plane_lines",
    "juttler.interpolation",
    "juttler.satz7",
    "juttler.satz8",
    "juttler.satz9",
    "juttler.lemma10",
    "juttler.satz11",
    "spaeth.eq5",
    "spaeth.eq7",
    "spaeth.eq8",
    "spaeth.eq9",
    "spaeth.eq10",
    "spaeth.eq11",
    "spaeth.sampling",
    "spaeth.example1",
    "spaeth.example2",
    "spaeth.example3",
    "planes.wabis",
    "chiang.theorem",
    "chiang.corollary1",
    "chiang.corollary2",
    "chiang.corollary5",
    "chiang.example4",
    "chiang.conic_table",
    "chiang.conic_type",
    "chiang.line",
    "chiang.vicinity",
    "chiang.offset",
    "chiang.ph_degree",
    "chiang.ph_points",
    "chiang.ph_normals",
    "chiang.ph_radius",
    "chiang.ph_offsets",
];

/// Catalogue ids that are not ids of the claim list (documented in `claims`' module doc).
const EXTRA_IDS: [&str; 1] = ["juttler.interpolation_degree"];

/// The verdict each claim gets, pinned here independently of the catalogue's own expectation
/// (so changing an expectation in the catalogue alone does not make this test pass).
const VERDICTS: [(&str, Verdict); 46] = [
    ("juttler.lebesgue", Verdict::Proved),
    ("juttler.dietz", Verdict::Proved),
    ("juttler.satz1", Verdict::Proved),
    ("juttler.satz2", Verdict::Proved),
    ("juttler.sigma_inverse", Verdict::Proved),
    ("juttler.satz3", Verdict::Proved),
    ("juttler.lemma4", Verdict::Proved),
    ("juttler.satz5", Verdict::Proved),
    ("juttler.focal_absolute", Verdict::Proved),
    ("juttler.circle_preimage", Verdict::Proved),
    ("juttler.line_preimage", Verdict::Proved),
    ("juttler.line_image", Verdict::Proved),
    ("juttler.plane_lines", Verdict::Proved),
    ("juttler.satz8", Verdict::Proved),
    ("juttler.satz9", Verdict::Proved),
    ("juttler.lemma10", Verdict::Proved),
    ("juttler.interpolation", Verdict::Holds),
    ("juttler.interpolation_degree", Verdict::Fails),
    ("juttler.satz7", Verdict::Holds),
    ("juttler.satz11", Verdict::Proved),
    ("spaeth.eq5", Verdict::Fails),
    ("spaeth.eq7", Verdict::Proved),
    ("spaeth.eq8", Verdict::Proved),
    ("spaeth.eq9", Verdict::Fails),
    ("spaeth.eq10", Verdict::Fails),
    ("spaeth.eq11", Verdict::Proved),
    ("spaeth.sampling", Verdict::Fails),
    ("spaeth.example1", Verdict::Holds),
    ("spaeth.example2", Verdict::Holds),
    ("spaeth.example3", Verdict::Holds),
    ("planes.wabis", Verdict::Proved),
    ("chiang.theorem", Verdict::Proved),
    ("chiang.corollary1", Verdict::Proved),
    ("chiang.corollary2", Verdict::Proved),
    ("chiang.corollary5", Verdict::Proved),
    ("chiang.example4", Verdict::Fails),
    ("chiang.conic_table", Verdict::Holds),
    ("chiang.conic_type", Verdict::Holds),
    ("chiang.line", Verdict::Proved),
    ("chiang.vicinity", Verdict::Fails),
    ("chiang.offset", Verdict::Proved),
    ("chiang.ph_degree", Verdict::Proved),
    ("chiang.ph_points", Verdict::Holds),
    ("chiang.ph_normals", Verdict::Fails),
    ("chiang.ph_radius", Verdict::Fails),
    ("chiang.ph_offsets", Verdict::Fails),
];

#[test]
fn every_claim_gets_its_expected_verdict() {
    let rows = verify(None).expect("the catalogue is not empty");
    // Every claim of the catalogue is checked, once, in catalogue order.
    let ids: Vec<&str> = exactcheck::papers::catalogue()
        .iter()
        .map(|c| c.id)
        .collect();
    assert_eq!(rows.iter().map(|r| r.id.as_str()).collect::<Vec<_>>(), ids);
    for r in &rows {
        let o = r
            .outcome
            .as_ref()
            .unwrap_or_else(|e| panic!("{}: {e}", r.id));
        assert!(r.as_expected(), "{}: {} ({})", r.id, o.verdict, o.evidence);
        assert_eq!(o.verdict, r.expected, "{}: {}", r.id, o.evidence);
        assert!(!o.method.is_empty() && !o.evidence.is_empty(), "{}", r.id);
        let pinned = VERDICTS
            .iter()
            .find(|(id, _)| *id == r.id.as_str())
            .unwrap_or_else(|| panic!("{}: no pinned verdict in this test", r.id));
        assert_eq!(o.verdict, pinned.1, "{}: {}", r.id, o.evidence);
    }
    assert_eq!(rows.len(), VERDICTS.len());
}

#[test]
fn every_implemented_spec_id_is_in_the_catalogue() {
    let ids: Vec<&str> = exactcheck::papers::catalogue()
        .iter()
        .map(|c| c.id)
        .collect();
    for id in SPEC_IDS {
        assert!(ids.contains(&id), "{id} missing");
    }
    // Every juttler/spaeth id is an id of the papers' claim list or a documented extra.
    for id in &ids {
        if id.starts_with("juttler.") || id.starts_with("spaeth.") {
            assert!(
                SPEC_IDS.contains(id) || EXTRA_IDS.contains(id),
                "{id} is neither in the claim list nor a documented extra"
            );
        }
    }
    let mut sorted = ids.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), ids.len(), "duplicate ids");
}

fn exactcheck(args: &[&str]) -> std::process::Output {
    common::exactcheck().args(args).output().expect("runs")
}

#[test]
fn verify_json_and_prefix() {
    let o = exactcheck(&["verify", "--json", "--only", "juttler"]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON array");
    let arr = v.as_array().expect("array");
    let juttler = exactcheck::papers::catalogue()
        .iter()
        .filter(|c| c.id.starts_with("juttler"))
        .count();
    assert_eq!(arr.len(), juttler);
    assert_eq!(juttler, 20);
    for c in arr {
        for key in ["id", "verdict", "method", "evidence"] {
            assert!(c.get(key).is_some(), "{key} missing in {c}");
        }
        assert!(c["id"].as_str().unwrap().starts_with("juttler."));
    }
    let o = exactcheck(&["verify", "--only", "nosuch"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
    let o = exactcheck(&["verify"]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stdout).contains("juttler.lebesgue  "));
}

#[test]
fn prove_identities_typed_as_text() {
    let lebesgue = exactcheck(&[
        "prove",
        "(p0^2+p1^2+p2^2+p3^2)^2",
        "(2*p0*p1 - 2*p2*p3)^2 + (2*p0*p2 + 2*p1*p3)^2 + (p1^2+p2^2-p0^2-p3^2)^2",
    ]);
    assert!(lebesgue.status.success());
    assert!(String::from_utf8_lossy(&lebesgue.stdout).starts_with("proved"));
    let dietz = exactcheck(&["prove", "(q0*q3)*(q1*q2) - (q1*q3)*(q0*q2)"]);
    assert!(dietz.status.success());
    let circle = exactcheck(&[
        "prove",
        "c^2 x^3 + s^2 x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
    ]);
    // As the identity is usually written: juxtaposition multiplies.
    assert!(
        circle.status.success(),
        "{}",
        String::from_utf8_lossy(&circle.stdout)
    );
    let flipped = exactcheck(&[
        "prove",
        "c^2 x^3 - s^2 x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
    ]);
    assert_eq!(flipped.status.code(), Some(1));
    let circle = exactcheck(&[
        "prove",
        "c^2*x^3 + s^2*x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
    ]);
    assert!(
        circle.status.success(),
        "{}",
        String::from_utf8_lossy(&circle.stdout)
    );
}

#[test]
fn prove_reports_a_counter_example_for_a_flipped_sign() {
    let o = exactcheck(&[
        "prove",
        "c^2*x^3 - s^2*x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["verdict"], "fails");
    // The point satisfies the relation exactly and the residual there is the reported value.
    let q = |name: &str| {
        v["point"][name]
            .as_str()
            .unwrap()
            .parse::<exactcheck_exact::Rational>()
            .unwrap()
    };
    let (c, s, x) = (q("c"), q("s"), q("x"));
    use exactcheck_core::Ring;
    assert_eq!(c.square() + s.square(), exactcheck_exact::Rational::ONE);
    let lhs = c.square() * x.pow(3) - s.square() * x.pow(3) - &x;
    let rhs = x.pow(3) - &x;
    let value: exactcheck_exact::Rational = v["value"].as_str().unwrap().parse().unwrap();
    assert_eq!(lhs - rhs, value);
    assert!(!value.is_zero());
    // Lebesgue with one sign flipped fails too.
    let o = exactcheck(&[
        "prove",
        "(p0^2+p1^2+p2^2+p3^2)^2",
        "(2*p0*p1 + 2*p2*p3)^2 + (2*p0*p2 + 2*p1*p3)^2 + (p1^2+p2^2-p0^2-p3^2)^2",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("fails: at "));
}

#[test]
fn prove_rejects_bad_input_with_status_2() {
    for args in [
        &["prove", "x +"][..],
        &["prove", "x/0"][..],
        &["prove", "x/(y - y)"][..],
        &["prove", "x", "--where", "x"][..],
        &["prove", "sqrt(-1)*x"][..],
        &["prove", "(((x"][..],
    ] {
        let o = exactcheck(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(!err.contains("panicked"));
    }
}

#[test]
fn prove_random_mod_p() {
    let o = exactcheck(&[
        "prove",
        "c^2*x^3 + s^2*x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
        "--random",
        "4",
        "--json",
    ]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "holds");
    assert!(v["evidence"]
        .as_str()
        .unwrap()
        .contains("probability <= 2^-"));
    let o = exactcheck(&[
        "prove",
        "c^2*x^3 - s^2*x^3 - x",
        "x^3 - x",
        "--where",
        "c^2 + s^2 = 1",
        "--random",
        "4",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("fails"));
    // Chiang's identity for (m, n) = (4, 6) as text (the benchmark chiang-identity's input, as
    // `bench/scripts/anchors/chiang_text.py 4 6` prints it): holds mod p, and proved by expansion.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/chiang_identity_4_6.txt"
    ))
    .expect("the fixture");
    let (lhs, rhs) = text.trim_end().split_once('\n').expect("two lines");
    let (lhs, rhs) = (lhs.to_string(), rhs.to_string());
    let o = exactcheck(&["prove", &lhs, &rhs, "--random", "3"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stdout));
    let o = exactcheck(&["prove", &lhs, &rhs]);
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("proved"));
    // A perturbed coefficient (the anchors' --negative) fails both ways.
    let bad = rhs.replacen("1/1*", "8/7*", 1);
    assert_ne!(bad, rhs);
    assert_eq!(
        exactcheck(&["prove", &lhs, &bad, "--random", "3"])
            .status
            .code(),
        Some(1)
    );
    assert_eq!(exactcheck(&["prove", &lhs, &bad]).status.code(), Some(1));
}

fn exactcheck_on_threads(threads: &str, args: &[&str]) -> std::process::Output {
    common::exactcheck()
        .args(args)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .expect("runs")
}

/// The lines of `chiang.theorem`'s row with the digits taken out: its evidence reports measured
/// milliseconds (the only timing in the table); every other line is compared as it is.
fn without_times(text: &str) -> String {
    text.lines()
        .map(|l| {
            if l.starts_with("chiang.theorem ") {
                l.chars().filter(|c| !c.is_ascii_digit()).collect()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The claims run in parallel, but `verify`, `verify --json` and `verify --latex` print the
/// same bytes on one thread and on several (times aside: `seconds` and the theorem's measured
/// milliseconds), in catalogue order.
#[test]
fn verify_output_does_not_depend_on_the_number_of_threads() {
    let text = |threads| {
        let o = exactcheck_on_threads(threads, &["verify"]);
        assert!(o.status.success(), "{threads} threads");
        without_times(&String::from_utf8_lossy(&o.stdout))
    };
    let one = text("1");
    assert!(one.contains("46 claims, 46 as expected"), "{one}");
    assert_eq!(one, text("3"));
    let json = |threads| {
        let o = exactcheck_on_threads(threads, &["verify", "--json"]);
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON array");
        v.as_array()
            .expect("array")
            .iter()
            .map(|c| {
                let mut c = c.clone();
                c.as_object_mut().expect("object").remove("seconds");
                if c["id"] == "chiang.theorem" {
                    let e = c["evidence"].as_str().expect("evidence");
                    c["evidence"] = without_times(&format!("chiang.theorem {e}")).into();
                }
                c
            })
            .collect::<Vec<_>>()
    };
    let one = json("1");
    let ids: Vec<&str> = one.iter().map(|c| c["id"].as_str().unwrap()).collect();
    let catalogue: Vec<&str> = exactcheck::papers::catalogue()
        .iter()
        .map(|c| c.id)
        .collect();
    assert_eq!(ids, catalogue);
    assert_eq!(one, json("4"));
    let latex = |threads| exactcheck_on_threads(threads, &["verify", "--latex"]).stdout;
    assert_eq!(latex("1"), latex("2"));
}

/// `--limit` is read by the claims on rayon's worker threads (every claim runs on one): a
/// limit too low for the printed formulas makes the same claims errors naming it, on one
/// thread and on several.
#[test]
fn worker_threads_see_the_limits() {
    let rows = |threads| {
        let o = exactcheck_on_threads(
            threads,
            &[
                "verify", "--only", "juttler", "--json", "--limit", "terms=3",
            ],
        );
        assert_eq!(
            o.status.code(),
            Some(1),
            "{threads} threads: not as expected"
        );
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON array");
        v.as_array()
            .expect("array")
            .iter()
            .map(|c| (c["id"].clone(), c["verdict"].clone(), c["evidence"].clone()))
            .collect::<Vec<_>>()
    };
    let many = rows("4");
    let limited: Vec<_> = many
        .iter()
        .filter(|(_, v, e)| {
            v == "error"
                && e.as_str()
                    .unwrap()
                    .contains("exceeds the limit terms = 3 (found 4")
        })
        .map(|(id, _, _)| id.as_str().unwrap())
        .collect();
    assert!(limited.contains(&"juttler.lebesgue"), "{many:?}");
    assert!(limited.contains(&"juttler.satz2"), "{many:?}");
    assert_eq!(many, rows("1"));
    // The default limit: no error.
    let o = exactcheck_on_threads("4", &["verify", "--only", "juttler.lebesgue"]);
    assert!(o.status.success());
}
