//! The tool's error type: every variant is one line naming what is wrong.

/// An error the user can cause (bad input, impossible request). The CLI prints it as one line and
/// exits with status 2.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// An argument value is out of range or inconsistent.
    #[error("{0}")]
    Usage(String),
    /// A problem file or expression is malformed or describes degenerate input; the message
    /// names the field or position.
    #[error("{0}")]
    Input(String),
    /// Reading a file failed.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The path (or `-` for standard input).
        path: String,
        /// The underlying error.
        source: std::io::Error,
    },
}
