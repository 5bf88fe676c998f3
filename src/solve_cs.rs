//! `solve` kind `cylinder_sphere` (Spaeth, SPEC §2): decision, coefficients of A and B,
//! parametrization, tangency points and sample points of the intersection curve.
//!
//! Exact mode works over Q with rational angles `{cos, sin}` (checked on the unit circle;
//! `{radians}` is approximated by a nearby rational point and the answer says so); sample points
//! are computed in the square-root field, so each lies exactly on both surfaces (checked and
//! reported). Float mode evaluates the same generic formulas in f64.

use crate::solve::{array, exact_number, out, Mode};
use crate::Error;
use exactcheck_core::cylinder_sphere::{unit_circle_point, Angle, Contact, CylinderSphere};
use exactcheck_core::{Field, OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::Bound;
use exactcheck_exact::{Radical, Rational};
use serde_json::{json, Map, Value};

fn field<'a>(obj: &'a Map<String, Value>, name: &str, path: &str) -> Result<&'a Value, Error> {
    obj.get(name)
        .ok_or_else(|| Error::Input(format!("missing field \"{path}{name}\"")))
}

fn object<'a>(v: &'a Value, path: &str) -> Result<&'a Map<String, Value>, Error> {
    v.as_object()
        .ok_or_else(|| Error::Input(format!("\"{path}\" must be an object")))
}

pub(crate) fn rational(v: &Value, path: &str) -> Result<Rational, Error> {
    let x = exact_number(v, path)?;
    x.to_rational().ok_or_else(|| Error::Input(format!("{path}: {x} is irrational; cylinder_sphere needs rational input in exact mode (angles as rational points {{cos, sin}} of the unit circle)")))
}

pub(crate) fn float(v: &Value, path: &str) -> Result<f64, Error> {
    match v {
        Value::Number(n) => n
            .as_f64()
            .ok_or_else(|| Error::Input(format!("{path}: not a number"))),
        other => Ok(exact_number(other, path)?.to_f64()),
    }
}

/// An angle given exactly `{cos, sin}` or as `{radians}`; `approx` notes a radians input taken
/// as a nearby rational point.
pub(crate) fn exact_angle(
    v: &Value,
    path: &str,
    notes: &mut Vec<Value>,
) -> Result<Angle<Rational>, Error> {
    let o = object(v, path)?;
    if let Some(r) = o.get("radians") {
        let theta = float(r, &format!("{path}.radians"))?;
        if !theta.is_finite() {
            return Err(Error::Input(format!("{path}.radians must be finite")));
        }
        let (angle, tau, dev) = crate::claims::spaeth::rational_angle(theta, 1_000_000);
        notes.push(json!({"field": path, "radians": theta, "rational_tau": tau.to_string(), "cos": angle.cos.to_string(), "sin": angle.sin.to_string(), "deviation_radians": dev}));
        return Ok(angle);
    }
    let c = rational(
        field(o, "cos", &format!("{path}."))?,
        &format!("{path}.cos"),
    )?;
    let s = rational(
        field(o, "sin", &format!("{path}."))?,
        &format!("{path}.sin"),
    )?;
    if c.square() + s.square() != Rational::ONE {
        return Err(Error::Input(format!(
            "{path}: cos^2 + sin^2 = {} != 1",
            c.square() + s.square()
        )));
    }
    Ok(Angle { cos: c, sin: s })
}

pub(crate) fn float_angle(v: &Value, path: &str) -> Result<Angle<f64>, Error> {
    let o = object(v, path)?;
    if let Some(r) = o.get("radians") {
        let t = float(r, &format!("{path}.radians"))?;
        return Ok(Angle {
            cos: t.cos(),
            sin: t.sin(),
        });
    }
    let c = float(
        field(o, "cos", &format!("{path}."))?,
        &format!("{path}.cos"),
    )?;
    let s = float(
        field(o, "sin", &format!("{path}."))?,
        &format!("{path}.sin"),
    )?;
    if ((c * c + s * s) - 1.0).abs() > 1e-9 {
        return Err(Error::Input(format!(
            "{path}: cos^2 + sin^2 = {} is not 1",
            c * c + s * s
        )));
    }
    Ok(Angle { cos: c, sin: s })
}

