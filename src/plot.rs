//! `exactcheck plot`: SVG figures of Spaeth's cylinder/sphere intersection (SPEC §2).
//!
//! Two views of one configuration (one of the paper's examples, or a `cylinder_sphere` problem
//! file as read by `solve`):
//! * the **t-u diagram** (the paper's Fig. 2 and 3, which the seeds do not contain): the branches
//!   `u1(t) <= u2(t)` of `u^2 + 2 A(t) u + B(t) = 0` over `t` in degrees, sampled densely in f64
//!   ([`DiscSampler::roots`]) and broken where the discriminant is negative; the paper's
//!   10-degree samples as dots; the ends of the real t-intervals and the touching points from
//!   the **exact** analysis ([`analyze`], Sturm on the tau-quartic) as markers;
//! * a **3D view**: an orthographic projection of the cylinder and sphere wireframes and the
//!   intersection curve, drawn back to front.
//!
//! The SVG is written by hand ([`Svg`]), every text and attribute value escaped ([`escape`]).

use crate::Error;
use clap::{Args, ValueEnum};
use exactcheck_core::cylinder_sphere::{rotate_x, rotate_y, Angle, CylinderSphere, SpaethExample};
use exactcheck_core::{Sign, Vec3};
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::{Bound, RootInterval, UPoly};
use exactcheck_exact::Rational;
use exactcheck_float::sampler::DiscSampler;
use std::f64::consts::TAU;
use std::fmt::{self, Display, Write as _};

/// Arguments of `exactcheck plot`.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// `spaeth` (with `--example N`) or a `cylinder_sphere` problem file (the format of `solve`).
    pub source: String,
    /// Which of Spaeth's examples to draw (1, 2 or 3), with `spaeth`.
    #[arg(long, value_name = "N")]
    pub example: Option<u32>,
    /// The figure: the t-u diagram (the paper's Fig. 2 / 3) or a 3D view.
    #[arg(long, value_enum, default_value_t = View::Tu)]
    pub view: View,
    /// The SVG file to write.
    #[arg(short = 'o', long = "output", value_name = "FILE.svg")]
    pub output: String,
}

/// The figures `plot` draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum View {
    /// The t-u diagram: t in degrees against the roots u1 <= u2.
    Tu,
    /// An orthographic 3D view of cylinder, sphere and intersection curve.
    #[value(name = "3d")]
    ThreeD,
}

/// Runs `exactcheck plot`: draws the figure, writes it and prints one line.
///
/// # Errors
/// [`Error::Usage`] for an unknown example, a missing or misplaced `--example`, or an output
/// path that cannot be written; [`Error::Io`] / [`Error::Input`] for an unreadable or malformed
/// problem file or one of another kind.
pub fn run(args: &PlotArgs) -> Result<(), Error> {
    let scene = match (args.source.as_str(), args.example) {
        ("spaeth", Some(n)) => spaeth_scene(n)?,
        ("spaeth", None) => {
            return Err(Error::Usage("plot spaeth needs --example 1, 2 or 3".into()))
        }
        (_, Some(_)) => {
            return Err(Error::Usage(format!(
                "--example goes with `plot spaeth`, not with a problem file ({})",
                args.source
            )))
        }
        (path, None) => file_scene(path)?,
    };
    let (svg, what) = match args.view {
        View::Tu => (tu_diagram(&scene), "t-u diagram"),
        View::ThreeD => (view_3d(&scene), "3D view"),
    };
    std::fs::write(&args.output, &svg)
        .map_err(|e| Error::Usage(format!("cannot write {}: {e}", args.output)))?;
    println!(
        "wrote {}: {what} of {}{} ({} bytes of SVG)",
        args.output,
        scene.name,
        match (args.view, scene.figure) {
            (View::Tu, Some(f)) => format!(" (the paper's {f})"),
            _ => String::new(),
        },
        svg.len()
    );
    Ok(())
}

// ------------------------------------------------------------------------------ the scenes

/// What is drawn: the f64 configuration (curves and samples) and the exact analysis (markers).
struct Scene {
    /// "Spaeth Example 1" or the problem file.
    name: String,
    /// The paper's figure, if it has one.
    figure: Option<&'static str>,
    /// The configuration in words.
    config: String,
    /// The configuration the curves and the 10-degree samples are computed for.
    float: CylinderSphere<f64>,
    /// The exact analysis, or why there is none.
    exact: Result<ExactInfo, String>,
    /// How the f64 configuration was taken, if worth saying.
    note_float: Option<String>,
    /// How the exact configuration differs from the f64 one, if it does.
    note_exact: Option<String>,
}

/// The exact analysis turned into angles (degrees in `[0, 360)`).
struct ExactInfo {
    /// Arcs `(start, end)` of `t` where the discriminant is `>= 0`, counter-clockwise
    /// (`start > end` when the arc passes through 0); empty when nowhere.
    arcs: Vec<(f64, f64)>,
    /// Whether the discriminant is `>= 0` for every `t` (then `arcs` is empty).
    everywhere: bool,
    /// Isolated touching points.
    tangents: Vec<f64>,
    /// One line: contact, components, the real set.
    summary: String,
}

fn to_f64(q: &Rational) -> f64 {
    q.to_f64()
}

