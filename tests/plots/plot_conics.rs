//! End-to-end tests of `exactcheck plot conics` and `exactcheck plot FILE.json` for a `conic`
//! problem: the SVG is written and well-formed, has one panel per section with both pieces,
//! their control polygons and finite control points, one pole marker per exact pole of the
//! `solve conic` answers, labels with the type, and matches the committed `docs/conics.svg`.

use crate::plot_support;
use exactcheck::plot::conics::FRAME;
use exactcheck::plot::style::{hex, BLUE, ORANGE, PURPLE};
use exactcheck::solve::{solve, Mode};
use plot_support::{check_svg, elements, exactcheck, Elem, TempDir};

const TABLE1: [&str; 4] = ["[0,0,1]", "[1,1,3]", "[1,1,\"sqrt(2)\"]", "[1,1,0]"];

/// The number of poles `solve conic` finds for the plane through (1,1,1) with this normal.
fn exact_poles(problem: &str) -> usize {
    let a = solve(problem, Mode::Exact).expect("an answer");
    a["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["poles"].as_array().unwrap().len())
        .sum()
}

/// The panels: each frame (a rect stroked in the frame colour) with the elements whose
/// representative point lies inside it, in document order.
fn panels(svg: &str) -> Vec<Vec<Elem>> {
    let all = elements(svg);
    let frame = hex(FRAME);
    let boxes: Vec<(f64, f64, f64, f64)> = all
        .iter()
        .filter(|e| e.name == "rect" && e.attr("stroke") == Some(frame.as_str()))
        .map(|e| (e.num("x"), e.num("y"), e.num("width"), e.num("height")))
        .collect();
    let mut out: Vec<Vec<Elem>> = boxes.iter().map(|_| Vec::new()).collect();
    for e in all {
        if e.name == "svg" || e.name == "title" {
            continue;
        }
        let (x, y) = e.at();
        if let Some(k) = boxes
            .iter()
            .position(|b| x >= b.0 && x <= b.0 + b.2 && y >= b.1 && y <= b.1 + b.3)
        {
            out[k].push(e);
        }
    }
    out
}

fn count(panel: &[Elem], name: &str, want: &[(&str, &str)]) -> usize {
    panel
        .iter()
        .filter(|e| e.name == name && e.has(want))
        .count()
}

fn table1_problem(normal: &str) -> String {
    format!(r#"{{"kind":"conic","normal":{normal},"point":[1,1,1]}}"#)
}

#[test]
fn table1_figure_is_written_with_four_panels_and_the_exact_poles() {
    let dir = TempDir::new("conics");
    let file = dir.path("conics.svg");
    let path = file.to_str().expect("utf-8 temp path");
    let o = exactcheck(&["plot", "conics", "-o", path]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    assert!(
        stdout.starts_with(&format!("wrote {path}: Chiang Table 1")),
        "{stdout}"
    );
    let svg = std::fs::read_to_string(&file).expect("the SVG was written");
    check_svg(&svg);
    let panels = panels(&svg);
    assert_eq!(panels.len(), 4);
    // Each panel: both pieces drawn (3 pixels wide), their control polygons (1 pixel), their
    // finite control points (all 3 + 3 are finite in Table 1; a point outside a panel would
    // not be drawn).
    let (blue, orange, purple) = (hex(BLUE), hex(ORANGE), hex(PURPLE));
    for (panel, ty) in panels
        .iter()
        .zip(["circle", "ellipse", "parabola", "hyperbola"])
    {
        let want = format!("{ty} (angle rule = weights)");
        assert!(
            panel.iter().any(|e| e.name == "text" && e.text == want),
            "{ty}"
        );
        for c in [&blue, &orange] {
            for w in ["3", "1"] {
                assert!(
                    count(panel, "polyline", &[("stroke", c), ("stroke-width", w)]) > 0,
                    "{ty}: {c} width {w}"
                );
            }
            assert_eq!(count(panel, "circle", &[("fill", c)]), 3, "{ty}: {c}");
        }
    }
    // One marker per exact pole: none for the circle and the ellipse, the parabola's double
    // pole t = 1/2, the hyperbola's two.
    let per_panel: Vec<usize> = TABLE1
        .iter()
        .map(|n| exact_poles(&table1_problem(n)))
        .collect();
    assert_eq!(per_panel, vec![0, 0, 1, 2]);
    for (panel, want) in panels.iter().zip(&per_panel) {
        let rings = count(panel, "circle", &[("fill", "none"), ("stroke", &purple)]);
        assert_eq!(rings, *want);
        let asymptotes = count(panel, "polyline", &[("stroke", &purple)]);
        assert_eq!(asymptotes, *want);
    }
    // The hyperbola's poles at 1 - 1/sqrt 2 and 1/sqrt 2, the parabola's at 1/2.
    for label in ["t ≈ 0.2929", "t ≈ 0.7071", "t ≈ 0.5"] {
        assert!(svg.contains(label), "missing {label}");
    }
    assert!(svg.contains("w+ = 4, 5*√2/2, 4"), "the ellipse's weights");
}

#[test]
fn committed_figure_is_current() {
    let o = exactcheck(&["plot", "conics", "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).expect("utf-8 SVG");
    check_svg(&svg);
    // Regenerate with `exactcheck plot conics -o docs/conics.svg` or EXACTCHECK_BLESS=1.
    plot_support::golden::assert_golden("docs/conics.svg", &svg);
}

#[test]
fn a_conic_problem_file_is_one_panel() {
    let dir = TempDir::new("conic-file");
    let problem = dir.path("h.json");
    let text = r#"{"kind":"conic","normal":["1/2","sqrt(3)",1],"point":["sqrt(2)",0,"-1/3"]}"#;
    std::fs::write(&problem, text).unwrap();
    let o = exactcheck(&["plot", problem.to_str().unwrap(), "-o", "-"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = String::from_utf8(o.stdout).unwrap();
    check_svg(&svg);
    let panels = panels(&svg);
    assert_eq!(panels.len(), 1);
    assert!(panels[0]
        .iter()
        .any(|e| e.name == "text" && e.text == "hyperbola (angle rule = weights)"));
    let purple = hex(PURPLE);
    assert_eq!(
        count(
            &panels[0],
            "circle",
            &[("fill", "none"), ("stroke", &purple)]
        ),
        exact_poles(text)
    );
    // A plane through the apex and a zero normal are one-line errors (exit 2).
    for (bad, needle) in [
        (r#"{"kind":"conic","plane":[1,1,0,0]}"#, "through the apex"),
        (r#"{"kind":"conic","plane":[0,0,0,1]}"#, "zero vector"),
    ] {
        std::fs::write(&problem, bad).unwrap();
        let o = exactcheck(&["plot", problem.to_str().unwrap(), "-o", "-"]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(o.stdout.is_empty());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle) && err.contains("h.json"), "{err}");
    }
    let o = exactcheck(&["plot", "conics", "--example", "1", "-o", "-"]);
    assert_eq!(o.status.code(), Some(2));
}
