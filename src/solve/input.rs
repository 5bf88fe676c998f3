//! Reading a problem: the input file (the one reader of every command's input files), the
//! problem's envelope (JSON syntax, nesting depth, the `"kind"`, the radicands of all its exact
//! numbers together, the values that leave the radical field), and its typed input.
//!
//! The envelope is read once into a [`Value`] ([`Problem::read`]). The typed input is read from
//! the text itself, not from that value: a [`Value`] forgets a repeated field (the last one
//! wins) and the line and column every error message ends with, and the number deserializers
//! decide by how a number was written. The depth of the text was bounded by the envelope's scan
//! ([`super::depth`]), so the typed read switches serde_json's own recursion limit off.

use super::depth;
use super::number;
use crate::Error;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// Reads an input file (`-` or none: standard input) as UTF-8 text, at most the `file-size`
/// limit of bytes: the one reader of every command's input files.
///
/// # Errors
/// [`Error::Io`] when the file cannot be read or is not UTF-8; [`Error::Limit`] when it is
/// larger than the `file-size` limit (read no further than the limit).
pub fn read_problem(path: Option<&str>) -> Result<String, Error> {
    use std::io::Read;
    let limit = &crate::limits::FILE_SIZE;
    let shown = path.unwrap_or("-");
    let io = |source| Error::Io {
        path: shown.into(),
        source,
    };
    let reader: Box<dyn Read> = match path {
        None | Some("-") => Box::new(std::io::stdin()),
        Some(p) => Box::new(std::fs::File::open(p).map_err(io)?),
    };
    let mut bytes = Vec::new();
    reader
        .take(limit.get().saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit.get() {
        return Err(Error::Limit(
            limit.exceeded(format!("{shown}: more than {} bytes", limit.get())),
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        io(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "not UTF-8 (invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            ),
        ))
    })
}

/// The text without a leading UTF-8 byte-order mark.
fn without_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// The problem as a JSON value (within the `depth` limit) and its `"kind"`.
///
/// # Errors
/// As [`problem_kind`].
fn envelope(text: &str) -> Result<(Value, String), Error> {
    let v: Value = depth::parse_json(text)
        .map_err(|(_, e)| Error::Limit(e))?
        .map_err(|e| Error::Input(format!("malformed JSON: {e}")))?;
    let kind = v
        .as_object()
        .ok_or_else(|| Error::Input("the problem must be a JSON object".into()))?
        .get("kind")
        .ok_or_else(|| Error::Input("missing field \"kind\"".into()))?
        .as_str()
        .ok_or_else(|| Error::Input("\"kind\" must be a string".into()))?
        .to_string();
    Ok((v, kind))
}

/// The problem's `"kind"`.
///
/// # Errors
/// [`Error::Input`] for malformed JSON, a non-object, a missing or non-string kind;
/// [`Error::Limit`] of `depth` for arrays and objects nested deeper than the limit.
pub fn problem_kind(text: &str) -> Result<String, Error> {
    envelope(without_bom(text)).map(|(_, kind)| kind)
}

/// The strings of a JSON value, in document order.
fn strings<'a>(v: &'a Value, out: &mut Vec<&'a str>) {
    match v {
        Value::String(s) => out.push(s),
        Value::Array(items) => items.iter().for_each(|x| strings(x, out)),
        Value::Object(map) => map.values().for_each(|x| strings(x, out)),
        _ => {}
    }
}

