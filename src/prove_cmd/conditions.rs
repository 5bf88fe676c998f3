//! The conditions of `prove` and of claims files: relations `A = B`, hypotheses `A != B` and
//! domains `0 <= t <= 1`, read from their texts; and the domains as bounds on the variables of a
//! table ([`var_domains`]), where the domain of an angle of sin, cos and tan, given in multiples
//! of pi (`0 <= theta <= pi`), becomes the signs of the cosine and sine of its base angle.

use super::parse_in;
use crate::Error;
use exactcheck_core::Ring;
use exactcheck_exact::expr::{library, parse_expr, split_equation, variable_base, Expr, PI};
use exactcheck_exact::poly::{Var, Vars};
use exactcheck_exact::prove::VarDomain;
use exactcheck_exact::Rational;
use num_traits::ToPrimitive;
use std::cell::RefCell;

/// A variable's domain, as given: its bounds (numbers, or multiples of pi for an angle) and the
/// text it was read from.
#[derive(Clone, Debug)]
pub struct Domain {
    /// The variable.
    pub name: String,
    /// The bounds.
    pub bounds: VarDomain,
    /// Whether the bounds are multiples of pi: the domain of an angle of sin, cos and tan.
    pub in_pi: bool,
    /// The text, for the verdict.
    pub text: String,
}

/// A `--where` argument (or a claims file's `where` entry): a relation or a domain.
pub enum Where {
    /// `A = B`.
    Relation(Expr, Expr),
    /// A variable's bounds.
    Domain(Domain),
    /// `A != B`: a hypothesis the proof may use (and the counter-example search respects).
    NonZero(Expr, Expr),
}

