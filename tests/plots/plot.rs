//! End-to-end tests of `exactcheck plot`: the SVG figures of Spaeth's examples and of problem
//! files, and the one-line errors (exit status 2).

use std::path::Path;

use crate::plot_support;
use exactcheck::plot::style::{hex, BLUE, INK, ORANGE, PURPLE};
use plot_support::{check_svg, elements, exactcheck, find, polylines, TempDir};

fn plot(args: &[&str], out: &Path) -> String {
    let mut all: Vec<&str> = vec!["plot"];
    all.extend_from_slice(args);
    let out_str = out.to_str().expect("utf-8 temp path");
    all.extend_from_slice(&["-o", out_str]);
    let o = exactcheck(&all);
    assert!(
        o.status.success(),
        "{all:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(stdout.lines().count(), 1, "one line: {stdout}");
    assert!(stdout.starts_with("wrote "), "{stdout}");
    std::fs::read_to_string(out).expect("the SVG was written")
}

/// The polylines of the intersection curve (branch colours, more than the 2 points of a legend
/// line or a dash).
fn curve_polylines(svg: &str) -> usize {
    [BLUE, ORANGE]
        .iter()
        .flat_map(|c| {
            elements(svg)
                .into_iter()
                .filter(|e| e.name == "polyline" && e.attr("stroke") == Some(&hex(*c)))
                .map(|e| e.points().len())
                .collect::<Vec<_>>()
        })
        .filter(|&n| n > 2)
        .count()
}

/// The circles filled with `colour` (markers and legend dots).
fn filled_circles(svg: &str, colour: &str) -> usize {
    find(&elements(svg), "circle", &[("fill", colour)]).len()
}

/// The circles with a `colour` rim and no fill (hollow markers and rings).
fn rings(svg: &str, colour: &str) -> usize {
    find(
        &elements(svg),
        "circle",
        &[("fill", "none"), ("stroke", colour)],
    )
    .len()
}

#[test]
fn spaeth_examples_in_both_views() {
    let dir = TempDir::new("examples");
    for n in ["1", "2", "3"] {
        for view in ["tu", "3d"] {
            let out = dir.path(&format!("example{n}_{view}.svg"));
            let svg = plot(&["spaeth", "--example", n, "--view", view], &out);
            check_svg(&svg);
            assert!(svg.contains(&format!("Spaeth Example {n}")));
            let curves = curve_polylines(&svg);
            if n == "3" {
                assert_eq!(curves, 0, "example 3 has no curve ({view})");
            } else {
                assert!(
                    curves >= 2,
                    "example {n} ({view}): {curves} curve polylines"
                );
            }
            assert!(svg.contains("Legend"));
        }
    }
}

#[test]
fn tu_diagram_details() {
    let dir = TempDir::new("tu");
    // Example 1: two branches over the whole circle, every 10-degree sample real (37 with 360).
    let ink = hex(INK);
    let e1 = plot(&["spaeth", "--example", "1"], &dir.path("e1.svg"));
    assert_eq!(curve_polylines(&e1), 2);
    assert_eq!(filled_circles(&e1, &ink), 2 * 37 + 1); // + the legend's dot
    assert_eq!(rings(&e1, &ink), 0);
    assert!(e1.contains("real for every t"));
    assert!(e1.contains("Fig. 2"));
    // Example 2: one real t-interval, its two exact ends marked, the rational rotations stated.
    let e2 = plot(&["spaeth", "--example", "2"], &dir.path("e2.svg"));
    assert!(e2.contains("Fig. 3"));
    assert!(e2.contains("rational rotations"));
    // The exact ends: vertical ticks (2 points, same x) of the ink colour, two and the legend's.
    let ends: Vec<Vec<(f64, f64)>> = find(
        &elements(&e2),
        "polyline",
        &[("stroke", ink.as_str()), ("stroke-width", "2")],
    )
    .iter()
    .map(|e| e.points())
    .collect();
    assert_eq!(ends.len(), 2 + 1, "{ends:?}");
    assert!(ends.iter().all(|p| p.len() == 2 && p[0].0 == p[1].0));
    assert!(rings(&e2, &ink) > 1);
    // Each end is drawn at its exact angle: at the x of its label (24.64°, 151.81°), which is
    // written 4 pixels right of the guide line.
    for label in ["24.64°", "151.81°"] {
        let all = elements(&e2);
        let text = all
            .iter()
            .find(|e| e.name == "text" && e.text == label)
            .unwrap_or_else(|| panic!("no label {label}"));
        let x = text.num("x") - 4.0;
        assert!(
            ends.iter().any(|p| (p[0].0 - x).abs() <= 1.0),
            "no end at {label} (x = {x}): {ends:?}"
        );
    }
    // Example 3: only hollow samples.
    let e3 = plot(&["spaeth", "--example", "3"], &dir.path("e3.svg"));
    assert_eq!(filled_circles(&e3, &ink), 0);
    assert_eq!(rings(&e3, &ink), 37 + 1);
    assert_eq!(polylines(&e3, &hex(BLUE), 2), Vec::<usize>::new());
}

#[test]
fn problem_files() {
    let dir = TempDir::new("files");
    let problem = dir.path("touch & go.json");
    // Touching from outside at t = 0 (Example-1 cylinder, sphere centre (8,0,3), R = 3).
    std::fs::write(
        &problem,
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":[8,0,3],"radius":3}}"#,
    )
    .unwrap();
    let p = problem.to_str().unwrap();
    let svg = plot(&[p], &dir.path("touch.svg"));
    check_svg(&svg);
    assert!(svg.contains("touch &amp; go.json"), "the name is escaped");
    assert!(svg.contains("touching at t = 0°"));
    // The touching point: one diamond (and the legend's), on the guide at t = 0 (the left edge
    // of the plot, where the 0° tick label is centred).
    let all = elements(&svg);
    let diamonds = find(&all, "polygon", &[("fill", hex(PURPLE).as_str())]);
    assert_eq!(diamonds.len(), 1 + 1);
    let zero = all
        .iter()
        .find(|e| e.name == "text" && e.text == "0°")
        .expect("the 0° tick label");
    let xs: Vec<f64> = diamonds[0].points().iter().map(|p| p.0).collect();
    let centre = (xs.iter().copied().fold(f64::MAX, f64::min)
        + xs.iter().copied().fold(f64::MIN, f64::max))
        / 2.0;
    assert!(
        (centre - zero.num("x")).abs() <= 1.0,
        "{centre} vs {}",
        zero.num("x")
    );
    check_svg(&plot(&[p, "--view", "3d"], &dir.path("touch3d.svg")));
    // Radians and float literals: drawn in f64, the exact line says why there is none or how
    // the radians were taken.
    let radians = dir.path("radians.json");
    std::fs::write(
        &radians,
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"radians":1},"gamma":{"radians":-1}},"sphere":{"center":[1,2,4],"radius":5}}"#,
    )
    .unwrap();
    let svg = plot(&[radians.to_str().unwrap()], &dir.path("radians.svg"));
    assert!(svg.contains("radians taken as rational rotations"));
    assert!(curve_polylines(&svg) >= 2);
    let floats = dir.path("floats.json");
    std::fs::write(
        &floats,
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0.0,0.0],"radius":5.0,"beta":{"radians":1.0},"gamma":{"radians":-1.0}},"sphere":{"center":[1.0,2.0,4.0],"radius":5.0}}"#,
    )
    .unwrap();
    let svg = plot(&[floats.to_str().unwrap()], &dir.path("floats.svg"));
    check_svg(&svg);
    assert!(svg.contains("no exact analysis"));
    assert!(curve_polylines(&svg) >= 2);
}

