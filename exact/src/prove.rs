//! The proof engine: decide a polynomial identity `residual = 0` exactly, for all values of its
//! variables, or for all values satisfying declared relations.
//!
//! * **proved** — the residual expands to the zero polynomial, or its normal form modulo a
//!   Gröbner basis of the relations is zero (then it vanishes wherever the relations hold);
//! * **fails** — the normal form is non-zero and an exact point is found where the relations hold
//!   and the residual does not vanish; the point, the residual there and the normal form (what the
//!   two sides really differ by) are reported;
//! * **undecided** — the normal form is non-zero but no such point was found (possible only with
//!   relations other than unit circles: a non-zero normal form means "not in the ideal", which
//!   is not always "false at some real point").
//!
//! Points on unit circles `c^2 + s^2 = 1` are taken as rational points
//! `((1 - tau^2)/(1 + tau^2), 2 tau/(1 + tau^2))`, so the search stays exact.

use crate::expr::Coefficient;
use crate::poly::{groebner, Poly, Var};
use crate::Rational;
use exactcheck_core::{Field, Ring, Rng};

/// The decision on an identity.
#[derive(Clone, Debug)]
pub enum Decision<C> {
    /// The residual is zero (modulo the relations).
    Proved {
        /// Terms of the expanded residual before reduction (0 when it expanded to zero outright).
        expanded_terms: usize,
    },
    /// A counter-example: relations hold, the residual does not vanish.
    Fails {
        /// The normal form of the residual modulo the relations.
        normal_form: Poly<C>,
        /// The point: a value for every variable (by index).
        point: Vec<(Var, Rational)>,
        /// The residual's value there (non-zero).
        value: C,
    },
    /// Non-zero normal form, but no point on the relations' variety was found.
    Undecided {
        /// The normal form of the residual modulo the relations.
        normal_form: Poly<C>,
    },
}

/// Splits relations into unit-circle pairs `c^2 + s^2 - 1` (recognised up to sign) and others.
pub fn unit_circle_pairs<C: Field>(relations: &[Poly<C>]) -> (Vec<(Var, Var)>, Vec<Poly<C>>) {
    let mut pairs = Vec::new();
    let mut others = Vec::new();
    for r in relations {
        match circle_pair(r) {
            Some(p)
                if !pairs
                    .iter()
                    .any(|&(c, s): &(Var, Var)| [c, s].contains(&p.0) || [c, s].contains(&p.1)) =>
            {
                pairs.push(p)
            }
            _ => others.push(r.clone()),
        }
    }
    (pairs, others)
}

fn circle_pair<C: Field>(r: &Poly<C>) -> Option<(Var, Var)> {
    if r.len() != 3 {
        return None;
    }
    let mut squares = Vec::new();
    let mut constant = None;
    let mut square_coeff = None;
    for (m, c) in r.terms() {
        let e = m.exponents();
        match e.as_slice() {
            [] => constant = Some(c.clone()),
            [(v, 2)] => {
                if square_coeff.get_or_insert_with(|| c.clone()) != c {
                    return None;
                }
                squares.push(*v);
            }
            _ => return None,
        }
    }
    let (k, a) = (constant?, square_coeff?);
    // a c^2 + a s^2 - a = 0.
    if squares.len() == 2 && k == a.neg_ref() {
        Some((squares[0], squares[1]))
    } else {
        None
    }
}

/// A small rational `n/d`, `|n| <= 9`, `1 <= d <= 4`, for the counter-example search.
fn small_rational(rng: &mut Rng) -> Rational {
    let n = (rng.next_u64() % 19) as i64 - 9;
    let d = (rng.next_u64() % 4) as i64 + 1;
    Rational::new(n, d).unwrap_or(Rational::ZERO)
}

