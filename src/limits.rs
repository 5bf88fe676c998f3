//! The limits of the command-line tool and the one registry the user sees.
//!
//! The library crates declare the limits they enforce in `exactcheck_core::limits`; the limits
//! only this tool enforces (the size of an input file, samples, interpolation points, the
//! precision asked of a root, the work of two `solve` kinds, worker threads) are declared here,
//! in the same declarative form ([`exactcheck_core::declare_limits!`]). [`all`] joins both in the
//! order of the "Resource limits" table of docs/limits.md: `--limit NAME=VALUE`, `exactcheck
//! limits` and the help text read it, so the user sees one registry.

use exactcheck_core::limits::{self as core_limits, Limit};

exactcheck_core::declare_limits! {
    /// The limits only the command-line tool enforces, in their order in [`all`].
    fn tool_limits;
    /// Size of an input file or of standard input, in bytes.
    FILE_SIZE = ("file-size", "input size", "bytes", 8 << 20);
    /// Bits of precision asked of an isolated root (`precision` = 2^-bits).
    PRECISION_BITS = ("precision-bits", "precision asked", "bits", 1_024);
    /// Samples of one `solve` answer or one built-in regression run.
    SAMPLES = ("samples", "number of samples", "", 100_000);
    /// Points of one `sphere_interpolation` problem (an exact linear system of about 2N x 2N
    /// with growing rationals: about N^4 work).
    POINTS = ("points", "number of interpolation points", "", 30);
    /// Work of one exact `ruled_line` problem: its degree `m + n` times the dimension `2^k` of
    /// the square-root field of its numbers (`k` independent square roots). The exact
    /// subdivision's cost grows about as the sixth power of the degree and several-fold per
    /// square root.
    RULED_WORK = ("ruled-work", "degree times field dimension of a ruled_line problem", "", 32);
    /// Size in bits of the Bernstein coefficients `u` and `v` of one exact `ph_offset` problem,
    /// all together: every exact polynomial of the answer is built from their products.
    PH_BITS = ("ph-bits", "size of the coefficients of a ph_offset problem", "bits", 2_048);
    /// Worker threads of the parallel pool (`RAYON_NUM_THREADS` asks for a number; each thread
    /// reserves a stack).
    THREADS = ("threads", "worker threads (RAYON_NUM_THREADS)", "", 1_024);
}

/// Every limit, the library crates' and the tool's, in the order of the table in docs/limits.md.
pub fn all() -> &'static [&'static Limit] {
    use core_limits as c;
    static ALL: [&Limit; 31] = [
        &FILE_SIZE,
        &c::DEPTH,
        &c::DIGITS,
        &c::EXPONENT,
        &c::FORMULA_EXPONENT,
        &c::LOOP_ITERATIONS,
        &c::LOOP_VALUE_BITS,
        &c::CONSTANT_BITS,
        &c::RADICANDS,
        &c::ALGEBRAIC_DEGREE,
        &c::FACTOR_COMBINATIONS,
        &c::PI_BITS,
        &c::VARIABLES,
        &c::TERMS,
        &c::DEGREE,
        &c::DIFF_ORDER,
        &c::SUM_TERMS,
        &c::ANGLE_MULTIPLE,
        &c::GROEBNER_STEPS,
        &c::GROEBNER_BASIS,
        &c::GROEBNER_BITS,
        &c::BISECTION,
        &PRECISION_BITS,
        &SAMPLES,
        &POINTS,
        &c::BERNSTEIN_DEGREE,
        &c::MATRIX_POWER,
        &RULED_WORK,
        &PH_BITS,
        &c::MEMORY,
        &THREADS,
    ];
    &ALL
}

/// The limit called `name`.
pub fn find(name: &str) -> Option<&'static Limit> {
    core_limits::find(all(), name)
}

/// Sets a limit from `NAME=VALUE` (the argument of `--limit`).
///
/// # Errors
/// As [`exactcheck_core::limits::set_from_str`]: an unknown name (with the known names) or a
/// value that is not a non-negative integer.
pub fn set_from_str(arg: &str) -> Result<&'static Limit, String> {
    core_limits::set_from_str(all(), arg)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The registry holds every limit of both lists once, and nothing else.
    #[test]
    fn the_registry_is_the_union_of_the_library_and_tool_limits() {
        let mut want: Vec<&str> = core_limits::all()
            .iter()
            .chain(tool_limits())
            .map(|l| l.name())
            .collect();
        let mut got: Vec<&str> = all().iter().map(|l| l.name()).collect();
        want.sort_unstable();
        got.sort_unstable();
        assert_eq!(got, want);
        for l in all() {
            assert!(std::ptr::eq(find(l.name()).unwrap(), *l));
        }
        assert!(set_from_str("nope=3")
            .unwrap_err()
            .contains("no limit named `nope` (limits: file-size, depth,"));
    }
}
