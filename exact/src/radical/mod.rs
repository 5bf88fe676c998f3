//! `Radical`: the multi-quadratic numbers, exact sums `sum_m c_m sqrt(m)` over Q; and
//! `ComplexRadical`, the same with `i = sqrt(-1)` adjoined.
//!
//! # Where they are used
//! * Chiang's paper (docs/papers/chiang.md): Example 4 has control vectors with `sqrt 2` and `sqrt 6`, and
//!   Table 1 (the conic sections of the cone) has weights `1/sqrt 2`, `1 + sqrt 2` and planes with
//!   normal `(1, 1, sqrt 2)`; the ruled-surface formulas run over [`Radical`] to reproduce them
//!   exactly. Roots of quadratics (poles, parameters `t = 1/sqrt 2`) are exact [`Radical`]s too,
//!   through [`Sqrt`].
//! * Juettler's Satz 5 (docs/papers/juttler.md): the complex focal lines `xi (1,0,0,i) + zeta (0,1,-i,0)` of
//!   the elliptic linear congruence need `i`; they are checked over [`ComplexRadical`].
//! * Numbers in JSON (docs/solve.md): input strings such as `"1/sqrt(2)"` or `"(2+sqrt(2))/3"` are
//!   parsed by [`Radical`]'s `FromStr` (the one grammar of [`crate::expr`], evaluated exactly), and answers are printed by its `Display` in the same syntax
//!   (the output parses back to the same value).
//!
//! # Canonical form
//! A [`Radical`] is a list of terms `(m, c_m)` meaning `c_m sqrt(m)`, where
//! * each radicand `m` ([`Radicand`]) is a positive **square-free** integer, `m = 1` standing for
//!   the rational part;
//! * the list is **sorted by strictly increasing `m`**;
//! * **no coefficient is zero** (zero is the empty list), and every coefficient is a canonical
//!   [`Rational`].
//!
//! The square roots of distinct square-free integers are linearly independent over Q
//! (Besicovitch 1940), so this representation is unique: `==` is equality of numbers and the
//! derived `Hash` is consistent with it. No context (no fixed field `Q(sqrt d)`) is needed: the
//! product rule `sqrt(m1) sqrt(m2) = g sqrt((m1/g)(m2/g))`, `g = gcd(m1, m2)`, keeps the basis
//! closed, so numbers built from any radicals combine freely (`Q(sqrt 2, sqrt 6) = Q(sqrt 2,
//! sqrt 3)` needs no declaration).
//!
//! # Algorithms
//! Field operations split a number along one radical: choose an integer `q > 1` that divides or is
//! coprime to every radicand present (a "coprime-basis" element; found by gcd refinement, no
//! factoring) and write `x = a + b sqrt(q)` with `a`, `b` free of `sqrt(q)`. Since `q` is coprime
//! to the radicands of `a` and `b`, `sqrt(q)` is not in the field they generate (Kummer theory),
//! so `a^2 - q b^2 != 0` for `x != 0`. Then
//! * **inverse**: `x^-1 = (a - b sqrt q) / (a^2 - q b^2)`, recursing on the norm, which has one
//!   radical fewer, until it is rational;
//! * **sign** (exact): if `sign a` and `sign b` agree or one is zero, that is the sign; otherwise it
//!   is `sign(a) sign(a^2 - q b^2)`, the norm's sign being decided recursively. A floating-point
//!   filter with a rigorous error bound answers first when the value is clearly away from zero
//!   (as CGAL's filtered predicates do); [`Radical::sign_exact`] skips it;
//! * **square root**: of a rational `n/d`, `sqrt(n d)/d` after extracting the square part of `n`
//!   and `d` (trial division, then Miller–Rabin and Pollard's rho for 64-bit cofactors); of
//!   `x = a + b sqrt q`, denesting: if the norm `a^2 - q b^2` has a square root `n` in the field of
//!   `a` and `b`, then `sqrt x = sqrt((a + n)/2) + sign(b) sqrt((a - n)/2)`, recursively; otherwise
//!   `sqrt x` is not multi-quadratic at all. Every root is verified (`y >= 0`, `y^2 == x`)
//!   before it is returned.
//!
//! Costs grow with the number `k` of independent radicals: an element has up to `2^k` terms, a
//! product up to `4^k` term products, and the inverse and square root recurse through norms
//! of half the size. The workspace's own formulas have `k <= 3`; input from the command line is
//! bounded by the limit `radicands` ([`exactcheck_core::limits::RADICANDS`], default 10: the
//! inverse of ten roots takes well under a second, twelve took 10-16 s, twenty-five asked for
//! terabytes). The count is [`Radical::independent_radicals`] (the rank of the radicands modulo
//! squares, through a coprime base, no factoring), checked by the expression evaluator on every
//! folded constant and coefficient ([`crate::expr::Coefficient::check_limits`]) before the value
//! is multiplied, inverted or denested.
//!
//! The square-free part of a big integer is found by trial division, dividing out each prime's
//! whole power in `O(log e)` big divisions, and stopping as soon as the cofactor fits 64 bits
//! (then factored completely) or is a perfect square; the latter is the common case of the norms
//! met in denesting, where running the trial division to its bound made `sqrt((S10)^2)` take
//! 3-14 s. A cofactor that is neither, with no prime factor below the bound, is reported as out
//! of reach naming the bound ([`crate::expr::Coefficient::sqrt_hint_for`]).
//!
//! # Layout
//! * `radicand`: [`Radicand`] and square-free factoring (number theory on 64-bit integers);
//! * `field`: [`Radical`], the multi-quadratic field (arithmetic, sign, square roots, printing);
//! * `complex`: [`ComplexRadical`];
//! * here: the operator plumbing shared by both number types;
//! * parsing (`FromStr`, which evaluates an expression of [`crate::expr`] in the number type)
//!   lives with the grammar, in `expr::numbers`, so that this module does not depend on it.

