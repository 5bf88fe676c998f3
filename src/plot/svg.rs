//! A minimal SVG writer, hand-written because the figures need only a handful of elements:
//! nesting checked, every text and attribute value escaped ([`escape`]); and axis ticks at "nice"
//! steps ([`nice_ticks`]).

use std::fmt::{self, Display, Write as _};

/// `s` with the five XML special characters escaped and characters XML 1.0 cannot hold
/// (control characters other than tab, newline, carriage return) replaced by U+FFFD.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => out.push(c),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// A number as an SVG coordinate (two decimals at most).
pub(super) struct N(pub(super) f64);

impl Display for N {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = if self.0.is_finite() { self.0 } else { 0.0 };
        let s = format!("{x:.2}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if s == "-0" { "0" } else { s })
    }
}

/// A polyline's points attribute (one decimal: enough at this size).
pub(super) struct Points<'a>(pub(super) &'a [(f64, f64)]);

impl Display for Points<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, (x, y)) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_char(' ')?;
            }
            write!(f, "{:.1},{:.1}", x, y)?;
        }
        Ok(())
    }
}

/// A minimal SVG writer: elements with escaped attributes and text, nesting checked.
pub struct Svg {
    pub(super) buf: String,
    open: Vec<&'static str>,
}

/// Attributes: names with displayable values (escaped when written).
pub(super) type Attrs<'a> = &'a [(&'a str, &'a dyn Display)];

impl Svg {
    /// A document of the given size (the viewBox is `0 0 width height`), with a title.
    pub fn new(width: f64, height: f64, title: &str) -> Svg {
        let mut s = Svg {
            buf: String::new(),
            open: Vec::new(),
        };
        s.open(
            "svg",
            &[
                ("xmlns", &"http://www.w3.org/2000/svg"),
                ("viewBox", &format!("0 0 {} {}", N(width), N(height))),
                ("width", &N(width)),
                ("height", &N(height)),
                ("font-family", &"DejaVu Sans, Helvetica, Arial, sans-serif"),
            ],
        );
        s.open("title", &[]);
        s.raw_text(title);
        s.close();
        s
    }

    fn tag(&mut self, tag: &str, attrs: Attrs<'_>) {
        self.buf.push('<');
        self.buf.push_str(tag);
        for (k, v) in attrs {
            let _ = write!(self.buf, " {k}=\"{}\"", escape(&v.to_string()));
        }
    }

    /// Opens an element (closed by [`Svg::close`]).
    pub fn open(&mut self, tag: &'static str, attrs: Attrs<'_>) {
        self.tag(tag, attrs);
        self.buf.push('>');
        if tag != "title" && tag != "text" && tag != "style" {
            self.buf.push('\n');
        }
        self.open.push(tag);
    }

    /// Closes the innermost open element.
    pub fn close(&mut self) {
        if let Some(tag) = self.open.pop() {
            let _ = writeln!(self.buf, "</{tag}>");
        }
    }

    /// An empty element.
    pub fn leaf(&mut self, tag: &str, attrs: Attrs<'_>) {
        self.tag(tag, attrs);
        self.buf.push_str("/>\n");
    }

    fn raw_text(&mut self, text: &str) {
        self.buf.push_str(&escape(text));
    }

    /// A `<text>` element at `(x, y)`.
    pub fn text(&mut self, x: f64, y: f64, text: &str, attrs: Attrs<'_>) {
        let (x, y) = (N(x), N(y));
        let mut all: Vec<(&str, &dyn Display)> = vec![("x", &x), ("y", &y)];
        all.extend_from_slice(attrs);
        self.open("text", &all);
        self.raw_text(text);
        self.close();
    }

    /// A `<line>`.
    pub(super) fn line(&mut self, (x1, y1): (f64, f64), (x2, y2): (f64, f64), attrs: Attrs<'_>) {
        let (x1, y1, x2, y2) = (N(x1), N(y1), N(x2), N(y2));
        let mut all: Vec<(&str, &dyn Display)> =
            vec![("x1", &x1), ("y1", &y1), ("x2", &x2), ("y2", &y2)];
        all.extend_from_slice(attrs);
        self.leaf("line", &all);
    }

    /// The document, with every open element closed.
    pub fn finish(mut self) -> String {
        while !self.open.is_empty() {
            self.close();
        }
        self.buf
    }
}

/// Ticks at the multiples of a "nice" step (1, 2 or 5 times a power of ten) giving about
/// `target` intervals over `[lo, hi]`, extended outwards to whole steps: `(ticks, step)`.
///
/// Any finite range works: a zero-width range is widened to `lo -+ max(|lo|, 1)`; a range
/// narrower than f64 resolves at its magnitude (relative width below `1e-12`, or an absolute
/// width below `1e-290`, e.g. the subnormal sphere radii of a valid problem file) is widened
/// to that width about its centre, so the step is a normal number. A range so wide that
/// whole multiples of the step do not fit in f64 (near `f64::MAX`) gets ticks at its two ends
/// only. The tick count is bounded by `4 target + 5` whatever the input. Non-finite bounds give
/// no ticks (and a NaN step).
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    if !(lo.is_finite() && hi.is_finite()) {
        return (Vec::new(), f64::NAN);
    }
    let target = target.clamp(2, 1000);
    let (mut lo, mut hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    let finite = |x: f64| x.clamp(-f64::MAX, f64::MAX);
    if hi == lo {
        let half = lo.abs().max(1.0);
        (lo, hi) = (finite(lo - half), finite(lo + half));
    }
    let scale = lo.abs().max(hi.abs());
    let min_width = (scale * 1e-12).max(1e-290);
    // Halves first: `hi - lo` itself can overflow.
    if hi / 2.0 - lo / 2.0 < min_width / 2.0 {
        let centre = lo / 2.0 + hi / 2.0;
        (lo, hi) = (
            finite(centre - min_width / 2.0),
            finite(centre + min_width / 2.0),
        );
    }
    let raw = (hi / 2.0 - lo / 2.0) / target as f64 * 2.0;
    let mag = 10f64.powf(raw.log10().floor());
    let norm = raw / mag;
    let step = mag
        * if norm < 1.5 {
            1.0
        } else if norm < 3.0 {
            2.0
        } else if norm < 7.0 {
            5.0
        } else {
            10.0
        };
    let first = (lo / step + 1e-9).floor();
    let last = (hi / step - 1e-9).ceil();
    let fits = step.is_finite()
        && step > 0.0
        && first.is_finite()
        && last.is_finite()
        && last - first <= (4 * target + 4) as f64
        && (first * step).is_finite()
        && (last * step).is_finite();
    if fits {
        let ticks: Vec<f64> = (first as i64..=last as i64)
            .map(|k| k as f64 * step)
            .collect();
        return (ticks, step);
    }
    (vec![lo, hi], hi / 2.0 - lo / 2.0)
}

/// A tick label: as many decimals as the step needs; scientific notation where that would be
/// more than 6 decimals or the value has 16 or more digits.
pub(super) fn tick_label(x: f64, step: f64) -> String {
    if step.is_finite() && step >= 1e-6 && x.abs() < 1e15 {
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        short(x, decimals)
    } else if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.3e}").replace('-', "−")
    }
}

/// A short decimal: at most `decimals` places, trailing zeros dropped, no `-0`.
pub(super) fn short(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        return "?".into();
    }
    let s = format!("{:.*}", decimals, x);
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s.replace('-', "−")
    }
}