fn assert_error(args: &[&str], needle: &str) {
    let o = exactcheck(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(needle), "{args:?}: {err}");
    assert!(o.stdout.is_empty(), "{args:?}");
}

#[test]
fn errors_have_status_2() {
    let dir = TempDir::new("errors");
    let out = dir.path("x.svg");
    let out = out.to_str().unwrap();
    assert_error(
        &["plot", "spaeth", "--example", "4", "-o", out],
        "unknown example 4",
    );
    assert_error(&["plot", "spaeth", "-o", out], "--example");
    assert_error(&["plot", "spaeth", "--example", "1"], "--output");
    assert_error(
        &[
            "plot",
            "spaeth",
            "--example",
            "1",
            "--view",
            "side",
            "-o",
            out,
        ],
        "side",
    );
    let missing = dir.path("missing.json");
    assert_error(
        &["plot", missing.to_str().unwrap(), "-o", out],
        "cannot read",
    );
    let other = dir.path("other.json");
    std::fs::write(
        &other,
        r#"{"kind":"sphere_interpolation","points":[],"params":[]}"#,
    )
    .unwrap();
    // The message names every kind plot draws (it said "cylinder_sphere only" after conic and
    // ph_offset files became drawable).
    assert_error(
        &["plot", other.to_str().unwrap(), "-o", out],
        r#"plot draws problem files of kind "cylinder_sphere", "conic" or "ph_offset" (found kind "sphere_interpolation")"#,
    );
    let broken = dir.path("broken.json");
    std::fs::write(&broken, "{not json").unwrap();
    assert_error(
        &["plot", broken.to_str().unwrap(), "-o", out],
        "malformed JSON",
    );
    let bad = dir.path("bad.json");
    std::fs::write(
        &bad,
        r#"{"kind":"cylinder_sphere","cylinder":{"axis_point":[0,0],"radius":5,"beta":{"cos":1,"sin":0},"gamma":{"cos":1,"sin":0}},"sphere":{"center":[1,0],"radius":7}}"#,
    )
    .unwrap();
    assert_error(&["plot", bad.to_str().unwrap(), "-o", out], "sphere.center");
    assert_error(
        &["plot", other.to_str().unwrap(), "--example", "1", "-o", out],
        "--example",
    );
    let unwritable = dir.path("no/such/dir/x.svg");
    assert_error(
        &[
            "plot",
            "spaeth",
            "--example",
            "1",
            "-o",
            unwritable.to_str().unwrap(),
        ],
        "cannot write",
    );
    assert!(!Path::new(out).exists(), "nothing written on errors");
}

