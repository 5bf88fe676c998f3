//! The domain text: `x in [-1, 1], y >= 0` parsed into intervals ([`parse_domain`]), and an
//! interval shown back in that syntax.
use super::values::exact;
use exactcheck_exact::program::fpcore::{Bound, Range};
use exactcheck_exact::Rational;

/// A bound value: as a double when it is one (`1e15`, `0.5`), else as the exact rational.
pub(super) fn show_value(q: &Rational) -> String {
    let d = q.to_f64();
    if d.is_finite() && &exact(d) == q {
        let a = d.abs();
        if a != 0.0 && !(1e-4..1e6).contains(&a) {
            format!("{d:e}")
        } else {
            format!("{d}")
        }
    } else {
        q.to_string()
    }
}

/// `[lo, hi]`, `(lo, inf)`, ...
pub(super) fn show_interval(iv: &Range) -> String {
    let lo = match &iv.lo {
        Bound::Unbounded => "(-inf".to_string(),
        Bound::Closed(q) => format!("[{}", show_value(q)),
        Bound::Open(q) => format!("({}", show_value(q)),
    };
    let hi = match &iv.hi {
        Bound::Unbounded => "inf)".to_string(),
        Bound::Closed(q) => format!("{}]", show_value(q)),
        Bound::Open(q) => format!("{})", show_value(q)),
    };
    format!("{lo}, {hi}")
}

/// Which sides of an input a domain text has bounded so far.
#[derive(Clone, Copy, Default)]
struct Seen {
    lo: bool,
    hi: bool,
}

/// Parses a domain text into one [`Range`] per variable of `vars`.
///
/// The text is a comma-separated list of parts, each `NAME in [a, b]` (brackets: `[`/`]`
/// closed, `(`/`)` open; `inf`, `+inf`, `-inf` for a missing bound) or a one-sided
/// `NAME >= a`, `NAME > a`, `NAME <= b`, `NAME < b` (a lower and an upper one-sided part may
/// bound the same variable). Numbers are in the workspace's number syntax, parsed by
/// [`Rational`]'s `FromStr`: `1e15`, `-2^60`, `1/3`, `0.1` (exactly one tenth). A variable not
/// mentioned is unbounded on both sides; an empty text bounds nothing.
///
/// # Errors
/// A one-line message naming the part: an unknown variable, a variable bounded twice (on the
/// same side), an unparsable number, `lo > hi`, or garbage.
pub fn parse_domain(text: &str, vars: &[String]) -> Result<Vec<Range>, String> {
    let mut out = vec![Range::UNBOUNDED; vars.len()];
    let mut seen = vec![Seen::default(); vars.len()];
    for part in split_parts(text) {
        let part = part.trim();
        if part.is_empty() {
            if text.trim().is_empty() {
                continue;
            }
            return Err(format!("domain {text:?}: an empty part between commas"));
        }
        let bad = |why: &str| format!("domain part {part:?}: {why}");
        let name_end = part
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(part.len());
        let name = &part[..name_end];
        if name.is_empty() {
            return Err(bad("expected a variable name"));
        }
        let Some(i) = vars.iter().position(|v| v == name) else {
            return Err(bad(&format!(
                "unknown variable `{name}` (the variables are {})",
                vars.join(", ")
            )));
        };
        let rest = part[name_end..].trim_start();
        let (lo, hi) = if let Some(spec) = rest.strip_prefix("in") {
            let spec = spec.trim();
            let (lo, hi) = parse_bracketed(spec).map_err(|why| bad(&why))?;
            if seen[i].lo || seen[i].hi {
                return Err(bad(&format!("`{name}` is bounded twice")));
            }
            (Some(lo), Some(hi))
        } else {
            let (op, value) = [">=", "<=", ">", "<"]
                .iter()
                .find_map(|op| rest.strip_prefix(op).map(|v| (*op, v)))
                .ok_or_else(|| bad("expected `in [a, b]` or a comparison `>= a`, `< b`, ..."))?;
            let v = parse_number(value.trim()).map_err(|why| bad(&why))?;
            let Some(v) = v else {
                return Err(bad("a one-sided bound must be a finite number"));
            };
            match op {
                ">=" => (Some(Bound::Closed(v)), None),
                ">" => (Some(Bound::Open(v)), None),
                "<=" => (None, Some(Bound::Closed(v))),
                _ => (None, Some(Bound::Open(v))),
            }
        };
        if let Some(lo) = lo {
            if seen[i].lo {
                return Err(bad(&format!("`{name}` has two lower bounds")));
            }
            seen[i].lo = true;
            out[i].lo = lo;
        }
        if let Some(hi) = hi {
            if seen[i].hi {
                return Err(bad(&format!("`{name}` has two upper bounds")));
            }
            seen[i].hi = true;
            out[i].hi = hi;
        }
        if let (Some(l), Some(h)) = (out[i].lo.value(), out[i].hi.value()) {
            let open = matches!(out[i].lo, Bound::Open(_)) || matches!(out[i].hi, Bound::Open(_));
            if l > h || (l == h && open) {
                return Err(bad(&format!(
                    "the interval of `{name}` is empty: {}",
                    show_interval(&out[i])
                )));
            }
        }
    }
    Ok(out)
}

