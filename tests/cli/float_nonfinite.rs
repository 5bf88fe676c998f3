//! Float mode on extreme but finite input("NaN / infinity / subnormal inputs give a
//! clear error or a flagged result, never a silent NaN"): numbers near f64's largest (1e300),
//! numbers whose squares overflow (1e154), subnormals (1e-320), for every kind that has a float
//! mode, in `--float` and `--both`. Each run answers with valid JSON holding only finite
//! numbers (no `null` in place of a number, no `NaN`/`Infinity` token) and exit status 0, or
//! refuses with exit status 2 and one line; never a panic.

use crate::common;

use common::{has_null_number, solve_stdin};
use serde_json::Value;

/// Every problem of every float kind with the number `x` in its most sensitive places.
fn problems(x: &str) -> Vec<String> {
    vec![
        format!(
            r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[{x},0],"radius":{x},"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":[{x},{x},0],"radius":{x}}},"samples":3}}"#
        ),
        format!(
            r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":1,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":[{x},0,0],"radius":2}},"samples":3}}"#
        ),
        format!(
            r#"{{"kind":"plane_plane","planes":[{{"normal":[{x},1,0],"point":[0,{x},0]}},{{"normal":[0,{x},1],"point":[{x},0,0]}}]}}"#
        ),
        format!(
            r#"{{"kind":"ruled_plane","base":[[0,0,{x}],[1,{x},0]],"directions":[[{x},0,1],[0,1,{x}]],"plane":[0,0,1,{x}]}}"#
        ),
        format!(
            r#"{{"kind":"ruled_line","base":[[0,0,0],[{x},1,0]],"directions":[[0,0,1],[1,0,{x}]],"line":{{"point":[{x},0,0],"direction":[1,{x},0]}}}}"#
        ),
        format!(r#"{{"kind":"conic","normal":[{x},1,1],"point":[1,{x},1]}}"#),
        format!(r#"{{"kind":"conic","plane":[1,1,{x},{x}]}}"#),
        format!(r#"{{"kind":"ph_offset","u":[{x},1],"v":[1,{x}],"start":[0,{x}],"r":[{x},1]}}"#),
    ]
}

#[test]
fn extreme_finite_input_answers_with_finite_numbers_or_one_line() {
    let mut answered = 0;
    let mut refused = 0;
    for x in [
        "1e300",
        "-1e300",
        "1e154",
        "1e-320",
        "\"1/10^320\"",
        "\"10^154\"",
    ] {
        for problem in problems(x) {
            for mode in ["--float", "--both"] {
                let o = solve_stdin(problem.as_bytes(), &[mode]);
                let out = String::from_utf8_lossy(&o.stdout);
                let err = String::from_utf8_lossy(&o.stderr);
                assert!(!err.contains("panicked"), "{mode} {problem}: {err}");
                match o.status.code() {
                    Some(0) => {
                        assert!(
                            !out.contains("NaN") && !out.contains("Infinity"),
                            "{mode} {problem}: {out}"
                        );
                        let v: Value = serde_json::from_str(&out)
                            .unwrap_or_else(|e| panic!("{mode} {problem}: invalid JSON {e}"));
                        assert!(!has_null_number(&v), "{mode} {problem}: {out}");
                        answered += 1;
                    }
                    Some(2) => {
                        assert_eq!(err.lines().count(), 1, "{mode} {problem}: {err}");
                        assert!(out.is_empty(), "{mode} {problem}");
                        refused += 1;
                    }
                    other => panic!("{mode} {problem}: exit {other:?}: {err}"),
                }
            }
        }
    }
    // Both outcomes occur: the extreme inputs are not all refused wholesale.
    assert!(
        answered > 0 && refused > 0,
        "{answered} answered, {refused} refused"
    );
}

#[test]
fn a_non_finite_float_result_is_refused_naming_the_field() {
    // Finite input whose f64 polynomial overflows: the answer used to carry a silent `null`
    // for it (serde_json writes NaN and inf as null) with exit status 0.
    let problem = r#"{"kind":"ruled_line","base":[[0,0,0],["10^200",1,0]],"directions":[[0,0,1],[1,0,"10^200"]],"line":{"point":["10^200",0,0],"direction":[1,"10^200",0]}}"#;
    for (mode, path) in [("--float", ""), ("--both", "float.")] {
        let o = solve_stdin(problem.as_bytes(), &[mode]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{mode}: {err}");
        assert_eq!(
            err,
            format!("exactcheck: error: {path}polynomial[0]: the f64 computation overflowed (inf); use exact mode\n"),
            "{mode}"
        );
        assert!(o.stdout.is_empty(), "{mode}");
    }
}

#[test]
fn an_exact_answer_beyond_f64s_range_is_kept_with_its_approximations_listed() {
    // Exact input 10^400: the exact answer is the answer; its f64 twins are infinite. It used to
    // be refused whole ("approx.point[0]: ... not finite"); now they are `null` and listed.
    let problem = r#"{"kind":"plane_plane","planes":[{"normal":[1,1,0],"point":[1,0,0]},{"normal":[0,"sqrt(2)","sqrt(2)"],"point":[0,0,"10^400"]}]}"#;
    for mode in ["--exact", "--both"] {
        let o = solve_stdin(problem.as_bytes(), &[mode]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{mode}: {err}");
        let v: Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
        if mode == "--both" {
            // The float part cannot read 10^400: its failure, naming the field, is a note
            // beside the exact answer.
            let e = v["float"]["error"].as_str().expect("the float failure");
            assert!(e.contains("planes[1].point[2]"), "{e}");
        }
        assert_eq!(
            v["approx_out_of_range"],
            serde_json::json!(["approx.point[0]", "approx.point[1]", "approx.point[2]"])
        );
        assert_eq!(v["approx"]["point"], serde_json::json!([null, null, null]));
        // The exact point is there, with 400-digit coordinates, and the finite twins too.
        let x = v["point"][0].as_str().expect("an exact coordinate");
        assert!(x.len() > 400 && x.starts_with("-9999"), "{x}");
        assert!(v["approx"]["direction"][0].is_number());
        assert!(!has_null_number(&v));
    }
    // Without the list the same nulls would be findings of the test helper.
    let o = solve_stdin(problem.as_bytes(), &["--exact"]);
    let mut v: Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    v["approx"]["point"][1] = Value::from(1.5);
    assert!(has_null_number(&v), "a listed path that is not null");
    v.as_object_mut()
        .expect("an object")
        .remove("approx_out_of_range");
    assert!(has_null_number(&v));
}
