//! Algebraic constants and angles in the randomized identity test: the sides are rewritten
//! exactly as the exact path rewrites them, then tested modulo `p` (see the module
//! documentation of [`super`], "Constants and angles").
//!
//! * The constants (`sqrt(2)`, `cos(pi/8)`, `sqrt(2 + sqrt(3))`, the multiples of pi of angles
//!   with variables) are abstracted by [`crate::expr::abstract_constants`] and put in one
//!   field with a primitive element `c` by [`AlgebraicConstants`], as `prove` does without
//!   `--random`: each side becomes a tree over Q in the variables and `c`, with `m(c) = 0`.
//! * The angles are expanded by [`crate::expr::expand_angles`] (the conversion's multiple-angle
//!   and addition formulas) into polynomials in `cos(x)`, `sin(x)`, which are sampled on the unit
//!   circle; `tan` stays a quotient, whose poles are skipped.
//! * A point where the sides differ modulo `p` is confirmed by an exact evaluation of the same
//!   trees at rational points in `Q(theta)` ([`confirm`]) before the identity is said to fail.

use super::ring::{constant_exponent, eval, EvalError, ExactField, Rationals, Values};
use crate::expr::{
    abstract_constants, angle_of, angle_variable, cos_name, describe_point, expand_angles_in,
    has_trig, lindemann_weierstrass, register_angle_bases, sin_name, Expr, ExprKind, PI,
};
use crate::poly::Vars;
use crate::prove::{small_height_rationals, AlgebraicConstants, CONSTANT_ATTEMPTS};
use crate::Rational;
use exactcheck_core::limits;
use exactcheck_core::{Ring, Rng};
use num_bigint::BigInt;
use std::collections::HashMap;

/// Whether a side has a square root or an angle: the identity then takes this path.
pub(crate) fn needs_preparation(e: &Expr) -> bool {
    has_trig(e) || crate::expr::library::has_sqrt(e)
}

/// What the field of the constants adds to the error bound.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldBound {
    /// `n`, the degree of the primitive element's minimal polynomial `m`.
    pub degree: u64,
    /// `log2 ||m||_1 <= modulus_bits` (`m` primitive with integer coefficients).
    pub modulus_bits: u64,
    /// `log2 |lc(m)| < lead_bits`.
    pub lead_bits: u64,
}

/// The identity rewritten for the test.
pub(crate) struct Prepared {
    /// The sides, over Q in the variables, the angles' `cos(x)`, `sin(x)` and `c`.
    pub lhs: Expr,
    pub rhs: Expr,
    /// The constants' field, when a side has an irrational constant.
    pub constants: Option<AlgebraicConstants>,
    /// The unit circles `(cos(x), sin(x))` of the angles.
    pub angle_circles: Vec<(String, String)>,
    /// The angles `x`.
    pub angles: Vec<String>,
    /// Whether a side has `tan` (a quotient with the side condition `cos != 0`).
    pub tan: bool,
}

impl Prepared {
    /// The integer coefficients of `m` (constant first) and its [`FieldBound`].
    pub fn modulus(&self) -> Option<(Vec<BigInt>, FieldBound)> {
        let k = self.constants.as_ref()?;
        let m = k.field.modulus().primitive_part();
        let coeffs: Vec<BigInt> = m.coeffs().iter().map(|q| q.numer()).collect();
        let norm: BigInt = coeffs
            .iter()
            .map(|a| a.magnitude().clone())
            .sum::<num_bigint::BigUint>()
            .into();
        let lead = coeffs.last().expect("m has a leading coefficient");
        let bound = FieldBound {
            degree: m.degree() as u64,
            modulus_bits: norm.bits(),
            lead_bits: lead.bits(),
        };
        Some((coeffs, bound))
    }
}

