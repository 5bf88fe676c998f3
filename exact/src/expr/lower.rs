//! Lowering: the functions of the core language rewritten as plain arithmetic trees, for the
//! front ends that evaluate a tree operation by operation (`regress --formula` in f64 and
//! exactly, `prove --random` modulo a prime).
//!
//! [`lower`] takes a tree resolved by the [`library`](super::library) (vectors, matrices,
//! `det`, `dot`, `cross`, `norm2`, `bezier`, definitions and user functions are already
//! arithmetic there) and replaces every remaining call of the core language:
//! * `binomial(n, k)` and `factorial(n)` by their exact integer value;
//! * `sum(k, a, b, E)` by the unrolled sum `E(a) + E(a+1) + ... + E(b)`, each term lowered in
//!   turn (nested sums share the one `sum-terms` budget, as in the exact conversions); with a
//!   bound that has a variable (`sum(k, 1, n, k^2)`), by its closed form expanded as `diff`
//!   below (a polynomial in the bound's variables);
//! * `diff(E, t[, k])` by the derivative expanded as a rational function in lowest terms
//!   (numerator, or numerator `/` denominator), computed exactly by [`Expr::to_ratfun`]. When
//!   `E` has square roots or `sin`, `cos`, `tan`, the expansion is over the square-root field,
//!   with each square root of an expression `sqrt(R)` and the cosine and sine of each angle
//!   variable `x` as variables (the chain rule of the conversion differentiates them:
//!   `d sqrt(R) = R'/(2 sqrt(R))`, `d sin(x) = cos(x)`, `tan = sin/cos`); those variables are
//!   then written back as the calls `sqrt(R)` (`R` lowered in turn), `cos(x)` and `sin(x)`, so
//!   `diff(sqrt(1 + t^2), t)` lowers to `t/sqrt(1 + t^2)`;
//! * `integrate(E, t, a, b)` by its exact value expanded the same way (a trigonometric
//!   polynomial integrates to a polynomial in the bounds' cosines and sines); with a bound that
//!   holds a square root or a trigonometric call, or that is not an angle (`x^2`), by
//!   `G(b) - G(a)` where `G(u) = integrate(E, t, 0, u)` is expanded and the lowered bounds are
//!   substituted for `u` (so `cos(u)` becomes `cos(x^2)`).
//!
//! Everything else is kept as written (`+ - * /`, powers, `sqrt`, the trigonometric calls with
//! their arguments lowered), so a division the user wrote stays a division. The derivative and
//! the integral have no written operation order to keep: the lowered tree is the expanded
//! result, and a caller evaluating in floating point evaluates that tree (its documentation says
//! so). What the exact conversion refuses is refused here with its one-line error (an integrand
//! with a square root that changes with the variable, `tan` in an integrand, an angle that is
//! not linear in its variables inside `diff`).
//!
//! The size of the lowered tree is held to [`library::MAX_NODES`](super::library::MAX_NODES)
//! nodes, as the library holds its resolved trees. Hand-written: the rewriting is a recursion
//! over the grammar of this module's parent, which no crate knows.

use super::calculus::sum_terms;
use super::from_poly::ratfun_to_expr;
use super::library::{count_nodes, has_sqrt, substitute, MAX_NODES};
use super::map::at_pos;
use super::symbolic_sum::is_symbolic;
use super::trig::has_trig;
use super::*;
use crate::poly::Vars;
use crate::ratfun::RatFun;
use crate::Radical;

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
/// `diff` by a non-variable, ...), of the exact expansion (limits, a division by zero, an
/// integrand it does not integrate), and a lowered tree beyond [`MAX_NODES`] nodes.
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
        // A bound with a variable: the closed form, expanded like a derivative.
        "sum" if is_symbolic(args) => expand(e),
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
        "diff" => expand(e),
        "integrate" => lower_integral(e, args),
        _ => e.try_map_children(lower_node),
    }
}

/// The exact value of `e` as an expanded rational function, every node at the position of `e`
/// (module documentation): over the rationals when the tree has no `sqrt` and no trigonometric
/// call, else over the square-root field with its roots and angles written back as calls.
fn expand(e: &Expr) -> Result<Expr, ExprError> {
    let mut vars = Vars::new();
    let out = if has_sqrt(e) || has_trig(e) {
        vars.allow_roots();
        let f: RatFun<Radical> = e.to_ratfun(&mut vars)?;
        // A radicand written back may itself hold calls to lower.
        lower_node(&ratfun_to_expr(&f, &vars))?
    } else {
        let f: RatFun<Rational> = e.to_ratfun(&mut vars)?;
        ratfun_to_expr(&f, &vars)
    };
    Ok(at_pos(&out, e.pos))
}

/// `integrate(E, t, a, b)` lowered (module documentation).
pub(super) fn lower_integral(call: &Expr, args: &[Expr]) -> Result<Expr, ExprError> {
    let [body, _, lo, hi] = args else {
        // The conversion names the arity.
        return expand(call);
    };
    let bounds_plain = [lo, hi].iter().all(|b| !has_sqrt(b) && !has_trig(b));
    if bounds_plain {
        match expand(call) {
            // A trigonometric integrand at a bound that is not an angle: through `G` below.
            Err(direct) if has_trig(body) => {
                return integral_at_bounds(call, args, lo, hi).map_err(|_| direct)
            }
            direct => return direct,
        }
    }
    integral_at_bounds(call, args, lo, hi)
}

