//! Spaeth's cylinder/sphere figures: the t-u diagram and the 3D view of one
//! configuration (a [`Scene`]: one of the paper's examples or a `cylinder_sphere` problem file).
//!
//! * The **t-u diagram** (the paper's Fig. 2 and 3, which the seeds do not contain): the branches
//!   `u1(t) <= u2(t)` of `u^2 + 2 A(t) u + B(t) = 0` over `t` in degrees, sampled densely in f64
//!   ([`runs`]) and broken where the discriminant is negative; the paper's 10-degree samples as
//!   dots (hollow where no real `u` exists); the real t-ranges (shaded), the ends of the real
//!   t-intervals (ticks) and the touching points (diamonds) from the **exact** analysis (root isolation
//!   on the tau-quartic, [`super::scene::exact_info`]). A `plotters` 2D chart with the axis ticks
//!   of [`nice_ticks`] (so a subnormal u-range still has a normal step).
//! * The **3D view**: a `plotters` 3D chart (`build_cartesian_3d`; world `z` is the chart's
//!   vertical axis) of the cylinder and sphere wireframes, the sphere's translucent disc and the
//!   intersection curve. `plotters` draws series in the order given and does no hidden-line
//!   removal, so the pieces are cut short and drawn back to front (painter's algorithm) by the
//!   depth of `plotters`' own projection matrix; lines on the far side of the cylinder or sphere
//!   are dashed, the curve's parts behind the sphere dashed in its colour.

use super::scene::*;
use super::style::*;
use exactcheck_core::cylinder_sphere::{rotate_x, rotate_y};
use exactcheck_core::Vec3;
use exactcheck_float::sampler::DiscSampler;
use plotters::coord::ranged3d::Cartesian3d;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::CoordTranslate;
use plotters::prelude::{
    ChartBuilder, Circle, Color, DashedLineSeries, EmptyElement, LineSeries, RGBColor, Rectangle,
    Text, TRANSPARENT,
};
use std::f64::consts::TAU;

/// Dense samples of the curves in the t-u diagram.
const TU_SAMPLES: usize = 2000;
/// Samples of the curve in the 3D view.
const VIEW_SAMPLES: usize = 1200;
/// Yaw and pitch of `plotters`' 3D projection (radians).
const YAW: f64 = 0.9;
const PITCH: f64 = -0.35;

