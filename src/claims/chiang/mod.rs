//! Claims of Chiang's ruled-surface / plane paper: the Theorem, Corollaries
//! 1, 2 and 5, and Example 4.
//!
//! The construction itself lives in `exactcheck_core::ruled` (generic over the scalar); here it is
//! instantiated over the polynomial ring `Q[p_jx, ..., q_iz, a, b, c, d, t]` of the proof engine
//! (symbolic proofs), over [`Rational`] (random exact instances) and over
//! [`exactcheck_exact::Radical`] (Example 4 in `Q(sqrt 2, sqrt 6)`).
//!
//! * `theorem` — the printed sums `(w_k, w_k r_k)` against the proof's substitution
//!   `C(t) = [(N.V) B - (N.B + d) V] / (N.V)`, coefficient by coefficient and as an identity in a
//!   symbolic `t`, for every `m <= 4, n <= 6`; then random exact instances up to `(12, 20)`.
//! * `corollaries` — the printed formulas, kept as text (ASCII transliterations) and parsed by the
//!   engine, against the substitution of the proof for the plane `z = 0`. Printed formulas are
//!   quotients (`r_k = (1/w_k) [...]`, `p_k - (p_kz / q_0z) q_0`), read as *fractions* `N / D` of
//!   polynomials by the exact crate's conversion without cancelling
//!   (`Expr::try_to_fraction`, [`fraction`]), a printed weight `w_k` inside a point formula
//!   substituted by its printed formula first; a printed `N / D` equals a derived `H / W`
//!   exactly when the polynomial `N W - H D` is zero (cross-multiplication; both denominators are
//!   non-zero polynomials). A non-zero residual is turned into an exact rational counter-example
//!   where both denominators are non-zero and the two values differ ([`compare`]).
//! * `example4` — the curve in `Q(sqrt 2, sqrt 6)`, every printed decimal judged exactly.
//!
//! Rust, not an embedded claims file, claim by claim: `chiang.theorem` and
//! `chiang.corollary1/2/5` are families over the degrees `(m, n)`, expanded with the Bernstein
//! products of `exactcheck_core::bernstein` and checked against the substitution of the proof,
//! de Casteljau and exact instances (a claims file states one formula of fixed degree at a
//! time); `chiang.example4` judges the printed decimals against the curve the core's ruled
//! surface construction (`exactcheck_core::ruled`) computes in `Q(sqrt 2, sqrt 6)`, an
//! independent derivation.

mod corollaries;
mod example4;
mod theorem;

pub use corollaries::{
    corollary1_with, corollary2_with, corollary5_with, Corollary5Text, COROLLARY1_POINT_TERM,
    COROLLARY1_WEIGHT_TERM, COROLLARY2_POINT, COROLLARY5,
};
pub use example4::{
    example4_markdown, example4_table, surface_and_plane, Example4Row, PRINTED_POINTS,
    PRINTED_WEIGHTS,
};
pub use theorem::{check_size, SizeReport, RANDOM_SIZES, SYMBOLIC_MAX};

use super::engine::{Rng, Symbols};
use super::{Claim, Outcome, Verdict};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Ring, Vec3};
use exactcheck_exact::expr::library::substitute_free;
use exactcheck_exact::expr::{parse_expr, Expr};
use exactcheck_exact::poly::Poly;
use exactcheck_exact::Rational;

type P = Poly<Rational>;

/// The `chiang.*` claims of this module, statements as printed.
pub fn claims() -> Vec<Claim> {
    vec![
        claim!("chiang.theorem", Proved, "Theorem (intersection with aX+bY+cZ+d=0): S(s,t) = B(t) + s V(t) meets the plane in a rational Bezier curve of degree m+n with w_k = (a b c) . (sum_{i=0}^{k} phi(m,n,i,k-i) q_i), r_k = (1/w_k) sum_{i=0}^{k} phi(m,n,i,k-i) ((a b c d).(q_i 0) p_{k-i} - (a b c d).(p_{k-i} 1) q_i), k = 0..m+n, phi(m,n,i,j) = C(m,i) C(n,j) / C(m+n,i+j)", theorem_claim),
        claim!("chiang.corollary1", Proved, "Corollary 1 (Z=0 plane): w_k = sum_{i=0}^{k} phi(m,n,i,k-i) q_iz, r_k = (1/w_k) sum_{i=0}^{k} phi(m,n,i,k-i) (q_iz p_{k-i} - p_{k-i}z q_i), k = 0..m+n; r_kz = 0", corollary1_claim),
        claim!("chiang.corollary2", Proved, "Corollary 2 (m=0, cylinder, Z=0 plane): r_k = p_k - (p_kz/q0z) q0, k = 0..n; all weights w_i equal q0z, so the curve is a (polynomial) Bezier curve", corollary2_claim),
        claim!("chiang.corollary5", Proved, "Corollary 5 (m=1, n=2, Z=0 plane): w0 = q0z, w1 = (1/3)(2q0z+q1z), w2 = (1/3)(q0z+2q1z), w3 = q1z, r0 = (1/w0)[(q0z, -p0z).(p0,q0)], r1 = (1/(3w1))[(q1z, 2q0z, -2p1z, -p0z).(p0,p1,q0,q1)], r2 = (1/(3w2))[(2q1z, q0z, -p2z, -2p1z).(p1,p2,q0,q1)], r3 = (1/w3)[(q1z, -p2z).(p2,q1)]", corollary5_claim),
        claim!("chiang.example4", Fails, "Example 4 (m=1, n=2): p0=(0,0,-1), p1=(1,1,-1), p2=(0,2,-1), q0=(-1,1,sqrt 2), q1=(-1,-1,sqrt 6), Z=0 plane: w0=1.41, w1=1.76, w2=2.10, w3=2.45, r0=(-0.705, 0.705, 0), r1=(-0.0341, 0.721, 0), r2=(0.3, 1.07, 0), r3=(-0.409, 1.60, 0)", example4_claim),
    ]
}

