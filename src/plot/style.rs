//! What every figure shares, on top of `plotters`' SVG backend: the palette, the fonts, the
//! document ([`render`]: a white page drawn into a `String`), the caption block ([`header`]),
//! the legend panel with notes ([`legend`]), marker shapes, and the axis ticks at "nice" steps
//! ([`nice_ticks`], [`tick_label`]) that keep a valid but extreme problem file (a subnormal
//! sphere radius) drawable: `plotters` is given a range that f64 resolves.
//!
//! A figure module is then: compute the scene (exactly where the paper's statement is exact),
//! [`render`] a page, [`header`] it, split off the [`legend`], build a `plotters` chart on the
//! rest and draw series on it.
//!
//! `plotters` writes presentation attributes (`stroke="#1F5FBF"`, `fill=...`), no classes:
//! the colours here are public so the tests find an element by its colour
//! ([`hex`] gives the attribute value `plotters` writes).

use plotters::coord::ranged3d::Cartesian3d;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write as _;

/// A 3D chart of an SVG page (the box of [`chart_3d`]).
pub type Chart3d<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian3d<RangedCoordf64, RangedCoordf64, RangedCoordf64>>;

/// The 3D chart every surface view uses: the box `lo..hi` on `area` with `margin` pixels, seen
/// from `view = (yaw, pitch, scale)` of `plotters`' projection, with light back panels, a grey
/// grid and grey axis labels (drawn).
///
/// # Errors
/// When `plotters` cannot draw the axes.
pub fn chart_3d<'a, 'b>(
    area: &'a Area<'b>,
    margin: u32,
    lo: (f64, f64, f64),
    hi: (f64, f64, f64),
    (yaw, pitch, scale): (f64, f64, f64),
) -> Result<Chart3d<'a, 'b>, DrawErr> {
    let mut chart = ChartBuilder::on(area).margin(margin).build_cartesian_3d(
        lo.0..hi.0,
        lo.1..hi.1,
        lo.2..hi.2,
    )?;
    chart.with_projection(|mut p| {
        p.yaw = yaw;
        p.pitch = pitch;
        p.scale = scale;
        p.into_matrix()
    });
    chart
        .configure_axes()
        .axis_panel_style(PANEL.filled())
        .bold_grid_style(RGBColor(0xdd, 0xdd, 0xdd))
        .light_grid_style(RGBColor(0xee, 0xee, 0xee))
        .max_light_lines(2)
        .label_style(font(12.0, GREY_TEXT))
        .draw()?;
    Ok(chart)
}

/// A drawing area of an SVG page.
pub type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
/// What drawing into an SVG string can fail with.
pub type DrawErr = DrawingAreaErrorKind<std::io::Error>;
/// What drawing into an SVG string can return.
pub type DrawResult = Result<(), DrawErr>;

/// The font family of every text.
pub const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

/// Branch `u1` (t-u diagram, 3D view), the piece `C+` (conics), the first offset (PH).
pub const BLUE: RGBColor = RGBColor(0x1f, 0x5f, 0xbf);
/// Branch `u2`, the piece `C-`, the second offset.
pub const ORANGE: RGBColor = RGBColor(0xe0, 0x62, 0x0d);
/// Touching points, asymptotes and poles, the third offset.
pub const PURPLE: RGBColor = RGBColor(0x8e, 0x24, 0xaa);
/// Control polygons and control points.
pub const GREEN: RGBColor = RGBColor(0x1b, 0x5e, 0x20);
/// Chiang's exact section curve, and the PH offsets' cusps.
pub const RED: RGBColor = RGBColor(0xc6, 0x28, 0x28);
/// The cusp markers.
pub const CUSP: RGBColor = RGBColor(0xd5, 0x00, 0x00);
/// The further offsets.
pub const TEAL: RGBColor = RGBColor(0x00, 0x89, 0x7b);
/// The sixth offset.
pub const BROWN: RGBColor = RGBColor(0x6d, 0x4c, 0x41);
/// Dark text and marker ink (the 10-degree samples, interval ends).
pub const INK: RGBColor = RGBColor(0x22, 0x22, 0x22);
/// Secondary text.
pub const GREY_TEXT: RGBColor = RGBColor(0x44, 0x44, 0x44);
/// The shading of the real t-range.
pub const BAND: RGBColor = RGBColor(0xe4, 0xf1, 0xda);
/// Front wireframe lines (cylinder, surface above the plane).
pub const WIRE: RGBColor = RGBColor(0x6d, 0x6d, 0x6d);
/// Back wireframe lines.
pub const WIRE_BACK: RGBColor = RGBColor(0xb5, 0xb5, 0xb5);
/// The sphere's front lines.
pub const SPHERE: RGBColor = RGBColor(0x5b, 0x93, 0xc9);
/// The sphere's back lines.
pub const SPHERE_BACK: RGBColor = RGBColor(0xa9, 0xc8, 0xe6);
/// The sphere's disc and the plane z = 0 (translucent).
pub const SKY: RGBColor = RGBColor(0xbc, 0xd7, 0xf0);
/// The back panels of a 3D chart's axis box.
pub const PANEL: RGBColor = RGBColor(0xf6, 0xf6, 0xf6);
/// Guide lines.
pub const GUIDE: RGBColor = RGBColor(0x99, 0x99, 0x99);

