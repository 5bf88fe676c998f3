//! Randomized identity testing (`prove --random K`): evaluate `LHS - RHS` at `K` random points
//! modulo a prime drawn at random for the run, without expanding anything, and bound the
//! probability that a false identity passes — for every input, not only for inputs whose
//! coefficients happen to be prime to a fixed modulus.
//!
//! # Why the prime is random
//! With a fixed prime `p` the test is blind to every identity over Q whose difference has all
//! coefficients divisible by `p` (`(2^61 - 1) x = 0` modulo `2^61 - 1`), and to exponents that
//! Fermat reduces (`x^p = x` modulo `p`). Here `p` is drawn uniformly from the primes in
//! `[2^62, 2^63)` ([`PrimeField::random_62`]) from the run's seed.
//!
//! # Where the seed comes from
//! The generator of the prime and the points is [`Rng::for_input`]`(seed, text)`, with `text` the
//! printed expression trees of both sides, the variables and the circles: the prime depends on
//! the seed *and* on the identity. The bound below is a probability over the prime, so it holds
//! only when the seed is independent of the identity:
//! * [`Seed::Fresh`] (drawn from the operating system for this run): the seed is uniform and
//!   independent of the input, hence so is the generator's seed `for_sample(seed, h)` for every
//!   input hash `h`, and the bound holds for every input;
//! * [`Seed::Chosen`] (given to reproduce a run): nothing makes it independent of the identity.
//!   A user who learns the prime of one run could otherwise write an identity whose coefficients
//!   it divides; since the prime now changes with the identity, the prime learnt is not the one
//!   used, but the derivation is not a cryptographic hash, so no probability is claimed: a
//!   chosen-seed run that finds zero at every point is [`RandomDecision::Reproduced`], never
//!   `Holds`, and carries no bound.
//!
//! # The bound
//! Write `LHS - RHS = F / D` with `F`, `D` in `Z[x]`, `D != 0`, built from the tree by the rules
//! below (not reduced). [`size_bound`] computes from the expression tree, without expanding,
//! numbers `L`, `L_D`, `d`, `e` with `log2 ||F||_1 <= L`, `log2 ||D||_1 <= L_D`, `deg F <= d`
//! and `deg D <= e` (`||F||_1` is the sum of the absolute values of the coefficients), by
//! structural induction, each rule being the triangle inequality and
//! `||F G||_1 <= ||F||_1 ||G||_1`:
//! * a number `n/d` (lowest terms): `F = n`, `D = d`: `L = bits(|n|)`, `L_D = bits(d)` (0 for
//!   `d = 1`);
//!   a variable: `L = L_D = 0`, degree 1; a negation changes nothing;
//! * a sum of `m` terms `F_i / D_i`: `F = sum_i F_i prod_{j != i} D_j`, `D = prod D_j`, so
//!   `L = ceil(log2 m) + max_i (L_i + sum_{j != i} L_Dj)` (for two terms
//!   `max(L_F + L_DG, L_G + L_DF) + 1`), `L_D = sum L_Dj`, `d = max_i (d_i + sum_{j != i} e_j)`,
//!   `e = sum e_j`;
//! * a product: `L = sum L_i`, `L_D = sum L_Di`, degrees the sums; a division by
//!   `F_c / D_c` multiplies by `D_c / F_c`: `L += L_Dc`, `L_D += L_c`, `d += e_c`, `e += d_c`;
//! * a power `b^k` (`k` a non-negative integer literal): `k L_b`, `k L_Db`, `k d_b`, `k e_b`;
//!   a power with a negative exponent is first written as a division, `b^(-k) = 1/b^k`.
//!
//! All of these are checked `u64` operations; an overflow makes the test report `undecided`
//! (it never wraps). Square roots of constants and angles are rewritten first (below,
//! "Constants and angles"); a square root of an expression is a generator `w` with `w^2` its
//! radicand, in a ring built at each point, with its own bounds and proof ([`roots`]). The
//! functions of the language are lowered first ([`crate::expr::lower`]): `binomial` and
//! `factorial` become integers, `sum` its unrolled terms, `diff` and `integrate` their exact
//! value expanded (the one expansion random mode does, with the square roots and the cosines
//! and sines written back as calls); the bound is then that of the lowered tree.
//!
//! A point where a divisor with a variable vanishes modulo `p` (a pole) is not in the domain of
//! the identity: it is skipped and another point drawn; `MAX_POLES` poles in a row are an
//! error (the divisor is then, with overwhelming probability, zero).
//!
//! A unit circle `c^2 + s^2 = 1` is sampled as `c = (1 - t^2)/(1 + t^2)`, `s = 2t/(1 + t^2)`
//! with `t` uniform among the residues where `1 + t^2 != 0`. Then
//! `G(t, x) = F(c(t), s(t), x) prod_i (1 + t_i^2)^d` is a polynomial; a monomial
//! `c^a s^b m` becomes `(1 - t^2)^a (2t)^b (1 + t^2)^{d - a - b} m`, of 1-norm at most `2^d` and
//! degree at most `2d + deg m`, so with `k` circles `||G||_1 <= 2^{dk} ||F||_1` and
//! `deg G <= d (1 + 2k)`. Likewise `H = D(c(t), s(t), x) prod_i (1 + t_i^2)^e` has degree at
//! most `e' = e (1 + 2k)`. If the identity is false modulo the circles, `G != 0` over Q (its
//! rational-function image is non-zero).
//!
//! **Theorem.** Let the identity be false (modulo the unit circles), `L' = L + dk`,
//! `d' = d(1 + 2k)`, `e' = e(1 + 2k)`, and `N` the number of primes in `[2^62, 2^63)`. The
//! probability that all `K` points give zero is at most
//!
//! `floor(L'/62) / (N - floor(L_D/62)) + (d' / (2^62 - 2k - e'))^K`.
//!
//! *Proof.* (1) The prime. The integer constants the evaluation inverts (denominators of
//! numbers, constant divisors) multiply to an integer `c` that divides the content of `D`, so
//! `|c| <= ||D||_1 <= 2^{L_D}`. A prime dividing one of them is detected (the inversion fails)
//! and discarded, and a new one drawn, so the prime used is uniform over the primes of the
//! range not dividing `c`, of which at least `N - floor(L_D/62)` remain (`c` has at most
//! `floor(L_D/62)` prime factors `>= 2^62`). `G` has a non-zero integer coefficient of absolute
//! value at most `||G||_1 <= 2^{L'}`, which likewise has at most `floor(L'/62)` prime factors
//! in the range; only those primes can make `G` vanish identically modulo `p`. (2) The points.
//! By induction over the tree, every inversion of the evaluation succeeds exactly when
//! `D != 0` at the point (each node's `D` divides its parent's, and a divisor's value is
//! `F_c / D_c` with `F_c` a factor of `D`), and then the value is `F / D` there. Points are
//! drawn uniformly until one is not a pole, so each is uniform on the set `S` of circle points
//! where `H != 0`: `|S| >= p^n (1 - 2k/p) - e' p^{n-1}` (each circle parameter avoids at most 2
//! residues; `H`, non-zero modulo `p` when a point of `S` exists, has at most `e' p^{n-1}`
//! zeros, Schwartz–Zippel). For `p` with `G mod p != 0`, `G` has at most `d' p^{n-1}` zeros, so
//! a point of `S` is a zero of `G` with probability at most `d' / (p - 2k - e') <=
//! d' / (2^62 - 2k - e')`; the `K` points are independent. At a point of `S`, the evaluated
//! value is `(G / H) prod (1 + t_i^2)^{e - d}`, so it is zero exactly
//! when `G` is. ∎
//!
//! `N > 2^56`: by Rosser and Schoenfeld (1962), `x / ln x < pi(x) < 1.25506 x / ln x` for
//! `x >= 17`, so `N = pi(2^63) - pi(2^62) > 2^63 / (63 ln 2) - 1.25506 · 2^62 / (62 ln 2)
//! = 2^62 (2 / 43.6683 - 1.25506 / 42.9752) > 2^62 (0.045800 - 0.029205) = 2^62 · 0.016595
//! > 2^62 · 2^-5.92 > 2^56`. The bound uses `N = 2^56`.
//!
//! # Constants and angles
//! An identity with `sin`, `cos`, `tan` or square roots of constants is rewritten exactly as the
//! exact path rewrites it ([`algebraic`]): its irrational constants (`sqrt(2)`, `cos(pi/8)`,
//! `sqrt(2 + sqrt(3))`, the multiples of pi of angles with variables) are replaced by
//! polynomials over Q in one primitive element `c` of their field, whose minimal polynomial `m`
//! (primitive, integer coefficients, degree `n`) gives `m(c) = 0`; each angle `x` by the
//! variables `cos(x)`, `sin(x)` on their unit circle, through the multiple-angle and addition
//! formulas ([`crate::expr::expand_angles`]), `tan` as `sin/cos` (the points where a cosine
//! vanishes are poles, skipped). The bounds `L`, `L_D`, `d`, `e` above are those of the
//! rewritten tree, with `c` counted as a variable.
//!
//! The tree is then evaluated in `R = F_p[c]/(m mod p)`, the image of `Z[c]/(m)` modulo `p`
//! ([`ring::QuotientRing`]): every variable a residue, `c` its class. `R` exists for every prime
//! not dividing `lc(m)` (the others are redrawn), whether `m` has a root modulo `p` or not — a
//! test at a root `r` of `m` modulo `p` would draw `p` among the primes where `m` has a root,
//! and no unconditional lower bound on their number in `[2^62, 2^63)` is known (the effective
//! Chebotarev theorems need the Riemann hypothesis or far larger ranges), so no bound could be
//! proved for it.
//!
//! **Theorem.** With `M >= log2 ||m||_1`, `lambda = bits(|lc(m)|)`, the probability that a false
//! identity passes `K` points is at most
//!
//! `floor((d' M + n L')/62) / (N - floor((e' M + n L_D)/62) - floor(lambda/62)) +
//! (d' / (2^62 - 2k - n e'))^K`,
//!
//! which is the bound above for `n = 1`, `M = lambda = 0`.
//!
//! *Proof.* Let `G(t, x, c)` be as above (the circles parametrized); `G` has integer
//! coefficients. (0) A true identity: `F` lies in the ideal of `m` and the circles over Q, so
//! `m` divides `G` in `Q[t, x, c]` (the circles vanish under the parametrization, and division by
//! `m` in `c` is unique), hence in `Z[t, x, c]` (Gauss's lemma, `m` primitive), so `G` is zero in
//! `R[t, x]` and every point evaluates to zero. (1) The prime. For a false identity, `G(t, x,
//! theta) != 0`, so some coefficient `a(c)` of `G` (in `Z[c]`, `deg a <= d'`,
//! `||a||_1 <= 2^{L'}`) is not divisible by the irreducible `m`: the resultant `Res(m, a)` is a
//! non-zero integer, of absolute value at most `||m||_2^{deg a} ||a||_2^n <= 2^{d' M + n L'}`
//! (Hadamard). If `G` is zero in `R[t, x]`, then `m mod p` divides `a mod p`, so they share a
//! factor and `p` divides `Res(m, a)` (`p` not dividing `lc(m)`): at most
//! `floor((d' M + n L')/62)` primes of the range. The primes redrawn divide `lc(m)` or the
//! resultant with `m` of a constant divisor's numerator `F_c` (a divisor in `c` alone that is
//! not a unit of `R`); by the structural rules these numerators multiply to at most
//! `2^{L_D}` in 1-norm and `e` in degree, so they exclude at most
//! `floor((e' M + n L_D)/62) + floor(lambda/62)` primes. (2) The points. In the basis `1, c,
//! ..., c^{n-1}` of `R` over `F_p`, `G` is `n` polynomials over `F_p`, one of them non-zero,
//! with at most `d' p^{N-1}` zeros, and `G` vanishes at a point only where all do. The points
//! where `H` is not a unit of `R` are the zeros of its norm, a polynomial of degree at most
//! `n e'` (non-zero when any point is not a pole), so each point is uniform on a set of at least
//! `p^N (1 - (2k + n e')/p)` points, as above. ∎
//!
//! A point where the sides differ modulo `p` shows the identity false, but `fails` is said only
//! with an exact counter-example: the same rewritten trees are evaluated exactly, in `Q(theta)`
//! (or Q), at rational values of the variables, rational points of the circles and
//! `c = theta` ([`algebraic::confirm`]); when none is found, or none can be given (an angle also
//! used as a number, `pi` outside an angle), the answer is
//! [`RandomDecision::Unconfirmed`], worded `undecided`.
//!
//! Without square roots of expressions, a non-zero value at a point is a proof that the identity
//! is false (over Q, and modulo the circles: a multiple of `c^2 + s^2 - 1` with integer
//! coefficients vanishes at every circle point modulo every `p`); with them it is not (the roots
//! are tested for either sign), and the answer is [`RandomDecision::Unconfirmed`]. The verdict `holds` is given only when the seed is fresh and the bound is
//! below `2^HOLDS_THRESHOLD_LOG2` ([`HOLDS_THRESHOLD_LOG2`] `= -30`); otherwise `undecided` with
//! the bound (or, with a chosen seed, `Reproduced` without one).

