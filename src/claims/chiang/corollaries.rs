//! `chiang.corollary1`, `chiang.corollary2`, `chiang.corollary5`: the printed formulas, as data,
//! against the derivation.
//!
//! The derivation is the proof's substitution for the plane `z = 0`
//! (`RuledSurface::substitution` with `N = (0, 0, 1)`, `d = 0`, over the polynomial ring), in the
//! scaled basis: `W_k = den_k / C(m+n, k)` and `r_k = (num_xk, num_yk, num_zk) / den_k`. It does
//! not use the theorem's sums (those are proved equal to it by `chiang.theorem`).
//!
//! The printed texts are ASCII transliterations of the paper's text: `×`, `⋅` and juxtaposition become
//! `*`; a printed dot product of a coefficient tuple with a point tuple, `(c1, c2).(v1, v2)`,
//! becomes `c1*v1 + c2*v2`; `{X}` stands for the coordinate (`x`, `y`, `z`: each printed vector
//! formula is three scalar formulas), `{i}`, `{j}`, `{k}` for indices. The printed sums of
//! Corollary 1, `sum_{i=0}^{k} phi(m,n,i,k-i) term(i, k-i)`, are assembled from the printed
//! summand with the numeric `phi`; the summands with `i > m` or `k - i > n` are left out (their
//! `phi` has the factor `C(m, i)` or `C(n, k-i)`, zero). A printed `w_k` inside a point formula
//! stands for the printed weight formula.

use super::{
    compare, fraction, outcome, printed_expr, quotient, symbolic_surface, Comparison, Fraction,
    Outcome, P,
};
use crate::claims::engine::Symbols;
use crate::claims::Verdict;
use exactcheck_core::ruled::Plane;
use exactcheck_core::{binomial, Ring};
use exactcheck_exact::expr::Expr;
use exactcheck_exact::Rational;

/// Corollary 1's printed weight summand: `w_k = sum_{i=0}^{k} phi(m,n,i,k-i) × q_iz`.
pub const COROLLARY1_WEIGHT_TERM: &str = "q{i}z";
/// Corollary 1's printed point summand: `r_k = (1/w_k) * sum phi (q_iz × p_{k-i} - p_{k-i}z × q_i)`
/// (`{j}` is `k - i`).
pub const COROLLARY1_POINT_TERM: &str = "q{i}z*p{j}{X} - p{j}z*q{i}{X}";
/// Corollary 2 as printed: `r_k = p_k - (p_kz/q0z) × q0`.
pub const COROLLARY2_POINT: &str = "p{k}{X} - (p{k}z/q0z)*q0{X}";

