//! The conversion of an [`Expr`] to a rational function ([`RatFun`]), and the arguments of
//! `diff`.

use super::eval::{check_constant, exponent_value, size_error};
use super::trig::{total_derivative, total_derivative_ratfun, Trig};
use super::*;
use crate::poly::{Poly, Vars};
use crate::ratfun::RatFun;
use exactcheck_core::Field;
use num_traits::ToPrimitive;

impl Expr {
    /// Whether the expression divides by something with a variable: a division by a
    /// non-constant expression, a negative power of one, or a `diff`, `integrate` or `sum` of
    /// such an expression (or with such bounds).
    /// Without one it is a polynomial, which [`Expr::to_ratfun`] converts by [`Expr::to_poly`]
    /// alone.
    pub fn has_fractions(&self) -> bool {
        match &self.kind {
            ExprKind::Number(_) | ExprKind::Var(_) | ExprKind::Sqrt(_) => false,
            ExprKind::Neg(x) => x.has_fractions(),
            ExprKind::Sum(ts) => ts.iter().any(|(_, t)| t.has_fractions()),
            ExprKind::Product(fs) => fs
                .iter()
                .any(|(op, f)| f.has_fractions() || (*op == MulOp::Divide && f.has_variable())),
            ExprKind::Pow(b, e) => {
                b.has_fractions() || (b.has_variable() && exponent_value(e).is_ok_and(|k| k < 0))
            }
            ExprKind::Call(name, args) => match name.as_str() {
                "diff" => args.first().is_some_and(Expr::has_fractions),
                "integrate" | "sum" => args.iter().any(Expr::has_fractions),
                "tan" => args.iter().any(Expr::has_variable),
                _ => false,
            },
        }
    }

    /// Whether a variable occurs in the tree.
    fn has_variable(&self) -> bool {
        match &self.kind {
            ExprKind::Number(_) => false,
            ExprKind::Var(_) => true,
            ExprKind::Neg(x) | ExprKind::Sqrt(x) => x.has_variable(),
            ExprKind::Pow(a, b) => a.has_variable() || b.has_variable(),
            ExprKind::Sum(ts) => ts.iter().any(|(_, t)| t.has_variable()),
            ExprKind::Product(fs) => fs.iter().any(|(_, f)| f.has_variable()),
            ExprKind::Call(_, args) => args.iter().any(Expr::has_variable),
        }
    }

    /// The rational function this expression denotes, over `C`, in lowest terms, with every
    /// divisor met in [`RatFun::conditions`]; variables are looked up (and added) in `vars`. An
    /// expression without fractions ([`Expr::has_fractions`]) is converted by
    /// [`Expr::to_poly`] alone, so a polynomial costs what it costs there.
    ///
    /// ```
    /// use exactcheck_core::Ring;
    /// use exactcheck_exact::{expr::parse_expr, poly::Vars, Rational};
    ///
    /// let mut vars = Vars::new();
    /// let f = parse_expr("(x^2 - 1)/(x - 1)").unwrap().to_ratfun::<Rational>(&mut vars).unwrap();
    /// assert_eq!(f.numerator().display(&vars).to_string(), "x + 1");
    /// assert!(f.denominator().is_one());
    /// assert_eq!(f.conditions()[0].display(&vars).to_string(), "x - 1");
    /// ```
    ///
    /// # Errors
    /// Those of [`Expr::to_poly`] except the division by a non-constant expression;
    /// [`ExprError::ZeroDivisor`] for a division by (or a negative power of) an expression that
    /// is identically zero, [`ExprError::BadCall`] for a malformed `diff`.
    pub fn to_ratfun<C: Coefficient + Field>(
        &self,
        vars: &mut Vars,
    ) -> Result<RatFun<C>, ExprError> {
        if !self.has_fractions() {
            return self.to_poly(vars).map(RatFun::from_poly);
        }
        let size = |e| size_error(e, self.pos);
        let f = match &self.kind {
            ExprKind::Neg(x) => x.to_ratfun::<C>(vars)?.neg(),
            ExprKind::Sum(items) => {
                let mut acc: Option<RatFun<C>> = None;
                for (op, x) in items {
                    let f = x.to_ratfun::<C>(vars)?;
                    let minus = *op == AddOp::Minus;
                    acc = Some(match acc {
                        None if minus => f.neg(),
                        None => f,
                        Some(a) => a.add(&f, minus).map_err(size)?,
                    });
                }
                acc.unwrap_or_else(|| RatFun::from_poly(Poly::zero()))
            }
            ExprKind::Product(items) => {
                let mut acc = RatFun::from_poly(Poly::one());
                for (op, x) in items {
                    if *op == MulOp::Divide {
                        if let Some(inv) = reciprocal_power::<C>(x, vars) {
                            acc = acc.mul(&inv).map_err(size)?;
                            continue;
                        }
                    }
                    let f = x.to_ratfun::<C>(vars)?;
                    acc = match op {
                        MulOp::Times => acc.mul(&f).map_err(size)?,
                        MulOp::Divide => {
                            acc.div(&f).map_err(size)?.ok_or_else(|| zero_divisor(x))?
                        }
                    };
                }
                acc
            }
            ExprKind::Pow(base, exp) => {
                let k = exponent_value(exp)?;
                base.to_ratfun::<C>(vars)?
                    .pow(k)
                    .map_err(size)?
                    .ok_or_else(|| zero_divisor(base))?
            }
            ExprKind::Call(name, args) if super::calculus::CALCULUS.contains(&name.as_str()) => {
                super::calculus::call_ratfun(self, name, args, vars)?
            }
            ExprKind::Call(name, args) if Trig::from_name(name).is_some() => {
                let which = Trig::from_name(name).expect("matched above");
                super::trig::trig_ratfun(self, which, args, vars)?
            }
            ExprKind::Call(_, args) => {
                let (e, t, k) = diff_arguments(self, args)?;
                let mut f = e.to_ratfun::<C>(vars)?;
                // In `t` and, by the chain rule, in the cosine and sine of the angle `t`; zero
                // when `t` occurs in neither (all of `e`'s variables are in the table now).
                for _ in 0..k {
                    f = total_derivative_ratfun(&f, vars, t).map_err(size)?;
                }
                f
            }
            ExprKind::Number(_) | ExprKind::Var(_) | ExprKind::Sqrt(_) => {
                unreachable!("a number, a variable or a sqrt has no fractions")
            }
        };
        for p in [f.numerator(), f.denominator()] {
            limits::TERMS
                .check_usize(p.len())
                .map_err(|error| ExprError::Limit {
                    pos: self.pos,
                    error,
                })?;
            p.coefficients()
                .iter()
                .try_for_each(|c| check_constant(c, self.pos))?;
        }
        Ok(f)
    }
}