mod algebraic;
mod ring;
mod roots;

pub use algebraic::{ExactPoint, FieldBound};

use crate::expr::{lower, Expr, ExprKind, MulOp};
use crate::modp::PrimeField;
use algebraic::Prepared;
use exactcheck_core::Rng;
use ring::{constant_exponent, eval, powers_as_divisions, EvalError, QuotientRing, Values};
use std::collections::HashMap;
use std::fmt;

/// `holds` only when the error bound is below `2^HOLDS_THRESHOLD_LOG2`.
pub const HOLDS_THRESHOLD_LOG2: f64 = -30.0;

/// The most random points one run may evaluate.
pub const MAX_RANDOM_TRIALS: u32 = 100_000;

/// Primes are redrawn at most this often when one divides a constant divisor; after that the
/// divisor is (with overwhelming probability) zero, which is an error.
const MAX_PRIME_REDRAWS: u32 = 64;

/// Points are redrawn at most this often in a row when a divisor vanishes there (a pole); after
/// that the divisor is (with overwhelming probability) zero, which is an error.
const MAX_POLES: u32 = 64;

/// `log2 N` for the lower bound `N = 2^56` on the number of primes in `[2^62, 2^63)`.
const LOG2_PRIMES: u32 = 56;

/// Bounds on `F / D` for an expression (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizeBound {
    /// `log2 ||F||_1 <= num_bits`.
    pub num_bits: u64,
    /// `log2 D <= den_bits`.
    pub den_bits: u64,
    /// `deg F <= degree`.
    pub degree: u64,
    /// `deg D <= den_degree` (0 when every divisor is a constant).
    pub den_degree: u64,
}

