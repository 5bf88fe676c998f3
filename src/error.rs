//! The tool's error type: every variant is one line naming what is wrong.

/// An error the user can cause (bad input, impossible request). The CLI prints it as one line and
/// exits with status 2 (a broken pipe on standard output ends the run quietly with status 0).
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// An argument value is out of range or inconsistent.
    #[error("{}", one_line(.0))]
    Usage(String),
    /// A problem file or expression is malformed or describes degenerate input; the message
    /// names the field or position.
    #[error("{}", one_line(.0))]
    Input(String),
    /// Reading a file failed.
    #[error("cannot read {}: {source}", one_line(.path))]
    Io {
        /// The path (or `-` for standard input).
        path: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A size, depth or count went past a named limit of [`exactcheck_core::limits`]; the
    /// message names the limit, its value and the flag that raises it (and may quote a file
    /// name, escaped like every other quoted input).
    #[error("{}", one_line(&.0.to_string()))]
    Limit(#[from] exactcheck_core::limits::LimitError),
    /// Writing standard output failed (see [`crate::output`]).
    #[error("cannot write standard output: {}", io_message(.0))]
    Output(std::io::Error),
    /// Writing an output file failed (see [`crate::output::write_file`]); the file that was
    /// there before is left as it was.
    #[error("cannot write {}: {}", one_line(.path), io_message(.source))]
    Write {
        /// The output path as the user gave it.
        path: String,
        /// The underlying error.
        source: std::io::Error,
    },
}

impl Error {
    /// Whether this is a write to a closed pipe (the reader went away, as `head` does): the CLI
    /// then ends quietly with exit status 0.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, Error::Output(e) if e.kind() == std::io::ErrorKind::BrokenPipe)
    }
}

/// `text` with its line breaks (control characters, U+2028, U+2029) escaped (`\n`, `\u{1b}`): messages
/// quote what the user wrote (a JSON key, a file name), which may contain any character, and an
/// error stays one line.
fn one_line(text: &str) -> std::borrow::Cow<'_, str> {
    let long = text
        .split(' ')
        .any(|w| w.chars().count() > MAX_ECHOED_CHARS);
    if !long && !text.chars().any(is_break) {
        return text.into();
    }
    escape_breaks(text)
        .split(' ')
        .map(shorten_word)
        .collect::<Vec<_>>()
        .join(" ")
        .into()
}

/// Whether `c` would break a line of output: a control character, U+2028 or U+2029.
fn is_break(c: char) -> bool {
    c.is_control() || c == '\u{2028}' || c == '\u{2029}'
}

/// `text` with every character that would break a line (`is_break`) escaped as Rust does
/// (`\n`, `\u{1b}`): the one escaping of user-supplied names shown in errors, tables and
/// report headings.
pub fn escape_breaks(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.chars().any(is_break) {
        return text.into();
    }
    text.chars()
        .map(|c| {
            if is_break(c) {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect::<String>()
        .into()
}

/// The longest word of an error message shown in full: an input echoed in a message (a
/// 200,000-character expression, a 30,000-digit number) is shortened to its two ends.
const MAX_ECHOED_CHARS: usize = 120;

/// `word` itself, or its first 60 and last 20 characters around `...` with its length.
fn shorten_word(word: &str) -> std::borrow::Cow<'_, str> {
    let n = word.chars().count();
    if n <= MAX_ECHOED_CHARS {
        return word.into();
    }
    let head: String = word.chars().take(60).collect();
    let tail: String = word.chars().skip(n - 20).collect();
    format!("{head}...{tail} [{n} characters]").into()
}

/// The operating system's message without the " (os error N)" suffix.
fn io_message(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.rfind(" (os error ") {
        Some(i) if s.ends_with(')') => s[..i].to_string(),
        _ => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_echoed_input_is_shortened_to_its_ends() {
        let deep = format!("\"{}1{}\"", "(".repeat(200_000), ")".repeat(200_000));
        let e = Error::Input(format!("normal[2]: {deep}: at 257: too deep"));
        let shown = e.to_string();
        assert!(shown.len() < 200, "{shown}");
        assert!(shown.starts_with("normal[2]: \"((((("), "{shown}");
        assert!(
            shown.ends_with("))))\": [400004 characters] at 257: too deep"),
            "{shown}"
        );
        let short = Error::Input("x: \"1/2\" is fine".into());
        assert_eq!(short.to_string(), "x: \"1/2\" is fine");
    }
}
