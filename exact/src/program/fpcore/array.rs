//! FPCore `(array ...)` results in tail position anywhere in the body: under `let`, `let*`,
//! `if`, `!` and a loop's result, not only as the whole body. Such a body has one output per
//! element; output `k` is the body with each tail array replaced by its element `k`
//! ([`project`]), so the bindings and conditions around it are shared by every output (each
//! output tree evaluates them again: pure expressions, the same values on both sides).
//!
//! A body with a loop is not repeated per element: a loop of thousands of iterations would run
//! once per output and count against `loop-iterations` that many times. Its tail arrays are
//! marked instead ([`shared`]) and the compiler evaluates the body once, binding the elements
//! to result slots that the outputs read.

use super::sexpr::{Pos, SExpr};

/// The tail expressions of `e` that its value comes from: `None` for an expression that is not
/// a `let`, `let*`, `if`, `!` or loop.
fn tails(e: &SExpr) -> Option<Vec<&SExpr>> {
    let SExpr::List(items, _) = e else {
        return None;
    };
    match (items.first().and_then(SExpr::sym), items.len()) {
        (Some("let" | "let*"), 3) => Some(vec![&items[2]]),
        (Some("while" | "while*"), 4) => Some(vec![&items[3]]),
        (Some("if"), 4) => Some(vec![&items[2], &items[3]]),
        (Some("!"), n) if n >= 2 => Some(vec![&items[n - 1]]),
        _ => None,
    }
}

fn is_array(e: &SExpr) -> Option<usize> {
    match e {
        SExpr::List(items, _) if items.first().and_then(SExpr::sym) == Some("array") => {
            Some(items.len() - 1)
        }
        _ => None,
    }
}

/// The number of elements of the array `body` returns, `None` when it returns a number.
///
/// # Errors
/// The position and message of an empty `(array)`, or of branches returning arrays of
/// different lengths (or an array and a number).
fn width(body: &SExpr) -> Result<Option<usize>, (Pos, String)> {
    if let Some(n) = is_array(body) {
        if n == 0 {
            return Err((body.pos(), "an empty (array) has no output".into()));
        }
        return Ok(Some(n));
    }
    let Some(ts) = tails(body) else {
        return Ok(None);
    };
    let mut found: Option<Option<usize>> = None;
    for t in ts {
        let w = width(t)?;
        match found {
            None => found = Some(w),
            Some(prev) if prev != w => {
                let show = |w: Option<usize>| {
                    w.map_or("a number".to_string(), |n| format!("an array of {n}"))
                };
                return Err((
                    t.pos(),
                    format!(
                        "the branches of an if return {} and {}",
                        show(prev),
                        show(w)
                    ),
                ));
            }
            Some(_) => {}
        }
    }
    Ok(found.flatten())
}

/// The outputs of `body` compiled by `num`, one per element of the array it returns; `None`
/// when it returns a number. `bad` makes the error of a malformed array result ([`width`]).
pub(super) fn elements<T, E>(
    body: &SExpr,
    mut num: impl FnMut(&SExpr) -> Result<T, E>,
    bad: impl Fn(Pos, String) -> E,
) -> Result<Option<Vec<T>>, E> {
    match width(body).map_err(|(pos, m)| bad(pos, m))? {
        None => Ok(None),
        Some(n) => (0..n)
            .map(|k| num(&project(body, k)))
            .collect::<Result<_, _>>()
            .map(Some),
    }
}

/// The head of the form that stands for a tail `(array e0 e1 ...)` in [`shared`]'s body: a
/// symbol no FPCore text can spell (it holds a space), so only the compiler's own rewriting
/// produces it.
pub(super) const RESULTS: &str = "array results";

/// The body of a program with a loop (`while`, `while*`, anywhere in it) that returns an array
/// of `n` elements, with every tail `(array e0 e1 ...)` replaced by `(RESULTS e0 e1 ...)`: the
/// compiler evaluates that body once and binds the elements to `n` result slots, so the loop
/// runs once per evaluation for all outputs. `None` for a body without a loop or without an
/// array result (each output is then its own tree, [`elements`]).
///
/// # Errors
/// As [`elements`]: a malformed array result.
pub(super) fn shared<E>(
    body: &SExpr,
    bad: impl Fn(Pos, String) -> E,
) -> Result<Option<(usize, SExpr)>, E> {
    match width(body).map_err(|(pos, m)| bad(pos, m))? {
        Some(n) if has_loop(body) => Ok(Some((n, replace_tails(body, &mark)))),
        _ => Ok(None),
    }
}