/// Why [`size_bound`] gave no bound.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BoundError {
    /// Not a polynomial expression this test handles (the message says why).
    Input(String),
    /// A bound does not fit in 64 bits.
    Overflow,
}

fn bits_of(n: &num_bigint::BigInt) -> u64 {
    n.bits()
}

fn ceil_log2(m: usize) -> u64 {
    (usize::BITS - m.saturating_sub(1).leading_zeros()) as u64
}

/// The structural bounds of the module documentation for one expression.
///
/// # Errors
/// [`BoundError::Input`] for a square root, a non-constant divisor or a non-literal exponent;
/// [`BoundError::Overflow`] when a bound exceeds `u64`.
pub fn size_bound(e: &Expr) -> Result<SizeBound, BoundError> {
    size_bound_in(e, &HashMap::new())
}

/// [`size_bound`] with the variables of `leaves` bounded as given (the square roots of
/// expressions, [`roots`]) instead of as variables.
pub(crate) fn size_bound_in(
    e: &Expr,
    leaves: &HashMap<String, SizeBound>,
) -> Result<SizeBound, BoundError> {
    let of = BoundError::Overflow;
    Ok(match &e.kind {
        ExprKind::Number(q) => SizeBound {
            num_bits: bits_of(&q.numer()),
            den_bits: if q.is_integer() {
                0
            } else {
                bits_of(&q.denom())
            },
            degree: 0,
            den_degree: 0,
        },
        ExprKind::Var(v) if leaves.contains_key(v) => leaves[v],
        ExprKind::Var(_) => SizeBound {
            num_bits: 0,
            den_bits: 0,
            degree: 1,
            den_degree: 0,
        },
        ExprKind::Neg(x) => size_bound_in(x, leaves)?,
        ExprKind::Sum(ts) => {
            let parts = ts
                .iter()
                .map(|(_, t)| size_bound_in(t, leaves))
                .collect::<Result<Vec<_>, _>>()?;
            let den_bits = parts
                .iter()
                .try_fold(0u64, |a, b| a.checked_add(b.den_bits))
                .ok_or(of.clone())?;
            let den_degree = parts
                .iter()
                .try_fold(0u64, |a, b| a.checked_add(b.den_degree))
                .ok_or(of.clone())?;
            let (mut num, mut degree) = (0u64, 0u64);
            for b in &parts {
                // L_i + sum_{j != i} L_Dj = L_i + (L_D - L_Di), and likewise for degrees.
                let v = b
                    .num_bits
                    .checked_add(den_bits - b.den_bits)
                    .ok_or(of.clone())?;
                num = num.max(v);
                let d = b
                    .degree
                    .checked_add(den_degree - b.den_degree)
                    .ok_or(of.clone())?;
                degree = degree.max(d);
            }
            SizeBound {
                num_bits: num.checked_add(ceil_log2(parts.len())).ok_or(of)?,
                den_bits,
                degree,
                den_degree,
            }
        }
        ExprKind::Product(fs) => {
            let mut acc = SizeBound {
                num_bits: 0,
                den_bits: 0,
                degree: 0,
                den_degree: 0,
            };
            for (op, f) in fs {
                let b = size_bound_in(f, leaves)?;
                // Dividing by F_b / D_b multiplies by D_b / F_b.
                let (num, den, deg, den_deg) = match op {
                    MulOp::Times | MulOp::Dot | MulOp::Cross => (b.num_bits, b.den_bits, b.degree, b.den_degree),
                    MulOp::Divide => (b.den_bits, b.num_bits, b.den_degree, b.degree),
                };
                acc.num_bits = acc.num_bits.checked_add(num).ok_or(of.clone())?;
                acc.den_bits = acc.den_bits.checked_add(den).ok_or(of.clone())?;
                acc.degree = acc.degree.checked_add(deg).ok_or(of.clone())?;
                acc.den_degree = acc.den_degree.checked_add(den_deg).ok_or(of.clone())?;
            }
            acc
        }
        ExprKind::Pow(b, x) => {
            let k = constant_exponent(x).ok_or_else(|| {
                BoundError::Input(
                    "exponents must be integer numbers from 0 to 2^64 - 1 in --random mode"
                        .into(),
                )
            })?;
            let b = size_bound_in(b, leaves)?;
            SizeBound {
                num_bits: b.num_bits.checked_mul(k).ok_or(of.clone())?,
                den_bits: b.den_bits.checked_mul(k).ok_or(of.clone())?,
                degree: b.degree.checked_mul(k).ok_or(of.clone())?,
                den_degree: b.den_degree.checked_mul(k).ok_or(of)?,
            }
        }
        ExprKind::Call(name, _) => return Err(BoundError::Input(unsupported_call(name))),
        ExprKind::Sqrt(_) => {
            return Err(BoundError::Input(
                "sqrt of a non-constant is not supported by --random (no error bound is proved for square roots of expressions modulo p); run without --random, which decides it exactly".into(),
            ))
        }
    })
}

