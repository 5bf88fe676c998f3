//! Resource limits: every bound the library crates (core, exact, float) put on what an input may
//! make them do (sizes, depths, degrees, counts, steps, memory), and the declarative form
//! ([`declare_limits!`](crate::declare_limits!)) in which the command-line tool declares its own (input size, samples,
//! points, threads, ...) and joins them with these into the one registry the user sees.
//!
//! Exact arithmetic on user-supplied formulas has no natural ceiling: a short input can ask for a
//! number of a billion digits, a field of 2^25 dimensions or a Groebner basis that never ends. So
//! every place where work or memory grows with the input checks it against a named [`Limit`]
//! *before* the work is done, and fails with a [`LimitError`] that names the limit, its value and
//! how to raise it (`--limit NAME=VALUE` on the command line). The defaults are generous for real
//! formulas and keep every run within seconds and far below 2 GB.
//!
//! The values are process-wide atomics: set once at start-up from the command line (or by a test
//! binary before it starts work), read with relaxed loads at the checks. Nothing here knows a
//! number type; a check takes the measured size as a `u64`.

use std::fmt;
use std::sync::atomic::{AtomicU64, Ordering};

/// One named limit: a bound on a size, a depth or a count of work.
#[derive(Debug)]
pub struct Limit {
    name: &'static str,
    what: &'static str,
    unit: &'static str,
    default: u64,
    value: AtomicU64,
}

impl Limit {
    /// A limit (used by [`declare_limits!`](crate::declare_limits!)).
    pub const fn new(
        name: &'static str,
        what: &'static str,
        unit: &'static str,
        default: u64,
    ) -> Limit {
        Limit {
            name,
            what,
            unit,
            default,
            value: AtomicU64::new(default),
        }
    }

    /// The name used on the command line (`--limit NAME=VALUE`), e.g. `depth`.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// What is limited, as a noun phrase (`nesting depth of an expression or a document`).
    pub fn what(&self) -> &'static str {
        self.what
    }

    /// The unit of the value (`levels`, `bits`, `MB`, ...).
    pub fn unit(&self) -> &'static str {
        self.unit
    }

    /// The built-in value.
    pub fn default_value(&self) -> u64 {
        self.default
    }

    /// The value in force.
    pub fn get(&self) -> u64 {
        self.value.load(Ordering::Relaxed)
    }

    /// The value in force, as a `usize` (saturating on 32-bit targets).
    pub fn get_usize(&self) -> usize {
        usize::try_from(self.get()).unwrap_or(usize::MAX)
    }

    /// Sets the value for the rest of the process.
    pub fn set(&self, value: u64) {
        self.value.store(value, Ordering::Relaxed);
    }

    /// Restores the built-in value.
    pub fn reset(&self) {
        self.set(self.default);
    }

    /// `Ok` when `actual` is within the limit (`actual <= value`).
    ///
    /// # Errors
    /// A [`LimitError`] naming this limit, its value and `actual`.
    pub fn check(&'static self, actual: u64) -> Result<(), LimitError> {
        if actual <= self.get() {
            Ok(())
        } else {
            Err(self.exceeded(actual.to_string()))
        }
    }

    /// [`Limit::check`] for a `usize` measure.
    ///
    /// # Errors
    /// As [`Limit::check`].
    pub fn check_usize(&'static self, actual: usize) -> Result<(), LimitError> {
        self.check(u64::try_from(actual).unwrap_or(u64::MAX))
    }

    /// The error for a measure found beyond this limit; `actual` says how far (`"257"`,
    /// `"more than 1000000"`).
    pub fn exceeded(&'static self, actual: impl Into<String>) -> LimitError {
        LimitError {
            limit: self,
            value: self.get(),
            actual: actual.into(),
        }
    }
}

/// A limit was exceeded. Displayed as one line: what, how much, the limit and its value, and the
/// flag that raises it.
#[derive(Debug, Clone)]
pub struct LimitError {
    /// The limit.
    pub limit: &'static Limit,
    /// Its value when the check failed.
    pub value: u64,
    /// The measure found (`"257"`, `"more than 1000000"`).
    pub actual: String,
}

impl PartialEq for LimitError {
    fn eq(&self, other: &LimitError) -> bool {
        std::ptr::eq(self.limit, other.limit)
            && self.value == other.value
            && self.actual == other.actual
    }
}

impl Eq for LimitError {}

impl fmt::Display for LimitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let l = self.limit;
        let unit = if l.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", l.unit)
        };
        write!(
            f,
            "{} exceeds the limit {} = {}{unit} (found {}; raise it with --limit {}=N)",
            l.what, l.name, self.value, self.actual, l.name
        )
    }
}

