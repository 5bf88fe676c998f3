//! Square roots and absolute values of non-constant expressions: `sqrt(E)` becomes a variable
//! `y` of the table, one per distinct expanded radicand, when the table allows it
//! ([`crate::poly::Vars::allow_roots`]). The relation `y^2 = E` (cleared of the denominator
//! when `E` is a fraction: `y^2 D = N` with `D != 0`) and the sign condition `y >= 0` that give
//! the variable its meaning are built by [`crate::prove::square_roots`]; a caller that does not
//! add them must not allow roots (the variable alone would be a free unknown).
//!
//! `abs(E)` is `|E| = sqrt(E^2)` exactly (the non-negative root), so it is the root variable of
//! the radicand `E^2`, shared with a `sqrt(E^2)` written elsewhere; of a constant it is the
//! constant's absolute value ([`Coefficient::try_abs`]).
//!
//! A radicand with a division (`sqrt(1/x)`, `abs(x/y)`) is converted as a rational function
//! ([`Expr::to_ratfun`]): the root's value is the variable, with the radicand's divisors as the
//! conditions under which it is defined.

use super::eval::{size_error, sqrt_of};
use super::{Coefficient, Expr, ExprError, ExprKind};
use crate::poly::{Poly, RootEntry, RootRadicand, Var, Vars};
use crate::ratfun::RatFun;
use crate::Rational;
use exactcheck_core::limits;
use exactcheck_core::{Field, Ring};
use std::any::Any;
use std::sync::Arc;

/// The name of the absolute value, `abs(E) = |E| = sqrt(E^2)`.
pub const ABS: &str = "abs";

/// Expressions are compared structurally; the numbers in them are exact, so equality is an
/// equivalence (the table of roots, [`crate::poly::RootEntry`], needs `Eq`).
impl Eq for Expr {}

/// The radicand of a square-root variable is the formula as written.
impl RootRadicand for Expr {
    fn eq_radicand(&self, other: &dyn RootRadicand) -> bool {
        other.as_any().downcast_ref::<Expr>() == Some(self)
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

impl RootEntry {
    /// The radicand as written (`E^2` for `abs(E)`): every root of a table is recorded by the
    /// conversions of formulas (`root_variable`), with its formula.
    pub fn radicand_expr(&self) -> &Expr {
        self.radicand
            .as_any()
            .downcast_ref::<Expr>()
            .expect("the conversions of formulas record every root with its formula")
    }
}

/// The argument `E` of the call `abs(E)`.
///
/// # Errors
/// [`ExprError::BadCall`] for any other number of arguments.
pub(super) fn abs_argument<'a>(call: &Expr, args: &'a [Expr]) -> Result<&'a Expr, ExprError> {
    match args {
        [e] => Ok(e),
        _ => Err(ExprError::BadCall {
            pos: call.pos,
            name: ABS.into(),
            why: format!("takes 1 argument, not {}", args.len()),
        }),
    }
}

/// `E^2`, the radicand of `abs(E) = sqrt(E^2)`, at the position of `E`.
pub fn abs_radicand(arg: &Expr) -> Expr {
    Expr {
        kind: ExprKind::Pow(
            Box::new(arg.clone()),
            Box::new(Expr {
                kind: ExprKind::Number(Rational::from_integer(2)),
                pos: arg.pos,
            }),
        ),
        pos: arg.pos,
    }
}

/// `|c|` of the constant `c`, the value of `abs(...)` at `call`.
fn abs_of<C: Coefficient>(c: C, call: &Expr) -> Result<C, ExprError> {
    c.try_abs().ok_or_else(|| ExprError::BadCall {
        pos: call.pos,
        name: ABS.into(),
        why: "the absolute value is not defined in this number type".into(),
    })
}

/// The exact value of the constant `abs(E)` at `call`.
pub(super) fn abs_constant<C: Coefficient>(call: &Expr, args: &[Expr]) -> Result<C, ExprError> {
    abs_of(abs_argument(call, args)?.eval_constant::<C>()?, call)
}

/// `sqrt(arg)` as a polynomial: the constant root of a constant, else the root's variable.
pub(super) fn sqrt_poly<C: Coefficient>(
    call: &Expr,
    arg: &Expr,
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let p = arg.to_poly::<C>(vars)?;
    match p.constant_value() {
        Some(c) => sqrt_of(c, call.pos, arg).map(Poly::constant),
        None => root_variable(format!("{p:?}"), arg, call, vars).map(Poly::var),
    }
}

