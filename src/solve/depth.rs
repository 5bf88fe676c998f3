//! The nesting depth of a JSON or TOML document, measured before it is parsed.
//!
//! `serde_json` and `toml` parse recursively: a document of a million `[` would overflow the
//! stack of a recursive reader (serde_json stops at its own fixed 128 levels with "recursion
//! limit exceeded", which names no limit). So every document is first scanned once, iteratively,
//! counting the open arrays and objects (`[`/`{` against `]`/`}`) outside strings and comments,
//! and refused past the `depth` limit with the byte offset where it was exceeded; the readers
//! then parse with serde_json's own recursion limit switched off (the scan has bounded the
//! depth). The scan does not validate anything else: a malformed document within the limit is
//! left to the parser's message.
//!
//! Hand-written because neither parser exposes a depth bound one can set.

use exactcheck_core::limits::{self, LimitError};

/// Checks the nesting depth of a JSON text against the `depth` limit.
///
/// # Errors
/// The byte offset of the bracket past the limit, and the [`LimitError`].
pub fn check_json(text: &str) -> Result<(), (usize, LimitError)> {
    let bytes = text.as_bytes();
    let mut meter = Meter::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => i = skip_string(bytes, i + 1, b"\"", true),
            b => {
                meter.bracket(b, i)?;
                i += 1;
            }
        }
    }
    Ok(())
}

/// Parses a JSON text (one value, nothing after it) within the `depth` limit: [`check_json`]
/// first, then serde_json with its own fixed recursion limit off (the scan has bounded it).
///
/// # Errors
/// The depth check's error (outer), or serde_json's (inner).
#[allow(clippy::type_complexity)]
pub fn parse_json<T: serde::de::DeserializeOwned>(
    text: &str,
) -> Result<Result<T, serde_json::Error>, (usize, LimitError)> {
    check_json(text)?;
    let mut de = serde_json::Deserializer::from_str(text);
    de.disable_recursion_limit();
    Ok(T::deserialize(&mut de).and_then(|v| de.end().map(|()| v)))
}

/// Checks the nesting depth of a TOML text (arrays, inline tables) against the `depth` limit;
/// basic, literal and multi-line strings and comments are skipped.
///
/// # Errors
/// The byte offset of the bracket past the limit, and the [`LimitError`].
pub fn check_toml(text: &str) -> Result<(), (usize, LimitError)> {
    let bytes = text.as_bytes();
    let mut meter = Meter::new();
    let mut i = 0;
    while i < bytes.len() {
        let rest = &bytes[i..];
        if rest.starts_with(b"\"\"\"") {
            i = skip_string(bytes, i + 3, b"\"\"\"", true);
        } else if rest.starts_with(b"'''") {
            i = skip_string(bytes, i + 3, b"'''", false);
        } else if rest[0] == b'"' {
            i = skip_string(bytes, i + 1, b"\"", true);
        } else if rest[0] == b'\'' {
            i = skip_string(bytes, i + 1, b"'", false);
        } else if rest[0] == b'#' {
            i = bytes[i..]
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len(), |k| i + k + 1);
        } else {
            meter.bracket(rest[0], i)?;
            i += 1;
        }
    }
    Ok(())
}

/// The index just past the string that starts before `i` and ends with `close` (`escapes`:
/// a backslash escapes the next byte); the end of the text for an unterminated string.
fn skip_string(bytes: &[u8], mut i: usize, close: &[u8], escapes: bool) -> usize {
    while i < bytes.len() {
        if escapes && bytes[i] == b'\\' {
            i += 2;
        } else if bytes[i..].starts_with(close) {
            return i + close.len();
        } else {
            i += 1;
        }
    }
    bytes.len()
}

/// The current depth and the limit in force.
struct Meter {
    depth: u64,
    max: u64,
}

impl Meter {
    fn new() -> Meter {
        Meter {
            depth: 0,
            max: limits::DEPTH.get(),
        }
    }

    fn bracket(&mut self, b: u8, at: usize) -> Result<(), (usize, LimitError)> {
        match b {
            b'[' | b'{' => {
                self.depth += 1;
                if self.depth > self.max {
                    return Err((
                        at,
                        limits::DEPTH.exceeded(format!(
                            "more than {} levels of arrays and objects at byte {at}",
                            self.max
                        )),
                    ));
                }
            }
            b']' | b'}' => self.depth = self.depth.saturating_sub(1),
            _ => {}
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_brackets_outside_strings_and_comments() {
        let max = limits::DEPTH.get() as usize;
        let deep = |n: usize| format!("{}{}", "[".repeat(n), "]".repeat(n));
        assert!(check_json(&deep(max)).is_ok());
        let (at, e) = check_json(&deep(max + 1)).unwrap_err();
        assert_eq!(at, max);
        assert!(e.to_string().contains("the limit depth ="), "{e}");
        // Brackets inside strings (with an escaped quote) do not count.
        let s = format!("{{\"k\": \"\\\" {} \"}}", "[".repeat(max + 5));
        assert!(check_json(&s).is_ok());
        // TOML: strings of every kind and comments are skipped; arrays count.
        let t = format!(
            "a = \"{0}\"\nb = '{0}'\nc = \"\"\"{0}\"\"\"\nd = '''{0}'''\n# {0}\n[x]\ne = {1}\n",
            "[".repeat(max + 5),
            deep(max)
        );
        assert!(check_toml(&t).is_ok());
        assert!(check_toml(&format!("e = {}\n", deep(max + 1))).is_err());
        // A million brackets: one error, no recursion.
        assert!(check_json(&"[".repeat(1_000_000)).is_err());
        assert!(check_toml(&format!("a = {}", "[".repeat(1_000_000))).is_err());
    }
}
