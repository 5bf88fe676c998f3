//! `exactcheck plot ph` (Chiang's worked PH example, SPEC §4) and `exactcheck plot FILE.json` for
//! a `ph_offset` problem: the PH curve, its control polygon, its offsets at the problem's
//! distances, and the offsets' cusps, in one planar figure.
//!
//! # What is exact and what is f64
//! Everything is computed over the rationals and only converted to f64 for drawing:
//! * the base curve is the exact Bezier curve of [`PhCurve::base`], evaluated exactly at
//!   `t = k / 192`;
//! * each offset is the exact rational Bezier curve of [`PhCurve::offset`] (Chiang's section
//!   of `B(t) + s V(t)` by `z = r`, projected to the plane), evaluated exactly at the same
//!   parameters (parameters where a weight polynomial vanishes, on a singular base, are skipped
//!   and break the line);
//! * the cusps are the exact zeros of `sigma^2 - 2 r w` isolated by [`PhCurve::offset_cusps`],
//!   drawn at the offset point of the isolating interval's midpoint (interval widths are below
//!   `2^-50` after refinement), one marker per cusp; the legend gives their parameters.
//!
//! The plot is written with the house SVG writer ([`Svg`]) and nice ticks on both axes at one
//! common scale (a circle stays a circle).

use super::figure::{circle, header, legend, Sym};
use super::svg::{nice_ticks, short, tick_label, Points, Svg, N};
use crate::Error;
use exactcheck_core::ph::{chiang_example, PhCurve};
use exactcheck_core::roots::{refine, IsolatedRoot};
use exactcheck_core::Vec3;
use exactcheck_exact::Rational;

/// Samples per curve (`t = k / STEPS`).
const STEPS: i64 = 192;

