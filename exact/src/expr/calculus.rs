//! The functions `integrate(E, t, a, b)`, `sum(k, a, b, E)`, `binomial(n, k)` and
//! `factorial(n)`: their arguments, and their conversion to polynomials, rational functions and
//! constants.
//!
//! * `integrate` converts `E` to a polynomial in `t`, `cos(t)` and `sin(t)` (coefficients:
//!   polynomials in the other variables, or a rational function whose denominator and divisors
//!   do not involve them), takes the antiderivative ([`trig_integral`]) and evaluates it at the
//!   bounds: powers of a bound by Horner's rule, `cos(k b)` and `sin(k b)` converted from their
//!   trees. The integration variable is bound: the antiderivative is taken in a copy of the
//!   variable table and mapped back, so it never enters the caller's table, and the bounds are
//!   converted in the caller's table.
//! * `sum` with integer constant bounds substitutes each integer of `[a, b]` for the index in
//!   the tree of `E` (so that `binomial(n, k)` sees constants) and converts the terms one at a
//!   time. Nested sums share the one budget `sum-terms` ([`limits::SUM_TERMS`]). A sum with a
//!   bound that has a variable (`sum(k, 1, n, k^2)`) is the closed form of [`symbolic_sum`].
//! * `binomial` and `factorial` are exact integers, their size predicted against
//!   `constant-bits` ([`limits::CONSTANT_BITS`]) before they are computed, and computed by
//!   binary splitting (products of halves), which keeps the operands balanced.
//!
//! These are written here rather than taken from a computer-algebra crate because they must
//! work on the workspace's own polynomial type over every [`Coefficient`] and honour its limits.

use super::eval::{check_constant, size_error};
use super::trig::{cos_name, sin_name};
use super::trig_integral::{self, Antiderivative};
use super::*;
use crate::poly::{Poly, Var, Vars};
use crate::ratfun::RatFun;
use exactcheck_core::Field;
use num_traits::{One, ToPrimitive, Zero};
use std::cell::Cell;

/// The functions of this module.
pub(super) const CALCULUS: &[&str] = &["integrate", "sum", "binomial", "factorial"];

pub(super) fn bad(call: &Expr, pos: usize, why: impl Into<String>) -> ExprError {
    let ExprKind::Call(name, _) = &call.kind else {
        unreachable!("bad takes a call")
    };
    ExprError::BadCall {
        pos,
        name: name.clone(),
        why: why.into(),
    }
}

fn arity(call: &Expr, args: &[Expr], n: usize, what: &str) -> Result<(), ExprError> {
    if args.len() == n {
        Ok(())
    } else {
        Err(bad(
            call,
            call.pos,
            format!("takes {n} arguments ({what}), not {}", args.len()),
        ))
    }
}

fn variable_name<'a>(call: &Expr, arg: &'a Expr, which: &str) -> Result<&'a str, ExprError> {
    match &arg.kind {
        ExprKind::Var(t) => Ok(t),
        _ => Err(bad(
            call,
            arg.pos,
            format!("the {which} argument must be a variable name, not {arg}"),
        )),
    }
}

/// The value of an argument that must be an integer constant; `what` names it.
fn integer_argument(call: &Expr, arg: &Expr, what: &str) -> Result<BigInt, ExprError> {
    let not_integer = |found: String| {
        bad(
            call,
            arg.pos,
            format!("{what} must be an integer constant, not {found}"),
        )
    };
    let q: Rational = match arg.eval_constant() {
        Ok(q) => q,
        Err(ExprError::NotConstant { .. }) => {
            let hint = if matches!(&call.kind, ExprKind::Call(n, _) if n != "sum") {
                " (it needs integer constants; inside sum(k, a, b, ...) the index k is \
                 replaced by each integer first)"
            } else {
                ""
            };
            return Err(not_integer(format!("{arg}{hint}")));
        }
        Err(e) => return Err(e),
    };
    if q.is_integer() {
        Ok(q.numer())
    } else {
        Err(not_integer(q.to_string()))
    }
}

// ------------------------------------------------------------------------------ integers