/// The refusal of a function call in random mode. The functions of the language (`diff`,
/// `integrate`, `sum`, `binomial`, `factorial`) are exact operations on whole polynomials or
/// rational functions: evaluating them at a point modulo `p` needs their expansion, and no
/// degree or size bound of that expansion is derived from the tree here, so they are refused
/// rather than bounded wrongly.
fn unsupported_call(name: &str) -> String {
    if crate::expr::FUNCTIONS.contains(&name) {
        format!(
            "{name}(...) is not supported by --random (no error bound is proved for it modulo \
             p); run without --random, which expands it exactly"
        )
    } else {
        format!("unknown function '{name}'")
    }
}

/// The seed of a run and where it came from (module documentation, "Where the seed comes
/// from").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seed {
    /// Drawn for this run independently of the identity: the error bound holds.
    Fresh(u64),
    /// Given by the user (to reproduce a run): no error bound is claimed.
    Chosen(u64),
}

impl Seed {
    /// The seed's value.
    pub fn value(self) -> u64 {
        match self {
            Seed::Fresh(s) | Seed::Chosen(s) => s,
        }
    }
}

/// What a random test did, for the evidence.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomReport {
    /// The seed of the run.
    pub seed: Seed,
    /// The prime used.
    pub prime: u64,
    /// Primes discarded because they divide a constant divisor.
    pub redrawn: u32,
    /// Points evaluated.
    pub trials: u32,
    /// Points drawn and skipped because a divisor vanishes there (poles).
    pub poles: u32,
    /// The constants' field as `prove` describes it (`with c = cos(pi/5), 4*c^2 - 2*c - 1 =
    /// 0`), when the identity has irrational constants.
    pub constants: Option<String>,
    /// What the constants' field adds to the error bound.
    pub field: Option<FieldBound>,
    /// The angles of `sin`, `cos`, `tan`, tested on their unit circles.
    pub angles: Vec<String>,
    /// Whether a side has `tan` (points where its cosine vanishes are skipped as poles).
    pub tan: bool,
    /// The square roots of expressions, as written, each a generator `w` with `w^2` its
    /// radicand ([`roots`]).
    pub roots: Vec<String>,
}

