//! The coprimality certificate modulo `2^61 - 1` ([`certified_coprime`]) and the modular test
//! that a divisor cannot divide ([`div_image_possible`]); see the documentation of the parent
//! module.

use crate::modp::ModP;
use crate::poly::{Poly, Var};
use crate::Rational;
use exactcheck_core::{Field, Ring, Rng};
use std::any::Any;

/// The seed of the residues [`certified_coprime`] substitutes (any fixed value: the test is
/// sound for every choice, and a bad one only costs a fallback).
const COPRIME_SEED: u64 = 0x6763_645f_6d6f_6470;

/// Both polynomials as polynomials with rational coefficients, `None` for another field.
fn as_rational<'a, C: Field>(
    a: &'a Poly<C>,
    b: &'a Poly<C>,
) -> Option<(&'a Poly<Rational>, &'a Poly<Rational>)> {
    let a = (a as &dyn Any).downcast_ref::<Poly<Rational>>()?;
    let b = (b as &dyn Any).downcast_ref::<Poly<Rational>>()?;
    Some((a, b))
}

/// The residues substituted for variables `0..n` (the same for every call).
fn residues(n: usize) -> Vec<ModP> {
    let mut rng = Rng::new(COPRIME_SEED);
    (0..n).map(|_| ModP::random(&mut rng)).collect()
}

/// The image of `p` modulo `2^61 - 1` as a polynomial in `v` (coefficient `i` of `v^i`), every
/// other variable `w` replaced by `at[w]`; `None` when a coefficient's denominator is a
/// multiple of the prime.
fn image_in(p: &Poly<Rational>, v: Var, at: &[ModP]) -> Option<Vec<ModP>> {
    let mut out = vec![ModP::ZERO; p.degree_in(v) as usize + 1];
    for (m, c) in p.terms() {
        let mut x = ModP::from_rational(c).ok()?;
        for (w, r) in at.iter().enumerate() {
            let e = m.exponent(w as Var);
            if e > 0 && w != v as usize {
                x *= r.pow_u64(u64::from(e));
            }
        }
        out[m.exponent(v) as usize] += x;
    }
    Some(out)
}

/// The terms of a polynomial with rational coefficients evaluated modulo the prime at the
/// residues `at` (coefficient times monomial), with their exponents: the images in one variable
/// after another ([`TermImages::image_in`]) then cost two products per term instead of an
/// evaluation of every other variable.
struct TermImages {
    /// The number of variables: the exponents of term `i` are `exps[i * n..(i + 1) * n]`.
    n: usize,
    /// The exponents of every term, dense.
    exps: Vec<u32>,
    /// The value of each term at `at`.
    values: Vec<ModP>,
}

impl TermImages {
    /// The terms of `p` at `at` (one residue per variable of `p`); `None` when a coefficient's
    /// denominator is a multiple of the prime.
    fn new(p: &Poly<Rational>, at: &[ModP]) -> Option<TermImages> {
        let n = at.len();
        let mut exps = Vec::with_capacity(p.len() * n);
        let mut values = Vec::with_capacity(p.len());
        for (m, c) in p.terms() {
            let mut x = ModP::from_rational(c).ok()?;
            for (w, r) in at.iter().enumerate() {
                let k = m.exponent(w as Var);
                if k > 0 {
                    x *= r.pow_u64(u64::from(k));
                }
                exps.push(k);
            }
            values.push(x);
        }
        Some(TermImages { n, exps, values })
    }

    /// The image of `p` (the polynomial of these terms) in `v`, as [`image_in`]: each term's
    /// value divided by `at[v]^e`; [`image_in`] itself when `at[v]` is zero.
    fn image_in(&self, p: &Poly<Rational>, v: Var, at: &[ModP]) -> Option<Vec<ModP>> {
        let Ok(inv) = at[v as usize].inv() else {
            return image_in(p, v, at);
        };
        let degree = p.degree_in(v) as usize;
        let mut powers = Vec::with_capacity(degree + 1);
        let mut x = ModP::ONE;
        for _ in 0..=degree {
            powers.push(x);
            x *= inv;
        }
        let mut out = vec![ModP::ZERO; degree + 1];
        for (i, x) in self.values.iter().enumerate() {
            let k = self.exps[i * self.n + v as usize] as usize;
            out[k] += *x * powers[k];
        }
        Some(out)
    }
}

/// `f` without its zero leading coefficients.
fn trimmed(mut f: Vec<ModP>) -> Vec<ModP> {
    while f.last().is_some_and(ModP::is_zero) {
        f.pop();
    }
    f
}

/// The remainder of `f` by `g` (`g` trimmed, not zero) modulo the prime.
fn rem_mod_p(mut f: Vec<ModP>, g: &[ModP]) -> Vec<ModP> {
    let inv = g[g.len() - 1]
        .inv()
        .expect("a trimmed polynomial leads with a unit");
    while f.len() >= g.len() {
        let q = f[f.len() - 1] * inv;
        let shift = f.len() - g.len();
        for (i, gi) in g.iter().enumerate() {
            f[shift + i] -= q * *gi;
        }
        f.pop();
        f = trimmed(f);
    }
    f
}