/// `floor(log2 m!)` summed from below: `sum_{i=2}^{m} floor(log2 i)`, saturating.
pub(super) fn log2_factorial_floor(m: u64) -> u64 {
    let mut total = 0u64;
    let mut j = 1u32;
    while j < 64 && (1u64 << j) <= m {
        let lo = 1u64 << j;
        let hi = if j == 63 {
            m
        } else {
            m.min((1u64 << (j + 1)) - 1)
        };
        total = total.saturating_add((hi - lo + 1).saturating_mul(u64::from(j)));
        j += 1;
    }
    total
}

/// The product of the integers `lo, lo + 1, ..., lo + n - 1` by binary splitting.
fn range_product(lo: &BigInt, n: u64) -> BigInt {
    match n {
        0 => BigInt::one(),
        1 => lo.clone(),
        _ => {
            let half = n / 2;
            range_product(lo, half) * range_product(&(lo + BigInt::from(half)), n - half)
        }
    }
}

fn constant_bits_error(pos: usize, bits: u64) -> ExprError {
    ExprError::Limit {
        pos,
        error: limits::CONSTANT_BITS.exceeded(format!("at least {bits}")),
    }
}

/// `n!` for the integer `n >= 0`, refused when its size (predicted exactly from below) exceeds
/// `constant-bits`.
pub(super) fn factorial(n: &BigInt, pos: usize) -> Result<BigInt, ExprError> {
    // n! >= n for n >= 1, so an n beyond u64 is far beyond any limit.
    let m = n
        .to_u64()
        .ok_or_else(|| constant_bits_error(pos, u64::MAX))?;
    let bits = log2_factorial_floor(m);
    limits::CONSTANT_BITS
        .check(bits)
        .map_err(|_| constant_bits_error(pos, bits))?;
    Ok(range_product(&BigInt::one(), m))
}

/// `binomial(n, k)` for integers `n >= 0` and `k` (0 when `k < 0` or `k > n`), refused when
/// the result, or the product `n (n - 1) ... (n - k' + 1)` (`k' = min(k, n - k)`) that is
/// divided by `k'!`, would exceed `constant-bits` (the product: twice the limit).
pub(super) fn binomial(n: &BigInt, k: &BigInt, pos: usize) -> Result<BigInt, ExprError> {
    if k.is_negative() || k > n {
        return Ok(BigInt::zero());
    }
    let other = n - k;
    let kk = if &other < k { other } else { k.clone() };
    if kk.is_zero() {
        return Ok(BigInt::one());
    }
    // kk <= n / 2, and binomial(n, kk) >= n >= 2 kk: a kk beyond u64 is beyond every limit.
    let m = kk
        .to_u64()
        .ok_or_else(|| constant_bits_error(pos, u64::MAX))?;
    // binomial(n, m) >= (n / m)^m, and the numerator is at least (n - m + 1)^m.
    let result_bits = log2_floor(&(n / &kk)).saturating_mul(m);
    limits::CONSTANT_BITS
        .check(result_bits)
        .map_err(|_| constant_bits_error(pos, result_bits))?;
    let low = n - &kk + 1;
    let numerator_bits = log2_floor(&low).saturating_mul(m);
    if numerator_bits > limits::CONSTANT_BITS.get().saturating_mul(2) {
        return Err(ExprError::Limit {
            pos,
            error: limits::CONSTANT_BITS.exceeded(format!(
                "an intermediate product of at least {numerator_bits} (twice the limit is \
                 allowed there)"
            )),
        });
    }
    Ok(range_product(&low, m) / range_product(&BigInt::one(), m))
}

/// The value of `binomial(n, k)` or `factorial(n)` (the call `call`), an exact integer.
pub(super) fn integer_call(call: &Expr, args: &[Expr]) -> Result<Rational, ExprError> {
    let ExprKind::Call(name, _) = &call.kind else {
        unreachable!("integer_call takes a call")
    };
    let value = if name == "factorial" {
        arity(call, args, 1, "n")?;
        let n = integer_argument(call, &args[0], "its argument")?;
        if n.is_negative() {
            return Err(bad(
                call,
                args[0].pos,
                format!("the factorial of a negative number ({n}) is not defined"),
            ));
        }
        factorial(&n, call.pos)?
    } else {
        arity(call, args, 2, "n, k")?;
        let n = integer_argument(call, &args[0], "n")?;
        let k = integer_argument(call, &args[1], "k")?;
        if n.is_negative() {
            return Err(bad(
                call,
                args[0].pos,
                format!("n must be a non-negative integer, not {n}"),
            ));
        }
        binomial(&n, &k, call.pos)?
    };
    Ok(Rational::from(value))
}

