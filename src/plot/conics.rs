//! `exactcheck plot conics`: the four sections of the cone `x^2 + y^2 = z^2` of Chiang's
//! Table 1, one panel each; `exactcheck plot FILE.json` draws one `conic` problem the
//! same way.
//!
//! # What is exact and what is f64
//! The sections are computed exactly ([`crate::solve::conic`], the code behind `solve conic`,
//! over `Q(sqrt 2, ...)`): the weights, the homogeneous control vectors, the poles (isolated
//! exactly) and the type decided by the angle rule and by the weights. Only then are the
//! homogeneous control vectors converted to f64 and the rational quadratic
//! `X(t) / W(t) = sum B_k(t) w_k r_k / sum B_k(t) w_k` evaluated for drawing, at 601 uniform
//! parameters plus parameters approaching each pole geometrically (`t0 +- 10^-j`), so the curve
//! reaches the panel's edge.
//!
//! # The panel
//! Each section is drawn in its plane's own orthonormal coordinates: origin the foot of the
//! perpendicular from the apex, `u` the horizontal direction `z x N` (or the x axis for a
//! horizontal plane), `v = N x u` (upwards in the plane), equal scale on both axes. Both cone
//! pieces in two colours (`V+` the quarter, `V-` the three-quarter cone), each with its control
//! polygon (a point at infinity, `w_k = 0`, becomes the ray towards its direction) and its
//! finite control points. The curve is broken where the weight changes sign (a pole: the curve
//! passes through infinity) and clipped to the panel. Every pole is marked: a simple pole
//! (hyperbola) by its asymptote `X'(t0)/W'(t0) + s X(t0)` and a marker where the asymptote leaves
//! the panel in the direction `X(t0)`; a double pole (parabola) by an arrow from the
//! centroid of the piece's finite control points in the direction in which the curve escapes,
//! `sign(W near t0) X(t0)`.
//!
//! Each panel is a `plotters` 2D chart on its own area (a grid of areas under the caption, the
//! legend row under them), its ranges chosen so both axes have one scale. The curves, control
//! polygons and asymptotes are clipped to the panel here (Liang–Barsky, a dozen lines rather
//! than a geometry dependency): `plotters`' SVG backend writes every point it is given, and a
//! curve through a pole has points far outside.

use super::style::*;
use crate::claims::chiang_conic::table1_planes;
use crate::solve::conic::{compute, exact_section, Computed};
use crate::Error;
use exactcheck_core::conic::SectionType;
use exactcheck_core::Vec3;
use exactcheck_exact::{Radical, Rational};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::{
    Cartesian2d, ChartBuilder, ChartContext, Color, EmptyElement, LineSeries, RGBColor, Rectangle,
    SVGBackend, ShapeStyle, Text,
};

/// The panels' frames (the tests find the panels by it).
pub const FRAME: RGBColor = RGBColor(0x88, 0x88, 0x88);

/// Panel size in the four-panel figure, and the gap between panels.
const PANEL_W: u32 = 470;
const PANEL_H: u32 = 420;
/// Panel size of a one-panel figure.
const SINGLE_W: u32 = 920;
const SINGLE_H: u32 = 640;
const GAP: u32 = 20;
/// Uniform samples per piece.
const SAMPLES: usize = 600;

/// One section in f64, ready to draw.
struct PanelData {
    title: String,
    sub: [String; 2],
    /// Per piece: weights, weighted points (3D), pole parameters with multiplicity.
    pieces: [PieceF; 2],
    /// Plane frame: origin, u, v.
    frame: [[f64; 3]; 3],
}

struct PieceF {
    w: [f64; 3],
    wp: [[f64; 3]; 3],
    poles: Vec<(f64, usize)>,
}

fn f(x: &Radical) -> f64 {
    x.to_f64()
}

fn dot3(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = dot3(&a, &a).sqrt();
    [a[0] / n, a[1] / n, a[2] / n]
}

fn vec_f(v: &Vec3<Radical>) -> [f64; 3] {
    [f(&v.x), f(&v.y), f(&v.z)]
}