/// Reads an angle field (exact `{cos, sin}` / `{radians}`, or f64).
type AngleReader<'a, T> = dyn FnMut(&Value, &str) -> Result<Angle<T>, Error> + 'a;

/// A point with coordinates `p + q sqrt(D)` as text, and its f64 approximation.
type QuadPoint = ([String; 3], [f64; 3]);

pub(crate) struct Input<T> {
    pub(crate) cs: CylinderSphere<T>,
    samples: usize,
}

pub(crate) fn read<T: Field + OrderedField>(
    obj: &Map<String, Value>,
    num: &dyn Fn(&Value, &str) -> Result<T, Error>,
    angle: &mut AngleReader<'_, T>,
) -> Result<Input<T>, Error> {
    let cyl = object(field(obj, "cylinder", "")?, "cylinder")?;
    let sph = object(field(obj, "sphere", "")?, "sphere")?;
    let axis = array(cyl, "axis_point").map_err(|e| Error::Input(format!("cylinder.{e}")))?;
    if axis.len() != 2 {
        return Err(Error::Input(format!(
            "cylinder.axis_point: expected [a, b], found {} numbers",
            axis.len()
        )));
    }
    let a = num(&axis[0], "cylinder.axis_point[0]")?;
    let b = num(&axis[1], "cylinder.axis_point[1]")?;
    let r = num(field(cyl, "radius", "cylinder.")?, "cylinder.radius")?;
    let beta = angle(field(cyl, "beta", "cylinder.")?, "cylinder.beta")?;
    let gamma = angle(field(cyl, "gamma", "cylinder.")?, "cylinder.gamma")?;
    let c = field(sph, "center", "sphere.")?;
    let ca = c
        .as_array()
        .ok_or_else(|| Error::Input("sphere.center: expected 3 numbers".into()))?;
    if ca.len() != 3 {
        return Err(Error::Input(format!(
            "sphere.center: expected 3 coordinates, found {}",
            ca.len()
        )));
    }
    let center = Vec3::new(
        num(&ca[0], "sphere.center[0]")?,
        num(&ca[1], "sphere.center[1]")?,
        num(&ca[2], "sphere.center[2]")?,
    );
    let radius = num(field(sph, "radius", "sphere.")?, "sphere.radius")?;
    if r.sign() != Sign::Positive {
        return Err(Error::Input("cylinder.radius must be positive".into()));
    }
    if radius.sign() != Sign::Positive {
        return Err(Error::Input("sphere.radius must be positive".into()));
    }
    let samples = match obj.get("samples") {
        None => 12,
        Some(v) => v
            .as_u64()
            .filter(|n| (1..=10_000).contains(n))
            .ok_or_else(|| Error::Input("samples must be an integer from 1 to 10000".into()))?
            as usize,
    };
    Ok(Input {
        cs: CylinderSphere {
            a,
            b,
            r,
            beta,
            gamma,
            center,
            radius,
        },
        samples,
    })
}

/// `{cylinder, sphere, samples}` → the answer (exact, float, or both).
pub fn cylinder_sphere(obj: &Map<String, Value>, mode: Mode) -> Result<Value, Error> {
    match mode {
        Mode::Exact => exact(obj),
        Mode::Float => float_answer(obj),
        Mode::Both => {
            let mut e = exact(obj)?;
            e["float"] = float_answer(obj)?;
            Ok(e)
        }
    }
}

fn trig_json<T: std::fmt::Display>(
    c: &exactcheck_core::cylinder_sphere::TrigCoefficients<T>,
    f: impl Fn(&T) -> Value,
) -> Value {
    json!({
        "A": {"basis": ["1", "cos t", "sin t"], "coefficients": c.a.iter().map(&f).collect::<Vec<_>>()},
        "B": {"basis": ["1", "cos t", "sin t", "cos^2 t", "cos t sin t", "sin^2 t"], "coefficients": c.b.iter().map(&f).collect::<Vec<_>>()},
    })
}

