//! End-to-end tests of `exactcheck plot chiang --example 4`: the SVG is produced, well-formed,
//! holds the surface, the plane, the exact section curve and the control polygon, matches the
//! committed `docs/chiang_example4.svg`, and other example numbers are one-line errors (exit 2).

use crate::plot_support;
use exactcheck::plot::style::{hex, GREEN, RED, SKY, WIRE, WIRE_BACK};
use plot_support::{check_svg, elements, exactcheck, find, polylines, TempDir};

#[test]
fn example_4_figure_is_written_and_well_formed() {
    let dir = TempDir::new("chiang");
    let file = dir.path("example4.svg");
    let path = file.to_str().expect("utf-8 temp path");
    let o = exactcheck(&["plot", "chiang", "--example", "4", "-o", path]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    assert!(
        stdout.starts_with(&format!("wrote {path}: Chiang Example 4")),
        "{stdout}"
    );
    let svg = std::fs::read_to_string(&file).expect("the SVG was written");
    check_svg(&svg);
    // The plane, the surface on both sides of it, the exact curve (97 samples), the control
    // polygon (4 points) and its 4 labelled points with the weights.
    let all = elements(&svg);
    assert_eq!(
        find(&all, "polygon", &[("fill", hex(SKY).as_str())]).len(),
        1
    );
    // 9 inner rulings and 7 inner s-curves reach above the plane (and the legend's line).
    assert!(polylines(&svg, &hex(WIRE), 1).len() > 9);
    // Below the plane: dashed, many short pieces.
    assert!(polylines(&svg, &hex(WIRE_BACK), 1).len() >= 9 * 3);
    // The section: one polyline of the 97 exact samples (the legend's line has 2 points).
    assert_eq!(polylines(&svg, &hex(RED), 3), vec![97, 2]);
    assert_eq!(polylines(&svg, &hex(GREEN), 1), vec![4, 2]);
    assert_eq!(
        find(&all, "circle", &[("fill", hex(GREEN).as_str())]).len(),
        4
    );
    for label in [
        "r0 (w0 = 1.414)",
        "r3 (w3 = 2.449)",
        "w0 = sqrt(2)",
        "w3 = sqrt(6)",
    ] {
        assert!(svg.contains(label), "missing {label}");
    }
    // The exact weights w1, w2 as radicals, and r0 = (-1/sqrt 2, 1/sqrt 2, 0) in decimals.
    assert!(svg.contains("w1 = 2*sqrt(2)/3 + sqrt(6)/3"));
    assert!(svg.contains("w2 = sqrt(2)/3 + 2*sqrt(6)/3"));
    assert!(svg.contains("r0 = (−0.7071, 0.7071, 0)"));
}

#[test]
fn committed_figure_is_current() {
    let o = exactcheck(&["plot", "chiang", "--example", "4", "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).expect("utf-8 SVG");
    check_svg(&svg);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.starts_with("wrote standard output: Chiang Example 4"),
        "{stderr}"
    );
    // Regenerate with `exactcheck plot chiang --example 4 -o docs/chiang_example4.svg` or EXACTCHECK_BLESS=1.
    plot_support::golden::assert_golden("docs/chiang_example4.svg", &svg);
}

#[test]
fn other_examples_are_one_line_errors() {
    for (args, needle) in [
        (
            &["plot", "chiang", "--example", "3", "-o", "-"][..],
            "unknown example 3",
        ),
        (
            &["plot", "chiang", "--example", "0", "-o", "-"][..],
            "unknown example 0",
        ),
        (
            &["plot", "chiang", "-o", "-"][..],
            "plot chiang needs --example 4",
        ),
    ] {
        let o = exactcheck(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(o.stdout.is_empty(), "{args:?}");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(
            stderr.contains(needle) && stderr.contains("--example 4"),
            "{stderr}"
        );
    }
}
