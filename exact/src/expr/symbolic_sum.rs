//! `sum(k, a, b, E)` with a bound that is not an integer constant (`sum(k, 1, n, k^2)`): the
//! closed form of a polynomial `E` in `k`.
//!
//! The bounds must take integer values: polynomials with integer coefficients in the other
//! variables (`n`, `n + 1`, `2 n`, `m`), which are then integers. `E` must be a polynomial in
//! `k` whose coefficients are free of `k` (polynomials in the other variables, square roots of
//! expressions free of `k`, or rational functions whose denominators are free of `k`). With
//! `E = sum_j c_j k^j`, the sum is `G(b) - G(a - 1)` for `G(x) = sum_j c_j F_j(x)` and the power
//! sums `F_j(x) = 1^j + 2^j + ... + x^j` (Faulhaber's polynomials, [`power_sums`]). Since
//! `F_j(x) - F_j(x - 1) = x^j` is an identity of polynomials, the sums telescope: the closed
//! form equals the sum for every integer `a <= b + 1` (`a = b + 1` is the empty sum, 0). An
//! identity with such a sum is decided as an identity of polynomials in the bound's variables,
//! which is then true at every integer value, and a counter-example is an integer value with
//! `a <= b + 1` (the front ends search those).
//!
//! A sum inside `E` whose bounds depend on `k` (`sum(k, 1, n, sum(j, 1, k, j))`) has its own
//! closed form, a polynomial in `k`; it stands for the sum only where its range is not reversed,
//! so it is taken only when its length `to - from + 1` is `alpha k + beta` with a constant
//! `alpha` and is at least 0 at the end of `a..b` where it is smallest (a constant there).
//!
//! Refused, with the reason: an exponent that depends on `k` (`x^k`: a geometric sum is not a
//! polynomial in `k`), `binomial` or `factorial` of an argument with `k`, a function of `k`
//! (`sqrt(k)`, `sin(k)`), a division by an expression in `k`, a bound with a fraction, a square
//! root or `pi`.

use super::calculus::{bad, checked_sum, horner, moving_with, rename, with_bound};
use super::eval::{check_constant, size_error};
use super::trig_integral::{binomials, TermList};
use super::*;
use crate::poly::{Poly, Var, Vars};
use crate::ratfun::RatFun;
use exactcheck_core::{Field, Sign};

/// Whether the free variables of `e` include `name`.
fn mentions(e: &Expr, name: &str) -> bool {
    let mut names = Vec::new();
    e.collect_variables(&mut names);
    names.iter().any(|n| n == name)
}

/// Whether `args` are those of a sum with a bound that has a variable (`sum(k, 1, n, E)`).
pub(super) fn is_symbolic(args: &[Expr]) -> bool {
    matches!(args, [_, a, b, _] if {
        let mut names = Vec::new();
        a.collect_variables(&mut names);
        b.collect_variables(&mut names);
        !names.is_empty()
    })
}

/// The bounds of the symbolic sums of `e` whose bounds involve only free variables (no index of
/// an enclosing sum): `(from, to)` pairs, each meaning `from <= to + 1`. Their variables take
/// integer values; a counter-example must satisfy every pair.
pub fn symbolic_sum_ranges(e: &Expr) -> Vec<(Expr, Expr)> {
    let mut out = Vec::new();
    collect_ranges(e, &mut Vec::new(), &mut out);
    out
}

fn collect_ranges(e: &Expr, bound: &mut Vec<String>, out: &mut Vec<(Expr, Expr)>) {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => {}
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => collect_ranges(x, bound, out),
        ExprKind::Pow(a, b) => {
            collect_ranges(a, bound, out);
            collect_ranges(b, bound, out);
        }
        ExprKind::Sum(ts) => ts.iter().for_each(|(_, t)| collect_ranges(t, bound, out)),
        ExprKind::Product(fs) => fs.iter().for_each(|(_, f)| collect_ranges(f, bound, out)),
        ExprKind::Call(name, args) => match (name.as_str(), args.as_slice()) {
            (
                "sum",
                [Expr {
                    kind: ExprKind::Var(k),
                    ..
                }, a, b, body],
            ) => {
                collect_ranges(a, bound, out);
                collect_ranges(b, bound, out);
                let free = !bound.iter().any(|v| mentions(a, v) || mentions(b, v));
                if is_symbolic(args) && free {
                    out.push((a.clone(), b.clone()));
                }
                bound.push(k.clone());
                collect_ranges(body, bound, out);
                bound.pop();
            }
            (
                "integrate",
                [body, Expr {
                    kind: ExprKind::Var(t),
                    ..
                }, a, b],
            ) => {
                collect_ranges(a, bound, out);
                collect_ranges(b, bound, out);
                bound.push(t.clone());
                collect_ranges(body, bound, out);
                bound.pop();
            }
            _ => args.iter().for_each(|a| collect_ranges(a, bound, out)),
        },
    }
}

