//! Inputs that matter, end to end through the binary: `regress --near` (samples near a
//! degenerate set), `--predicate` (sign errors), several outputs (`--formula` repeated, a
//! vector), and a saved run explained by `report --regress`.

use crate::common;

use serde_json::Value;
use std::process::Output;

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .output()
        .expect("the binary runs")
}

fn json_of(o: &Output) -> Value {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON on stdout")
}

/// A fresh directory of this test process.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("exactcheck-inputs-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir
}

const ORIENT: &str = "(bx-ax)*(cy-ay) - (by-ay)*(cx-ax)";
const VARS: &str = "ax,ay,bx,by,cx,cy";
const BOX: &str =
    "ax in [0, 1], ay in [0, 1], bx in [0, 1], by in [0, 1], cx in [0, 1], cy in [0, 1]";

fn orient(extra: &[&str]) -> Value {
    let mut args = vec![
        "regress",
        "--formula",
        ORIENT,
        "--vars",
        VARS,
        "--predicate",
        "--samples",
        "2000",
        "--worst",
        "2",
        "--json",
    ];
    args.extend_from_slice(extra);
    let doc = json_of(&exactcheck(&args));
    doc["entries"][0].clone()
}

#[test]
fn orient2d_near_a_line_has_sign_errors() {
    let e = orient(&[
        "--domain",
        BOX,
        "--near",
        "(bx-ax)*(cy-ay) = (by-ay)*(cx-ax)",
    ]);
    let p = &e["predicate"];
    assert_eq!(p["compared"], 2000, "{p}");
    let errors = p["wrong_sign"].as_u64().unwrap()
        + p["float_zero_exact_nonzero"].as_u64().unwrap()
        + p["float_nonzero_exact_zero"].as_u64().unwrap();
    assert!(errors > 20, "{p}");
    assert!(p["wrong_sign"].as_u64().unwrap() > 0, "{p}");
    // Every example is a real sign error, its inputs exactly printed.
    let w = p["worst"].as_array().unwrap();
    assert_eq!(w.len(), 2);
    assert_eq!(w[0]["verdict"], "WrongSign", "{p}");
    assert_eq!(w[0]["inputs_exact"].as_array().unwrap().len(), 6);
    // The report says how the samples were drawn.
    let gen = e["generator"].as_str().unwrap();
    assert!(
        gen.starts_with("near (bx-ax)*(cy-ay) = (by-ay)*(cx-ax): points of"),
        "{gen}"
    );
    assert!(e["max_ulps"].as_f64().unwrap() > 1e6, "{e}");
}

#[test]
fn orient2d_on_well_separated_points_has_none() {
    // c far above the line through a and b: the value is at least 3.
    let e = orient(&[
        "--domain",
        "ax in [0, 1], ay in [0, 1], bx in [2, 3], by in [0, 1], cx in [0, 1], cy in [5, 6]",
    ]);
    let p = &e["predicate"];
    assert_eq!(p["compared"], 2000, "{p}");
    for k in [
        "wrong_sign",
        "float_zero_exact_nonzero",
        "float_nonzero_exact_zero",
        "no_float_sign",
        "exact_zero",
    ] {
        assert_eq!(p[k], 0, "{k}: {p}");
    }
    assert!(p["worst"].as_array().unwrap().is_empty());
}

#[test]
fn uniform_inputs_rarely_reach_the_line_and_near_ones_do() {
    let uniform = orient(&["--domain", BOX]);
    let near = orient(&[
        "--domain",
        BOX,
        "--near",
        "(bx-ax)*(cy-ay) = (by-ay)*(cx-ax)",
    ]);
    let errors = |e: &Value| {
        let p = &e["predicate"];
        [
            "wrong_sign",
            "float_zero_exact_nonzero",
            "float_nonzero_exact_zero",
        ]
        .iter()
        .map(|k| p[k].as_u64().unwrap())
        .sum::<u64>()
    };
    // 2,000 uniform samples: no sign error; 2,000 near the line: dozens.
    assert_eq!(errors(&uniform), 0, "{uniform}");
    assert!(errors(&near) >= 20, "{near}");
}

