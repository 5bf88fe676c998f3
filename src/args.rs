//! Pieces several commands share: the choice of exact rational type and the range check of
//! counts given on the command line (each count has a documented maximum so that no command
//! allocates or loops in proportion to an unchecked user number).

use crate::Error;
use clap::ValueEnum;

/// The exact rational types a benchmark or regression can run on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScalarChoice {
    /// exactcheck's `Rational` (inline tier, Knuth/Henrici arithmetic, Lehmer gcd).
    Fast,
    /// num-rational's `BigRational`, unchanged (the baseline).
    Plain,
}

/// Checks `1 <= value <= max` for the count given as `flag`; `context` (e.g. `" with --mode
/// tree"`, or empty) says which limit applies.
///
/// # Errors
/// [`Error::Usage`] naming the flag, the allowed range and the value.
pub fn check_count(flag: &str, value: usize, max: usize, context: &str) -> Result<usize, Error> {
    if (1..=max).contains(&value) {
        Ok(value)
    } else {
        Err(Error::Usage(format!(
            "{flag} must be between 1 and {max}{context} (got {value})"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_checked_against_both_ends() {
        assert_eq!(check_count("--n", 5, 10, "").unwrap(), 5);
        assert_eq!(check_count("--n", 10, 10, "").unwrap(), 10);
        assert_eq!(
            check_count("--n", 0, 10, "").unwrap_err().to_string(),
            "--n must be between 1 and 10 (got 0)"
        );
        assert_eq!(
            check_count("--samples", usize::MAX, 10, " with x")
                .unwrap_err()
                .to_string(),
            format!(
                "--samples must be between 1 and 10 with x (got {})",
                usize::MAX
            )
        );
    }
}