// ------------------------------------------------------------------------------ sums

thread_local! {
    /// The nesting depth of sums being expanded and the terms they have taken so far: nested
    /// sums share one `sum-terms` budget.
    static SUM_BUDGET: Cell<(u32, u64)> = const { Cell::new((0, 0)) };
}

/// Holds a level of [`SUM_BUDGET`]; the outermost level resets the count.
struct SumLevel;

impl SumLevel {
    fn enter() -> SumLevel {
        SUM_BUDGET.with(|b| {
            let (depth, used) = b.get();
            b.set((depth + 1, if depth == 0 { 0 } else { used }));
        });
        SumLevel
    }

    /// Counts `n` more terms against the limit.
    fn take(&self, n: u64, pos: usize) -> Result<(), ExprError> {
        SUM_BUDGET.with(|b| {
            let (depth, used) = b.get();
            let used = used.saturating_add(n);
            b.set((depth, used));
            limits::SUM_TERMS
                .check(used)
                .map_err(|error| ExprError::Limit { pos, error })
        })
    }
}

impl Drop for SumLevel {
    fn drop(&mut self) {
        SUM_BUDGET.with(|b| {
            let (depth, used) = b.get();
            b.set((depth.saturating_sub(1), used));
        });
    }
}

/// The arguments of `sum(k, a, b, E)`: the index, the integer bounds and the body.
struct SumArgs<'a> {
    index: &'a str,
    from: BigInt,
    count: u64,
    body: &'a Expr,
}

fn sum_arguments<'a>(call: &Expr, args: &'a [Expr]) -> Result<SumArgs<'a>, ExprError> {
    arity(call, args, 4, "index, from, to, expression")?;
    let index = variable_name(call, &args[0], "first")?;
    let from = integer_argument(call, &args[1], "the lower bound")?;
    let to = integer_argument(call, &args[2], "the upper bound")?;
    let count = if to < from {
        0
    } else {
        (&to - &from + 1u32).to_u64().unwrap_or(u64::MAX)
    };
    Ok(SumArgs {
        index,
        from,
        count,
        body: &args[3],
    })
}

/// The terms of `sum(k, a, b, E)` (`E` with `k` replaced by `a`, `a + 1`, ..., `b`), each
/// converted by `convert`, counted against `sum-terms` before it is built.
pub(super) fn sum_terms<T>(
    call: &Expr,
    args: &[Expr],
    mut convert: impl FnMut(&Expr) -> Result<T, ExprError>,
) -> Result<Vec<T>, ExprError> {
    let s = sum_arguments(call, args)?;
    let level = SumLevel::enter();
    level.take(s.count, call.pos)?;
    let mut out = Vec::new();
    for j in 0..s.count {
        let value = Rational::from(&s.from + BigInt::from(j));
        let term = substitute(s.body, s.index, &value, call)?;
        out.push(convert(&term)?);
    }
    Ok(out)
}

/// `e` with the free occurrences of the variable `name` replaced by the number `value`, by the
/// library's binder-aware substitution ([`super::library::substitute_free`]: a `sum` or
/// `integrate` that binds the same name keeps its body). `diff` by `name` cannot be taken after
/// `name` is a number: it is refused first, naming `sum` (the call `within`).
fn substitute(e: &Expr, name: &str, value: &Rational, within: &Expr) -> Result<Expr, ExprError> {
    let mut by_index = None;
    super::library::map_tree(e, &mut |x| {
        if let ExprKind::Call(f, args) = &x.kind {
            if f == "diff"
                && matches!(args.get(1), Some(Expr { kind: ExprKind::Var(v), .. }) if v == name)
            {
                by_index.get_or_insert(args[1].pos);
            }
        }
    });
    if let Some(pos) = by_index {
        return Err(bad(
            within,
            pos,
            format!(
                "diff(..., {name}) differentiates by the summation index {name}, which is an \
                 integer there; take the derivative outside the sum"
            ),
        ));
    }
    super::library::substitute_free(e, name, &Expr::number(value.clone()))
        .map_err(|why| bad(within, within.pos, why))
}

// ------------------------------------------------------------------------------ integrals