#[test]
fn the_predicate_text_names_counts_and_examples() {
    let o = exactcheck(&[
        "regress",
        "--formula",
        ORIENT,
        "--vars",
        VARS,
        "--domain",
        BOX,
        "--near",
        "(bx-ax)*(cy-ay) = (by-ay)*(cx-ax)",
        "--predicate",
        "--samples",
        "500",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    for needle in [
        "predicate: the float sign against the exact sign on 500 compared samples near (bx-ax)*(cy-ay) = (by-ay)*(cx-ax)",
        "wrong sign (opposite signs):",
        "zero vs nonzero:",
        "worst examples (inputs exactly",
        "exactly [",
    ] {
        assert!(text.contains(needle), "{needle:?} missing:\n{text}");
    }
}

#[test]
fn incircle_near_a_circle_is_sampled_and_judged() {
    // incircle(a, b, c, d) with a, b, c fixed on the unit circle: the sign says whether d lies
    // inside their circle.
    let incircle = "det([[ax - dx, ay - dy, (ax - dx)^2 + (ay - dy)^2], [bx - dx, by - dy, (bx - dx)^2 + (by - dy)^2], [cx - dx, cy - dy, (cx - dx)^2 + (cy - dy)^2]])";
    let doc = json_of(&exactcheck(&[
        "regress",
        "--formula",
        incircle,
        "--vars",
        "ax,ay,bx,by,cx,cy,dx,dy",
        "--domain",
        "ax in [-1, 1], ay in [-1, 1], bx in [-1, 1], by in [-1, 1], cx in [-1, 1], cy in [-1, 1], dx in [-1, 1], dy in [-1, 1]",
        "--near",
        &format!("{incircle} = 0"),
        "--predicate",
        "--samples",
        "500",
        "--json",
    ]));
    let p = &doc["entries"][0]["predicate"];
    assert_eq!(p["compared"], 500, "{p}");
    let errors = p["wrong_sign"].as_u64().unwrap()
        + p["float_zero_exact_nonzero"].as_u64().unwrap()
        + p["float_nonzero_exact_zero"].as_u64().unwrap();
    assert!(errors > 0, "{p}");
}

#[test]
fn several_outputs_report_each_and_the_worst() {
    let run = |formulas: &[&str]| {
        let mut args = vec!["regress"];
        for f in formulas {
            args.extend(["--formula", f]);
        }
        args.extend([
            "--domain",
            "x in [1, 1e15], y in [1, 2]",
            "--samples",
            "500",
            "--json",
        ]);
        json_of(&exactcheck(&args))["entries"][0].clone()
    };
    let two = run(&["sqrt(x + 1) - sqrt(x)", "x*y"]);
    let per = two["max_ulps_per_output"].as_array().unwrap();
    assert_eq!(per.len(), 2, "{two}");
    assert!(
        per[0].as_f64().unwrap() > 1e6 && per[1].as_f64().unwrap() <= 0.5,
        "{two}"
    );
    assert_eq!(two["max_ulps"], per[0]);
    assert_eq!(two["name"], "sqrt(x + 1) - sqrt(x); x*y");
    // The same as one vector formula.
    let vector = run(&["vec(sqrt(x + 1) - sqrt(x), x*y)"]);
    assert_eq!(vector["max_ulps_per_output"], two["max_ulps_per_output"]);
    assert_eq!(vector["median_ulps"], two["median_ulps"]);
    // The text says which output loses what.
    let o = exactcheck(&[
        "regress",
        "--formula",
        "vec(sqrt(x + 1) - sqrt(x), x*y)",
        "--domain",
        "x in [1, 1e15], y in [1, 2]",
        "--samples",
        "300",
        "--quiet",
    ]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("max ulps per output: [1.106e15, 0.499] (a sample's error is the worst over its 2 outputs)"),
        "{text}"
    );
}

#[test]
fn an_fpcore_array_anywhere_is_several_outputs() {
    let dir = scratch("array");
    let path = dir.join("arr.fpcore");
    std::fs::write(
        &path,
        "(FPCore (x y) :name \"arr\" :pre (and (<= 1 x 2) (<= 1 y 2)) (let ([s (+ x y)]) (array s (* s y))))\n",
    )
    .unwrap();
    let doc = json_of(&exactcheck(&[
        "regress",
        "--fpcore",
        path.to_str().unwrap(),
        "--samples",
        "200",
        "--json",
    ]));
    let e = &doc["entries"][0];
    assert_eq!(
        e["max_ulps_per_output"].as_array().map(Vec::len),
        Some(2),
        "{e}"
    );
}

#[test]
fn a_saved_run_is_explained_in_the_report() {
    let dir = scratch("saved");
    let run = dir.join("run.json");
    let o = exactcheck(&[
        "regress",
        "--formula",
        "sqrt(x + 1) - sqrt(x)",
        "--domain",
        "x in [1, 1e15]",
        "--samples",
        "300",
        "--worst",
        "1",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::write(&run, &o.stdout).unwrap();
    let out = dir.join("page");
    let claims = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/mypaper.toml");
    let o = exactcheck(&[
        "report",
        claims,
        "--regress",
        run.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = std::fs::read_to_string(out.join("index.html")).unwrap();
    for needle in [
        "the worst samples explained",
        "sqrt(x + 1) - sqrt(x)",
        "subtraction",
        "conditioning",
    ] {
        assert!(page.contains(needle), "{needle:?} missing from the page");
    }
    // A file that is not a saved run: one line, exit 2.
    let o = exactcheck(&[
        "report",
        claims,
        "--regress",
        claims,
        "-o",
        dir.join("other").to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
}
