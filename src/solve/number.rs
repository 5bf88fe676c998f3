//! Numbers of the `solve` contract, read exactly.
//!
//! A number in a problem is a JSON integer (of any size: the workspace enables serde_json's
//! `arbitrary_precision`, so the digits arrive as written and are parsed exactly, never through
//! `i64`/`f64`), or a string in the exact syntax: a constant formula of the one expression
//! language, resolved by its function library and evaluated exactly (`parse_radical`; `"-3/4"`,
//! `"0.1"` = 1/10, `"1/sqrt(2)"`, `"2^-10"`, `"binomial(5, 2)/3"`, `"det([[1, 2], [3, 4]])"`). A JSON floating-point
//! literal (`0.1`, `1e+23`) is refused in exact mode, because JSON gives it no exact meaning
//! most readers agree on; the message suggests the string that means the written decimal
//! exactly (built from the literal's own digits, so it parses).
//!
//! The deserializers are hand-written (`Deserialize` impls reading one [`serde_json::Value`])
//! because the decision depends on *how* the number was written (integer token, floating token,
//! string), which serde's typed visitors forget; each error they raise is one line, and the
//! caller's `serde_path_to_error` puts the field path in front of it.
//!
//! * [`ExactNumber`]: any exact number (radical field).
//! * [`RationalNumber`]: an exact rational (irrational input is refused).
//! * [`RationalOrFieldNumber`]: the exact numbers of a kind computed over Q when its problem's
//!   values are all rational and in their number field otherwise (`Kind::RATIONAL_OR_FIELD`):
//!   read as [`RationalNumber`] (the driver sends a problem with an irrational value to the
//!   field path, which reads [`FieldNumber`]), described in the schema as what it accepts.
//! * [`FieldNumber`]: any exact number of a problem whose values leave the radical field
//!   (`"cos(pi/8)"`, `"cos(2*pi/7)"`), as an element of the problem's number field
//!   (the module `solve::field`).
//! * [`FloatNumber`]: `--float` input: integers, floating literals and exact strings, converted
//!   to the nearest `f64`; non-finite results (`"10^400"`, `1e400`) are refused.
//!
//! Every JSON number literal is checked against the `digits` limit before it is converted (the
//! digits of an integer, of a floating literal's mantissa); strings are checked by the
//! expression parser.
//!
//! * [`Radians`]: an angle in radians (approximate by nature: floating literals are accepted in
//!   every mode), finite.

use exactcheck_core::OrderedField;
use exactcheck_exact::algebraic::FieldElement;
use exactcheck_exact::expr::library::{self, Val};
use exactcheck_exact::{Algebraic, Radical, Rational};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::{Deserialize, Deserializer, Error as _};
use serde_json::Value;
use std::borrow::Cow;

/// The `JsonSchema` of a number type: named after the type, a JSON `integer` (exact types) or
/// any JSON `number` (approximate ones), or a string, with the description given.
macro_rules! number_schema {
    ($ty:ident, $json:literal, $description:expr) => {
        impl JsonSchema for $ty {
            fn schema_name() -> Cow<'static, str> {
                stringify!($ty).into()
            }

            fn json_schema(_: &mut SchemaGenerator) -> Schema {
                let description: String = $description;
                json_schema!({
                    "description": description,
                    "anyOf": [{"type": $json}, {"type": "string"}]
                })
            }
        }
    };
}

/// How a number was written in the problem.
enum Written {
    /// A JSON integer token, its digits as written.
    Integer(String),
    /// A JSON floating-point token (with `.`, `e` or `E`), as written.
    Float(String),
    /// A JSON string.
    Text(String),
}