fn calls_tan(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => false,
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => calls_tan(x),
        ExprKind::Pow(a, b) => calls_tan(a) || calls_tan(b),
        ExprKind::Sum(ts) => ts.iter().any(|(_, t)| calls_tan(t)),
        ExprKind::Product(fs) => fs.iter().any(|(_, f)| calls_tan(f)),
        ExprKind::Call(n, args) => n == "tan" || args.iter().any(calls_tan),
    }
}

/// Rewrites both (lowered) sides; `taken` are the names the generator must avoid.
///
/// # Errors
/// A constant the evaluator refuses (`tan(pi/2)`, `sqrt(-2)`), the field of the constants past
/// a limit, an angle that is not a rational combination of variables plus constants.
pub(crate) fn prepare(lhs: &Expr, rhs: &Expr, taken: &[String]) -> Result<Prepared, String> {
    let tan = calls_tan(lhs) || calls_tan(rhs);
    let mut leaves = Vec::new();
    let l = abstract_constants(lhs, &mut leaves).map_err(|e| e.to_string())?;
    let r = abstract_constants(rhs, &mut leaves).map_err(|e| e.to_string())?;
    let texts: Vec<String> = leaves.iter().map(|l| l.text.clone()).collect();
    let constants = AlgebraicConstants::new(leaves, taken)
        .map_err(|e| format!("the field of the constants {}: {e}", texts.join(", ")))?;
    let (l, r) = match &constants {
        Some(k) => (k.fill(&l), k.fill(&r)),
        None => (l, r),
    };
    // Both sides expand in the same base angles (`x/2` for `sin(x/2)` and `sin(x)`).
    let mut bases = Vars::new();
    register_angle_bases(&[&l, &r], &mut bases).map_err(|e| e.to_string())?;
    let (l, r) = (
        expand_angles_in(&l, &mut bases).map_err(|e| e.to_string())?,
        expand_angles_in(&r, &mut bases).map_err(|e| e.to_string())?,
    );
    let mut names = Vec::new();
    l.collect_variables(&mut names);
    r.collect_variables(&mut names);
    let mut angles: Vec<String> = Vec::new();
    for n in &names {
        if let Some((a, _)) = angle_of(n) {
            if !angles.iter().any(|b| b == a) {
                angles.push(a.to_string());
            }
        }
    }
    let angle_circles = angles.iter().map(|a| (cos_name(a), sin_name(a))).collect();
    Ok(Prepared {
        lhs: l,
        rhs: r,
        constants,
        angle_circles,
        angles,
        tan,
    })
}

/// An exact counter-example: the point (angles as their cosine and sine) and `LHS - RHS`
/// there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactPoint {
    /// `x = 1`, `x = angle with cos x = 3/5, sin x = 4/5`.
    pub point: Vec<String>,
    /// `LHS - RHS` there, exactly (not zero).
    pub value: String,
}

/// The largest exponent of a power in the tree.
fn max_exponent(e: &Expr) -> u64 {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => 0,
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => max_exponent(x),
        ExprKind::Pow(a, b) => max_exponent(a).max(constant_exponent(b).unwrap_or(u64::MAX)),
        ExprKind::Sum(ts) => ts.iter().map(|(_, t)| max_exponent(t)).max().unwrap_or(0),
        ExprKind::Product(fs) => fs.iter().map(|(_, f)| max_exponent(f)).max().unwrap_or(0),
        ExprKind::Call(_, args) => args.iter().map(max_exponent).max().unwrap_or(0),
    }
}

/// `LHS - RHS` of the prepared sides at an exact point, in `ring`; `None` at a pole or where it
/// is zero.
fn difference<R: Values>(
    p: &Prepared,
    ring: &R,
    point: &HashMap<String, R::V>,
    generator: &str,
) -> Option<R::V> {
    let constant = |v: &str| v == generator;
    let refused = |e: &Expr| format!("{e} is not evaluated");
    let l = eval(&p.lhs, ring, point, &constant, &refused);
    let r = eval(&p.rhs, ring, point, &constant, &refused);
    match (l, r) {
        (Ok(a), Ok(b)) => {
            let d = ring.sub(&a, &b);
            (!ring.is_zero(&d)).then_some(d)
        }
        (Err(EvalError::Input(_)), _) | (_, Err(EvalError::Input(_))) => None,
        _ => None,
    }
}