/// The arguments of `integrate(E, t, a, b)`.
fn integrate_arguments<'a>(
    call: &Expr,
    args: &'a [Expr],
) -> Result<(&'a Expr, &'a str, &'a Expr, &'a Expr), ExprError> {
    arity(call, args, 4, "expression, variable, from, to")?;
    let t = variable_name(call, &args[1], "second")?;
    refuse_bound_only(call, &args[0], &args[1], t)?;
    Ok((&args[0], t, &args[2], &args[3]))
}

/// The refusal of `diff(E, t)` or `integrate(E, t, ..)` (the call `call`, its variable argument
/// `var` naming `t`) when `t` is not a free variable of `E` but only the index of a `sum` or the
/// variable of an `integrate` inside it: bound there, it is not a variable of `E` to take the
/// derivative or the integral in.
pub(super) fn refuse_bound_only(
    call: &Expr,
    body: &Expr,
    var: &Expr,
    t: &str,
) -> Result<(), ExprError> {
    let mut free = Vec::new();
    body.collect_variables(&mut free);
    if free.iter().any(|v| v == t) {
        return Ok(());
    }
    let mut binder = None;
    super::library::map_tree(body, &mut |x| {
        if let ExprKind::Call(f, args) = &x.kind {
            let bound = match (f.as_str(), args.as_slice()) {
                ("sum", [k, _, _, _]) => Some((k, "the index of a sum")),
                ("integrate", [_, v, _, _]) => Some((v, "the variable of an integral")),
                _ => None,
            };
            if let Some((index, what)) = bound {
                if matches!(&index.kind, ExprKind::Var(v) if v == t) {
                    binder.get_or_insert(what);
                }
            }
        }
    });
    match binder {
        None => Ok(()),
        Some(what) => Err(bad(
            call,
            var.pos,
            format!(
                "{t} is not a free variable of the expression: it is only {what} inside it, \
                 bound there; name a variable the expression has"
            ),
        )),
    }
}

/// The variables of `vars` that change with the variable `t`: `t` itself, the cosine and sine
/// of the base angle of `t` (`t`, or `t/L`), and the square roots whose radicand has `t` as a
/// free variable.
pub(super) fn moving_with(vars: &Vars, t: &str) -> Vec<Var> {
    let mut out: Vec<Var> = vars.get(t).into_iter().collect();
    if let Some((angle, _)) = super::angle_base::variable_base(vars, t) {
        out.extend([angle.cos, angle.sin]);
    }
    for root in vars.roots() {
        let mut names = Vec::new();
        root.radicand_expr().collect_variables(&mut names);
        if names.iter().any(|n| n == t) {
            out.push(root.var);
        }
    }
    out
}

/// The refusal of an integrand that holds a function of the integration variable `t` other
/// than `t`, `cos(t)` and `sin(t)` (a square root such as `sqrt(t)`), `involves` telling which
/// variables occur in it.
fn refuse_functions_of(
    call: &Expr,
    integrand: &Expr,
    t: &str,
    vars: &Vars,
    involves: impl Fn(Var) -> bool,
) -> Result<(), ExprError> {
    let allowed = [t.to_string(), cos_name(t), sin_name(t)].map(|name| vars.get(&name));
    match moving_with(vars, t)
        .into_iter()
        .find(|&w| !allowed.contains(&Some(w)) && involves(w))
    {
        None => Ok(()),
        Some(w) => Err(bad(
            call,
            integrand.pos,
            format!(
                "the integrand {integrand} holds {}, which changes with {t}: only integrands \
                 that are polynomials in {t}, cos({t}) and sin({t}) (their coefficients free \
                 of {t}) are integrated exactly",
                vars.name(w).unwrap_or(t)
            ),
        )),
    }
}

