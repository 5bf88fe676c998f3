//! The tool's error type: every variant is one line naming what is wrong.

/// An error the user can cause (bad input, impossible request). The CLI prints it as one line and
/// exits with status 2.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// An argument value is out of range or inconsistent.
    #[error("{0}")]
    Usage(String),
}
