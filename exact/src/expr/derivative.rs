//! Total derivatives of converted expressions: `diff(E, t)` once `E` is a polynomial or a
//! rational function in the variables of a table. Besides `t` itself, two kinds of variables
//! of the table change with `t`, and the chain rule takes each into account:
//! * the cosine and sine of the base angle `t/L` of `t` (`L = 1`: `t` itself):
//!   `d cos(t/L)/dt = -sin(t/L)/L`, `d sin(t/L)/dt = cos(t/L)/L`;
//! * a square root `y = sqrt(R)` (a variable standing for the root, see [`Vars::roots`])
//!   whose radicand `R` changes with `t`: `dy/dt = (dR/dt) / (2 y)`, a fraction whose divisor
//!   `y` is recorded as a condition (the derivative exists where `R > 0`). `dR/dt` is itself a
//!   total derivative, so a root inside a radicand is differentiated in turn (an inner root
//!   comes before the roots whose radicands hold it, so the recursion ends).
//!
//! A polynomial in a root that changes with `t` has no polynomial derivative: the polynomial
//! form refuses it with one line, and [`Expr::has_fractions`] sends such a `diff` to the
//! rational form in the first place.
//!
//! Written here rather than taken from a computer-algebra crate: it works on the workspace's
//! own polynomial and rational-function types, whose variables stand for these functions.

use super::angle_base::{variable_base, Base};
use super::eval::size_error;
use super::*;
use crate::poly::{Poly, Var, Vars};
use crate::ratfun::{poly_derivative, Fraction, RatFun};
use exactcheck_core::Field;

/// The roots of `vars` that `involves` selects, with their radicands expanded over `C` as
/// `convert` gives them (a copy of the table converts them: every variable of a recorded
/// radicand is in the table already).
fn radicands<T>(
    vars: &Vars,
    involves: impl Fn(Var) -> bool,
    convert: impl Fn(&Expr, &mut Vars) -> Result<T, ExprError>,
) -> Result<Vec<(Var, T)>, ExprError> {
    let mut scratch = vars.clone();
    vars.roots()
        .iter()
        .filter(|entry| involves(entry.var))
        .map(|entry| Ok((entry.var, convert(entry.radicand_expr(), &mut scratch)?)))
        .collect()
}

/// The cosine and sine variables of the base angle `t/L` of `t`, when the table has them, with
/// the chain rule's factor `1/L` over `C`.
fn angle_of<C: Coefficient>(
    vars: &Vars,
    t: &str,
    pos: usize,
) -> Result<Option<(Var, Var, C)>, ExprError> {
    let Some((angle, base)) = variable_base(vars, t) else {
        return Ok(None);
    };
    let unit = match &base {
        Base::Variable { unit, .. } => unit.clone(),
        Base::Constant(_) => return Ok(None),
    };
    let factor = C::from_rational(&unit).ok_or_else(|| ExprError::Unrepresentable {
        pos,
        number: unit.to_string(),
    })?;
    Ok(Some((angle.cos, angle.sin, factor)))
}

/// `d/dt` of a polynomial (module documentation). A root of the table that changes with `t`
/// and occurs in `p` is refused: its derivative is a fraction.
pub(super) fn total_derivative<C: Coefficient>(
    p: &Poly<C>,
    vars: &Vars,
    t: &str,
    pos: usize,
) -> Result<Poly<C>, ExprError> {
    let mut d = match vars.get(t) {
        Some(v) => poly_derivative(p, v),
        None => Poly::zero(),
    };
    if let Some((c, s, unit)) = angle_of::<C>(vars, t, pos)? {
        let (cp, sp) = (Poly::<C>::var(c), Poly::<C>::var(s));
        let chain = (poly_derivative(p, s) * cp).sub_ref(&(poly_derivative(p, c) * sp));
        d += chain.scale(&unit);
    }
    if vars.roots().iter().any(|r| p.degree_in(r.var) > 0) {
        // A radicand with a division has no polynomial derivative to test: `None`.
        let involved = radicands(
            vars,
            |y| p.degree_in(y) > 0,
            |e, scratch| {
                if e.has_fractions() {
                    Ok(None)
                } else {
                    e.to_poly::<C>(scratch).map(Some)
                }
            },
        )?;
        for (y, radicand) in involved {
            let moves = match radicand {
                Some(radicand) => !total_derivative(&radicand, vars, t, pos)?.is_zero(),
                None => true,
            };
            if moves {
                return Err(ExprError::BadCall {
                    pos,
                    name: "diff".into(),
                    why: format!(
                        "the derivative of {} in {t} divides by the root: it is a fraction, \
                         not a polynomial",
                        vars.name(y).unwrap_or("the root")
                    ),
                });
            }
        }
    }
    Ok(d)
}

