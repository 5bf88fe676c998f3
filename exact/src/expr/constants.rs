//! Algebraic constants next to variables: the rewriting that lets an identity with variables
//! use any real algebraic constant (`x + cos(pi/5)`, `sin(x + pi/7)`, `sqrt(2 + sqrt(2)) x`),
//! whose value need not lie in a coefficient field of the conversion.
//!
//! * An angle with variables and a part `r pi` is split by the addition formulas,
//!   `sin(A + r pi) = sin(A) cos(r pi) + cos(A) sin(r pi)` (`cos` and `tan` alike), so that every
//!   constant is a *leaf*: `sqrt` or `abs` of a constant, or `sin`, `cos`, `tan` of a constant
//!   angle.
//! * [`abstract_constants`] evaluates each leaf exactly as an [`Algebraic`] number: a rational
//!   value becomes a number, an irrational one is recorded ([`ConstantLeaf`], equal values once)
//!   and replaced by a placeholder variable that no identifier can name.
//! * A definite integral of a trigonometric integrand with a bound that holds pi
//!   (`integrate(t cos(t), t, 0, pi/7)`, `integrate(cos(t), t, 0, x + pi/5)`) is replaced by its
//!   value `G(b) - G(a)` first, whose `cos(pi/7)` or `sin(x + pi/5)` are then leaves or split
//!   angles like those written by hand.
//! * [`fill_constants`] replaces the placeholders by expressions (the caller's polynomials in a
//!   primitive element of the field of the leaves, see [`crate::algebraic::primitive_element`]).
//!
//! [`needs_algebraic`] tells whether a tree has a leaf that a coefficient type cannot hold, so
//! that callers take this path only when the fast one refuses.

use super::map::at_pos;
use super::trig::{linear_angle, Trig};
use super::*;
use crate::univariate::UPoly;
use crate::Algebraic;

/// An irrational constant of an expression: its text and its exact value.
#[derive(Clone, Debug)]
pub struct ConstantLeaf {
    /// The leaf as written (`cos(pi/5)`, `sqrt(2 + sqrt(2))`).
    pub text: String,
    /// Its value.
    pub value: Algebraic,
}

/// The placeholder variable of leaf `i` (no identifier starts with `#`).
fn placeholder(i: usize) -> String {
    format!("#{i}")
}

/// Whether the tree has no variable but pi (a candidate constant).
fn only_pi(e: &Expr) -> bool {
    let mut names = Vec::new();
    e.collect_variables(&mut names);
    names.iter().all(|n| n == PI)
}

/// Whether `e` is a leaf candidate: `sqrt` or `abs` of a constant, a constant to a power that
/// is not an integer (`2^(1/3)`), or a trigonometric function of a constant angle that is a
/// multiple of pi (`sin(1)` has no algebraic value: it stays, the cosine and sine of the
/// constant base angle).
fn is_leaf(e: &Expr) -> bool {
    let shape = match &e.kind {
        ExprKind::Sqrt(_) => true,
        ExprKind::Pow(_, exp) => super::eval::fractional_exponent(exp).is_ok_and(|k| k.is_some()),
        ExprKind::Call(name, _) if name == ABS => true,
        ExprKind::Call(name, _) => {
            Trig::from_name(name).is_some() && !super::trig::is_transcendental_constant(e)
        }
        _ => false,
    };
    shape && only_pi(e)
}

/// An angle that is not yet an integer combination of variables, as `k*x + pi/5` in a sum over
/// `k` before the sum is unrolled: its terms with variables and its constant terms with pi, as
/// texts; `None` unless it is a sum with both.
fn split_terms(args: &[Expr]) -> Option<(String, String)> {
    let [arg] = args else { return None };
    let ExprKind::Sum(terms) = &arg.kind else {
        return None;
    };
    let (constant, varying): (Vec<_>, Vec<_>) =
        terms.iter().cloned().partition(|(_, t)| only_pi(t));
    let sum = |terms: Vec<(AddOp, Expr)>| Expr::new(ExprKind::Sum(terms)).to_string();
    let mut names = Vec::new();
    constant
        .iter()
        .for_each(|(_, t)| t.collect_variables(&mut names));
    if varying.is_empty() || names.is_empty() {
        return None;
    }
    Some((sum(varying), sum(constant)))
}