/// Decides `residual = 0` modulo `relations` (see the module documentation). `nvars` is the
/// number of variables in use (indices `0..nvars`).
pub fn decide<C: Field + Coefficient>(
    residual: &Poly<C>,
    relations: &[Poly<C>],
    nvars: usize,
) -> Decision<C> {
    let expanded_terms = residual.len();
    if residual.is_zero() {
        return Decision::Proved { expanded_terms: 0 };
    }
    let (pairs, others) = unit_circle_pairs(relations);
    let mut nf = residual.reduce_unit_circle(&pairs);
    if !others.is_empty() && !nf.is_zero() {
        let mut all: Vec<Poly<C>> = others.clone();
        all.extend(
            relations
                .iter()
                .filter(|r| circle_pair(r).is_some())
                .cloned(),
        );
        let basis = groebner(&all);
        nf = nf.reduce(&basis);
    }
    if nf.is_zero() {
        return Decision::Proved { expanded_terms };
    }
    if !others.is_empty() {
        return Decision::Undecided { normal_form: nf };
    }
    // Search an exact point: circle pairs from rational tau, the rest small rationals.
    let mut rng = Rng::new(0x5EED);
    for _ in 0..200 {
        let mut point: Vec<Rational> = (0..nvars).map(|_| small_rational(&mut rng)).collect();
        for &(c, s) in &pairs {
            let tau = small_rational(&mut rng);
            let t2 = tau.square();
            let den = (Rational::ONE + &t2).recip().unwrap_or(Rational::ONE);
            point[c as usize] = (Rational::ONE - &t2) * &den;
            point[s as usize] = tau.scale_i64(2) * &den;
        }
        let values: Vec<C> = point
            .iter()
            .map(|q| C::from_rational(q).unwrap_or_else(C::zero))
            .collect();
        let value = residual.eval(&values, |c| c.clone());
        if !value.is_zero() {
            let point = point
                .into_iter()
                .enumerate()
                .map(|(i, q)| (i as Var, q))
                .collect();
            return Decision::Fails {
                normal_form: nf,
                point,
                value,
            };
        }
    }
    Decision::Undecided { normal_form: nf }
}

// ------------------------------------------------------------------ randomized identity testing

use crate::expr::{AddOp, Expr, ExprKind, MulOp};
use crate::modp::{schwartz_zippel_log2_bound, ModP};
use std::collections::HashMap;

/// An upper bound on the total degree of the polynomial an expression denotes (`None` where it
/// is not a polynomial expression: a non-constant divisor or exponent, or a square root of a
/// non-constant).
pub fn degree_bound(e: &Expr) -> Option<u64> {
    match &e.kind {
        ExprKind::Number(_) => Some(0),
        ExprKind::Var(_) => Some(1),
        ExprKind::Neg(x) => degree_bound(x),
        ExprKind::Sum(ts) => ts
            .iter()
            .map(|(_, t)| degree_bound(t))
            .try_fold(0, |a, d| Some(a.max(d?))),
        ExprKind::Product(fs) => fs.iter().try_fold(0u64, |a, (op, f)| {
            let d = degree_bound(f)?;
            match op {
                MulOp::Times => a.checked_add(d),
                MulOp::Divide if d == 0 => Some(a),
                MulOp::Divide => None,
            }
        }),
        ExprKind::Pow(b, x) => {
            if degree_bound(x)? != 0 {
                return None;
            }
            let k = constant_exponent(x)?;
            degree_bound(b)?.checked_mul(k)
        }
        ExprKind::Sqrt(x) => (degree_bound(x)? == 0).then_some(0),
    }
}

fn constant_exponent(e: &Expr) -> Option<u64> {
    match &e.kind {
        ExprKind::Number(q) if q.is_integer() => q.numer().try_into().ok(),
        _ => None,
    }
}