/// Converts with `convert` in a copy of `vars` when `t` is not in it yet, so that the bound
/// variable `t` stays out of the caller's table; the results (free of `t` and of everything
/// that changes with it, [`moving_with`]) are mapped back, the other new variables added to
/// `vars` in order of first appearance: a square root as a root of `vars` (its radicand
/// converted there), any other name as a variable.
pub(super) fn with_bound<C: Coefficient, T>(
    vars: &mut Vars,
    t: &str,
    convert: impl FnOnce(&mut Vars) -> Result<T, ExprError>,
    remap: impl FnOnce(T, &dyn Fn(Var) -> Var) -> T,
    pos: usize,
) -> Result<T, ExprError> {
    if vars.get(t).is_some() {
        return convert(vars);
    }
    let mut inner = vars.clone();
    let value = convert(&mut inner)?;
    if inner.len() == vars.len() {
        return Ok(value);
    }
    let moving = moving_with(&inner, t);
    let names = inner.names().to_vec();
    let mut map: Vec<Var> = Vec::with_capacity(inner.len());
    for (index, name) in names.iter().enumerate() {
        let inner_var = index as Var;
        if moving.contains(&inner_var) {
            // Unused: the result does not involve t or a function of it.
            map.push(Var::MAX);
            continue;
        }
        let new_root = (index >= vars.len())
            .then(|| inner.roots().iter().find(|r| r.var == inner_var))
            .flatten();
        let v = match new_root {
            Some(root) => super::roots::register_root::<C>(root.radicand_expr(), name, vars)?,
            _ => vars.var(name),
        };
        limits::VARIABLES
            .check(u64::from(v) + 1)
            .map_err(|error| ExprError::Limit { pos, error })?;
        map.push(v);
    }
    Ok(remap(value, &|v| map[v as usize]))
}

/// `p` with every variable `v` renamed `map(v)` (a bijection onto its image).
pub(super) fn rename<C: Ring>(p: &Poly<C>, map: &dyn Fn(Var) -> Var) -> Poly<C> {
    Poly::from_terms(p.terms().map(|(m, c)| {
        let exps: Vec<(Var, u32)> = m
            .exponents()
            .into_iter()
            .map(|(v, e)| (map(v), e))
            .collect();
        (exps, c.clone())
    }))
}

/// `sum_k parts[k] x^k` by Horner's rule in the ring `T` (`mul_add(acc, part)` is
/// `acc * x + part`).
pub(super) fn horner<T, C: Coefficient>(
    parts: &[Poly<C>],
    zero: T,
    mut mul_add: impl FnMut(T, &Poly<C>) -> Result<T, ExprError>,
) -> Result<T, ExprError> {
    let mut acc = zero;
    for p in parts.iter().rev() {
        acc = mul_add(acc, p)?;
    }
    Ok(acc)
}

/// The antiderivative of the integrand of `call` in its variable `t`
/// ([`trig_integral::antiderivative`]) of the polynomial `integrand` gives, with the divisor
/// it may give along (free of `t`), both mapped back to the caller's table.
fn bound_antiderivative<C: Coefficient, X>(
    call: &Expr,
    e: &Expr,
    t: &str,
    vars: &mut Vars,
    integrand: impl FnOnce(&mut Vars) -> Result<(Poly<C>, X), ExprError>,
    remap_divisor: impl FnOnce(X, &dyn Fn(Var) -> Var) -> X,
) -> Result<(Antiderivative<C>, X), ExprError> {
    with_bound::<C, _>(
        vars,
        t,
        |vars| {
            let (p, divisor) = integrand(vars)?;
            refuse_functions_of(call, e, t, vars, |w| p.degree_in(w) > 0)?;
            Ok((trig_integral::antiderivative(call, &p, t, vars)?, divisor))
        },
        |(anti, divisor), map| {
            let anti = anti
                .into_iter()
                .map(|(wave, parts)| (wave, parts.iter().map(|p| rename(p, map)).collect()))
                .collect();
            (anti, remap_divisor(divisor, map))
        },
        call.pos,
    )
}