const STYLE: &str = "
.base{fill:none;stroke:#111;stroke-width:2.6;stroke-linejoin:round}
.cpoly{fill:none;stroke:#1b5e20;stroke-width:1.3;stroke-dasharray:6 4}
.cpt{fill:#1b5e20;stroke:#fff;stroke-width:1}
.clabel{font-size:12px;fill:#1b5e20}
.off0{fill:none;stroke:#1f5fbf;stroke-width:2;stroke-linejoin:round}
.off1{fill:none;stroke:#e0620d;stroke-width:2;stroke-linejoin:round}
.off2{fill:none;stroke:#8e24aa;stroke-width:2;stroke-linejoin:round}
.off3{fill:none;stroke:#00897b;stroke-width:2;stroke-linejoin:round}
.off4{fill:none;stroke:#c62828;stroke-width:2;stroke-linejoin:round}
.off5{fill:none;stroke:#6d4c41;stroke-width:2;stroke-linejoin:round}
.olabel{font-size:12.5px;fill:#333}
.cusp{fill:#d50000;stroke:#fff;stroke-width:1.2}
";

/// The classes of the offsets, cycled.
const OFFSET_CLASSES: [&str; 6] = ["off0", "off1", "off2", "off3", "off4", "off5"];

/// The SVG of `plot ph`.
///
/// # Errors
/// [`Error::Usage`] when an example number is given (there is one PH example).
pub fn figure(example: Option<u32>) -> Result<String, Error> {
    if let Some(n) = example {
        return Err(Error::Usage(format!(
            "plot ph draws Chiang's one worked PH example and takes no --example (got {n})"
        )));
    }
    let radii = ["3", "63/5", "15"]
        .iter()
        .map(|s| s.parse().expect("a rational literal"))
        .collect::<Vec<Rational>>();
    Ok(draw(
        "Chiang's PH example: offsets at r = 3, 12.6, 15",
        &[
            "u = (10, −1), v = (1, 10) in Bernstein form, p0 = (0, 0): a PH cubic; offsets: rational Bezier quintics (z = r sections of B(t) + s V(t))".to_string(),
            "all curves evaluated exactly over Q at t = k/192, then drawn; cusps = exact zeros of σ² − 2 r w (r = 12.6 = 63/5 < ρ_min = 101/8: no cusp)".to_string(),
        ],
        &chiang_example::<Rational>(),
        &radii,
    ))
}

/// The SVG of `plot FILE.json` for a `ph_offset` problem, or `None` when the file holds another
/// kind.
///
/// # Errors
/// [`Error::Io`] for an unreadable file; [`Error::Input`] (prefixed with the path) for what
/// `solve` refuses and for irrational numbers.
pub fn file_figure(path: &str) -> Result<Option<(String, String)>, Error> {
    let text = crate::solve::read_problem(Some(path))?;
    let in_file = |e: Error| Error::Input(format!("{path}: {e}"));
    if crate::solve::problem_kind(&text).map_err(in_file)? != "ph_offset" {
        return Ok(None);
    }
    let (curve, radii) = crate::solve::ph_offset::rational_problem(&text).map_err(in_file)?;
    let name = std::path::Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |f| f.to_string_lossy().into_owned());
    let u: Vec<String> = curve.u().coeffs().iter().map(ToString::to_string).collect();
    let v: Vec<String> = curve.v().coeffs().iter().map(ToString::to_string).collect();
    let title = format!("PH curve and offsets: {name}");
    let lines = [
        format!(
            "u = ({}), v = ({}) in Bernstein form, p0 = ({}, {}): a PH curve of degree {}",
            u.join(", "),
            v.join(", "),
            curve.start().x,
            curve.start().y,
            curve.degree()
        ),
        "all curves evaluated exactly over Q at t = k/192, then drawn; cusps = exact zeros of σ² − 2 r w".to_string(),
    ];
    let svg = draw(&title, &lines, &curve, &radii);
    Ok(Some((svg, format!("PH curve and offsets of {name}"))))
}

fn xy(p: &Vec3<Rational>) -> (f64, f64) {
    (p.x.to_f64(), p.y.to_f64())
}

fn param(k: i64) -> Rational {
    Rational::new(k, STEPS).expect("STEPS > 0")
}

/// One offset of the figure: `r`, its runs of samples (broken at poles), its cusps (isolated
/// parameter, point).
pub type OffsetDrawing = (
    Rational,
    Vec<Vec<(f64, f64)>>,
    Vec<(IsolatedRoot<Rational>, (f64, f64))>,
);

/// The exact data of the figure, converted to f64 after the exact computation.
pub struct Drawing {
    /// The base curve at `t = k / STEPS`.
    pub base: Vec<(f64, f64)>,
    /// The control points.
    pub control: Vec<(f64, f64)>,
    /// Per distance: `r`, the offset's runs of samples (broken at poles), its cusps
    /// (parameter, point).
    pub offsets: Vec<OffsetDrawing>,
    /// Whether the speed vanishes in `[0, 1]` (then no cusps are computed).
    pub singular: bool,
}

/// Computes the figure's curves exactly (module doc).
pub fn drawing(curve: &PhCurve<Rational>, radii: &[Rational]) -> Drawing {
    let base_curve = curve.base();
    let base = (0..=STEPS)
        .map(|k| xy(&base_curve.eval(&param(k))))
        .collect();
    let control = base_curve.control_points().iter().map(xy).collect();
    let singular = !curve.speed_zeros().is_empty();
    let width = Rational::new(1, 1 << 50).expect("a power of two");
    let offsets = radii
        .iter()
        .map(|r| {
            let off = curve.offset(r);
            let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for k in 0..=STEPS {
                match off.eval(&param(k)) {
                    Ok(p) => runs.last_mut().expect("one run at least").push(xy(&p)),
                    Err(_) => runs.push(Vec::new()),
                }
            }
            runs.retain(|r| r.len() > 1);
            let cusps = if singular {
                Vec::new()
            } else {
                let f = curve.cusp_polynomial(r);
                curve
                    .offset_cusps(r)
                    .expect("the speed has no zero in [0, 1]")
                    .into_iter()
                    .map(|c| {
                        let t = refine(&f, &c.t, &width);
                        let p = off
                            .eval(&t.midpoint())
                            .expect("the weight sigma has no zero on a regular base");
                        (t, xy(&p))
                    })
                    .collect()
            };
            (r.clone(), runs, cusps)
        })
        .collect();
    Drawing {
        base,
        control,
        offsets,
        singular,
    }
}

fn draw(title: &str, lines: &[String], curve: &PhCurve<Rational>, radii: &[Rational]) -> String {
    let d = drawing(curve, radii);
    let (width, height) = (1060.0, 760.0);
    let mut svg = Svg::new(width, height, title);
    let top = header(&mut svg, title, lines) + 6.0;
    svg.open("style", &[]);
    svg.buf.push_str(STYLE);
    svg.close();
    // The plot area and one common scale.
    let (x0, y0) = (70.0, top);
    let (w, h) = (700.0, height - top - 50.0);
    let all = d
        .base
        .iter()
        .chain(&d.control)
        .chain(d.offsets.iter().flat_map(|o| o.1.iter().flatten()));
    let (mut xl, mut xh, mut yl, mut yh) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in all {
        xl = xl.min(x);
        xh = xh.max(x);
        yl = yl.min(y);
        yh = yh.max(y);
    }
    let (xt, xs) = nice_ticks(xl, xh, 7);
    let (yt, ys) = nice_ticks(yl, yh, 7);
    let (xl, xh) = (xl.min(xt[0]), xh.max(*xt.last().expect("ticks")));
    let (yl, yh) = (yl.min(yt[0]), yh.max(*yt.last().expect("ticks")));
    let scale = (w / (xh - xl)).min(h / (yh - yl));
    let sx = |x: f64| x0 + (x - xl) * scale;
    let sy = |y: f64| y0 + h - (y - yl) * scale;
    let screen = |&(x, y): &(f64, f64)| (sx(x), sy(y));
    // Frame, grid and ticks.
    let (fx1, fy0) = (sx(xh), sy(yh));
    for &t in &xt {
        svg.line((sx(t), fy0), (sx(t), sy(yl)), &[("class", &"grid")]);
        svg.text(
            sx(t),
            sy(yl) + 18.0,
            &tick_label(t, xs),
            &[("class", &"tick"), ("text-anchor", &"middle")],
        );
    }
    for &t in &yt {
        svg.line((sx(xl), sy(t)), (fx1, sy(t)), &[("class", &"grid")]);
        svg.text(
            sx(xl) - 8.0,
            sy(t) + 4.0,
            &tick_label(t, ys),
            &[("class", &"tick"), ("text-anchor", &"end")],
        );
    }
    svg.leaf(
        "rect",
        &[
            ("class", &"frame"),
            ("x", &N(sx(xl))),
            ("y", &N(fy0)),
            ("width", &N(fx1 - sx(xl))),
            ("height", &N(sy(yl) - fy0)),
        ],
    );
    svg.text(
        (sx(xl) + fx1) / 2.0,
        sy(yl) + 38.0,
        "x",
        &[("class", &"axlabel"), ("text-anchor", &"middle")],
    );
    svg.text(
        sx(xl) - 48.0,
        (fy0 + sy(yl)) / 2.0,
        "y",
        &[("class", &"axlabel")],
    );
    // Offsets, then the control polygon and the curve on top, then the cusps.
    let mut rows: Vec<(String, Sym)> = vec![
        ("PH curve B(t) (exact)".into(), Sym::Line("base")),
        ("control polygon".into(), Sym::Line("cpoly")),
    ];
    for (i, (r, runs, _)) in d.offsets.iter().enumerate() {
        let class = OFFSET_CLASSES[i % OFFSET_CLASSES.len()];
        for run in runs {
            let s: Vec<(f64, f64)> = run.iter().map(screen).collect();
            svg.leaf("polyline", &[("class", &class), ("points", &Points(&s))]);
        }
        if let Some(&(x, y)) = runs.last().and_then(|r| r.last()) {
            svg.text(
                sx(x) + 6.0,
                sy(y) - 6.0,
                &format!("r = {}", short(r.to_f64(), 4)),
                &[("class", &"olabel")],
            );
        }
        rows.push((
            format!("offset r = {r} (≈ {})", short(r.to_f64(), 4)),
            Sym::Line(class),
        ));
    }
    let cs: Vec<(f64, f64)> = d.control.iter().map(screen).collect();
    svg.leaf("polyline", &[("class", &"cpoly"), ("points", &Points(&cs))]);
    let bs: Vec<(f64, f64)> = d.base.iter().map(screen).collect();
    svg.leaf("polyline", &[("class", &"base"), ("points", &Points(&bs))]);
    for (k, (x, y)) in cs.iter().enumerate() {
        circle(&mut svg, *x, *y, 4.2, "cpt");
        svg.text(x + 7.0, y - 7.0, &format!("p{k}"), &[("class", &"clabel")]);
    }
    let mut notes = vec!["control points (exact):".to_string()];
    for (k, p) in curve.base().control_points().iter().enumerate() {
        notes.push(format!("  p{k} = ({}, {})", p.x, p.y));
    }
    let mut cusp_count = 0;
    for (r, _, cusps) in &d.offsets {
        for (t, (x, y)) in cusps {
            circle(&mut svg, sx(*x), sy(*y), 5.5, "cusp");
            cusp_count += 1;
            let at = match t.exact() {
                Some(t) => format!("t = {t}"),
                None => format!("t ≈ {}", short(t.midpoint().to_f64(), 6)),
            };
            notes.push(format!("cusp of r = {r}: {at}"));
        }
    }
    if d.singular {
        notes.push("the speed vanishes in [0, 1]: singular base, no cusps computed".into());
    } else {
        notes.push(format!("{cusp_count} cusp(s) in all, counted exactly"));
    }
    rows.push(("cusp (exact parameter)".into(), Sym::Dot("cusp")));
    legend(&mut svg, x0 + w + 60.0, y0 + 10.0, &rows, &notes);
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chiang_drawing_has_two_cusps_at_r_15() {
        let radii: Vec<Rational> = ["3", "63/5", "15"]
            .iter()
            .map(|s| s.parse().unwrap())
            .collect();
        let d = drawing(&chiang_example::<Rational>(), &radii);
        let counts: Vec<usize> = d.offsets.iter().map(|o| o.2.len()).collect();
        assert_eq!(counts, vec![0, 0, 2]);
        assert_eq!(d.base.len(), STEPS as usize + 1);
        assert_eq!(
            d.control,
            vec![
                (0.0, 0.0),
                (33.0, 20.0 / 3.0),
                (79.0 / 3.0, 119.0 / 3.0),
                (-20.0 / 3.0, 33.0)
            ]
        );
        // The offset samples are at distance r from the base samples (f64 after exact).
        for (r, runs, _) in &d.offsets {
            for (b, o) in d.base.iter().zip(&runs[0]) {
                let dist = (b.0 - o.0).hypot(b.1 - o.1);
                assert!((dist - r.to_f64()).abs() < 1e-9);
            }
        }
        assert!(figure(Some(1)).is_err());
    }
}
