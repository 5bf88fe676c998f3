//! The exact answer of `cylinder_sphere` over Q: the analysis of the discriminant, sample
//! points in the square-root field, the touching points or circle.

use super::answer::{exact_answer, Curve, ExactAnswer, PointText};
use super::input::{configuration, exact_angle, Input};
use super::{approx3, on_both, strings};
use crate::solve::number::RationalOrFieldNumber;
use crate::Error;
use exactcheck_core::cylinder_sphere::{unit_circle_point, Angle, CylinderSphere};
use exactcheck_core::{OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::cylinder_sphere::analyze;
use exactcheck_exact::univariate::{Bound, RootBoundedInterval};
use exactcheck_exact::{Radical, Rational};
use num_rational::BigRational;
use num_traits::One;

pub(super) fn exact(input: Input<RationalOrFieldNumber>) -> Result<ExactAnswer, Error> {
    let mut notes = Vec::new();
    let (cs, n_samples) = configuration(
        &input,
        |x| x.0.clone(),
        |a, p| exact_angle(a, p, &mut notes, |x| x.0.clone(), Rational::clone),
    )?;
    let width = match &input.precision {
        None => None,
        Some(RationalOrFieldNumber(w)) => {
            if w.sign() != Sign::Positive {
                return Err(Error::Input("precision must be positive".into()));
            }
            crate::solve::number::check_precision(w)?;
            Some(w.clone())
        }
    };
    let analysis = analyze(&cs);
    let p = &analysis.discriminant;
    let taus = sample_taus(n_samples, &analysis.nonnegative);
    let lift = |q: &Rational| Radical::from(q);
    let rcs = cs.map(lift);
    let mut curve = Curve::default();
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
                curve.all_on_both &= ok;
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
                curve.all_on_both &= pts.iter().all(|x| on_both(&rcs, x));
                (
                    us.iter().map(ToString::to_string).collect(),
                    pts.iter().map(|x| (strings(x), approx3(x))).collect(),
                )
            }
        };
        curve.push(tau, &angle, us, pts);
    }
    exact_answer(&cs, analysis, &width, curve, notes)
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

/// The largest numerator or denominator (in bits) of a sample's discriminant that is factored
/// to write its square root in the radical field; bigger ones use `Q[w]/(w^2 - D)`.
const MAX_FACTORED_BITS: u64 = 256;

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
