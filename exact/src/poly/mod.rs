//! Sparse multivariate polynomials over a coefficient ring: the scalar that turns generic formula
//! code into a symbolic proof.
//!
//! [`Poly<C>`] implements [`Ring`], so every formula written against `Ring` (the scalar
//! traits of `exactcheck-core`) runs over polynomials: instantiate it with `Poly<Rational>` variables and an identity
//! is **proved** when its residual expands to the zero polynomial. Because the representation is
//! canonical, that test is `residual.is_zero()`.
//!
//! # Expressions
//! `Poly::to_expr` (with the formulas, [`crate::expr::CoeffExpr`]) turns a polynomial back into
//! a formula, so derived polynomials print in LaTeX and MathML too. Polynomials themselves do
//! not depend on formulas: the radicand of a square-root variable ([`RootEntry`]) is an opaque
//! payload ([`RootRadicand`]) that the formulas fill in.
//!
//! # Variables
//! A variable is an index ([`Var`], a `u32`); polynomials store no names. The [`Vars`] table maps
//! names to indices for the parser ([`crate::expr`]) and the printer ([`Poly::display`]).
//! `zero()`, `one()` and `from_i64()` need no variables at all. The monomial representation is
//! dense in the variable index (see below), so indices should be small and consecutive, as
//! [`Vars`] hands them out.
//!
//! # The monomial order
//! Terms are kept in **lexicographic order with the variables ranked by index, the highest index
//! largest** (`x_0 < x_1 < x_2 < ...`, so `x_1 > x_0^k` for every `k`), sorted by decreasing
//! monomial, without zero coefficients and without repeated monomials. The first term is the
//! leading term. This one order is used for the canonical form, for printing, and for
//! [`Poly::reduce`] and [`groebner`]. It is chosen so that [`unit_circle_relation`]`(c, s)` with
//! `c` declared before `s` has the leading monomial `s^2`: reduction then rewrites
//! `s^2 -> 1 - c^2` (declare the cosine before the sine).
//!
//! # Representation
//! Exponent vectors are packed into `u64` words, `64 / bits` variables per word, with a field
//! width `bits` of 8, 16, 32 or 64 chosen per polynomial (as in FLINT's `mpoly`): variable `v`
//! lives in word `v / (64 / bits)`, and within a word the higher variables take the higher bits,
//! so comparing the words as one multi-word unsigned integer, most significant word last, is the
//! monomial order, and multiplying monomials is adding words. The top bit of every field is a
//! guard bit that stays clear (exponents below `2^(bits-1)`), which makes divisibility one
//! subtraction per word. A polynomial uses as many words as its highest variable needs; operands
//! of different layouts are repacked to a common one. Before a product is formed, a bound on its
//! exponents (from the OR of all exponent words) picks a field width in which no field can
//! overflow, so the kernels never check. Exponents are limited to `u32::MAX` (the operators
//! panic beyond; [`Poly::checked_mul`] and [`Poly::checked_pow`] report it).
//!
//! # Algorithms
//! * Addition and subtraction merge the two sorted term lists (monomials of up to 16 words are
//!   compared and copied as fixed-size arrays). Sums of many large polynomials ([`Poly::sum`])
//!   are one k-way heap merge on compact keys of one or two words.
//! * Multiplication by a single term shifts and scales (the order is a monoid order, so the
//!   result is still sorted); the other factor is read in its own packing when only zero words
//!   are missing, not repacked. Products of at most 32 term products are formed directly, as a
//!   merge of the sorted rows `f_i g` (the shorter factor has at most five terms): planning a
//!   kernel would cost more. Otherwise the
//!   exponents of the two operands are first re-packed
//!   into **compact keys**: each variable gets just the bits its largest exponent in the product
//!   needs (a Kronecker substitution that keeps the order). Then:
//!   - when the box of possible product exponents is small (at most 4 cells per term product,
//!     and `2^22` cells), products are accumulated in a dense array indexed by mixed radix, and
//!     the touched cells sorted once (dense few-variable products);
//!   - otherwise by Johnson's heap algorithm with the chained stream insertion of Monagan and
//!     Pearce ("Sparse polynomial division using a heap", 2011): a heap of at most
//!     `min(#f, #g)` streams yields the products in decreasing order, equal monomials are
//!     accumulated as they leave the heap, and the result is born sorted, with no per-term
//!     allocation. With one-word keys (the benchmark chiang-identity: 74 variables in 10 words become one key word) the
//!     heap holds the keys themselves. Squaring runs the heap over the pairs `i <= j` only.
//!
//!   Full monomials are formed once per output term.
//!
//!   The kernels are generic over their coefficient arithmetic. For `Rational` and `ModP`
//!   coefficients (the [`WordCoefficients`] hook, `words`) a product first writes both
//!   coefficient lists as 63-bit integers over a common denominator and, when that succeeds,
//!   runs the same kernels on `i64` words with `i32`, `i64`, `i128` or 192-bit accumulators
//!   chosen by a bound on every partial sum (no overflow checks in the loops), converting back
//!   once per output term; dense products then accumulate directly in an array over the exponent box and
//!   read it back in order (no sort). Other coefficient types, and lists that do not fit, take
//!   the generic path.
//! * Powers: a single term is raised directly. A rational polynomial with a content `c != 1` is
//!   raised as `c^k P^k` with `P` primitive integer, so a big rational content never rides
//!   through the expansion. Then, for `Rational` and `ModP` coefficients, a cost model
//!   (`power`) chooses between binary powering (squarings and multiplications) and the power
//!   recurrence (J. C. P. Miller's, in a multivariate form with a leading term): every
//!   coefficient of `P^e` from `t - 1` earlier ones and one exact division, one pass linear in
//!   the output, which wins for high powers of few-term bases (`(t + x^2 + y + 3 x y_x)^74`:
//!   220,000 word products instead of binary powering's 34 million big ones). Other coefficient
//!   types take binary powering.
//! * Normal forms ([`Poly::reduce`]) by multivariate division with a heap of pending monomials
//!   and a hash map of their coefficients: every monomial leaves the heap once, already final. For
//!   independent unit-circle relations `c_i^2 + s_i^2 - 1` (a Gröbner basis in any order) there
//!   is a closed form, `s^(2h+r) = s^r (1 - c^2)^h`, applied term by term
//!   ([`Poly::reduce_unit_circle`]); `reduce` recognises such relation sets and takes it.
//! * Gröbner bases ([`groebner`]) by Buchberger's algorithm with both of Buchberger's criteria
//!   (coprime leading monomials; the chain criterion), the normal pair selection strategy, and a
//!   final inter-reduction: the result is the unique reduced Gröbner basis, so [`Poly::reduce`]
//!   against it is a canonical normal form.
//!
//! # Performance
//! The benchmark chiang-identity (the claim list at `(m, n) = (8, 13)`: a 9.5 kB expression pair
//! over 74 variables, 5,841 terms) parses, expands and compares these polynomials; the criterion
//! bench `bench/criterion/benches/poly.rs` and the side-by-side comparison with SymPy and python-flint
//! (`bench/scripts/compare.py`) measure it, and `docs/benchmarks.md` has the latest figures. A
//! large share of the time is coefficient arithmetic in [`crate::Rational`].

