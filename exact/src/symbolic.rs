//! Symbolic helpers on polynomials used to decide geometric statements about *families* of
//! quadrics (entries of a matrix are polynomials in parameters):
//!
//! * [`substitute_ints`] / [`substitute_all`]: several substitutions `x_v -> value` in turn.
//! * [`form_matrix`]: the symmetric matrix of a quadratic form in chosen variables by
//!   polarization, `M_ii = q(e_i)`, `M_ij = (q(e_i + e_j) - q(e_i) - q(e_j)) / 2`, whose entries
//!   are polynomials in the remaining variables. Polarization reads off a matrix from *any*
//!   polynomial; that `q` really is that quadratic form must be checked separately, by proving
//!   `q - x^T M x = 0` ([`quadratic`] builds `x^T M x`).
//! * [`definite_sign`]: a sufficient certificate for the strict sign of a polynomial on the real
//!   points. If every term has only even exponents, all coefficients have one sign `s`, and every
//!   variable that occurs also occurs in a pure-power term `c x_v^(2k)`, then at a real point
//!   every term is `s`-signed or zero and the pure-power term of any non-zero variable is
//!   strictly `s`-signed: the polynomial has the strict sign `s` wherever not all of its
//!   variables vanish (a non-zero constant has its sign everywhere). Nothing is claimed when the
//!   certificate does not apply (`None`).
//! * [`divide_by_var`]: exact division by one variable when it divides every term.
//!
//! Hand-written: these are small operations on this crate's sparse [`Poly`].

use crate::poly::{Poly, Var};
use exactcheck_core::{Field, OrderedField, Ring, Sign, ZeroDivisor};

/// `p` with the variables `vars` replaced by the integers `vals` (pairwise, in order).
pub fn substitute_ints<C: Ring>(p: &Poly<C>, vars: &[Var], vals: &[i64]) -> Poly<C> {
    let mut r = p.clone();
    for (v, x) in vars.iter().zip(vals) {
        r = r.substitute(*v, &Poly::from_i64(*x));
    }
    r
}

/// `p` with the variables `vars` replaced by the polynomials `vals` (one after another, so a
/// value may mention a later variable of `vars`, which is then substituted too).
pub fn substitute_all<C: Ring>(p: &Poly<C>, vars: &[Var], vals: &[Poly<C>]) -> Poly<C> {
    let mut r = p.clone();
    for (v, x) in vars.iter().zip(vals) {
        r = r.substitute(*v, x);
    }
    r
}

/// The symmetric matrix of the quadratic form `q` in `vars`, by polarization (see the module
/// documentation; whether `q` is that form is the caller's identity `q - x^T M x = 0`).
///
/// # Errors
/// [`ZeroDivisor`] in characteristic 2 (the factor 1/2).
pub fn form_matrix<C: Field>(q: &Poly<C>, vars: &[Var]) -> Result<Vec<Vec<Poly<C>>>, ZeroDivisor> {
    let half = C::from_ratio(1, 2)?;
    let n = vars.len();
    let unit = |i: usize| -> Vec<i64> { (0..n).map(|k| i64::from(k == i)).collect() };
    let diag: Vec<Poly<C>> = (0..n).map(|i| substitute_ints(q, vars, &unit(i))).collect();
    Ok((0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    if i == j {
                        diag[i].clone()
                    } else {
                        let e: Vec<i64> = (0..n).map(|k| i64::from(k == i || k == j)).collect();
                        (substitute_ints(q, vars, &e) - &diag[i] - &diag[j]).scale(&half)
                    }
                })
                .collect()
        })
        .collect())
}

/// `x^T M x`.
pub fn quadratic<C: Ring>(m: &[Vec<Poly<C>>], x: &[Poly<C>]) -> Poly<C> {
    let mut acc = Poly::zero();
    for (i, row) in m.iter().enumerate() {
        for (j, mij) in row.iter().enumerate() {
            acc += mij.mul_ref(&x[i]).mul_ref(&x[j]);
        }
    }
    acc
}