/// The colours of the offsets (PH), cycled.
pub const OFFSETS: [RGBColor; 6] = [BLUE, ORANGE, PURPLE, TEAL, RED, BROWN];

/// The attribute value `plotters` writes for a colour (`#1F5FBF`).
pub fn hex(c: RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

/// A solid stroke.
pub fn stroke(c: RGBColor, width: u32) -> ShapeStyle {
    c.stroke_width(width)
}

/// A text style of the house font.
pub fn font(size: f64, c: RGBColor) -> TextStyle<'static> {
    (FONT, size).into_font().color(&c)
}

/// A bold text style.
pub fn bold(size: f64, c: RGBColor) -> TextStyle<'static> {
    (FONT, size).into_font().style(FontStyle::Bold).color(&c)
}

/// `s` with the characters XML 1.0 cannot hold (control characters other than tab, newline,
/// carriage return; U+FFFE, U+FFFF) replaced by U+FFFD: `plotters` escapes the five markup
/// characters but passes these through, and a file name can hold them.
pub fn clean(s: &str) -> String {
    s.chars()
        .map(|c| match c {
            '\t' | '\n' | '\r' => c,
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => '\u{FFFD}',
            c => c,
        })
        .collect()
}

/// `s` with the five XML special characters escaped (and what [`clean`] replaces): for SVG or
/// HTML written outside `plotters`.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in clean(s).chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// Text at a pixel position of `area`.
pub fn text(area: &Area<'_>, s: &str, (x, y): (i32, i32), style: &TextStyle<'_>) -> DrawResult {
    area.draw(&Text::new(clean(s), (x, y), style.clone()))
}

/// A page of `width` x `height` pixels on a white background, drawn by `draw`; the SVG
/// document, with a `<title>` (the figure's caption, for screen readers and the browser's
/// tooltip) as its first child.
pub fn render(
    (width, height): (u32, u32),
    title: &str,
    draw: impl FnOnce(&Area<'_>) -> DrawResult,
) -> String {
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (width, height)).into_drawing_area();
        root.fill(&WHITE)
            .and_then(|()| draw(&root))
            .and_then(|()| root.present())
            .expect("drawing into a String: the SVG backend's only error is file I/O");
    }
    // The first line is the <svg ...> tag; the title goes right after it.
    let at = buf.find('\n').map_or(buf.len(), |i| i + 1);
    let mut t = String::new();
    let _ = writeln!(t, "<title>{}</title>", escape(title));
    buf.insert_str(at, &t);
    buf
}

/// The caption block: the title (bold) and the lines under it; returns the area below.
pub fn header<'a>(area: &Area<'a>, title: &str, lines: &[String]) -> Result<Area<'a>, DrawErr> {
    text(area, title, (24, 18), &bold(24.0, INK))?;
    let mut y = 18 + 28;
    for l in lines {
        text(area, l, (24, y), &font(15.5, GREY_TEXT))?;
        y += 18;
    }
    Ok(area.split_vertically(y + 10).1)
}