/// The power sums `F_j(x) = 1^j + 2^j + ... + x^j` for `j = 0..=top`, each as its coefficients
/// by power of `x` (constant first), from `(x + 1)^{j+1} - 1 = sum_{i <= j} C(j+1, i) F_i(x)`
/// (the sum over `k = 1..x` of `(k + 1)^{j+1} - k^{j+1}`).
pub(super) fn power_sums(top: u32) -> Vec<Vec<Rational>> {
    let mut sums: Vec<Vec<Rational>> = Vec::new();
    for j in 0..=top {
        let row = binomials(j + 1);
        // (x + 1)^{j+1} - 1: the coefficient of x^i is C(j+1, i), i >= 1.
        let mut f: Vec<Rational> = row.iter().map(|c| Rational::from(c.clone())).collect();
        f[0] = Rational::zero();
        for (i, fi) in sums.iter().enumerate() {
            let c = Rational::from(row[i].clone());
            for (slot, a) in f.iter_mut().zip(fi) {
                *slot = &*slot - &(a * &c);
            }
        }
        let inv = Rational::from(BigInt::from(j + 1))
            .recip()
            .expect("j + 1 is not zero");
        sums.push(f.into_iter().map(|a| a * &inv).collect());
    }
    sums
}

/// Refuses a bound that does not take integer values: it must be a polynomial with integer
/// coefficients (no fraction, square root or `pi`).
fn check_bound(call: &Expr, bound: &Expr, which: &str) -> Result<(), ExprError> {
    let refuse = |why: &str| {
        bad(
            call,
            bound.pos,
            format!(
                "the {which} bound {bound} must take integer values: an integer or a polynomial \
                 with integer coefficients in other variables (n, n + 1, 2*n){why}"
            ),
        )
    };
    if mentions(bound, PI) {
        return Err(refuse(", not an expression in pi"));
    }
    let mut scratch = Vars::new();
    let p: Poly<Rational> = bound.to_poly(&mut scratch).map_err(|e| match e {
        ExprError::Limit { .. } => e,
        _ => refuse(""),
    })?;
    if p.coefficients().iter().all(Rational::is_integer) {
        Ok(())
    } else {
        Err(refuse(", which makes them integers"))
    }
}

/// The first node of `body` that is not a polynomial in `k` for a reason the tree shows (an
/// exponent with `k`, `binomial` or `factorial` of `k`), refused with that reason; a sum or
/// integral inside that binds `k` again is looked into only in its bounds.
fn refuse_non_polynomial(call: &Expr, body: &Expr, k: &str) -> Result<(), ExprError> {
    let go = |e: &Expr| refuse_non_polynomial(call, e, k);
    match &body.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => Ok(()),
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => go(x),
        ExprKind::Pow(b, x) => {
            if mentions(x, k) {
                return Err(bad(
                    call,
                    x.pos,
                    format!(
                        "the exponent of {body} depends on the summation index {k}: a sum with a \
                         bound that is not an integer constant is taken in closed form only for \
                         a polynomial in {k} (a geometric sum such as x^{k} is not one); give \
                         integer bounds to add its terms"
                    ),
                ));
            }
            go(b)
        }
        ExprKind::Sum(ts) => ts.iter().try_for_each(|(_, t)| go(t)),
        ExprKind::Product(fs) => fs.iter().try_for_each(|(_, f)| go(f)),
        ExprKind::Call(name, args) => {
            let rebinds = match (name.as_str(), args.as_slice()) {
                ("sum", [v, a, b, _]) | ("integrate", [_, v, a, b]) => {
                    matches!(&v.kind, ExprKind::Var(n) if n == k).then_some([a, b])
                }
                _ => None,
            };
            if let Some(bounds) = rebinds {
                return bounds.into_iter().try_for_each(go);
            }
            if matches!(name.as_str(), "binomial" | "factorial")
                && args.iter().any(|a| mentions(a, k))
            {
                return Err(bad(
                    call,
                    body.pos,
                    format!(
                        "{body} depends on the summation index {k}: with a bound that is not an \
                         integer constant, only polynomials in {k} are summed in closed form; \
                         write it as a polynomial (binomial({k}, 2) = {k}*({k} - 1)/2 for \
                         {k} >= 0) or give integer bounds"
                    ),
                ));
            }
            args.iter().try_for_each(go)
        }
    }
}