/// The degree of the gcd of `f` and `g` modulo the prime (`None` when both are zero).
fn gcd_degree_mod_p(f: Vec<ModP>, g: Vec<ModP>) -> Option<usize> {
    let (mut f, mut g) = (trimmed(f), trimmed(g));
    while !g.is_empty() {
        let r = rem_mod_p(f, &g);
        f = g;
        g = r;
    }
    f.len().checked_sub(1)
}

/// Whether `a` and `b` are proved coprime by their images modulo `2^61 - 1` (see the module
/// documentation): `Some(true)` when proved, `Some(false)` when not (they probably share a
/// factor), `None` when the coefficients are not rational (the test does not apply).
///
/// Soundness: let `g` be the gcd over Q and `v` a variable of both. Scaled to be primitive over
/// the rationals whose denominators are prime to `p`, `g` and `a / g` have such coefficients
/// (Gauss's lemma), so the substitution `phi` (reduction modulo `p`, then the residues) maps
/// `g` to a divisor of both images. When the image of `a` keeps its degree in `v`, the leading
/// coefficient of `g` (a factor of `a`'s) does not vanish under `phi`, so `phi(g)` has the
/// degree of `g` in `v`, at most that of the image gcd. Degree 0 for every shared `v` leaves
/// `g` without the shared variables, and `g` divides both, so it is constant.
pub fn certified_coprime<C: Field>(a: &Poly<C>, b: &Poly<C>) -> Option<bool> {
    let (a, b) = as_rational(a, b)?;
    if a.is_zero() || b.is_zero() {
        return Some(a.is_constant() && b.is_constant() && !(a.is_zero() && b.is_zero()));
    }
    let vb = b.variables();
    let shared: Vec<Var> = a
        .variables()
        .into_iter()
        .filter(|v| vb.contains(v))
        .collect();
    let n = shared
        .iter()
        .chain(&vb)
        .chain(&a.variables())
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let at = residues(n);
    let (Some(ta), Some(tb)) = (TermImages::new(a, &at), TermImages::new(b, &at)) else {
        return Some(false);
    };
    for v in shared {
        let (Some(fa), Some(fb)) = (ta.image_in(a, v, &at), tb.image_in(b, v, &at)) else {
            return Some(false);
        };
        let keeps = |f: &[ModP]| f.last().is_some_and(|c| !c.is_zero());
        if !keeps(&fa) && !keeps(&fb) {
            return Some(false);
        }
        if gcd_degree_mod_p(fa, fb) != Some(0) {
            return Some(false);
        }
    }
    Some(true)
}

/// Whether `p` is proved square-free (no factor of positive degree divides it twice) by its
/// images modulo `2^61 - 1`: `Some(true)` when proved, `Some(false)` when not (it may have a
/// repeated factor), `None` when the coefficients are not rational (the test does not apply).
///
/// Soundness: let `p = f^2 g` with `f` of positive degree in a variable `v` of `p`. With `phi`
/// the substitution of [`certified_coprime`] into the image in `v`, `phi(p) = phi(f)^2 phi(g)`
/// and its derivative in `v` are both multiples of `phi(f)`; when `phi(p)` keeps its degree in
/// `v`, the leading coefficient of `f` (a factor of `p`'s) does not vanish, so `phi(f)` has
/// positive degree and the gcd of `phi(p)` and `phi(p)'` is not constant. A gcd of degree 0 in
/// every variable of `p`, each image keeping its degree, therefore leaves no such `f`. The
/// derivative is that of the image (differentiation in `v` commutes with the substitution of
/// the other variables and with the reduction modulo the prime), so no derivative over Q is
/// computed.
pub fn certified_square_free<C: Field>(p: &Poly<C>) -> Option<bool> {
    let p = (p as &dyn Any).downcast_ref::<Poly<Rational>>()?;
    if p.is_zero() {
        return Some(false);
    }
    let vars = p.variables();
    let n = vars.iter().map(|&v| v as usize + 1).max().unwrap_or(0);
    let at = residues(n);
    let Some(terms) = TermImages::new(p, &at) else {
        return Some(false);
    };
    for v in vars {
        let Some(f) = terms.image_in(p, v, &at) else {
            return Some(false);
        };
        if f.last().is_none_or(ModP::is_zero) {
            return Some(false);
        }
        let df: Vec<ModP> = f
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| *c * ModP::from(i as u64))
            .collect();
        if gcd_degree_mod_p(f, df) != Some(0) {
            return Some(false);
        }
    }
    Some(true)
}

/// Whether `h` may divide `p` (rational coefficients): `false` when, in a variable of `h`, the
/// image of `h` modulo the prime keeps its degree and does not divide the image of `p` (then
/// `h` does not divide `p`, and the exact division need not be tried); `true` otherwise.
pub(crate) fn div_image_possible<C: Field>(p: &Poly<C>, h: &Poly<C>) -> bool {
    let Some((p, h)) = as_rational(p, h) else {
        return true;
    };
    let Some(&v) = h.variables().first() else {
        return true;
    };
    let at = residues(crate::poly::variable_span(p, h));
    let (Some(fp), Some(fh)) = (image_in(p, v, &at), image_in(h, v, &at)) else {
        return true;
    };
    if fh.last().is_none_or(ModP::is_zero) {
        return true;
    }
    trimmed(rem_mod_p(fp, &fh)).is_empty()
}