/// The number strings of the contract, in one sentence: every schema description of a number
/// field is built from it, so that the schemas state the language the parser reads.
pub(crate) const EXACT_STRING: &str = "a string in the exact expression language of prove: integers, fractions \"-3/4\", decimals \"0.1\" (exactly 1/10) and \"2.5e-3\", + - * / ^ and parentheses, sqrt with nested radicals that denest (\"1/sqrt(2)\", \"sqrt(3 + 2*sqrt(2))\"), sin, cos and tan of rational multiples of pi or of angles in degrees (\"cos(pi/6)\", \"sin(45°)\"), and the library functions (binomial, factorial, sum, integrate, diff, det, dot, cross, norm2, ...), whose value is a real algebraic number (values outside the square-root field, such as \"cos(pi/8)\" or \"cos(2*pi/7)\", are computed in a number field built for the problem)";

/// What a number field expects, for type errors.
const EXPECTED: &str =
    "a number: a JSON integer or a string in the exact syntax such as \"-3/4\" or \"sqrt(2)/2\"";

fn written<'de, D: Deserializer<'de>>(d: D) -> Result<Written, D::Error> {
    match Value::deserialize(d)? {
        Value::Number(n) => {
            let t = n.to_string();
            // The digits as written (serde_json's arbitrary_precision keeps them), counted
            // before any conversion: a float literal's mantissa, an integer's every digit.
            let mantissa = t.split(['e', 'E']).next().unwrap_or("");
            let digits = mantissa.bytes().filter(u8::is_ascii_digit).count();
            exactcheck_core::limits::DIGITS
                .check_usize(digits)
                .map_err(D::Error::custom)?;
            Ok(if t.contains(['.', 'e', 'E']) {
                Written::Float(t)
            } else {
                Written::Integer(t)
            })
        }
        Value::String(s) => Ok(Written::Text(s)),
        other => Err(D::Error::custom(format!(
            "expected {EXPECTED}, found {}",
            kind_of(&other)
        ))),
    }
}

fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The exact value of a number string: a constant formula of the one expression language
/// (the library's `det`, `dot`, `norm2`, ... included, so `"det([[1, 2], [3, 4]])"` and
/// `"binomial(5, 2)/3"` are numbers), resolved by [`library::resolve`] and evaluated in the
/// radical field; a `diff`, `integrate` or `sum` with a variable of its own inside
/// (`"integrate(t^2, t, 0, 1)"`) is lowered to arithmetic first
/// ([`eval_lowered`](exactcheck_exact::expr::eval_lowered)). A vector or matrix, or a formula with a variable, is a one-line error (the
/// caller puts the field's path in front of it).
pub(crate) fn parse_radical(text: &str) -> Result<Radical, String> {
    let quoted = |m: String| format!("{text:?}: {m}");
    match library::resolve(text).map_err(|e| quoted(e.to_string()))? {
        Val::Scalar(e) => exactcheck_exact::expr::eval_lowered::<Radical>(&e)
            .map_err(|err| quoted(Radical::refusal(&e, err).to_string())),
        v => Err(quoted(format!("{} where a number is expected", v.shape()))),
    }
}

/// Why a number string has no real algebraic value.
#[derive(Debug)]
pub(crate) enum AlgebraicRefusal {
    /// A value past a named limit (the degree of `"cos(2*pi/1009)"` past `algebraic-degree`):
    /// the message, naming the string and the limit, and the limit's own error.
    Limit(String, exactcheck_core::limits::LimitError),
    /// Anything else (not a constant, bad syntax), in one line.
    Other(String),
}

/// The exact value of a number string as a real algebraic number (the same reading as
/// [`parse_radical`], in the field of all real algebraic numbers): used for the values that
/// leave the radical field.
pub(crate) fn parse_algebraic(text: &str) -> Result<Algebraic, AlgebraicRefusal> {
    let other = |m: String| AlgebraicRefusal::Other(format!("{text:?}: {m}"));
    match library::resolve(text).map_err(|e| other(e.to_string()))? {
        Val::Scalar(e) => {
            exactcheck_exact::expr::eval_lowered::<Algebraic>(&e).map_err(|err| match err.limit() {
                Some(limit) => AlgebraicRefusal::Limit(format!("{text:?}: {err}"), limit.clone()),
                None => other(err.to_string()),
            })
        }
        v => Err(other(format!("{} where a number is expected", v.shape()))),
    }
}

