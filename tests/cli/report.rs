//! `exactcheck report -o DIR`: the page of the built-in catalogue, checked as text (the browser
//! test, tests/cli/browser.rs, checks it rendered).

use crate::common;

use exactcheck::claims::Verdict;
use exactcheck::papers::catalogue;
use std::path::{Path, PathBuf};
use std::process::Output;

fn exactcheck(args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .output()
        .expect("the binary runs")
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The part of `html` from `<section id="ID"` to its `</section>`.
fn section<'a>(html: &'a str, id: &str) -> &'a str {
    let start = html
        .find(&format!("<section id=\"{id}\""))
        .unwrap_or_else(|| panic!("no section #{id}"));
    let end = start + html[start..].find("</section>").expect("a closed section");
    &html[start..end]
}

/// Every value of attribute `attr` (` attr="..."`) in `html`.
fn attribute_values<'a>(html: &'a str, attr: &str) -> Vec<&'a str> {
    let pat = format!(" {attr}=\"");
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&pat) {
        rest = &rest[i + pat.len()..];
        let end = rest.find('"').expect("a closed attribute");
        out.push(&rest[..end]);
    }
    out
}

/// Checks that the main elements open and close in a properly nested order.
fn check_nesting(html: &str) {
    const TAGS: [&str; 24] = [
        "html",
        "head",
        "body",
        "header",
        "main",
        "footer",
        "section",
        "article",
        "nav",
        "table",
        "thead",
        "tbody",
        "tr",
        "td",
        "th",
        "figure",
        "figcaption",
        "svg",
        "details",
        "summary",
        "dl",
        "ul",
        "select",
        "script",
    ];
    let mut stack: Vec<&str> = Vec::new();
    let bytes = html.as_bytes();
    let mut i = 0;
    while let Some(off) = html[i..].find('<') {
        let at = i + off;
        let closing = bytes.get(at + 1) == Some(&b'/');
        let name_start = at + 1 + usize::from(closing);
        let name_len = html[name_start..]
            .find(|c: char| !c.is_ascii_alphanumeric())
            .unwrap_or(0);
        let name = &html[name_start..name_start + name_len];
        i = name_start;
        if !TAGS.contains(&name) {
            continue;
        }
        let end = at + html[at..].find('>').expect("a closed tag");
        if html[at..end].ends_with('/') {
            continue; // <svg .../>
        }
        if closing {
            let open = stack.pop();
            assert_eq!(open, Some(name), "</{name}> at byte {at} closes {open:?}");
        } else {
            stack.push(name);
        }
        if name == "script" && !closing {
            // The script's text is not markup.
            i = at + html[at..].find("</script>").expect("a closed script");
        }
    }
    assert!(stack.is_empty(), "unclosed: {stack:?}");
}

