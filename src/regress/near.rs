//! `regress --near 'LHS = RHS'`: the inputs of a formula drawn near the set where the equation
//! holds ([`exactcheck_float::NearSet`]), every sign of `LHS - RHS` decided exactly by the same
//! exact evaluation as the reference side ([`Program::eval_exact`]).

use crate::Error;
use exactcheck_exact::expr::{
    parse_expr_with_calls, reserved_constant, split_equation, AddOp, Expr, ExprKind, PI,
};
use exactcheck_exact::program::Program;
use exactcheck_exact::Rational;
use exactcheck_float::{ExactScalar, InputGen, NearSet, Rng};
use std::cmp::Ordering;

/// How many samples are tried before a sweep: if none of them can be placed, the set is
/// reported as unreachable instead of sweeping invalid inputs.
const PROBES: usize = 4;

/// The input names an expression of `option` (`--bin`, `--near`) over a program's inputs is
/// compiled with. An FPCore input may have a name the formula syntax reads as a constant (`e`,
/// `i`, `pi`: FPBench's `matrixDeterminant` has an input `e`); such an input gets an alias, its
/// name followed by zeros (`e0`, or `e00` if `e0` is taken), so that expressions over the other
/// inputs work and this one can be named too. An expression naming the constant where the
/// program has an input of that name is refused, since it would not mean the input.
///
/// # Errors
/// `text` names such a constant.
pub fn expression_inputs(
    option: &str,
    text: &str,
    inputs: &[String],
) -> Result<Vec<String>, Error> {
    let constant = |n: &str| n == PI || reserved_constant(n).is_some();
    if !inputs.iter().any(|n| constant(n)) {
        return Ok(inputs.to_vec());
    }
    let mut out: Vec<String> = inputs.to_vec();
    for k in 0..out.len() {
        if !constant(&out[k]) {
            continue;
        }
        let mut alias = format!("{}0", out[k]);
        while out.contains(&alias) || inputs.contains(&alias) {
            alias.push('0');
        }
        out[k] = alias;
    }
    // A syntax error is left to the caller's compilation, which reports it with its position.
    if let Ok(expr) = parse_expr_with_calls(text) {
        let mut named = Vec::new();
        expr.collect_variables(&mut named);
        if let Some(k) = inputs.iter().position(|n| constant(n) && named.contains(n)) {
            return Err(Error::Input(format!(
                "{option}: '{n}' in '{}' is a constant in the formula syntax, not the input {n} of this benchmark: write {} for that input",
                text.trim(),
                out[k],
                n = inputs[k],
            )));
        }
    }
    Ok(out)
}

/// The program of `LHS - RHS` over the formula's inputs.
fn difference(text: &str, inputs: &[String]) -> Result<Program, Error> {
    let bad = |why: String| Error::Input(format!("--near: {why}"));
    let inputs = &expression_inputs("--near", text, inputs)?;
    let Some((lhs, rhs)) = split_equation(text) else {
        return Err(bad(format!(
            "'{}' is not one equation EXPR = EXPR (e.g. 'x*y = 1' or 'a - b = 0')",
            text.trim()
        )));
    };
    let mut parsed = Vec::new();
    for (side, t) in [("left side", lhs.as_str()), ("right side", rhs.as_str())] {
        if t.trim().is_empty() {
            return Err(bad(format!("the {side} of '{}' is empty", text.trim())));
        }
        // Each side alone first, so that an error's position is within the side it names.
        Program::parse(t, Some(inputs)).map_err(|e| bad(format!("{side}: {e}")))?;
        parsed.push(parse_expr_with_calls(t).map_err(|e| bad(format!("{side}: {e}")))?);
    }
    let rhs = parsed.pop().expect("two sides");
    let lhs = parsed.pop().expect("two sides");
    let diff = Expr {
        kind: ExprKind::Sum(vec![(AddOp::Plus, lhs), (AddOp::Minus, rhs)]),
        pos: 0,
    };
    let mut p = Program::from_expr(&diff, Some(inputs)).map_err(|e| bad(e.to_string()))?;
    if p.outputs.len() != 1 {
        return Err(bad(format!(
            "'{}' has {} sides' coordinates; an equation of scalars is one set",
            text.trim(),
            p.outputs.len()
        )));
    }
    p.name = text.trim().to_string();
    Ok(p)
}