/// `integrate(E, t, a, b)` of a polynomial `E` in `t`, `cos(t)`, `sin(t)` with polynomial
/// bounds: the antiderivative's value at `b` minus its value at `a`, `cos(k b)` and `sin(k b)`
/// converted from their trees.
pub(super) fn integrate_poly<C: Coefficient>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let (e, t, a, b) = integrate_arguments(call, args)?;
    let size = |err| size_error(err, call.pos);
    // The bounds first: their variables are free (a `t` there is the caller's).
    let lo = a.to_poly::<C>(vars)?;
    let hi = b.to_poly::<C>(vars)?;
    let (anti, _) = bound_antiderivative(
        call,
        e,
        t,
        vars,
        |vars| Ok((e.to_poly::<C>(vars)?, ())),
        |x, _| x,
    )?;
    let mut at = |x: &Poly<C>, bound: &Expr| -> Result<Poly<C>, ExprError> {
        let mut total = Poly::zero();
        for (wave, parts) in &anti {
            let value = horner(parts, Poly::zero(), |acc: Poly<C>, part| {
                let q = acc.try_mul(x).map_err(size)? + part.clone();
                q.coefficients()
                    .iter()
                    .try_for_each(|c| check_constant(c, call.pos))?;
                Ok(q)
            })?;
            let value = match trig_integral::wave_at(*wave, bound) {
                None => value,
                Some(tree) => {
                    let w = tree
                        .to_poly::<C>(vars)
                        .map_err(|why| not_angle(call, bound, why))?;
                    value.try_mul(&w).map_err(size)?
                }
            };
            total = total.add_ref(&value);
        }
        Ok(total)
    };
    Ok(at(&hi, b)? - at(&lo, a)?)
}

/// The refusal of a bound whose cosine or sine the conversion refused (`x^2`, `sqrt(2)`, `1`),
/// naming the bound; limits pass through unchanged.
fn not_angle(call: &Expr, bound: &Expr, why: ExprError) -> ExprError {
    match why {
        ExprError::Limit { .. } => why,
        ExprError::BadCall { why, .. } => bad(
            call,
            bound.pos,
            format!("the integral takes sin and cos of the bound {bound}, which is not an angle: {why}"),
        ),
        other => bad(
            call,
            bound.pos,
            format!("the integral takes sin and cos of the bound {bound}, which is not an angle: {other}"),
        ),
    }
}

/// `integrate(E, t, a, b)` of a rational function `E` whose denominator and divisors do not
/// involve `t`, `cos(t)` or `sin(t)`, with rational-function bounds.
pub(super) fn integrate_ratfun<C: Coefficient + Field>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<RatFun<C>, ExprError> {
    let (e, t, a, b) = integrate_arguments(call, args)?;
    let size = |err| size_error(err, call.pos);
    let lo = a.to_ratfun::<C>(vars)?;
    let hi = b.to_ratfun::<C>(vars)?;
    // E's denominator, free of t (its reciprocal, with E's conditions), mapped back with the
    // antiderivative of E's numerator.
    let (anti, divisor) = bound_antiderivative(
        call,
        e,
        t,
        vars,
        |vars| {
            let f = e.to_ratfun::<C>(vars)?;
            refuse_functions_of(call, e, t, vars, |w| {
                [f.numerator(), f.denominator()]
                    .into_iter()
                    .chain(f.conditions())
                    .any(|p| p.degree_in(w) > 0)
            })?;
            let moving = [t.to_string(), cos_name(t), sin_name(t)].map(|name| vars.get(&name));
            let divides = |p: &Poly<C>| moving.iter().flatten().any(|&w| p.degree_in(w) > 0);
            if divides(f.denominator()) || f.conditions().iter().any(divides) {
                return Err(bad(
                    call,
                    e.pos,
                    format!(
                        "the integrand {e} divides by an expression in {t}: only polynomials in \
                     {t}, cos({t}) and sin({t}) are integrated (the integral of a rational \
                     function is not in general rational)"
                    ),
                ));
            }
            Ok((f.numerator().clone(), f.denominator_reciprocal()))
        },
        |d, map| d.map_polys(|p| rename(p, map)),
    )?;
    let at = |x: &RatFun<C>, bound: &Expr, vars: &mut Vars| -> Result<RatFun<C>, ExprError> {
        let mut total = RatFun::from_poly(Poly::zero());
        for (wave, parts) in &anti {
            let value = horner(parts, RatFun::from_poly(Poly::zero()), |acc, part| {
                acc.mul(x)
                    .and_then(|q| q.add(&RatFun::from_poly(part.clone()), false))
                    .map_err(size)
            })?;
            let value = match trig_integral::wave_at(*wave, bound) {
                None => value,
                Some(tree) => {
                    let w = tree
                        .to_ratfun::<C>(vars)
                        .map_err(|why| not_angle(call, bound, why))?;
                    value.mul(&w).map_err(size)?
                }
            };
            total = total.add(&value, false).map_err(size)?;
        }
        Ok(total)
    };
    let value = at(&hi, b, vars)?
        .add(&at(&lo, a, vars)?, true)
        .map_err(size)?;
    // Divide by E's denominator (free of t), keeping E's conditions.
    value.mul(&divisor).map_err(size)
}