/// Spaeth's examples (r = 5, axis through the origin), rebuilt from the printed values
/// (`exactcheck_core::cylinder_sphere::SPAETH_EXAMPLES`).
fn spaeth_scene(n: u32) -> Result<Scene, Error> {
    let ex = SpaethExample::get(n).ok_or_else(|| {
        Error::Usage(format!(
            "unknown example {n}: Spaeth's examples are 1, 2 and 3"
        ))
    })?;
    let exact = ex.config(|theta| crate::claims::spaeth::rational_angle(theta, 1000).0);
    let float = ex.float_config();
    let figure = match n {
        1 => Some("Fig. 2"),
        2 => Some("Fig. 3"),
        _ => None,
    };
    let note = (n == 2).then(|| {
        let (_, tb, db) = crate::claims::spaeth::rational_angle(ex.beta_radians, 1000);
        let (_, tg, dg) = crate::claims::spaeth::rational_angle(ex.gamma_radians, 1000);
        format!("rational rotations τβ = {tb}, τγ = {tg} (off by {db:.1e}, {dg:.1e} rad)")
    });
    Ok(Scene {
        name: format!("Spaeth Example {n}"),
        figure,
        config: describe(&float),
        float,
        exact: Ok(exact_info(&exact)),
        note_float: (n == 2).then(|| "f64 with β = 1, γ = −1 rad as printed".to_string()),
        note_exact: note,
    })
}

/// A `cylinder_sphere` problem file, read as `solve` reads it: in f64 for the curves and exactly
/// (when the file is exact input) for the markers.
fn file_scene(path: &str) -> Result<Scene, Error> {
    let text = crate::solve::read_problem(Some(path))?;
    let in_file = |e: Error| Error::Input(format!("{path}: {e}"));
    let kind = crate::solve::problem_kind(&text).map_err(in_file)?;
    if kind != "cylinder_sphere" {
        return Err(Error::Input(format!(
            "{path}: plot draws problems of kind \"cylinder_sphere\" only (found kind {kind:?})"
        )));
    }
    let configs = crate::solve::cylinder_sphere::configurations(&text).map_err(in_file)?;
    let fcs = configs.float;
    let exact = configs.exact;
    let notes = configs.approximated_angles;
    let note = (!notes.is_empty()).then(|| {
        let taus: Vec<String> = notes
            .iter()
            .map(|n| format!("{}: τ = {}", n.field, n.rational_tau))
            .collect();
        format!("radians taken as rational rotations ({})", taus.join(", "))
    });
    let name = std::path::Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |f| f.to_string_lossy().into_owned());
    Ok(Scene {
        name,
        figure: None,
        config: describe(&fcs),
        float: fcs,
        exact: exact
            .map(|cs| exact_info(&cs))
            .map_err(|e| format!("no exact analysis: {e}")),
        note_float: None,
        note_exact: note,
    })
}