mod display;
mod divide;
pub mod factor;
pub mod gcd;
mod kernels;
mod layout;
mod power;
mod reduce;
mod ring;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod word_tests;
mod words;

pub(crate) use display::fallback_name;
pub use display::PolyDisplay;
pub(crate) use divide::variable_span;
pub use divide::{div_exact, poly_derivative};
pub use factor::{square_free, Factorization};
pub use reduce::{groebner, unit_circle_relation};
pub use ring::{Monomial, Poly, SizeError, Terms};
pub use words::{WordCoefficients, WordSum};

use exactcheck_core::Ring;
use kernels::*;
use layout::*;
use std::any::Any;
use std::collections::HashMap;
use std::sync::Arc;

/// A variable: an index into a [`Vars`] table (or any numbering the caller chooses).
pub type Var = u32;

/// The largest supported exponent.
const MAX_EXP: u64 = u32::MAX as u64;

// ------------------------------------------------------------------------------------ Vars

/// A table of variable names: name <-> index. Indices are handed out consecutively from 0 in the
/// order names are first seen.
///
/// Names should be identifiers (`[A-Za-z_][A-Za-z0-9_]*`, not `sqrt`) for printed polynomials to
/// parse back ([`crate::expr`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Vars {
    names: Vec<String>,
    index: HashMap<String, Var>,
    /// The square roots of non-constant expressions met so far, when they are allowed
    /// ([`Vars::allow_roots`]); `None` (the default) refuses them.
    roots: Option<Vec<RootEntry>>,
}