/// The parts of a domain text: split at the commas outside brackets and parentheses.
fn split_parts(text: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '[' | '(' => depth += 1,
            ']' | ')' => depth -= 1,
            ',' if depth <= 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// `[a, b]`, `(a, b]`, ... into its two bounds.
fn parse_bracketed(spec: &str) -> Result<(Bound, Bound), String> {
    let open_lo = match spec.chars().next() {
        Some('[') => false,
        Some('(') => true,
        _ => return Err("expected `[` or `(` after `in`".to_string()),
    };
    let open_hi = match spec.chars().last() {
        Some(']') if spec.len() > 1 => false,
        Some(')') if spec.len() > 1 => true,
        _ => return Err("expected the interval to end with `]` or `)`".to_string()),
    };
    let inner = &spec[1..spec.len() - 1];
    // The comma between the bounds: the first one outside parentheses.
    let mut depth = 0i32;
    let comma = inner.char_indices().find_map(|(i, c)| {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => return Some(i),
            _ => {}
        }
        None
    });
    let Some(comma) = comma else {
        return Err("expected two bounds `a, b` in the interval".to_string());
    };
    let lo_text = inner[..comma].trim();
    let hi_text = inner[comma + 1..].trim();
    let lo = match parse_number(lo_text)? {
        Some(v) if open_lo => Bound::Open(v),
        Some(v) => Bound::Closed(v),
        None if is_minus_inf(lo_text) => Bound::Unbounded,
        None => return Err("the lower bound cannot be +inf".to_string()),
    };
    let hi = match parse_number(hi_text)? {
        Some(v) if open_hi => Bound::Open(v),
        Some(v) => Bound::Closed(v),
        None if !is_minus_inf(hi_text) => Bound::Unbounded,
        None => return Err("the upper bound cannot be -inf".to_string()),
    };
    Ok((lo, hi))
}

fn is_minus_inf(s: &str) -> bool {
    s.starts_with('-')
}

/// A bound: `Ok(None)` for `inf`, `+inf`, `-inf` (also `infinity`), else the exact number.
fn parse_number(s: &str) -> Result<Option<Rational>, String> {
    let unsigned = s.strip_prefix(['+', '-']).unwrap_or(s).trim();
    if unsigned.eq_ignore_ascii_case("inf") || unsigned.eq_ignore_ascii_case("infinity") {
        return Ok(None);
    }
    if s.is_empty() {
        return Err("expected a number".to_string());
    }
    s.parse::<Rational>()
        .map(Some)
        .map_err(|e| format!("`{s}` is not a number ({e})"))
}
