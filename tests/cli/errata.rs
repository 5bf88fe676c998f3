//! The errata of the built-in catalogue: every failing claim carries an erratum computed by its
//! check (corrected form or correction, counter-example), `verify --json` carries it and
//! `verify --latex` prints it.

use exactcheck::claims::{self, latex, Checked, Verdict};

/// The failing claims of the catalogue.
const FAILING: [&str; 10] = [
    "juttler.interpolation_degree",
    "spaeth.eq5",
    "spaeth.eq9",
    "spaeth.eq10",
    "spaeth.sampling",
    "chiang.example4",
    "chiang.vicinity",
    "chiang.ph_normals",
    "chiang.ph_radius",
    "chiang.ph_offsets",
];

fn check(id: &str) -> Checked {
    let mut rows = exactcheck::papers::verify(Some(id)).expect("a catalogue id");
    rows.retain(|r| r.id == id);
    rows.pop().expect("the claim")
}

#[test]
fn every_failing_claim_has_an_erratum() {
    for id in FAILING {
        let row = check(id);
        let o = row.outcome.as_ref().expect("the check runs");
        assert_eq!(o.verdict, Verdict::Fails, "{id}");
        let e = o
            .erratum
            .as_ref()
            .unwrap_or_else(|| panic!("{id}: no erratum"));
        assert!(
            !e.corrected.is_empty() || !e.correction.is_empty(),
            "{id}: neither a corrected form nor a correction"
        );
        assert!(!e.counter_example.is_empty(), "{id}: no counter-example");
        assert!(!e.residual.is_empty(), "{id}: no residual");
        // Every equation prints as LaTeX with the erratum's notation (which must be valid).
        let lines = latex::erratum_latex(e);
        assert!(
            lines.iter().all(|(_, l)| l.contains(" = ")),
            "{id}: {lines:?}"
        );
        let json = row.to_json();
        let ej = &json["erratum"];
        assert!(ej["counter_example"][0]["text"].is_string(), "{id}: {json}");
        assert!(
            ej["counter_example"][0]["latex"].is_string(),
            "{id}: {json}"
        );
    }
}

#[test]
fn spaeth_eq5_corrected_x_in_latex() {
    let row = check("spaeth.eq5");
    let e = row.outcome.as_ref().unwrap().erratum.as_ref().unwrap();
    let x = &e.corrected[0];
    assert_eq!(x.lhs.to_string(), "x");
    let tex = x.latex(&e.notation());
    assert!(tex.starts_with("x = "), "{tex}");
    assert!(tex.contains("\\cos\\beta"), "{tex}");
    assert!(tex.contains("\\sin\\gamma"), "{tex}");
    // The printed x lacks the gamma terms the corrected one has.
    let printed = e.printed[0].latex(&e.notation());
    assert!(!printed.contains("\\gamma"), "{printed}");
    // The counter-example's residual is the engine's exact value.
    // (At the small-height point a = b = u = 0, r = 1, every angle a right angle, it is 1.)
    assert_eq!(e.residual[0].rhs.to_string(), "1");
}

#[test]
fn json_carries_the_erratum_and_proved_claims_have_none() {
    let rows = exactcheck::papers::verify(Some("spaeth.eq")).unwrap();
    for r in &rows {
        let j = r.to_json();
        let o = r.outcome.as_ref().unwrap();
        match o.verdict {
            Verdict::Fails => {
                let e = &j["erratum"];
                for key in ["printed", "corrected", "counter_example", "residual"] {
                    assert!(e[key].is_array(), "{}: {key}", r.id);
                }
                assert!(e["correction"].is_string());
                let first = &e["printed"][0];
                assert!(first["text"].as_str().unwrap().contains(" = "));
                assert!(first["latex"].as_str().unwrap().contains("\\"));
            }
            _ => assert!(j.get("erratum").is_none(), "{}", r.id),
        }
    }
}

#[test]
fn latex_document_lines() {
    let rows: Vec<Checked> = ["spaeth.eq10", "chiang.ph_offsets"]
        .iter()
        .map(|id| check(id))
        .collect();
    let doc = latex::document(&rows);
    assert!(doc.contains("% spaeth.eq10 (fails): printed\n"), "{doc}");
    assert!(doc.contains("% spaeth.eq10 (fails): corrected\n"), "{doc}");
    assert!(
        doc.contains("% chiang.ph_offsets (fails): counter-example\n"),
        "{doc}"
    );
    // The corrected (10) has the - R^2 the printed one lacks.
    let corrected = doc
        .lines()
        .skip_while(|l| *l != "% spaeth.eq10 (fails): corrected")
        .nth(1)
        .unwrap();
    assert!(
        corrected.starts_with("B = ") && corrected.ends_with(" - R^{2}"),
        "{corrected}"
    );
    assert!(
        doc.contains(
            "r_{0}\\left(3\\right) = \\left(-\\frac{60}{101}, \\frac{297}{101}, 3\\right)"
        ),
        "{doc}"
    );
    for l in doc.lines() {
        assert!(!l.contains('$'), "{l}");
        // Braces balance on every line (each line is a formula on its own).
        if !l.starts_with('%') {
            let open = l.matches('{').count() - l.matches("\\{").count();
            let close = l.matches('}').count() - l.matches("\\}").count();
            assert_eq!(open, close, "{l}");
        }
    }
}

#[test]
fn ph_radius_erratum_names_the_false_cusp_counts_not_the_radius() {
    // 12.6 is a correct rounding of the smallest radius 101/8; what is false are the cusp
    // counts at r = 63/5 (none, not one) and just above it (none, not two). The erratum used to
    // present 12.6 as a misprinted radius with residual 1/40.
    let row = check("chiang.ph_radius");
    let e = row.outcome.as_ref().unwrap().erratum.as_ref().unwrap();
    let text = |eqs: &[claims::Equation]| eqs.iter().map(|q| q.text()).collect::<Vec<_>>();
    let (printed, corrected) = (text(&e.printed), text(&e.corrected));
    let (counter, residual) = (text(&e.counter_example), text(&e.residual));
    assert!(
        printed
            .iter()
            .chain(&corrected)
            .all(|t| !t.contains("rho_min")),
        "{printed:?} {corrected:?}"
    );
    assert_eq!(printed.len(), 2, "{printed:?}");
    assert!(
        printed[0].starts_with("n_cusps(")
            && printed[0].contains("63/5")
            && printed[0].ends_with(" = 1"),
        "{printed:?}"
    );
    assert!(
        printed[1].contains("1009/80") && printed[1].ends_with(" = 2"),
        "{printed:?}"
    );
    assert!(
        counter[0].contains("63/5") && counter[0].ends_with(" = 0"),
        "{counter:?}"
    );
    assert!(
        counter[1].contains("1009/80") && counter[1].ends_with(" = 0"),
        "{counter:?}"
    );
    assert!(
        residual[0].ends_with(" = -1") && residual[1].ends_with(" = -2"),
        "{residual:?}"
    );
    assert!(
        corrected[0].contains("101/8") && corrected[0].ends_with(" = 1"),
        "{corrected:?}"
    );
}