fn exact(obj: &Map<String, Value>) -> Result<Value, Error> {
    let mut notes = Vec::new();
    let input = read::<Rational>(obj, &|v, p| rational(v, p), &mut |v, p| {
        exact_angle(v, p, &mut notes)
    })?;
    let cs = input.cs;
    let analysis = analyze(&cs);
    let by_distance = cs.contact_by_distance();
    let coeffs = cs.trig_coefficients();
    let p = &analysis.discriminant;
    // Sample parameters: rational tau on a grid of angles, plus one inside every interval, kept
    // where the discriminant is >= 0.
    let mut taus: Vec<Rational> = Vec::new();
    for k in 0..input.samples {
        let t = std::f64::consts::TAU * k as f64 / input.samples as f64;
        if (t - std::f64::consts::PI).abs() > 1e-9 {
            let (_, tau, _) = crate::claims::spaeth::rational_angle(t, 1000);
            taus.push(tau);
        }
    }
    for iv in &analysis.nonnegative {
        let mid = match (&iv.lo, &iv.hi) {
            (Bound::Root(a), Bound::Root(b)) => {
                (a.midpoint() + b.midpoint()) * Rational::new(1, 2).unwrap_or(Rational::ONE)
            }
            (Bound::NegInf, Bound::Root(b)) => b.lo.clone() - Rational::ONE,
            (Bound::Root(a), Bound::PosInf) => a.hi.clone() + Rational::ONE,
            _ => Rational::ZERO,
        };
        taus.push(mid);
    }
    taus.sort();
    taus.dedup();
    let point_json = |x: &Vec3<Radical>| json!([out(&x.x), out(&x.y), out(&x.z)]);
    let approx_json =
        |x: &Vec3<Radical>| json!([x.x.to_f64() + 0.0, x.y.to_f64() + 0.0, x.z.to_f64() + 0.0]);
    let lift = |q: &Rational| Radical::from(q);
    let rcs = CylinderSphere {
        a: lift(&cs.a),
        b: lift(&cs.b),
        r: lift(&cs.r),
        beta: Angle {
            cos: lift(&cs.beta.cos),
            sin: lift(&cs.beta.sin),
        },
        gamma: Angle {
            cos: lift(&cs.gamma.cos),
            sin: lift(&cs.gamma.sin),
        },
        center: cs.center.map(lift),
        radius: lift(&cs.radius),
    };
    let (axis_q, axis_d) = rcs.axis();
    let on_both = |x: &Vec3<Radical>| {
        let sphere = (x - &rcs.center).norm_squared() == rcs.radius.square();
        let cyl = (x - &axis_q).cross(&axis_d).norm_squared() == rcs.r.square();
        sphere && cyl
    };
    let mut samples = Vec::new();
    let mut points = Vec::new();
    let mut all_on_both = true;
    for tau in &taus {
        if p.sign_at(tau) == Sign::Negative {
            continue;
        }
        let Ok(angle) = unit_circle_point(tau) else {
            continue;
        };
        let (a, b) = cs.coefficients_at(&angle.cos, &angle.sin);
        let disc = a.square() - &b;
        // u and the points: in the radical field, or in Q(w), w^2 = disc, when the radicand
        // cannot be certified square-free.
        let (us, exact_pts, approx_pts): (Vec<Value>, Vec<Value>, Vec<Value>) =
            match Radical::sqrt_rational(&disc) {
                None => {
                    let (pts, ok) = quadratic_points(&cs, &angle, &a, &disc);
                    all_on_both &= ok;
                    let minus_a = a.neg_ref();
                    (
                        vec![
                            json!(format!("{minus_a} - sqrt({disc})")),
                            json!(format!("{minus_a} + sqrt({disc})")),
                        ],
                        pts.iter().map(|p| json!(p.0)).collect(),
                        pts.iter().map(|p| json!(p.1)).collect(),
                    )
                }
                Some(root) => {
                    let (c, s) = (lift(&angle.cos), lift(&angle.sin));
                    let minus_a = lift(&a).neg_ref();
                    let us: Vec<Radical> = if disc.is_zero() {
                        vec![minus_a]
                    } else {
                        vec![minus_a.sub_ref(&root), minus_a.add_ref(&root)]
                    };
                    let pts: Vec<Vec3<Radical>> = us.iter().map(|u| rcs.point(&c, &s, u)).collect();
                    all_on_both &= pts.iter().all(&on_both);
                    (
                        us.iter().map(out).collect(),
                        pts.iter().map(point_json).collect(),
                        pts.iter().map(approx_json).collect(),
                    )
                }
            };
        samples.push(json!({
            "tau": tau.to_string(),
            "cos": out(&angle.cos),
            "sin": out(&angle.sin),
            "t_degrees": 2.0 * tau.to_f64().atan().to_degrees(),
            "u": us,
            "points": exact_pts.clone(),
        }));
        points.extend(
            exact_pts
                .into_iter()
                .zip(approx_pts)
                .map(|(e, a)| json!({"exact": e, "approx": a})),
        );
    }
    // Tangency points.
    let mut tangent_points = Vec::new();
    for tp in &analysis.tangent_params {
        let (angle, exact_tau) = match tp {
            None => (
                Angle {
                    cos: Rational::from_integer(-1),
                    sin: Rational::ZERO,
                },
                Some("infinity (t = pi)".to_string()),
            ),
            Some(ri) => match ri.exact_value() {
                Some(v) => (
                    unit_circle_point(v)
                        .map_err(|_| Error::Input("bad tangency parameter".into()))?,
                    Some(v.to_string()),
                ),
                None => {
                    let refined = p.refine(ri, &Rational::new(1, 1 << 40).unwrap_or(Rational::ONE));
                    tangent_points.push(json!({"tau_interval": [refined.lo.to_string(), refined.hi.to_string()], "approx": {"tau": refined.to_f64()}}));
                    continue;
                }
            },
        };
        let (a, _) = cs.coefficients_at(&angle.cos, &angle.sin);
        let x = rcs.point(&lift(&angle.cos), &lift(&angle.sin), &lift(&a).neg_ref());
        all_on_both &= on_both(&x);
        tangent_points.push(json!({"tau": exact_tau, "point": point_json(&x), "approx": approx_json(&x), "on_both_surfaces": on_both(&x)}));
    }
    // Endpoints to the requested precision (optional field "precision": a positive width).
    let width = match obj.get("precision") {
        None => None,
        Some(v) => {
            let w = rational(v, "precision")?;
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision must be positive".into()));
            }
            Some(w)
        }
    };
    let refine = |r: &exactcheck_exact::univariate::RootInterval| match &width {
        Some(w) if !r.is_exact() => p.refine(r, w),
        _ => r.clone(),
    };
    let intervals: Vec<Value> = analysis
        .nonnegative
        .iter()
        .map(|iv| {
            let b = |x: &Bound| match x {
                Bound::NegInf => json!("-inf"),
                Bound::PosInf => json!("+inf"),
                Bound::Root(r) => match r.exact_value() {
                    Some(v) => json!(v.to_string()),
                    None => {
                        let r = refine(r);
                        json!({"interval": [r.lo.to_string(), r.hi.to_string()], "approx": r.to_f64()})
                    }
                },
            };
            json!([b(&iv.lo), b(&iv.hi)])
        })
        .collect();
    let contact = |c: Contact| format!("{c:?}").to_lowercase();
    let mut answer = json!({
        "kind": "cylinder_sphere",
        "mode": "exact",
        "intersects": analysis.contact != Contact::Disjoint,
        "contact": contact(analysis.contact),
        "contact_by_axis_distance": contact(by_distance),
        "methods_agree": analysis.contact == by_distance,
        "components": analysis.components,
        "tangent_points": tangent_points,
        "coefficients": trig_json(&coeffs, out),
        "parametrization": {
            "angle": "cos t = (1 - tau^2)/(1 + tau^2), sin t = 2*tau/(1 + tau^2) (tau = infinity at t = pi)",
            "u": "-A(t) +- sqrt(P(tau))/(1 + tau^2)",
            "P": p.display("tau").to_string(),
            "point": "Rx(gamma) Ry(beta) (a + r cos t, b + r sin t, u)",
            "real_for_tau_in": intervals,
            "real_at_t_pi": analysis.sign_at_pi != Sign::Negative,
        },
        "samples": samples,
        "points": points,
        "all_points_on_both_surfaces": all_on_both,
    });
    if !notes.is_empty() {
        answer["approximated_angles"] = Value::Array(notes);
    }
    Ok(answer)
}