#[test]
fn subnormal_sphere_radius_draws_without_overflow() {
    // Old: "capacity overflow" in the tick computation (the u-range is subnormal in f64).
    let dir = TempDir::new("tiny");
    for (i, centre) in ["[8,0,3]", "[0,0,0]"].iter().enumerate() {
        let problem = dir.path(&format!("tiny{i}.json"));
        std::fs::write(
            &problem,
            format!(
                r#"{{"kind":"cylinder_sphere","cylinder":{{"axis_point":[0,0],"radius":5,"beta":{{"cos":1,"sin":0}},"gamma":{{"cos":1,"sin":0}}}},"sphere":{{"center":{centre},"radius":"1/10^323"}}}}"#
            ),
        )
        .unwrap();
        let p = problem.to_str().unwrap();
        check_svg(&plot(&[p], &dir.path(&format!("tiny{i}.svg"))));
        check_svg(&plot(
            &[p, "--view", "3d"],
            &dir.path(&format!("tiny{i}3d.svg")),
        ));
    }
}

/// A copy of the golden problem of Spaeth's example 1 in `dir`.
fn problem_copy(dir: &TempDir, name: &str) -> std::path::PathBuf {
    let golden = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/solve_golden/cs_example1.json"
    );
    let p = dir.path(name);
    std::fs::copy(golden, &p).expect("copy the problem");
    p
}

/// The files of `dir` whose names end in `.tmp` (what an interrupted write would leave).
fn temp_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .expect("list the directory")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect()
}