/// The exact value of a JSON floating-point literal, written in the exact string syntax: a plain
/// decimal for moderate exponents (`2.5e-3` -> `0.0025`, `1e+23` -> `100000000000000000000000`),
/// `digits*10^k` or `digits/10^k` beyond, nested powers past the parser's exponent limit of 1024.
/// `None` only for exponents beyond about a million, which the syntax cannot write.
pub fn exact_decimal(literal: &str) -> Option<String> {
    let (sign, body) = match literal.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", literal),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], body[i + 1..].parse::<i64>().ok()?),
        None => (body, 0),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let mut digits = format!("{int_part}{frac_part}");
    let k = exponent.checked_sub(i64::try_from(frac_part.len()).ok()?)?;
    let trimmed = digits.trim_start_matches('0');
    if trimmed.is_empty() {
        return Some("0".into());
    }
    digits = trimmed.to_string();
    let len = i64::try_from(digits.len()).ok()?;
    let text = if (0..=30).contains(&k) {
        format!("{digits}{}", "0".repeat(k as usize))
    } else if (-30..0).contains(&k) {
        if len > -k {
            let cut = (len + k) as usize;
            format!("{}.{}", &digits[..cut], &digits[cut..])
        } else {
            format!("0.{}{digits}", "0".repeat((-k - len) as usize))
        }
    } else {
        let (op, e) = if k > 0 { ('*', k) } else { ('/', -k) };
        let power = if e <= 1024 {
            format!("10^{e}")
        } else if e / 1024 <= 1024 {
            format!("((10^1024)^{}*10^{})", e / 1024, e % 1024)
        } else {
            return None;
        };
        format!("{digits}{op}{power}")
    };
    Some(format!("{sign}{text}"))
}

fn float_refused(literal: &str) -> String {
    match exact_decimal(literal) {
        Some(s) => format!(
            "{literal} is a JSON floating-point literal, which exact mode refuses; write the exact value as a string, \"{s}\", or use --float"
        ),
        None => format!(
            "{literal} is a JSON floating-point literal, which exact mode refuses, and its exponent is beyond what the exact syntax can write; use --float"
        ),
    }
}

/// Checks a `precision` (positive) against the `precision-bits` limit: `w >= 2^-bits`.
///
/// # Errors
/// [`Error::Limit`] of `precision-bits` when a finer precision is asked.
pub(crate) fn check_precision<T: OrderedField>(w: &T) -> Result<(), crate::Error> {
    let limit = &crate::limits::PRECISION_BITS;
    let bits = limit.get();
    let cap = u32::try_from(bits).unwrap_or(u32::MAX);
    let two = T::one() + T::one();
    // w >= 2^-bits  <=>  w * 2^bits >= 1 (for f64, 2^bits may be +inf: every w passes, and
    // an f64 precision has at most 1074 bits anyway).
    if w.mul_ref(&two.pow(cap)) >= T::one() {
        // Refining a root isolated in an interval of width 1 (the unit interval of the
        // Bernstein kinds) to w takes at most log2(1/w) halvings: check the `bisection` limit
        // too, before any work (cylinder_sphere checks its own intervals' widths again).
        exactcheck_core::roots::halvings_within_limit(&T::one(), w).map_err(crate::Error::Limit)
    } else {
        Err(crate::Error::Limit(
            limit.exceeded(format!("a precision below 2^-{bits}")),
        ))
    }
}

/// An exact number of the problem (the radical field).
#[derive(Clone, Debug, PartialEq)]
pub struct ExactNumber(pub Radical);

impl<'de> Deserialize<'de> for ExactNumber {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match written(d)? {
            Written::Integer(t) | Written::Text(t) => {
                parse_radical(&t).map(ExactNumber).map_err(D::Error::custom)
            }
            Written::Float(t) => Err(D::Error::custom(float_refused(&t))),
        }
    }
}