/// Corollary 5's eight printed formulas (`{X}` the coordinate in the points).
#[derive(Clone, Debug)]
pub struct Corollary5Text {
    /// `w0..w3`.
    pub weights: [&'static str; 4],
    /// `r0..r3`; `w0..w3` in them are the printed weights.
    pub points: [&'static str; 4],
}

/// Corollary 5 as the paper prints it.
pub const COROLLARY5: Corollary5Text = Corollary5Text {
    weights: ["q0z", "(1/3)*(2*q0z + q1z)", "(1/3)*(q0z + 2*q1z)", "q1z"],
    points: [
        "(1/w0)*(q0z*p0{X} - p0z*q0{X})",
        "(1/(3*w1))*(q1z*p0{X} + 2*q0z*p1{X} - 2*p1z*q0{X} - p0z*q1{X})",
        "(1/(3*w2))*(2*q1z*p1{X} + q0z*p2{X} - p2z*q0{X} - 2*p1z*q1{X})",
        "(1/w3)*(q1z*p2{X} - p2z*q1{X})",
    ],
};

const METHOD: &str = "symbolic: the printed formulas (data) parsed by the engine as fractions, cross-multiplied against the proof's substitution for z = 0 (Bernstein products over the polynomial ring) and expanded";

const AXES: [&str; 3] = ["x", "y", "z"];

/// The derivation for `z = 0` at degrees `(m, n)`: the weights and the points as fractions.
struct Derived {
    weights: Vec<Fraction>,
    points: Vec<[Fraction; 3]>,
}

fn derive(sym: &mut Symbols, m: usize, n: usize) -> Result<Derived, String> {
    let surface = symbolic_surface(sym, m, n);
    let [den, x, y, z] = surface.substitution(&Plane::<P>::z0());
    let mut weights = Vec::new();
    let mut points = Vec::new();
    for k in 0..=m + n {
        let c = Rational::new(1, binomial((m + n) as u32, k as u32) as i64)
            .expect("a binomial coefficient is not zero");
        weights.push(Fraction::from_poly(den[k].scale(&c)));
        let point = |num: &P| quotient(num, &den[k]);
        points.push([point(&x[k])?, point(&y[k])?, point(&z[k])?]);
    }
    Ok(Derived { weights, points })
}

fn phi_text(m: usize, n: usize, i: usize, j: usize) -> String {
    let num = binomial(m as u32, i as u32) * binomial(n as u32, j as u32);
    let den = binomial((m + n) as u32, (i + j) as u32);
    format!("{num}/{den}")
}

/// `sum_{i=0}^{k} phi(m,n,i,k-i) (term)` as text, the out-of-range summands left out.
fn printed_sum(term: &str, m: usize, n: usize, k: usize, axis: &str) -> String {
    (0..=k)
        .filter(|&i| i <= m && k - i <= n)
        .map(|i| {
            let t = term
                .replace("{i}", &i.to_string())
                .replace("{j}", &(k - i).to_string())
                .replace("{X}", axis);
            format!("{}*({t})", phi_text(m, n, i, k - i))
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

/// Every printed `r_kz` is identically zero (the side statement `r_kz = 0`).
fn z_vanishes(
    sym: &mut Symbols,
    defs: &[(String, Expr)],
    texts: &[(String, String)],
) -> Result<Option<String>, String> {
    for (label, text) in texts {
        let f = fraction(text, sym, defs)?;
        if !f.numerator().is_zero() {
            return Ok(Some(format!(
                "{label} as printed, {text}, is not identically zero: it is ({}) / ({})",
                f.numerator().display(&sym.vars),
                super::denominator(&f)?.display(&sym.vars)
            )));
        }
    }
    Ok(None)
}

fn side_failure(e: String) -> Outcome {
    Outcome {
        verdict: Verdict::Fails,
        method: METHOD.into(),
        evidence: e,
        erratum: None,
    }
}

/// Corollary 1 with the given printed summands (the claim uses [`COROLLARY1_WEIGHT_TERM`] and
/// [`COROLLARY1_POINT_TERM`]), for every `m <= 4`, `n <= 6`.
///
/// # Errors
/// A printed text that does not parse.
pub fn corollary1_with(weight_term: &str, point_term: &str) -> Result<Outcome, String> {
    let mut comparisons_total = 0;
    let mut terms_total = 0;
    for m in 0..=4 {
        for n in 0..=6 {
            let mut sym = Symbols::new(&[]);
            let derived = derive(&mut sym, m, n)?;
            let mut defs = Vec::new();
            let mut comparisons = Vec::new();
            let mut z_texts = Vec::new();
            for k in 0..=m + n {
                let w = printed_sum(weight_term, m, n, k, "z");
                comparisons.push(Comparison {
                    label: format!("w{k} (m = {m}, n = {n})"),
                    printed: w.clone(),
                    derived: derived.weights[k].clone(),
                });
                defs.push((format!("w{k}"), printed_expr(&w)?));
            }
            for k in 0..=m + n {
                for (a, axis) in AXES.iter().enumerate() {
                    let text = format!("(1/w{k})*({})", printed_sum(point_term, m, n, k, axis));
                    if a == 2 {
                        z_texts.push((format!("r{k}z (m = {m}, n = {n})"), text.clone()));
                    }
                    comparisons.push(Comparison {
                        label: format!("r{k}.{axis} (m = {m}, n = {n})"),
                        printed: text,
                        derived: derived.points[k][a].clone(),
                    });
                }
            }
            comparisons_total += comparisons.len();
            match compare(&mut sym, &defs, &comparisons)? {
                super::Compared::Equal { terms } => terms_total += terms,
                other => return Ok(outcome(other, METHOD, |_| String::new())),
            }
            if let Some(e) = z_vanishes(&mut sym, &defs, &z_texts)? {
                return Ok(side_failure(e));
            }
        }
    }
    Ok(Outcome {
        verdict: Verdict::Proved,
        method: METHOD.into(),
        evidence: format!(
            "the printed sums equal the derivation for every (m, n) with m <= 4, n <= 6: {comparisons_total} formulas (w_k and the three coordinates of r_k), {terms_total} terms cancelled after cross-multiplication; the side statement r_kz = 0 holds identically (every printed z sum expands to 0)"
        ), erratum: None, })
}

/// Corollary 2 with the given printed point formula (the claim uses [`COROLLARY2_POINT`]), for
/// `m = 0`, every `n <= 6`; also the printed "all weights equal `q0z`".
///
/// # Errors
/// A printed text that does not parse.
pub fn corollary2_with(point: &str) -> Result<Outcome, String> {
    let mut comparisons_total = 0;
    let mut terms_total = 0;
    for n in 0..=6 {
        let mut sym = Symbols::new(&[]);
        let derived = derive(&mut sym, 0, n)?;
        let mut comparisons = Vec::new();
        let mut z_texts = Vec::new();
        for k in 0..=n {
            comparisons.push(Comparison {
                label: format!("w{k} (n = {n}), printed as all equal to q0z"),
                printed: "q0z".into(),
                derived: derived.weights[k].clone(),
            });
            for (a, axis) in AXES.iter().enumerate() {
                let text = point.replace("{k}", &k.to_string()).replace("{X}", axis);
                if a == 2 {
                    z_texts.push((format!("r{k}z (n = {n})"), text.clone()));
                }
                comparisons.push(Comparison {
                    label: format!("r{k}.{axis} (n = {n})"),
                    printed: text,
                    derived: derived.points[k][a].clone(),
                });
            }
        }
        comparisons_total += comparisons.len();
        match compare(&mut sym, &[], &comparisons)? {
            super::Compared::Equal { terms } => terms_total += terms,
            other => return Ok(outcome(other, METHOD, |_| String::new())),
        }
        if let Some(e) = z_vanishes(&mut sym, &[], &z_texts)? {
            return Ok(side_failure(e));
        }
    }
    Ok(Outcome {
        verdict: Verdict::Proved,
        method: METHOD.into(),
        evidence: format!(
            "for m = 0 and every n <= 6 the printed r_k equal the derivation and every derived weight is q0z: {comparisons_total} formulas, {terms_total} terms cancelled after cross-multiplication; with all weights equal (and q0z != 0, the paper's general case) the rational curve is the polynomial Bezier curve with control points r_k; r_kz = 0 identically"
        ), erratum: None, })
}

/// Corollary 5 with the given printed formulas (the claim uses [`COROLLARY5`]).
///
/// # Errors
/// A printed text that does not parse.
pub fn corollary5_with(printed: &Corollary5Text) -> Result<Outcome, String> {
    let (m, n) = (1, 2);
    let mut sym = Symbols::new(&[]);
    let derived = derive(&mut sym, m, n)?;
    let mut defs = Vec::new();
    let mut comparisons = Vec::new();
    let mut z_texts = Vec::new();
    for (k, w) in printed.weights.iter().enumerate() {
        comparisons.push(Comparison {
            label: format!("w{k}"),
            printed: (*w).into(),
            derived: derived.weights[k].clone(),
        });
        defs.push((format!("w{k}"), printed_expr(w)?));
    }
    for (k, r) in printed.points.iter().enumerate() {
        for (a, axis) in AXES.iter().enumerate() {
            let text = r.replace("{X}", axis);
            if a == 2 {
                z_texts.push((format!("r{k}z"), text.clone()));
            }
            comparisons.push(Comparison {
                label: format!("r{k}.{axis}"),
                printed: text,
                derived: derived.points[k][a].clone(),
            });
        }
    }
    let count = comparisons.len();
    let compared = compare(&mut sym, &defs, &comparisons)?;
    if matches!(compared, super::Compared::Equal { .. }) {
        if let Some(e) = z_vanishes(&mut sym, &defs, &z_texts)? {
            return Ok(side_failure(e));
        }
    }
    Ok(outcome(compared, METHOD, |terms| {
        format!(
            "the eight printed formulas (w0..w3, r0..r3: {count} scalar formulas) equal the derivation for m = 1, n = 2, z = 0; {terms} terms cancelled after cross-multiplication; r_kz = 0 identically"
        )
    }))
}
