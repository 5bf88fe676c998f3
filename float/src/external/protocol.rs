//! The protocol's line forms: the input line written per sample, the answer line read back.
use super::*;

/// Appends `x` in the protocol's form: shortest round-trip decimal, valid JSON for finite `x`.
pub(super) fn push_number(s: &mut String, x: f64) {
    if x.is_nan() {
        s.push_str("NaN");
    } else if x.is_infinite() {
        s.push_str(if x > 0.0 { "Infinity" } else { "-Infinity" });
    } else {
        // `{:?}` of a finite f64 is the shortest decimal that reads back as the same double,
        // always with a digit before any `.` and an optional `e` exponent: JSON's number grammar.
        let _ = write!(s, "{x:?}");
    }
}

/// The line written to the program for the inputs `xs`: a JSON array and a newline.
pub fn input_line(xs: &[f64]) -> String {
    let mut s = String::with_capacity(2 + 24 * xs.len());
    push_line(&mut s, xs);
    s
}

pub(super) fn push_line(s: &mut String, xs: &[f64]) {
    s.push('[');
    for (i, &x) in xs.iter().enumerate() {
        if i > 0 {
            s.push_str(", ");
        }
        push_number(s, x);
    }
    s.push_str("]\n");
}

/// Reads one answer line: an optional `[` ... `]` around numbers separated by white space and/or
/// commas. Special values (`nan`, `inf`, `Infinity`, ... in any case, with a sign) are accepted.
///
/// # Errors
/// A short reason when the line is not of that form (an unmatched bracket, a token that is not
/// a number).
pub fn parse_answer(line: &str) -> Result<Vec<f64>, String> {
    let mut body = line.trim();
    if let Some(rest) = body.strip_prefix('[') {
        body = rest
            .trim_end()
            .strip_suffix(']')
            .ok_or_else(|| "'[' without a closing ']'".to_string())?;
    } else if body.ends_with(']') {
        return Err("']' without an opening '['".into());
    }
    body.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| {
            // Rust's float parser reads decimal and exponent forms, `inf`, `infinity` and `nan`
            // in any case with an optional sign; nothing else (no hex, no `_`).
            t.parse::<f64>()
                .map_err(|_| format!("{} is not a number", quote(t)))
        })
        .collect()
}
