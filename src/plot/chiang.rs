//! `exactcheck plot chiang --example 4`: Chiang's Example 4 as a 3D figure — the ruled
//! surface patch `S(s,t) = B(t) + s V(t)`, the plane `z = 0` as a translucent rectangle, the
//! section curve and its control polygon with the weights as labels.
//!
//! # What is exact and what is f64
//! * The **section curve and its control polygon are exact**: the curve is Chiang's Theorem 1
//!   ([`RuledSurface::plane_section`]) over `Q(sqrt 2, sqrt 6)` ([`Radical`]), evaluated exactly
//!   at `t = k/96` and only then converted to f64 for drawing ([`Radical::to_f64`], a display
//!   approximation far finer than a pixel); the control points `r_k` are the exact quotients
//!   `(w_k r_k) / w_k`, and the weight labels print the exact radicals.
//! * The **surface patch** is drawn in f64 from the same generic data
//!   ([`surface_and_plane`] with `f64` square roots): rulings `t = k/10` and the curves
//!   `s = const` over `s` in `[0, 1.35 max s(t)]`, where `s(t) = -(N.B + d)/(N.V) =
//!   1/((1-t) sqrt 2 + t sqrt 6)` is the ruling parameter of the section, so the patch covers
//!   the section with room on both sides of the plane.
//!
//! # Drawing
//! A `plotters` 3D chart (`build_cartesian_3d`, world `z` as its vertical axis, one cube so the
//! scales are equal) seen from above the plane. `plotters` draws in the order given, with no
//! hidden-line removal, and none is needed here: the parts of the surface below the plane are
//! drawn first (lighter, dashed), then the translucent plane, then the parts above it, then the
//! curve and the control polygon, which lie in the plane. Surface polylines are split where
//! they cross `z = 0` (at the linearly interpolated crossing), so nothing needs a depth sort.

use super::spaeth::cube;
use super::style::*;
use crate::claims::chiang::surface_and_plane;
use crate::Error;
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::Vec3;
use exactcheck_exact::{Radical, Rational};
use plotters::coord::CoordTranslate;
use plotters::prelude::{Color, DashedLineSeries, EmptyElement, LineSeries, Polygon, Text};
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Yaw and pitch of `plotters`' 3D projection (radians): from above the plane.
const YAW: f64 = 0.6;
const PITCH: f64 = 0.45;
/// Samples of the exact curve (`t = k / CURVE_STEPS`).
const CURVE_STEPS: i64 = 96;

/// The exact data of the figure: the section's weights (as radicals), control points and
/// sampled curve (converted to f64 after the exact computation).
pub struct ExactSection {
    /// The weights `w_k`, exact.
    pub weights: Vec<Radical>,
    /// The control points `r_k`, exact (`None` where `w_k = 0`; never in Example 4).
    pub points: Vec<Option<Vec3<Radical>>>,
    /// The curve at `t = k / 96`, computed exactly, then converted to f64.
    pub curve: Vec<Vec3<f64>>,
}

fn to_f64(v: &Vec3<Radical>) -> Vec3<f64> {
    v.map(Radical::to_f64)
}

/// Example 4's section computed over `Q(sqrt 2, sqrt 6)`.
pub fn exact_section() -> ExactSection {
    let (surface, plane) = surface_and_plane(Radical::sqrt_of(2), Radical::sqrt_of(6));
    let curve = surface.plane_section(&plane);
    let samples = (0..=CURVE_STEPS)
        .map(|k| {
            let t = Radical::from(Rational::new(k, CURVE_STEPS).expect("CURVE_STEPS > 0"));
            let p = curve
                .eval(&t)
                .expect("Example 4's weight (1-t) sqrt 2 + t sqrt 6 is positive on [0, 1]");
            to_f64(&p)
        })
        .collect();
    ExactSection {
        weights: curve.weights(),
        points: curve.points(),
        curve: samples,
    }
}

/// Pushes the runs of `pts` on one side of `z = 0` to `below` / `above`, each run closed with
/// the interpolated crossing point.
fn split_at_plane(
    pts: &[Vec3<f64>],
    below: &mut Vec<Vec<Vec3<f64>>>,
    above: &mut Vec<Vec<Vec3<f64>>>,
) {
    let mut run: Vec<Vec3<f64>> = Vec::new();
    for (i, p) in pts.iter().enumerate() {
        if i > 0 {
            let q = &pts[i - 1];
            if (q.z < 0.0) != (p.z < 0.0) {
                let f = q.z / (q.z - p.z);
                let x = q.add_scaled(&f, &(p - q));
                run.push(x.clone());
                let done = std::mem::replace(&mut run, vec![x]);
                if q.z < 0.0 {
                    below.push(done);
                } else {
                    above.push(done);
                }
            }
        }
        run.push(p.clone());
    }
    if run.len() > 1 {
        if run.iter().all(|p| p.z <= 0.0) {
            below.push(run);
        } else {
            above.push(run);
        }
    }
}

