//! The PH-curve claims of Chiang: each verdict, and the checks can fail — a planted
//! misprint in the printed control points, a planted non-PH hodograph in the offset proof.

use exactcheck::claims::chiang_ph::{
    offset_proof, ph_normals_with, ph_offsets_markdown, ph_offsets_rows, ph_points_with,
    self_intersection_evidence, weights_markdown, BaseForm, PRINTED_NORMALS, PRINTED_POINTS,
};
use exactcheck::claims::{Outcome, Verdict};
use exactcheck::papers::catalogue;
use exactcheck_exact::Rational;

fn run(id: &str) -> Outcome {
    let claim = catalogue()
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("{id} is not in the catalogue"));
    claim.run().unwrap_or_else(|e| panic!("{id}: {e}"))
}

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

#[test]
fn each_claim_gets_its_verdict() {
    for (id, verdict) in [
        ("chiang.offset", Verdict::Proved),
        ("chiang.ph_degree", Verdict::Proved),
        ("chiang.ph_points", Verdict::Holds),
        ("chiang.ph_normals", Verdict::Fails),
        ("chiang.ph_radius", Verdict::Fails),
        ("chiang.ph_offsets", Verdict::Fails),
    ] {
        let o = run(id);
        assert_eq!(o.verdict, verdict, "{id}: {}", o.evidence);
    }
}

#[test]
fn the_offset_proof_covers_both_forms_and_three_degrees() {
    let o = run("chiang.offset");
    for k in 1..=3 {
        for form in ["base in z = -r cut by z = 0", "base in z = 0 cut by z = r"] {
            let case = format!(
                "k = {k} (degree {}), {form}: all 12 residuals expand to 0",
                2 * k + 1
            );
            assert!(o.evidence.contains(&case), "{case} missing: {}", o.evidence);
        }
    }
    assert!(o.evidence.contains("32 random PH curves"), "{}", o.evidence);
}

#[test]
fn a_non_ph_hodograph_fails_the_offset_identity() {
    // X' = u^2 - v^2 + 1: the displacement is still r(-Y', X' + 1)/sigma, but its length is
    // not r. The engine finds it with a counter-example.
    for k in [1, 2] {
        for form in [BaseForm::BelowCutAtZero, BaseForm::AtZeroCutAtR] {
            let o = offset_proof(k, form, 1);
            assert_eq!(o.verdict, Verdict::Fails, "k = {k}: {}", o.evidence);
            assert!(o.evidence.contains("length r"), "{}", o.evidence);
            assert!(
                o.evidence.contains("counter")
                    || o.evidence.starts_with("at ")
                    || o.evidence.contains(" at "),
                "{}",
                o.evidence
            );
        }
        // The PH hodograph itself is proved.
        assert_eq!(
            offset_proof(k, BaseForm::AtZeroCutAtR, 0).verdict,
            Verdict::Proved
        );
    }
}

#[test]
fn the_degrees_are_counted_up_to_n_11() {
    let o = run("chiang.ph_degree");
    for n in [3, 5, 7] {
        assert!(
            o.evidence
                .contains(&format!("symbolic: n = {n}: V has {n} control vectors")),
            "{}",
            o.evidence
        );
    }
    for n in [9, 11] {
        assert!(
            o.evidence
                .contains(&format!("the offset's W C_x of exact degree {}", 2 * n - 1)),
            "{}",
            o.evidence
        );
    }
    assert!(o
        .evidence
        .contains("gcd of the four homogeneous coordinates 1"));
}

#[test]
fn a_planted_misprint_in_p2_is_named() {
    let mut printed = PRINTED_POINTS;
    printed[1][1] = "118/3";
    let o = ph_points_with(&printed).unwrap();
    assert_eq!(o.verdict, Verdict::Fails, "{}", o.evidence);
    assert!(
        o.evidence
            .starts_with("1 of 9 printed entries differ: p2.y: printed 118/3, derived 119/3"),
        "{}",
        o.evidence
    );
    // Unchanged data holds.
    assert_eq!(
        ph_points_with(&PRINTED_POINTS).unwrap().verdict,
        Verdict::Holds
    );
}