/// The hypotheses of one `--where` text (or claims-file `where` entry): a comma-separated list as a
/// paper prints it is several, `a >= 0, b >= 0` is `a >= 0` and `b >= 0`, and a list of variables
/// sharing one comparison, `a, b > 0`, is `a > 0` and `b > 0`. Commas inside parentheses or brackets
/// (`binomial(4, 2)`, `[1, 2]`) do not split; a text without a top-level comma is itself.
pub fn split_where(text: &str) -> Vec<String> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0usize, 0);
    for (i, ch) in text.char_indices() {
        match ch {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                parts.push(text[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(text[start..].trim());
    if parts.len() == 1 {
        return vec![text.to_string()];
    }
    let is_name = exactcheck_exact::expr::library::is_name;
    // `a, b, c > 0`: the leading bare names take the last part's comparison.
    let last = parts[parts.len() - 1];
    let head = last
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(last.len());
    let comparison = last[head..].trim_start();
    let shared = parts[..parts.len() - 1].iter().all(|p| is_name(p))
        && is_name(&last[..head])
        && comparison.starts_with(['<', '>', '=', '!']);
    if shared {
        let mut texts: Vec<String> = parts[..parts.len() - 1]
            .iter()
            .map(|p| format!("{p} {comparison}"))
            .collect();
        texts.push(last.to_string());
        return texts;
    }
    parts.into_iter().map(str::to_string).collect()
}

/// Parses `--where #i` (`what` names it): `A = B`, or a chain `a < v`, `v >= a`, `a <= v < b`
/// with a variable `v` and constants `a`, `b`.
pub(super) fn parse_where(
    text: &str,
    what: &str,
    defs: &RefCell<library::Defs>,
) -> Result<Where, Error> {
    parse_where_with(text, what, &|t, w| parse_in(defs, t, w))
}

/// `parse_where` with the expression parser given (the claims files resolve their
/// definitions and functions in it): `parse(text, what)`.
///
/// # Errors
/// [`Error::Input`] naming `what` for a malformed relation or domain.
pub fn parse_where_with(
    text: &str,
    what: &str,
    parse: &dyn Fn(&str, &str) -> Result<Expr, Error>,
) -> Result<Where, Error> {
    let given = text;
    let ascii = ascii_comparisons(text);
    let text = ascii.as_str();
    if let Some((a, b)) = text.split_once("!=") {
        if b.contains(['=', '<', '>', '!']) || a.contains(['=', '<', '>']) {
            return Err(Error::Input(format!(
                "{what}: {text:?} must have the form 'A != B' (one '!=', no other comparison)"
            )));
        }
        return Ok(Where::NonZero(
            parse(a, &format!("{what} left side"))?,
            parse(b, &format!("{what} right side"))?,
        ));
    }
    // Split at the comparison operators.
    let mut parts = Vec::new();
    let mut ops = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(['<', '>']) {
        parts.push(&rest[..i]);
        let strict = !rest[i + 1..].starts_with('=');
        ops.push((rest.as_bytes()[i] == b'<', strict));
        rest = &rest[i + if strict { 1 } else { 2 }..];
    }
    parts.push(rest);
    if ops.is_empty() {
        let Some((lhs, rhs)) = split_equation(text) else {
            return Err(Error::Input(format!(
                "{what}: {text:?} must have the form 'A = B' (one '='), or a domain such as 'r > 0' or '0 <= t <= 1'"
            )));
        };
        return Ok(Where::Relation(
            parse(&lhs, &format!("{what} left side"))?,
            parse(&rhs, &format!("{what} right side"))?,
        ));
    }
    let bad = |why: &str| {
        Error::Input(format!(
            "{what}: {text:?} is not a domain ({why}); write e.g. 'r > 0', 'R >= 1/2' or '0 <= t <= 1'"
        ))
    };
    if parts.iter().any(|p| p.contains('=')) {
        return Err(bad("'=' mixed with '<' or '>'"));
    }
    if ops.len() > 2 || (ops.len() == 2 && ops[0].0 != ops[1].0) {
        return Err(bad("at most two bounds, both '<' or both '>'"));
    }
    // Bounds that are multiples of pi make an angle's domain (`0 <= theta <= pi`); a bound of
    // `0` is `0 pi` there.
    let in_pi: Vec<Option<Rational>> = parts.iter().map(|p| multiple_of_pi(p)).collect();
    let pi_bounds = in_pi.iter().any(Option::is_some);
    let exprs = parts
        .iter()
        .zip(&in_pi)
        .map(|(p, c)| match c {
            Some(c) => Ok(Expr::number(c.clone())),
            None => parse(p, what),
        })
        .collect::<Result<Vec<Expr>, Error>>()?;
    let var_at: Vec<usize> = exprs
        .iter()
        .enumerate()
        .filter(|(_, e)| matches!(e.kind, exactcheck_exact::expr::ExprKind::Var(_)))
        .map(|(i, _)| i)
        .collect();
    let vi = match (var_at.as_slice(), ops.len()) {
        ([i], 1) => *i,
        ([1], 2) => 1,
        ([], _) if pi_bounds => {
            return Err(Error::Input(format!(
                "{what}: {given:?}: pi is a constant, not a variable: it takes no domain"
            )))
        }
        _ => {
            return Err(bad(
                "one side must be a single variable, the other(s) constants",
            ))
        }
    };
    let exactcheck_exact::expr::ExprKind::Var(name) = &exprs[vi].kind else {
        unreachable!("vi indexes a variable (var_at holds only variables)")
    };
    let name = name.clone();
    let constant = |e: &Expr| -> Result<Rational, Error> {
        let mut scratch = Vars::new();
        let p = e
            .to_poly::<Rational>(&mut scratch)
            .map_err(|err| Error::Input(format!("{what}: {err}")))?;
        if !scratch.is_empty() {
            return Err(bad("bounds must be constants"));
        }
        Ok(p.constant_value()
            .expect("a polynomial without variables is a constant"))
    };
    let mut domain = VarDomain::all();
    for (k, &(less, strict)) in ops.iter().enumerate() {
        // parts[k] op parts[k + 1].
        let (other, var_left) = if k + 1 == vi {
            (k, false)
        } else {
            (k + 1, true)
        };
        let c = constant(&exprs[other])?;
        if pi_bounds && in_pi[other].is_none() && !c.is_zero() {
            return Err(bad(
                "a bound in multiples of pi and one without: write both as multiples of pi, e.g. '0 <= theta <= pi/2'",
            ));
        }
        // var_left: v op c; else c op v. `less` with v on the left is an upper bound.
        let upper = less == var_left;
        if upper {
            domain.upper = Some((c, strict));
        } else {
            domain.lower = Some((c, strict));
        }
    }
    Ok(Where::Domain(Domain {
        name,
        bounds: domain,
        in_pi: pi_bounds,
        text: given.to_string(),
    }))
}

/// The relations `A = B` among `--where` texts (each split as [`split_where`] does), for the
/// verdict: domains and hypotheses `A != B` (in ASCII, LaTeX or Unicode) are left out.
pub fn relation_texts(texts: &[String]) -> Vec<String> {
    texts
        .iter()
        .flat_map(|t| split_where(t))
        .filter(|t| !ascii_comparisons(t).contains(['<', '>', '!']))
        .collect()
}

/// `text` with the comparisons of LaTeX (`\\le`, `\\leq`, `\\leqslant`, `\\ge`, ..., `\\ne`,
/// `\\neq`, `\\lt`, `\\gt`) and of Unicode (`≤`, `≥`, `≠`) written as `<=`, `>=`, `!=`, `<`, `>`.
fn ascii_comparisons(text: &str) -> String {
    const COMMANDS: [(&str, &str); 10] = [
        ("leqslant", "<="),
        ("geqslant", ">="),
        ("leq", "<="),
        ("geq", ">="),
        ("neq", "!="),
        ("le", "<="),
        ("ge", ">="),
        ("ne", "!="),
        ("lt", "<"),
        ("gt", ">"),
    ];
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        let after = &rest[c.len_utf8()..];
        let unicode = match c {
            '≤' => Some("<="),
            '≥' => Some(">="),
            '≠' => Some("!="),
            _ => None,
        };
        if let Some(op) = unicode {
            out.push_str(&format!(" {op} "));
            rest = after;
            continue;
        }
        if c == '\\' {
            let word_len = after
                .find(|ch: char| !ch.is_ascii_alphabetic())
                .unwrap_or(after.len());
            if let Some((_, op)) = COMMANDS.iter().find(|(w, _)| *w == &after[..word_len]) {
                out.push_str(&format!(" {op} "));
                rest = &after[word_len..];
                continue;
            }
        }
        out.push(c);
        rest = after;
    }
    out
}

/// `c` when `text` is the rational multiple `c pi` of pi (`pi`, `pi/2`, `-3*pi/2`, `\\pi`), else
/// `None` (also for `0`, which is a bound of either kind).
fn multiple_of_pi(text: &str) -> Option<Rational> {
    let e = parse_expr(text).ok()?;
    let mut scratch = Vars::new();
    let p = e.to_poly::<Rational>(&mut scratch).ok()?;
    let pi = scratch.get(PI)?;
    (scratch.len() == 1 && p.len() == 1 && p.degree_in(pi) == 1).then(|| p.coefficient(&[(pi, 1)]))
}

/// The domains as bounds on the variables of `vars`: a number's domain on its variable; an
/// angle's (in multiples of pi) as the signs of `cos` and `sin` of its base angle `x/L`, which
/// say exactly the same for a statement in the sines and cosines of multiples of `x/L` when the
/// angle runs over a quarter or a half turn between multiples of pi/2 (a full turn or more says
/// nothing). Other angle domains are refused, as is a domain of a variable the table lacks.
///
/// Each bound comes with its text for the verdict: the domain's own, or for an angle the sign
/// and the domain it comes from (`sin(theta/2) >= 0 since 0 <= theta <= pi`).
///
/// # Errors
/// The domain's text and why, in one line.
pub fn var_domains(vars: &Vars, domains: &[Domain]) -> Result<VarBounds, String> {
    let mut out = VarBounds::default();
    for d in domains {
        let Domain {
            name, bounds, text, ..
        } = d;
        if !d.in_pi {
            let var = vars.get(name).ok_or_else(|| match variable_base(vars, name) {
                Some(_) => format!("{text:?}: {name} is an angle of sin, cos or tan: give its domain in multiples of pi (e.g. '0 <= {name} <= pi')"),
                None => format!("{text:?}: {name} does not occur in the identity or its relations"),
            })?;
            out.bounds.push((var, bounds.clone()));
            out.texts.push((name.clone(), text.trim().to_string()));
            continue;
        }
        if vars.get(name).is_some() {
            return Err(format!("{text:?}: {name} is used as a number, and a domain in multiples of pi is only for an angle of sin, cos and tan"));
        }
        let (angle, base) = variable_base(vars, name).ok_or_else(|| {
            format!("{text:?}: {name} is not an angle of sin, cos or tan in the identity or its relations")
        })?;
        let unit = base.unit().clone();
        let scaled = |b: &Option<(Rational, bool)>| b.as_ref().map(|(c, s)| (c * &unit, *s));
        let signs = arc_signs(scaled(&bounds.lower), scaled(&bounds.upper))
            .map_err(|why| format!("{text:?}: {why}"))?;
        for (which, sign) in signs {
            let var = if which == Which::Cos {
                angle.cos
            } else {
                angle.sin
            };
            let var_name = vars.name(var).unwrap_or_default().to_string();
            let op = match (&sign.lower, &sign.upper) {
                (Some((_, true)), _) => ">",
                (Some(_), _) => ">=",
                (_, Some((_, true))) => "<",
                _ => "<=",
            };
            out.texts.push((
                var_name.clone(),
                format!("{var_name} {op} 0 since {}", text.trim()),
            ));
            out.bounds.push((var, sign));
        }
    }
    Ok(out)
}

/// The bounds on the variables of a table ([`var_domains`]).
#[derive(Default)]
pub struct VarBounds {
    /// Each variable's bounds.
    pub bounds: Vec<(Var, VarDomain)>,
    /// `(variable name, text)` of each bound, for the verdict.
    pub texts: Vec<(String, String)>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Which {
    Cos,
    Sin,
}

/// The signs of `cos` and `sin` on the arc `lower <= phi <= upper` (multiples of pi, each end
/// strict or not) that hold exactly there: a quarter turn between multiples of pi/2 fixes both,
/// a half turn one, a full turn or more none.
fn arc_signs(
    lower: Option<(Rational, bool)>,
    upper: Option<(Rational, bool)>,
) -> Result<Vec<(Which, VarDomain)>, String> {
    let (Some((lo, lo_strict)), Some((hi, hi_strict))) = (lower, upper) else {
        return Ok(Vec::new());
    };
    let two = Rational::from_i64(2);
    let half = Rational::new(1, 2).expect("2 is not zero");
    let width = &hi - &lo;
    if width >= two && !(width == two && lo_strict && hi_strict) {
        return Ok(Vec::new());
    }
    let quarters = |q: &Rational| (q * &two).is_integer();
    if !(quarters(&lo) && quarters(&hi)) || !(width == half || width == Rational::ONE) {
        return Err(
            "an angle's domain runs over a quarter or a half turn between multiples of pi/2 (e.g. '0 <= theta <= pi/2', '-pi/2 < theta < pi/2'), or a full turn or more".into(),
        );
    }
    // The quarter where the arc starts: 0, 1, 2, 3 for [0, pi/2], [pi/2, pi], ... (modulo a
    // full turn).
    let start = ((&lo * &two).numer() % num_bigint::BigInt::from(4))
        .to_i64()
        .map(|r| r.rem_euclid(4))
        .expect("a remainder modulo 4 fits in i64");
    // On each quarter the signs of (cos, sin); the function that vanishes at its start.
    let signs = [(1, 1), (-1, 1), (-1, -1), (1, -1)];
    let zero_at = |q: i64| if q % 2 == 0 { Which::Sin } else { Which::Cos };
    let sign_domain = |positive: bool, strict: bool| {
        let zero = Some((Rational::ZERO, strict));
        if positive {
            VarDomain {
                lower: zero,
                ..VarDomain::all()
            }
        } else {
            VarDomain {
                upper: zero,
                ..VarDomain::all()
            }
        }
    };
    let pick = |w: Which, (c, s): (i64, i64)| if w == Which::Cos { c > 0 } else { s > 0 };
    if width == half {
        // The start's function vanishes at the lower end, the other one at the upper end.
        let (first, second) = (zero_at(start), zero_at(start + 1));
        let sign = signs[start as usize];
        Ok(vec![
            (first, sign_domain(pick(first, sign), lo_strict)),
            (second, sign_domain(pick(second, sign), hi_strict)),
        ])
    } else {
        // A half turn: the function that vanishes at both ends keeps one sign between them.
        if lo_strict != hi_strict {
            return Err("a half turn of an angle is given with one end open and one closed; give both ends open or both closed".into());
        }
        let w = zero_at(start);
        Ok(vec![(
            w,
            sign_domain(pick(w, signs[start as usize]), lo_strict),
        )])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n, d).unwrap()
    }

    fn signs(lo: (i64, i64, bool), hi: (i64, i64, bool)) -> Vec<(Which, Option<bool>, bool)> {
        arc_signs(Some((q(lo.0, lo.1), lo.2)), Some((q(hi.0, hi.1), hi.2)))
            .unwrap()
            .into_iter()
            .map(|(w, d)| match (d.lower, d.upper) {
                (Some((_, s)), None) => (w, Some(true), s),
                (None, Some((_, s))) => (w, Some(false), s),
                _ => (w, None, false),
            })
            .collect()
    }

    #[test]
    fn half_and_quarter_turns_give_exact_signs() {
        use Which::*;
        // 0 <= phi <= pi: sin >= 0.
        assert_eq!(
            signs((0, 1, false), (1, 1, false)),
            vec![(Sin, Some(true), false)]
        );
        // -pi/2 < phi < pi/2: cos > 0.
        assert_eq!(
            signs((-1, 2, true), (1, 2, true)),
            vec![(Cos, Some(true), true)]
        );
        // pi <= phi <= 2 pi: sin <= 0.
        assert_eq!(
            signs((1, 1, false), (2, 1, false)),
            vec![(Sin, Some(false), false)]
        );
        // 0 <= phi < pi/2: sin >= 0, cos > 0.
        assert_eq!(
            signs((0, 1, false), (1, 2, true)),
            vec![(Sin, Some(true), false), (Cos, Some(true), true)]
        );
        // pi/2 <= phi <= pi: cos <= 0, sin >= 0.
        assert_eq!(
            signs((1, 2, false), (1, 1, false)),
            vec![(Cos, Some(false), false), (Sin, Some(true), false)]
        );
        // -pi <= phi <= -pi/2 (the third quarter): sin <= 0, cos <= 0.
        assert_eq!(
            signs((-1, 1, false), (-1, 2, false)),
            vec![(Sin, Some(false), false), (Cos, Some(false), false)]
        );
        // A full turn or more says nothing.
        assert!(signs((0, 1, false), (2, 1, true)).is_empty());
        assert!(signs((-3, 1, false), (5, 1, false)).is_empty());
    }

    #[test]
    fn other_arcs_are_refused() {
        for (lo, hi) in [
            ((0, 1), (1, 3)),
            ((0, 1), (3, 2)),
            ((1, 4), (3, 4)),
            ((0, 1), (2, 1)),
        ] {
            let strict = lo == (0, 1) && hi == (2, 1);
            assert!(
                arc_signs(Some((q(lo.0, lo.1), strict)), Some((q(hi.0, hi.1), strict))).is_err(),
                "{lo:?} {hi:?}"
            );
        }
        assert!(arc_signs(Some((q(0, 1), true)), Some((q(1, 1), false))).is_err());
    }

    #[test]
    fn latex_and_unicode_comparisons_are_read() {
        assert_eq!(
            ascii_comparisons("-\\pi \\le \\theta \\leq \\pi")
                .split_whitespace()
                .collect::<Vec<_>>(),
            ["-\\pi", "<=", "\\theta", "<=", "\\pi"]
        );
        assert_eq!(
            ascii_comparisons("x ≥ 0")
                .split_whitespace()
                .collect::<Vec<_>>(),
            ["x", ">=", "0"]
        );
        assert_eq!(
            ascii_comparisons("w \\neq 0")
                .split_whitespace()
                .collect::<Vec<_>>(),
            ["w", "!=", "0"]
        );
        // Commands that only begin like a comparison stay.
        assert_eq!(
            ascii_comparisons("\\left(x\\right) \\geqx"),
            "\\left(x\\right) \\geqx"
        );
        assert!(matches!(
            parse_where("0 \\le t \\lt 1", "w", &RefCell::default()),
            Ok(Where::Domain(Domain { in_pi: false, .. }))
        ));
        assert!(matches!(
            parse_where(
                "$-\\frac{\\pi}{2} < \\theta < \\frac{\\pi}{2}$",
                "w",
                &RefCell::default()
            ),
            Ok(Where::Domain(Domain { in_pi: true, .. }))
        ));
        assert!(parse_where("1 <= theta <= pi", "w", &RefCell::default()).is_err());
    }

    #[test]
    fn multiples_of_pi_are_read() {
        assert_eq!(multiple_of_pi("pi"), Some(q(1, 1)));
        assert_eq!(multiple_of_pi("-3*pi/2"), Some(q(-3, 2)));
        assert_eq!(multiple_of_pi("\\frac{\\pi}{2}"), Some(q(1, 2)));
        assert_eq!(multiple_of_pi("2pi"), Some(q(2, 1)));
        assert_eq!(multiple_of_pi("0"), None);
        assert_eq!(multiple_of_pi("pi^2"), None);
        assert_eq!(multiple_of_pi("1 + pi"), None);
        assert_eq!(multiple_of_pi("x*pi"), None);
    }
}