/// `G(hi) - G(lo)` for `G(u) = integrate(E, t, 0, u)` expanded, `u` a fresh name (module
/// documentation).
fn integral_at_bounds(call: &Expr, args: &[Expr], lo: &Expr, hi: &Expr) -> Result<Expr, ExprError> {
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

#[cfg(test)]
mod tests {
    use super::super::trig::{angles, Angle};
    use super::*;
    use crate::expr::parse_expr;
    use crate::poly::Poly;
    use crate::prove::{decide, Decision};

    fn lowered(text: &str) -> Expr {
        lower(&parse_expr(text).unwrap()).unwrap()
    }

    /// Whether the lowered tree `e` equals `expected` as a function: both converted in one table
    /// (a root is one variable in both), decided modulo the unit circles of the angles and the
    /// squares of the roots (`y^2 = R`).
    fn agrees(e: &Expr, expected: &str) -> bool {
        let mut vars = Vars::new();
        vars.allow_roots();
        let l: RatFun<Radical> = e.to_ratfun(&mut vars).unwrap();
        let r: RatFun<Radical> = parse_expr(expected).unwrap().to_ratfun(&mut vars).unwrap();
        let difference = l.add(&r, true).unwrap();
        let mut rels: Vec<Poly<Radical>> = angles(&vars).iter().map(Angle::relation).collect();
        let mut scratch = vars.clone();
        for root in vars.roots() {
            let radicand: Poly<Radical> = root.radicand_expr().to_poly(&mut scratch).unwrap();
            let y = Poly::<Radical>::var(root.var);
            rels.push(y.try_mul(&y).unwrap().sub_ref(&radicand));
        }
        matches!(
            decide(difference.numerator(), &rels, vars.len()).unwrap(),
            Decision::Proved { .. }
        )
    }

    fn has_calculus(e: &Expr) -> bool {
        let text = e.to_string();
        text.contains("diff") || text.contains("integrate")
    }

    /// Every case `(text, expected)` lowers to a tree without `diff` or `integrate`, in which
    /// `calls` finds its calls, that equals `expected` and not `expected + shift`.
    fn lowers_to(cases: &[(&str, &str)], calls: fn(&Expr) -> bool, shift: &str) {
        for (text, expected) in cases {
            let e = lowered(text);
            assert!(!has_calculus(&e) && calls(&e), "{text}: {e}");
            assert!(agrees(&e, expected), "{text}: {e} against {expected}");
            assert!(!agrees(&e, &format!("{expected} + {shift}")), "{text}");
        }
    }

    #[test]
    fn derivatives_of_roots_become_calls_of_sqrt() {
        let e = lowered("diff(sqrt(1 + t^2), t)");
        assert_eq!(e.to_string(), "t/sqrt(1 + t^2)");
        let cases = [
            ("diff(sqrt(x), x)", "1/(2*sqrt(x))"),
            ("diff(sqrt(x), x, 2)", "-1/(4*x*sqrt(x))"),
            ("diff(sqrt(2)*t^2, t)", "2*sqrt(2)*t"),
            (
                "diff(x*sqrt(x^2 + y), x)",
                "sqrt(x^2 + y) + x^2/sqrt(x^2 + y)",
            ),
            (
                "diff(sqrt(1 + sqrt(x)), x)",
                "1/(4*sqrt(x)*sqrt(1 + sqrt(x)))",
            ),
            // A radicand with a call of the language is lowered as well.
            ("diff(sqrt(sum(k, 1, 2, k*t)), t)", "3/(2*sqrt(3*t))"),
        ];
        lowers_to(&cases, has_sqrt, "1");
    }

    #[test]
    fn derivatives_of_angles_become_calls_of_sin_and_cos() {
        let cases = [
            ("diff(sin(x)^2, x)", "sin(2*x)"),
            ("diff(cos(3*x), x)", "-3*sin(3*x)"),
            ("diff(tan(x), x)", "1 + tan(x)^2"),
            ("diff(sin(x + pi/4), x)", "cos(x + pi/4)"),
            (
                "diff(sqrt(1 + sin(x)^2), x)",
                "sin(x)*cos(x)/sqrt(1 + sin(x)^2)",
            ),
        ];
        lowers_to(&cases, has_trig, "x");
    }

    #[test]
    fn integrals_of_trigonometric_polynomials_at_the_bounds() {
        let e = lowered("integrate(t*sin(t), t, 0, x)");
        assert!(!has_calculus(&e) && has_trig(&e), "{e}");
        assert!(agrees(&e, "sin(x) - x*cos(x)"), "{e}");
        assert!(!agrees(&e, "sin(x) + x*cos(x)"), "{e}");
        let cases = [
            ("integrate(t*sin(t), t, 0, pi)", "pi"),
            ("integrate(sin(t)^3, t, 0, x)", "2/3 - cos(x) + cos(x)^3/3"),
            ("integrate(y*cos(t), t, a, 2*b)", "y*(sin(2*b) - sin(a))"),
        ];
        lowers_to(&cases, |_| true, "1");
        // A bound that is not an angle: the antiderivative's calls take the bound as written.
        let e = lowered("integrate(cos(t), t, 0, x^2)");
        assert_eq!(e.to_string(), "sin(x^2) - sin(0)");
        let e = lowered("integrate(cos(t), t, 0, sqrt(x))");
        assert_eq!(e.to_string(), "sin(sqrt(x)) - sin(0)");
    }

    #[test]
    fn what_the_exact_conversion_refuses_is_refused_in_one_line() {
        for (text, says) in [
            ("integrate(sqrt(t), t, 0, x)", "which changes with t"),
            (
                "integrate(tan(t), t, 0, x)",
                "divides by an expression in t",
            ),
            ("diff(sin(x^2), x)", "not linear"),
        ] {
            let err = lower(&parse_expr(text).unwrap()).unwrap_err().to_string();
            assert!(err.contains(says), "{text}: {err}");
            assert!(!err.contains('\n'), "{text}: {err}");
        }
    }
}