/// The scan of the exact numbers of a problem together: the `radicands` limit on its radicals
/// (each may be within it while the field the answer is computed in, spanned by all of them, is
/// not), and, when a value leaves the radical field (`"cos(pi/8)"`), the values of all its
/// number strings as real algebraic numbers with the strings, from which the problem's number
/// field is built (and named).
/// Strings that do not parse are left to the typed read, which names their field.
///
/// # Errors
/// [`Error::Limit`] of `radicands`, or of `algebraic-degree` for a value past it.
fn scan_numbers(v: &Value) -> Result<Option<Vec<(exactcheck_exact::Algebraic, String)>>, Error> {
    let mut texts = Vec::new();
    strings(v, &mut texts);
    let mut radicals = Vec::new();
    let mut leaves = false;
    for s in &texts {
        match number::parse_radical(s) {
            Ok(r) => radicals.push(r),
            Err(_) => match number::parse_algebraic(s) {
                Ok(_) => leaves = true,
                // A value past the degree limit refuses the problem here; every other refusal
                // (another limit, bad syntax) is left to the typed read, which names the field.
                Err(number::AlgebraicRefusal::Limit(m, limit))
                    if std::ptr::eq(limit.limit, &exactcheck_core::limits::ALGEBRAIC_DEGREE) =>
                {
                    return Err(Error::Input(m))
                }
                Err(_) => {}
            },
        }
    }
    exactcheck_exact::Radical::check_radicands_together(&radicals).map_err(Error::Limit)?;
    if !leaves {
        return Ok(None);
    }
    Ok(Some(irrational_strings(&texts)))
}

/// The irrational values of the number strings `texts` (those that parse), with their strings.
fn irrational_strings(texts: &[&str]) -> Vec<(exactcheck_exact::Algebraic, String)> {
    texts
        .iter()
        .filter_map(|s| {
            number::parse_algebraic(s)
                .ok()
                .map(|a| (a, s.trim().to_string()))
        })
        .filter(|(a, _)| !a.is_rational())
        .collect()
}

/// A problem whose envelope was read and checked: valid JSON within the `depth` limit, an
/// object with a string `"kind"`, its exact numbers within the `radicands` limit together.
pub struct Problem<'a> {
    /// The text, without a byte-order mark.
    text: &'a str,
    kind: String,
    /// The irrational values of the number strings, when one of them leaves the radical field
    /// (the problem is then computed in the number field they generate).
    algebraic: Option<Vec<exactcheck_exact::Algebraic>>,
    /// The strings of those values, in the same order: the names the field's elements are
    /// printed in ([`super::field::ProblemField::build`]).
    names: Vec<String>,
}