/// The trigonometric call `e` (`which` of `args`) with an angle `A + r pi`, `A` with variables
/// or a rational number and `r != 0`, split by the addition formulas; `None` when the angle has
/// no such two parts (or is malformed: the conversion reports that).
fn split_angle(e: &Expr, which: Trig, args: &[Expr]) -> Option<Expr> {
    let (a, r) = match linear_angle(e, which.name(), args) {
        Ok(angle) if (angle.terms.is_empty() && angle.constant.is_zero()) || angle.pi.is_zero() => {
            return None
        }
        Ok(angle) => (linear_text(&angle), super::trig::angle_text(&angle.pi)),
        Err(_) => split_terms(args)?,
    };
    let (sa, ca) = (format!("sin({a})"), format!("cos({a})"));
    let (sr, cr) = (format!("sin({r})"), format!("cos({r})"));
    let sin = format!("{sa}*{cr} + {ca}*{sr}");
    let cos = format!("{ca}*{cr} - {sa}*{sr}");
    let text = match which {
        Trig::Sin => sin,
        Trig::Cos => cos,
        Trig::Tan => format!("({sin})/({cos})"),
    };
    let parsed = parse_expr(&text).ok()?;
    Some(at_pos(&parsed, e.pos))
}

/// The part of an angle without pi as text: its rational combination of variables and its
/// rational constant (`(1/2)*x - y + (1)`).
fn linear_text(angle: &super::trig::LinearAngle) -> String {
    let mut a = String::new();
    let parts = angle
        .terms
        .iter()
        .map(|(x, k)| (Some(x.as_str()), k))
        .chain((!angle.constant.is_zero()).then_some((None, &angle.constant)));
    for (i, (x, k)) in parts.enumerate() {
        let negative = k.signum() == exactcheck_core::Sign::Negative;
        let sign = match (i, negative) {
            (0, false) => "",
            (0, true) => "-",
            (_, false) => " + ",
            (_, true) => " - ",
        };
        let k = if negative { k.neg_ref() } else { k.clone() };
        let term = match x {
            Some(x) if k.is_one() => x.to_string(),
            Some(x) => format!("({k})*{x}"),
            None => format!("({k})"),
        };
        a += &format!("{sign}{term}");
    }
    a
}

/// `integrate(E, t, a, b)` of a trigonometric integrand with a bound that holds pi
/// (`pi/7`, `x + pi/5`) as its value `G(b) - G(a)`, the antiderivative's `cos` and `sin` taking
/// the bounds as written ([`super::lower::lower_integral`]), so that their constants become
/// leaves and their angles are split like any other (`sin(x + pi/5)`); `None` for any other
/// call, and when the lowering refuses the integral (the conversion then says why).
fn integral_at_constant_angle(e: &Expr, name: &str, args: &[Expr]) -> Option<Expr> {
    let [body, _, lo, hi] = args else {
        return None;
    };
    let with_pi = |b: &Expr| {
        let mut names = Vec::new();
        b.collect_variables(&mut names);
        names.iter().any(|n| n == PI)
    };
    if name != "integrate" || !super::trig::has_trig(body) || !(with_pi(lo) || with_pi(hi)) {
        return None;
    }
    super::lower::lower_integral(e, args).ok()
}

/// Rebuilds `e` top-down: `leaf` may replace a leaf candidate (`Some`), angles with variables
/// and a multiple of pi are split first.
fn walk(
    e: &Expr,
    leaf: &mut dyn FnMut(&Expr) -> Result<Option<Expr>, ExprError>,
) -> Result<Expr, ExprError> {
    if is_leaf(e) {
        if let Some(r) = leaf(e)? {
            return Ok(r);
        }
    }
    if let ExprKind::Call(name, args) = &e.kind {
        if let Some(value) = integral_at_constant_angle(e, name, args) {
            return walk(&value, leaf);
        }
        if let Some(which) = Trig::from_name(name) {
            if let Some(split) = split_angle(e, which, args) {
                return walk(&split, leaf);
            }
            // An angle is a rational combination of variables plus a number, without pi:
            // nothing in it to rewrite.
            return Ok(e.clone());
        }
    }
    e.try_map_children(|x| walk(x, leaf))
}

