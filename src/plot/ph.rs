//! `exactcheck plot ph` (Chiang's worked PH example) and `exactcheck plot FILE.json` for
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
//! The plot is a `plotters` 2D chart with nice ticks ([`nice_ticks`]) on both axes at one common
//! scale (a circle stays a circle: the ranges are widened to the plotting area's aspect).

use super::style::*;
use crate::claims::chiang_ph::example_curve;
use crate::Error;
use exactcheck_core::ph::PhCurve;
use exactcheck_core::roots::{refine, IsolatedRoot};
use exactcheck_core::Vec3;
use exactcheck_exact::Rational;
use plotters::prelude::{
    ChartBuilder, Color, EmptyElement, LineSeries, RGBColor, Text, TRANSPARENT,
};

/// Samples per curve (`t = k / STEPS`).
const STEPS: i64 = 192;

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
        &example_curve(),
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
    let (xaxis, yaxis) = (Ticked::nice(xl, xh, 7), Ticked::nice(yl, yh, 7));
    render((1060, 780), title, |root| {
        let body = header(root, title, lines)?;
        let (plot, side) = body.split_horizontally(760);
        // One common scale (a circle stays a circle): the tick ranges widened to the plotting
        // area's aspect.
        let (margin, xlab, ylab) = (12, 44, 60);
        let (pw, ph) = plot.dim_in_pixel();
        let aspect = f64::from(pw - 2 * margin - ylab) / f64::from(ph - 2 * margin - xlab);
        let (xr, yr) = equal_scale(xaxis.range, yaxis.range, aspect);
        let mut chart = ChartBuilder::on(&plot)
            .margin(margin)
            .x_label_area_size(xlab)
            .y_label_area_size(ylab)
            .build_cartesian_2d(
                Ticked {
                    range: xr,
                    ..xaxis.clone()
                },
                Ticked {
                    range: yr,
                    ..yaxis.clone()
                },
            )?;
        chart
            .configure_mesh()
            .light_line_style(TRANSPARENT)
            .bold_line_style(RGBColor(0xe4, 0xe4, 0xe4))
            .x_desc("x")
            .y_desc("y")
            .label_style(font(15.0, INK))
            .axis_desc_style(font(17.0, INK))
            .draw()?;
        // Offsets, then the control polygon and the curve on top, then the cusps.
        let mut rows: Vec<(String, Sym)> = vec![
            ("PH curve B(t) (exact)".into(), Sym::Line(INK, 3)),
            ("control polygon".into(), Sym::Line(GREEN, 1)),
        ];
        for (i, (r, runs, _)) in d.offsets.iter().enumerate() {
            let c = OFFSETS[i % OFFSETS.len()];
            for run in runs {
                chart.draw_series(LineSeries::new(run.iter().copied(), c.stroke_width(2)))?;
            }
            if let Some(&end) = runs.last().and_then(|r| r.last()) {
                chart.plotting_area().draw(
                    &(EmptyElement::at(end)
                        + Text::new(
                            format!("r = {}", short(r.to_f64(), 4)),
                            (6, -20),
                            font(15.0, INK),
                        )),
                )?;
            }
            rows.push((
                format!("offset r = {r} (≈ {})", short(r.to_f64(), 4)),
                Sym::Line(c, 2),
            ));
        }
        chart.draw_series(LineSeries::new(
            d.control.iter().copied(),
            GREEN.stroke_width(1),
        ))?;
        chart.draw_series(LineSeries::new(d.base.iter().copied(), INK.stroke_width(3)))?;
        for (k, p) in d.control.iter().enumerate() {
            chart.plotting_area().draw(&dot(*p, 5, GREEN))?;
            chart.plotting_area().draw(
                &(EmptyElement::at(*p) + Text::new(format!("p{k}"), (7, -22), font(14.0, GREEN))),
            )?;
        }
        let mut notes = vec!["control points (exact):".to_string()];
        for (k, p) in curve.base().control_points().iter().enumerate() {
            notes.push(format!("  p{k} = ({}, {})", p.x, p.y));
        }
        let mut cusp_count = 0;
        for (r, _, cusps) in &d.offsets {
            for (t, p) in cusps {
                chart.plotting_area().draw(&dot(*p, 6, CUSP))?;
                cusp_count += 1;
                let at = match t.exact() {
                    Some(t) => format!("t = {t}"),
                    None => format!("t ≈ {}", short(t.midpoint().to_f64(), 6)),
                };
                notes.push(format!("cusp of r = {r}: {at}"));
            }
        }
        if d.singular {
            notes.push("the speed vanishes in [0, 1]: singular base,".into());
            notes.push("no cusps computed".into());
        } else {
            notes.push(format!("{cusp_count} cusp(s) in all, counted exactly"));
        }
        rows.push(("cusp (exact parameter)".into(), Sym::Dot(CUSP)));
        legend(&side, &rows, &notes)
    })
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
        let d = drawing(&example_curve(), &radii);
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
