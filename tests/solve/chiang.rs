//! The `chiang.*` claims: verdicts, planted misprints, Example 4's exact values, and the paper page
//! table (generated from the check's own output).

use exactcheck::claims::chiang::{
    check_size, claims, corollary1_with, corollary2_with, corollary5_with, example4_markdown,
    example4_table, Corollary5Text, COROLLARY1_POINT_TERM, COROLLARY1_WEIGHT_TERM,
    COROLLARY2_POINT, COROLLARY5, SYMBOLIC_MAX,
};
use exactcheck::claims::Verdict;
use exactcheck_exact::Radical;

fn verdict_of(id: &str) -> (Verdict, String) {
    let claim = claims()
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("{id} is registered"));
    let o = claim.run().expect("the check runs");
    (o.verdict, o.evidence)
}

#[test]
fn verdicts() {
    for (id, expected) in [
        ("chiang.theorem", Verdict::Proved),
        ("chiang.corollary1", Verdict::Proved),
        ("chiang.corollary2", Verdict::Proved),
        ("chiang.corollary5", Verdict::Proved),
        ("chiang.example4", Verdict::Fails),
    ] {
        let (v, evidence) = verdict_of(id);
        assert_eq!(v, expected, "{id}: {evidence}");
    }
}

#[test]
fn registered_in_the_catalogue() {
    let ids: Vec<&str> = exactcheck::papers::catalogue()
        .iter()
        .map(|c| c.id)
        .collect();
    for id in [
        "chiang.theorem",
        "chiang.corollary1",
        "chiang.corollary2",
        "chiang.corollary5",
        "chiang.example4",
    ] {
        assert!(ids.contains(&id), "{id}");
    }
}

#[test]
fn theorem_symbolic_at_the_largest_size() {
    let r = check_size(SYMBOLIC_MAX.0, SYMBOLIC_MAX.1);
    assert!(r.failure.is_none(), "{:?}", r.failure);
    assert!(r.sum_terms > 0 && r.t_terms > r.sum_terms);
}

#[test]
fn planted_misprint_in_corollary5_fails_with_a_counter_example() {
    // r1 with the sign of 2 p1z q0 flipped.
    let mut printed: Corollary5Text = COROLLARY5.clone();
    printed.points[1] = "(1/(3*w1))*(q1z*p0{X} + 2*q0z*p1{X} + 2*p1z*q0{X} - p0z*q1{X})";
    let o = corollary5_with(&printed).unwrap();
    assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    assert!(o.evidence.starts_with("r1.x as printed"), "{}", o.evidence);
    assert!(o.evidence.contains("counter-example"), "{}", o.evidence);
    assert!(
        o.evidence.contains("derived form: r1.x ="),
        "{}",
        o.evidence
    );
    // A weight misprint: w2 = (q0z + 2 q1z)/3 printed with a minus sign.
    let mut printed = COROLLARY5.clone();
    printed.weights[2] = "(1/3)*(q0z - 2*q1z)";
    let o = corollary5_with(&printed).unwrap();
    assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    assert!(o.evidence.starts_with("w2 as printed"), "{}", o.evidence);
}

#[test]
fn planted_misprints_in_corollaries_1_and_2_fail() {
    let o = corollary1_with(
        COROLLARY1_WEIGHT_TERM,
        "q{i}z*p{j}{X} + p{j}z*q{i}{X}", // sign flipped
    )
    .unwrap();
    assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    assert!(o.evidence.contains("counter-example"), "{}", o.evidence);
    // A weight summand with the wrong coordinate.
    let o2 = corollary1_with("q{i}x", COROLLARY1_POINT_TERM).unwrap();
    assert_eq!(o2.verdict, Verdict::Fails, "{}", o2.evidence);
    let o3 = corollary2_with("p{k}{X} + (p{k}z/q0z)*q0{X}").unwrap();
    assert_eq!(o3.verdict, Verdict::Fails, "{}", o3.evidence);
    // The printed ones are proved.
    assert_eq!(
        corollary2_with(COROLLARY2_POINT).unwrap().verdict,
        Verdict::Proved
    );
}

#[test]
fn example4_exact_weights_are_the_radical_forms() {
    let rows = example4_table().unwrap();
    let expected = [
        "sqrt(2)",
        "(2*sqrt(2) + sqrt(6))/3",
        "(sqrt(2) + 2*sqrt(6))/3",
        "sqrt(6)",
    ];
    for (row, text) in rows.iter().zip(expected) {
        assert_eq!(row.exact_text, text);
        assert_eq!(row.exact, text.parse::<Radical>().unwrap());
    }
    assert_eq!(rows[4].exact, "-sqrt(2)/2".parse::<Radical>().unwrap());
    assert_eq!(rows[13].exact, "-1/sqrt(6)".parse::<Radical>().unwrap());
    // The printed values that are not correctly rounded: r0 (both), r1 (both), r3 (x, y).
    let wrong: Vec<&str> = rows
        .iter()
        .filter(|r| !r.correctly_rounded)
        .map(|r| r.name.as_str())
        .collect();
    assert_eq!(wrong, ["r0.x", "r0.y", "r1.x", "r1.y", "r3.x", "r3.y"]);
    // r0 = -sqrt(2)/2 printed as -0.705 is -1.41/2: reproduced by the rounded radical form.
    assert!(rows[4]
        .reproduced_by
        .iter()
        .any(|h| h.starts_with("the exact radical form with sqrt 2 = 1.41")));
}

/// docs/papers/chiang.md's Example 4 section shows the check's own output: its verdict and its table, verbatim.
#[test]
fn paper_page_table_is_the_checks_output() {
    let rows = example4_table().unwrap();
    let (verdict, _) = verdict_of("chiang.example4");
    let readme = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/papers/chiang.md"
    ))
    .unwrap();
    let table = example4_markdown(&rows);
    assert!(
        readme.contains(&table),
        "docs/papers/chiang.md's Example 4 table is stale; the check prints:\n{table}"
    );
    assert!(readme.contains(&format!("`chiang.example4` (verdict: **{verdict}**)")));
}

#[test]
fn theorem_evidence_states_the_symbolic_range_it_ran() {
    // The statement is for every m, n; the evidence used to cite a bound "the claim states".
    let (_, e) = verdict_of("chiang.theorem");
    assert!(!e.contains("claim states"), "{e}");
    let covered = format!(
        "The symbolic proof covers m <= {}, n <= {} and ({}, {}) only",
        SYMBOLIC_MAX.0,
        SYMBOLIC_MAX.1,
        SYMBOLIC_MAX.0 + 1,
        SYMBOLIC_MAX.1 + 1
    );
    assert!(e.contains(&covered), "{e}");
}