impl<'a> Problem<'a> {
    /// Reads the envelope of a problem (a leading byte-order mark is skipped).
    ///
    /// # Errors
    /// As [`problem_kind`], then [`Error::Limit`] of `radicands`.
    pub fn read(text: &'a str) -> Result<Problem<'a>, Error> {
        let text = without_bom(text);
        let (value, kind) = envelope(text)?;
        let (algebraic, names) = match scan_numbers(&value)? {
            None => (None, Vec::new()),
            Some(found) => {
                let (values, names) = found.into_iter().unzip();
                (Some(values), names)
            }
        };
        Ok(Problem {
            text,
            kind,
            algebraic,
            names,
        })
    }

    /// The problem's `"kind"`.
    pub fn kind(&self) -> &str {
        &self.kind
    }

    /// The irrational values of the problem's number strings when one of them leaves the radical
    /// field, `None` otherwise.
    pub(crate) fn algebraic_values(&self) -> Option<&[exactcheck_exact::Algebraic]> {
        self.algebraic.as_deref()
    }

    /// The irrational values of the problem's number strings (radicals included), with their
    /// strings.
    ///
    /// # Errors
    /// None in practice: the text was read as JSON by [`Problem::read`].
    pub(crate) fn irrational_values(
        &self,
    ) -> Result<Vec<(exactcheck_exact::Algebraic, String)>, Error> {
        let (value, _) = envelope(self.text)?;
        let mut texts = Vec::new();
        strings(&value, &mut texts);
        Ok(irrational_strings(&texts))
    }

    /// The problem read into an input type whose numbers are [`super::number::FieldNumber`]s:
    /// the number field of the problem's algebraic values and of `constants` (those a kind
    /// computes with, such as `sqrt(2)`) is built first ([`super::field::ProblemField`]).
    ///
    /// # Errors
    /// As [`Problem::input`]; [`Error::Limit`] of `algebraic-degree` when the field's degree is
    /// past it.
    pub(crate) fn input_in_field<T: DeserializeOwned>(
        &self,
        constants: &[&str],
    ) -> Result<T, Error> {
        let extras: Vec<exactcheck_exact::Algebraic> = constants
            .iter()
            .map(|c| {
                c.parse()
                    .expect("a kind's field constants are constant formulas")
            })
            .collect();
        let (values, names) = match &self.algebraic {
            Some(values) => (values.clone(), self.names.clone()),
            None => self.irrational_values()?.into_iter().unzip(),
        };
        let field =
            std::sync::Arc::new(super::field::ProblemField::build(&values, &names, &extras)?);
        super::field::read_in(&field, || typed(self.text))
    }

    /// The problem read into an input type; every error is one line naming the field path.
    ///
    /// # Errors
    /// As [`parse`] (the depth was checked by [`Problem::read`]).
    pub fn input<T: DeserializeOwned>(&self) -> Result<T, Error> {
        typed(self.text)
    }
}

/// Reads a problem into its input type; every error is one line naming the field path.
///
/// # Errors
/// [`Error::Limit`] of `depth` for arrays and objects nested deeper than the limit.
/// [`Error::Input`]: `malformed JSON: ...` for syntax errors, `PATH: ...` for everything the
/// types refuse (unknown or repeated fields, wrong types, bad numbers).
pub fn parse<T: DeserializeOwned>(text: &str) -> Result<T, Error> {
    let text = without_bom(text);
    depth::check_json(text).map_err(|(_, e)| Error::Limit(e))?;
    typed(text)
}

/// The typed read of a text whose depth is within the `depth` limit.
fn typed<T: DeserializeOwned>(text: &str) -> Result<T, Error> {
    let mut de = serde_json::Deserializer::from_str(text);
    // The depth was bounded by the scan of module `depth`.
    de.disable_recursion_limit();
    let value: T = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        if inner.is_syntax() || inner.is_eof() {
            Error::Input(format!("malformed JSON: {inner}"))
        } else if path == "." {
            Error::Input(inner.to_string())
        } else {
            Error::Input(format!("{path}: {inner}"))
        }
    })?;
    de.end()
        .map_err(|e| Error::Input(format!("malformed JSON: {e}")))?;
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_envelope_is_checked_in_order_and_the_typed_read_names_the_field() {
        let err = |text: &str| Problem::read(text).err().map(|e| e.to_string());
        assert!(err("[1]").unwrap().contains("must be a JSON object"));
        assert!(err("{}").unwrap().contains("missing field \"kind\""));
        assert!(err(r#"{"kind": 1}"#).unwrap().contains("must be a string"));
        assert!(err(r#"{"kind": "x""#).unwrap().contains("malformed JSON"));
        let p = Problem::read("\u{feff}{\"kind\": \"x\", \"n\": 3}").expect("an envelope");
        assert_eq!(p.kind(), "x");
        #[derive(serde::Deserialize, Debug)]
        #[serde(deny_unknown_fields)]
        #[allow(dead_code)]
        struct In {
            kind: String,
            n: u8,
        }
        assert_eq!(p.input::<In>().expect("typed").n, 3);
        let bad = Problem::read(r#"{"kind": "x", "n": "three"}"#).expect("an envelope");
        let e = bad.input::<In>().unwrap_err().to_string();
        assert!(e.contains("n: invalid type: string \"three\""), "{e}");
        assert!(e.ends_with("at line 1 column 26"), "{e}");
        // A repeated field is refused by the typed read (a JSON value keeps the last one).
        let twice = Problem::read(r#"{"kind": "x", "n": 1, "n": 2}"#).expect("an envelope");
        let e = twice.input::<In>().unwrap_err().to_string();
        assert!(e.contains("duplicate field `n`"), "{e}");
    }
}