fn theorem_claim() -> Result<Outcome, String> {
    theorem::check()
}

fn corollary1_claim() -> Result<Outcome, String> {
    corollary1_with(COROLLARY1_WEIGHT_TERM, COROLLARY1_POINT_TERM)
}

fn corollary2_claim() -> Result<Outcome, String> {
    corollary2_with(COROLLARY2_POINT)
}

fn corollary5_claim() -> Result<Outcome, String> {
    corollary5_with(&COROLLARY5)
}

fn example4_claim() -> Result<Outcome, String> {
    example4::check()
}

// ------------------------------------------------------------------------ symbolic surfaces

/// The ruled surface with symbolic control points `p_j = (pjx, pjy, pjz)` (degree `n`) and
/// control vectors `q_i = (qix, qiy, qiz)` (degree `m`).
fn symbolic_surface(sym: &mut Symbols, m: usize, n: usize) -> RuledSurface<P> {
    let mut point = |name: String| {
        Vec3::new(
            sym.vars.poly::<Rational>(&format!("{name}x")),
            sym.vars.poly::<Rational>(&format!("{name}y")),
            sym.vars.poly::<Rational>(&format!("{name}z")),
        )
    };
    let base = (0..=n).map(|j| point(format!("p{j}"))).collect();
    let directions = (0..=m).map(|i| point(format!("q{i}"))).collect();
    RuledSurface::from_control(base, directions).expect("n + 1 >= 1 points, m + 1 >= 1 vectors")
}

// ------------------------------------------------------------------------ printed fractions

/// A quotient of polynomials as the exact crate builds it from an expression (nothing
/// cancelled; [`Expr::try_to_fraction`]).
pub type Fraction = exactcheck_exact::ratfun::Fraction<Rational>;

/// The printed formula `text` (the engine's expression syntax) as a [`Fraction`]; a name listed
/// in `defs` (e.g. `w1`, the printed weight that a printed point divides by) stands for its
/// printed formula, every other name is a variable of `sym`.
///
/// # Errors
/// A syntax error, a `sqrt` of a variable, a non-integer exponent, a division by zero.
pub fn fraction(
    text: &str,
    sym: &mut Symbols,
    defs: &[(String, Expr)],
) -> Result<Fraction, String> {
    let wrap = |e: String| format!("printed formula {text:?}: {e}");
    let mut e = printed_expr(text)?;
    for (name, value) in defs {
        e = substitute_free(&e, name, value).map_err(wrap)?;
    }
    e.try_to_fraction::<Rational>(&mut sym.vars)
        .map_err(|e| wrap(e.to_string()))
}

/// The printed formula `text` as an expression, for `defs` of [`fraction`].
///
/// # Errors
/// A syntax error.
pub fn printed_expr(text: &str) -> Result<Expr, String> {
    parse_expr(text).map_err(|e| format!("printed formula {text:?}: {e}"))
}

/// The derived quotient `num / den` (`den` not the zero polynomial).
fn quotient(num: &P, den: &P) -> Result<Fraction, String> {
    let over = |f: Option<Fraction>| f.ok_or_else(|| "the derivation passes a limit".to_string());
    let inv = over(Fraction::from_poly(den.clone()).recip())?;
    over(Fraction::from_poly(num.clone()).mul(&inv))
}

/// The expanded denominator of a fraction.
fn denominator(f: &Fraction) -> Result<P, String> {
    f.denominator()
        .ok_or_else(|| "a denominator passes a limit".to_string())
}

