//! The exact answer of `cylinder_sphere` over Q: the analysis of the discriminant, sample
//! points in the square-root field, the touching points or circle.

use super::answer::{
    CircleApprox, Coefficients, CurvePoint, End, ExactAnswer, Parametrization, PointText, Sample,
    TangentCircle, TangentPoint, TauApprox,
};
use super::input::{configuration, exact_angle, Input};
use super::{approx3, contact_name, on_both, strings};
use crate::solve::number::RationalNumber;
use crate::Error;
use exactcheck_core::cylinder_sphere::{unit_circle_point, Angle, Contact, CylinderSphere};
use exactcheck_core::limits::LimitError;
use exactcheck_core::{OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::{Bound, RootBoundedInterval, RootInterval};
use exactcheck_exact::{Radical, Rational};
use num_rational::BigRational;
use num_traits::One;

pub(super) fn exact(input: Input<RationalNumber>) -> Result<ExactAnswer, Error> {
    let mut notes = Vec::new();
    let (cs, n_samples) = configuration(
        &input,
        |x| x.0.clone(),
        |a, p| exact_angle(a, p, &mut notes, |x| x.0.clone(), Rational::clone),
    )?;
    let width = match &input.precision {
        None => None,
        Some(RationalNumber(w)) => {
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision must be positive".into()));
            }
            crate::solve::number::check_precision(w)?;
            Some(w.clone())
        }
    };
    let analysis = analyze(&cs);
    let by_distance = cs.contact_by_distance();
    let coeffs = cs.trig_coefficients();
    let p = &analysis.discriminant;
    let taus = sample_taus(n_samples, &analysis.nonnegative);
    let lift = |q: &Rational| Radical::from(q);
    let rcs = cs.map(lift);
    let mut samples = Vec::new();
    let mut points = Vec::new();
    let mut all_on_both = true;
    for tau in &taus {
        if p.sign_at(tau) == Sign::Negative {
            continue;
        }
        let angle = unit_circle_point(tau).expect("1 + tau^2 > 0 for rational tau");
        let (a, b) = cs.coefficients_at(&angle.cos, &angle.sin);
        let disc = a.square() - &b;
        // u and the points: in the radical field, or in Q(w), w^2 = disc, when the radicand
        // cannot be certified square-free or is too big to factor quickly (the square-free
        // part needs a factorization: a few hundred digits already take seconds).
        let small =
            disc.numer().bits() <= MAX_FACTORED_BITS && disc.denom().bits() <= MAX_FACTORED_BITS;
        let root = if small {
            Radical::sqrt_rational(&disc)
        } else {
            None
        };
        let (us, pts): (Vec<String>, Vec<PointText>) = match root {
            None => {
                let (pts, ok) = quadratic_points(&cs, &angle, &a, &disc);
                all_on_both &= ok;
                let minus_a = a.neg_ref();
                (
                    vec![
                        format!("{minus_a} - sqrt({disc})"),
                        format!("{minus_a} + sqrt({disc})"),
                    ],
                    pts,
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
                all_on_both &= pts.iter().all(|x| on_both(&rcs, x));
                (
                    us.iter().map(ToString::to_string).collect(),
                    pts.iter().map(|x| (strings(x), approx3(x))).collect(),
                )
            }
        };
        samples.push(Sample {
            tau: tau.to_string(),
            cos: angle.cos.to_string(),
            sin: angle.sin.to_string(),
            t_degrees: 2.0 * tau.to_f64().atan().to_degrees(),
            u: us,
            points: pts.iter().map(|p| p.0.clone()).collect(),
        });
        points.extend(
            pts.into_iter()
                .map(|(exact, approx)| CurvePoint { exact, approx }),
        );
    }
    // Touching points: every multiple root of the discriminant.
    let mut tangent_points = Vec::new();
    for tp in &analysis.tangent_params {
        let (angle, tau_text) = match touching_angle(tp.as_ref(), |r, w| p.try_refine(r, w))? {
            Ok(at) => at,
            Err(isolated) => {
                tangent_points.push(isolated);
                continue;
            }
        };
        let (a, _) = cs.coefficients_at(&angle.cos, &angle.sin);
        let x = cs.point(&angle.cos, &angle.sin, &a.neg_ref());
        let ok = on_both(&cs, &x);
        all_on_both &= ok;
        let xr = x.map(lift);
        tangent_points.push(TangentPoint::Exact {
            tau: tau_text,
            point: strings(&x),
            approx: approx3(&xr),
            on_both_surfaces: ok,
        });
    }
    let tangent_circle = analysis
        .touching_circle
        .then(|| tangent_circle(&cs, Rational::to_f64));
    if let Some(c) = &tangent_circle {
        all_on_both &= c.on_both_surfaces;
    }
    let intervals = interval_ends(&analysis.nonnegative, |r, w| p.try_refine(r, w), &width)?;
    Ok(ExactAnswer {
        kind: "cylinder_sphere",
        mode: "exact",
        intersects: analysis.contact != Contact::Disjoint,
        contact: contact_name(analysis.contact),
        contact_by_axis_distance: contact_name(by_distance),
        methods_agree: analysis.contact == by_distance
            && analysis.touching() == Some(cs.touching_by_distance()),
        components: analysis.components,
        tangent_points,
        tangent_circle,
        coefficients: Coefficients::new(&coeffs, ToString::to_string),
        parametrization: Parametrization {
            angle: "cos t = (1 - tau^2)/(1 + tau^2), sin t = 2*tau/(1 + tau^2) (tau = infinity at t = pi)",
            u: "-A(t) +- sqrt(P(tau))/(1 + tau^2)",
            p: p.display("tau").to_string(),
            point: "Rx(gamma) Ry(beta) (a + r cos t, b + r sin t, u)",
            real_for_tau_in: intervals,
            real_at_t_pi: analysis.sign_at_pi != Sign::Negative,
        },
        samples,
        points,
        all_points_on_both_surfaces: all_on_both,
        approximated_angles: notes,
        float: None,
    })
}

/// The angle of a touching parameter (a multiple root of the discriminant, `None` for
/// `t = pi`) with its printed `tau`, when the root is rational; otherwise the isolated touching
/// point, its interval refined by `refine` to width `2^-40`.
///
/// # Errors
/// The refinement's limit error.
pub(super) fn touching_angle(
    tp: Option<&RootInterval>,
    refine: impl FnOnce(&RootInterval, &Rational) -> Result<RootInterval, LimitError>,
) -> Result<Result<(Angle<Rational>, String), TangentPoint>, Error> {
    Ok(match tp {
        None => Ok((
            Angle {
                cos: Rational::from_integer(-1),
                sin: Rational::ZERO,
            },
            "infinity (t = pi)".to_string(),
        )),
        Some(ri) => match ri.exact_value() {
            Some(v) => Ok((
                unit_circle_point(v).expect("1 + tau^2 > 0 for rational tau"),
                v.to_string(),
            )),
            None => {
                let w = Rational::new(1, 1 << 40).expect("2^40 != 0");
                let refined = refine(ri, &w)?;
                Err(TangentPoint::Isolated {
                    tau_interval: [refined.lo.to_string(), refined.hi.to_string()],
                    approx: TauApprox {
                        tau: refined.to_f64(),
                    },
                })
            }
        },
    })
}

/// Sample parameters: rational tau on a grid of `n_samples` angles (without t = pi), plus one
/// inside every interval where the discriminant is `>= 0`; sorted, without repetitions.
pub(super) fn sample_taus(n_samples: usize, nonnegative: &[RootBoundedInterval]) -> Vec<Rational> {
    let half = Rational::new(1, 2).expect("2 != 0");
    let mut taus: Vec<Rational> = Vec::new();
    for k in 0..n_samples {
        let t = std::f64::consts::TAU * k as f64 / n_samples as f64;
        if (t - std::f64::consts::PI).abs() > 1e-9 {
            let (_, tau, _) = exactcheck_exact::cylinder_sphere::rational_angle(t, 1000);
            taus.push(tau);
        }
    }
    for iv in nonnegative {
        let mid = match (&iv.lo, &iv.hi) {
            (Bound::Root(a), Bound::Root(b)) => (a.midpoint() + b.midpoint()) * &half,
            (Bound::NegInf, Bound::Root(b)) => b.lo.clone() - Rational::ONE,
            (Bound::Root(a), Bound::PosInf) => a.hi.clone() + Rational::ONE,
            // The whole line (an interval never starts at +inf or ends at -inf).
            _ => Rational::ZERO,
        };
        taus.push(mid);
    }
    taus.sort();
    taus.dedup();
    taus
}

/// The real tau-intervals with their ends: exact, infinite, or isolated (refined by `refine` to
/// the width `width` when one is asked for).
pub(super) fn interval_ends<E>(
    nonnegative: &[RootBoundedInterval],
    refine: impl Fn(&RootInterval, &Rational) -> Result<RootInterval, E>,
    width: &Option<Rational>,
) -> Result<Vec<[End; 2]>, Error>
where
    Error: From<E>,
{
    let refine = |r: &RootInterval| -> Result<RootInterval, Error> {
        match width {
            Some(w) if !r.is_exact() => Ok(refine(r, w)?),
            _ => Ok(r.clone()),
        }
    };
    let end = |x: &Bound| -> Result<End, Error> {
        Ok(match x {
            Bound::NegInf => End::Exact("-inf".into()),
            Bound::PosInf => End::Exact("+inf".into()),
            Bound::Root(r) => match r.exact_value() {
                Some(v) => End::Exact(v.to_string()),
                None => {
                    let r = refine(r)?;
                    End::Isolated {
                        interval: [r.lo.to_string(), r.hi.to_string()],
                        approx: r.to_f64(),
                    }
                }
            },
        })
    };
    nonnegative
        .iter()
        .map(|iv| Ok([end(&iv.lo)?, end(&iv.hi)?]))
        .collect()
}

/// The largest numerator or denominator (in bits) of a sample's discriminant that is factored
/// to write its square root in the radical field; bigger ones use `Q[w]/(w^2 - D)`.
const MAX_FACTORED_BITS: u64 = 256;

/// The touching circle of a configuration whose discriminant vanishes identically: centre and
/// radius from the geometry (the sphere's centre on the axis, the cylinder's radius), `u` from
/// `A` at `t = 0`, and the exact check at four of its points.
pub(super) fn tangent_circle<T: OrderedField + std::fmt::Display>(
    cs: &CylinderSphere<T>,
    to_f64: impl Fn(&T) -> f64,
) -> TangentCircle {
    let (_, normal) = cs.axis();
    let (a0, _) = cs.coefficients_at(&T::one(), &T::zero());
    let u = a0.neg_ref();
    let quarter_turns = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    let ok = quarter_turns.iter().all(|&(c, s)| {
        let (c, s) = (T::from_i64(c), T::from_i64(s));
        let x = cs.point(&c, &s, &u);
        let rel = &x - &cs.center;
        on_both(cs, &x) && rel.norm_squared() == cs.r.square() && rel.dot(&normal).is_zero()
    });
    TangentCircle {
        center: strings(&cs.center),
        radius: cs.r.to_string(),
        normal: strings(&normal),
        u: u.to_string(),
        on_both_surfaces: ok,
        approx: CircleApprox {
            center: [
                to_f64(&cs.center.x) + 0.0,
                to_f64(&cs.center.y) + 0.0,
                to_f64(&cs.center.z) + 0.0,
            ],
            radius: to_f64(&cs.r),
        },
    }
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
) -> (Vec<PointText>, bool) {
    use exactcheck_exact::poly::Poly;
    type P = Poly<Rational>;
    let k = |q: &Rational| P::constant(q.clone());
    let w = P::var(0);
    let relation = [w.square() - k(disc)];
    let pcs = cs.map(k);
    let (axis_q, axis_d) = pcs.axis_polynomial();
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
                let sign = p1.sign();
                plus_sqrt_term(
                    &p0.to_string(),
                    sign,
                    &p1.abs().to_string(),
                    &disc.to_string(),
                )
            };
            // The one conversion of sums of roots: finite and NaN-free where the terms alone
            // leave f64's range.
            let approx = exactcheck_exact::to_f64::sum_of_roots_to_f64(&[
                (p0.to_big_rational(), BigRational::one()),
                (p1.to_big_rational(), disc.to_big_rational()),
            ]);
            (text, approx + 0.0)
        };
        let (cx, cy, cz) = (coord(&x.x), coord(&x.y), coord(&x.z));
        pts.push(([cx.0, cy.0, cz.0], [cx.1, cy.1, cz.1]));
    }
    (pts, ok)
}

/// `p0 + p1*sqrt(D)` written with the sign of `p1` as the operator (`p0 - 3*sqrt(D)`, never
/// `p0 + -3*sqrt(D)`), given `p0`, the sign of `p1`, the text of `|p1|` (parenthesized here
/// when it is a sum) and `D`.
pub(super) fn plus_sqrt_term(p0: &str, p1_sign: Sign, p1_abs: &str, disc: &str) -> String {
    let op = if p1_sign == Sign::Negative { '-' } else { '+' };
    let compound = p1_abs.contains(" + ") || p1_abs.contains(" - ");
    if compound {
        format!("{p0} {op} ({p1_abs})*sqrt({disc})")
    } else {
        format!("{p0} {op} {p1_abs}*sqrt({disc})")
    }
}