/// Refuses a sum inside `body` whose range depends on the index `k` of the sum `call` (running
/// over `from..to`) unless its length `L = to' - from' + 1` is `alpha k + beta` with a constant
/// `alpha` and `L >= 0` at the end of the range where `L` is smallest, a constant there (module
/// documentation): its closed form is then the sum for every `k` of the range.
fn check_inner_ranges(
    call: &Expr,
    body: &Expr,
    k: &str,
    from: &Expr,
    to: &Expr,
) -> Result<(), ExprError> {
    let mut inner = Vec::new();
    super::library::map_tree(body, &mut |x| {
        if let ExprKind::Call(name, args) = &x.kind {
            if name == "sum" && args.len() == 4 && (mentions(&args[1], k) || mentions(&args[2], k))
            {
                inner.push(x.clone());
            }
        }
    });
    for sum in inner {
        let ExprKind::Call(_, args) = &sum.kind else {
            continue;
        };
        let mut scratch = Vars::new();
        let kv = scratch.var(k);
        let mut poly = |e: &Expr| e.to_poly::<Rational>(&mut scratch).ok();
        let (Some(lo), Some(hi), Some(a), Some(b)) =
            (poly(&args[1]), poly(&args[2]), poly(from), poly(to))
        else {
            // The inner sum refuses its own bounds when it is converted.
            continue;
        };
        let length = hi - lo + Poly::constant(Rational::one());
        let alpha = length
            .terms()
            .filter(|(m, _)| m.exponent(kv) > 0)
            .map(|(m, c)| (m.exponents().len() == 1 && m.exponent(kv) == 1).then(|| c.clone()))
            .collect::<Option<Vec<Rational>>>();
        let smallest = alpha.map(|coefficients| {
            let alpha = coefficients
                .into_iter()
                .next()
                .unwrap_or_else(Rational::zero);
            let end = if alpha.signum() == Sign::Negative {
                &b
            } else {
                &a
            };
            length.substitute(kv, end).constant_value()
        });
        let fine = matches!(smallest, Some(Some(l)) if l.signum() != Sign::Negative);
        if !fine {
            return Err(bad(
                call,
                sum.pos,
                format!(
                    "the range of {sum} depends on the summation index {k}, and it is not shown \
                     to be non-empty (from <= to + 1) for every {k} from {from} to {to}; its \
                     closed form is the sum only there (a range whose length is a*{k} + b, \
                     a constant, and at least 0 at an end of {from}..{to} is shown)"
                ),
            ));
        }
    }
    Ok(())
}

/// The parts of `p` by power of `k` (free of `k`), and the checks of the module documentation
/// on the variables that change with `k`.
fn parts_in<C: Coefficient>(
    call: &Expr,
    body: &Expr,
    p: &Poly<C>,
    k: &str,
    vars: &Vars,
) -> Result<Vec<Poly<C>>, ExprError> {
    let kv = vars.get(k);
    if let Some(w) = moving_with(vars, k)
        .into_iter()
        .find(|&w| Some(w) != kv && p.degree_in(w) > 0)
    {
        return Err(bad(
            call,
            body.pos,
            format!(
                "the summand {body} holds {}, which changes with {k}: with a bound that is not \
                 an integer constant, only polynomials in {k} are summed in closed form",
                vars.name(w).unwrap_or(k)
            ),
        ));
    }
    let Some(kv) = kv else {
        return Ok(vec![p.clone()]);
    };
    let top = p.degree_in(kv);
    let mut terms: Vec<TermList<C>> = vec![Vec::new(); top as usize + 1];
    for (m, c) in p.terms() {
        let rest: Vec<(Var, u32)> = m
            .exponents()
            .into_iter()
            .filter(|&(w, _)| w != kv)
            .collect();
        terms[m.exponent(kv) as usize].push((rest, c.clone()));
    }
    Ok(terms.into_iter().map(Poly::from_terms).collect())
}

/// `G(x) = sum_j parts[j] F_j(x)` by power of `x` ([`power_sums`]).
fn antidifference<C: Coefficient>(
    call: &Expr,
    parts: &[Poly<C>],
) -> Result<Vec<Poly<C>>, ExprError> {
    let top = parts.len() as u64;
    limits::DEGREE
        .check(top)
        .map_err(|error| ExprError::Limit {
            pos: call.pos,
            error,
        })?;
    let sums = power_sums(top.saturating_sub(1) as u32);
    let mut out = vec![Poly::zero(); parts.len() + 1];
    for (c, f) in parts.iter().zip(&sums) {
        if c.is_zero() {
            continue;
        }
        for (slot, r) in out.iter_mut().zip(f) {
            if r.is_zero() {
                continue;
            }
            let r = C::from_rational(r).ok_or_else(|| ExprError::Unrepresentable {
                pos: call.pos,
                number: r.to_string(),
            })?;
            let term = c.scale(&r);
            term.coefficients()
                .iter()
                .try_for_each(|x| check_constant(x, call.pos))?;
            *slot = slot.add_ref(&term);
        }
    }
    Ok(out)
}

