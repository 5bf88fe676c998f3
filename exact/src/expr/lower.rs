//! Lowering: the functions of the core language rewritten as plain arithmetic trees, for the
//! front ends that evaluate a tree operation by operation (`regress --formula` in f64 and
//! exactly, `prove --random` modulo a prime).
//!
//! [`lower`] takes a tree resolved by the [`library`](super::library) (vectors, matrices,
//! `det`, `dot`, `cross`, `norm2`, `bezier`, definitions and user functions are already
//! arithmetic there) and replaces every remaining call of the core language:
//! * `binomial(n, k)` and `factorial(n)` by their exact integer value;
//! * `sum(k, a, b, E)` by the unrolled sum `E(a) + E(a+1) + ... + E(b)`, each term lowered in
//!   turn (nested sums share the one `sum-terms` budget, as in the exact conversions);
//! * `diff(E, t[, k])` by the derivative expanded as a rational function in lowest terms
//!   (numerator, or numerator `/` denominator), computed exactly by [`Expr::to_ratfun`];
//! * `integrate(E, t, a, b)` by its exact value expanded the same way; with a bound that holds a
//!   square root, by `G(b) - G(a)` where `G(u) = integrate(E, t, 0, u)` is expanded and the
//!   lowered bounds are substituted for `u`.
//!
//! Everything else is kept as written (`+ - * /`, powers, `sqrt`, the trigonometric calls with
//! their arguments lowered), so a division the user wrote stays a division. The derivative and
//! the integral have no written operation order to keep: the lowered tree is the expanded
//! result, and a caller evaluating in floating point evaluates that tree (its documentation says
//! so). `diff` and `integrate` of an expression with a square root or a trigonometric function
//! are refused with a one-line error: the expansion here is over polynomials in the variables.
//!
//! The size of the lowered tree is held to [`library::MAX_NODES`](super::library::MAX_NODES)
//! nodes, as the library holds its resolved trees. Hand-written: the rewriting is a recursion
//! over the grammar of this module's parent, which no crate knows.

use super::calculus::sum_terms;
use super::fraction::diff_arguments;
use super::library::{count_nodes, has_sqrt, substitute, MAX_NODES};
use super::map::at_pos;
use super::trig::has_trig;
use super::*;
use crate::poly::Vars;
use crate::ratfun::RatFun;

/// `e` with every call of `diff`, `integrate`, `sum`, `binomial` and `factorial` replaced by
/// plain arithmetic (module documentation). A tree without such calls comes back unchanged.
///
/// ```
/// use exactcheck_exact::expr::{lower, parse_expr};
/// use exactcheck_exact::{poly::Vars, Rational};
///
/// let e = parse_expr("diff(t^3, t) + sum(k, 1, 3, k) + binomial(5, 2)").unwrap();
/// let lowered = lower(&e).unwrap();
/// assert!(!lowered.to_string().contains("diff") && !lowered.to_string().contains("sum"));
/// let mut vars = Vars::new();
/// let value = lowered.to_poly::<Rational>(&mut vars).unwrap();
/// let expected = parse_expr("3 t^2 + 16").unwrap().to_poly::<Rational>(&mut vars).unwrap();
/// assert_eq!(value, expected);
/// ```
///
/// # Errors
/// The errors of the calls' arguments (wrong arity, a bound that is not an integer constant, a
/// `diff` by a non-variable, ...), of the exact expansion (limits, a division by zero), a `diff`
/// or `integrate` of an expression with `sqrt` or a trigonometric function, and a lowered tree
/// beyond [`MAX_NODES`] nodes.
pub fn lower(e: &Expr) -> Result<Expr, ExprError> {
    let out = lower_node(e)?;
    let nodes = count_nodes(&out);
    if nodes > MAX_NODES {
        return Err(ExprError::BadCall {
            pos: e.pos,
            name: "the formula".into(),
            why: format!(
                "its functions expand to {nodes} operations, more than {MAX_NODES}; lower the \
                 bounds of its sums or the orders of its derivatives"
            ),
        });
    }
    Ok(out)
}