use crate::coefficient::Coefficient;
use crate::rational::Rational;
use exactcheck_core::limits::LimitError;
use exactcheck_core::{Field, OrderedField, Sign, Sqrt};

// ====================================================================== operator plumbing

mod complex;
mod field;
mod radicand;
#[cfg(test)]
mod tests;

pub use complex::ComplexRadical;
pub use field::Radical;
pub use radicand::Radicand;

exactcheck_core::ring_ops! {
    impl[] Radical;
    Neg::neg: |a| a.neg_borrowed(), owned |a| a.neg_in_place();
    Add::add, AddAssign::add_assign: |a, b| a.add_borrowed(b), owned |a, b| a.add_owned(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_borrowed(b), owned |a, b| a.sub_owned(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_borrowed(b), owned |a, b| a.mul_owned(b);
    Div::div, DivAssign::div_assign: |a, b| a.div_borrowed(b), owned |a, b| a.div_owned(b);
}

exactcheck_core::ring_ops! {
    impl[] ComplexRadical;
    Neg::neg: |a| a.neg_borrowed(), owned |a| a.neg_in_place();
    Add::add, AddAssign::add_assign: |a, b| a.add_borrowed(b), owned |a, b| a.add_owned(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_borrowed(b), owned |a, b| a.sub_owned(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_borrowed(b), owned |a, b| a.mul_owned(b);
    Div::div, DivAssign::div_assign: |a, b| a.div_borrowed(b), owned |a, b| a.div_owned(b);
}

impl Coefficient for Radical {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(Radical::from(q))
    }
    fn try_inverse(&self) -> Option<Self> {
        self.inv().ok()
    }
    fn try_sqrt(&self) -> Option<Self> {
        Sqrt::sqrt(self)
    }
    fn try_abs(&self) -> Option<Self> {
        Some(if self.sign() == Sign::Negative {
            -self.clone()
        } else {
            self.clone()
        })
    }
    fn sqrt_hint() -> &'static str {
        " (no square root in the square-root field: negative, or not denestable)"
    }
    /// Says which: negative; a positive rational whose square-free part could not be certified
    /// (names the trial-division bound); or an irrational value that does not denest.
    fn sqrt_hint_for(&self) -> &'static str {
        match (self.sign(), self.is_rational()) {
            (Sign::Negative, _) => " (it is negative: no real square root)",
            (_, true) => {
                " (its square-free part is out of reach: a factor beyond 64 bits has no prime \
                 factor below the trial-division bound 2^20 (2^14 beyond 512 bits) and is not a \
                 square)"
            }
            _ => {
                " (no square root in the square-root field: not denestable, or a rational met in \
                 denesting has a factor beyond 64 bits with no prime factor below the \
                 trial-division bound 2^20)"
            }
        }
    }
    fn check_limits(&self) -> Result<(), LimitError> {
        self.check_radicands()
    }
    /// The largest size of a term `c sqrt(m)`: `size_bits(c) + floor(log2 m) / 2`.
    fn size_bits(&self) -> u64 {
        self.terms()
            .iter()
            .map(|(m, c)| c.size_bits() + m.to_biguint().bits().saturating_sub(1) / 2)
            .max()
            .unwrap_or(0)
    }
    fn size_within(&self, max: u64) -> bool {
        self.terms()
            .iter()
            .all(|(m, c)| c.size_within(max.saturating_sub(m.to_biguint().bits() / 2)))
    }
}

impl Coefficient for ComplexRadical {
    fn from_rational(q: &Rational) -> Option<Self> {
        Some(ComplexRadical::from(q.clone()))
    }
    fn try_inverse(&self) -> Option<Self> {
        self.inv().ok()
    }
    fn try_sqrt(&self) -> Option<Self> {
        self.principal_sqrt()
    }
    /// `|a + b i| = sqrt(a^2 + b^2)`, the non-negative real root (when it lies in the field).
    fn try_abs(&self) -> Option<Self> {
        let square = &self.re * &self.re + &self.im * &self.im;
        Coefficient::try_abs(&self.re)
            .filter(|_| self.is_real())
            .or_else(|| Sqrt::sqrt(&square))
            .map(ComplexRadical::from)
    }
    fn size_bits(&self) -> u64 {
        self.re.size_bits().max(self.im.size_bits())
    }
    /// `i`, the imaginary unit.
    fn named_constant(name: &str) -> Option<Self> {
        (name == "i").then(ComplexRadical::i)
    }
    /// The independent square roots of the real and imaginary parts together, against
    /// [`exactcheck_core::limits::RADICANDS`].
    fn check_limits(&self) -> Result<(), LimitError> {
        let max = exactcheck_core::limits::RADICANDS.get_usize();
        let (re, im) = (self.re.terms(), self.im.terms());
        let mut radicands = re.iter().chain(im).map(|(m, _)| m).filter(|m| !m.is_one());
        if radicands.clone().count() <= max {
            return Ok(());
        }
        let k = radicand::independent_count(&mut radicands);
        exactcheck_core::limits::RADICANDS.check_usize(k)
    }
}