/// A legend symbol.
#[derive(Clone, Copy)]
pub enum Sym {
    /// A short solid line.
    Line(RGBColor, u32),
    /// A short dashed line.
    Dashed(RGBColor, u32),
    /// A dot (filled, white rim).
    Dot(RGBColor),
    /// A hollow dot.
    Hollow(RGBColor),
    /// A vertical tick (an exact interval end).
    Tick(RGBColor),
    /// A diamond (a touching point).
    Diamond(RGBColor),
    /// A filled box (a shaded range, a translucent surface).
    Band(RGBColor),
    /// A ring (a pole).
    Ring(RGBColor),
}

/// A circle of radius `r` pixels filled with `fill` and rimmed with `rim` `width` pixels wide:
/// the one shape behind [`dot`], [`hollow`] and [`ring`].
fn circle_marker<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    fill: RGBColor,
    (rim, width): (RGBColor, u32),
) -> DynElement<'b, DB, C> {
    let e = EmptyElement::at(at)
        + Circle::new((0, 0), r, fill.filled())
        + Circle::new((0, 0), r, rim.stroke_width(width));
    e.into_dyn()
}

/// A filled dot with a white rim, as a pixel-relative element.
pub fn dot<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    c: RGBColor,
) -> DynElement<'b, DB, C> {
    circle_marker(at, r, c, (WHITE, 1))
}

/// A hollow dot (white fill, coloured rim).
pub fn hollow<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    c: RGBColor,
) -> DynElement<'b, DB, C> {
    circle_marker(at, r, WHITE, (c, 1))
}

/// A ring: white inside, a coloured rim 2 pixels wide.
pub fn ring<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    c: RGBColor,
) -> DynElement<'b, DB, C> {
    circle_marker(at, r, WHITE, (c, 2))
}

/// A diamond of half-diagonal `r` pixels.
pub fn diamond<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    c: RGBColor,
) -> DynElement<'b, DB, C> {
    let e = EmptyElement::at(at) + Polygon::new(vec![(0, -r), (r, 0), (0, r), (-r, 0)], c.filled());
    e.into_dyn()
}

/// A vertical tick of half-length `r` pixels.
pub fn tick<'b, DB: DrawingBackend + 'b, C: Clone + 'b>(
    at: C,
    r: i32,
    c: RGBColor,
) -> DynElement<'b, DB, C> {
    let e = EmptyElement::at(at) + PathElement::new(vec![(0, -r), (0, r)], c.stroke_width(2));
    e.into_dyn()
}

/// A legend symbol centred at `(sx, ry)` (pixels of `area`).
fn symbol(area: &Area<'_>, sym: Sym, (sx, ry): (i32, i32)) -> DrawResult {
    match sym {
        Sym::Line(c, w) => area.draw(&PathElement::new(
            vec![(sx - 12, ry), (sx + 12, ry)],
            c.stroke_width(w),
        )),
        Sym::Dashed(c, w) => {
            for k in 0..3 {
                area.draw(&PathElement::new(
                    vec![(sx - 12 + 9 * k, ry), (sx - 7 + 9 * k, ry)],
                    c.stroke_width(w),
                ))?;
            }
            Ok(())
        }
        Sym::Dot(c) => area.draw(&dot((sx, ry), 4, c)),
        Sym::Hollow(c) => area.draw(&hollow((sx, ry), 4, c)),
        Sym::Tick(c) => area.draw(&tick((sx, ry), 8, c)),
        Sym::Diamond(c) => area.draw(&diamond((sx, ry), 6, c)),
        Sym::Band(c) => area.draw(&Rectangle::new(
            [(sx - 12, ry - 7), (sx + 12, ry + 7)],
            c.filled(),
        )),
        Sym::Ring(c) => area.draw(&ring((sx, ry), 6, c)),
    }
}

/// A legend in one row (wrapping to the next when the area is full).
pub fn legend_row(area: &Area<'_>, rows: &[(String, Sym)]) -> DrawResult {
    let width = area.dim_in_pixel().0 as i32;
    let (mut x, mut y) = (4, 14);
    for (label, sym) in rows {
        let step = 30 + 8 * label.chars().count() as i32 + 18;
        if x + step > width && x > 4 {
            x = 4;
            y += 24;
        }
        symbol(area, *sym, (x + 12, y))?;
        text(area, label, (x + 30, y - 8), &font(15.0, INK))?;
        x += step;
    }
    Ok(())
}