number_schema!(
    ExactNumber,
    "integer",
    format!("An exact number: a JSON integer of any size, or {EXACT_STRING}. JSON floating-point literals are refused in exact mode (accepted with --float).")
);

/// An exact number of a problem whose values leave the radical field: its value as an element
/// of the problem's number field, built before the typed read (the module `solve::field`).
#[derive(Clone, Debug, PartialEq)]
pub struct FieldNumber(pub FieldElement);

impl<'de> Deserialize<'de> for FieldNumber {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match written(d)? {
            Written::Integer(t) | Written::Text(t) => {
                let value = parse_algebraic(&t).map_err(|e| match e {
                    AlgebraicRefusal::Limit(m, _) | AlgebraicRefusal::Other(m) => {
                        D::Error::custom(m)
                    }
                })?;
                super::field::current_element(&value)
                    .map(FieldNumber)
                    .map_err(D::Error::custom)
            }
            Written::Float(t) => Err(D::Error::custom(float_refused(&t))),
        }
    }
}

/// An exact rational number of the problem.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalNumber(pub Rational);

impl<'de> Deserialize<'de> for RationalNumber {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let ExactNumber(x) = ExactNumber::deserialize(d)?;
        x.to_rational().map(RationalNumber).ok_or_else(|| {
            D::Error::custom(format!(
                "{x} is irrational; this kind needs rational input in exact mode (angles as rational points {{cos, sin}} of the unit circle)"
            ))
        })
    }
}

number_schema!(
    RationalNumber,
    "integer",
    format!("An exact rational number: a JSON integer of any size, or {EXACT_STRING}; the value must be rational. JSON floating-point literals are refused in exact mode (accepted with --float).")
);

/// An exact number of a kind computed over Q when every value of its problem is rational and
/// in the problem's number field otherwise (`Kind::RATIONAL_OR_FIELD`). It is read as a
/// [`RationalNumber`]: a problem with an irrational value never reaches this type, the driver
/// reads it with [`FieldNumber`] instead; the schema says so, unlike [`RationalNumber`]'s.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalOrFieldNumber(pub Rational);

impl<'de> Deserialize<'de> for RationalOrFieldNumber {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        RationalNumber::deserialize(d).map(|RationalNumber(q)| RationalOrFieldNumber(q))
    }
}

number_schema!(
    RationalOrFieldNumber,
    "integer",
    format!("An exact number: a JSON integer of any size, or {EXACT_STRING}. A problem whose values are all rational is computed over Q; one with an irrational value (\"sqrt(2)/2\", \"cos(pi/8)\") in the number field of its values. JSON floating-point literals are refused in exact mode (accepted with --float).")
);

/// The nearest `f64` of a real algebraic number: the midpoint of an isolating interval narrowed
/// to a relative width of `2^-60` (an irrational number is not zero, so the interval separates
/// from 0).
fn algebraic_f64(a: &Algebraic) -> f64 {
    if let Some(q) = a.to_rational() {
        return q.to_f64();
    }
    let mut bits = 64;
    loop {
        let (lo, hi) = a.enclosure(bits);
        let scale = lo.abs().min(hi.abs());
        if lo.signum() == hi.signum()
            && (hi.clone() - &lo) * Rational::from_integer(1i64 << 60) <= scale
        {
            return ((lo + hi) * Rational::new(1, 2).expect("2 != 0")).to_f64();
        }
        bits *= 2;
    }
}

/// The nearest `f64` of a number written in any form; an error if it is not finite.
fn finite_f64(w: Written) -> Result<f64, String> {
    let (x, text) = match w {
        Written::Float(t) => (t.parse::<f64>().map_err(|e| format!("{t}: {e}"))?, t),
        Written::Integer(t) | Written::Text(t) => {
            let x = match parse_radical(&t) {
                Ok(r) => r.to_f64(),
                // A value outside the radical field (`"cos(2*pi/7)"`) is rounded from its
                // algebraic value; a string that is no number keeps the radical reading's error.
                Err(e) => algebraic_f64(&parse_algebraic(&t).map_err(|_| e)?),
            };
            (x, t)
        }
    };
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!(
            "{text} is not a finite f64 (f64 computation cannot represent it); use exact mode"
        ))
    }
}

