//! Dense univariate polynomials over [`Rational`] and exact real root isolation.
//!
//! The question this module answers for the rest of the workspace is the claim list's: with the rational
//! circle parameter `tau`, the discriminant `A(t)^2 - B(t)` of Spaeth's cylinder/sphere
//! intersection, times `(1 + tau^2)^2`, is a polynomial `D(tau)` with rational coefficients, and the
//! surfaces meet exactly where `D >= 0`. [`UPoly::nonnegative_set`] describes that set exactly, as a
//! union of closed intervals whose finite endpoints are real roots of `D`, each isolated by a
//! [`RootInterval`] with rational endpoints (or given exactly, when the root is rational).
//! Nothing here uses floating point for a decision.
//!
//! A caveat for the claim list's callers: `tau = tan(t/2)` misses `t = pi`. The sign there is the sign
//! of the limit of `D(tau) / (1 + tau^2)^2` as `tau -> inf`, i.e. of the coefficient of `tau^4`
//! (zero if the degree dropped below 4); check it separately.
//!
//! # Representation
//! A [`UPoly`] is the vector of its coefficients from the constant term up, without trailing
//! zeros (the zero polynomial is the empty vector), so the representation is canonical and `==`
//! is equality of polynomials. [`UPoly`] implements [`Ring`].
//!
//! # Real roots
//! The workspace's real-root API is in `real_roots` ([`isolate_real_roots`],
//! [`isolate_real_roots_sturm`], [`isolate_real_roots_in`], [`refine_real_root`],
//! [`sign_at_real_root`], [`common_real_roots_in`], [`descartes_bound`]): one result type,
//! [`RootInterval`], exact exactly when the root is rational. Polynomials with coefficients in a
//! real number field (`algebraic::FieldUPoly`, which builds on this module) have the same root,
//! sign-chart and refinement answers, found through the rational isolator applied to their norm. Every root count and isolation
//! runs on Descartes' rule (module `descartes`): [`UPoly::roots`], [`UPoly::sign_chart`] and the
//! sets built on them, [`UPoly::count_roots`], [`UPoly::count_real_roots`], and
//! [`UPoly::isolate_roots`], which lays the roots out in the intervals of the dyadic bisection
//! (module `isolate`: the shape algebraic numbers are printed with). The Sturm bisection (module
//! `sturm`, [`isolate_real_roots_sturm`]) is the reference of the tests, and the fallback beyond
//! [`MAX_DESCARTES_DEGREE`].
//!
//! # Algorithms
//! * Division with remainder over Q; gcds by Euclid's algorithm in which every remainder is
//!   replaced by its primitive part (integer coefficients with gcd 1, see [`UPoly::content`]):
//!   the *primitive remainder sequence*, which keeps the coefficients as small as the remainders'
//!   true sizes instead of letting the denominators grow as in the plain rational sequence.
//! * Square-free parts `p / gcd(p, p')` and Yun's square-free decomposition
//!   ([`UPoly::square_free_decomposition`]); root multiplicities come from the latter.
//! * Factorisation into irreducible factors over Z ([`UPoly::factor`], module `factor`:
//!   Zassenhaus' algorithm on the square-free parts above).
//! * Isolation by Descartes' rule of signs on the primitive square-free part (module
//!   `descartes`). The bisection shape of [`UPoly::isolate_roots`]: bisection of `(-2^k, 2^k)`,
//!   with `2^k` above Cauchy's root bound, each node's root count read off the isolated roots;
//!   a midpoint that is a root is recorded exactly and the bisection continues from non-roots on
//!   either side of it (so no interval ever ends at a root). Afterwards every interval is tested
//!   for a *rational* root: if the primitive square-free part has leading coefficient `l`, a
//!   rational root `p/q` has `q | l` (rational root theorem), so `l * root` is an integer;
//!   narrowing the interval below `1/(2l)` (by the quadratic refinement below) leaves at most
//!   one candidate `k / l`, which is evaluated exactly. Hence [`RootInterval::is_exact`] holds
//!   **exactly when the root is rational**.
//! * Sturm sequences (module `sturm`), normalised to primitive polynomials (positive factors
//!   only, which leaves every sign, hence every sign-variation count, unchanged): the number of
//!   distinct roots in `(a, b]` is `V(a) - V(b)`, also when `a` or `b` is a root. They drive
//!   the reference isolator.
//! * Refinement ([`UPoly::refine`]) narrows the interval on the sign of the primitive
//!   square-free part ([`UPoly::primitive_square_free_part`], no Sturm chain), which changes
//!   across every isolated root, by Abbott's quadratic interval refinement
//!   (`exactcheck_core::roots::refine_isolating`: secant predictions on a grid of `N` parts with
//!   `N` squared on success, a bisection on failure), so a width of `2^-10240` costs a few dozen
//!   evaluations, not 10,240 bisections; [`UPoly::try_refine`] checks the `bisection` limit
//!   first.
//! * The sign on each gap between consecutive roots ([`UPoly::sign_chart`]) follows from the
//!   leading coefficient and the multiplicities, without further evaluation.
//!
//! # Limits
//! Dense representation: fine for the low degrees of the workspace (the discriminants are of
//! degree at most 4), usable into the hundreds for isolation. The bisection shape costs about
//! `log2(2^k / sep)` comparisons of a root with a midpoint, `sep` the root separation, each at
//! most one evaluation; the test for a rational root then refines quadratically to `1/(2l)`,
//! `l` as above.

