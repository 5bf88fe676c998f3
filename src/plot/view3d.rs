//! The 3D view: an orthographic projection of the cylinder and sphere wireframes and the
//! intersection curve, cut into short pieces and drawn back to front (painter's algorithm).

use super::*;

/// Azimuth and elevation of the fixed view direction (degrees).
const AZIMUTH: f64 = -60.0;
/// Negative: from slightly below, where Example 2's curve lies (it is nearly a great circle of
/// the sphere, tilted towards -z).
const ELEVATION: f64 = -25.0;

/// Orthographic projection: screen right, screen up and the direction towards the viewer.
pub(super) struct Camera {
    right: Vec3<f64>,
    up: Vec3<f64>,
    toward: Vec3<f64>,
}

impl Camera {
    pub(super) fn new(azimuth: f64, elevation: f64) -> Camera {
        let (sa, ca) = azimuth.to_radians().sin_cos();
        let (se, ce) = elevation.to_radians().sin_cos();
        Camera {
            right: Vec3::new(-sa, ca, 0.0),
            up: Vec3::new(-se * ca, -se * sa, ce),
            toward: Vec3::new(ce * ca, ce * sa, se),
        }
    }

    /// `(x, y)` on the image plane (y up).
    pub(super) fn project(&self, p: &Vec3<f64>) -> (f64, f64) {
        (p.dot(&self.right), p.dot(&self.up))
    }

    pub(super) fn depth(&self, p: &Vec3<f64>) -> f64 {
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
pub(super) fn view_3d(scene: &Scene) -> String {
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