/// The t-u diagram (the paper's Fig. 2 / 3).
pub(super) fn tu_diagram(scene: &Scene) -> String {
    let title = format!(
        "{}: t-u diagram{}",
        scene.name,
        scene
            .figure
            .map(|f| format!(" (the paper's {f})"))
            .unwrap_or_default()
    );
    let lines = subtitle_lines(scene, "", ["curves and dots", "exact markers"]);
    render((980, 620), &title, |root| {
        let body = header(root, &title, &lines)?;
        let (plot, side) = body.split_horizontally(730);
        let sampler = DiscSampler::new(&scene.float);
        let curves = runs(&sampler, TU_SAMPLES);
        // u-range: the sphere's extent along the axis (every curve point lies in it) and u = 0.
        let (lo, hi) = sphere_u_range(&scene.float);
        let uaxis = Ticked::nice(lo.min(0.0), hi.max(0.0), 6);
        let (umin, umax) = uaxis.range;
        let taxis = Ticked {
            range: (0.0, 360.0),
            ticks: (0..=12).map(|k| f64::from(k) * 30.0).collect(),
            step: 30.0,
        };
        let mut chart = ChartBuilder::on(&plot)
            .margin(12)
            .x_label_area_size(50)
            .y_label_area_size(86)
            .build_cartesian_2d(taxis, uaxis)?;
        // The real t-ranges (exact), under everything.
        if let Ok(e) = &scene.exact {
            let mut bands = Vec::new();
            if e.everywhere {
                bands.push((0.0, 360.0));
            }
            for &(s, t) in &e.arcs {
                if s <= t {
                    bands.push((s, t));
                } else {
                    bands.extend([(s, 360.0), (0.0, t)]);
                }
            }
            chart.draw_series(
                bands
                    .into_iter()
                    .map(|(a, b)| Rectangle::new([(a, umax), (b, umin)], BAND.filled())),
            )?;
        }
        chart
            .configure_mesh()
            .light_line_style(TRANSPARENT)
            .bold_line_style(RGBColor(0xe4, 0xe4, 0xe4))
            .x_label_formatter(&|t| format!("{t}°"))
            .x_desc("t (degrees)")
            .y_desc("u (along the cylinder axis)")
            .label_style(font(15.0, INK))
            .axis_desc_style(font(17.0, INK))
            .draw()?;
        chart.draw_series(LineSeries::new(
            [(0.0, 0.0), (360.0, 0.0)],
            RGBColor(0x77, 0x77, 0x77).stroke_width(1),
        ))?;
        // The branches.
        for run in &curves {
            for (branch, c) in [(1, BLUE), (2, ORANGE)] {
                chart.draw_series(LineSeries::new(
                    run.iter().map(|p| (p[0].to_degrees(), p[branch])),
                    c.stroke_width(2),
                ))?;
            }
        }
        if curves.is_empty() {
            chart.plotting_area().draw(
                &(EmptyElement::at((180.0, umax))
                    + Text::new(
                        "A(t)² − B(t) < 0 for every sampled t: no real u, no curve",
                        (0, 16),
                        italic(15.5, INK).pos(plotters::style::text_anchor::Pos::new(
                            plotters::style::text_anchor::HPos::Center,
                            plotters::style::text_anchor::VPos::Top,
                        )),
                    )),
            )?;
        }
        // The paper's 10-degree samples (under the exact markers).
        let mut sample_real = (0, 0);
        for k in 0..=36 {
            let t = k as f64 * 10.0;
            match sampler.roots(t.to_radians()) {
                Some((u1, u2)) => {
                    sample_real.0 += 1;
                    chart.plotting_area().draw(&dot((t, u1), 4, INK))?;
                    chart.plotting_area().draw(&dot((t, u2), 4, INK))?;
                }
                None => {
                    sample_real.1 += 1;
                    chart.plotting_area().draw(&hollow((t, 0.0), 4, INK))?;
                }
            }
        }
        // Exact ends of the real t-intervals and touching points, with staggered labels.
        let mid_u = |t_deg: f64| {
            let p = eval(&sampler, t_deg.to_radians());
            0.5 * (p[1] + p[2])
        };
        let mut labelled: Vec<i32> = Vec::new();
        let mut label = |t: f64, text: String| -> DrawResult {
            chart.draw_series(DashedLineSeries::new(
                [(t, umin), (t, umax)],
                2,
                3,
                GUIDE.stroke_width(1),
            ))?;
            let x = chart.backend_coord(&(t, umax)).0;
            let row = labelled.iter().filter(|&&o| (o - x).abs() < 48).count() as i32;
            labelled.push(x);
            chart.plotting_area().draw(
                &(EmptyElement::at((t, umax))
                    + Text::new(text, (4, 3 + 14 * row), font(13.0, INK))),
            )
        };
        if let Ok(e) = &scene.exact {
            for &(s, t) in &e.arcs {
                for end in [s, t] {
                    label(end, format!("{}°", short(end, 2)))?;
                }
            }
            for &t in &e.tangents {
                label(t, format!("{}° (touching)", short(t, 2)))?;
            }
            for &(s, t) in &e.arcs {
                for end in [s, t] {
                    chart
                        .plotting_area()
                        .draw(&tick((end, mid_u(end)), 9, INK))?;
                }
            }
            for &t in &e.tangents {
                chart
                    .plotting_area()
                    .draw(&diamond((t, mid_u(t)), 7, PURPLE))?;
            }
        }
        // The legend: the entries that occur.
        let mut rows: Vec<(String, Sym)> = Vec::new();
        if !curves.is_empty() {
            rows.push(("u1 = −A − √(A² − B)".into(), Sym::Line(BLUE, 2)));
            rows.push(("u2 = −A + √(A² − B)".into(), Sym::Line(ORANGE, 2)));
        }
        if sample_real.0 > 0 {
            rows.push(("10° sample: real u1, u2".into(), Sym::Dot(INK)));
        }
        if sample_real.1 > 0 {
            rows.push(("10° sample: not real".into(), Sym::Hollow(INK)));
        }
        let mut notes = vec![
            format!("curves: f64, {TU_SAMPLES} steps in t,"),
            "broken where A² − B < 0".to_string(),
        ];
        if let Ok(e) = &scene.exact {
            if e.everywhere || !e.arcs.is_empty() {
                rows.push(("A² − B ≥ 0 (exact)".into(), Sym::Band(BAND)));
            }
            if !e.arcs.is_empty() {
                rows.push(("end of a real t-interval".into(), Sym::Tick(INK)));
            }
            if !e.tangents.is_empty() {
                rows.push(("touching point".into(), Sym::Diamond(PURPLE)));
            }
            if e.everywhere || !e.arcs.is_empty() || !e.tangents.is_empty() {
                notes.push("shading, ends, touching points:".into());
                notes.push("exact (root isolation on the τ-quartic)".into());
            }
        }
        legend(&side, &rows, &notes)
    })
}