/// The outcome of a randomized identity test.
#[derive(Clone, Debug, PartialEq)]
pub enum RandomDecision {
    /// Zero at every point, the seed was fresh and the error bound is below the threshold.
    Holds {
        /// The run.
        report: RandomReport,
        /// The bounds `L'`, `L_D`, `d'` used.
        bound: SizeBound,
        /// log2 of the error probability bound (below [`HOLDS_THRESHOLD_LOG2`]).
        log2_bound: f64,
    },
    /// Zero at every point with a [`Seed::Chosen`], where a fresh seed's bound would be below
    /// the threshold: the run is reproduced, but no probability bound is claimed.
    Reproduced {
        /// The run.
        report: RandomReport,
    },
    /// Zero at every point, but the bound is not small enough (or could not be computed).
    Undecided {
        /// The run.
        report: RandomReport,
        /// The bounds used (`None` when they overflow).
        bound: Option<SizeBound>,
        /// log2 of the error probability bound (at most 0).
        log2_bound: f64,
    },
    /// Non-zero at a point modulo p: the identity is false (over Q as well).
    Fails {
        /// The run.
        report: RandomReport,
        /// The point, as residues modulo the prime.
        point: Vec<(String, u64)>,
        /// The residual there.
        value: u64,
    },
    /// With constants or angles: non-zero at a point modulo the prime, and an exact
    /// counter-example found at a rational point.
    Refuted {
        /// The run.
        report: RandomReport,
        /// The exact counter-example.
        exact: ExactPoint,
    },
    /// With constants or angles: non-zero at a point modulo the prime (which shows the identity
    /// false), but no exact counter-example was found or can be given.
    Unconfirmed {
        /// The run.
        report: RandomReport,
        /// The point modulo the prime where the sides differ.
        point: Vec<(String, u64)>,
        /// Why no exact counter-example is given.
        why: String,
    },
}

/// `log2(floor(L'/62) / (2^56 - floor(L_D/62)) + (d'/(2^62 - 2k - e'))^K)`, rounded up (0 when
/// the bound is not below 1).
pub fn log2_error_bound(bound: &SizeBound, circles: usize, trials: u32) -> f64 {
    log2_error_bound_in(bound, None, circles, trials)
}

/// [`log2_error_bound`] with the algebraic constants' field (module documentation, "Constants
/// and angles"): with `n`, `M`, `lambda` of the [`FieldBound`],
/// `log2(floor((d' M + n L')/62) / (2^56 - floor((e' M + n L_D)/62) - floor(lambda/62))
/// + (d'/(2^62 - 2k - n e'))^K)`; without a field `n = 1`, `M = lambda = 0`.
pub fn log2_error_bound_in(
    bound: &SizeBound,
    field: Option<&FieldBound>,
    circles: usize,
    trials: u32,
) -> f64 {
    let (n, m, lead) = field.map_or((1u128, 0u128, 0u128), |f| {
        (
            u128::from(f.degree),
            u128::from(f.modulus_bits),
            u128::from(f.lead_bits),
        )
    });
    let (d, e) = (u128::from(bound.degree), u128::from(bound.den_degree));
    let bad_primes = ((d * m + n * u128::from(bound.num_bits)) / 62) as f64;
    let excluded = ((e * m + n * u128::from(bound.den_bits)) / 62 + lead / 62) as f64;
    let primes = 2f64.powi(LOG2_PRIMES as i32);
    if excluded >= primes {
        return 0.0;
    }
    let prime_term = bad_primes / (primes - excluded);
    let per_point = d as f64 / (2f64.powi(62) - 2.0 * circles as f64 - (n * e) as f64);
    if per_point < 0.0 {
        return 0.0;
    }
    if prime_term >= 1.0 || per_point >= 1.0 {
        return 0.0;
    }
    let l1 = if bad_primes == 0.0 {
        f64::NEG_INFINITY
    } else {
        prime_term.log2()
    };
    let l2 = if bound.degree == 0 {
        f64::NEG_INFINITY
    } else {
        trials as f64 * per_point.log2()
    };
    let (hi, lo) = if l1 >= l2 { (l1, l2) } else { (l2, l1) };
    if hi == f64::NEG_INFINITY {
        return f64::NEG_INFINITY;
    }
    // log2(2^hi + 2^lo), plus a margin that covers the floating-point rounding.
    let sum = hi + (1.0 + (lo - hi).exp2()).log2();
    (sum + 1e-9 * sum.abs().max(1.0)).min(0.0)
}

/// The bounds of `LHS - RHS` with `k` unit circles (`L'`, `L_D`, `d'`, `e'` of the module
/// documentation), `None` when one overflows.
fn difference_bound(l: &SizeBound, r: &SizeBound, k: u64) -> Option<SizeBound> {
    let num = (l.num_bits.checked_add(r.den_bits)?)
        .max(r.num_bits.checked_add(l.den_bits)?)
        .checked_add(1)?;
    // LHS - RHS = (F_l D_r - F_r D_l) / (D_l D_r).
    let degree = (l.degree.checked_add(r.den_degree)?).max(r.degree.checked_add(l.den_degree)?);
    let den_degree = l.den_degree.checked_add(r.den_degree)?;
    let spread = k.checked_mul(2)?.checked_add(1)?;
    Some(SizeBound {
        num_bits: num.checked_add(degree.checked_mul(k)?)?,
        den_bits: l.den_bits.checked_add(r.den_bits)?,
        degree: degree.checked_mul(spread)?,
        den_degree: den_degree.checked_mul(spread)?,
    })
}