/// `abs(E)` as a polynomial: the absolute value of a constant, else the variable of the root
/// of `E^2`.
pub(super) fn abs_poly<C: Coefficient>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let arg = abs_argument(call, args)?;
    let p = arg.to_poly::<C>(vars)?;
    if let Some(c) = p.constant_value() {
        return abs_of(c, call).map(Poly::constant);
    }
    let radicand = abs_radicand(arg);
    let square = radicand.to_poly::<C>(vars)?;
    root_variable(format!("{square:?}"), &radicand, call, vars).map(Poly::var)
}

/// `sqrt(E)` or `abs(E)` (the node `call`) of an `E` with a division, as a rational function:
/// the constant root or absolute value of a constant, else the root's variable; either way with
/// the divisors of `E` as conditions.
pub(super) fn root_ratfun<C: Coefficient + Field>(
    call: &Expr,
    vars: &mut Vars,
) -> Result<RatFun<C>, ExprError> {
    let (arg, radicand) = match &call.kind {
        ExprKind::Sqrt(arg) => (arg.as_ref(), None),
        ExprKind::Call(_, args) => {
            let arg = abs_argument(call, args)?;
            (arg, Some(abs_radicand(arg)))
        }
        _ => unreachable!("root_ratfun takes a sqrt or an abs"),
    };
    let f = arg.to_ratfun::<C>(vars)?;
    let conditions = f.conditions().to_vec();
    if f.denominator().is_one() {
        if let Some(c) = f.numerator().constant_value() {
            let value = match radicand {
                None => sqrt_of(c, call.pos, arg)?,
                Some(_) => abs_of(c, call)?,
            };
            return Ok(RatFun::from_poly(Poly::constant(value)).with_conditions(conditions));
        }
    }
    let square = match &radicand {
        None => f,
        Some(_) => f
            .mul(&f)
            .map_err(|e| size_error(e, call.pos))?
            .with_conditions(conditions.clone()),
    };
    // A radicand in lowest terms with denominator 1 has the key of the polynomial, so that
    // `sqrt(x^2/x)` and `sqrt(x)` are one root.
    let key = if square.denominator().is_one() {
        format!("{:?}", square.numerator())
    } else {
        format!("{:?} / {:?}", square.numerator(), square.denominator())
    };
    let written = radicand.as_ref().unwrap_or(arg);
    let y = root_variable(key, written, call, vars)?;
    Ok(RatFun::from_poly(Poly::var(y)).with_conditions(conditions))
}

/// The variable of the root `root` (a `sqrt` or `abs` node) of the radicand `radicand` as
/// written, whose expanded form has the printed `key` (the coefficient types print their values
/// exactly in `Debug`, and the terms of a polynomial are in a canonical order, so equal radicands
/// have equal keys): the variable already recorded for the key, else a new one named as the
/// root is printed.
///
/// # Errors
/// [`ExprError::NonConstantSqrt`] (for `abs`, [`ExprError::BadCall`]) when the table does not
/// allow roots; the `variables` limit.
fn root_variable(
    key: String,
    radicand: &Expr,
    root: &Expr,
    vars: &mut Vars,
) -> Result<Var, ExprError> {
    if !vars.roots_allowed() {
        return Err(match &root.kind {
            ExprKind::Call(..) => ExprError::BadCall {
                pos: root.pos,
                name: ABS.into(),
                why: "the absolute value of a non-constant expression is sqrt(E^2), a square \
                      root of an expression, which is not converted here"
                    .into(),
            },
            _ => ExprError::NonConstantSqrt { pos: radicand.pos },
        });
    }
    add_root(key, radicand, root.to_string(), vars)
}

/// The root named `name` in another table, with the radicand `written`, in `vars` (its radicand
/// converted there): the variable already recorded for an equal radicand, else a new one.
///
/// # Errors
/// The conversion's errors (a radicand with a division is refused here); the `variables`
/// limit.
pub(super) fn register_root<C: Coefficient>(
    written: &Expr,
    name: &str,
    vars: &mut Vars,
) -> Result<Var, ExprError> {
    let radicand = written.to_poly::<C>(vars)?;
    add_root(format!("{radicand:?}"), written, name.to_string(), vars)
}