/// The f64 drawing data of an exactly computed section.
fn panel_data(c: &Computed<Radical>, title: String, sub: [String; 2]) -> PanelData {
    let n = vec_f(&c.plane.normal);
    let d = f(&c.plane.d);
    let nn = dot3(&n, &n);
    let origin = [-d * n[0] / nn, -d * n[1] / nn, -d * n[2] / nn];
    let horizontal =
        c.plane.normal.x == Radical::default() && c.plane.normal.y == Radical::default();
    let u = if horizontal {
        [1.0, 0.0, 0.0]
    } else {
        unit([-n[1], n[0], 0.0])
    };
    let v = cross(&unit(n), &u);
    let piece = |k: usize| {
        let p = &c.pieces[k];
        let ctrl = p.curve.control();
        let w = [f(&ctrl[0].0[0]), f(&ctrl[1].0[0]), f(&ctrl[2].0[0])];
        let wp = [0, 1, 2].map(|i| [f(&ctrl[i].0[1]), f(&ctrl[i].0[2]), f(&ctrl[i].0[3])]);
        let poles = p
            .poles
            .iter()
            .map(|q| {
                (
                    q.zero.midpoint().to_f64(),
                    q.multiplicity.expect("exact mode gives multiplicities"),
                )
            })
            .collect();
        PieceF { w, wp, poles }
    };
    PanelData {
        title,
        sub,
        pieces: [piece(0), piece(1)],
        frame: [origin, u, v],
    }
}

impl PanelData {
    /// Plane coordinates of a 3D point.
    fn to2(&self, p: &[f64; 3]) -> (f64, f64) {
        let q = [
            p[0] - self.frame[0][0],
            p[1] - self.frame[0][1],
            p[2] - self.frame[0][2],
        ];
        (dot3(&q, &self.frame[1]), dot3(&q, &self.frame[2]))
    }

    /// Plane coordinates of a 3D direction.
    fn dir2(&self, p: &[f64; 3]) -> (f64, f64) {
        (dot3(p, &self.frame[1]), dot3(p, &self.frame[2]))
    }
}

impl PieceF {
    /// `(W(t), X(t))` and the derivatives `(W'(t), X'(t))`.
    fn hom(&self, t: f64) -> (f64, [f64; 3], f64, [f64; 3]) {
        let b = [(1.0 - t) * (1.0 - t), 2.0 * t * (1.0 - t), t * t];
        let db = [-2.0 * (1.0 - t), 2.0 - 4.0 * t, 2.0 * t];
        let comb = |c: &[f64; 3], x: &dyn Fn(usize) -> f64| c[0] * x(0) + c[1] * x(1) + c[2] * x(2);
        let w = comb(&b, &|k| self.w[k]);
        let dw = comb(&db, &|k| self.w[k]);
        let x = [0, 1, 2].map(|a| comb(&b, &|k| self.wp[k][a]));
        let dx = [0, 1, 2].map(|a| comb(&db, &|k| self.wp[k][a]));
        (w, x, dw, dx)
    }

    /// The sample parameters: uniform, plus geometric approaches to each pole.
    fn params(&self) -> Vec<f64> {
        let mut ts: Vec<f64> = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64).collect();
        for &(t0, _) in &self.poles {
            for j in 2..=12 {
                let h = 10f64.powi(-j);
                ts.extend([t0 - h, t0 + h, t0 - 3.0 * h, t0 + 3.0 * h]);
            }
        }
        ts.retain(|t| (0.0..=1.0).contains(t));
        ts.sort_by(f64::total_cmp);
        ts.dedup();
        ts
    }
}

/// The axis-aligned view box in plane coordinates: `(xmin, xmax, ymin, ymax)`.
type Box2 = (f64, f64, f64, f64);

/// The part of the segment `a b` inside the box (Liang–Barsky), if any.
fn clip(a: (f64, f64), b: (f64, f64), bx: Box2) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - bx.0),
        (dx, bx.1 - a.0),
        (-dy, a.1 - bx.2),
        (dy, bx.3 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

/// Runs of a polyline clipped to the box.
fn clip_polyline(pts: &[(f64, f64)], bx: Box2) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for w in pts.windows(2) {
        match clip(w[0], w[1], bx) {
            Some((p, q)) => {
                if run.last() != Some(&p) {
                    if run.len() > 1 {
                        runs.push(std::mem::take(&mut run));
                    }
                    run.clear();
                    run.push(p);
                }
                run.push(q);
                if q != w[1] {
                    runs.push(std::mem::take(&mut run));
                }
            }
            None => {
                if run.len() > 1 {
                    runs.push(std::mem::take(&mut run));
                }
                run.clear();
            }
        }
    }
    if run.len() > 1 {
        runs.push(run);
    }
    runs
}