/// One printed formula against its derivation.
pub struct Comparison {
    /// What it is, e.g. `r1.x (m=1, n=2)`.
    pub label: String,
    /// The printed text (data), in the engine's syntax.
    pub printed: String,
    /// The derivation's value.
    pub derived: Fraction,
}

/// The result of [`compare`]: all equal, or the first mismatch with an exact counter-example.
pub enum Compared {
    /// Every printed fraction equals its derivation; the total number of terms of the
    /// cross-multiplied sides that cancelled.
    Equal {
        /// Terms of `N W` and `H D`, summed over all comparisons.
        terms: usize,
    },
    /// The first mismatch: the evidence (counter-example, both values, the derived form).
    Mismatch(String),
    /// A non-zero residual without a counter-example found (never expected).
    NoWitness(String),
}

/// Decides every comparison: printed `N / D` against derived `H / W` by `N W - H D = 0`; on the
/// first non-zero residual, a rational point (small numerators and denominators, deterministic)
/// where `D != 0`, `W != 0` and the two values differ.
///
/// # Errors
/// A printed text that does not parse.
pub fn compare(
    sym: &mut Symbols,
    defs: &[(String, Expr)],
    comparisons: &[Comparison],
) -> Result<Compared, String> {
    let mut terms = 0;
    for c in comparisons {
        let printed = fraction(&c.printed, sym, defs)?;
        let left = printed.numerator().mul_ref(&denominator(&c.derived)?);
        let right = c.derived.numerator().mul_ref(&denominator(&printed)?);
        terms += left.len() + right.len();
        let residual = left.sub_ref(&right);
        if residual.is_zero() {
            continue;
        }
        let derived_text = format!(
            "({}) / ({})",
            c.derived.numerator().display(&sym.vars),
            denominator(&c.derived)?.display(&sym.vars)
        );
        return Ok(match witness(sym, &printed, &c.derived, &residual)? {
            Some((at, p, d)) => Compared::Mismatch(format!(
                "{} as printed, {}, is not the derivation's: counter-example {at}: printed {p}, derived {d}; derived form: {} = {derived_text}",
                c.label, c.printed, c.label
            )),
            None => Compared::NoWitness(format!(
                "{} as printed, {}, differs from the derivation {derived_text} (residual {}), but no rational point separating them was found",
                c.label,
                c.printed,
                residual.display(&sym.vars)
            )),
        });
    }
    Ok(Compared::Equal { terms })
}

/// A rational point where both denominators are non-zero and the printed and derived values
/// differ: `(assignment, printed value, derived value)`.
fn witness(
    sym: &Symbols,
    printed: &Fraction,
    derived: &Fraction,
    residual: &P,
) -> Result<Option<(String, Rational, Rational)>, String> {
    let (printed_den, derived_den) = (denominator(printed)?, denominator(derived)?);
    let mut used: Vec<_> = [residual, &printed_den, &derived_den]
        .iter()
        .flat_map(|p| p.variables())
        .collect();
    used.sort();
    used.dedup();
    let mut rng = Rng::new(0x00C4_1A4C);
    for _ in 0..2000 {
        let mut point = vec![Rational::ZERO; sym.vars.len()];
        for v in &used {
            point[*v as usize] = rng.rational(9, 4);
        }
        let at = |p: &P| p.eval(&point, |c| c.clone());
        let (pd, dd) = (at(&printed_den), at(&derived_den));
        if pd.is_zero() || dd.is_zero() {
            continue;
        }
        let pv = at(printed.numerator())
            .checked_div(&pd)
            .expect("checked non-zero");
        let dv = at(derived.numerator())
            .checked_div(&dd)
            .expect("checked non-zero");
        if pv != dv {
            let assignment: Vec<String> = used
                .iter()
                .map(|v| {
                    format!(
                        "{} = {}",
                        sym.vars.name(*v).expect("a variable of the context"),
                        point[*v as usize]
                    )
                })
                .collect();
            return Ok(Some((assignment.join(", "), pv, dv)));
        }
    }
    Ok(None)
}

/// An outcome from a [`Compared`] (with the method and the evidence of the equal case).
fn outcome(compared: Compared, method: &str, proved: impl FnOnce(usize) -> String) -> Outcome {
    let (verdict, evidence) = match compared {
        Compared::Equal { terms } => (Verdict::Proved, proved(terms)),
        Compared::Mismatch(e) => (Verdict::Fails, e),
        Compared::NoWitness(e) => (Verdict::Undecided, e),
    };
    Outcome {
        verdict,
        method: method.into(),
        evidence,
        erratum: None,
    }
}
