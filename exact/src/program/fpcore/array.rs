//! FPCore `(array ...)` results in tail position anywhere in the body: under `let`, `let*`,
//! `if`, `!` and a loop's result, not only as the whole body. Such a body has one output per
//! element; output `k` is the body with each tail array replaced by its element `k`
//! ([`project`]), so the bindings and conditions around it are shared by every output (each
//! output tree evaluates them again: pure expressions, the same values on both sides).

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

/// `body` with every tail `(array e0 e1 ...)` replaced by `ek`.
fn project(body: &SExpr, k: usize) -> SExpr {
    if is_array(body).is_some() {
        let SExpr::List(items, _) = body else {
            unreachable!("an array is a list")
        };
        return items[k + 1].clone();
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
                project(it, k)
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