/// Where the ray from `p` (inside the box) in direction `d` leaves the box.
fn exit_point(p: (f64, f64), d: (f64, f64), bx: Box2) -> (f64, f64) {
    let big = 4.0 * ((bx.1 - bx.0) + (bx.3 - bx.2));
    let len = (d.0 * d.0 + d.1 * d.1).sqrt().max(f64::MIN_POSITIVE);
    let far = (p.0 + big * d.0 / len, p.1 + big * d.1 / len);
    clip(p, far, bx).map_or(p, |(_, q)| q)
}

/// The pieces' curves as polylines in plane coordinates, broken at the poles.
fn curves(data: &PanelData) -> [Vec<Vec<(f64, f64)>>; 2] {
    [0, 1].map(|k| {
        let piece = &data.pieces[k];
        let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
        let mut run = Vec::new();
        let mut last_sign = 0.0;
        for t in piece.params() {
            let (w, x, _, _) = piece.hom(t);
            let sign = if w > 0.0 {
                1.0
            } else if w < 0.0 {
                -1.0
            } else {
                0.0
            };
            if sign == 0.0 || sign != last_sign {
                if run.len() > 1 {
                    runs.push(std::mem::take(&mut run));
                }
                run.clear();
            }
            last_sign = sign;
            if sign != 0.0 {
                run.push(data.to2(&[x[0] / w, x[1] / w, x[2] / w]));
            }
        }
        if run.len() > 1 {
            runs.push(run);
        }
        runs
    })
}