#[test]
fn the_printed_normals_lost_their_minus_signs() {
    let o = ph_normals_with(&PRINTED_NORMALS).unwrap();
    assert_eq!(o.verdict, Verdict::Fails);
    assert!(o.evidence.contains(
        "Left field (-Y', X', sigma) (the claim's V): exactly one of the 2^8 sign patterns gives it: a minus sign on q0.x, q1.x, q1.y, q2.y"
    ), "{}", o.evidence);
    assert!(o.evidence.contains(
        "Right field (Y', -X', sigma): exactly one of the 2^8 sign patterns gives it: a minus sign on q0.y, q2.x"
    ), "{}", o.evidence);
    assert!(o
        .evidence
        .contains("corrected: q0 = (-20, 99, 101), q1 = (-99, -20, 0), q2 = (20, -99, 101)"));
    // The derived field, given as printed data, holds.
    let derived = [
        ["-20", "99", "101"],
        ["-99", "-20", "0"],
        ["20", "-99", "101"],
    ];
    let o = ph_normals_with(&derived).unwrap();
    assert_eq!(o.verdict, Verdict::Holds, "{}", o.evidence);
}

#[test]
fn the_radius_and_the_cusps_are_exact() {
    let o = run("chiang.ph_radius");
    assert!(
        o.evidence
            .starts_with("smallest radius of curvature exactly 101/8 = 12.625000 at t = 1/2"),
        "{}",
        o.evidence
    );
    assert!(
        o.evidence
            .contains("r = 12.6 (= 63/5, as printed): no cusp"),
        "{}",
        o.evidence
    );
    assert!(o
        .evidence
        .contains("r = 101/8 (the exact minimum): 1 cusp: t = 1/2 (multiplicity 2)"));
    assert!(o.evidence.contains("r = 15: 2 cusps"));
    assert!(o
        .evidence
        .contains("r = 1009/80 (between the printed 12.6 and the exact minimum): no cusp"));
    assert!(o
        .evidence
        .contains("Corrected: the smallest radius is 101/8"));
    // Cusps and self-intersections, both decided exactly: none at 3 and 63/5, one crossing at 15.
    let e = self_intersection_evidence(&q("63/5")).unwrap();
    assert!(
        e.starts_with("r = 63/5: no cusp and no self-intersection (certified"),
        "{e}"
    );
    let e = self_intersection_evidence(&q("3")).unwrap();
    assert!(e.contains("no cusp and no self-intersection"), "{e}");
    assert!(o.evidence.contains("r = 15: 2 cusps"), "{}", o.evidence);
    assert!(
        o.evidence.contains("1 self-intersection: C(s) = C(t)"),
        "{}",
        o.evidence
    );
}

#[test]
fn the_offsets_table_has_the_exact_values() {
    let rows = ph_offsets_rows().unwrap();
    assert_eq!(rows.len(), 12);
    let md = ph_offsets_markdown(&rows);
    assert!(md.contains("| 15 | r0.x | 2.96 | `-300/101` | -2.970297 | +5.93 | **no**; neither the exact value nor its magnitude, rounded or truncated |"), "{md}");
    assert!(md.contains("| 3 | r0.x | 0.594 | `-60/101` | -0.594059 | +1.19 | **no**; reproduced by the magnitude of the exact value correctly rounded (a lost minus sign) |"), "{md}");
    assert!(
        md.contains("| 15 | r0.y | 14.7 | `1485/101` | 14.702970 | -0.00297 | yes |"),
        "{md}"
    );
    // Every row has exactly the table's 7 cells (no '|' inside a cell).
    assert!(md.lines().all(|l| l.matches('|').count() == 8), "{md}");
    let w = weights_markdown().unwrap();
    assert!(w.lines().all(|l| l.matches('|').count() == 5), "{w}");
    assert!(
        w.contains("| 15 | 0 | 101 | (-300/101, 1485/101, 15) |"),
        "{w}"
    );
    assert!(w.contains("| 63/5 | 1 | 303/5 |"), "{w}");
    let o = run("chiang.ph_offsets");
    assert!(o
        .evidence
        .starts_with("3 of 12 printed values are not the exact value correctly rounded"));
}

/// docs/papers/chiang.md shows the PH offsets' tables as the checks print them, verbatim.
#[test]
fn paper_page_tables_are_the_checks_output() {
    let readme = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/papers/chiang.md"
    ))
    .unwrap();
    let offsets = ph_offsets_markdown(&ph_offsets_rows().unwrap());
    assert!(
        readme.contains(offsets.trim()),
        "docs/papers/chiang.md's PH offsets table is stale; the check prints:\n{offsets}"
    );
    let weights = weights_markdown().unwrap();
    assert!(
        readme.contains(weights.trim()),
        "docs/papers/chiang.md's PH weights table is stale; the check prints:\n{weights}"
    );
}