/// `d/dt` of a rational function (module documentation); the roots' divisors become
/// conditions of the result.
pub(super) fn total_derivative_ratfun<C: Coefficient + Field>(
    f: &RatFun<C>,
    vars: &Vars,
    t: &str,
    pos: usize,
) -> Result<RatFun<C>, ExprError> {
    let size = |err| size_error(err, pos);
    let mut d = match vars.get(t) {
        Some(v) => f.derivative(v).map_err(size)?,
        None => f.mul(&RatFun::from_poly(Poly::zero())).map_err(size)?,
    };
    if let Some((c, s, unit)) = angle_of::<C>(vars, t, pos)? {
        let by_c = f
            .derivative(c)
            .and_then(|x| x.mul(&RatFun::from_poly(Poly::<C>::var(s).scale(&unit))))
            .map_err(size)?;
        let by_s = f
            .derivative(s)
            .and_then(|x| x.mul(&RatFun::from_poly(Poly::<C>::var(c).scale(&unit))))
            .map_err(size)?;
        d = d
            .add(&by_c, true)
            .and_then(|x| x.add(&by_s, false))
            .map_err(size)?;
    }
    let involves = |y: Var| {
        f.numerator().degree_in(y) > 0
            || f.denominator().degree_in(y) > 0
            || f.conditions().iter().any(|p| p.degree_in(y) > 0)
    };
    if vars.roots().iter().any(|r| involves(r.var)) {
        for (y, radicand) in radicands(vars, involves, |e, scratch| e.to_ratfun::<C>(scratch))? {
            let d_radicand = total_derivative_ratfun(&radicand, vars, t, pos)?;
            if d_radicand.numerator().is_zero() {
                continue;
            }
            let two_y = RatFun::from_poly(Poly::<C>::var(y) + Poly::<C>::var(y));
            let d_root =
                d_radicand
                    .div(&two_y)
                    .map_err(size)?
                    .ok_or_else(|| ExprError::ZeroDivisor {
                        pos,
                        divisor: format!("2*{}", vars.name(y).unwrap_or("the root")),
                    })?;
            let term = f.derivative(y).and_then(|x| x.mul(&d_root)).map_err(size)?;
            d = d.add(&term, false).map_err(size)?;
        }
    }
    Ok(d)
}

/// [`total_derivative_ratfun`] on a [`Fraction`] (nothing cancelled). `None` when a root of
/// the table occurs in `f` (its chain rule is left to the rational form) or a size runs out.
pub(super) fn total_derivative_fraction<C: Field>(
    f: &Fraction<C>,
    vars: &Vars,
    t: &str,
) -> Option<Fraction<C>> {
    let involves = |y: Var| {
        f.numerator().degree_in(y) > 0 || f.factors().iter().any(|(p, _)| p.degree_in(y) > 0)
    };
    if vars.roots().iter().any(|r| involves(r.var)) {
        return None;
    }
    let mut d = match vars.get(t) {
        Some(v) => f.derivative(v)?,
        None => f.mul(&Fraction::from_poly(Poly::zero()))?,
    };
    if let Some((angle, base)) = variable_base(vars, t) {
        // The chain rule's factor of a base angle `t/L` is left to the rational form.
        if !base.unit().is_one() {
            return None;
        }
        let (c, s) = (angle.cos, angle.sin);
        let by_c = f
            .derivative(c)?
            .mul(&Fraction::from_poly(Poly::<C>::var(s)))?;
        let by_s = f
            .derivative(s)?
            .mul(&Fraction::from_poly(Poly::<C>::var(c)))?;
        d = d.add(&by_c, true)?.add(&by_s, false)?;
    }
    Some(d)
}

/// Whether the tree takes the square root (or the absolute value, `sqrt(E^2)`) of an expression
/// with a variable: a `diff` of it may divide by that root.
pub(super) fn has_variable_root(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => false,
        ExprKind::Sqrt(x) => x.has_variable() || has_variable_root(x),
        ExprKind::Call(name, args) if name == ABS => args
            .iter()
            .any(|x| x.has_variable() || has_variable_root(x)),
        ExprKind::Neg(x) => has_variable_root(x),
        ExprKind::Pow(a, b) => has_variable_root(a) || has_variable_root(b),
        ExprKind::Sum(ts) => ts.iter().any(|(_, t)| has_variable_root(t)),
        ExprKind::Product(fs) => fs.iter().any(|(_, f)| has_variable_root(f)),
        ExprKind::Call(_, args) => args.iter().any(has_variable_root),
    }
}