/// The view box: the finite control points and the curve points not too far from them,
/// padded, with equal scales for the given aspect `width / height`.
fn view_box(data: &PanelData, curves: &[Vec<Vec<(f64, f64)>>; 2], aspect: f64) -> Box2 {
    let mut pts: Vec<(f64, f64)> = Vec::new();
    for p in &data.pieces {
        for k in 0..3 {
            if p.w[k] != 0.0 {
                let w = p.w[k];
                pts.push(data.to2(&[p.wp[k][0] / w, p.wp[k][1] / w, p.wp[k][2] / w]));
            }
        }
    }
    let reach = pts
        .iter()
        .map(|p| p.0.abs().max(p.1.abs()))
        .fold(1.0f64, f64::max)
        * 2.5;
    for (piece, runs) in data.pieces.iter().zip(curves) {
        let bounded = piece.poles.is_empty();
        pts.extend(
            runs.iter()
                .flatten()
                .filter(|p| bounded || (p.0.abs() <= reach && p.1.abs() <= reach)),
        );
    }
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &pts {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    if pts.is_empty() {
        (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
    }
    let pad = 0.12 * (x1 - x0).max(y1 - y0).max(1e-9);
    let (mut x0, mut x1, mut y0, mut y1) = (x0 - pad, x1 + pad, y0 - pad, y1 + pad);
    let (w, h) = (x1 - x0, y1 - y0);
    if w / h < aspect {
        let grow = (aspect * h - w) / 2.0;
        x0 -= grow;
        x1 += grow;
    } else {
        let grow = (w / aspect - h) / 2.0;
        y0 -= grow;
        y1 += grow;
    }
    (x0, x1, y0, y1)
}

/// Whether the f64 drawing data of a panel is usable: every number finite, and the view box
/// finite with positive extent. A plane whose numbers leave f64's range (a normal of
/// `10^400`, or of `10^-200` whose squares vanish) gives `inf` or NaN here, which the drawing
/// cannot place.
fn drawable(data: &PanelData) -> bool {
    let numbers = data
        .frame
        .iter()
        .flatten()
        .chain(
            data.pieces
                .iter()
                .flat_map(|p| p.w.iter().chain(p.wp.iter().flatten())),
        )
        .chain(
            data.pieces
                .iter()
                .flat_map(|p| p.poles.iter().map(|(t, _)| t)),
        );
    if !numbers.into_iter().all(|x| x.is_finite()) {
        return false;
    }
    let (x0, x1, y0, y1) = view_box(data, &curves(data), 1.0);
    [x0, x1, y0, y1].iter().all(|x| x.is_finite()) && x0 < x1 && y0 < y1
}

/// Draws one panel on `area`; returns the number of pole markers.
fn panel(area: &Area<'_>, data: &PanelData) -> Result<usize, DrawErr> {
    let (pw, ph) = area.dim_in_pixel();
    let (pw, ph) = (pw as i32, ph as i32);
    area.draw(&Rectangle::new(
        [(0, 0), (pw - 1, ph - 1)],
        RGBColor(0xfc, 0xfc, 0xfc).filled(),
    ))?;
    area.draw(&Rectangle::new(
        [(0, 0), (pw - 1, ph - 1)],
        FRAME.stroke_width(1),
    ))?;
    text(area, &data.title, (12, 8), &bold(18.0, INK))?;
    text(area, &data.sub[0], (12, 30), &font(14.0, GREY_TEXT))?;
    text(area, &data.sub[1], (12, 47), &font(14.0, GREY_TEXT))?;
    let inner = area.margin(68, 10, 10, 10);
    let (aw, ah) = inner.dim_in_pixel();
    let curves = curves(data);
    let bx = view_box(data, &curves, f64::from(aw) / f64::from(ah));
    let scale = f64::from(aw) / (bx.1 - bx.0);
    let mut chart = ChartBuilder::on(&inner).build_cartesian_2d(bx.0..bx.1, bx.2..bx.3)?;
    let line = |chart: &mut Chart<'_, '_>, pts: Vec<(f64, f64)>, style: ShapeStyle| {
        chart.draw_series(LineSeries::new(pts, style)).map(|_| ())
    };
    // The plane's axes through the foot of the perpendicular from the apex.
    for seg in [((bx.0, 0.0), (bx.1, 0.0)), ((0.0, bx.2), (0.0, bx.3))] {
        if let Some((a, b)) = clip(seg.0, seg.1, bx) {
            line(
                &mut chart,
                vec![a, b],
                RGBColor(0xcc, 0xcc, 0xcc).stroke_width(1),
            )?;
        }
    }
    let colour = [BLUE, ORANGE];
    let mut markers = 0;
    for k in 0..2 {
        let piece = &data.pieces[k];
        // The control polygon: segments between finite points, rays towards points at infinity.
        let pt = |i: usize| -> Option<(f64, f64)> {
            let w = piece.w[i];
            (w != 0.0)
                .then(|| data.to2(&[piece.wp[i][0] / w, piece.wp[i][1] / w, piece.wp[i][2] / w]))
        };
        let mut poly: Vec<Vec<(f64, f64)>> = Vec::new();
        for i in 0..2 {
            match (pt(i), pt(i + 1)) {
                (Some(a), Some(b)) => poly.push(vec![a, b]),
                (Some(a), None) => {
                    poly.push(vec![a, exit_point(a, data.dir2(&piece.wp[i + 1]), bx)]);
                }
                (None, Some(b)) => {
                    poly.push(vec![b, exit_point(b, data.dir2(&piece.wp[i]), bx)]);
                }
                (None, None) => {}
            }
        }
        for seg in poly {
            for run in clip_polyline(&seg, bx) {
                line(&mut chart, run, colour[k].stroke_width(1))?;
            }
        }
        for run in &curves[k] {
            for clipped in clip_polyline(run, bx) {
                line(&mut chart, clipped, colour[k].stroke_width(3))?;
            }
        }
        for i in 0..3 {
            if let Some(p) = pt(i) {
                if p.0 >= bx.0 && p.0 <= bx.1 && p.1 >= bx.2 && p.1 <= bx.3 {
                    chart.plotting_area().draw(&dot(p, 5, colour[k]))?;
                }
            }
        }
    }
    // The poles.
    let centre = ((bx.0 + bx.1) / 2.0, (bx.2 + bx.3) / 2.0);
    let inset = 8.0 / scale;
    for k in 0..2 {
        let piece = &data.pieces[k];
        for &(t0, mult) in &piece.poles {
            let (_, x, dw, dx) = piece.hom(t0);
            let dir = data.dir2(&x);
            let tip = if mult == 1 && dw != 0.0 {
                let a = data.to2(&[dx[0] / dw, dx[1] / dw, dx[2] / dw]);
                let big = 4.0 * ((bx.1 - bx.0) + (bx.3 - bx.2));
                let len = (dir.0 * dir.0 + dir.1 * dir.1)
                    .sqrt()
                    .max(f64::MIN_POSITIVE);
                let (p, q) = (
                    (a.0 - big * dir.0 / len, a.1 - big * dir.1 / len),
                    (a.0 + big * dir.0 / len, a.1 + big * dir.1 / len),
                );
                match clip(p, q, bx) {
                    Some((p, q)) => {
                        line(&mut chart, vec![p, q], PURPLE.stroke_width(1))?;
                        q
                    }
                    None => exit_point(centre, dir, bx),
                }
            } else {
                // A double pole: the direction in which the curve escapes.
                let near = piece
                    .hom((t0 + 1e-3).min(1.0))
                    .0
                    .max(piece.hom((t0 - 1e-3).max(0.0)).0);
                let s = if near < 0.0 { -1.0 } else { 1.0 };
                let d = (s * dir.0, s * dir.1);
                // From the centroid of the piece's finite control points (near the vertex).
                let finite: Vec<(f64, f64)> = (0..3)
                    .filter(|&i| piece.w[i] != 0.0)
                    .map(|i| {
                        let w = piece.w[i];
                        data.to2(&[piece.wp[i][0] / w, piece.wp[i][1] / w, piece.wp[i][2] / w])
                    })
                    .collect();
                let anchor = if finite.is_empty() {
                    centre
                } else {
                    let n = finite.len() as f64;
                    let c = finite
                        .iter()
                        .fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
                    ((c.0 / n).clamp(bx.0, bx.1), (c.1 / n).clamp(bx.2, bx.3))
                };
                let q = exit_point(anchor, d, bx);
                line(&mut chart, vec![anchor, q], PURPLE.stroke_width(1))?;
                q
            };
            let tip = (
                tip.0.clamp(bx.0 + inset, bx.1 - inset),
                tip.1.clamp(bx.2 + inset, bx.3 - inset),
            );
            chart.plotting_area().draw(&ring(tip, 6, PURPLE))?;
            let label = format!("C{}(t) = ∞ at t ≈ {}", ["+", "−"][k], short(t0, 4));
            let dx = if tip.0 > centre.0 { -170 } else { 10 };
            let dy = if tip.1 > bx.3 - 3.0 * inset { 10 } else { -24 };
            chart
                .plotting_area()
                .draw(&(EmptyElement::at(tip) + Text::new(label, (dx, dy), font(13.5, PURPLE))))?;
            markers += 1;
        }
    }
    Ok(markers)
}

/// A panel's chart.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws panels in a grid of `cols` columns under a header, with a legend row under them;
/// returns the SVG and the number of pole markers.
fn draw(panels: &[PanelData], cols: usize, title: &str, lines: &[String]) -> (String, usize) {
    let rows = panels.len().div_ceil(cols) as u32;
    let (pw, ph) = if panels.len() == 1 {
        (SINGLE_W, SINGLE_H)
    } else {
        (PANEL_W, PANEL_H)
    };
    let width = GAP + cols as u32 * (pw + GAP);
    let top = 46 + 18 * lines.len() as u32 + 10;
    let height = top + rows * (ph + GAP) + 70;
    let mut markers = 0;
    let svg = render((width, height), title, |root| {
        let body = header(root, title, lines)?;
        for (i, p) in panels.iter().enumerate() {
            let (c, r) = ((i % cols) as u32, (i / cols) as u32);
            let (x, y) = (GAP + c * (pw + GAP), r * (ph + GAP));
            let area = body.clone().shrink((x, y), (pw, ph));
            markers += panel(&area, p)?;
        }
        let strip = body
            .clone()
            .shrink((GAP, rows * (ph + GAP)), (width - 2 * GAP, 60));
        legend_row(
            &strip,
            &[
                ("C+ (quarter cone V+)".into(), Sym::Line(BLUE, 3)),
                ("C− (three-quarter cone V−)".into(), Sym::Line(ORANGE, 3)),
                ("control polygons (thin)".into(), Sym::Line(BLUE, 1)),
                ("asymptote / escape direction".into(), Sym::Line(PURPLE, 1)),
                ("pole (weight = 0)".into(), Sym::Ring(PURPLE)),
            ],
        )
    });
    (svg, markers)
}

/// Short text of an exact number (the exact form when short, else a decimal).
fn exact_text(x: &Radical) -> String {
    let s = x.to_string();
    if s.len() <= 14 {
        // sqrt(k) -> √k
        let mut out = String::new();
        let mut rest = s.as_str();
        while let Some(i) = rest.find("sqrt(") {
            out.push_str(&rest[..i]);
            let after = &rest[i + 5..];
            let close = after.find(')').expect("the printer closes every sqrt(");
            out.push('√');
            out.push_str(&after[..close]);
            rest = &after[close + 1..];
        }
        out.push_str(rest);
        out
    } else {
        short(x.to_f64(), 4)
    }
}

fn describe_type(c: &Computed<Radical>) -> String {
    let t = c.angle;
    let both = c.pieces.iter().all(|p| p.bezier == Some(t));
    format!(
        "{}{}",
        t.name(),
        if both {
            " (angle rule = weights)"
        } else {
            " (angle rule; the weights disagree)"
        }
    )
}

fn weights_line(c: &Computed<Radical>) -> String {
    let w = |k: usize| {
        c.pieces[k]
            .curve
            .weights()
            .iter()
            .map(exact_text)
            .collect::<Vec<_>>()
            .join(", ")
    };
    format!("w+ = {}; w− = {}", w(0), w(1))
}

/// The four sections of Table 1, and the number of pole markers drawn.
pub fn table1() -> (String, usize) {
    let width = Radical::from(Rational::new(1, 1 << 40).expect("2^40 != 0"));
    let names = ["(0, 0, 1)", "(1, 1, 3)", "(1, 1, √2)", "(1, 1, 0)"];
    let panels: Vec<PanelData> = table1_planes()
        .into_iter()
        .zip(names)
        .map(|(plane, name)| {
            let c = compute(plane, &width).expect("Table 1's normals are not zero");
            let sub = format!("normal {name} through (1, 1, 1)");
            panel_data(&c, describe_type(&c), [sub, weights_line(&c)])
        })
        .collect();
    draw(
        &panels,
        2,
        "Chiang Table 1: the cone x² + y² = z² cut by four planes",
        &[
            "each section as two rational quadratic Bézier pieces: C+ on V+ (the quarter cone), C− on V− (the other three quarters)".into(),
            "weights, control points and poles exact (solve conic, Q(√2)); type by the angle rule and by the weights; drawn in f64 in each plane's own coordinates".into(),
        ],
    )
}

/// One `conic` problem file as a one-panel figure, and the number of pole markers.
///
/// # Errors
/// As `solve conic` for the file's content.
pub fn file(path: &str, text_in: &str) -> Result<(String, usize), Error> {
    let c = exact_section(text_in).map_err(|e| Error::Input(format!("{path}: {e}")))?;
    if let SectionType::Degenerate(_) = c.angle {
        return Err(Error::Input(format!(
            "{path}: the plane passes through the apex ({}): plot draws proper conics only; `solve` names the rulings",
            c.angle.name()
        )));
    }
    let n = &c.plane.normal;
    let sub = format!(
        "plane ({})x + ({})y + ({})z + ({}) = 0",
        exact_text(&n.x),
        exact_text(&n.y),
        exact_text(&n.z),
        exact_text(&c.plane.d)
    );
    let name = std::path::Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |f| f.to_string_lossy().into_owned());
    let panels = [panel_data(&c, describe_type(&c), [sub, weights_line(&c)])];
    if !panels.iter().all(drawable) {
        return Err(Error::Input(format!(
            "{path}: {}",
            crate::solve::F64_OUT_OF_RANGE
        )));
    }
    Ok(draw(
        &panels,
        1,
        &format!("The cone x² + y² = z² cut by the plane of {name}"),
        &["C+ on V+, C− on V−; exact section (solve conic), drawn in f64 in the plane's own coordinates".into()],
    ))
}
