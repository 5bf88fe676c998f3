//! A unit's embedded claims file: the claims that state the paper's printed formulas (an
//! identity of printed formulas, a printed value against its exact value, a worked example's
//! printed numbers) in the claims-file format, compiled into the binary (`include_str!`) and
//! decided by the claims-file engine ([`crate::claimfile`]) as `verify FILE` decides them. The
//! unit's list of claims names each by its id (`Check::Printed`), in the order of the papers'
//! claim list, next to the claims its Rust code computes; the registry ([`super::Paper`]) gives
//! them their statement and expected verdict from the file and decides them here. It lives with
//! the registry, above both the claims and the claims-file engine, which never refer to each
//! other.
//!
//! The file is parsed once per process, on first use; a file that does not parse or lacks an
//! id makes the claims that need it errors naming the file (a test parses every unit's file).

use crate::claimfile::{self, ClaimsFile, FileClaim, Run};
use crate::claims::Verdict;
use std::sync::OnceLock;

/// A claims file compiled into the binary.
pub struct Embedded {
    /// Its path in the repository (named in messages).
    pub path: &'static str,
    /// Its text.
    pub text: &'static str,
    parsed: OnceLock<Result<ClaimsFile, String>>,
}

impl Embedded {
    /// The file at `path` with the text `text`.
    pub const fn new(path: &'static str, text: &'static str) -> Self {
        Embedded {
            path,
            text,
            parsed: OnceLock::new(),
        }
    }

    /// The parsed file, or why it does not parse.
    ///
    /// # Errors
    /// The parser's one-line message.
    pub fn file(&'static self) -> Result<&'static ClaimsFile, &'static str> {
        self.parsed
            .get_or_init(|| {
                claimfile::parse(self.text, self.path, "claims").map_err(|e| e.to_string())
            })
            .as_ref()
            .map_err(String::as_str)
    }

    fn find(&'static self, id: &str) -> Result<&'static FileClaim, String> {
        let file = self.file().map_err(str::to_string)?;
        file.claims
            .iter()
            .find(|c| c.id == id)
            .ok_or_else(|| format!("{}: no claim {id:?}", self.path))
    }

    /// The statement and the expected verdict of the claim `id` as the file gives them (empty
    /// and `proved` when the file lacks it: deciding it then says so).
    pub fn statement_and_expected(&'static self, id: &str) -> (&'static str, Verdict) {
        match self.find(id) {
            Ok(c) => (c.statement.as_str(), c.expected_before()),
            Err(_) => ("", Verdict::Proved),
        }
    }

    /// Decides the claim `id` of this file.
    pub fn decide(&'static self, id: &str) -> Run {
        self.find(id)
            .map_err(|m| (m, false))
            .and_then(|c| c.decide(self.path))
    }
}
