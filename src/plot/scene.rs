//! The scenes `plot` draws: one cylinder/sphere configuration in f64 (for the curves) and its
//! exact analysis (for the markers), built from one of Spaeth's examples or a `cylinder_sphere`
//! problem file; and the dense f64 sampling of the branches `u1(t) <= u2(t)`, broken where the
//! discriminant is negative, with the ends of each run found by bisection on the sign.

use super::*;

/// What is drawn: the f64 configuration (curves and samples) and the exact analysis (markers).
pub(super) struct Scene {
    /// "Spaeth Example 1" or the problem file.
    pub(super) name: String,
    /// The paper's figure, if it has one.
    pub(super) figure: Option<&'static str>,
    /// The configuration in words.
    pub(super) config: String,
    /// The configuration the curves and the 10-degree samples are computed for.
    pub(super) float: CylinderSphere<f64>,
    /// The exact analysis, or why there is none.
    pub(super) exact: Result<ExactInfo, String>,
    /// How the f64 configuration was taken, if worth saying.
    pub(super) note_float: Option<String>,
    /// How the exact configuration differs from the f64 one, if it does.
    pub(super) note_exact: Option<String>,
}

/// The exact analysis turned into angles (degrees in `[0, 360)`).
pub(super) struct ExactInfo {
    /// Arcs `(start, end)` of `t` where the discriminant is `>= 0`, counter-clockwise
    /// (`start > end` when the arc passes through 0); empty when nowhere.
    pub(super) arcs: Vec<(f64, f64)>,
    /// Whether the discriminant is `>= 0` for every `t` (then `arcs` is empty).
    pub(super) everywhere: bool,
    /// Isolated touching points.
    pub(super) tangents: Vec<f64>,
    /// One line: contact, components, the real set.
    pub(super) summary: String,
}

pub(super) fn to_f64(q: &Rational) -> f64 {
    q.to_f64()
}

/// Spaeth's examples (r = 5, axis through the origin), rebuilt from the printed values
/// (`crate::claims::spaeth::SPAETH_EXAMPLES`).
pub(super) fn spaeth_scene(n: u32) -> Result<Scene, Error> {
    let ex = SpaethExample::get(n).ok_or_else(|| {
        Error::Usage(format!(
            "unknown example {n}: Spaeth's examples are 1, 2 and 3"
        ))
    })?;
    let exact = ex.config(|theta| exactcheck_exact::cylinder_sphere::rational_angle(theta, 1000).0);
    let float = ex.float_config();
    let figure = match n {
        1 => Some("Fig. 2"),
        2 => Some("Fig. 3"),
        _ => None,
    };
    let note = (n == 2).then(|| {
        let (_, tb, db) = exactcheck_exact::cylinder_sphere::rational_angle(ex.beta_radians, 1000);
        let (_, tg, dg) = exactcheck_exact::cylinder_sphere::rational_angle(ex.gamma_radians, 1000);
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
pub(super) fn file_scene(path: &str) -> Result<Scene, Error> {
    let text = crate::solve::read_problem(Some(path))?;
    let in_file = |e: Error| Error::Input(format!("{path}: {e}"));
    let kind = crate::solve::problem_kind(&text).map_err(in_file)?;
    if kind != "cylinder_sphere" {
        return Err(Error::Input(format!(
            "{path}: plot draws problem files of kind \"cylinder_sphere\", \"conic\" or \"ph_offset\" (found kind {kind:?})"
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

pub(super) fn describe(cs: &CylinderSphere<f64>) -> String {
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
pub(super) fn tau_degrees(tau: f64) -> f64 {
    let d = (2.0 * tau.atan()).to_degrees();
    if d < 0.0 {
        d + 360.0
    } else {
        d
    }
}

/// A root of `p`, refined to width 2^-40, in degrees.
pub(super) fn root_degrees(p: &UPoly, ri: &RootInterval) -> f64 {
    match ri.exact_value() {
        Some(v) => tau_degrees(to_f64(v)),
        None => {
            let width = Rational::new(1, 1 << 40).expect("2^40 is not zero");
            tau_degrees(p.refine(ri, &width).to_f64())
        }
    }
}

pub(super) fn exact_info(cs: &CylinderSphere<Rational>) -> ExactInfo {
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
        "exact (root isolation on the τ-quartic): {}, {} component{}, {set}{touching}",
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
pub(super) fn eval(s: &DiscSampler, t: f64) -> [f64; 3] {
    let (sn, c) = t.sin_cos();
    let (a, b) = s.ab(c, sn);
    let d = (a * a - b).max(0.0).sqrt();
    [t, -a - d, -a + d]
}

/// The point next to the boundary between `real` and `not_real`, on the real side.
pub(super) fn boundary(s: &DiscSampler, mut real: f64, mut not_real: f64) -> f64 {
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
pub(super) fn runs(s: &DiscSampler, n: usize) -> Vec<Vec<[f64; 3]>> {
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
pub(super) fn sphere_u_range(cs: &CylinderSphere<f64>) -> (f64, f64) {
    let (q, a) = cs.axis_polynomial();
    let uc = (&cs.center - &q).dot(&a);
    (uc - cs.radius.abs(), uc + cs.radius.abs())
}