/// A piece of the 3D view: a short polyline (solid or dashed) or the sphere's disc.
enum Prim {
    Line {
        pts: Vec<Vec3<f64>>,
        color: RGBColor,
        dashed: bool,
        depth: f64,
    },
    Disc {
        centre: Vec3<f64>,
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

/// The chart's coordinates of a world point: world `z` is `plotters`' vertical `y`.
fn chart_xyz(p: &Vec3<f64>) -> (f64, f64, f64) {
    (p.x, p.z, p.y)
}

/// The unit vector pointing from the scene towards the viewer of a `plotters` 3D chart, in
/// world coordinates: minus the gradient of the projection's depth (its third row, through the
/// axes' pixel scales).
pub(super) fn toward_viewer(
    coord: &Cartesian3d<RangedCoordf64, RangedCoordf64, RangedCoordf64>,
    lo: (f64, f64, f64),
    hi: (f64, f64, f64),
) -> Vec3<f64> {
    let r = coord.projection().as_ref()[2];
    let a = coord.map_3d(&lo.0, &lo.1, &lo.2);
    let b = coord.map_3d(&hi.0, &hi.1, &hi.2);
    let s = |i: usize, d: f64, span: f64| r[i] * d / span;
    // Chart (X, Y, Z) = world (x, z, y).
    let gx = s(0, f64::from(b.0 - a.0), hi.0 - lo.0);
    let gz = s(1, f64::from(b.1 - a.1), hi.1 - lo.1);
    let gy = s(2, f64::from(b.2 - a.2), hi.2 - lo.2);
    let n = (gx * gx + gy * gy + gz * gz).sqrt();
    Vec3::new(-gx / n, -gy / n, -gz / n)
}

/// Adds a 3D polyline cut into short pieces (so the painter's order works along it) and where
/// its style (`style_of(index)`) changes.
fn add_polyline(
    prims: &mut Vec<Prim>,
    toward: &Vec3<f64>,
    pts: &[Vec3<f64>],
    style_of: impl Fn(usize) -> (RGBColor, bool),
) {
    const PIECE: usize = 16;
    let mut i = 0;
    while i + 1 < pts.len() {
        let style = style_of(i);
        let mut j = i + 1;
        while j + 1 < pts.len() && j - i < PIECE && style_of(j) == style {
            j += 1;
        }
        let piece = &pts[i..=j];
        let depth = -piece.iter().map(|p| p.dot(toward)).sum::<f64>() / piece.len() as f64;
        prims.push(Prim::Line {
            pts: piece.to_vec(),
            color: style.0,
            dashed: style.1,
            depth,
        });
        i = j;
    }
}

/// The 3D view.
pub(super) fn view_3d(scene: &Scene) -> String {
    let title = format!(
        "{}: cylinder, sphere and intersection curve (3D)",
        scene.name
    );
    let extra = "; plotters 3D chart, drawn back to front";
    let lines = subtitle_lines(scene, extra, ["curve", "exact analysis"]);
    render((980, 700), &title, |root| {
        let body = header(root, &title, &lines)?;
        let (plot, side) = body.split_horizontally(710);
        let cs = &scene.float;
        let centre = &cs.center;
        let big_r = cs.radius.abs();
        // The cylinder over a u-range covering the sphere.
        let (lo, hi) = sphere_u_range(cs);
        let margin = 0.35 * big_r.max(cs.r.abs());
        let (umin, umax) = (lo - margin, hi + margin);
        let rot = |v: Vec3<f64>| rotate_x(&cs.gamma, &rotate_y(&cs.beta, &v));
        let (e1, e2) = (rot(Vec3::new(1.0, 0.0, 0.0)), rot(Vec3::new(0.0, 1.0, 0.0)));
        let point = |t: f64, u: f64| cs.point(&t.cos(), &t.sin(), &u);
        // A cube around the scene (equal scales: the sphere stays round).
        let corners: Vec<Vec3<f64>> = [umin, umax]
            .iter()
            .flat_map(|&u| (0..8).map(move |k| (u, TAU * k as f64 / 8.0)))
            .map(|(u, t)| point(t, u))
            .chain([
                centre.add_scaled(&big_r, &Vec3::new(1.0, 1.0, 1.0)),
                centre.add_scaled(&-big_r, &Vec3::new(1.0, 1.0, 1.0)),
            ])
            .collect();
        let (lo3, hi3) = cube(&corners);
        let mut chart = chart_3d(&plot, 16, lo3, hi3, (YAW, PITCH, 0.8))?;
        let toward = toward_viewer(chart.as_coord_spec(), lo3, hi3);
        let mut prims: Vec<Prim> = Vec::new();
        let front = |t: f64| (e1.dot(&toward) * t.cos() + e2.dot(&toward) * t.sin()) > 0.0;
        let cyl = |t: f64| (if front(t) { WIRE } else { WIRE_BACK }, !front(t));
        for k in 0..=4 {
            let u = umin + (umax - umin) * k as f64 / 4.0;
            let ts: Vec<f64> = (0..=144).map(|i| TAU * i as f64 / 144.0).collect();
            let pts: Vec<Vec3<f64>> = ts.iter().map(|&t| point(t, u)).collect();
            add_polyline(&mut prims, &toward, &pts, |i| cyl(ts[i]));
        }
        for j in 0..16 {
            let t = TAU * j as f64 / 16.0;
            let pts: Vec<Vec3<f64>> = (0..=12)
                .map(|i| point(t, umin + (umax - umin) * i as f64 / 12.0))
                .collect();
            add_polyline(&mut prims, &toward, &pts, |_| cyl(t));
        }
        // The cylinder's silhouette rulings.
        let ts = (-e1.dot(&toward)).atan2(e2.dot(&toward));
        for t in [ts, ts + TAU / 2.0] {
            let pts: Vec<Vec3<f64>> = (0..=12)
                .map(|i| point(t, umin + (umax - umin) * i as f64 / 12.0))
                .collect();
            add_polyline(&mut prims, &toward, &pts, |_| (GREY_TEXT, false));
        }
        // The sphere: a translucent disc at the depth of its centre, latitudes and longitudes.
        prims.push(Prim::Disc {
            centre: centre.clone(),
            depth: -centre.dot(&toward),
        });
        let sph = |p: &Vec3<f64>| {
            if (p - centre).dot(&toward) >= 0.0 {
                (SPHERE, false)
            } else {
                (SPHERE_BACK, true)
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
            add_polyline(&mut prims, &toward, &pts, |i| sph(&pts[i]));
        }
        for k in 0..6 {
            let lon = (k as f64 * 30.0).to_radians();
            let pts: Vec<Vec3<f64>> = (0..=120)
                .map(|i| on_sphere(TAU * i as f64 / 120.0, lon))
                .collect();
            add_polyline(&mut prims, &toward, &pts, |i| sph(&pts[i]));
        }
        // The intersection curve, both branches; dashed behind the sphere.
        let sampler = DiscSampler::new(cs);
        let curves = runs(&sampler, VIEW_SAMPLES);
        let mut curve_points = 0;
        for run in &curves {
            for (branch, c) in [(1, BLUE), (2, ORANGE)] {
                let pts: Vec<Vec3<f64>> = run.iter().map(|p| point(p[0], p[branch])).collect();
                curve_points += pts.len();
                let visible = |i: usize| (&pts[i] - centre).dot(&toward) >= -1e-9 * big_r;
                add_polyline(&mut prims, &toward, &pts, |i| (c, !visible(i)));
            }
        }
        // Back to front.
        prims.sort_by(|a, b| b.depth().total_cmp(&a.depth()));
        let disc_radius = {
            let side = toward.cross(&Vec3::new(0.0, 0.0, 1.0));
            let side = if side.norm_squared() < 1e-12 {
                Vec3::new(1.0, 0.0, 0.0)
            } else {
                side.scale(&(1.0 / side.norm_squared().sqrt()))
            };
            let coord = chart.as_coord_spec();
            let a = coord.translate(&chart_xyz(centre));
            let b = coord.translate(&chart_xyz(&centre.add_scaled(&big_r, &side)));
            f64::from(a.0 - b.0).hypot(f64::from(a.1 - b.1)).round() as i32
        };
        for p in &prims {
            match p {
                Prim::Line {
                    pts, color, dashed, ..
                } => {
                    let xyz = pts.iter().map(chart_xyz);
                    if *dashed {
                        chart.draw_series(DashedLineSeries::new(
                            xyz,
                            4,
                            3,
                            color.stroke_width(if *color == BLUE || *color == ORANGE {
                                2
                            } else {
                                1
                            }),
                        ))?;
                    } else {
                        let w = if *color == BLUE || *color == ORANGE {
                            3
                        } else {
                            1
                        };
                        chart.draw_series(LineSeries::new(xyz, color.stroke_width(w)))?;
                    }
                }
                Prim::Disc { centre, .. } => {
                    chart.plotting_area().draw(&Circle::new(
                        chart_xyz(centre),
                        disc_radius,
                        SKY.mix(0.5).filled(),
                    ))?;
                }
            }
        }
        if curve_points == 0 {
            text(
                &plot,
                "no real point of the curve: the surfaces do not meet",
                (150, 6),
                &italic(15.5, INK),
            )?;
        }
        let mut rows: Vec<(String, Sym)> = vec![
            (
                format!("cylinder, r = {}", short(cs.r, 4)),
                Sym::Line(GREY_TEXT, 2),
            ),
            (format!("sphere, R = {}", short(big_r, 4)), Sym::Band(SKY)),
            ("back sides (dashed)".into(), Sym::Dashed(WIRE_BACK, 1)),
        ];
        if curve_points > 0 {
            rows.push(("branch u1 (−√)".into(), Sym::Line(BLUE, 3)));
            rows.push(("branch u2 (+√)".into(), Sym::Line(ORANGE, 3)));
            rows.push(("curve behind the sphere".into(), Sym::Dashed(BLUE, 2)));
        }
        let notes = [
            "drawn back to front (no hidden-line".to_string(),
            format!("removal); curve: f64, {VIEW_SAMPLES} steps in t,"),
            "broken where A² − B < 0".to_string(),
        ];
        legend(&side, &rows, &notes)
    })
}

/// The smallest axis-aligned cube around `pts`, padded by 4%: `(lo, hi)` in chart coordinates
/// (world `z` second).
pub(super) fn cube(pts: &[Vec3<f64>]) -> ((f64, f64, f64), (f64, f64, f64)) {
    let mut lo = [f64::MAX; 3];
    let mut hi = [f64::MIN; 3];
    for p in pts {
        for (i, v) in [p.x, p.z, p.y].into_iter().enumerate() {
            lo[i] = lo[i].min(v);
            hi[i] = hi[i].max(v);
        }
    }
    let half = (0..3)
        .map(|i| (hi[i] - lo[i]) / 2.0)
        .fold(f64::MIN_POSITIVE, f64::max)
        * 1.04;
    let c = |i: usize| lo[i] / 2.0 + hi[i] / 2.0;
    (
        (c(0) - half, c(1) - half, c(2) - half),
        (c(0) + half, c(1) + half, c(2) + half),
    )
}

/// The lines under a figure's title: the configuration, how the f64 and exact configurations
/// were taken, and the exact analysis in one line.
pub(super) fn subtitle_lines(scene: &Scene, extra: &str, what: [&str; 2]) -> Vec<String> {
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
