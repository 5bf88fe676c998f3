//! Real root isolation of integer polynomials on the whole real line by Descartes' rule of signs
//! (Vincent–Collins–Akritas bisection in the Bernstein basis, on integers), and refinement of
//! the isolating intervals to a given width by filtered exact sign evaluation at dyadic points
//! with Newton steps.
//!
//! # Isolation
//! 1. **Primitive square-free part.** The input is made primitive with a positive leading
//!    coefficient. It is square-free when `gcd(q mod p, q' mod p) = 1` over `F_p` for a prime `p`
//!    that divides neither the leading coefficient of `q` nor that of `q'`: then the resultant
//!    `Res(q, q')` (which reduces modulo `p` to the resultant of the reductions, the degrees being
//!    kept) is non-zero modulo `p`, hence non-zero, hence `gcd(q, q') = 1` over `Q`. Four primes
//!    are tried ([`is_square_free_mod_p`], `O(n^2)` word operations: Euclid without inverses,
//!    `a <- lc(b) a - lc(a) x^k b`): first the Mersenne prime `2^31 - 1` on 64-bit products,
//!    which almost always decides, then `2^61 - 1` and two 62-bit primes; only when all fail
//!    (a repeated root, or a resultant divisible by all three) is the exact square-free part
//!    computed by the primitive remainder sequence ([`UPoly::square_free_part`]).
//! 2. **Four unit problems.** The real line minus `{-1, 0, 1}` is covered by `(0, 1)`, `(1, inf)`,
//!    `(-1, 0)` and `(-inf, -1)`; the roots of `q` there are the roots in `(0, 1)` of `q(x)`,
//!    `x^n q(1/x)`, `q(-x)` and `x^n q(-1/x)`. The points `0, 1, -1` are tested exactly. An
//!    interval `(0, b)` of the two reciprocal problems maps to `(1/b, B)` (resp. `(-B, -1/b)`) with
//!    `B` a power of two above Cauchy's bound `1 + max |a_i / a_n|`, so every interval is bounded.
//! 3. **Bernstein form on integers.** The Bernstein coefficients `b_i` of a degree-`n`
//!    polynomial on `[0, 1]` are `c_{n-i} / C(n, i)`, `c` the coefficients of `(1 + y)^n p(1/(1 + y))`
//!    (reversal, then a Taylor shift by 1: `n(n+1)/2` additions). Multiplied by
//!    `L = lcm_i C(n, i)` (about `1.44 n` bits) they are integers. Subdivision at `1/2` is de
//!    Casteljau's scheme without the halvings (`B^(k)_i = B^(k-1)_i + B^(k-1)_{i+1}`, `n(n+1)/2`
//!    additions); the halves are `2^(n-i) B^(i)_0` and `2^i B^(n-i)_i` (both `2^n` times the true
//!    coefficients, so integers), divided by their common power of two.
//! 4. **Descartes' rule.** The number `V` of sign changes of the Bernstein coefficients (zeros
//!    skipped) bounds the number of roots in the *open* interval and has its parity; an end
//!    point that is a root only removes a zero coefficient. `V = 0`: no root; `V = 1` with
//!    non-zero end coefficients: one root, the ends are not roots; otherwise split. A zero middle
//!    value `B^(n)_0` is an exact dyadic root. Termination on square-free input follows from the
//!    one- and two-circle theorems (see [`exactcheck_core::roots`]): the depth is
//!    `O(log(1 / sep))`.
//!
//! The Bernstein form costs one `O(n^2)` pass per subdivision against two Taylor shifts per node
//! in the classical monomial VCA (one for the test, one for the right child), and its sign count
//! is free. The coefficients grow by `n` bits per level either way.
//!
//! The multipliers `L / C(n, i)` come from `L = lcm(1, ..., n + 1) / (n + 1)` (the lcm of a row
//! of Pascal's triangle) and `m_{i+1} = m_i (i + 1) / (n - i)` (an exact division by a word, both
//! sides being integers), with no big-integer lcm or division.
//! 5. **Fixed-width limbs.** The subdivision and the Taylor shift run on [`Limbs`]: every
//!    coefficient of a node in the same number of 64-bit two's complement limbs, one flat vector,
//!    additions as carry chains in place; the width is fixed before each split for `max bits +
//!    n + 1` bits, which no entry of the triangle can exceed (module `limbs`). The `BigInt`
//!    kernels are kept ([`split_half`], `taylor_shift_1`) and the tests assert equality.
//! 6. **Close pairs.** On a node with `V = 2` whose end values have the same sign `s` (depth at
//!    least 2, and its parent's `V` was 2 as well: both variations survived a split, so a pair
//!    that one split separates never pays for the attempt), a point `c` strictly inside with `sgn q(c) = -s` separates the node: each half
//!    has a sign change at its ends, hence a root, and the node has at most `V = 2` roots, so
//!    each half holds exactly one and is an isolating interval. `c` is sought as the critical
//!    point between the pair: Newton's method on `q'` in `f64` from the middle (abandoned when
//!    it leaves the node), then exact Newton steps `c - q'(c) / q''(c)` on dyadics, the
//!    precision doubling each step (quadratic convergence), up to 4096 bits, abandoned when a
//!    step grows or leaves the node; each `c` is tested by the exact sign of `q(c)`. Only the
//!    exact sign certifies; when no `c` is found the node is subdivided as before. The attempt
//!    is made only when the `f64` estimate `sqrt(2 |q / q''|)` of the half-distance of the pair
//!    at the critical point is below `1/256` of the node width (a pair bisection would not
//!    separate in a few levels). Mignotte's `x^40 - 2 (10 x - 1)^2`, whose pair at `1/10` is
//!    `1.4e-21` apart, is separated at depth 2 instead of about 70 levels. The same estimate
//!    `c -/+ delta` starts the refinement of the two halves.
//! 7. **Filtered subdivision.** Up to degree 1000 the subdivision runs on `f64` Bernstein
//!    coefficients with one rigorous error bound per node (module `filtered`): Descartes' rule is
//!    decided in `f64` when every sign it needs is certain (`|g_i| > E`, the largest variation
//!    count over the uncertain signs deciding), an uncertain split point by an exact dyadic
//!    evaluation, and a node that runs out of precision gets its exact integer coefficients back
//!    (exact splits on limbs, cached) and continues from them; beyond a depth cap the exact
//!    subdivision above takes over. A split costs `n(n+1)/2` `f64` additions instead of as many
//!    carry chains on growing limbs; the results are the same kind of intervals (not
//!    necessarily the same ones) and the tests compare both with Sturm counts.
//!
//! # Rational roots
//! A rational root `u / v` (lowest terms) of the primitive `q` has `v | lc(q)` and `u | a_k`,
//! `a_k` the lowest non-zero coefficient (rational root theorem). For every subdivision leaf an
//! `f64` estimate of its root is computed from the leaf's Bernstein coefficients (locally well
//! conditioned, unlike the power basis: safeguarded Newton from the control polygon's crossing
//! on `B(t) / (1 - t)^n` and `B(t) / t^n`, every power at most 1; degree at most 1000). Its
//! continued-fraction convergents `u / v` are the candidates (Legendre: a rational within
//! `1 / (2 v^2)` of the estimate is one of them): a candidate inside the isolating interval that
//! passes the two divisibility tests (word remainders) is a root exactly when `v x - u` divides
//! `q`, decided by synthetic division on fixed-width limbs ([`Limbs::divide_by_linear`]): in
//! the ring `Z / 2^(64 w)`, dividing by whichever of `u`, `v` is odd (a Hensel division per
//! step), and accepted only when the remainder vanishes there and every quotient coefficient is
//! small enough that the congruence `(v x - u) s = q` is an equality over `Z`; the width `w`
//! comes from Mignotte's bound on the factors of `q`, so no true factor is refused. While the
//! coefficients fit in `i128` the same division runs in `Z / 2^128` with the headroom taken
//! from the sizes of `u` and `v` (module `deflate`), the limbs deciding only what it cannot.
//! The estimate stays a dyadic plus an `f64` offset until the refinement needs it exactly, so a
//! recognised root costs no rational arithmetic beyond its own value. The leaf's Newton
//! iteration first stops at a coarse point (a correction below `2^-24`, so the point is within
//! about `2^-48` of the root), whose convergents of denominator up to `2^10` are tried; only
//! when none is a root does the iteration resume, with the same steps as without the stop, and
//! the convergents of the final estimate are tried (those already tried skipped). A root found is returned
//! as the exact point `[u/v, u/v]`, like the Sturm isolator's, and divided out of the
//! polynomial the later candidates are tested against. Nothing is decided on the estimate: an
//! irrational root fails the tests (almost always at the divisibility, without an exact
//! evaluation) and is refined as below.
//!
//! # Refinement
//! Each isolating interval `(lo, hi)` of the square-free `q` has known end signs (all roots are
//! simple: the sign right of the `i`-th of `K` roots is `sgn(lc) (-1)^(K-1-i)`), so no end point
//! is evaluated. Points are dyadic `m = c / 2^k`, with `k` at most `K` where `h = 2^-K` is the
//! largest power of two with `4h <= width`.
//! * **Filtered sign.** `q(m)` in `f64` by Horner's scheme, with `s = sum |a_i| |m|^i` computed
//!   alongside. The coefficients and `m` are rounded once (relative error `u = 2^-53` each, twice
//!   that allowed for the integer conversion), Horner adds `2n` roundings, so
//!   `|fl(q(m)) - q(m)| <= gamma_{3n+3} * s * (1 + gamma_{2n})` with `gamma_k = k u / (1 - k u)`
//!   (Higham, *Accuracy and Stability*, 5.1), plus at most `2n * 2^-1074` from underflow. The
//!   filter decides when `|fl(q(m))| > (3n + 6) 2^-52 s + 2^-1000`, which exceeds that bound
//!   (for `n < 2^40`); it declines when `s` is not finite or `m` or its numerator has more than
//!   1000 bits. Otherwise the exact sign is the sign of the integer
//!   `q(c / 2^k) 2^(kn) = sum a_i c^i 2^(k(n-i))` (Horner on big integers).
//! * **Estimate window.** With an estimate `e` of the root (the leaf's, above), first the grid
//!   points `e -/+ 2h` (`e` rounded to the grid `h`) are evaluated exactly; when the root is
//!   outside that window, points `2^m 2h` away on its side (`m = 1, ..., 6`) until the sign
//!   flips. Every point only updates the bracket by its exact sign.
//! * **Bisection** at a dyadic point near the middle while the filter decides.
//! * **Newton with verification.** Where it cannot, the exact evaluation also gives
//!   `q'(m) 2^(k(n-1))`, and the Newton point `g = m - q(m)/q'(m)` (ratio in `f64`, rounded to
//!   the grid `h`) is the next evaluation point when it lies inside the bracket (a bisection
//!   otherwise, and after a Newton step that did not halve the bracket). Once the Newton
//!   correction is below `2^10 h`, the two grid points `g -/+ 2h` are evaluated exactly: signs
//!   `(sgn(lo), sgn(hi))` certify `[g - 2h, g + 2h]`, of width `4h <= width`. Every bracket
//!   update is an exact sign, so the result is certified whatever the `f64` steps did; a zero
//!   value is an exact root.
//! * **Limb evaluation.** Where `m` has a word numerator, the exact values come from Horner's
//!   scheme on one two's complement limb vector per value (`limbs::DyadicHorner`), and the
//!   window signs first from the same scheme truncated to `128 + e n + log2(n + 1)` fraction
//!   bits (`|m| < 2^e`), whose error stays below `(n + 1) 2^(e n)` units: a larger result has
//!   the exact sign, a smaller one is evaluated exactly. The `BigInt` schemes are the
//!   reference of the tests.
//!
//! # Which isolator where
//! This isolator serves the workspace's real-root API ([`super::isolate_real_roots`],
//! [`super::isolate_real_roots_in`]): there every interval that the leaf estimates did not
//! resolve is narrowed below `1 / (2 l)` and its one candidate `k / l` of the rational root
//! theorem is evaluated exactly, so a root is exact **exactly when it is rational**, as with the
//! Sturm isolator ([`UPoly::isolate_roots`], the tests' reference). On its own
//! ([`integer_real_roots`], [`UPoly::real_roots_descartes`]) an isolating interval is exact when
//! a split point hits the root; the refined intervals ([`integer_real_roots_to`], the real-roots
//! benchmark) are exact also for the rational roots recognised above (in practice every rational
//! root with a denominator below about `2^26`, degree at most 1000), which is not a promise for
//! every rational root.
//!
//! The accelerations (limbs, close pairs, rational roots, estimate windows) can be switched off
//! one by one (`Options`); the tests run both and compare them with the Sturm isolator.
//!
//! Hand-written because the workspace has no arbitrary-precision interval arithmetic or
//! polynomial library beyond num-bigint; the kernels (Taylor shift, de Casteljau, Horner) are a
//! few lines each.