/// The exact value of a constant formula, also when a `diff`, `integrate` or `sum` inside binds
/// a variable of its own (`integrate(t^2, t, 0, 1)`, `diff(t^3, t)` at a point after a
/// substitution): evaluated as written when that succeeds, else lowered first ([`lower`]) and
/// then evaluated. The front ends that read a constant (the number strings of `solve`, the
/// instances of a claims file) evaluate through here.
///
/// ```
/// use exactcheck_exact::expr::{eval_lowered, parse_expr};
/// use exactcheck_exact::Rational;
///
/// let e = parse_expr("integrate(t^2, t, 0, 1) + sum(k, 1, 3, k)").unwrap();
/// assert_eq!(eval_lowered::<Rational>(&e).unwrap(), Rational::new(19, 3).unwrap());
/// ```
///
/// # Errors
/// The error of the lowered tree's evaluation (a free variable, a division by zero, ...), or of
/// the evaluation as written when the lowering itself fails.
pub fn eval_lowered<C: Coefficient>(e: &Expr) -> Result<C, ExprError> {
    let direct = match e.eval_constant::<C>() {
        Ok(v) => return Ok(v),
        Err(err) => err,
    };
    match lower(e) {
        Ok(lowered) => lowered.eval_constant::<C>(),
        Err(_) => Err(direct),
    }
}

fn lower_node(e: &Expr) -> Result<Expr, ExprError> {
    let ExprKind::Call(name, args) = &e.kind else {
        return e.try_map_children(lower_node);
    };
    match name.as_str() {
        "binomial" | "factorial" => {
            let q: Rational = e.eval_constant()?;
            Ok(at_pos(&Expr::number(q), e.pos))
        }
        "sum" => {
            let terms = sum_terms(e, args, lower_node)?;
            if terms.is_empty() {
                return Ok(at_pos(&Expr::number(Rational::ZERO), e.pos));
            }
            Ok(Expr {
                kind: ExprKind::Sum(terms.into_iter().map(|t| (AddOp::Plus, t)).collect()),
                pos: e.pos,
            })
        }
        "diff" => {
            let (body, _, _) = diff_arguments(e, args)?;
            refuse_roots_and_angles(e, body)?;
            expand(e)
        }
        "integrate" => lower_integral(e, args),
        _ => e.try_map_children(lower_node),
    }
}

/// The refusal of a `diff` or `integrate` (the call `call`) whose expression `body` has a
/// square root or an angle: [`expand`] works over polynomials in the variables.
fn refuse_roots_and_angles(call: &Expr, body: &Expr) -> Result<(), ExprError> {
    let ExprKind::Call(name, _) = &call.kind else {
        unreachable!("a call")
    };
    let what = if has_sqrt(body) {
        "sqrt"
    } else if has_trig(body) {
        "sin, cos or tan"
    } else {
        return Ok(());
    };
    Err(ExprError::BadCall {
        pos: body.pos,
        name: name.clone(),
        why: format!(
            "{body} contains {what}; a formula evaluated operation by operation expands {name} \
             exactly as a rational function, which it cannot do with {what}"
        ),
    })
}

/// The exact value of `e` as an expanded rational function: the numerator, or numerator `/`
/// denominator, every node at the position of `e`.
fn expand(e: &Expr) -> Result<Expr, ExprError> {
    let mut vars = Vars::new();
    let f: RatFun<Rational> = e.to_ratfun(&mut vars)?;
    let num = f.numerator().to_expr(&vars);
    let out = if f.denominator().is_one() {
        num
    } else {
        Expr::new(ExprKind::Product(vec![
            (MulOp::Times, num),
            (MulOp::Divide, f.denominator().to_expr(&vars)),
        ]))
    };
    Ok(at_pos(&out, e.pos))
}

/// `integrate(E, t, a, b)` lowered (module documentation).
fn lower_integral(call: &Expr, args: &[Expr]) -> Result<Expr, ExprError> {
    let [body, _, lo, hi] = args else {
        // The conversion names the arity.
        return expand(call);
    };
    refuse_roots_and_angles(call, body)?;
    let bounds_plain = [lo, hi].iter().all(|b| !has_sqrt(b) && !has_trig(b));
    if bounds_plain {
        return expand(call);
    }
    // G(u) = integrate(E, t, 0, u) for a name u free in the call, then G(b) - G(a).
    let mut names = Vec::new();
    call.collect_variables(&mut names);
    for a in args {
        a.collect_variables(&mut names);
    }
    let u = (0u32..)
        .map(|k| format!("_u{k}"))
        .find(|n| !names.contains(n))
        .expect("finitely many names are taken");
    let mut g_args = args.to_vec();
    g_args[2] = Expr::number(Rational::ZERO);
    g_args[3] = Expr::var(&u);
    let g = expand(&Expr {
        kind: ExprKind::Call("integrate".into(), g_args),
        pos: call.pos,
    })?;
    let (lo, hi) = (lower_node(lo)?, lower_node(hi)?);
    Ok(Expr {
        kind: ExprKind::Sum(vec![
            (AddOp::Plus, substitute(&g, &u, &hi)),
            (AddOp::Minus, substitute(&g, &u, &lo)),
        ]),
        pos: call.pos,
    })
}
