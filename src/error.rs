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
    /// message names the limit, its value and the flag that raises it.
    #[error("{0}")]
    Limit(#[from] exactcheck_core::limits::LimitError),
    /// Writing standard output failed (see [`crate::output`]).
    #[error("cannot write standard output: {}", io_message(.0))]
    Output(std::io::Error),
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
    let breaks = |c: char| c.is_control() || c == '\u{2028}' || c == '\u{2029}';
    if text.chars().any(breaks) {
        text.chars()
            .map(|c| {
                if breaks(c) {
                    c.escape_default().to_string()
                } else {
                    c.to_string()
                }
            })
            .collect::<String>()
            .into()
    } else {
        text.into()
    }
}

/// The operating system's message without the " (os error N)" suffix.
fn io_message(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.rfind(" (os error ") {
        Some(i) if s.ends_with(')') => s[..i].to_string(),
        _ => s,
    }
}
