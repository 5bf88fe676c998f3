//! The conversion of an [`Expr`] to a rational function ([`RatFun`]), and the arguments of
//! `diff`.

use super::derivative::{
    has_variable_root, total_derivative, total_derivative_fraction, total_derivative_ratfun,
};
use super::eval::{check_constant, exponent_value, size_error};
use super::trig::Trig;
use super::*;
use crate::poly::{Poly, Vars};
use crate::ratfun::{Fraction, RatFun};
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
            ExprKind::Number(_) | ExprKind::Var(_) => false,
            ExprKind::Neg(x) | ExprKind::Sqrt(x) => x.has_fractions(),
            ExprKind::Sum(ts) => ts.iter().any(|(_, t)| t.has_fractions()),
            ExprKind::Product(fs) => fs
                .iter()
                .any(|(op, f)| f.has_fractions() || (*op == MulOp::Divide && f.has_variable())),
            ExprKind::Pow(b, e) => {
                b.has_fractions() || (b.has_variable() && exponent_value(e).is_ok_and(|k| k < 0))
            }
            ExprKind::Call(name, args) => match name.as_str() {
                "diff" => args
                    .first()
                    .is_some_and(|e| e.has_fractions() || has_variable_root(e)),
                "integrate" | "sum" | super::ABS => args.iter().any(Expr::has_fractions),
                "tan" => self.has_variable(),
                _ => false,
            },
        }
    }

    /// Whether a variable occurs in the tree (or the cosine or sine of a constant angle that is
    /// no multiple of pi, which the conversion makes variables).
    pub(super) fn has_variable(&self) -> bool {
        match &self.kind {
            ExprKind::Number(_) => false,
            ExprKind::Var(_) => true,
            ExprKind::Neg(x) | ExprKind::Sqrt(x) => x.has_variable(),
            ExprKind::Pow(a, b) => a.has_variable() || b.has_variable(),
            ExprKind::Sum(ts) => ts.iter().any(|(_, t)| t.has_variable()),
            ExprKind::Product(fs) => fs.iter().any(|(_, f)| f.has_variable()),
            // `sin(1)` is the sine of the constant base angle, a variable of the conversion.
            ExprKind::Call(_, args) => {
                args.iter().any(Expr::has_variable) || super::trig::is_transcendental_constant(self)
            }
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
                        MulOp::Times | MulOp::Dot | MulOp::Cross => acc.mul(&f).map_err(size)?,
                        MulOp::Divide => {
                            acc.div(&f).map_err(size)?.ok_or_else(|| zero_divisor(x))?
                        }
                    };
                }
                acc
            }
            ExprKind::Pow(base, exp) => {
                if let Some(c) = super::eval::fractional_power(self, exp) {
                    return Ok(RatFun::from_poly(Poly::constant(c?)));
                }
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
            ExprKind::Sqrt(_) => super::roots::root_ratfun(self, vars)?,
            ExprKind::Call(name, _) if name == super::ABS => super::roots::root_ratfun(self, vars)?,
            ExprKind::Call(_, args) => {
                let (e, t, k) = diff_arguments(self, args)?;
                let mut f = e.to_ratfun::<C>(vars)?;
                // In `t` and, by the chain rule, in the cosine and sine of the angle `t`; zero
                // when `t` occurs in neither (all of `e`'s variables are in the table now).
                for _ in 0..k {
                    f = total_derivative_ratfun(&f, vars, t, self.pos)?;
                }
                f
            }
            ExprKind::Number(_) | ExprKind::Var(_) => {
                unreachable!("a number or a variable has no fractions")
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

impl Expr {
    /// The rational function as a [`Fraction`]: the operations of [`Expr::to_ratfun`] (the same
    /// divisors recorded in the same order) without any cancellation; calls other than `diff`
    /// are converted by [`Expr::to_ratfun`]. `None` for anything [`Expr::to_ratfun`] might
    /// refuse or reduce differently: an error, a limit on a numerator or a factor, a factor list
    /// past its budget.
    pub fn to_fraction<C: Coefficient + Field>(&self, vars: &mut Vars) -> Option<Fraction<C>> {
        if !self.has_fractions() {
            return self.to_poly(vars).ok().map(Fraction::from_poly);
        }
        let f = match &self.kind {
            ExprKind::Neg(x) => x.to_fraction::<C>(vars)?.neg(),
            ExprKind::Sum(items) => {
                let mut acc: Option<Fraction<C>> = None;
                for (op, x) in items {
                    let f = x.to_fraction::<C>(vars)?;
                    let minus = *op == AddOp::Minus;
                    acc = Some(match acc {
                        None if minus => f.neg(),
                        None => f,
                        Some(a) => a.add(&f, minus)?,
                    });
                }
                acc.unwrap_or_else(|| Fraction::from_poly(Poly::zero()))
            }
            ExprKind::Product(items) => {
                let mut acc = Fraction::from_poly(Poly::one());
                for (op, x) in items {
                    let f = match (op, &x.kind) {
                        // `1 / B^k` as `(1 / B)^k`, as `to_ratfun` takes it.
                        (MulOp::Divide, ExprKind::Pow(base, exp))
                            if exponent_value(exp).is_ok_and(|k| k > 0) =>
                        {
                            let k = exponent_value(exp).ok()?;
                            base.to_fraction::<C>(vars)?.pow(-k)?
                        }
                        (MulOp::Divide, _) => x.to_fraction::<C>(vars)?.recip()?,
                        (MulOp::Times | MulOp::Dot | MulOp::Cross, _) => {
                            x.to_fraction::<C>(vars)?
                        }
                    };
                    acc = acc.mul(&f)?;
                }
                acc
            }
            ExprKind::Pow(base, exp) => {
                if let Some(c) = super::eval::fractional_power(self, exp) {
                    return Some(Fraction::from_ratfun(&RatFun::from_poly(Poly::constant(
                        c.ok()?,
                    ))));
                }
                let k = exponent_value(exp).ok()?;
                base.to_fraction::<C>(vars)?.pow(k)?
            }
            ExprKind::Call(name, args) if name == "diff" => {
                let (e, t, k) = diff_arguments(self, args).ok()?;
                let mut f = e.to_fraction::<C>(vars)?;
                for _ in 0..k {
                    f = total_derivative_fraction(&f, vars, t)?;
                }
                f
            }
            ExprKind::Call(..) | ExprKind::Sqrt(_) => {
                Fraction::from_ratfun(&self.to_ratfun::<C>(vars).ok()?)
            }
            ExprKind::Number(_) | ExprKind::Var(_) => {
                unreachable!("a number or a variable has no fractions")
            }
        };
        for p in std::iter::once(f.numerator()).chain(f.factors().iter().map(|(p, _)| p)) {
            limits::TERMS.check_usize(p.len()).ok()?;
            p.coefficients()
                .iter()
                .try_for_each(|c| check_constant(c, self.pos))
                .ok()?;
        }
        Some(f)
    }
}

impl Expr {
    /// The expression as a [`Fraction`] with its reason when there is none: the fraction of
    /// [`Expr::to_fraction`] (nothing cancelled), else, where that gives up (a factor list past
    /// its budget), the rational function of [`Expr::to_ratfun`] as a fraction; a division by
    /// zero, a bad exponent or call, a limit are [`Expr::to_ratfun`]'s errors.
    ///
    /// ```
    /// use exactcheck_exact::{expr::parse_expr, poly::Vars, Rational};
    ///
    /// let mut vars = Vars::new();
    /// let f = parse_expr("(x^2 - 1)/(x - 1)").unwrap().try_to_fraction::<Rational>(&mut vars);
    /// let f = f.unwrap();
    /// assert_eq!(f.numerator().display(&vars).to_string(), "x^2 - 1");
    /// assert_eq!(f.denominator().unwrap().display(&vars).to_string(), "x - 1");
    /// assert!(parse_expr("1/(x - x)").unwrap().try_to_fraction::<Rational>(&mut vars).is_err());
    /// ```
    ///
    /// # Errors
    /// Those of [`Expr::to_ratfun`].
    pub fn try_to_fraction<C: Coefficient + Field>(
        &self,
        vars: &mut Vars,
    ) -> Result<Fraction<C>, ExprError> {
        match self.to_fraction::<C>(vars) {
            Some(f) => Ok(f),
            None => self.to_ratfun::<C>(vars).map(|r| Fraction::from_ratfun(&r)),
        }
    }
}

/// The two sides of an identity `lhs = rhs` as rational functions: what [`Expr::to_ratfun`]
/// gives for each, computed more cheaply when the identity holds.
///
/// Both sides are first converted without cancellation ([`Expr::to_fraction`]) and
/// cross-multiplied once ([`Fraction::cross_residual`]). When that residual vanishes the two
/// are the same rational function, so they have the same lowest terms: only the smaller side
/// is reduced ([`Fraction::to_ratfun`], from the fraction already built, which gives what
/// [`Expr::to_ratfun`] gives), and the other side is that fraction with its own divisors
/// ([`RatFun::with_conditions`]). A true identity then costs about what its cleared numerator
/// costs as a polynomial identity, instead of an exact division of every summed numerator by
/// the common factors of its denominator. Otherwise (and whenever the cheap conversion gives
/// up) each side is converted by [`Expr::to_ratfun`], as before.
///
/// # Errors
/// Those of [`Expr::to_ratfun`], with the side they come from: `Err((false, e))` for the left
/// side, `Err((true, e))` for the right one.
#[allow(clippy::type_complexity)]
pub fn ratfun_sides<C: Coefficient + Field>(
    lhs: &Expr,
    rhs: &Expr,
    vars: &mut Vars,
) -> Result<(RatFun<C>, RatFun<C>), (bool, ExprError)> {
    if lhs.has_fractions() || rhs.has_fractions() {
        let mut cheap = || -> Option<(RatFun<C>, RatFun<C>)> {
            let l = lhs.to_fraction::<C>(vars)?;
            let r = rhs.to_fraction::<C>(vars)?;
            if !l.cross_residual(&r)?.is_zero() {
                return None;
            }
            // The smaller side reduced as built, held to the limits `to_ratfun` checks.
            let fits = |f: &RatFun<C>, pos: usize| {
                [f.numerator(), f.denominator()].iter().all(|p| {
                    limits::TERMS.check_usize(p.len()).is_ok()
                        && p.coefficients()
                            .iter()
                            .all(|c| check_constant(c, pos).is_ok())
                })
            };
            if l.terms() <= r.terms() {
                let reduced = l.to_ratfun().filter(|f| fits(f, lhs.pos))?;
                let other = reduced.with_conditions(r.into_conditions());
                Some((reduced, other))
            } else {
                let reduced = r.to_ratfun().filter(|f| fits(f, rhs.pos))?;
                let other = reduced.with_conditions(l.into_conditions());
                Some((other, reduced))
            }
        };
        if let Some(sides) = cheap() {
            return Ok(sides);
        }
    }
    let l = lhs.to_ratfun::<C>(vars).map_err(|e| (false, e))?;
    let r = rhs.to_ratfun::<C>(vars).map_err(|e| (true, e))?;
    Ok((l, r))
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
    super::calculus::refuse_bound_only(call, &args[0], &args[1], t)?;
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
        p = total_derivative(&p, vars, t, call.pos)?;
    }
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use proptest::prelude::*;

    /// `ratfun_sides` on the texts against each side's own `to_ratfun`: the same fractions, the
    /// same conditions, the same variables (or the same error, on the same side).
    fn same_as_each_side(lhs: &str, rhs: &str) {
        let (l, r) = (parse_expr(lhs).unwrap(), parse_expr(rhs).unwrap());
        let mut v1 = Vars::new();
        let fast = ratfun_sides::<Rational>(&l, &r, &mut v1);
        let mut v2 = Vars::new();
        let plain = l
            .to_ratfun::<Rational>(&mut v2)
            .map_err(|e| (false, e))
            .and_then(|a| Ok((a, r.to_ratfun::<Rational>(&mut v2).map_err(|e| (true, e))?)));
        match (fast, plain) {
            (Ok(a), Ok(b)) => assert_eq!(a, b, "{lhs} = {rhs}"),
            (Err((s1, e1)), Err((s2, e2))) => {
                assert_eq!((s1, e1.to_string()), (s2, e2.to_string()), "{lhs} = {rhs}")
            }
            (a, b) => panic!("{lhs} = {rhs}: {a:?} vs {b:?}"),
        }
        assert_eq!(v1.names(), v2.names(), "{lhs} = {rhs}");
    }

    #[test]
    fn true_identities_take_the_cheap_route_to_the_same_sides() {
        same_as_each_side("(x^2-1)/(x-1)", "x+1");
        same_as_each_side("((1-t^2)/(1+t^2))^2 + (2*t/(1+t^2))^2", "1");
        same_as_each_side("diff(t^3/(1+t), t)", "(2*t^3+3*t^2)/(1+t)^2");
        same_as_each_side("x/(x*y) + 1/(y^2)", "(y + 1)/y^2");
        // Not identities, or not fractions: each side on its own.
        same_as_each_side("(x^2-1)/(x-1)", "x");
        same_as_each_side("x + 1", "1 + x");
        // Errors keep their side.
        same_as_each_side("1/(x-x)", "1");
        same_as_each_side("1/x", "diff(x, 2)");
    }

    /// An expression in `x, y` from the drawn choices: atoms combined by `+ - * /`, powers and
    /// derivatives.
    fn expression(choices: &[u8]) -> String {
        const ATOMS: [&str; 6] = ["x", "y", "x + 1", "x - y", "x^2 + 1", "2*y"];
        let mut it = choices.iter();
        let mut e = ATOMS[usize::from(*it.next().unwrap_or(&0)) % ATOMS.len()].to_string();
        while let (Some(&op), Some(&a)) = (it.next(), it.next()) {
            let atom = ATOMS[usize::from(a) % ATOMS.len()];
            e = match op % 6 {
                0 => format!("({e}) + ({atom})"),
                1 => format!("({e}) - ({atom})"),
                2 => format!("({e}) * ({atom})"),
                3 => format!("({e}) / ({atom})"),
                4 => format!("({atom}) / ({e})^2"),
                _ => format!("diff({e}, x)"),
            };
        }
        e
    }

    /// `try_to_fraction` against `to_ratfun` on the text: the same rational function (zero
    /// cross residual with the reduced one) with the same conditions, or the same error.
    fn fraction_agrees(text: &str) {
        let e = parse_expr(text).unwrap();
        let mut v1 = Vars::new();
        let f = e.try_to_fraction::<Rational>(&mut v1);
        let mut v2 = Vars::new();
        let r = e.to_ratfun::<Rational>(&mut v2);
        match (f, r) {
            (Ok(f), Ok(r)) => {
                let reduced = Fraction::from_ratfun(&r);
                assert!(f.cross_residual(&reduced).unwrap().is_zero(), "{text}");
                assert_eq!(f.conditions(), r.conditions(), "{text}");
                let den = f.denominator().unwrap();
                assert_eq!(
                    f.numerator().mul_ref(r.denominator()),
                    r.numerator().mul_ref(&den),
                    "{text}"
                );
            }
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{text}"),
            (a, b) => panic!("{text}: {a:?} vs {b:?}"),
        }
        assert_eq!(v1.names(), v2.names(), "{text}");
    }

    #[test]
    fn fractions_with_their_errors() {
        // Nothing cancelled: the written numerator over the written denominator.
        let mut vars = Vars::new();
        let f = parse_expr("(x^2 - 1)/(x - 1) + 1/(x - 1)")
            .unwrap()
            .try_to_fraction::<Rational>(&mut vars)
            .unwrap();
        assert_eq!(f.numerator().display(&vars).to_string(), "x^2");
        assert_eq!(f.factors().len(), 1);
        fraction_agrees("(x^2 - 1)/(x - 1) + 1/(x - 1)");
        fraction_agrees("(1/3)*(2*x + y)/(x*y)");
        fraction_agrees("x^3");
        // Past the factor budget: the reduced rational function, the same conditions.
        let many: Vec<String> = (1..=crate::ratfun::MAX_FACTORS + 1)
            .map(|k| format!("1/(x + {k})"))
            .collect();
        let text = many.join(" + ");
        assert!(parse_expr(&text)
            .unwrap()
            .to_fraction::<Rational>(&mut Vars::new())
            .is_none());
        fraction_agrees(&text);
        // The errors of to_ratfun.
        fraction_agrees("1/(x - x)");
        fraction_agrees("x^(1/2)");
        fraction_agrees("sqrt(x)");
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Random rational expressions: the fraction (or the error) is the rational function
        /// `to_ratfun` gives.
        #[test]
        fn try_to_fraction_is_the_rational_function(
            choices in proptest::collection::vec(0u8..=255, 1..=9),
        ) {
            fraction_agrees(&expression(&choices));
        }

        /// Random rational expressions against their own lowest terms written out (a true
        /// identity) and against those plus one (a false one): the cheap route gives the sides
        /// (or the error) that converting each side on its own gives.
        #[test]
        fn cheap_sides_equal_each_side_reduced(
            choices in proptest::collection::vec(0u8..=255, 1..=9),
        ) {
            let lhs = expression(&choices);
            let mut vars = Vars::from_names(["x", "y"]);
            let Ok(f) = parse_expr(&lhs).unwrap().to_ratfun::<Rational>(&mut vars) else {
                return Ok(());
            };
            let shown = format!(
                "({}) / ({})",
                f.numerator().display(&vars),
                f.denominator().display(&vars)
            );
            same_as_each_side(&lhs, &shown);
            same_as_each_side(&shown, &lhs);
            same_as_each_side(&lhs, &format!("{shown} + 1"));
        }
    }
}