/// A square root `sqrt(E)` of a non-constant expression, named by a variable of the table
/// ([`crate::expr`] introduces one variable per distinct radicand).
#[derive(Clone, Debug)]
pub struct RootEntry {
    /// The variable standing for the root.
    pub var: Var,
    /// The radicand as written, recorded by the front end that introduced the root (a formula,
    /// converted again by [`crate::prove::square_roots`]).
    pub radicand: Arc<dyn RootRadicand>,
    /// The expanded radicand, printed in a canonical form: equal radicands share a variable.
    pub key: String,
}

impl PartialEq for RootEntry {
    fn eq(&self, other: &RootEntry) -> bool {
        self.var == other.var
            && self.key == other.key
            && self.radicand.eq_radicand(other.radicand.as_ref())
    }
}

impl Eq for RootEntry {}

/// The radicand of a square-root variable as its front end records it (the formula as written,
/// [`crate::expr`]): opaque to the polynomials, so that they do not depend on formulas.
pub trait RootRadicand: std::fmt::Debug + Any + Send + Sync {
    /// Equality with another radicand (false for one of another type).
    fn eq_radicand(&self, other: &dyn RootRadicand) -> bool;
    /// The radicand as [`Any`], for its front end to read it back.
    fn as_any(&self) -> &dyn Any;
}

impl Vars {
    /// An empty table.
    pub fn new() -> Self {
        Self::default()
    }

    /// A table with these names, numbered in order (repeated names keep their first index).
    pub fn from_names<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Self {
        let mut v = Vars::new();
        for n in names {
            v.var(n.as_ref());
        }
        v
    }

    /// The index of `name`, adding it to the table if it is new.
    ///
    /// # Panics
    /// When the table already holds `u32::MAX` names.
    pub fn var(&mut self, name: &str) -> Var {
        if let Some(&i) = self.index.get(name) {
            return i;
        }
        let i = Var::try_from(self.names.len()).expect("too many variables");
        self.names.push(name.to_string());
        self.index.insert(name.to_string(), i);
        i
    }

    /// The polynomial of the variable `name` (added to the table if new).
    pub fn poly<C: Ring>(&mut self, name: &str) -> Poly<C> {
        Poly::var(self.var(name))
    }

    /// The index of `name`, if it is in the table.
    pub fn get(&self, name: &str) -> Option<Var> {
        self.index.get(name).copied()
    }

    /// The name of variable `var`, if it is in the table.
    pub fn name(&self, var: Var) -> Option<&str> {
        self.names.get(var as usize).map(String::as_str)
    }

    /// The names, by index.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The number of names.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// Whether the table is empty.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// Lets conversions turn `sqrt(E)` of a non-constant `E` into a variable of this table
    /// (recorded in [`Vars::roots`]); without this call such a root is an error.
    pub fn allow_roots(&mut self) {
        self.roots.get_or_insert_with(Vec::new);
    }

    /// Whether [`Vars::allow_roots`] was called.
    pub fn roots_allowed(&self) -> bool {
        self.roots.is_some()
    }

    /// The square roots of non-constant expressions met, in order of appearance (an inner
    /// root before the roots whose radicands contain it).
    pub fn roots(&self) -> &[RootEntry] {
        self.roots.as_deref().unwrap_or_default()
    }

    /// The variable of the root with canonical radicand `key`, if one was recorded.
    pub fn root_by_key(&self, key: &str) -> Option<Var> {
        self.roots().iter().find(|r| r.key == key).map(|r| r.var)
    }

    /// Records the root `sqrt(radicand)` under a new variable named `name` (roots must be
    /// allowed, [`Vars::allow_roots`]) and returns the variable.
    ///
    /// # Panics
    /// When roots are not allowed, or the table already holds `u32::MAX` names.
    pub fn add_root(&mut self, name: &str, radicand: Arc<dyn RootRadicand>, key: String) -> Var {
        let var = self.var(name);
        self.roots
            .as_mut()
            .expect("roots are allowed (checked by the caller)")
            .push(RootEntry { var, radicand, key });
        var
    }
}