/// `G(hi) - G(lo - 1)` for the parts of `G` by power of `x`, by Horner's rule.
fn telescope<C: Coefficient>(
    call: &Expr,
    g: &[Poly<C>],
    lo: &Poly<C>,
    hi: &Poly<C>,
) -> Result<Poly<C>, ExprError> {
    let size = |err| size_error(err, call.pos);
    let at = |x: &Poly<C>| {
        horner(g, Poly::zero(), |acc: Poly<C>, part| {
            let q = acc.try_mul(x).map_err(size)? + part.clone();
            q.coefficients()
                .iter()
                .try_for_each(|c| check_constant(c, call.pos))?;
            Ok(q)
        })
    };
    let below = lo.clone() - Poly::constant(C::one());
    checked_sum(at(hi)? - at(&below)?, call.pos)
}

/// The index, the bounds and the summand of a symbolic sum, checked (module documentation).
fn arguments<'a>(
    call: &Expr,
    args: &'a [Expr],
) -> Result<(&'a str, &'a Expr, &'a Expr, &'a Expr), ExprError> {
    let [index, a, b, body] = args else {
        unreachable!("is_symbolic holds only for four arguments")
    };
    let ExprKind::Var(k) = &index.kind else {
        return Err(bad(
            call,
            index.pos,
            format!("the first argument must be a variable name, not {index}"),
        ));
    };
    check_bound(call, a, "lower")?;
    check_bound(call, b, "upper")?;
    refuse_non_polynomial(call, body, k)?;
    check_inner_ranges(call, body, k, a, b)?;
    Ok((k, a, b, body))
}

/// `sum(k, a, b, E)` with a symbolic bound as a polynomial (module documentation).
pub(super) fn sum_poly<C: Coefficient>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<Poly<C>, ExprError> {
    let (k, a, b, body) = arguments(call, args)?;
    let lo = a.to_poly::<C>(vars)?;
    let hi = b.to_poly::<C>(vars)?;
    let g = with_bound::<C, _>(
        vars,
        k,
        |vars| {
            let p = body.to_poly::<C>(vars)?;
            antidifference(call, &parts_in(call, body, &p, k, vars)?)
        },
        |g, map| g.iter().map(|p| rename(p, map)).collect(),
        call.pos,
    )?;
    telescope(call, &g, &lo, &hi)
}

/// `sum(k, a, b, E)` with a symbolic bound as a rational function: `E`'s denominator must be
/// free of `k` (module documentation).
pub(super) fn sum_ratfun<C: Coefficient + Field>(
    call: &Expr,
    args: &[Expr],
    vars: &mut Vars,
) -> Result<RatFun<C>, ExprError> {
    let (k, a, b, body) = arguments(call, args)?;
    let lo = a.to_poly::<C>(vars)?;
    let hi = b.to_poly::<C>(vars)?;
    let (g, divisor) = with_bound::<C, _>(
        vars,
        k,
        |vars| {
            let f = body.to_ratfun::<C>(vars)?;
            let divides = |p: &Poly<C>| vars.get(k).is_some_and(|kv| p.degree_in(kv) > 0);
            if divides(f.denominator()) || f.conditions().iter().any(divides) {
                return Err(bad(
                    call,
                    body.pos,
                    format!(
                        "the summand {body} divides by an expression in {k}: with a bound that \
                         is not an integer constant, only polynomials in {k} are summed in \
                         closed form"
                    ),
                ));
            }
            for p in [f.denominator()].into_iter().chain(f.conditions()) {
                parts_in(call, body, p, k, vars)?;
            }
            let g = antidifference(call, &parts_in(call, body, f.numerator(), k, vars)?)?;
            Ok((g, f.denominator_reciprocal()))
        },
        |(g, d), map| {
            (
                g.iter().map(|p| rename(p, map)).collect(),
                d.map_polys(|p| rename(p, map)),
            )
        },
        call.pos,
    )?;
    let size = |err| size_error(err, call.pos);
    RatFun::from_poly(telescope(call, &g, &lo, &hi)?)
        .mul(&divisor)
        .map_err(size)
}