/// The variable recorded for `key`, else a new root variable `name` (made distinct from the
/// table's names) with the radicand `radicand`.
fn add_root(
    key: String,
    radicand: &Expr,
    mut name: String,
    vars: &mut Vars,
) -> Result<Var, ExprError> {
    if let Some(v) = vars.root_by_key(&key) {
        return Ok(v);
    }
    // A different radicand printed the same way (impossible for the printer's output, kept
    // apart all the same).
    while vars.get(&name).is_some() {
        name.push(' ');
    }
    limits::VARIABLES
        .check(vars.len() as u64 + 1)
        .map_err(|error| ExprError::Limit {
            pos: radicand.pos,
            error,
        })?;
    Ok(vars.add_root(&name, Arc::new(radicand.clone()), key))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::{parse_expr, parse_expr_with_calls, to_latex, to_mathml, Notation};
    use crate::{ComplexRadical, Radical};

    fn constant<C: Coefficient>(text: &str) -> C {
        parse_expr(text).unwrap().eval_constant::<C>().unwrap()
    }

    #[test]
    fn abs_of_constants_in_every_number_type() {
        let q = |n, d| Rational::new(n, d).unwrap();
        assert_eq!(constant::<Rational>("abs(-3/2)"), q(3, 2));
        assert_eq!(constant::<Rational>("abs(2 - 5) + abs(4)"), q(7, 1));
        assert_eq!(
            constant::<Radical>("abs(1 - sqrt(2))"),
            constant::<Radical>("sqrt(2) - 1")
        );
        assert_eq!(
            constant::<ComplexRadical>("abs(3 + 4*i)"),
            constant::<ComplexRadical>("5")
        );
        assert_eq!(
            constant::<ComplexRadical>("abs(-2)"),
            constant::<ComplexRadical>("2")
        );
        let err = parse_expr("abs(1, 2)")
            .unwrap()
            .eval_constant::<Rational>()
            .unwrap_err();
        assert_eq!(err.to_string(), "abs at 0: takes 1 argument, not 2");
    }

    #[test]
    fn abs_is_the_root_of_the_square_and_shares_it() {
        let mut vars = Vars::new();
        vars.allow_roots();
        let a: Poly<Rational> = parse_expr("abs(x - 1)")
            .unwrap()
            .to_poly(&mut vars)
            .unwrap();
        let s: Poly<Rational> = parse_expr("sqrt(x^2 - 2*x + 1)")
            .unwrap()
            .to_poly(&mut vars)
            .unwrap();
        assert_eq!(a, s);
        assert_eq!(vars.roots().len(), 1);
        assert_eq!(vars.names(), ["x", "abs(x - 1)"]);
        assert_eq!(vars.roots()[0].radicand_expr().to_string(), "(x - 1)^2");
        // Without roots allowed: one line naming abs.
        let err = parse_expr("abs(x)")
            .unwrap()
            .to_poly::<Rational>(&mut Vars::new())
            .unwrap_err();
        assert!(err
            .to_string()
            .starts_with("abs at 0: the absolute value of a non-constant"));
    }

    #[test]
    fn roots_of_fractions_are_variables_with_the_divisors_as_conditions() {
        let mut vars = Vars::new();
        vars.allow_roots();
        let f: RatFun<Rational> = parse_expr("sqrt(1/x)")
            .unwrap()
            .to_ratfun(&mut vars)
            .unwrap();
        let y = vars.get("sqrt(1/x)").unwrap();
        assert_eq!(f.numerator(), &Poly::var(y));
        assert!(f.denominator().is_one());
        assert_eq!(f.conditions(), [Poly::var(vars.get("x").unwrap())]);
        // A radicand whose lowest terms are a polynomial is the root of that polynomial.
        let g: RatFun<Rational> = parse_expr("sqrt(x^2/x) - sqrt(x)")
            .unwrap()
            .to_ratfun(&mut vars)
            .unwrap();
        assert!(g.numerator().is_zero());
        // abs of a fraction; a constant fraction keeps its divisor.
        let h: RatFun<Rational> = parse_expr("abs(x/y)")
            .unwrap()
            .to_ratfun(&mut vars)
            .unwrap();
        assert_eq!(h.conditions().len(), 1);
        assert_eq!(vars.roots().len(), 3);
        let k: RatFun<Rational> = parse_expr("sqrt(4*x/x)")
            .unwrap()
            .to_ratfun(&mut vars)
            .unwrap();
        assert_eq!(k.numerator(), &Poly::constant(Rational::from_integer(2)));
        assert_eq!(k.conditions().len(), 1);
        // The polynomial conversion still refuses the division.
        assert!(matches!(
            parse_expr("sqrt(1/x)")
                .unwrap()
                .to_poly::<Rational>(&mut vars),
            Err(ExprError::NonConstantDivisor { .. })
        ));
    }

    #[test]
    fn abs_prints_as_bars() {
        let e = parse_expr_with_calls("abs(x - y)^2 / abs(2*t)").unwrap();
        assert_eq!(e.to_string(), "abs(x - y)^2/abs(2*t)");
        let n = Notation::new();
        assert_eq!(
            to_latex(&e, &n),
            "\\frac{\\left|x - y\\right|^{2}}{\\left|2\\,t\\right|}"
        );
        let m = to_mathml(&parse_expr("abs(x)").unwrap(), &n);
        assert_eq!(
            m,
            "<math display=\"block\"><mrow><mo>|</mo><mi>x</mi><mo>|</mo></mrow></math>"
        );
    }
}