/// A short decimal: at most `decimals` places, trailing zeros dropped, no `-0`.
fn short(x: f64, decimals: usize) -> String {
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

fn describe(cs: &CylinderSphere<f64>) -> String {
    let deg = |a: &Angle<f64>| {
        let d = a.sin.atan2(a.cos);
        if d == 0.0 {
            "0".to_string()
        } else {
            format!("{} rad", short(d, 4))
        }
    };
    let c = &cs.center;
    format!(
        "cylinder r = {}, axis through ({}, {}), β = {}, γ = {}; sphere centre ({}, {}, {}), R = {}",
        short(cs.r, 4),
        short(cs.a, 4),
        short(cs.b, 4),
        deg(&cs.beta),
        deg(&cs.gamma),
        short(c.x, 4),
        short(c.y, 4),
        short(c.z, 4),
        short(cs.radius, 4)
    )
}

/// The angle `t` in degrees, in `[0, 360)`, of the circle parameter `tau = tan(t/2)`.
fn tau_degrees(tau: f64) -> f64 {
    let d = (2.0 * tau.atan()).to_degrees();
    if d < 0.0 {
        d + 360.0
    } else {
        d
    }
}

/// A root of `p`, refined to width 2^-40, in degrees.
fn root_degrees(p: &UPoly, ri: &RootInterval) -> f64 {
    match ri.exact_value() {
        Some(v) => tau_degrees(to_f64(v)),
        None => {
            let width = Rational::new(1, 1 << 40).unwrap_or(Rational::ONE);
            tau_degrees(p.refine(ri, &width).to_f64())
        }
    }
}

fn exact_info(cs: &CylinderSphere<Rational>) -> ExactInfo {
    let a = analyze(cs);
    let p = &a.discriminant;
    // (start, end, starts at tau = -inf, ends at tau = +inf)
    let mut arcs: Vec<(f64, f64, bool, bool)> = Vec::new();
    for iv in a.nonnegative.iter().filter(|iv| !iv.is_point()) {
        let end = |b: &Bound| match b {
            Bound::Root(r) => root_degrees(p, r),
            Bound::NegInf | Bound::PosInf => 180.0,
        };
        arcs.push((
            end(&iv.lo),
            end(&iv.hi),
            matches!(iv.lo, Bound::NegInf),
            matches!(iv.hi, Bound::PosInf),
        ));
    }
    let everywhere = arcs.len() == 1 && arcs[0].2 && arcs[0].3;
    // The two unbounded tau-intervals are one arc through t = pi when the discriminant is >= 0
    // there.
    if arcs.len() >= 2 && arcs[0].2 && arcs[arcs.len() - 1].3 && a.sign_at_pi != Sign::Negative {
        if let Some(last) = arcs.pop() {
            arcs[0].0 = last.0;
        }
    }
    let mut arcs: Vec<(f64, f64)> = if everywhere {
        Vec::new()
    } else {
        arcs.iter().map(|a| (a.0, a.1)).collect()
    };
    arcs.sort_by(|x, y| x.0.total_cmp(&y.0));
    let tangents: Vec<f64> = a
        .tangent_params
        .iter()
        .map(|t| t.as_ref().map_or(180.0, |ri| root_degrees(p, ri)))
        .collect();
    let set = if everywhere {
        "real for every t".to_string()
    } else if arcs.is_empty() {
        "real for no t".to_string()
    } else {
        let parts: Vec<String> = arcs
            .iter()
            .map(|(s, e)| {
                let through = if s > e { " through 0°" } else { "" };
                format!("{}° → {}°{through}", short(*s, 2), short(*e, 2))
            })
            .collect();
        format!("real for t in {}", parts.join(", "))
    };
    let touching = if tangents.is_empty() {
        String::new()
    } else {
        let ts: Vec<String> = tangents
            .iter()
            .map(|t| format!("{}°", short(*t, 2)))
            .collect();
        format!("; touching at t = {}", ts.join(", "))
    };
    let summary = format!(
        "exact (Sturm on the τ-quartic): {}, {} component{}, {set}{touching}",
        format!("{:?}", a.contact).to_lowercase(),
        a.components,
        if a.components == 1 { "" } else { "s" }
    );
    ExactInfo {
        arcs,
        everywhere,
        tangents,
        summary,
    }
}

// ------------------------------------------------------------------------------ sampling

/// `(t, u1, u2)` at `t` (radians); the discriminant clamped at 0 (for points at the boundary).
fn eval(s: &DiscSampler, t: f64) -> [f64; 3] {
    let (sn, c) = t.sin_cos();
    let (a, b) = s.ab(c, sn);
    let d = (a * a - b).max(0.0).sqrt();
    [t, -a - d, -a + d]
}

/// The point next to the boundary between `real` and `not_real`, on the real side.
fn boundary(s: &DiscSampler, mut real: f64, mut not_real: f64) -> f64 {
    for _ in 0..60 {
        let mid = 0.5 * (real + not_real);
        if s.discriminant(mid) >= 0.0 {
            real = mid;
        } else {
            not_real = mid;
        }
    }
    real
}

/// The curve over `t` in `[0, 2 pi]` with `n` steps, as runs of `(t, u1, u2)` where the
/// discriminant is `>= 0`; each run is closed up to the boundary (found by bisection), with
/// extra samples spaced quadratically towards it so the vertical tangent there is drawn.
fn runs(s: &DiscSampler, n: usize) -> Vec<Vec<[f64; 3]>> {
    const K: usize = 12;
    let mut out = Vec::new();
    let mut cur: Vec<[f64; 3]> = Vec::new();
    let mut prev: Option<(f64, bool)> = None;
    for i in 0..=n {
        let t = TAU * i as f64 / n as f64;
        let real = s.discriminant(t) >= 0.0;
        match prev {
            Some((tp, false)) if real => {
                let te = boundary(s, t, tp);
                cur.extend((0..K).map(|k| {
                    let f = (k as f64 / K as f64).powi(2);
                    eval(s, te + f * (t - te))
                }));
            }
            Some((tp, true)) if !real => {
                let te = boundary(s, tp, t);
                cur.extend((0..K).rev().map(|k| {
                    let f = (k as f64 / K as f64).powi(2);
                    eval(s, te - f * (te - tp))
                }));
                out.push(std::mem::take(&mut cur));
            }
            _ => {}
        }
        if real {
            cur.push(eval(s, t));
        }
        prev = Some((t, real));
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out.retain(|r| r.iter().all(|p| p.iter().all(|x| x.is_finite())));
    out
}

/// The u-range of the sphere along the cylinder axis, `(u_c - R, u_c + R)`: every curve point
/// lies in it.
fn sphere_u_range(cs: &CylinderSphere<f64>) -> (f64, f64) {
    let (q, a) = cs.axis_polynomial();
    let uc = (&cs.center - &q).dot(&a);
    (uc - cs.radius.abs(), uc + cs.radius.abs())
}

// ------------------------------------------------------------------------------ SVG

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
struct N(f64);

impl Display for N {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = if self.0.is_finite() { self.0 } else { 0.0 };
        let s = format!("{x:.2}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if s == "-0" { "0" } else { s })
    }
}

/// A polyline's points attribute (one decimal: enough at this size).
struct Points<'a>(&'a [(f64, f64)]);

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
    buf: String,
    open: Vec<&'static str>,
}

/// Attributes: names with displayable values (escaped when written).
type Attrs<'a> = &'a [(&'a str, &'a dyn Display)];

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
    fn line(&mut self, (x1, y1): (f64, f64), (x2, y2): (f64, f64), attrs: Attrs<'_>) {
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
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo - 1.0, lo + 1.0)
    };
    let raw = (hi - lo) / target.max(1) as f64;
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
    let first = (lo / step + 1e-9).floor() as i64;
    let last = (hi / step - 1e-9).ceil() as i64;
    ((first..=last).map(|k| k as f64 * step).collect(), step)
}

/// A tick label: as many decimals as the step needs.
fn tick_label(x: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    short(x, decimals)
}