/// Tests `lhs = rhs` at `trials` random points modulo a random prime (see the module
/// documentation); variables on unit circles `(c, s)` are drawn on the circle. The prime and
/// the points come from `seed` and the identity (`Rng::for_input`). Square roots of constants,
/// `sin`, `cos`, `tan` of angles and the constants of angles are rewritten first (module
/// documentation, "Constants and angles").
///
/// # Errors
/// A message for `trials` outside `1..=MAX_RANDOM_TRIALS`, a square root of a non-constant, a
/// non-polynomial expression, a constant the evaluator refuses (`tan(pi/2)`), or a constant
/// divisor that is zero (modulo `MAX_PRIME_REDRAWS` random primes).
pub fn random_identity_test(
    lhs: &Expr,
    rhs: &Expr,
    variables: &[String],
    circles: &[(String, String)],
    trials: u32,
    seed: Seed,
) -> Result<RandomDecision, String> {
    if !(1..=MAX_RANDOM_TRIALS).contains(&trials) {
        return Err(format!(
            "--random takes 1 to {MAX_RANDOM_TRIALS} points, not {trials}"
        ));
    }
    let (lhs, rhs) = (
        powers_as_divisions(&lower(lhs).map_err(|e| e.to_string())?),
        powers_as_divisions(&lower(rhs).map_err(|e| e.to_string())?),
    );
    let mut taken: Vec<String> = variables.to_vec();
    lhs.collect_variables(&mut taken);
    rhs.collect_variables(&mut taken);
    taken.extend(circles.iter().flat_map(|(c, s)| [c.clone(), s.clone()]));
    let (lhs, rhs, roots) = roots::abstract_roots(&lhs, &rhs, &taken)?;
    let (lhs, rhs) = (&lhs, &rhs);
    let sides = Sides {
        lhs,
        rhs,
        roots: &roots,
    };
    if !(algebraic::needs_preparation(lhs) || algebraic::needs_preparation(rhs)) {
        return run(&sides, variables, circles, trials, seed, None);
    }
    taken.extend(roots.iter().map(|r| r.name.clone()));
    let prepared = algebraic::prepare(lhs, rhs, &taken)?;
    let mut all_circles = circles.to_vec();
    all_circles.extend(prepared.angle_circles.iter().cloned());
    let mut names = Vec::new();
    prepared.lhs.collect_variables(&mut names);
    prepared.rhs.collect_variables(&mut names);
    // A variable only under a root is one of the point too.
    for root in &roots {
        root.radicand.collect_variables(&mut names);
    }
    let generator = prepared.constants.as_ref().map(|k| k.name.clone());
    let free: Vec<String> = names
        .into_iter()
        .filter(|n| {
            Some(n) != generator.as_ref()
                && !all_circles.iter().any(|(c, s)| c == n || s == n)
                && !roots.iter().any(|r| r.name == *n)
        })
        .collect();
    let sides = Sides {
        lhs: &prepared.lhs,
        rhs: &prepared.rhs,
        roots: &roots,
    };
    run(&sides, &free, &all_circles, trials, seed, Some(&prepared))
}

/// The ring of one prime: `Z/pZ`, or the quotient ring of the constants' field.
enum Modular {
    Field(PrimeField),
    Quotient(QuotientRing),
}

/// The sides of the test, the square roots of expressions abstracted ([`roots`]).
struct Sides<'a> {
    lhs: &'a Expr,
    rhs: &'a Expr,
    roots: &'a [roots::Root],
}

/// The sides at one point (residues of the variables in `values`), evaluated in `ring`, or in
/// the tower of the square roots over it: `LHS - RHS`, zero or not.
fn difference_at<R: Values>(
    sides: &Sides<'_>,
    ring: &R,
    values: &HashMap<String, u64>,
    embed: &dyn Fn(u64) -> R::V,
    generator: Option<(&str, R::V)>,
) -> Result<bool, EvalError> {
    let mut point: HashMap<String, R::V> =
        values.iter().map(|(v, x)| (v.clone(), embed(*x))).collect();
    if let Some((name, c)) = &generator {
        point.insert(name.to_string(), c.clone());
    }
    let constant = |v: &str| generator.as_ref().is_some_and(|(n, _)| *n == v);
    let refused = |e: &Expr| match &e.kind {
        ExprKind::Call(name, _) => unsupported_call(name),
        _ => "sqrt of a non-constant is not supported by --random; run without --random".into(),
    };
    if sides.roots.is_empty() {
        return differs(sides, ring, &point, &constant, &refused);
    }
    let (tower, lifted) = roots::Tower::at(ring, sides.roots, &point, &constant, &refused)?;
    differs(sides, &tower, &lifted, &constant, &refused)
}

/// Whether `LHS - RHS` is non-zero in `ring` at `point`.
fn differs<R: Values>(
    sides: &Sides<'_>,
    ring: &R,
    point: &HashMap<String, R::V>,
    constant: &dyn Fn(&str) -> bool,
    refused: &dyn Fn(&Expr) -> String,
) -> Result<bool, EvalError> {
    let l = eval(sides.lhs, ring, point, constant, refused);
    let r = eval(sides.rhs, ring, point, constant, refused);
    match (l, r) {
        (Ok(a), Ok(b)) => Ok(!ring.is_zero(&ring.sub(&a, &b))),
        (Err(EvalError::Input(m)), _) | (_, Err(EvalError::Input(m))) => Err(EvalError::Input(m)),
        (Err(EvalError::Pole), _) | (_, Err(EvalError::Pole)) => Err(EvalError::Pole),
        _ => Err(EvalError::NotInvertible),
    }
}