/// Evaluates an expression at a point modulo p = 2^61 - 1, without expanding it.
///
/// # Errors
/// A message for a variable without a value, a divisor that vanishes mod p, a non-constant or
/// negative exponent, or a square root (no square roots are taken mod p).
pub fn eval_modp(e: &Expr, point: &HashMap<String, ModP>) -> Result<ModP, String> {
    Ok(match &e.kind {
        ExprKind::Number(q) => ModP::from_rational(q)
            .map_err(|_| format!("the number {q} has a denominator divisible by p"))?,
        ExprKind::Var(v) => *point.get(v).ok_or_else(|| format!("no value for {v}"))?,
        ExprKind::Neg(x) => -eval_modp(x, point)?,
        ExprKind::Sum(ts) => {
            let mut acc = ModP::ZERO;
            for (op, t) in ts {
                let v = eval_modp(t, point)?;
                match op {
                    AddOp::Plus => acc += v,
                    AddOp::Minus => acc -= v,
                }
            }
            acc
        }
        ExprKind::Product(fs) => {
            let mut acc = ModP::ONE;
            for (op, f) in fs {
                let v = eval_modp(f, point)?;
                match op {
                    MulOp::Times => acc *= v,
                    MulOp::Divide => {
                        acc *= v
                            .inv()
                            .map_err(|_| "a divisor vanishes modulo p".to_string())?
                    }
                }
            }
            acc
        }
        ExprKind::Pow(b, x) => {
            let k =
                constant_exponent(x).ok_or("exponents must be non-negative integer constants")?;
            eval_modp(b, point)?.pow_u64(k)
        }
        ExprKind::Sqrt(_) => {
            return Err("square roots are not available modulo p (use exact expansion)".into())
        }
    })
}

/// The outcome of a randomized identity test.
#[derive(Clone, Debug, PartialEq)]
pub enum RandomDecision {
    /// Zero at every random point: a non-zero residual would vanish at all of them with
    /// probability at most `2^log2_bound` (Schwartz–Zippel).
    Holds {
        /// Points tried.
        trials: u32,
        /// The total-degree bound used.
        degree: u64,
        /// log2 of the error probability bound.
        log2_bound: f64,
    },
    /// Non-zero at a point modulo p: the identity is false (over Q as well).
    Fails {
        /// The point, as residues.
        point: Vec<(String, ModP)>,
        /// The residual there.
        value: ModP,
    },
}

/// Tests `lhs = rhs` at `trials` random points modulo p = 2^61 - 1 (variables on unit circles
/// `(c, s)` are drawn as `((1 - tau^2)/(1 + tau^2), 2 tau/(1 + tau^2))`), without expanding.
///
/// # Errors
/// A message when the expressions are not polynomial or cannot be evaluated modulo p.
pub fn random_identity_test(
    lhs: &Expr,
    rhs: &Expr,
    variables: &[String],
    circles: &[(String, String)],
    trials: u32,
    seed: u64,
) -> Result<RandomDecision, String> {
    let d = degree_bound(lhs)
        .zip(degree_bound(rhs))
        .map(|(a, b)| a.max(b))
        .ok_or("the expressions are not polynomials (non-constant divisor or exponent)")?;
    // Clearing the denominators (1 + tau^2) of circle points at most doubles the degree.
    let degree = if circles.is_empty() { d } else { 2 * d };
    let mut rng = Rng::new(seed);
    for _ in 0..trials {
        let mut point: HashMap<String, ModP> = variables
            .iter()
            .map(|v| (v.clone(), ModP::random(&mut rng)))
            .collect();
        for (c, s) in circles {
            let (cv, sv) = loop {
                let tau = ModP::random(&mut rng);
                if let Ok(inv) = (ModP::ONE + tau * tau).inv() {
                    break ((ModP::ONE - tau * tau) * inv, (tau + tau) * inv);
                }
            };
            point.insert(c.clone(), cv);
            point.insert(s.clone(), sv);
        }
        let value = eval_modp(lhs, &point)? - eval_modp(rhs, &point)?;
        if value != ModP::ZERO {
            let mut point: Vec<(String, ModP)> = point.into_iter().collect();
            point.sort_by(|a, b| a.0.cmp(&b.0));
            return Ok(RandomDecision::Fails { point, value });
        }
    }
    Ok(RandomDecision::Holds {
        trials,
        degree,
        log2_bound: schwartz_zippel_log2_bound(degree, trials),
    })
}