/// The legend panel: a framed box "Legend" with one row per entry, then the notes under it.
pub fn legend(area: &Area<'_>, rows: &[(String, Sym)], notes: &[String]) -> DrawResult {
    let (x, y) = (10, 10);
    let h = rows.len() as i32 * 24 + 36;
    let w = area.dim_in_pixel().0 as i32 - 20;
    area.draw(&Rectangle::new(
        [(x, y), (x + w, y + h)],
        RGBColor(0xfa, 0xfa, 0xfa).filled(),
    ))?;
    area.draw(&Rectangle::new(
        [(x, y), (x + w, y + h)],
        RGBColor(0xbb, 0xbb, 0xbb).stroke_width(1),
    ))?;
    text(area, "Legend", (x + 10, y + 8), &bold(15.5, INK))?;
    let mut ry = y + 42;
    for (label, sym) in rows {
        symbol(area, *sym, (x + 24, ry))?;
        text(area, label, (x + 46, ry - 8), &font(15.5, INK))?;
        ry += 24;
    }
    let mut ny = y + h + 10;
    for l in notes {
        text(area, l, (x, ny), &font(13.0, GREY_TEXT))?;
        ny += 16;
    }
    Ok(())
}

/// The ranges `x`, `y` widened about their centres so one unit is as long on both axes in a
/// plotting area of the given `aspect` (width / height).
pub fn equal_scale(x: (f64, f64), y: (f64, f64), aspect: f64) -> ((f64, f64), (f64, f64)) {
    let (w, h) = (x.1 - x.0, y.1 - y.0);
    if w / h < aspect {
        let grow = (aspect * h - w) / 2.0;
        ((x.0 - grow, x.1 + grow), y)
    } else {
        let grow = (w / aspect - h) / 2.0;
        (x, (y.0 - grow, y.1 + grow))
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
pub fn tick_label(x: f64, step: f64) -> String {
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
pub fn short(x: f64, decimals: usize) -> String {
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

/// An f64 axis over `[lo, hi]` with the given tick positions (from [`nice_ticks`], or any list)
/// as its key points, labelled by [`tick_label`] at `step`: `plotters`' own f64 axis picks its
/// ticks itself, which leaves no way to ask for degrees in steps of 30 or to keep a subnormal
/// range's ticks normal.
#[derive(Clone, Debug)]
pub struct Ticked {
    /// The axis range.
    pub range: (f64, f64),
    /// The key points (those inside the range are used).
    pub ticks: Vec<f64>,
    /// The step the labels are written for.
    pub step: f64,
}

impl Ticked {
    /// The axis over the ticks' span (the ticks of [`nice_ticks`] enclose the data).
    pub fn nice(lo: f64, hi: f64, target: usize) -> Ticked {
        let (ticks, step) = nice_ticks(lo, hi, target);
        let range = match (ticks.first(), ticks.last()) {
            (Some(&a), Some(&b)) => (a, b),
            _ => (lo, hi),
        };
        Ticked { range, ticks, step }
    }
}

impl Ranged for Ticked {
    type FormatOption = plotters::coord::ranged1d::NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let (lo, hi) = self.range;
        let f = (value - lo) / (hi - lo);
        let px = f64::from(limit.0) + f * f64::from(limit.1 - limit.0);
        // Far-off points (a curve through a pole) saturate instead of wrapping.
        px.round().clamp(-1e6, 1e6) as i32
    }

    fn key_points<H: plotters::coord::ranged1d::KeyPointHint>(&self, _hint: H) -> Vec<f64> {
        let (lo, hi) = self.range;
        let eps = (hi - lo) * 1e-9;
        self.ticks
            .iter()
            .copied()
            .filter(|t| *t >= lo - eps && *t <= hi + eps)
            .collect()
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.range.0..self.range.1
    }
}

impl plotters::coord::ranged1d::ValueFormatter<f64> for Ticked {
    fn format_ext(&self, value: &f64) -> String {
        tick_label(*value, self.step)
    }
}

/// An italic text style.
pub fn italic(size: f64, c: RGBColor) -> TextStyle<'static> {
    (FONT, size).into_font().style(FontStyle::Italic).color(&c)
}