/// The test proper, on lowered (and, with `prepared`, rewritten) sides.
fn run(
    sides: &Sides<'_>,
    variables: &[String],
    circles: &[(String, String)],
    trials: u32,
    seed: Seed,
    prepared: Option<&Prepared>,
) -> Result<RandomDecision, String> {
    let (lhs, rhs) = (sides.lhs, sides.rhs);
    let k = circles.len() as u64;
    let bound = match roots::leaf_bounds(sides.roots)
        .map(|leaves| (size_bound_in(lhs, &leaves), size_bound_in(rhs, &leaves)))
    {
        Err(BoundError::Input(m)) => return Err(m),
        Ok((Err(BoundError::Input(m)), _) | (_, Err(BoundError::Input(m)))) => return Err(m),
        Ok((Ok(l), Ok(r))) => difference_bound(&l, &r, k),
        _ => None,
    };
    let modulus = prepared.and_then(Prepared::modulus);
    let field_bound = modulus.as_ref().map(|(_, b)| b.clone());
    let generator = prepared
        .and_then(|p| p.constants.as_ref())
        .map(|k| k.name.as_str());
    let mut input = format!("{lhs}\n{rhs}\n{variables:?}\n{circles:?}");
    for root in sides.roots {
        input += &format!("\n{} = sqrt({})", root.name, root.radicand);
    }
    if let Some(k) = prepared.and_then(|p| p.constants.as_ref()) {
        input += &format!("\n{}", k.relation_text());
    }
    let mut rng = Rng::for_input(seed.value(), input.as_bytes());
    let mut redrawn = 0;
    let redraw = |redrawn: &mut u32| {
        *redrawn += 1;
        if *redrawn > MAX_PRIME_REDRAWS {
            return Err(format!(
                "a divisor is zero modulo {MAX_PRIME_REDRAWS} random primes above 2^62: it is zero"
            ));
        }
        Ok(())
    };
    'prime: loop {
        let field = PrimeField::random_62(&mut rng);
        let ring = match &modulus {
            None => Modular::Field(field),
            Some((m, _)) => match QuotientRing::new(field, m) {
                Some(q) => Modular::Quotient(q),
                None => {
                    // The prime divides the leading coefficient of m.
                    redraw(&mut redrawn)?;
                    continue 'prime;
                }
            },
        };
        let mut report = RandomReport {
            seed,
            prime: field.modulus(),
            redrawn,
            trials,
            poles: 0,
            constants: prepared
                .and_then(|p| p.constants.as_ref())
                .map(|k| k.description()),
            field: field_bound.clone(),
            angles: prepared.map(|p| p.angles.clone()).unwrap_or_default(),
            tan: prepared.is_some_and(|p| p.tan),
            roots: sides.roots.iter().map(|r| r.written.clone()).collect(),
        };
        let mut poles = 0u32;
        let mut done = 0u32;
        while done < trials {
            let mut point: HashMap<String, u64> = variables
                .iter()
                .map(|v| (v.clone(), field.random(&mut rng)))
                .collect();
            for (c, s) in circles {
                let (cv, sv) = loop {
                    let t = field.random(&mut rng);
                    let t2 = field.mul(t, t);
                    if let Ok(inv) = field.inv(field.add(1, t2)) {
                        break (
                            field.mul(field.sub(1, t2), inv),
                            field.mul(field.add(t, t), inv),
                        );
                    }
                };
                point.insert(c.clone(), cv);
                point.insert(s.clone(), sv);
            }
            let differs = match &ring {
                Modular::Field(f) => difference_at(sides, f, &point, &|x| x, None),
                Modular::Quotient(q) => difference_at(
                    sides,
                    q,
                    &point,
                    &|x| {
                        let mut v = q.number(&crate::Rational::ZERO).expect("0 maps");
                        v[0] = x;
                        v
                    },
                    generator.map(|g| (g, q.generator())),
                ),
            };
            let differs = match differs {
                Ok(d) => d,
                Err(EvalError::Input(m)) => return Err(m),
                Err(EvalError::Pole) => {
                    // A pole: the point is not in the domain; another one is drawn.
                    poles += 1;
                    report.poles = report.poles.saturating_add(1);
                    if poles > MAX_POLES {
                        return Err(format!(
                            "a divisor is zero at {MAX_POLES} random points in a row modulo the \
                             random prime p = {}: it is zero (run without --random to see which)",
                            field.modulus()
                        ));
                    }
                    continue;
                }
                Err(EvalError::NotInvertible) => {
                    redraw(&mut redrawn)?;
                    continue 'prime;
                }
            };
            poles = 0;
            done += 1;
            if differs {
                let mut point: Vec<(String, u64)> = point.into_iter().collect();
                point.sort_by(|a, b| a.0.cmp(&b.0));
                if !sides.roots.is_empty() {
                    let why = roots::NOT_A_REFUTATION.to_string();
                    return Ok(RandomDecision::Unconfirmed { report, point, why });
                }
                let Some(prepared) = prepared else {
                    let value = match &ring {
                        Modular::Field(f) => {
                            let l = eval(lhs, f, &scalar(&point), &|_| false, &|_| String::new());
                            let r = eval(rhs, f, &scalar(&point), &|_| false, &|_| String::new());
                            match (l, r) {
                                (Ok(a), Ok(b)) => f.sub(a, b),
                                _ => unreachable!("the point evaluated a moment ago"),
                            }
                        }
                        Modular::Quotient(_) => unreachable!("no constants without preparation"),
                    };
                    return Ok(RandomDecision::Fails {
                        report,
                        point,
                        value,
                    });
                };
                return Ok(match algebraic::confirm(prepared, variables, circles) {
                    Ok(exact) => RandomDecision::Refuted { report, exact },
                    Err(why) => RandomDecision::Unconfirmed { report, point, why },
                });
            }
        }
        return Ok(match bound {
            Some(b) => {
                let log2_bound = roots::norm_bound(&b, sides.roots.len()).map_or(0.0, |n| {
                    log2_error_bound_in(&n, field_bound.as_ref(), circles.len(), trials)
                });
                if log2_bound < HOLDS_THRESHOLD_LOG2 && matches!(seed, Seed::Chosen(_)) {
                    RandomDecision::Reproduced { report }
                } else if log2_bound < HOLDS_THRESHOLD_LOG2 {
                    RandomDecision::Holds {
                        report,
                        bound: b,
                        log2_bound,
                    }
                } else {
                    RandomDecision::Undecided {
                        report,
                        bound: Some(b),
                        log2_bound,
                    }
                }
            }
            None => RandomDecision::Undecided {
                report,
                bound: None,
                log2_bound: 0.0,
            },
        });
    }
}