fn float_answer(obj: &Map<String, Value>) -> Result<Value, Error> {
    let input = read::<f64>(obj, &|v, p| float(v, p), &mut |v, p| float_angle(v, p))?;
    let cs = input.cs;
    let sampler = exactcheck_float::sampler::DiscSampler::new(&cs);
    let n = input.samples;
    let mut samples = Vec::new();
    for k in 0..n {
        let t = std::f64::consts::TAU * k as f64 / n as f64;
        let (s, c) = t.sin_cos();
        let u: Vec<f64> = sampler
            .roots(t)
            .map(|(a, b)| vec![a, b])
            .unwrap_or_default();
        let points: Vec<[f64; 3]> = u.iter().map(|u| cs.point(&c, &s, u).into_array()).collect();
        samples.push(json!({"t": t, "cos": c, "sin": s, "u": u, "points": points}));
    }
    let contact = cs.contact_by_distance();
    Ok(json!({
        "kind": "cylinder_sphere",
        "mode": "float",
        "intersects": contact != Contact::Disjoint,
        "contact_by_axis_distance": format!("{contact:?}").to_lowercase(),
        "coefficients": trig_json(&cs.trig_coefficients(), |x| json!(x)),
        "samples": samples,
    }))
}

/// The two curve points at an angle where `u = -A +- sqrt(disc)` and `sqrt(disc)` is not
/// available in the radical field: coordinates `p + q sqrt(disc)` computed over `Q[w]` modulo
/// `w^2 - disc`, and the exact check that both lie on the sphere and the cylinder (the surface
/// equations reduce to 0 modulo `w^2 - disc`).
fn quadratic_points(
    cs: &CylinderSphere<Rational>,
    angle: &Angle<Rational>,
    a: &Rational,
    disc: &Rational,
) -> (Vec<QuadPoint>, bool) {
    use exactcheck_exact::poly::Poly;
    type P = Poly<Rational>;
    let k = |q: &Rational| P::constant(q.clone());
    let w = P::var(0);
    let relation = [w.square() - k(disc)];
    let pcs = CylinderSphere {
        a: k(&cs.a),
        b: k(&cs.b),
        r: k(&cs.r),
        beta: Angle {
            cos: k(&cs.beta.cos),
            sin: k(&cs.beta.sin),
        },
        gamma: Angle {
            cos: k(&cs.gamma.cos),
            sin: k(&cs.gamma.sin),
        },
        center: cs.center.map(k),
        radius: k(&cs.radius),
    };
    let (axis_q, axis_d) = pcs.axis_polynomial();
    let sqrt_d = disc.to_f64().sqrt();
    let mut ok = true;
    let mut pts = Vec::new();
    for sign in [-1i64, 1] {
        let u = k(&a.neg_ref()) + w.scale_i64(sign);
        let x = pcs.point(&k(&angle.cos), &k(&angle.sin), &u);
        let sphere = ((&x - &pcs.center).norm_squared() - pcs.radius.square()).reduce(&relation);
        let cyl = ((&x - &axis_q).cross(&axis_d).norm_squared() - pcs.r.square()).reduce(&relation);
        ok &= sphere.is_zero() && cyl.is_zero();
        let coord = |c: &P| {
            let p0 = c.coefficient(&[]);
            let p1 = c.coefficient(&[(0, 1)]);
            let text = if p1.is_zero() {
                p0.to_string()
            } else {
                format!("{p0} + {p1}*sqrt({disc})")
            };
            let f = |q: &Rational| q.to_f64();
            (text, f(&p0) + f(&p1) * sqrt_d)
        };
        let (cx, cy, cz) = (coord(&x.x), coord(&x.y), coord(&x.z));
        pts.push(([cx.0, cy.0, cz.0], [cx.1, cy.1, cz.1]));
    }
    (pts, ok)
}