/// Searches an exact counter-example to the prepared identity after the test modulo `p` found
/// the sides different: rational values of the variables (small heights first), rational points
/// of the unit circles (`circles`, the angles' and the user's), `c = theta`; `LHS - RHS`
/// evaluated exactly in `Q(theta)`. `free` are the other variables.
///
/// # Errors
/// Why no exact counter-example can be given or none was found.
pub(crate) fn confirm(
    p: &Prepared,
    free: &[String],
    circles: &[(String, String)],
) -> Result<ExactPoint, String> {
    // Pi outside an angle is an indeterminate: LHS - RHS non-zero at a rational value of it is
    // a non-zero rational function of pi over the algebraic numbers, hence not zero at pi
    // (transcendental), at the same values of the other variables. With a constant angle
    // (`sin(1)`) that would need pi and the angle's cosine and sine algebraically independent,
    // which is not known.
    let pi_free = free.iter().any(|v| v == PI);
    if pi_free {
        if let Some(u) = p.angles.iter().find(|a| angle_variable(a).is_none()) {
            return Err(format!(
                "pi occurs outside an angle next to the constant angle {u}, and whether pi and \
                 cos({u}) + i sin({u}) are algebraically independent is not known"
            ));
        }
    }
    let mixed: Vec<String> = p
        .angles
        .iter()
        .filter_map(|a| angle_variable(a))
        .filter(|x| free.contains(x))
        .collect();
    if !mixed.is_empty() {
        return Err(format!(
            "{} {} both as a number and as an angle of sin, cos or tan, and a rational point gives the number and the angle's cosine and sine independent values",
            mixed.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", "),
            if mixed.len() == 1 { "occurs" } else { "occur" }
        ));
    }
    let limit = limits::EXPONENT.get();
    if max_exponent(&p.lhs).max(max_exponent(&p.rhs)) > limit {
        return Err(format!(
            "an exponent above {limit} (the exponent limit) is not evaluated exactly"
        ));
    }
    let heights = small_height_rationals(12);
    let list: Vec<Rational> = heights.iter().take(24).cloned().collect();
    let generator = p.constants.as_ref().map_or("", |k| k.name.as_str());
    let mut rng = Rng::new(0x5EED_00C1);
    for attempt in 0..CONSTANT_ATTEMPTS {
        let reach = list.len().min(2 + attempt / 8);
        let mut pick = || {
            if attempt == 0 {
                list[0].clone()
            } else {
                list[rng.below(reach as u64) as usize].clone()
            }
        };
        let mut values: Vec<(String, Rational)> = Vec::new();
        for (c, s) in circles {
            let t = pick();
            let t2 = t.square();
            let den = (Rational::ONE + &t2)
                .recip()
                .expect("1 + t^2 >= 1 is not zero");
            values.push((c.clone(), (Rational::ONE - &t2) * &den));
            values.push((s.clone(), t.scale_i64(2) * &den));
        }
        for v in free {
            values.push((v.clone(), pick()));
        }
        let value = match &p.constants {
            Some(k) => {
                let ring = ExactField(&k.field);
                let mut point: HashMap<String, _> = values
                    .iter()
                    .map(|(v, q)| (v.clone(), crate::univariate::UPoly::constant(q.clone())))
                    .collect();
                point.insert(k.name.clone(), crate::univariate::UPoly::x());
                difference(p, &ring, &point, generator).map(|d| k.field.value(&d).to_string())
            }
            None => {
                let point: HashMap<String, Rational> = values.iter().cloned().collect();
                difference(p, &Rationals, &point, generator).map(|d| d.to_string())
            }
        };
        if let Some(value) = value {
            let shown: Vec<(String, String)> = values
                .iter()
                .map(|(v, q)| (v.clone(), q.to_string()))
                .collect();
            // The constant angle's cosine and sine took a rational point of their circle, not
            // their values: LHS - RHS, a polynomial in them, is non-zero there, so non-zero
            // modulo the circle, and at the angle itself by Lindemann–Weierstrass.
            let pi_value = shown.iter().find(|(v, _)| v == PI).map(|(_, q)| q.clone());
            let shown: Vec<(String, String)> = shown.into_iter().filter(|(v, _)| v != PI).collect();
            if let Some(q) = pi_value {
                return Ok(ExactPoint {
                    point: describe_point(&shown),
                    value: format!(
                        "{value} with pi replaced by {q} (so LHS - RHS{} is a non-zero \
                         rational function of pi over the algebraic numbers, and pi, which is \
                         transcendental, is no root of it)",
                        if shown.is_empty() {
                            ""
                        } else {
                            " at this point"
                        }
                    ),
                });
            }
            let value = match p.angles.iter().find(|a| angle_variable(a).is_none()) {
                Some(u) => {
                    let at = |n: String| {
                        shown
                            .iter()
                            .find(|(v, _)| *v == n)
                            .map_or("?", |(_, q)| q.as_str())
                    };
                    format!(
                        "{value} at the point cos({u}) = {}, sin({u}) = {} of their circle, so it is {}",
                        at(cos_name(u)),
                        at(sin_name(u)),
                        lindemann_weierstrass(u)
                    )
                }
                None => value,
            };
            return Ok(ExactPoint {
                point: describe_point(&shown),
                value,
            });
        }
    }
    Err(format!(
        "no rational point among {CONSTANT_ATTEMPTS} tried makes LHS - RHS non-zero exactly"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;

    fn prepared(l: &str, r: &str) -> Prepared {
        prepare(
            &parse_expr(l).unwrap(),
            &parse_expr(r).unwrap(),
            &["x".into()],
        )
        .unwrap()
    }

    #[test]
    fn constants_and_angles_are_rewritten() {
        let p = prepared("(x + sqrt(2))^2", "x^2 + 2*x*sqrt(2) + 2");
        let k = p.constants.as_ref().unwrap();
        assert_eq!(k.field.degree(), 2);
        let (m, b) = p.modulus().unwrap();
        assert_eq!(m.len(), 3);
        assert_eq!(b.degree, 2);
        let p = prepared("sin(3*x)", "3*sin(x) - 4*sin(x)^3");
        assert!(p.constants.is_none());
        assert_eq!(p.angles, ["x"]);
        assert_eq!(
            p.angle_circles,
            [("cos(x)".to_string(), "sin(x)".to_string())]
        );
        let p = prepared("tan(x + y)", "(tan(x) + tan(y))/(1 - tan(x)*tan(y))");
        assert!(p.tan && p.constants.is_none());
        assert_eq!(p.angles, ["x", "y"]);
        let p = prepared("tan(x + pi/4)", "(1 + tan(x))/(1 - tan(x))");
        assert!(p.tan && p.constants.is_some());
        let err = prepare(
            &parse_expr("tan(pi/2)").unwrap(),
            &parse_expr("0").unwrap(),
            &[],
        );
        assert!(err.is_err());
    }

    #[test]
    fn exact_confirmation() {
        let p = prepared("(x + sqrt(2))^2", "x^2 + 2*x*sqrt(3) + 2");
        let found = confirm(&p, &["x".into()], &[]).unwrap();
        // x = 0 gives 0; x = 1 gives 2 sqrt(2) - 2 sqrt(3).
        assert_eq!(found.point, ["x = 1"]);
        let want: crate::Algebraic = "2*sqrt(2) - 2*sqrt(3)".parse().unwrap();
        assert_eq!(found.value, want.to_string());
        let p = prepared("cos(x + y)", "cos(x)*cos(y) + sin(x)*sin(y)");
        let found = confirm(&p, &[], &p.angle_circles.clone()).unwrap();
        assert!(
            found.point[0].starts_with("x = angle with cos x = "),
            "{found:?}"
        );
        let p = prepared("sin(x)^2 + cos(x)^2", "1");
        assert!(confirm(&p, &[], &p.angle_circles.clone()).is_err());
        let p = prepared("x + sin(x)", "x");
        assert!(confirm(&p, &["x".into()], &p.angle_circles.clone()).is_err());
    }

    use super::super::{random_identity_test, RandomDecision, Seed};
    use proptest::prelude::*;

    fn test(l: &str, r: &str, seed: u64) -> RandomDecision {
        let (l, r) = (parse_expr(l).unwrap(), parse_expr(r).unwrap());
        let mut names = Vec::new();
        l.collect_variables(&mut names);
        r.collect_variables(&mut names);
        random_identity_test(&l, &r, &names, &[], 6, Seed::Fresh(seed)).unwrap()
    }

    const CONSTANTS: [(&str, &str); 4] = [
        // (K, an expression of K^2 through other constants of its field).
        ("sqrt(2)", "2"),
        ("cos(pi/5)", "(3 + sqrt(5))/8"),
        ("sqrt(2 + sqrt(3))", "2 + sqrt(3)"),
        ("cos(2*pi/7)", "(1 + cos(4*pi/7))/2"),
    ];

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]
        /// `(a K + b)(x + c K) = a x K + a c K^2 + b x + b c K` with `K^2` written through the
        /// field's other constants holds; with `delta K` added to one side it fails, and the
        /// exact value is `-delta K`, as the real algebraic numbers compute it on their own.
        #[test]
        fn field_identities_hold_and_perturbed_ones_fail(
            which in 0usize..4, a in -4i64..=4, b in -4i64..=4, c in -4i64..=4,
            delta in 1i64..=3, seed in any::<u64>(),
        ) {
            let (k, k2) = CONSTANTS[which];
            let lhs = format!("({a}*{k} + {b})*(x + {c}*{k})");
            let rhs = format!("{a}*x*{k} + {}*({k2}) + {b}*x + {}*{k}", a * c, b * c);
            let d = test(&lhs, &rhs, seed);
            prop_assert!(matches!(d, RandomDecision::Holds { .. }), "{lhs} = {rhs}: {d:?}");
            let wrong = format!("{rhs} + {delta}*{k}");
            match test(&lhs, &wrong, seed) {
                RandomDecision::Refuted { exact, .. } => {
                    let want: crate::Algebraic = format!("-{delta}*{k}").parse().unwrap();
                    prop_assert_eq!(exact.value, want.to_string());
                }
                other => prop_assert!(false, "{lhs} = {wrong}: {other:?}"),
            }
        }

        /// The addition formulas on random integer combinations of two angles hold; with the
        /// sign of the second term flipped they fail at an exact angle.
        #[test]
        fn angle_sums_hold_and_wrong_signs_fail(
            a in -3i64..=3, b in -3i64..=3, sine in any::<bool>(), seed in any::<u64>(),
        ) {
            prop_assume!(a != 0 && b != 0);
            let (u, v) = (format!("{a}*x"), format!("{b}*y"));
            let (lhs, right, wrong) = if sine {
                (
                    format!("sin({u} + {v})"),
                    format!("sin({u})*cos({v}) + cos({u})*sin({v})"),
                    format!("sin({u})*cos({v}) - cos({u})*sin({v})"),
                )
            } else {
                (
                    format!("cos({u} + {v})"),
                    format!("cos({u})*cos({v}) - sin({u})*sin({v})"),
                    format!("cos({u})*cos({v}) + sin({u})*sin({v})"),
                )
            };
            let d = test(&lhs, &right, seed);
            prop_assert!(matches!(d, RandomDecision::Holds { .. }), "{lhs} = {right}: {d:?}");
            let d = test(&lhs, &wrong, seed);
            prop_assert!(matches!(d, RandomDecision::Refuted { .. }), "{lhs} = {wrong}: {d:?}");
        }
    }
}