mod filtered;

use super::limbs::{DyadicHorner, Limbs};
use super::*;
use num_bigint::Sign as BigSign;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Largest degree accepted by the Descartes isolator (the coefficients grow by `n` bits per
/// subdivision level and every level costs `O(n^2)` big-integer additions).
pub const MAX_DESCARTES_DEGREE: usize = 1 << 14;

mod deflate;
mod estimate;
mod modp;
mod pairs;
mod refine;
mod subdivision;
#[cfg(test)]
mod tests;

use deflate::*;
use estimate::*;
use modp::*;
use pairs::*;
use refine::*;
use subdivision::*;

// ------------------------------------------------------------------------------ isolation

fn pow2(k: u64) -> Rational {
    Rational::from(BigInt::one() << k)
}

fn dyadic(c: &BigInt, j: u64) -> Rational {
    Rational::from_dyadic(c, j)
}

/// A power of two `B` strictly above Cauchy's bound `1 + max |a_i / a_n|`.
fn root_bound(q: &[BigInt]) -> Rational {
    let n = q.len() - 1;
    let bm = q[..n].iter().map(|c| c.bits()).max().unwrap_or(0) as i64;
    let bn = q[n].bits() as i64;
    pow2((bm + 2 - bn).max(1) as u64)
}

/// An isolating interval with an estimate of its root when there is one (for
/// [`RationalRoots::recognise_in`] and the first window of the refinement).
struct Isolated {
    ri: RootInterval,
    estimate: Option<Estimate>,
}

/// Isolating intervals of all real roots of the primitive square-free `q` (degree >= 1,
/// positive leading coefficient), sorted. `pairs`: whether close pairs are split at a point of
/// opposite sign ([`PairSplitter`]) rather than by subdivision alone.
fn isolate_square_free(q: &[BigInt], opts: Options) -> Vec<Isolated> {
    let n = q.len() - 1;
    let bound = root_bound(q);
    let exact = |x: Rational| Isolated {
        ri: RootInterval::exact(x),
        estimate: None,
    };
    // Descartes' rule of signs on the power basis: no sign variation among the coefficients of
    // q(x) (of q(-x)) means no positive (negative) root, and both unit problems of that side
    // are skipped, with the test of 1 (of -1). The signs of q(-x) are read off q's.
    let positive = variations(q) > 0;
    let negative = isolate::count_variations(q.iter().enumerate().map(|(i, c)| {
        let s = sign_of(c);
        if i % 2 == 1 {
            sign_neg(s)
        } else {
            s
        }
    })) > 0;
    let one = positive && sign_of_sum(q) == Sign::Zero;
    let neg: Vec<BigInt> = if negative {
        q.iter()
            .enumerate()
            .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
            .collect()
    } else {
        Vec::new()
    };
    let minus_one = negative && sign_of_sum_at(q, true) == Sign::Zero;
    let rev: Vec<BigInt> = if positive {
        q.iter().rev().cloned().collect()
    } else {
        Vec::new()
    };
    let rev_neg: Vec<BigInt> = neg.iter().rev().cloned().collect();
    // The four unit problems x = t, 1/t, -t, -1/t for t in (0, 1), taken in increasing order of
    // x: every subdivision lists its roots in increasing t, which -1/t and t keep and 1/t and
    // -t reverse; the exact roots -1, 0 and 1 between them.
    let mut out: Vec<Isolated> = Vec::with_capacity(n);
    for which in [3, 2, 0, 1] {
        let p: &[BigInt] = [q, &rev[..], &neg[..], &rev_neg[..]][which];
        if which == 2 && minus_one {
            out.push(exact(-Rational::ONE));
        }
        if which == 0 && q[0].is_zero() {
            out.push(exact(Rational::ZERO));
        }
        if which == 1 && one {
            out.push(exact(Rational::ONE));
        }
        if (which < 2 && !positive) || (which >= 2 && !negative) {
            continue;
        }
        debug_assert_eq!(p.len(), n + 1);
        let mut roots = unit_roots(p, opts);
        if which == 1 || which == 2 {
            roots.reverse();
        }
        for r in roots {
            let item = match r {
                UnitRoot::Exact(c, j) => {
                    let x = dyadic(&c, j);
                    exact(match which {
                        0 => x,
                        1 => x.recip().expect("a unit root is positive"),
                        2 => -x,
                        _ => -x.recip().expect("a unit root is positive"),
                    })
                }
                UnitRoot::Open { a, b, estimate } => {
                    let inv = |x: &Rational| {
                        if x.is_zero() {
                            bound.clone()
                        } else {
                            x.recip().expect("checked non-zero")
                        }
                    };
                    let ri = match which {
                        0 => RootInterval { lo: a, hi: b },
                        1 => RootInterval {
                            lo: inv(&b),
                            hi: inv(&a),
                        },
                        2 => RootInterval { lo: -b, hi: -a },
                        _ => RootInterval {
                            lo: -inv(&a),
                            hi: -inv(&b),
                        },
                    };
                    let estimate = estimate.map(|unit| Estimate { unit, which });
                    Isolated { ri, estimate }
                }
            };
            out.push(item);
        }
    }
    // Disjoint intervals and points: by the lower end, an exact root before the open interval
    // it bounds.
    let key =
        |x: &Isolated, y: &Isolated| x.ri.lo.cmp(&y.ri.lo).then_with(|| x.ri.hi.cmp(&y.ri.hi));
    if !out.is_sorted_by(|x, y| key(x, y) != std::cmp::Ordering::Greater) {
        out.sort_by(key);
    }
    out
}

/// The sign of `p(1)` (`p(-1)` when `alternate`): the sum of the coefficients (with the odd
/// ones negated), in `i128` while every coefficient and partial sum fits, else on big integers.
fn sign_of_sum_at(p: &[BigInt], alternate: bool) -> Sign {
    let mut acc: Option<i128> = Some(0);
    for (i, c) in p.iter().enumerate() {
        let Some(s) = acc else { break };
        acc = c.to_i128().and_then(|v| {
            if alternate && i % 2 == 1 {
                s.checked_sub(v)
            } else {
                s.checked_add(v)
            }
        });
    }
    match acc {
        Some(s) => match s.cmp(&0) {
            std::cmp::Ordering::Less => Sign::Negative,
            std::cmp::Ordering::Equal => Sign::Zero,
            std::cmp::Ordering::Greater => Sign::Positive,
        },
        None => {
            let mut s = BigInt::zero();
            for (i, c) in p.iter().enumerate() {
                if alternate && i % 2 == 1 {
                    s -= c;
                } else {
                    s += c;
                }
            }
            sign_of(&s)
        }
    }
}

/// The sign of `p(1)`, the sum of the coefficients ([`sign_of_sum_at`]).
fn sign_of_sum(p: &[BigInt]) -> Sign {
    sign_of_sum_at(p, false)
}

fn sign_of(x: &BigInt) -> Sign {
    match x.sign() {
        BigSign::Minus => Sign::Negative,
        BigSign::NoSign => Sign::Zero,
        BigSign::Plus => Sign::Positive,
    }
}

// ------------------------------------------------------------------------------ public API

/// Isolating intervals of the distinct real roots of the integer polynomial with these
/// coefficients (constant term first), by Descartes' rule (module documentation): sorted,
/// pairwise disjoint, each an exact dyadic or reciprocal-of-dyadic root or an open interval
/// holding exactly one root with non-root ends. Empty for constants.
///
/// # Errors
/// [`ZeroPolynomial`] for the zero polynomial.
///
/// # Panics
/// Beyond [`MAX_DESCARTES_DEGREE`].
pub fn integer_real_roots(coeffs: &[BigInt]) -> Result<Vec<RootInterval>, ZeroPolynomial> {
    Ok(prepare(coeffs)?.map_or_else(Vec::new, |q| {
        isolate_square_free(&q, Options::FAST)
            .into_iter()
            .map(|i| i.ri)
            .collect()
    }))
}

/// [`integer_real_roots`], each interval refined to width at most `width` (see the module
/// documentation; a root hit by an evaluation point is exact). Unlike the isolating intervals,
/// which may share an end, the refined intervals are disjoint as closed intervals.
///
/// # Errors
/// [`ZeroPolynomial`] for the zero polynomial.
///
/// # Panics
/// When `width <= 0`, or beyond [`MAX_DESCARTES_DEGREE`].
pub fn integer_real_roots_to(
    coeffs: &[BigInt],
    width: &Rational,
) -> Result<Vec<RootInterval>, ZeroPolynomial> {
    assert!(
        width.signum() == Sign::Positive,
        "integer_real_roots_to: the width must be positive"
    );
    real_roots_to_with(coeffs, width, Options::FAST)
}

/// [`integer_real_roots`] with every rational root exact: an interval that is not recognised by
/// the leaf estimates (module documentation, "Rational roots") is narrowed below `1 / (2 l)`,
/// `l` the leading coefficient of the primitive square-free part, where at most one candidate
/// `k / l` of the rational root theorem remains, and that candidate is evaluated exactly. An
/// irrational root keeps the narrowed interval. The intervals are disjoint as closed intervals.
///
/// # Errors
/// [`ZeroPolynomial`] for the zero polynomial.
///
/// # Panics
/// Beyond [`MAX_DESCARTES_DEGREE`].
pub(super) fn integer_real_roots_rational_exact(
    coeffs: &[BigInt],
) -> Result<Vec<RootInterval>, ZeroPolynomial> {
    let Some(q) = prepare(coeffs)? else {
        return Ok(Vec::new());
    };
    let roots = isolate_square_free(&q, Options::FAST);
    // Built on the first root that needs refining (none when every root is exact).
    let refiner_cell = std::cell::OnceCell::new();
    let mut rationals = RationalRoots::new(&q);
    let l = Rational::from(q[q.len() - 1].clone());
    let width = Rational::ONE / l.mul_ref(&Rational::from_integer(2));
    let k = roots.len();
    let mut out: Vec<RootInterval> = Vec::with_capacity(k);
    for (i, Isolated { ri, estimate }) in roots.into_iter().enumerate() {
        if ri.is_exact() {
            out.push(ri);
            continue;
        }
        if let Ok(r) = recognise(Some(&mut rationals), estimate, &ri) {
            out.push(RootInterval::exact(r));
            continue;
        }
        // The sign right of root i is (-1)^(k-1-i) (positive leading coefficient).
        let s_lo = if (k - 1 - i) % 2 == 0 {
            Sign::Negative
        } else {
            Sign::Positive
        };
        let refiner = refiner_cell.get_or_init(|| Refiner::new(&q));
        let narrow = refiner.refine(ri.lo, ri.hi, s_lo, &width, None);
        if narrow.is_exact() {
            out.push(narrow);
            continue;
        }
        // At most one integer m with lo * l < m < hi * l.
        let m = floor(&narrow.lo.mul_ref(&l)) + 1;
        let candidate = Rational::from(m) / &l;
        if candidate < narrow.hi && sign_at_rational(&q, &candidate) == Sign::Zero {
            out.push(RootInterval::exact(candidate));
        } else {
            out.push(narrow);
        }
    }
    Ok(out)
}

/// The rational root of the isolating interval `ri` recognised from its estimate
/// ([`RationalRoots`], when given): from a leaf's coarse point first (denominators up to
/// [`COARSE_DENOMINATOR`]; the leaf's iteration is not run to its end for a root found there),
/// then from the final estimate; otherwise the final estimate, for the refinement.
fn recognise(
    rationals: Option<&mut RationalRoots>,
    estimate: Option<Estimate>,
    ri: &RootInterval,
) -> Result<Rational, Option<Estimate>> {
    let Some(rationals) = rationals else {
        return Err(estimate.and_then(Estimate::sharpened));
    };
    let window = Window::new(&ri.lo, &ri.hi);
    // The convergents tried at the coarse point are not tried again at the final estimate
    // (whose first convergents are usually the same).
    let mut phase = Phase::Only;
    if let Some(est) = estimate.as_ref().filter(|e| e.is_coarse()) {
        if let Some(r) = rationals.recognise_in(est.to_f64(), &window, Phase::Coarse) {
            return Ok(r);
        }
        phase = Phase::Final;
    }
    let estimate = estimate.and_then(Estimate::sharpened);
    if let Some(est) = &estimate {
        if let Some(r) = rationals.recognise_in(est.to_f64(), &window, phase) {
            return Ok(r);
        }
    }
    Err(estimate)
}

/// Descartes' bound for the open interval `(0, 1)` of the integer polynomial with these
/// coefficients (constant term first, degree `n`): the sign variations of
/// `(1 + x)^n p(1 / (1 + x))`, whose coefficients are positive multiples of the Bernstein
/// coefficients of `p` on `[0, 1]` in reverse order. It bounds the number of roots in `(0, 1)`
/// counted with multiplicity and has the same parity; 0 and 1 are exact.
pub(super) fn unit_descartes_bound(coeffs: &[BigInt]) -> usize {
    let mut a = coeffs.to_vec();
    a.reverse();
    taylor_shift_1(&mut a);
    variations(&a)
}

/// Which of the accelerations of the module documentation run; [`Options::FAST`] is the public
/// behaviour, the others are the references of the tests.
#[derive(Clone, Copy, Debug)]
struct Options {
    /// Close pairs split at a point of opposite sign ([`PairSplitter`]).
    pairs: bool,
    /// Rational roots recognised from the leaf estimates ([`RationalRoots`]).
    rationals: bool,
    /// The refinement starts with a window of the target width around the estimate.
    windows: bool,
    /// The subdivision on fixed-width limbs ([`Limbs`]) instead of `BigInt`s.
    limbs: bool,
    /// The subdivision on `f64` with a rigorous error bound, exact where that cannot decide
    /// ([`filtered`]; degrees up to [`filtered::MAX_FILTERED_DEGREE`]).
    filtered: bool,
}

impl Options {
    const FAST: Options = Options {
        pairs: true,
        rationals: true,
        windows: true,
        limbs: true,
        filtered: true,
    };
    #[cfg(test)]
    const REFERENCE: Options = Options {
        pairs: false,
        rationals: false,
        windows: false,
        limbs: false,
        filtered: false,
    };
}

/// [`integer_real_roots_to`] with a choice of accelerations.
fn real_roots_to_with(
    coeffs: &[BigInt],
    width: &Rational,
    opts: Options,
) -> Result<Vec<RootInterval>, ZeroPolynomial> {
    let Some(q) = prepare(coeffs)? else {
        return Ok(Vec::new());
    };
    let roots = isolate_square_free(&q, opts);
    // Built on the first root that needs refining (none when every root is exact).
    let refiner_cell = std::cell::OnceCell::new();
    // The rational roots found so far divided out: the later candidates are tested against a
    // polynomial of lower degree (its roots are the remaining roots of q, all simple).
    let mut rationals = RationalRoots::new(&q);
    let k = roots.len();
    let mut out: Vec<RootInterval> = Vec::with_capacity(k);
    for (i, iso) in roots.into_iter().enumerate() {
        let Isolated { ri, estimate } = iso;
        if ri.is_exact() {
            out.push(ri);
            continue;
        }
        let estimate = match recognise(opts.rationals.then_some(&mut rationals), estimate, &ri) {
            Ok(r) => {
                out.push(RootInterval::exact(r));
                continue;
            }
            Err(estimate) => estimate,
        };
        // The sign right of root i is (-1)^(k-1-i) (positive leading coefficient).
        let s_right = if (k - 1 - i) % 2 == 0 {
            Sign::Positive
        } else {
            Sign::Negative
        };
        let s_lo = sign_neg(s_right);
        let estimate = estimate
            .filter(|_| opts.windows)
            .and_then(|e| e.to_rational());
        let refiner = refiner_cell.get_or_init(|| Refiner::new(&q));
        let r = refiner.refine(ri.lo, ri.hi, s_lo, width, estimate);
        // Isolating intervals may share an end (a subdivision point); the closed refined
        // intervals must not: narrow the left one until its upper end moves (its root is
        // strictly below the shared end).
        if let Some(prev) = out.last_mut() {
            while !prev.is_exact() && prev.hi == r.lo {
                let s_prev = sign_neg(s_lo);
                let half_width = prev.width() * half();
                *prev = refiner.refine(prev.lo.clone(), prev.hi.clone(), s_prev, &half_width, None);
            }
        }
        out.push(r);
    }
    Ok(out)
}

/// The primitive square-free part, `None` for non-zero constants.
fn prepare(coeffs: &[BigInt]) -> Result<Option<Vec<BigInt>>, ZeroPolynomial> {
    let len = coeffs.len() - coeffs.iter().rev().take_while(|c| c.is_zero()).count();
    if len == 0 {
        return Err(ZeroPolynomial);
    }
    assert!(
        len - 1 <= MAX_DESCARTES_DEGREE,
        "the Descartes isolator accepts degrees up to {MAX_DESCARTES_DEGREE}"
    );
    if len == 1 {
        return Ok(None);
    }
    Ok(Some(square_free_integer(&coeffs[..len])))
}

impl UPoly {
    /// The coefficients of the primitive integer multiple `self / content` (see
    /// [`UPoly::content`]).
    pub fn integer_coefficients(&self) -> Vec<BigInt> {
        self.primitive_part()
            .coeffs()
            .iter()
            .map(|c| {
                debug_assert!(c.is_integer());
                c.numer()
            })
            .collect()
    }

    /// The primitive square-free part with a positive leading coefficient (a positive multiple
    /// of [`UPoly::square_free_part`]): certified square-free modulo word-size primes when it is
    /// (module documentation, step 1), so the usual case needs no remainder sequence. The zero
    /// polynomial and constants are returned as their primitive parts.
    pub fn primitive_square_free_part(&self) -> UPoly {
        if self.is_constant() {
            return self.primitive_part();
        }
        let q = square_free_integer(&self.integer_coefficients());
        UPoly::from_coeffs(q.into_iter().map(Rational::from).collect())
    }

    /// Isolating intervals of all distinct real roots by Descartes' rule of signs (the
    /// module documentation of `descartes`; [`integer_real_roots`]): sorted, pairwise disjoint,
    /// the [`RootInterval`] contract; exact when a subdivision point hits the root (not
    /// necessarily for every rational root, unlike [`UPoly::isolate_roots`]). Empty for
    /// constants and for the zero polynomial.
    pub fn real_roots_descartes(&self) -> Vec<RootInterval> {
        if self.is_constant() {
            return Vec::new();
        }
        integer_real_roots(&self.integer_coefficients()).expect("not the zero polynomial")
    }

    /// [`UPoly::real_roots_descartes`] with every interval refined to width at most `width`
    /// ([`integer_real_roots_to`]).
    ///
    /// # Panics
    /// When `width <= 0`.
    pub fn isolate_real_roots_to(&self, width: &Rational) -> Vec<RootInterval> {
        if self.is_constant() {
            return Vec::new();
        }
        integer_real_roots_to(&self.integer_coefficients(), width).expect("not the zero polynomial")
    }
}