/// Whether `e` has a `while` or `while*` form anywhere.
fn has_loop(e: &SExpr) -> bool {
    match e {
        SExpr::List(items, _) => {
            matches!(items.first().and_then(SExpr::sym), Some("while" | "while*"))
                || items.iter().any(has_loop)
        }
        _ => false,
    }
}

/// `(array e0 e1 ...)` as `(RESULTS e0 e1 ...)`.
fn mark(array: &SExpr) -> SExpr {
    let SExpr::List(items, pos) = array else {
        unreachable!("an array is a list")
    };
    let mut out = items.clone();
    out[0] = SExpr::Sym(RESULTS.to_string(), items[0].pos());
    SExpr::List(out, *pos)
}

/// `body` with every tail `(array e0 e1 ...)` replaced by `ek`.
fn project(body: &SExpr, k: usize) -> SExpr {
    replace_tails(body, &|array: &SExpr| {
        let SExpr::List(items, _) = array else {
            unreachable!("an array is a list")
        };
        items[k + 1].clone()
    })
}

/// `body` with every tail array replaced by `f` of it.
fn replace_tails(body: &SExpr, f: &dyn Fn(&SExpr) -> SExpr) -> SExpr {
    if is_array(body).is_some() {
        return f(body);
    }
    let Some(ts) = tails(body) else {
        return body.clone();
    };
    let SExpr::List(items, pos) = body else {
        unreachable!("only lists have tails")
    };
    let tail_at: Vec<usize> = items
        .iter()
        .enumerate()
        .filter(|(_, it)| ts.iter().any(|t| std::ptr::eq(*t, *it)))
        .map(|(i, _)| i)
        .collect();
    let items = items
        .iter()
        .enumerate()
        .map(|(i, it)| {
            if tail_at.contains(&i) {
                replace_tails(it, f)
            } else {
                it.clone()
            }
        })
        .collect();
    SExpr::List(items, *pos)
}

#[cfg(test)]
mod tests {
    use crate::program::fpcore::parse_file;
    use crate::program::Program;

    fn program(text: &str) -> Program {
        let b = parse_file(text).expect("parses");
        b[0].program.clone().expect("supported")
    }

    #[test]
    fn arrays_under_let_if_and_annotations_are_outputs() {
        let p = program("(FPCore (x y) (let ([s (+ x y)]) (array s (* s y))))");
        assert_eq!(p.outputs.len(), 2);
        assert_eq!(p.eval_f64(&[1.0, 2.0]), vec![3.0, 6.0]);
        let p = program(
            "(FPCore (x) (if (< x 0) (array (- x) 1) (! :precision binary64 (array x 2))))",
        );
        assert_eq!(p.eval_f64(&[-3.0]), vec![3.0, 1.0]);
        assert_eq!(p.eval_f64(&[5.0]), vec![5.0, 2.0]);
        let p = program("(FPCore (x) (let* ([a x] [b (* a a)]) (array a b (- b a))))");
        assert_eq!(p.eval_f64(&[3.0]), vec![3.0, 9.0, 6.0]);
    }

    #[test]
    fn branches_of_different_shapes_are_errors() {
        for (text, msg) in [
            (
                "(FPCore (x) (if (< x 0) (array x 1) x))",
                "an array of 2 and a number",
            ),
            (
                "(FPCore (x) (if (< x 0) (array x) (array x x)))",
                "an array of 1 and an array of 2",
            ),
            ("(FPCore (x) (let ([a x]) (array)))", "an empty (array)"),
        ] {
            let Err(e) = parse_file(text) else {
                panic!("{text} is accepted")
            };
            let e = e.to_string();
            assert!(e.contains(msg), "{text}: {e}");
        }
    }
}