/// The polynomial value `p` of a sum at `pos`, held to the `terms` and `constant-bits` limits.
pub(super) fn checked_sum<C: Coefficient>(p: Poly<C>, pos: usize) -> Result<Poly<C>, ExprError> {
    limits::TERMS
        .check_usize(p.len())
        .map_err(|error| ExprError::Limit { pos, error })?;
    p.coefficients()
        .iter()
        .try_for_each(|c| check_constant(c, pos))?;
    Ok(p)
}

/// The value of a call of this module as a polynomial.
pub(super) fn call_poly<C: Coefficient>(
    call: &Expr,
    name: &str,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    match name {
        "integrate" => integrate_poly(call, args, vars),
        "sum" if super::symbolic_sum::is_symbolic(args) => {
            super::symbolic_sum::sum_poly(call, args, vars)
        }
        "sum" => {
            let parts = sum_terms(call, args, |term| term.to_poly::<C>(vars))?;
            checked_sum(Poly::sum(parts), call.pos)
        }
        _ => {
            let q = integer_call(call, args)?;
            C::from_rational(&q)
                .map(Poly::constant)
                .ok_or_else(|| ExprError::Unrepresentable {
                    pos: call.pos,
                    number: q.to_string(),
                })
        }
    }
}

/// The value of a call of this module as a rational function.
pub(super) fn call_ratfun<C: Coefficient + Field>(
    call: &Expr,
    name: &str,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<RatFun<C>, ExprError> {
    match name {
        "integrate" => integrate_ratfun(call, args, vars),
        "sum" if super::symbolic_sum::is_symbolic(args) => {
            super::symbolic_sum::sum_ratfun(call, args, vars)
        }
        "sum" => {
            let size = |err| size_error(err, call.pos);
            let mut acc = RatFun::from_poly(Poly::zero());
            for f in sum_terms(call, args, |term| term.to_ratfun::<C>(vars))? {
                acc = acc.add(&f, false).map_err(size)?;
            }
            Ok(acc)
        }
        _ => call_poly(call, name, args, vars).map(RatFun::from_poly),
    }
}

/// The value of a call of this module in a constant expression.
pub(super) fn call_constant<C: Coefficient>(
    call: &Expr,
    name: &str,
    args: &[Expr],
) -> Result<C, ExprError> {
    match name {
        "sum" => {
            let mut acc = C::zero();
            for v in sum_terms(call, args, |term| term.eval_constant::<C>())? {
                acc += v;
                check_constant(&acc, call.pos)?;
            }
            Ok(acc)
        }
        "integrate" => {
            let mut vars = Vars::new();
            let p = integrate_poly::<C>(call, args, &mut vars)?;
            p.constant_value().ok_or_else(|| {
                let name = p
                    .variables()
                    .first()
                    .and_then(|&v| vars.name(v))
                    .unwrap_or("?")
                    .to_string();
                ExprError::NotConstant {
                    pos: call.pos,
                    name,
                    hint: "",
                }
            })
        }
        _ => {
            let q = integer_call(call, args)?;
            C::from_rational(&q).ok_or_else(|| ExprError::Unrepresentable {
                pos: call.pos,
                number: q.to_string(),
            })
        }
    }
}

/// Appends the free variables of `call` (a call of this module) to `out`: a sum's index and an
/// integral's variable are bound in the body.
pub(super) fn collect_call_variables(name: &str, args: &[Expr], out: &mut Vec<String>) {
    let (bound, body, rest): (Option<&Expr>, Option<&Expr>, Vec<&Expr>) = match (name, args) {
        ("sum", [k, a, b, e]) => (Some(k), Some(e), vec![a, b]),
        ("integrate", [e, t, a, b]) => (Some(t), Some(e), vec![a, b]),
        _ => (None, None, args.iter().collect()),
    };
    for a in rest {
        a.collect_variables(out);
    }
    let Some(body) = body else { return };
    let mut inner = Vec::new();
    body.collect_variables(&mut inner);
    for v in inner {
        let is_bound = matches!(bound, Some(Expr { kind: ExprKind::Var(k), .. }) if *k == v);
        if !is_bound && !out.contains(&v) {
            out.push(v);
        }
    }
}