#[test]
fn the_catalogue_report_has_every_part() {
    let dir = scratch("report");
    let out_dir = dir.join("out");
    let out = exactcheck(&[
        "report",
        "-o",
        out_dir.to_str().unwrap(),
        "--samples",
        "40",
        "--quiet",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let claims = catalogue();
    let failing: Vec<&str> = claims
        .iter()
        .filter(|c| c.expected == Verdict::Fails)
        .map(|c| c.id)
        .collect();
    let figures = exactcheck::papers::figures().unwrap();
    let index = out_dir.join("index.html");
    assert_eq!(
        stdout.trim(),
        format!(
            "wrote {}: {} claims ({} errata), {} figures, 4 regression summaries",
            index.display(),
            claims.len(),
            failing.len(),
            figures.len()
        )
    );
    let html = std::fs::read_to_string(&index).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    check_nesting(&html);

    // The verdict table: one row per claim, each with its source and verdict.
    let table = section(&html, "claims");
    assert_eq!(table.matches("<table id=\"verdicts\">").count(), 1);
    assert_eq!(table.matches("<tr id=\"claim-").count(), claims.len());
    assert_eq!(attribute_values(table, "data-source").len(), claims.len());
    let verdicts = attribute_values(table, "data-verdict");
    assert_eq!(verdicts.len(), claims.len());
    for c in &claims {
        assert!(
            table.contains(&format!("<code>{}</code>", c.id)),
            "{}",
            c.id
        );
    }
    assert_eq!(
        verdicts.iter().filter(|v| **v == "fails").count(),
        failing.len()
    );

    // The errata: every failing claim of the catalogue, and only those.
    let errata = section(&html, "errata");
    let listed = attribute_values(errata, "data-claim");
    assert_eq!(
        listed, failing,
        "the errata list the failing claims in order"
    );
    assert_eq!(failing.len(), 10);

    // Every figure, inline.
    let figs = section(&html, "figures");
    assert_eq!(attribute_values(figs, "data-figure").len(), figures.len());
    for f in &figures {
        assert!(
            figs.contains(&format!("data-figure=\"{}\"", f.id)),
            "{}",
            f.id
        );
    }
    assert_eq!(figs.matches("<svg").count(), figures.len());

    // The regression tables of the four kernels.
    let regress = section(&html, "regressions");
    for kernel in [
        "cylinder-sphere",
        "bezier-cubic",
        "plane-plane",
        "ruled-plane",
    ] {
        assert!(
            regress.contains(&format!("id=\"regress-{kernel}\"")),
            "{kernel}"
        );
    }
    assert!(regress.matches("<table class=\"regress\">").count() >= 4);
    assert!(regress.contains("--samples 40 --seed 1"));

    // Self-contained: no external resource, unique ids.
    for attr in ["src", "href", "xlink:href"] {
        for v in attribute_values(&html, attr) {
            assert!(
                v.starts_with('#') || v.starts_with("data:"),
                "{attr}=\"{v}\" is an external reference"
            );
        }
    }
    for bad in [
        "<link",
        "<script src",
        "@import",
        "url(http",
        "<iframe",
        "<img src=\"http",
    ] {
        assert!(!html.contains(bad), "{bad}");
    }
    let ids = attribute_values(&html, "id");
    let mut unique = ids.clone();
    unique.sort_unstable();
    unique.dedup();
    assert_eq!(unique.len(), ids.len(), "duplicate ids in the page");
}

#[test]
fn bad_outputs_and_counts_are_one_line_errors() {
    let dir = scratch("report-errors");
    let file = dir.join("taken");
    std::fs::write(&file, "not a directory").unwrap();
    let out = exactcheck(&["report", "-o", file.to_str().unwrap(), "--quiet"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("is a file, not a directory"), "{err}");
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "not a directory",
        "the file is left alone"
    );
    let out = exactcheck(&["report", "-o", dir.to_str().unwrap(), "--samples", "0"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("--samples must be between 1 and"), "{err}");
    assert!(!dir.join("index.html").exists());
}

/// Runs `exactcheck ARGS` in the directory `cwd`.
fn exactcheck_in(cwd: &Path, args: &[&str]) -> Output {
    common::exactcheck()
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("the binary runs")
}

/// The one line of a run that must fail with exit status 2 and print nothing.
fn one_error_line(o: &Output) -> String {
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    assert!(o.stdout.is_empty(), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(err.lines().count(), 1, "{err}");
    err.trim_end().to_string()
}

const PAPER: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/mypaper.toml");

#[test]
fn an_empty_or_dash_output_is_refused() {
    // Old: `-o ''` wrote ./index.html over the one in the working directory, `-o -` made a
    // directory named `-`.
    let dir = scratch("report-empty-dash");
    std::fs::write(dir.join("index.html"), "mine").unwrap();
    let e = one_error_line(&exactcheck_in(&dir, &["report", PAPER, "-o", ""]));
    assert!(e.contains("the output path is empty"), "{e}");
    assert_eq!(
        std::fs::read_to_string(dir.join("index.html")).unwrap(),
        "mine"
    );
    let e = one_error_line(&exactcheck_in(&dir, &["report", PAPER, "-o", "-"]));
    assert!(
        e.contains("`-` means standard output") && e.contains("./-"),
        "{e}"
    );
    assert!(!dir.join("-").exists());
    // `./-` names a directory called `-`.
    let o = exactcheck_in(&dir, &["report", PAPER, "-o", "./-", "--quiet"]);
    assert!(o.status.success(), "{o:?}");
    assert!(dir.join("-/index.html").is_file());
}

#[test]
fn the_input_is_read_before_the_directory_is_created() {
    // Old: the directory was created first and left empty when the claims file was missing.
    let dir = scratch("report-input-first");
    let out = dir.join("new/out");
    let e = one_error_line(&exactcheck(&[
        "report",
        "no/such/paper.toml",
        "-o",
        out.to_str().unwrap(),
    ]));
    assert!(e.contains("no/such/paper.toml"), "{e}");
    assert!(!dir.join("new").exists(), "no directory on an error");
}

#[cfg(unix)]
#[test]
fn a_symlink_at_index_html_is_replaced_not_followed() {
    // Old: the page was written through the link, outside the output directory.
    let dir = scratch("report-symlink");
    let outside = dir.join("outside.html");
    std::fs::write(&outside, "not the report's").unwrap();
    let out = dir.join("out");
    std::fs::create_dir(&out).unwrap();
    std::os::unix::fs::symlink(&outside, out.join("index.html")).unwrap();
    let o = exactcheck(&["report", PAPER, "-o", out.to_str().unwrap(), "--quiet"]);
    assert!(o.status.success(), "{o:?}");
    assert_eq!(
        std::fs::read_to_string(&outside).unwrap(),
        "not the report's"
    );
    let index = out.join("index.html");
    assert!(std::fs::symlink_metadata(&index)
        .unwrap()
        .file_type()
        .is_file());
    assert!(std::fs::read_to_string(&index).unwrap().contains("<html"));
}