/// The strict sign of a signed sum of even powers with a pure power of every variable, and its
/// variables: the polynomial has that sign at every real point where not all of them vanish.
/// `None` when the certificate (module documentation) does not apply, e.g. for zero.
pub fn definite_sign<C: OrderedField>(p: &Poly<C>) -> Option<(Sign, Vec<Var>)> {
    let mut sign = None;
    let mut pure = Vec::new();
    for (m, c) in p.terms() {
        let e = m.exponents();
        if e.iter().any(|&(_, k)| k % 2 == 1) {
            return None;
        }
        let s = c.sign();
        if *sign.get_or_insert(s) != s {
            return None;
        }
        if let [(v, _)] = e.as_slice() {
            pure.push(*v);
        }
    }
    let vars = p.variables();
    if vars.iter().all(|v| pure.contains(v)) {
        sign.map(|s| (s, vars))
    } else {
        None
    }
}

/// `p / x_v` when `x_v` divides every term of `p` (`None` otherwise; zero divides to zero).
pub fn divide_by_var<C: Ring>(p: &Poly<C>, v: Var) -> Option<Poly<C>> {
    let mut terms = Vec::new();
    for (m, c) in p.terms() {
        let mut e = m.exponents();
        let slot = e.iter_mut().find(|(w, _)| *w == v)?;
        slot.1 -= 1;
        terms.push((e, c.clone()));
    }
    Some(Poly::from_terms(terms))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Vars;
    use crate::Rational;

    type P = Poly<Rational>;

    fn setup() -> (Vars, P, P, P) {
        let mut v = Vars::from_names(["a", "b", "x"]);
        let (a, b, x) = (v.poly("a"), v.poly("b"), v.poly("x"));
        (v, a, b, x)
    }

    #[test]
    fn definite_sign_needs_pure_powers() {
        let (_, a, b, _) = setup();
        let s = a.square() + b.square();
        assert_eq!(definite_sign(&s).map(|x| x.0), Some(Sign::Positive));
        // a^2 b^2 alone vanishes on the axes without a = b = 0: rejected.
        assert_eq!(definite_sign(&(a.square() * b.square())), None);
        assert_eq!(definite_sign(&(a.square() - b.square())), None);
        assert_eq!(definite_sign(&(a.clone() * &b)), None);
        assert_eq!(definite_sign(&P::zero()), None);
        assert_eq!(
            definite_sign(&(-(a.square()) - b.square().square())).map(|x| x.0),
            Some(Sign::Negative)
        );
        assert_eq!(
            definite_sign(&P::from_i64(-3)),
            Some((Sign::Negative, vec![]))
        );
    }

    #[test]
    fn form_matrix_and_quadratic_round_trip() {
        let (mut vars, a, b, x) = setup();
        let (av, bv) = (vars.var("a"), vars.var("b"));
        // q = x a^2 + 3 a b - b^2: a quadratic form in (a, b) with a coefficient in x.
        let q = x.clone() * a.square() + (a.clone() * &b).scale_i64(3) - b.square();
        let m = form_matrix(&q, &[av, bv]).unwrap();
        let three_halves = P::constant(Rational::new(3, 2).unwrap());
        assert_eq!(m[0][0], x);
        assert_eq!(m[0][1], three_halves);
        assert_eq!(m[1][0], m[0][1]);
        assert_eq!(m[1][1], P::from_i64(-1));
        assert_eq!(quadratic(&m, &[a.clone(), b.clone()]), q);
        // A non-quadratic polynomial gets a matrix too, but the round trip fails.
        let cubic = a.square() * &a;
        let mc = form_matrix(&cubic, &[av, bv]).unwrap();
        assert_ne!(quadratic(&mc, &[a, b]), cubic);
    }

    #[test]
    fn substitutions_and_division() {
        let (mut vars, a, b, x) = setup();
        let (av, bv, xv) = (vars.var("a"), vars.var("b"), vars.var("x"));
        let p = a.clone() * &x + b.clone() * &x * &x;
        assert_eq!(
            substitute_ints(&p, &[av, bv], &[2, 3]),
            x.scale_i64(2) + (x.square()).scale_i64(3)
        );
        assert_eq!(
            substitute_all(&p, &[xv], &[a.clone() + &b]),
            a.clone() * (a.clone() + &b) + b.clone() * (a.clone() + &b).square()
        );
        assert_eq!(divide_by_var(&p, xv), Some(a.clone() + b.clone() * &x));
        assert_eq!(divide_by_var(&p, av), None);
        assert_eq!(divide_by_var(&P::zero(), av), Some(P::zero()));
    }
}