/// `1 / x` for a divisor `x = B^k` (`k` a positive integer) as `(1 / B)^k`: the same fraction
/// and the same condition (that of `B`, the square-free part of `B^k`) without computing the
/// square-free part of `B^k` by gcds. `None` when `x` is not such a power or anything fails
/// (zero, a limit), so that the caller's general path reports it as before.
fn reciprocal_power<C: Coefficient + Field>(x: &Expr, vars: &mut Vars) -> Option<RatFun<C>> {
    let ExprKind::Pow(base, exp) = &x.kind else {
        return None;
    };
    let k = exponent_value(exp).ok().filter(|&k| k > 0)?;
    let inv = base.to_ratfun::<C>(vars).ok()?.pow(-k).ok()??;
    let fits = |p: &Poly<C>| {
        limits::TERMS.check_usize(p.len()).is_ok()
            && p.coefficients()
                .iter()
                .all(|c| check_constant(c, x.pos).is_ok())
    };
    (fits(inv.numerator()) && fits(inv.denominator())).then_some(inv)
}

/// The error of dividing by `divisor`, which is identically zero.
fn zero_divisor(divisor: &Expr) -> ExprError {
    ExprError::ZeroDivisor {
        pos: divisor.pos,
        divisor: divisor.to_string(),
    }
}

/// The arguments of the call `call` = `diff(E, t)` or `diff(E, t, k)`: `E`, the name `t` and
/// the order `k` (1 when not given), a non-negative integer constant within the `diff-order`
/// limit. A call of another name is [`ExprError::UnknownFunction`].
pub(super) fn diff_arguments<'a>(
    call: &Expr,
    args: &'a [Expr],
) -> Result<(&'a Expr, &'a str, u32), ExprError> {
    let ExprKind::Call(name, _) = &call.kind else {
        unreachable!("diff_arguments takes a call")
    };
    if name != "diff" {
        return Err(ExprError::UnknownFunction {
            pos: call.pos,
            name: name.clone(),
        });
    }
    let bad = |pos: usize, why: String| ExprError::BadCall {
        pos,
        name: name.clone(),
        why,
    };
    if !(2..=3).contains(&args.len()) {
        return Err(bad(
            call.pos,
            format!(
                "takes 2 or 3 arguments (expression, variable[, order]), not {}",
                args.len()
            ),
        ));
    }
    let ExprKind::Var(t) = &args[1].kind else {
        return Err(bad(
            args[1].pos,
            format!(
                "the second argument must be a variable name, not {}",
                args[1]
            ),
        ));
    };
    if t == PI {
        return Err(bad(
            args[1].pos,
            "pi is a constant, not a variable to differentiate in".into(),
        ));
    }
    let k = match args.get(2) {
        None => 1,
        Some(order) => {
            let not_order = || {
                bad(
                    order.pos,
                    format!("the order must be a non-negative integer constant, not {order}"),
                )
            };
            let q: Rational = order.eval_constant().map_err(|_| not_order())?;
            if !q.is_integer() || q.signum() == exactcheck_core::Sign::Negative {
                return Err(not_order());
            }
            let k = q.numer().to_u64().unwrap_or(u64::MAX);
            limits::DIFF_ORDER
                .check(k)
                .map_err(|error| ExprError::Limit {
                    pos: order.pos,
                    error,
                })?;
            u32::try_from(k).map_err(|_| ExprError::Limit {
                pos: order.pos,
                error: limits::DIFF_ORDER.exceeded(k.to_string()),
            })?
        }
    };
    Ok((&args[0], t, k))
}

/// `diff` of a polynomial: `E` converted by [`Expr::to_poly`] and differentiated `k` times.
pub(super) fn diff_poly<C: Coefficient>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let (e, t, k) = diff_arguments(call, args)?;
    let mut p = e.to_poly::<C>(vars)?;
    for _ in 0..k {
        p = total_derivative(&p, vars, t);
    }
    Ok(p)
}