pub mod bench_instances;
mod bernstein;
mod descartes;
mod factor;
mod isolate;
mod limbs;
mod real_roots;
mod resultant;
mod sturm;
#[cfg(test)]
mod tests;
mod upoly;

pub use descartes::{integer_real_roots, integer_real_roots_to, MAX_DESCARTES_DEGREE};
pub use exactcheck_core::roots::{IsolatedRoot, ZeroPolynomial};
pub use factor::Factorisation;
pub(crate) use isolate::{compare_simple, nonnegative_in_chart, sign_chart_from};
pub use real_roots::{
    common_real_roots_in, compare_with_real_root, descartes_bound, isolate_real_roots,
    isolate_real_roots_in, isolate_real_roots_sturm, isolate_real_roots_sturm_in, refine_real_root,
    sign_at_real_root,
};
pub use sturm::sign_variations;
pub(crate) use upoly::write_terms;
pub use upoly::UPolyDisplay;

use crate::poly::Var;
use crate::Rational;
use exactcheck_core::{Ring, Sign};
use num_bigint::BigInt;
use num_integer::Integer;

/// The largest degree [`UPoly::from_poly`] accepts (the representation is dense).
pub const MAX_FROM_POLY_DEGREE: u32 = 1 << 16;

/// A dense univariate polynomial with [`Rational`] coefficients, in canonical form (see the
/// module documentation).
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct UPoly {
    /// Coefficients from degree 0 up; the last one (if any) is non-zero.
    coeffs: Vec<Rational>,
}

/// The error of [`UPoly::from_poly`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FromPolyError {
    /// A variable other than the requested one occurs.
    #[error("the polynomial is not univariate: variable #{0} occurs besides the requested one")]
    OtherVariable(Var),
    /// The degree exceeds [`MAX_FROM_POLY_DEGREE`].
    #[error("degree {0} is too large for a dense univariate polynomial")]
    DegreeTooLarge(u32),
}

/// An isolating interval of one real root of a polynomial.
///
/// Either `lo == hi`, and the root is exactly that rational number, or `lo < hi`, and the root
/// lies in the **open** interval `(lo, hi)`, which contains no other root; then neither endpoint
/// is a root. The intervals returned by [`UPoly::isolate_roots`] are exact exactly when the root
/// is rational.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct RootInterval {
    /// The lower end.
    pub lo: Rational,
    /// The upper end (`>= lo`).
    pub hi: Rational,
}

/// A real root with its multiplicity.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Root {
    /// The isolating interval.
    pub interval: RootInterval,
    /// The multiplicity (`>= 1`).
    pub multiplicity: u32,
}

/// The signs of a polynomial along the real line: its distinct real roots, increasing, and its
/// (constant) sign on each gap between them.
///
/// `gaps.len() == roots.len() + 1`: `gaps[0]` is the sign on `(-inf, root 0)`, `gaps[i]` on
/// `(root i-1, root i)`, the last on `(last root, +inf)`. For the zero polynomial `roots` is
/// empty and `gaps == [Sign::Zero]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SignChart {
    /// The distinct real roots, increasing.
    pub roots: Vec<Root>,
    /// The sign on each open gap.
    pub gaps: Vec<Sign>,
}

/// An end of a [`RootBoundedInterval`]: an infinity or a real root.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Bound {
    /// Minus infinity (the interval is unbounded below).
    NegInf,
    /// A real root of the polynomial the interval was computed for (included in the interval).
    Root(RootInterval),
    /// Plus infinity (the interval is unbounded above).
    PosInf,
}

/// A closed interval of the real line, possibly unbounded or a single point: the set of `x` with
/// `lo <= x <= hi` (a finite end is included, an infinite end is not a point).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RootBoundedInterval {
    /// The lower end ([`Bound::NegInf`] or a root).
    pub lo: Bound,
    /// The upper end (a root or [`Bound::PosInf`]).
    pub hi: Bound,
}

// ------------------------------------------------------------------------------ small helpers

fn half() -> Rational {
    Rational::new(1, 2).expect("2 is not zero")
}

fn midpoint(a: &Rational, b: &Rational) -> Rational {
    a.add_ref(b) * half()
}

/// `floor(x)` as an integer.
fn floor(x: &Rational) -> BigInt {
    x.numer().div_floor(&x.denom())
}

pub(crate) fn sign_neg(s: Sign) -> Sign {
    match s {
        Sign::Negative => Sign::Positive,
        Sign::Zero => Sign::Zero,
        Sign::Positive => Sign::Negative,
    }
}

/// `2^k` as an `f64`, exactly (`inf` above the range, subnormals below `2^-1022`, `0` below
/// `2^-1074`): [`crate::to_f64::pow2`] for the `i64` exponents of the isolation.
fn pow2f(k: i64) -> f64 {
    crate::to_f64::pow2(k.clamp(-2000, 2000) as i32)
}