/// `e` with its angles split and every constant leaf evaluated exactly: a rational one becomes a
/// number, an irrational one the placeholder of its entry in `leaves` (appended when its value
/// is new). See the module documentation of `exact/src/expr/constants.rs`.
///
/// # Errors
/// The evaluator's errors of a leaf (a negative radicand, `tan(pi/2)`, the `algebraic-degree`
/// limit); a leaf with pi outside an angle (`sqrt(pi)`) is left as it is.
pub fn abstract_constants(e: &Expr, leaves: &mut Vec<ConstantLeaf>) -> Result<Expr, ExprError> {
    walk(e, &mut |x: &Expr| {
        let value = match x.eval_constant::<Algebraic>() {
            Ok(v) => v,
            Err(ExprError::NotConstant { .. }) => return Ok(None),
            Err(err) => return Err(err),
        };
        if let Some(q) = value.to_rational() {
            return Ok(Some(at_pos(&Expr::number(q.clone()), x.pos)));
        }
        let i = match leaves.iter().position(|l| l.value == value) {
            Some(i) => i,
            None => {
                leaves.push(ConstantLeaf {
                    text: x.to_string(),
                    value,
                });
                leaves.len() - 1
            }
        };
        Ok(Some(Expr {
            kind: ExprKind::Var(placeholder(i)),
            pos: x.pos,
        }))
    })
}

/// `e` with the placeholder of leaf `i` replaced by `values[i]`.
pub fn fill_constants(e: &Expr, values: &[Expr]) -> Expr {
    if let ExprKind::Var(n) = &e.kind {
        return match n.strip_prefix('#').and_then(|i| i.parse::<usize>().ok()) {
            Some(i) if i < values.len() => at_pos(&values[i], e.pos),
            _ => e.clone(),
        };
    }
    e.map_children(|x| fill_constants(x, values))
}

/// The polynomial `p` in the variable `name` as an expression (`2*c^2 - 1/3*c + 5`).
pub fn upoly_expr(p: &UPoly, name: &str) -> Expr {
    let mut terms = Vec::new();
    for (k, c) in p.coeffs().iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let op = if c.signum() == exactcheck_core::Sign::Negative {
            AddOp::Minus
        } else {
            AddOp::Plus
        };
        let mut factors = vec![(
            MulOp::Times,
            Expr::new(ExprKind::Number(if op == AddOp::Minus {
                c.neg_ref()
            } else {
                c.clone()
            })),
        )];
        if k > 0 {
            let var = Expr::var(name);
            factors.push((
                MulOp::Times,
                if k == 1 {
                    var
                } else {
                    Expr::new(ExprKind::Pow(
                        Box::new(var),
                        Box::new(Expr::new(ExprKind::Number(Rational::from_integer(
                            k as i64,
                        )))),
                    ))
                },
            ));
        }
        terms.push((op, Expr::new(ExprKind::Product(factors))));
    }
    if terms.is_empty() {
        return Expr::number(Rational::ZERO);
    }
    Expr::new(ExprKind::Sum(terms))
}

