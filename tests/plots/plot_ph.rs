//! End-to-end tests of `exactcheck plot ph` and `exactcheck plot FILE.json` for a `ph_offset`
//! problem: the SVG is written and well-formed, holds the PH curve, its control polygon, one
//! offset per distance and exactly as many cusp markers as `offset_cusps` counts, and the
//! committed `docs/ph_offsets.svg` is current.

use crate::plot_support;
use exactcheck::claims::chiang_ph::example_curve;
use exactcheck::plot::style::{hex, CUSP, GREEN, INK, OFFSETS};
use exactcheck_exact::Rational;
use plot_support::{check_svg, elements, exactcheck, find, polylines, TempDir};

fn exact_cusp_count(radii: &[&str]) -> usize {
    let c = example_curve();
    radii
        .iter()
        .map(|r| {
            c.offset_cusps(&r.parse::<Rational>().unwrap())
                .unwrap()
                .len()
        })
        .sum()
}

#[test]
fn ph_figure_is_written_and_well_formed() {
    let dir = TempDir::new("ph");
    let file = dir.path("ph.svg");
    let path = file.to_str().expect("utf-8 temp path");
    let o = exactcheck(&["plot", "ph", "-o", path]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    assert!(
        stdout.starts_with(&format!("wrote {path}: Chiang's PH curve")),
        "{stdout}"
    );
    let svg = std::fs::read_to_string(&file).expect("the SVG was written");
    check_svg(&svg);
    // The curve (193 exact samples), the control polygon (4 points), three offsets.
    // (Each list ends with the legend's 2-point line.)
    assert_eq!(polylines(&svg, &hex(INK), 3), vec![193, 2]);
    assert_eq!(polylines(&svg, &hex(GREEN), 1), vec![4, 2]);
    for c in &OFFSETS[..3] {
        assert_eq!(polylines(&svg, &hex(*c), 2), vec![193, 2], "{}", hex(*c));
    }
    assert!(polylines(&svg, &hex(OFFSETS[3]), 2).is_empty());
    for label in [
        "r = 3",
        "r = 12.6",
        "r = 15",
        "offset r = 63/5",
        "p3 = (-20/3, 33)",
    ] {
        assert!(svg.contains(label), "missing {label}");
    }
    // One marker per cusp, as many as the exact count (2: both at r = 15).
    let cusps = exact_cusp_count(&["3", "63/5", "15"]);
    assert_eq!(cusps, 2);
    assert_eq!(
        find(&elements(&svg), "circle", &[("fill", hex(CUSP).as_str())]).len(),
        cusps + 1,
        "markers and the legend dot"
    );
    assert_eq!(svg.matches("cusp of r = 15").count(), 2);
    assert!(svg.contains("2 cusp(s) in all"));
}

#[test]
fn committed_figure_is_current() {
    let o = exactcheck(&["plot", "ph", "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).expect("utf-8 SVG");
    check_svg(&svg);
    // Regenerate with `exactcheck plot ph -o docs/ph_offsets.svg` or EXACTCHECK_BLESS=1.
    plot_support::golden::assert_golden("docs/ph_offsets.svg", &svg);
}

#[test]
fn a_ph_offset_problem_file_is_drawn() {
    let golden = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/solve_golden/");
    let o = exactcheck(&["plot", &format!("{golden}ph_quintic.json"), "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).expect("utf-8 SVG");
    check_svg(&svg);
    assert_eq!(polylines(&svg, &hex(GREEN), 1)[0], 6, "a quintic");
    assert!(
        polylines(&svg, &hex(OFFSETS[1]), 2).len() > 1,
        "two distances"
    );
    // A singular base: drawn, its offsets broken at the pole, no cusps computed.
    let o = exactcheck(&["plot", &format!("{golden}ph_singular.json"), "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).expect("utf-8 SVG");
    check_svg(&svg);
    assert!(svg.contains("singular base"));
    // Refusals: one line, exit 2.
    let dir = TempDir::new("ph-bad");
    for (text, needle) in [
        (
            r#"{"kind":"ph_offset","u":[0],"v":[0],"start":[0,0],"r":1}"#,
            "zero",
        ),
        (
            r#"{"kind":"ph_offset","u":["sqrt(2)"],"v":[1],"start":[0,0],"r":1}"#,
            "rational numbers only",
        ),
    ] {
        let f = dir.path("bad.json");
        std::fs::write(&f, text).unwrap();
        let o = exactcheck(&["plot", f.to_str().unwrap(), "-o", "-"]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle) && err.contains("bad.json"), "{err}");
    }
    let o = exactcheck(&["plot", "ph", "--example", "1", "-o", "-"]);
    assert_eq!(o.status.code(), Some(2));
}