const STYLE: &str = "
.title{font-size:20px;font-weight:bold;fill:#222}
.sub{font-size:12.5px;fill:#444}
.tick{font-size:12px;fill:#333}
.axlabel{font-size:14px;fill:#222}
.legend{font-size:12.5px;fill:#222}
.mark{font-size:10.5px;fill:#333}
.frame{fill:none;stroke:#444;stroke-width:1}
.grid{stroke:#e4e4e4;stroke-width:1}
.taxis{stroke:#777;stroke-width:1.2}
.real{fill:#eef6e8}
.curve{fill:none;stroke-linejoin:round;stroke-linecap:round}
.u1{stroke:#1f5fbf;stroke-width:2.4}
.u2{stroke:#e0620d;stroke-width:2.4}
.hidden{stroke-width:1.8;stroke-opacity:0.7;stroke-dasharray:5 4}
.dot{fill:#222;stroke:#fff;stroke-width:0.8}
.hollow{fill:#fff;stroke:#222;stroke-width:1.2}
.end{stroke:#111;stroke-width:2}
.guide{stroke:#999;stroke-width:0.8;stroke-dasharray:2 3}
.tangent{fill:#8e24aa;stroke:#fff;stroke-width:0.8}
.cyl{fill:none;stroke:#8a8a8a;stroke-width:0.9}
.cyl-back{fill:none;stroke:#c4c4c4;stroke-width:0.8;stroke-dasharray:4 3}
.cyl-sil{fill:none;stroke:#555;stroke-width:1.5}
.sph{fill:none;stroke:#5b93c9;stroke-width:0.8}
.sph-back{fill:none;stroke:#a9c8e6;stroke-width:0.7;stroke-dasharray:3 3}
.sph-disc{fill:#d3e5f6;fill-opacity:0.5;stroke:#2f6da3;stroke-width:1.5}
.axis3{stroke:#333;stroke-width:1.3}
";

/// The title, subtitle lines and style of a figure; returns the y below them.
fn header(svg: &mut Svg, title: &str, lines: &[String]) -> f64 {
    svg.open("style", &[]);
    svg.buf.push_str(STYLE);
    svg.close();
    svg.leaf(
        "rect",
        &[("width", &"100%"), ("height", &"100%"), ("fill", &"#fff")],
    );
    svg.text(24.0, 34.0, title, &[("class", &"title")]);
    let mut y = 34.0;
    for l in lines {
        y += 18.0;
        svg.text(24.0, y, l, &[("class", &"sub")]);
    }
    y + 14.0
}

fn subtitle_lines(scene: &Scene, extra: &str, what: [&str; 2]) -> Vec<String> {
    let mut lines = vec![format!("{}{extra}", scene.config)];
    let parts: Vec<String> = [(what[0], &scene.note_float), (what[1], &scene.note_exact)]
        .iter()
        .filter_map(|(w, n)| n.as_ref().map(|n| format!("{w}: {n}")))
        .collect();
    if !parts.is_empty() {
        lines.push(parts.join("; "));
    }
    lines.push(match &scene.exact {
        Ok(e) => e.summary.clone(),
        Err(why) => why.clone(),
    });
    lines
}

/// A legend symbol.
#[derive(Clone, Copy)]
enum Sym {
    /// A short line of the class.
    Line(&'static str),
    /// A dot (circle) of the class.
    Dot(&'static str),
    /// The exact interval end.
    Tick,
    /// The touching point.
    Diamond,
    /// The shading of the real t-range.
    Band,
    /// The sphere.
    Disc,
}

/// A legend box at `(x, y)` with one row per entry, and notes below it.
fn legend(svg: &mut Svg, x: f64, y: f64, rows: &[(String, Sym)], notes: &[String]) {
    svg.leaf(
        "rect",
        &[
            ("x", &N(x - 10.0)),
            ("y", &N(y - 8.0)),
            ("width", &N(220.0)),
            ("height", &N(rows.len() as f64 * 24.0 + 34.0)),
            ("fill", &"#fafafa"),
            ("stroke", &"#bbb"),
            ("rx", &4),
        ],
    );
    svg.text(
        x,
        y + 10.0,
        "Legend",
        &[("class", &"legend"), ("font-weight", &"bold")],
    );
    let mut ry = y + 34.0;
    for (label, sym) in rows {
        let sx = x + 14.0;
        match *sym {
            Sym::Line(class) => svg.line((sx - 12.0, ry), (sx + 12.0, ry), &[("class", &class)]),
            Sym::Dot(class) => circle(svg, sx, ry, 3.4, class),
            Sym::Tick => svg.line((sx, ry - 8.0), (sx, ry + 8.0), &[("class", &"end")]),
            Sym::Diamond => diamond(svg, sx, ry, 6.0, "tangent"),
            Sym::Band => svg.leaf(
                "rect",
                &[
                    ("class", &"real"),
                    ("x", &N(sx - 12.0)),
                    ("y", &N(ry - 7.0)),
                    ("width", &24),
                    ("height", &14),
                    ("stroke", &"#cde3bd"),
                ],
            ),
            Sym::Disc => circle(svg, sx, ry, 8.0, "sph-disc"),
        }
        svg.text(x + 36.0, ry + 4.5, label, &[("class", &"legend")]);
        ry += 24.0;
    }
    for (i, l) in notes.iter().enumerate() {
        svg.text(
            x - 10.0,
            ry + 14.0 + 16.0 * i as f64,
            l,
            &[("class", &"mark")],
        );
    }
}

fn diamond(svg: &mut Svg, x: f64, y: f64, r: f64, class: &str) {
    let pts = [(x, y - r), (x + r, y), (x, y + r), (x - r, y)];
    svg.leaf("polygon", &[("class", &class), ("points", &Points(&pts))]);
}

fn circle(svg: &mut Svg, x: f64, y: f64, r: f64, class: &str) {
    svg.leaf(
        "circle",
        &[
            ("class", &class),
            ("cx", &N(x)),
            ("cy", &N(y)),
            ("r", &N(r)),
        ],
    );
}

// ------------------------------------------------------------------------------ t-u diagram

/// Dense samples of the curves in the t-u diagram.
const TU_SAMPLES: usize = 2000;

/// The t-u diagram (the paper's Fig. 2 / 3).
fn tu_diagram(scene: &Scene) -> String {
    let (width, height) = (980.0, 600.0);
    let title = format!(
        "{}: t-u diagram{}",
        scene.name,
        scene
            .figure
            .map(|f| format!(" (the paper's {f})"))
            .unwrap_or_default()
    );
    let mut svg = Svg::new(width, height, &title);
    let top = header(
        &mut svg,
        &title,
        &subtitle_lines(scene, "", ["curves and dots", "exact markers"]),
    ) + 18.0;
    let (x0, w) = (80.0, 640.0);
    let (y0, h) = (top, height - top - 70.0);
    let sampler = DiscSampler::new(&scene.float);
    let curves = runs(&sampler, TU_SAMPLES);
    // u-range: the sphere's extent along the axis (every curve point lies in it) and u = 0.
    let (lo, hi) = sphere_u_range(&scene.float);
    let (uticks, ustep) = nice_ticks(lo.min(0.0), hi.max(0.0), 6);
    let (umin, umax) = (uticks[0], uticks[uticks.len() - 1]);
    let px = |t_deg: f64| x0 + t_deg / 360.0 * w;
    let py = |u: f64| y0 + h - (u - umin) / (umax - umin) * h;

    // Real t-ranges (exact), grid, frame, the t axis.
    if let Ok(e) = &scene.exact {
        let band = |svg: &mut Svg, a: f64, b: f64| {
            svg.leaf(
                "rect",
                &[
                    ("class", &"real"),
                    ("x", &N(px(a))),
                    ("y", &N(y0)),
                    ("width", &N(px(b) - px(a))),
                    ("height", &N(h)),
                ],
            );
        };
        if e.everywhere {
            band(&mut svg, 0.0, 360.0);
        }
        for &(s, t) in &e.arcs {
            if s <= t {
                band(&mut svg, s, t);
            } else {
                band(&mut svg, s, 360.0);
                band(&mut svg, 0.0, t);
            }
        }
    }
    for k in 0..=12 {
        let x = px(k as f64 * 30.0);
        svg.line((x, y0), (x, y0 + h), &[("class", &"grid")]);
    }
    for &u in &uticks {
        svg.line((x0, py(u)), (x0 + w, py(u)), &[("class", &"grid")]);
    }
    svg.leaf(
        "rect",
        &[
            ("class", &"frame"),
            ("x", &N(x0)),
            ("y", &N(y0)),
            ("width", &N(w)),
            ("height", &N(h)),
        ],
    );
    svg.line((x0, py(0.0)), (x0 + w, py(0.0)), &[("class", &"taxis")]);
    for k in 0..=36 {
        let x = px(k as f64 * 10.0);
        let len = if k % 3 == 0 { 6.0 } else { 3.0 };
        svg.line((x, y0 + h), (x, y0 + h + len), &[("stroke", &"#444")]);
        if k % 3 == 0 {
            svg.text(
                x,
                y0 + h + 20.0,
                &format!("{}°", k * 10),
                &[("class", &"tick"), ("text-anchor", &"middle")],
            );
        }
    }
    for &u in &uticks {
        svg.line((x0 - 6.0, py(u)), (x0, py(u)), &[("stroke", &"#444")]);
        svg.text(
            x0 - 10.0,
            py(u) + 4.0,
            &tick_label(u, ustep),
            &[("class", &"tick"), ("text-anchor", &"end")],
        );
    }
    svg.text(
        x0 + w / 2.0,
        y0 + h + 44.0,
        "t (degrees)",
        &[("class", &"axlabel"), ("text-anchor", &"middle")],
    );
    let (lx, ly) = (x0 - 52.0, y0 + h / 2.0);
    svg.text(
        lx,
        ly,
        "u (along the cylinder axis)",
        &[
            ("class", &"axlabel"),
            ("text-anchor", &"middle"),
            ("transform", &format!("rotate(-90 {} {})", N(lx), N(ly))),
        ],
    );

    // The branches.
    for run in &curves {
        for (branch, class) in [(1, "curve u1"), (2, "curve u2")] {
            let pts: Vec<(f64, f64)> = run
                .iter()
                .map(|p| (px(p[0].to_degrees()), py(p[branch])))
                .collect();
            svg.leaf("polyline", &[("class", &class), ("points", &Points(&pts))]);
        }
    }
    if curves.is_empty() {
        svg.text(
            x0 + w / 2.0,
            y0 + 28.0,
            "A(t)² − B(t) < 0 for every sampled t: no real u, no curve",
            &[
                ("class", &"legend"),
                ("text-anchor", &"middle"),
                ("font-style", &"italic"),
            ],
        );
    }

    // The paper's 10-degree samples (under the exact markers).
    let mut sample_real = (0, 0);
    for k in 0..=36 {
        let t = k as f64 * 10.0;
        match sampler.roots(t.to_radians()) {
            Some((u1, u2)) => {
                sample_real.0 += 1;
                circle(&mut svg, px(t), py(u1), 3.4, "dot");
                circle(&mut svg, px(t), py(u2), 3.4, "dot");
            }
            None => {
                sample_real.1 += 1;
                circle(&mut svg, px(t), py(0.0), 3.4, "hollow");
            }
        }
    }

    // Exact ends of the real t-intervals and touching points.
    let mid_u = |t_deg: f64| {
        let p = eval(&sampler, t_deg.to_radians());
        0.5 * (p[1] + p[2])
    };
    let mut labelled: Vec<f64> = Vec::new();
    let mut label = |svg: &mut Svg, t: f64, text: String| {
        let x = px(t);
        svg.line((x, y0), (x, y0 + h), &[("class", &"guide")]);
        // Stagger labels that would overlap.
        let row = labelled
            .iter()
            .filter(|&&o| (px(o) - x).abs() < 44.0)
            .count();
        labelled.push(t);
        svg.text(
            x + 3.0,
            y0 + 13.0 + 12.0 * row as f64,
            &text,
            &[("class", &"mark")],
        );
    };
    if let Ok(e) = &scene.exact {
        for &(s, t) in &e.arcs {
            for end in [s, t] {
                let (x, y) = (px(end), py(mid_u(end)));
                label(&mut svg, end, format!("{}°", short(end, 2)));
                svg.line((x, y - 9.0), (x, y + 9.0), &[("class", &"end")]);
            }
        }
        for &t in &e.tangents {
            label(&mut svg, t, format!("{}° (touching)", short(t, 2)));
            diamond(&mut svg, px(t), py(mid_u(t)), 6.0, "tangent");
        }
    }

    // Legend: the entries that occur.
    let mut rows: Vec<(String, Sym)> = Vec::new();
    if !curves.is_empty() {
        rows.push(("u1 = −A − √(A² − B)".into(), Sym::Line("curve u1")));
        rows.push(("u2 = −A + √(A² − B)".into(), Sym::Line("curve u2")));
    }
    if sample_real.0 > 0 {
        rows.push(("10° sample: real u1, u2".into(), Sym::Dot("dot")));
    }
    if sample_real.1 > 0 {
        rows.push(("10° sample: not real".into(), Sym::Dot("hollow")));
    }
    let mut notes = vec![
        format!("curves: f64, {TU_SAMPLES} steps in t,"),
        "broken where A² − B < 0".to_string(),
    ];
    if let Ok(e) = &scene.exact {
        if e.everywhere || !e.arcs.is_empty() {
            rows.push(("A² − B ≥ 0 (exact)".into(), Sym::Band));
        }
        if !e.arcs.is_empty() {
            rows.push(("end of a real t-interval".into(), Sym::Tick));
        }
        if !e.tangents.is_empty() {
            rows.push(("touching point".into(), Sym::Diamond));
        }
        if e.everywhere || !e.arcs.is_empty() || !e.tangents.is_empty() {
            notes.push("shading, ends, touching points:".into());
            notes.push("exact (Sturm on the τ-quartic)".into());
        }
    }
    legend(&mut svg, x0 + w + 36.0, y0, &rows, &notes);
    svg.finish()
}

// ------------------------------------------------------------------------------ 3D view

/// Azimuth and elevation of the fixed view direction (degrees).
const AZIMUTH: f64 = -60.0;
/// Negative: from slightly below, where Example 2's curve lies (it is nearly a great circle of
/// the sphere, tilted towards -z).
const ELEVATION: f64 = -25.0;

/// Orthographic projection: screen right, screen up and the direction towards the viewer.
struct Camera {
    right: Vec3<f64>,
    up: Vec3<f64>,
    toward: Vec3<f64>,
}

impl Camera {
    fn new(azimuth: f64, elevation: f64) -> Camera {
        let (sa, ca) = azimuth.to_radians().sin_cos();
        let (se, ce) = elevation.to_radians().sin_cos();
        Camera {
            right: Vec3::new(-sa, ca, 0.0),
            up: Vec3::new(-se * ca, -se * sa, ce),
            toward: Vec3::new(ce * ca, ce * sa, se),
        }
    }

    /// `(x, y)` on the image plane (y up).
    fn project(&self, p: &Vec3<f64>) -> (f64, f64) {
        (p.dot(&self.right), p.dot(&self.up))
    }

    fn depth(&self, p: &Vec3<f64>) -> f64 {
        p.dot(&self.toward)
    }
}

/// What the 3D view is made of, sorted by depth before drawing.
enum Prim {
    Line {
        pts: Vec<(f64, f64)>,
        class: &'static str,
        depth: f64,
    },
    Disc {
        centre: (f64, f64),
        radius: f64,
        depth: f64,
    },
}

impl Prim {
    fn depth(&self) -> f64 {
        match self {
            Prim::Line { depth, .. } | Prim::Disc { depth, .. } => *depth,
        }
    }
}

/// Adds a 3D polyline cut into short pieces (so the painter's order works along it) and where
/// the class of its points (`class_of(index)`) changes.
fn add_polyline(
    prims: &mut Vec<Prim>,
    cam: &Camera,
    pts: &[Vec3<f64>],
    class_of: impl Fn(usize) -> &'static str,
) {
    const PIECE: usize = 16;
    let mut i = 0;
    while i + 1 < pts.len() {
        let class = class_of(i);
        let mut j = i + 1;
        while j + 1 < pts.len() && j - i < PIECE && class_of(j) == class {
            j += 1;
        }
        let piece = &pts[i..=j];
        let depth = piece.iter().map(|p| cam.depth(p)).sum::<f64>() / piece.len() as f64;
        prims.push(Prim::Line {
            pts: piece.iter().map(|p| cam.project(p)).collect(),
            class,
            depth,
        });
        i = j;
    }
}

/// The 3D view.
fn view_3d(scene: &Scene) -> String {
    let (width, height) = (980.0, 680.0);
    let title = format!(
        "{}: cylinder, sphere and intersection curve (3D)",
        scene.name
    );
    let mut svg = Svg::new(width, height, &title);
    let extra = format!("; orthographic view, azimuth {AZIMUTH}°, elevation {ELEVATION}°");
    let top = header(
        &mut svg,
        &title,
        &subtitle_lines(scene, &extra, ["curve", "exact analysis"]),
    ) + 6.0;
    let (x0, y0, w, h) = (20.0, top, 700.0, height - top - 16.0);
    let cs = &scene.float;
    let cam = Camera::new(AZIMUTH, ELEVATION);
    let centre = &cs.center;
    let big_r = cs.radius.abs();
    let mut prims: Vec<Prim> = Vec::new();

    // The cylinder over a u-range covering the sphere.
    let (lo, hi) = sphere_u_range(cs);
    let margin = 0.35 * big_r.max(cs.r.abs());
    let (umin, umax) = (lo - margin, hi + margin);
    let rot = |v: Vec3<f64>| rotate_x(&cs.gamma, &rotate_y(&cs.beta, &v));
    let (e1, e2) = (rot(Vec3::new(1.0, 0.0, 0.0)), rot(Vec3::new(0.0, 1.0, 0.0)));
    let front = |t: f64| (e1.dot(&cam.toward) * t.cos() + e2.dot(&cam.toward) * t.sin()) > 0.0;
    let cyl_class = |t: f64| if front(t) { "cyl" } else { "cyl-back" };
    let point = |t: f64, u: f64| cs.point(&t.cos(), &t.sin(), &u);
    for k in 0..=4 {
        let u = umin + (umax - umin) * k as f64 / 4.0;
        let ts: Vec<f64> = (0..=144).map(|i| TAU * i as f64 / 144.0).collect();
        let pts: Vec<Vec3<f64>> = ts.iter().map(|&t| point(t, u)).collect();
        add_polyline(&mut prims, &cam, &pts, |i| cyl_class(ts[i]));
    }
    for j in 0..16 {
        let t = TAU * j as f64 / 16.0;
        let pts: Vec<Vec3<f64>> = (0..=12)
            .map(|i| point(t, umin + (umax - umin) * i as f64 / 12.0))
            .collect();
        let class = cyl_class(t);
        add_polyline(&mut prims, &cam, &pts, |_| class);
    }
    let ts = (-e1.dot(&cam.toward)).atan2(e2.dot(&cam.toward));
    for t in [ts, ts + TAU / 2.0] {
        let pts: Vec<Vec3<f64>> = (0..=12)
            .map(|i| point(t, umin + (umax - umin) * i as f64 / 12.0))
            .collect();
        add_polyline(&mut prims, &cam, &pts, |_| "cyl-sil");
    }

    // The sphere: a translucent disc at the depth of its centre, latitudes and longitudes.
    prims.push(Prim::Disc {
        centre: cam.project(centre),
        radius: big_r,
        depth: cam.depth(centre),
    });
    let sph_class = |p: &Vec3<f64>| {
        if (p - centre).dot(&cam.toward) >= 0.0 {
            "sph"
        } else {
            "sph-back"
        }
    };
    let on_sphere = |lat: f64, lon: f64| {
        Vec3::new(
            centre.x + big_r * lat.cos() * lon.cos(),
            centre.y + big_r * lat.cos() * lon.sin(),
            centre.z + big_r * lat.sin(),
        )
    };
    for lat in [-60.0f64, -30.0, 0.0, 30.0, 60.0] {
        let pts: Vec<Vec3<f64>> = (0..=120)
            .map(|i| on_sphere(lat.to_radians(), TAU * i as f64 / 120.0))
            .collect();
        add_polyline(&mut prims, &cam, &pts, |i| sph_class(&pts[i]));
    }
    for k in 0..6 {
        let lon = (k as f64 * 30.0).to_radians();
        let pts: Vec<Vec3<f64>> = (0..=120)
            .map(|i| on_sphere(TAU * i as f64 / 120.0, lon))
            .collect();
        add_polyline(&mut prims, &cam, &pts, |i| sph_class(&pts[i]));
    }

    // The intersection curve, both branches.
    let sampler = DiscSampler::new(cs);
    let curves = runs(&sampler, 1200);
    let mut curve_points = 0;
    for run in &curves {
        for (branch, class, hidden) in [
            (1, "curve u1", "curve u1 hidden"),
            (2, "curve u2", "curve u2 hidden"),
        ] {
            let pts: Vec<Vec3<f64>> = run.iter().map(|p| point(p[0], p[branch])).collect();
            curve_points += pts.len();
            let visible = |i: usize| (&pts[i] - centre).dot(&cam.toward) >= -1e-9 * big_r;
            add_polyline(&mut prims, &cam, &pts, |i| {
                if visible(i) {
                    class
                } else {
                    hidden
                }
            });
        }
    }

    // Fit to the drawing area.
    let (mut bx0, mut by0, mut bx1, mut by1) = (
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    );
    let mut grow = |x: f64, y: f64| {
        bx0 = bx0.min(x);
        bx1 = bx1.max(x);
        by0 = by0.min(y);
        by1 = by1.max(y);
    };
    for p in &prims {
        match p {
            Prim::Line { pts, .. } => pts.iter().for_each(|&(x, y)| grow(x, y)),
            Prim::Disc {
                centre: (x, y),
                radius,
                ..
            } => {
                grow(x - radius, y - radius);
                grow(x + radius, y + radius);
            }
        }
    }
    let scale = 0.94 * (w / (bx1 - bx0)).min(h / (by1 - by0));
    let (cx, cy) = (0.5 * (bx0 + bx1), 0.5 * (by0 + by1));
    let sx = |x: f64| x0 + w / 2.0 + (x - cx) * scale;
    let sy = |y: f64| y0 + h / 2.0 - (y - cy) * scale;
    prims.sort_by(|a, b| a.depth().total_cmp(&b.depth()));
    for p in &prims {
        match p {
            Prim::Line { pts, class, .. } => {
                let pts: Vec<(f64, f64)> = pts.iter().map(|&(x, y)| (sx(x), sy(y))).collect();
                svg.leaf("polyline", &[("class", class), ("points", &Points(&pts))]);
            }
            Prim::Disc {
                centre: (x, y),
                radius,
                ..
            } => circle(&mut svg, sx(*x), sy(*y), radius * scale, "sph-disc"),
        }
    }
    if curve_points == 0 {
        svg.text(
            x0 + w / 2.0,
            y0 + 14.0,
            "no real point of the curve: the surfaces do not meet",
            &[
                ("class", &"legend"),
                ("text-anchor", &"middle"),
                ("font-style", &"italic"),
            ],
        );
    }

    // Axis triad.
    svg.open("defs", &[]);
    svg.open(
        "marker",
        &[
            ("id", &"arrow"),
            ("viewBox", &"0 0 10 10"),
            ("refX", &9),
            ("refY", &5),
            ("markerWidth", &7),
            ("markerHeight", &7),
            ("orient", &"auto"),
        ],
    );
    svg.leaf("path", &[("d", &"M0,0 L10,5 L0,10 z"), ("fill", &"#333")]);
    svg.close();
    svg.close();
    let (ox, oy) = (x0 + 48.0, y0 + h - 44.0);
    for (name, e) in [
        ("x", Vec3::new(1.0, 0.0, 0.0)),
        ("y", Vec3::new(0.0, 1.0, 0.0)),
        ("z", Vec3::new(0.0, 0.0, 1.0)),
    ] {
        let (ex, ey) = cam.project(&e);
        svg.line(
            (ox, oy),
            (ox + 36.0 * ex, oy - 36.0 * ey),
            &[("class", &"axis3"), ("marker-end", &"url(#arrow)")],
        );
        svg.text(
            ox + 48.0 * ex - 4.0,
            oy - 48.0 * ey + 4.0,
            name,
            &[("class", &"tick"), ("font-style", &"italic")],
        );
    }

    // Legend.
    let mut rows: Vec<(String, Sym)> = vec![
        (
            format!("cylinder, r = {}", short(cs.r, 4)),
            Sym::Line("cyl-sil"),
        ),
        (format!("sphere, R = {}", short(big_r, 4)), Sym::Disc),
        ("back sides (dashed)".into(), Sym::Line("cyl-back")),
    ];
    if curve_points > 0 {
        rows.push(("branch u1 (−√)".into(), Sym::Line("curve u1")));
        rows.push(("branch u2 (+√)".into(), Sym::Line("curve u2")));
        rows.push((
            "curve behind the sphere".into(),
            Sym::Line("curve u1 hidden"),
        ));
    }
    let notes = [
        "drawn back to front (no hidden-line".to_string(),
        "removal); curve: f64, 1200 steps in t,".to_string(),
        "broken where A² − B < 0".to_string(),
    ];
    legend(&mut svg, x0 + w + 36.0, y0 + 10.0, &rows, &notes);
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escaping() {
        assert_eq!(
            escape(r#"a < b && c > "d" 'e'"#),
            "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &apos;e&apos;"
        );
        assert_eq!(escape("plain °√ text"), "plain °√ text");
        assert_eq!(escape("bell\u{7}tab\t"), "bell\u{FFFD}tab\t");
        let mut svg = Svg::new(10.0, 10.0, "<T&>");
        svg.text(1.0, 2.0, "x<y", &[("class", &"a\"b")]);
        let out = svg.finish();
        assert!(out.contains("<title>&lt;T&amp;&gt;</title>"), "{out}");
        assert!(
            out.contains(r#"<text x="1" y="2" class="a&quot;b">x&lt;y</text>"#),
            "{out}"
        );
        assert!(out.trim_end().ends_with("</svg>"));
    }

    #[test]
    fn ticks() {
        let (t, step) = nice_ticks(-7.0, 7.0, 6);
        assert_eq!(step, 2.0);
        assert_eq!(t, vec![-8.0, -6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0, 8.0]);
        let (t, step) = nice_ticks(0.0, 9.0, 6);
        assert_eq!((t[0], *t.last().unwrap(), step), (0.0, 10.0, 2.0));
        let (t, step) = nice_ticks(0.0, 1.0, 5);
        assert!((step - 0.2).abs() < 1e-12);
        assert_eq!(t.len(), 6);
        assert_eq!(tick_label(t[3], step), "0.6");
        let (t, step) = nice_ticks(-3.0, 30.0, 6);
        assert_eq!(step, 5.0);
        assert_eq!((t[0], *t.last().unwrap()), (-5.0, 30.0));
        assert_eq!(tick_label(-5.0, step), "−5");
        // A degenerate range still gives ticks.
        assert!(nice_ticks(2.0, 2.0, 4).0.len() >= 2);
    }

    #[test]
    fn angles_from_tau() {
        assert_eq!(tau_degrees(0.0), 0.0);
        assert!((tau_degrees(1.0) - 90.0).abs() < 1e-12);
        assert!((tau_degrees(-1.0) - 270.0).abs() < 1e-12);
    }

    #[test]
    fn exact_arcs_of_the_examples() {
        let e1 = spaeth_scene(1)
            .map(|s| s.exact.ok())
            .ok()
            .flatten()
            .expect("example 1");
        assert!(e1.everywhere && e1.arcs.is_empty());
        let e3 = spaeth_scene(3)
            .map(|s| s.exact.ok())
            .ok()
            .flatten()
            .expect("example 3");
        assert!(!e3.everywhere && e3.arcs.is_empty() && e3.tangents.is_empty());
        let e2 = spaeth_scene(2)
            .map(|s| s.exact.ok())
            .ok()
            .flatten()
            .expect("example 2");
        assert!(!e2.everywhere && !e2.arcs.is_empty());
        // The f64 sampler agrees with the exact arcs away from their ends.
        let s = spaeth_scene(2).expect("example 2");
        let sampler = DiscSampler::new(&s.float);
        for &(a, b) in &e2.arcs {
            let len = if a <= b { b - a } else { b + 360.0 - a };
            let mid = (a + len / 2.0) % 360.0;
            assert!(sampler.discriminant(mid.to_radians()) > 0.0, "{a} {b}");
        }
        assert!(spaeth_scene(4).is_err());
    }

    #[test]
    fn runs_are_closed_at_the_boundary() {
        let s = spaeth_scene(2).expect("example 2");
        let sampler = DiscSampler::new(&s.float);
        let rs = runs(&sampler, 500);
        assert!(!rs.is_empty());
        for r in &rs {
            let first = r[0];
            let last = r[r.len() - 1];
            // Where a run starts or ends inside (0, 2 pi) the branches meet.
            if first[0] > 1e-9 {
                assert!((first[1] - first[2]).abs() < 1e-3, "{first:?}");
            }
            if last[0] < TAU - 1e-9 {
                assert!((last[1] - last[2]).abs() < 1e-3, "{last:?}");
            }
        }
    }
}