/// The ruling parameter `s(t)` of the section (f64, for the patch's range).
fn section_s(surface: &RuledSurface<f64>, t: f64) -> f64 {
    let plane = exactcheck_core::ruled::Plane::z0();
    surface
        .section_parameter(&plane, &t)
        .expect("Example 4 has no ruling parallel to z = 0 for t in [0, 1]")
}

/// The SVG of `plot chiang --example n`.
///
/// # Errors
/// [`Error::Usage`] for an example other than 4 (the only one of Chiang's examples with data).
pub fn figure(example: Option<u32>) -> Result<String, Error> {
    match example {
        Some(4) => Ok(example4()),
        Some(n) => Err(Error::Usage(format!(
            "unknown example {n}: plot chiang draws Example 4 only (--example 4)"
        ))),
        None => Err(Error::Usage("plot chiang needs --example 4".into())),
    }
}

fn example4() -> String {
    let exact = exact_section();
    let (surface, _) = surface_and_plane(2f64.sqrt(), 6f64.sqrt());
    let title = "Chiang Example 4: ruled surface ∩ plane z = 0";
    let lines = [
        "S(s,t) = B(t) + s V(t); B: p0 = (0,0,−1), p1 = (1,1,−1), p2 = (0,2,−1); V: q0 = (−1,1,√2), q1 = (−1,−1,√6)".to_string(),
        "section: Chiang's Theorem 1, a rational cubic, computed exactly in Q(√2, √6); surface patch in f64".to_string(),
        "plotters 3D chart (z vertical); below the plane, the plane, above it, then the curve in it".to_string(),
    ];

    // The patch: t in [0, 1], s in [0, s_hi].
    let s_max = (0..=100)
        .map(|k| section_s(&surface, k as f64 / 100.0))
        .fold(0.0, f64::max);
    let s_hi = 1.35 * s_max;
    let (mut below, mut above) = (Vec::new(), Vec::new());
    let (mut edge_below, mut edge_above) = (Vec::new(), Vec::new());
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let pts: Vec<Vec3<f64>> = (0..=40)
            .map(|i| surface.eval(&(s_hi * i as f64 / 40.0), &t))
            .collect();
        if k == 0 || k == 10 {
            split_at_plane(&pts, &mut edge_below, &mut edge_above);
        } else {
            split_at_plane(&pts, &mut below, &mut above);
        }
    }
    for j in 0..=8 {
        let s = s_hi * j as f64 / 8.0;
        let pts: Vec<Vec3<f64>> = (0..=60)
            .map(|i| surface.eval(&s, &(i as f64 / 60.0)))
            .collect();
        if j == 0 || j == 8 {
            split_at_plane(&pts, &mut edge_below, &mut edge_above);
        } else {
            split_at_plane(&pts, &mut below, &mut above);
        }
    }
    // The plane: a rectangle around the patch's (and the polygon's) x-y extent.
    let control: Vec<Vec3<f64>> = exact
        .points
        .iter()
        .map(|p| {
            to_f64(
                p.as_ref()
                    .expect("Example 4's weights sqrt 2 .. sqrt 6 are all positive"),
            )
        })
        .collect();
    let all3: Vec<Vec3<f64>> = below
        .iter()
        .chain(&above)
        .chain(&edge_below)
        .chain(&edge_above)
        .flatten()
        .chain(&control)
        .cloned()
        .collect();
    let (mut xl, mut xh, mut yl, mut yh) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &all3 {
        xl = xl.min(p.x);
        xh = xh.max(p.x);
        yl = yl.min(p.y);
        yh = yh.max(p.y);
    }
    let m = 0.12 * (xh - xl).max(yh - yl);
    let rect = [
        Vec3::new(xl - m, yl - m, 0.0),
        Vec3::new(xh + m, yl - m, 0.0),
        Vec3::new(xh + m, yh + m, 0.0),
        Vec3::new(xl - m, yh + m, 0.0),
    ];
    let mut box_pts = all3.clone();
    box_pts.extend(rect.iter().cloned());
    let (lo, hi) = cube(&box_pts);

    render((1000, 720), title, |root| {
        let body = header(root, title, &lines)?;
        let (plot, side) = body.split_horizontally(700);
        let mut chart = chart_3d(&plot, 14, lo, hi, (YAW, PITCH, 0.85))?;
        let xyz = |p: &Vec3<f64>| (p.x, p.z, p.y);
        for r in &below {
            chart.draw_series(DashedLineSeries::new(
                r.iter().map(xyz),
                4,
                3,
                WIRE_BACK.stroke_width(1),
            ))?;
        }
        for r in &edge_below {
            chart.draw_series(DashedLineSeries::new(
                r.iter().map(xyz),
                4,
                3,
                GUIDE.stroke_width(2),
            ))?;
        }
        chart.draw_series(std::iter::once(Polygon::new(
            rect.iter().map(xyz).collect::<Vec<_>>(),
            SKY.mix(0.5).filled(),
        )))?;
        for r in &above {
            chart.draw_series(LineSeries::new(r.iter().map(xyz), WIRE.stroke_width(1)))?;
        }
        for r in &edge_above {
            chart.draw_series(LineSeries::new(r.iter().map(xyz), INK.stroke_width(2)))?;
        }
        chart.draw_series(LineSeries::new(
            control.iter().map(xyz),
            GREEN.stroke_width(1),
        ))?;
        chart.draw_series(LineSeries::new(
            exact.curve.iter().map(xyz),
            RED.stroke_width(3),
        ))?;
        // Labels pushed away from the polygon's centre (screen space), so they do not overlap it.
        let coord = chart.as_coord_spec();
        let cs: Vec<(i32, i32)> = control.iter().map(|p| coord.translate(&xyz(p))).collect();
        let n = cs.len() as f64;
        let (mx, my) = cs.iter().fold((0.0, 0.0), |(a, b), p| {
            (a + f64::from(p.0) / n, b + f64::from(p.1) / n)
        });
        for (k, ((p, (x, y)), wk)) in control.iter().zip(&cs).zip(&exact.weights).enumerate() {
            chart.plotting_area().draw(&dot(xyz(p), 5, GREEN))?;
            let (dx, dy) = (f64::from(*x) - mx, f64::from(*y) - my);
            let len = dx.hypot(dy).max(1e-9);
            let (lx, ly) = (18.0 * dx / len, 18.0 * dy / len);
            let anchor = if dx < 0.0 { HPos::Right } else { HPos::Left };
            let label = format!("r{k} (w{k} = {})", short(wk.to_f64(), 3));
            chart.plotting_area().draw(
                &(EmptyElement::at(xyz(p))
                    + Text::new(
                        label,
                        (lx.round() as i32, ly.round() as i32),
                        font(14.0, GREEN).pos(Pos::new(anchor, VPos::Center)),
                    )),
            )?;
        }

        // Legend and the exact values.
        let rows: Vec<(String, Sym)> = vec![
            ("surface above z = 0".into(), Sym::Line(WIRE, 1)),
            ("surface below z = 0".into(), Sym::Dashed(WIRE_BACK, 1)),
            ("plane z = 0".into(), Sym::Band(SKY)),
            ("section curve (exact)".into(), Sym::Line(RED, 3)),
            ("control polygon r0..r3".into(), Sym::Line(GREEN, 1)),
        ];
        let mut notes = vec!["exact control points r_k (decimals):".to_string()];
        for (k, p) in control.iter().enumerate() {
            notes.push(format!(
                "  r{k} = ({}, {}, {})",
                short(p.x, 4),
                short(p.y, 4),
                short(p.z, 4)
            ));
        }
        notes.push("weights w_k (exact, labels rounded):".to_string());
        for (k, wk) in exact.weights.iter().enumerate() {
            notes.push(format!("  w{k} = {wk} ≈ {}", short(wk.to_f64(), 4)));
        }
        notes.push(format!("patch: t in [0, 1], s in [0, {}]", short(s_hi, 3)));
        notes.push(format!(
            "rulings t = k/10; curve: {} exact samples",
            CURVE_STEPS + 1
        ));
        legend(&side, &rows, &notes)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::{Field, Ring};

    #[test]
    fn the_exact_section_is_in_the_plane_and_on_the_surface() {
        let e = exact_section();
        assert_eq!(e.weights.len(), 4);
        assert_eq!(e.weights[0], Radical::sqrt_of(2));
        assert_eq!(e.weights[3], Radical::sqrt_of(6));
        // The control points lie in z = 0 exactly.
        for p in &e.points {
            assert!(p.as_ref().unwrap().z.is_zero());
        }
        // The sampled curve: z = 0 and on the surface at s(t).
        let (surface, _) = surface_and_plane(2f64.sqrt(), 6f64.sqrt());
        for (k, p) in e.curve.iter().enumerate() {
            let t = k as f64 / CURVE_STEPS as f64;
            assert!(p.z.abs() < 1e-12);
            let q = surface.eval(&section_s(&surface, t), &t);
            assert!((p - &q).norm_squared() < 1e-20, "t = {t}: {p:?} vs {q:?}");
        }
        let w1 = (Radical::sqrt_of(2).mul_ref(&Radical::from(2)) + Radical::sqrt_of(6))
            .checked_div(&Radical::from(3))
            .unwrap();
        assert_eq!(e.weights[1], w1);
    }

    #[test]
    fn split_at_plane_closes_runs_on_the_plane() {
        let pts = vec![
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(1.0, 0.0, 1.0),
            Vec3::new(2.0, 0.0, 3.0),
        ];
        let (mut b, mut a) = (Vec::new(), Vec::new());
        split_at_plane(&pts, &mut b, &mut a);
        assert_eq!(b, vec![vec![pts[0].clone(), Vec3::new(0.5, 0.0, 0.0)]]);
        assert_eq!(
            a,
            vec![vec![
                Vec3::new(0.5, 0.0, 0.0),
                pts[1].clone(),
                pts[2].clone()
            ]]
        );
    }

    #[test]
    fn other_examples_are_usage_errors() {
        assert!(figure(Some(4)).unwrap().starts_with("<svg"));
        let e = figure(Some(3)).unwrap_err().to_string();
        assert!(
            e.contains("unknown example 3") && e.contains("--example 4"),
            "{e}"
        );
        assert!(matches!(figure(None), Err(Error::Usage(_))));
    }
}