/// The exact sign of the program's one output at `x`; `None` outside its domain or undecided.
fn exact_sign(g: &Program, x: &[f64]) -> Option<Ordering> {
    let q: Vec<Rational> = x
        .iter()
        .map(|&v| Rational::from_f64_exact(v))
        .collect::<Option<_>>()?;
    let r = g.eval_exact(&q).ok()?;
    // An inexact reference has the true value's sign (the contract of `program::real`).
    Some(
        r[0].value
            .cmp(&num_rational::BigRational::from_integer(0.into())),
    )
}

/// The generator of `--near TEXT` around points of `base`, after checking that the set can be
/// reached from the first samples of the sweep.
///
/// # Errors
/// The equation does not parse or names a variable the formula does not have, or no probe
/// sample could be placed on its set (empty inside the domain, touched without a sign change,
/// or undefined there).
pub fn generator<'a, G: InputGen + 'a>(
    text: &str,
    inputs: &[String],
    base: G,
    seed: u64,
) -> Result<NearSet<'a, G>, Error> {
    let g = difference(text, inputs)?;
    let set = g.name.clone();
    let near = NearSet::new(base, set, Box::new(move |x: &[f64]| exact_sign(&g, x)));
    let mut first = None;
    for i in 0..PROBES {
        match near.place(&mut Rng::for_sample(seed, i as u64)) {
            Ok(_) => return Ok(near),
            Err(e) => first = first.or(Some(e)),
        }
    }
    Err(Error::Input(format!(
        "--near: {}",
        first.expect("at least one probe")
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_float::UniformBox;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| (*s).to_string()).collect()
    }

    #[test]
    fn equations_are_read_and_checked() {
        let g = difference("x*y = 1", &names(&["x", "y"])).unwrap();
        assert_eq!(exact_sign(&g, &[2.0, 0.5]), Some(Ordering::Equal));
        assert_eq!(exact_sign(&g, &[2.0, 1.0]), Some(Ordering::Greater));
        for (text, msg) in [
            ("x*y", "is not one equation"),
            ("x = y = 1", "is not one equation"),
            (" = 1", "the left side of '= 1' is empty"),
            ("x = z", "right side: unknown variable 'z'"),
        ] {
            let e = difference(text, &names(&["x", "y"]))
                .unwrap_err()
                .to_string();
            assert!(e.starts_with("--near: ") && e.contains(msg), "{text}: {e}");
        }
    }

    #[test]
    fn inputs_named_like_constants_get_an_alias() {
        let inputs = names(&["a", "e", "e0", "i", "pi"]);
        assert_eq!(
            expression_inputs("--bin", "a*e00", &inputs).unwrap(),
            names(&["a", "e00", "e0", "i0", "pi0"])
        );
        let plain = names(&["x", "y"]);
        assert_eq!(expression_inputs("--bin", "x", &plain).unwrap(), plain);
        for (text, n, alias) in [
            ("a*e", "e", "e00"),
            ("i + 1", "i", "i0"),
            ("pi", "pi", "pi0"),
        ] {
            let e = expression_inputs("--near", text, &inputs)
                .unwrap_err()
                .to_string();
            assert_eq!(
                e,
                format!("--near: '{n}' in '{text}' is a constant in the formula syntax, not the input {n} of this benchmark: write {alias} for that input")
            );
        }
        // The aliases compile, in the inputs' order.
        let g = difference("e00 = a*i0", &inputs).unwrap();
        assert_eq!(g.inputs, names(&["a", "e00", "e0", "i0", "pi0"]));
        assert_eq!(
            exact_sign(&g, &[2.0, 6.0, 0.0, 3.0, 0.0]),
            Some(Ordering::Equal)
        );
        assert_eq!(
            exact_sign(&g, &[2.0, 7.0, 0.0, 3.0, 0.0]),
            Some(Ordering::Greater)
        );
    }

    #[test]
    fn an_unreachable_set_is_one_error() {
        let base = UniformBox::cube(2, -1.0, 1.0).unwrap();
        let e = generator("x^2 + y^2 = -1", &names(&["x", "y"]), &base, 1)
            .err()
            .unwrap()
            .to_string();
        assert!(
            e.starts_with("--near: no input near x^2 + y^2 = -1 could be placed"),
            "{e}"
        );
        let e = generator("1/(x - x) = 0", &names(&["x", "y"]), &base, 1)
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains("could be placed"), "{e}");
        assert!(generator("x = y", &names(&["x", "y"]), &base, 1).is_ok());
    }
}