/// Whether `e` has a constant that `C` cannot hold but a real algebraic number can: a leaf
/// (`cos(pi/5)`, `sqrt(2 + sqrt(2))`) or the multiple of pi of an angle with variables
/// (`sin(x + pi/5)`) that `C` refuses and [`Algebraic`] evaluates, or (an angle's cosine, sine or tangent) refuses only by a limit.
pub fn needs_algebraic<C: Coefficient>(e: &Expr) -> bool {
    let mut found = false;
    let _ = walk(e, &mut |x: &Expr| {
        // An angle's cosine that the algebraic numbers refuse by a limit (`cos(2*pi/1009)`)
        // goes the same way, so that the refusal names the limit rather than `C`'s table of
        // angles; a square root past the limit stays with `C`, which may still denest it.
        if !found && x.eval_constant::<C>().is_err() {
            found = match x.eval_constant::<Algebraic>() {
                Ok(_) => true,
                Err(e) => {
                    e.limit().is_some()
                        && matches!(&x.kind, ExprKind::Call(name, _) if Trig::from_name(name).is_some())
                }
            };
        }
        // Keep the leaf: only the answer matters.
        Ok(Some(x.clone()))
    });
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Radical;

    fn rewrite(text: &str) -> (String, Vec<String>) {
        let mut leaves = Vec::new();
        let e = abstract_constants(&parse_expr(text).unwrap(), &mut leaves).unwrap();
        (e.to_string(), leaves.into_iter().map(|l| l.text).collect())
    }

    #[test]
    fn leaves_are_abstracted_and_angles_split() {
        let (e, l) = rewrite("x + cos(pi/5)");
        assert_eq!(e, "x + #0");
        assert_eq!(l, ["cos(pi/5)"]);
        let (e, l) = rewrite("sin(x + pi/5)");
        assert_eq!(e, "sin(x)*#0 + cos(x)*#1");
        assert_eq!(l, ["cos(pi/5)", "sin(pi/5)"]);
        // Rational values become numbers, equal values one leaf.
        let (e, l) = rewrite("cos(x + pi/2) + sqrt(2)*y + sqrt(4/2)*z + cos(pi/3)");
        assert_eq!(l, ["sqrt(2)"]);
        assert!(e.contains("1/2") && !e.contains("pi"), "{e}");
        // A nested radical is one leaf; an angle without pi is untouched.
        let (e, l) = rewrite("sqrt(2 + sqrt(2))*x + sin(2*x - y)");
        assert_eq!(l, ["sqrt(2 + sqrt(2))"]);
        assert_eq!(e, "#0*x + sin(2*x - y)");
    }

    #[test]
    fn angles_with_a_sum_index_are_split_before_the_sum_is_unrolled() {
        let (e, l) = rewrite("sum(k, 1, 2, sin(k*x + pi/5))");
        assert_eq!(e, "sum(k, 1, 2, sin(k*x)*#0 + cos(k*x)*#1)");
        assert_eq!(l, ["cos(pi/5)", "sin(pi/5)"]);
        let (e, _) = rewrite("sum(k, 1, 2, cos(-k*x - 2*pi/7 + y))");
        assert_eq!(e, "sum(k, 1, 2, cos(-k*x + y)*#0 - sin(-k*x + y)*#1)");
        // Without pi in the constant terms there is nothing to split.
        let (e, l) = rewrite("sum(k, 1, 2, sin(k*x + 1))");
        assert_eq!(e, "sum(k, 1, 2, sin(k*x + 1))");
        assert!(l.is_empty());
        assert!(needs_algebraic::<Radical>(
            &parse_expr("sum(k, 1, 3, tan(k*x + pi/10))").unwrap()
        ));
    }

    #[test]
    fn errors_and_detection() {
        let mut leaves = Vec::new();
        let err = abstract_constants(&parse_expr("x + sqrt(-2)").unwrap(), &mut leaves);
        assert!(err.is_err());
        let needs = |t: &str| needs_algebraic::<Radical>(&parse_expr(t).unwrap());
        assert!(needs("x + cos(pi/5)"));
        assert!(needs("sin(x + pi/7)"));
        assert!(needs("x*sqrt(2 + sqrt(2))"));
        assert!(!needs("x + cos(pi/4)"));
        assert!(!needs("sin(x + pi/3) + sqrt(x)"));
        assert!(!needs("x + sqrt(-2)"));
    }

    #[test]
    fn integrals_to_a_bound_with_pi_give_leaves() {
        let (e, l) = rewrite("integrate(t*cos(t), t, 0, pi/7)");
        assert!(!e.contains("integrate") && e.contains("#0"), "{e}");
        assert_eq!(l.len(), 2, "{l:?}");
        assert!(l.iter().all(|x| x.contains("pi/7")), "{l:?}");
        // An angle with a variable is split by the addition formulas.
        let (e, l) = rewrite("integrate(cos(t), t, 0, x + pi/5)");
        assert!(e.contains("sin(x)") && e.contains("cos(x)"), "{e}");
        assert!(!e.contains("integrate") && !e.contains("pi"), "{e}");
        assert_eq!(l, ["cos(pi/5)", "sin(pi/5)"]);
        let needs = |t: &str| needs_algebraic::<Radical>(&parse_expr(t).unwrap());
        assert!(needs("integrate(sin(t)^2, t, 0, pi/7)"));
        assert!(needs("integrate(cos(t), t, 0, x + pi/5)"));
        // In the square-root field the fast path keeps the integral.
        assert!(!needs("integrate(t*cos(t), t, 0, pi/3)"));
        assert!(!needs("integrate(t^2, t, 0, pi/7)"));
        let (e, _) = rewrite("integrate(t^2, t, 0, pi/7)");
        assert!(e.contains("integrate"), "{e}");
        // A bound that is not an angle does not take this path: the conversion says why.
        assert!(!needs("integrate(cos(t), t, 0, pi^2)"));
    }

    #[test]
    fn filled_placeholders_and_polynomials() {
        let p = UPoly::from_i64_coeffs(&[-1, 0, 2]);
        let filled = fill_constants(&parse_expr("x + 1").unwrap(), &[]);
        assert_eq!(filled.to_string(), "x + 1");
        let mut leaves = Vec::new();
        let e = abstract_constants(&parse_expr("x*cos(pi/5)").unwrap(), &mut leaves).unwrap();
        let filled = fill_constants(&e, &[upoly_expr(&p, "c")]);
        assert_eq!(filled.to_string(), "x*(-1 + 2*c^2)");
    }
}
