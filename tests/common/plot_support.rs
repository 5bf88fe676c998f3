//! What the plot tests share (`#[path]`-included, so crates that do not plot do not compile
//! it): a temporary directory, the binary, the SVG well-formedness check and a polyline counter.

#[path = "exe.rs"]
pub mod exe;
#[path = "golden.rs"]
pub mod golden;

use std::path::PathBuf;
use std::process::Output;
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
    exe::exactcheck()
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
    // A size: positive width and height, and the viewBox "0 0 width height".
    let root = &elements(svg)[0];
    let (w, h) = (root.num("width"), root.num("height"));
    assert!(w > 0.0 && h > 0.0, "size {w} x {h}");
    assert_eq!(root.attr("viewBox"), Some(format!("0 0 {w} {h}").as_str()));
    // Every coordinate is a finite number.
    for e in elements(svg) {
        for key in [
            "x", "y", "cx", "cy", "r", "x1", "y1", "x2", "y2", "width", "height",
        ] {
            if let Some(v) = e.attr(key) {
                let n: f64 = v
                    .parse()
                    .unwrap_or_else(|_| panic!("{key}=\"{v}\" in <{}>", e.name));
                assert!(n.is_finite(), "{key}={v}");
            }
        }
        for (x, y) in e.points() {
            assert!(x.is_finite() && y.is_finite(), "points of <{}>", e.name);
        }
    }
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

/// One element of an SVG document: its name, its attributes (unescaped only as far as the
/// tests need: values are compared as written) and its text content (trimmed).
#[allow(dead_code)] // not every plot test reads every field
pub struct Elem {
    pub name: String,
    pub attrs: Vec<(String, String)>,
    pub text: String,
}

#[allow(dead_code)]
impl Elem {
    pub fn attr(&self, key: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    /// A numeric attribute (NaN when absent or not a number).
    pub fn num(&self, key: &str) -> f64 {
        self.attr(key)
            .and_then(|v| v.parse().ok())
            .unwrap_or(f64::NAN)
    }

    /// The `points` of a polyline or polygon.
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.attr("points")
            .unwrap_or_default()
            .split_whitespace()
            .map(|p| {
                let (x, y) = p.split_once(',').expect("x,y");
                (x.parse().expect("a number"), y.parse().expect("a number"))
            })
            .collect()
    }

    /// Whether the element has these attribute values.
    pub fn has(&self, want: &[(&str, &str)]) -> bool {
        want.iter().all(|(k, v)| self.attr(k) == Some(v))
    }

    /// A representative point: the centre of a circle, the first point of a polyline or
    /// polygon, `(x, y)` of a rect or text.
    pub fn at(&self) -> (f64, f64) {
        match self.name.as_str() {
            "circle" => (self.num("cx"), self.num("cy")),
            "polyline" | "polygon" => self.points()[0],
            "line" => (self.num("x1"), self.num("y1")),
            _ => (self.num("x"), self.num("y")),
        }
    }
}

/// The elements of `svg` in document order (start tags and empty-element tags).
pub fn elements(svg: &str) -> Vec<Elem> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let after = &rest[i + 1..];
        let end = after.find('>').expect("unterminated tag");
        let tag = after[..end].trim_end_matches('/');
        rest = &after[end + 1..];
        if tag.starts_with('/') {
            continue;
        }
        let name = tag
            .split_whitespace()
            .next()
            .unwrap_or_default()
            .to_string();
        let mut attrs = Vec::new();
        let mut a = &tag[name.len()..];
        while let Some(eq) = a.find("=\"") {
            let key = a[..eq].trim().to_string();
            let val_end = a[eq + 2..].find('"').expect("closing quote");
            attrs.push((key, a[eq + 2..eq + 2 + val_end].to_string()));
            a = &a[eq + 2 + val_end + 1..];
        }
        let text = rest[..rest.find('<').unwrap_or(rest.len())]
            .trim()
            .to_string();
        out.push(Elem { name, attrs, text });
    }
    out
}

/// The elements named `name` with these attribute values.
#[allow(dead_code)]
pub fn find<'a>(all: &'a [Elem], name: &str, want: &[(&str, &str)]) -> Vec<&'a Elem> {
    all.iter()
        .filter(|e| e.name == name && e.has(want))
        .collect()
}

/// The point counts of the polylines of this stroke colour and width.
#[allow(dead_code)]
pub fn polylines(svg: &str, stroke: &str, width: u32) -> Vec<usize> {
    let w = width.to_string();
    find(
        &elements(svg),
        "polyline",
        &[("stroke", stroke), ("stroke-width", w.as_str())],
    )
    .iter()
    .map(|e| e.points().len())
    .collect()
}