/// The residues of a point, by name.
fn scalar(point: &[(String, u64)]) -> HashMap<String, u64> {
    point.iter().cloned().collect()
}

impl fmt::Display for SizeBound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "log2 ||F||_1 <= {}, log2 ||D||_1 <= {}, degree <= {}, degree of D <= {}",
            self.num_bits, self.den_bits, self.degree, self.den_degree
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_expr;

    fn bound(text: &str) -> SizeBound {
        size_bound(&parse_expr(text).unwrap()).unwrap()
    }

    #[test]
    fn structural_bounds() {
        assert_eq!(
            bound("2305843009213693951*x"),
            SizeBound {
                num_bits: 61,
                den_bits: 0,
                degree: 1,
                den_degree: 0,
            }
        );
        let b = bound("(x + 3)^4 / 5");
        assert_eq!((b.num_bits, b.den_bits, b.degree), (4 * 3, 3, 4));
        let b = bound("x/3 + y/5");
        // max(0 + 3, 0 + 2) + 1.
        assert_eq!((b.num_bits, b.den_bits), (4, 5));
        assert!(matches!(
            size_bound(&parse_expr("sqrt(2) x").unwrap()),
            Err(BoundError::Input(_))
        ));
        // 1/x + 2/(y + 3)^2 = (1 (y + 3)^2 + 2 x) / (x (y + 3)^2): 1/x gives L = bits(1) = 1,
        // e = 1; 2/(y + 3)^2 gives L = bits(2) = 2, L_D = 2 (bits(3) + 1) = 6, e = 2; the sum
        // max(1 + 6, 2 + 0) + 1 = 8, L_D = 6, d = max(0 + 2, 0 + 1) = 2, e = 3.
        let b = bound("1/x + 2/(y + 3)^2");
        assert_eq!(
            (b.num_bits, b.den_bits, b.degree, b.den_degree),
            (8, 6, 2, 3)
        );
    }

    #[test]
    fn error_bound_arithmetic() {
        let b = SizeBound {
            num_bits: 62 * 4,
            den_bits: 0,
            degree: 0,
            den_degree: 0,
        };
        // 4 / 2^56 = 2^-54.
        assert!((log2_error_bound(&b, 0, 5) + 54.0).abs() < 1e-6);
        let b = SizeBound {
            num_bits: 10,
            den_bits: 0,
            degree: 1 << 52,
            den_degree: 0,
        };
        // (2^52 / 2^62)^3 = 2^-30.
        assert!((log2_error_bound(&b, 0, 3) + 30.0).abs() < 1e-6);
        let b = SizeBound {
            num_bits: 10,
            den_bits: 0,
            degree: u64::MAX,
            den_degree: 0,
        };
        assert_eq!(log2_error_bound(&b, 0, 100), 0.0);
    }

    #[test]
    fn error_bound_with_a_field() {
        // x cos(2 pi/7) = x (2 cos(pi/7)^2 - 1): L' = 16, L_D = 4, d' = 5, m = 8c^3 + 4c^2 - 4c
        // - 1 (n = 3, M = 5, lambda = 4): floor((5*5 + 3*16)/62) = 1 bad prime among at least
        // 2^56 - floor((0 + 12)/62) - 0 = 2^56, and (5/2^62)^20 besides.
        let b = SizeBound {
            num_bits: 16,
            den_bits: 4,
            degree: 5,
            den_degree: 0,
        };
        let field = FieldBound {
            degree: 3,
            modulus_bits: 5,
            lead_bits: 4,
        };
        let l = log2_error_bound_in(&b, Some(&field), 0, 20);
        assert!((l + 56.0).abs() < 1e-6, "{l}");
        // Without a field it is the bound over Q.
        assert_eq!(
            log2_error_bound_in(&b, None, 1, 7),
            log2_error_bound(&b, 1, 7)
        );
        // The field's degree multiplies the points avoided: n e' close to 2^62 leaves no bound.
        let wide = SizeBound {
            den_degree: 1 << 61,
            ..b
        };
        let two = FieldBound { degree: 2, ..field };
        assert_eq!(log2_error_bound_in(&wide, Some(&two), 0, 20), 0.0);
    }
}