#[test]
fn the_problem_file_is_never_the_output() {
    // Old: `plot p.json -o p.json` replaced the problem with its SVG figure (exit 0).
    let dir = TempDir::new("self");
    let p = problem_copy(&dir, "p.json");
    let before = std::fs::read(&p).unwrap();
    let p_str = p.to_str().unwrap();
    let dotted = format!("{}/./p.json", dir.path("").display());
    std::fs::hard_link(&p, dir.path("hard.json")).unwrap();
    let hard = dir.path("hard.json");
    for out in [p_str, dotted.as_str(), hard.to_str().unwrap()] {
        let o = exactcheck(&["plot", p_str, "-o", out]);
        assert_eq!(o.status.code(), Some(2), "-o {out}: {o:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.contains("is the input") && err.contains("would replace the input"),
            "{err}"
        );
        assert!(o.stdout.is_empty());
        assert_eq!(
            std::fs::read(&p).unwrap(),
            before,
            "the problem file is intact"
        );
    }
    // A different file next to it is written as before.
    check_svg(&plot(&[p_str], &dir.path("p.svg")));
    assert_eq!(std::fs::read(&p).unwrap(), before);
}

#[cfg(unix)]
#[test]
fn a_symlink_at_the_output_is_replaced_not_followed() {
    // Old: the SVG was written through the link into the file it points to.
    let dir = TempDir::new("link");
    let p = problem_copy(&dir, "p.json");
    let target = dir.path("elsewhere.txt");
    std::fs::write(&target, "keep me").unwrap();
    let link = dir.path("fig.svg");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    check_svg(&plot(&[p.to_str().unwrap()], &link));
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep me");
    let meta = std::fs::symlink_metadata(&link).unwrap();
    assert!(
        meta.file_type().is_file(),
        "the link was replaced by the figure"
    );
    // A link to the problem file itself: the link is replaced, the problem stays.
    let to_problem = dir.path("to_problem.svg");
    std::os::unix::fs::symlink(&p, &to_problem).unwrap();
    let before = std::fs::read(&p).unwrap();
    check_svg(&plot(&[p.to_str().unwrap()], &to_problem));
    assert_eq!(std::fs::read(&p).unwrap(), before);
    assert!(temp_files(&dir.path("")).is_empty());
}

#[test]
fn an_output_path_that_names_no_file_is_refused_before_drawing() {
    let dir = TempDir::new("names");
    let d = dir.path("");
    let d = d.to_str().unwrap().trim_end_matches('/');
    let slash = format!("{d}/x.svg/");
    let dot = format!("{d}/.");
    for (out, needle) in [
        ("", "the output path is empty"),
        (d, "is a directory, not a file"),
        (slash.as_str(), "names a directory, not a file"),
        (dot.as_str(), "names a directory, not a file"),
    ] {
        let o = exactcheck(&["plot", "spaeth", "--example", "1", "-o", out]);
        assert_eq!(o.status.code(), Some(2), "-o {out:?}: {o:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "-o {out:?}: {err}");
    }
    assert!(!dir.path("x.svg").exists());
    let o = exactcheck(&["plot", "spaeth", "--example", "1", "-o", "/dev/null"]);
    assert!(o.status.success(), "a device is written in place: {o:?}");
}

#[test]
fn replacing_a_figure_keeps_its_permissions_and_leaves_no_temporary_file() {
    let dir = TempDir::new("replace");
    let out = dir.path("fig.svg");
    std::fs::write(&out, "old figure").unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o640)).unwrap();
    }
    check_svg(&plot(&["spaeth", "--example", "2"], &out));
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let mode = std::fs::metadata(&out).unwrap().permissions().mode();
        assert_eq!(mode & 0o777, 0o640);
    }
    assert!(temp_files(&dir.path("")).is_empty());
}

#[cfg(target_os = "linux")]
#[test]
fn a_name_in_dev_is_written_in_place() {
    // `/dev/fd/1` is this process's standard output (here a file): written through, not
    // replaced by a rename (which cannot create a file in /proc and would destroy the link).
    let dir = TempDir::new("devfd");
    let out = dir.path("out.txt");
    let o = plot_support::exe::exactcheck()
        .args(["plot", "spaeth", "--example", "1", "-o", "/dev/fd/1"])
        .stdout(std::fs::File::create(&out).unwrap())
        .output()
        .expect("run exactcheck");
    assert!(o.status.success(), "{o:?}");
    // The summary line goes to the same file at the descriptor's own offset (as with any
    // second opening of a redirected standard output); the figure is there.
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.contains("</svg>"), "{}", &text[..text.len().min(80)]);
}