/// A number of a `--float` problem, as the nearest finite `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatNumber(pub f64);

impl<'de> Deserialize<'de> for FloatNumber {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        finite_f64(written(d)?)
            .map(FloatNumber)
            .map_err(D::Error::custom)
    }
}

number_schema!(
    FloatNumber,
    "number",
    format!("A number for f64 computation: any JSON number, or {EXACT_STRING}; rounded to the nearest f64, which must be finite.")
);

/// An angle in radians (any JSON number or an exact string), finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radians(pub f64);

impl<'de> Deserialize<'de> for Radians {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        finite_f64(written(d)?)
            .map(Radians)
            .map_err(D::Error::custom)
    }
}

number_schema!(
    Radians,
    "number",
    format!("An angle in radians: any JSON number (floating literals accepted in every mode, since radians are approximate), or {EXACT_STRING}; it must be finite as an f64.")
);

/// A fixed number `N` of values of `T`: a JSON array whose wrong length is reported as
/// "expected N coordinates, found M".
#[derive(Clone, Debug, PartialEq)]
pub struct Coords<T, const N: usize>(pub [T; N]);

impl<'de, T: Deserialize<'de>, const N: usize> Deserialize<'de> for Coords<T, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Vec::<T>::deserialize(d)?;
        let found = v.len();
        <[T; N]>::try_from(v)
            .map(Coords)
            .map_err(|_| D::Error::custom(format!("expected {N} coordinates, found {found}")))
    }
}

impl<T: JsonSchema, const N: usize> JsonSchema for Coords<T, N> {
    fn schema_name() -> Cow<'static, str> {
        format!("Coords{N}_{}", T::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let item = generator.subschema_for::<T>();
        json_schema!({
            "type": "array",
            "items": item,
            "minItems": N,
            "maxItems": N
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn float_literal_suggestions_mean_the_written_decimal_and_parse() {
        for (literal, want) in [
            ("0.5", "0.5"),
            ("-2.5e-3", "-0.0025"),
            ("1e+23", "100000000000000000000000"),
            ("1E23", "100000000000000000000000"),
            ("12.50", "12.50"),
            ("0.0", "0"),
            ("3e-40", "3/10^40"),
            ("7e300", "7*10^300"),
            ("1e5000", "1*((10^1024)^4*10^904)"),
        ] {
            let s = exact_decimal(literal).expect("writable");
            assert_eq!(s, want, "{literal}");
            let value: Radical = s.parse().unwrap_or_else(|e| panic!("{s}: {e}"));
            if let Ok(x) = literal.parse::<f64>() {
                if x.is_finite() && x != 0.0 {
                    assert!((value.to_f64() - x).abs() <= 1e-12 * x.abs(), "{literal}");
                }
            }
        }
        assert_eq!(exact_decimal("1e99999999"), None);
    }

    #[test]
    fn number_strings_with_bound_variables_are_lowered_before_evaluation() {
        let q = |n: i64, d: i64| Radical::from(Rational::new(n, d).unwrap());
        for (text, want) in [
            ("integrate(t^2, t, 0, 1)", q(1, 3)),
            (
                "integrate(t^2, t, 0, sqrt(2))",
                Radical::sqrt_of(2) * q(2, 3),
            ),
            ("subs(diff(t^3, t), t, 2)", q(12, 1)),
            ("diff(t^3, t, 3)", q(6, 1)),
            ("sum(k, 1, 4, k^2)/binomial(5, 2)", q(3, 1)),
            ("integrate(diff(t^4, t), t, 0, 1/2)", q(1, 16)),
        ] {
            assert_eq!(parse_radical(text).unwrap(), want, "{text}");
        }
        // A derivative that keeps its variable is no number: the error names the variable.
        let e = parse_radical("diff(t^3, t)").unwrap_err();
        assert!(e.contains("variable 't'"), "{e}");
    }
}