impl std::error::Error for LimitError {}

/// Declares limits as statics and a function listing them in order:
/// `declare_limits! { /// doc of the list
/// fn all; /// doc
/// NAME = ("cli-name", "what", "unit", default); ... }`.
#[macro_export]
macro_rules! declare_limits {
    ($(#[$listdoc:meta])* fn $all:ident; $($(#[$doc:meta])* $id:ident = ($name:literal, $what:literal, $unit:literal, $default:expr);)*) => {
        $($(#[$doc])* pub static $id: $crate::limits::Limit = $crate::limits::Limit::new($name, $what, $unit, $default);)*
        $(#[$listdoc])*
        pub fn $all() -> &'static [&'static $crate::limits::Limit] {
            static ALL: &[&$crate::limits::Limit] = &[$(&$id),*];
            ALL
        }
    };
}

declare_limits! {
    /// Every limit the library crates enforce, in the order of the table in docs/limits.md (the
    /// command-line tool's registry adds its own between them).
    fn all;
    /// Nesting depth of an expression (parentheses, signs, powers, calls) and of a JSON or TOML
    /// document (arrays and objects).
    DEPTH = ("depth", "nesting depth", "levels", 256);
    /// Decimal digits of a number written in the input, counting a decimal exponent
    /// (`1e5000` has 5001).
    DIGITS = ("digits", "digits of a number", "digits", 10_000);
    /// Absolute value of an exponent after `^`.
    EXPONENT = ("exponent", "exponent", "", 10_000);
    /// Absolute value of an exponent `k` of `a^k` in a regressed formula (`regress --formula`,
    /// `--fpcore`): its float side does `|k| - 1` multiplications per sample, and `2^1024`
    /// already overflows a double.
    FORMULA_EXPONENT = ("formula-exponent", "exponent of a power in a regressed formula", "", 1_024);
    /// Loop iterations of one evaluation of a regressed program (FPCore `while`, `while*`; the
    /// iterations of all its loops together): every iteration is evaluated exactly, and a loop
    /// that never ends (`while TRUE`) must stop somewhere.
    LOOP_ITERATIONS = ("loop-iterations", "loop iterations of one evaluation", "", 10_000);
    /// Size in bits of the exact value of one loop variable in the exact zero test of a
    /// regressed program (which keeps every value exact, where the interval passes carry a grown
    /// value as an enclosure): a loop whose values grow every iteration, a diverging iteration,
    /// would otherwise grow them up to `constant-bits`, at minutes per sample.
    LOOP_VALUE_BITS = ("loop-value-bits", "size of a loop variable's exact value", "bits", 16_384);
    /// Size in bits of any exact constant: a folded constant expression, a polynomial
    /// coefficient, an exact intermediate.
    CONSTANT_BITS = ("constant-bits", "size of a constant", "bits", 1_000_000);
    /// Distinct square-free radicands in one square-root field (its dimension over Q is 2^k).
    RADICANDS = ("radicands", "number of distinct square roots", "", 10);
    /// Degree of the defining polynomial of one real algebraic number (an operation on two
    /// numbers of degree `d` computes a resultant of degree up to `d^2`).
    ALGEBRAIC_DEGREE = ("algebraic-degree", "degree of an algebraic number", "", 64);
    /// Subsets of modular factors tested while factoring one polynomial over Q (Zassenhaus
    /// recombination is exponential in the number of modular factors); past it a minimal
    /// polynomial is not known and a number field over it is refused.
    FACTOR_COMBINATIONS = ("factor-combinations", "subsets of modular factors tested in factoring", "", 200_000);
    /// Bits of pi computed to decide a comparison of a value in pi (`2*pi/3` against a printed
    /// decimal): a value that close to a rounding boundary needs that many bits.
    PI_BITS = ("pi-bits", "bits of pi", "bits", 65_536);
    /// Distinct variables of one polynomial.
    VARIABLES = ("variables", "number of variables", "", 1_000);
    /// Terms of one polynomial during expansion.
    TERMS = ("terms", "number of polynomial terms", "", 1_000_000);
    /// Total degree of one polynomial during expansion.
    DEGREE = ("degree", "polynomial degree", "", 100_000);
    /// Order `k` of a derivative `diff(E, t, k)` (every order squares a denominator before its
    /// common factor cancels).
    DIFF_ORDER = ("diff-order", "order of a derivative", "", 100);
    /// Terms of a `sum(k, a, b, E)`, each an expansion of `E`; the terms of nested sums count
    /// together (an inner sum's terms for every term of the outer one).
    SUM_TERMS = ("sum-terms", "terms of a sum", "", 100_000);
    /// Absolute value of the integer multiple `k` of a base angle in `sin`, `cos`, `tan`: of an
    /// angle variable `x`, or of `x/L` when `x` has coefficients with denominators (`L` their
    /// lcm), or of the constant angle (`sin(k x)` expands to a Chebyshev polynomial of degree `k`
    /// with `k`-bit coefficients).
    ANGLE_MULTIPLE = ("angle-multiple", "multiple of an angle variable", "", 1_000);
    /// S-polynomial reductions of one Groebner basis computation.
    GROEBNER_STEPS = ("groebner-steps", "Groebner basis steps", "", 150);
    /// Elements of one Groebner basis.
    GROEBNER_BASIS = ("groebner-basis", "Groebner basis size", "polynomials", 200);
    /// Size in bits of a coefficient of a new Groebner basis element (the cost of the later
    /// reductions grows with it).
    GROEBNER_BITS = ("groebner-bits", "size of a Groebner basis coefficient", "bits", 10_000);
    /// Bisection or refinement steps spent on one real root.
    BISECTION = ("bisection", "refinement steps for one root", "", 100_000);
    /// Degree of one Bernstein polynomial or Bezier curve of a claims file (`bernstein(i, n, t)`:
    /// `n`; `bezier(t, p0, ..., pn)`: `n`, one less than the points): its expansion grows about
    /// as the cube of the degree.
    BERNSTEIN_DEGREE = ("bernstein-degree", "degree of a Bernstein polynomial or Bezier curve", "", 1_000);
    /// Heap memory of the whole process, in MB (enforced by the command-line tool's allocator).
    MEMORY = ("memory", "memory in use", "MB", 1_536);
    /// Exponent `k` of a matrix power `M^k`: each squaring multiplies the size of every entry's
    /// tree by about twice the dimension before anything is expanded.
    MATRIX_POWER = ("matrix-power", "exponent of a matrix power", "", 64);
}

/// The limit called `name` in `registry` (a list such as [`all`]).
pub fn find(registry: &[&'static Limit], name: &str) -> Option<&'static Limit> {
    registry.iter().copied().find(|l| l.name == name)
}

/// Sets a limit of `registry` from `NAME=VALUE` (the argument of `--limit`); the value is a
/// non-negative integer, `_` allowed between digits.
///
/// # Errors
/// One line naming an unknown limit (with the known names) or a value that is not an integer.
pub fn set_from_str(registry: &[&'static Limit], arg: &str) -> Result<&'static Limit, String> {
    let (name, value) = arg
        .split_once('=')
        .ok_or_else(|| format!("--limit takes NAME=VALUE, not `{arg}`"))?;
    let name = name.trim();
    let limit = find(registry, name).ok_or_else(|| {
        let names: Vec<&str> = registry.iter().map(|l| l.name).collect();
        format!(
            "--limit: no limit named `{name}` (limits: {})",
            names.join(", ")
        )
    })?;
    let digits: String = value.trim().chars().filter(|&c| c != '_').collect();
    let v: u64 = digits
        .parse()
        .map_err(|_| format!("--limit {name}: `{value}` is not a non-negative integer"))?;
    limit.set(v);
    Ok(limit)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_found() {
        for l in all() {
            assert!(std::ptr::eq(find(all(), l.name()).unwrap(), *l));
            assert_eq!(all().iter().filter(|m| m.name() == l.name()).count(), 1);
        }
        assert!(find(all(), "nonsense").is_none());
    }

    #[test]
    fn the_message_names_the_limit_its_value_and_the_flag() {
        // A private limit, so that the process-wide ones are not disturbed under parallel tests.
        static L: Limit = Limit::new("test-depth", "nesting depth", "levels", 3);
        assert!(L.check(3).is_ok());
        let e = L.check(4).unwrap_err();
        assert_eq!(
            e.to_string(),
            "nesting depth exceeds the limit test-depth = 3 levels (found 4; raise it with --limit test-depth=N)"
        );
        L.set(4);
        assert!(L.check(4).is_ok());
        L.reset();
        assert_eq!(L.get(), 3);
    }

    #[test]
    fn set_from_str_rejects_unknown_names_and_bad_values() {
        assert!(set_from_str(all(), "depth")
            .unwrap_err()
            .contains("NAME=VALUE"));
        assert!(set_from_str(all(), "nope=3")
            .unwrap_err()
            .contains("no limit named `nope`"));
        assert!(set_from_str(all(), "depth=-1")
            .unwrap_err()
            .contains("not a non-negative integer"));
        assert!(set_from_str(all(), "depth=1x")
            .unwrap_err()
            .contains("not a non-negative integer"));
    }
}
