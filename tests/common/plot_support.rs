//! What the plot tests share (`#[path]`-included, so crates that do not plot do not compile
//! it): a temporary directory, the binary, the SVG well-formedness check and a polyline counter.

use std::path::PathBuf;
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A fresh directory under the system temp dir, removed when dropped.
pub struct TempDir(PathBuf);

impl TempDir {
    pub fn new(tag: &str) -> TempDir {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        let dir = std::env::temp_dir().join(format!(
            "exactcheck-plot-{tag}-{}-{nanos}-{}",
            std::process::id(),
            COUNTER.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&dir).expect("create temp dir");
        TempDir(dir)
    }

    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs the binary with `args`.
pub fn exactcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_exactcheck"))
        .args(args)
        .output()
        .expect("run exactcheck")
}

/// Well-formed enough: starts with `<svg`, one `<svg` and one `</svg>` at the end, and every
/// element that is opened is closed (a simple tag-stack check; no comments or CDATA are written).
pub fn check_svg(svg: &str) {
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert_eq!(svg.matches("<svg").count(), 1);
    assert_eq!(svg.matches("</svg>").count(), 1);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("viewBox=\"0 0 "));
    let mut stack: Vec<String> = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let after = &rest[i + 1..];
        let end = after.find('>').expect("unterminated tag");
        let tag = &after[..end];
        // Attribute values are escaped: no raw '<' inside a tag.
        assert!(!tag.contains('<'), "raw < inside a tag: {tag}");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop().as_deref(),
                Some(name.trim()),
                "mismatched </{name}>"
            );
        } else if !tag.ends_with('/') {
            let name = tag.split_whitespace().next().unwrap_or_default();
            stack.push(name.to_string());
        }
        rest = &after[end + 1..];
    }
    assert!(stack.is_empty(), "unclosed: {stack:?}");
    // Text is escaped: a bare '&' is always an entity.
    for (i, _) in svg.match_indices('&') {
        let ent = &svg[i..svg.len().min(i + 7)];
        assert!(
            ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"]
                .iter()
                .any(|e| ent.starts_with(e)),
            "bare & at {i}: {ent}"
        );
    }
}

/// The number of points of the first `<polyline class="CLASS" points="...">`.
#[allow(dead_code)] // not every plot test counts polyline points
pub fn polyline_points(svg: &str, class: &str) -> usize {
    let key = format!("<polyline class=\"{class}\" points=\"");
    let i = svg
        .find(&key)
        .unwrap_or_else(|| panic!("no polyline {class}"));
    let pts = svg[i + key.len()..].split('"').next().unwrap_or_default();
    pts.split_whitespace().count()
}
