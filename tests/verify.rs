//! The claim catalogue reproduces its verdicts, and `verify` / `prove` keep their CLI contracts.

use exactcheck::claims::{verify, Verdict};
use std::process::Command;

#[test]
fn every_claim_gets_its_expected_verdict() {
    let rows = verify(None).expect("the catalogue is not empty");
    assert!(rows.len() >= 14);
    for r in &rows {
        let o = r
            .outcome
            .as_ref()
            .unwrap_or_else(|e| panic!("{}: {e}", r.id));
        assert_eq!(o.verdict, r.expected, "{}: {}", r.id, o.evidence);
        assert!(!o.method.is_empty() && !o.evidence.is_empty(), "{}", r.id);
    }
    for id in [
        "juttler.lebesgue",
        "juttler.dietz",
        "juttler.satz1",
        "juttler.satz5",
        "juttler.lemma4",
    ] {
        let r = rows.iter().find(|r| r.id == id).expect(id);
        assert_eq!(
            r.outcome.as_ref().map(|o| o.verdict).ok(),
            Some(Verdict::Proved),
            "{id}"
        );
    }
}

#[test]
fn every_spec_juttler_and_spaeth_id_is_in_the_catalogue() {
    let ids: Vec<&str> = exactcheck::claims::catalogue()
        .iter()
        .map(|c| c.id)
        .collect();
    for id in [
        "juttler.lebesgue",
        "juttler.dietz",
        "juttler.satz1",
        "juttler.satz2",
        "juttler.sigma_inverse",
        "juttler.satz3",
        "juttler.lemma4",
        "juttler.satz5",
        "juttler.focal_absolute",
        "juttler.interpolation",
        "juttler.satz8",
        "juttler.satz9",
        "juttler.lemma10",
        "juttler.satz11",
    ] {
        assert!(ids.contains(&id), "{id} missing");
    }
    let mut sorted = ids.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), ids.len(), "duplicate ids");
}

fn exactcheck(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(args)
        .output()
        .expect("runs")
}

#[test]
fn verify_json_and_prefix() {
    let o = exactcheck(&["verify", "--json", "--only", "juttler"]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON array");
    let arr = v.as_array().expect("array");
    assert!(arr.len() >= 14);
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
        &["prove", "x/y"][..],
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
    // W1 for (m, n) = (4, 6) as text: holds mod p, and proved by expansion.
    let (lhs, rhs) = exactcheck_exact::expr::w1_text(4, 6);
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
