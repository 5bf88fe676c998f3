//! `solve` claims: a solver's exact answer compared with expected fields.

use super::*;

/// A field of an answer: by JSON pointer (`/a/0`) or dotted path (`a.0`).
fn lookup<'a>(answer: &'a Value, path: &str) -> Option<&'a Value> {
    if path.starts_with('/') {
        return answer.pointer(path);
    }
    let mut v = answer;
    for seg in path.split('.') {
        v = match v {
            Value::Object(m) => m.get(seg)?,
            Value::Array(a) => a.get(seg.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(v)
}

/// An exact number of a JSON value (a number or a numeric string).
fn exact_number(v: &Value) -> Option<Radical> {
    match v {
        Value::Number(n) => n.to_string().parse().ok(),
        Value::String(s) => s.parse().ok(),
        _ => None,
    }
}

/// Whether an answer's value is the expected one: equal JSON, or equal exact numbers, or
/// arrays/objects equal element by element in that sense.
fn matches(expected: &Value, got: &Value) -> bool {
    match (expected, got) {
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| matches(x, y))
        }
        (Value::Object(a), Value::Object(b)) => {
            a.len() == b.len()
                && a.iter()
                    .all(|(k, x)| b.get(k).is_some_and(|y| matches(x, y)))
        }
        _ if expected == got => true,
        _ => match (exact_number(expected), exact_number(got)) {
            (Some(x), Some(y)) => x == y,
            _ => false,
        },
    }
}

pub(super) fn solve(problem: &str, fields: &[(String, Value)]) -> Result<Outcome, Fault> {
    let answer = crate::solve::solve(problem, crate::solve::Mode::Exact)
        .map_err(|e| Fault::Input("problem", e.to_string()))?;
    let kind = answer
        .get("kind")
        .and_then(Value::as_str)
        .unwrap_or("?")
        .to_string();
    let mut matched = Vec::new();
    let mut mismatched = Vec::new();
    let mut e = Erratum::default();
    for (path, expected) in fields {
        match lookup(&answer, path) {
            Some(got) if matches(expected, got) => matched.push(format!("{path} = {expected}")),
            Some(got) => {
                mismatched.push(format!("{path} is {got}, not {expected}"));
                if let (Some(x), Some(y)) = (exact_number(expected), exact_number(got)) {
                    let label = var(&path
                        .trim_start_matches('/')
                        .replace(|c: char| !c.is_ascii_alphanumeric(), "_"));
                    e.printed.push(Equation {
                        lhs: label.clone(),
                        rhs: value_expr(&x)?,
                    });
                    e.corrected.push(Equation {
                        lhs: label,
                        rhs: value_expr(&y)?,
                    });
                }
            }
            None => mismatched.push(format!("{path} is not in the answer (expected {expected})")),
        }
    }
    let method = format!("the exact solver (solve, kind {kind}) on the given configuration");
    if mismatched.is_empty() {
        return Ok(Outcome {
            verdict: Verdict::Holds,
            method,
            evidence: format!(
                "the exact answer has every expected field: {}",
                matched.join(", ")
            ),
            erratum: None,
        });
    }
    e.correction = format!("the exact solver finds: {}", mismatched.join("; "));
    Ok(Outcome {
        verdict: Verdict::Fails,
        method,
        evidence: format!(
            "{}{}",
            mismatched.join("; "),
            if matched.is_empty() {
                String::new()
            } else {
                format!(" (matched: {})", matched.join(", "))
            }
        ),
        erratum: Some(Box::new(e)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn answer_fields_compare_exactly() {
        let a = json!({"type": "parabola", "plane": ["1", "sqrt(2)"], "n": 3, "ok": false});
        assert!(matches(&json!("parabola"), lookup(&a, "type").unwrap()));
        assert!(matches(
            &json!([1, "2/sqrt(2)"]),
            lookup(&a, "plane").unwrap()
        ));
        assert!(matches(&json!("6/2"), lookup(&a, "/n").unwrap()));
        assert!(!matches(&json!(true), lookup(&a, "ok").unwrap()));
        assert!(matches(&json!(1), lookup(&a, "plane.0").unwrap()));
        assert!(lookup(&a, "plane.2").is_none());
    }
}
