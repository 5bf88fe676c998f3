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
//!    kept) is non-zero modulo `p`, hence non-zero, hence `gcd(q, q') = 1` over `Q`. Three 61/62-bit
//!    primes are tried ([`is_square_free_mod_p`], `O(n^2)` word operations: Euclid without
//!    inverses, `a <- lc(b) a - lc(a) x^k b`, and Mersenne folding modulo the first prime
//!    `2^61 - 1`, which almost always decides); only when all fail
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
//! comes from Mignotte's bound on the factors of `q`, so no true factor is refused. The
//! estimate stays a dyadic plus an `f64` offset until the refinement needs it exactly, so a
//! recognised root costs no rational arithmetic beyond its own value. A root found is returned
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
//!
//! # Which isolator where
//! [`UPoly::isolate_roots`] (Sturm bisection over `Rational`) stays the workspace's default: it
//! promises an exact interval **exactly when the root is rational**, which callers
//! (`planar`, `solve`) rely on, and the workspace's polynomials are of degree at most a few
//! dozen, where Sturm sequences are cheap. The Descartes isolator is for large degrees
//! ([`UPoly::real_roots_descartes`], [`UPoly::isolate_real_roots_to`], the W4 benchmark): an
//! isolating interval is exact when a split point hits the root; the refined intervals
//! ([`integer_real_roots_to`]) are exact also for the rational roots recognised above (in
//! practice every rational root with a denominator below about `2^26`, degree at most 1000),
//! which is not a promise for every rational root.
//!
//! The accelerations (limbs, close pairs, rational roots, estimate windows) can be switched off
//! one by one (`Options`); the tests run both and compare them with the Sturm isolator.
//!
//! Hand-written because the workspace has no arbitrary-precision interval arithmetic or
//! polynomial library beyond num-bigint; the kernels (Taylor shift, de Casteljau, Horner) are a
//! few lines each.

mod filtered;

use super::limbs::Limbs;
use super::*;
use num_bigint::Sign as BigSign;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Largest degree accepted by the Descartes isolator (the coefficients grow by `n` bits per
/// subdivision level and every level costs `O(n^2)` big-integer additions).
pub const MAX_DESCARTES_DEGREE: usize = 1 << 14;

// ------------------------------------------------------------------------------ square-free

/// Three primes below `2^62` for the modular square-freeness test.
const PRIMES: [u64; 3] = [
    (1 << 61) - 1,
    4_611_686_018_427_387_847,
    4_611_686_018_427_387_817,
];

/// Multiplication modulo one of the [`PRIMES`]: Mersenne folding for `2^61 - 1`
/// ([`ModP`](crate::modp::ModP)), a `u128` remainder for the others.
#[inline]
fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    if p == crate::modp::P {
        crate::modp::ModP::from_u128(u128::from(a) * u128::from(b)).value()
    } else {
        (u128::from(a) * u128::from(b) % u128::from(p)) as u64
    }
}

/// `x mod p` for an integer `x` (non-negative result).
fn big_mod(x: &BigInt, p: u64) -> u64 {
    if p == crate::modp::P {
        return crate::modp::ModP::from_bigint(x).value();
    }
    let r = rem_small(x, p);
    if x.is_negative() && r != 0 {
        p - r
    } else {
        r
    }
}

/// The degree of `gcd(a, b)` over `F_p` (both non-zero, trailing zeros trimmed). Euclid's
/// algorithm without inverses: `a <- lc(b) a - lc(a) x^k b` cancels the leading term of `a`
/// and multiplies the gcd by the unit `lc(b)` only, so the degrees are those of the monic
/// remainder sequence.
fn gcd_degree_mod_p(mut a: Vec<u64>, mut b: Vec<u64>, p: u64) -> usize {
    fn trim(v: &mut Vec<u64>) {
        while v.last() == Some(&0) {
            v.pop();
        }
    }
    trim(&mut a);
    trim(&mut b);
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_empty() {
        // a <- a mod b (up to a unit factor)
        let db = b.len() - 1;
        let lb = b[db];
        while a.len() > db {
            let top = a.len() - 1;
            let f = a[top];
            let shift = top - db;
            for x in &mut a[..shift] {
                *x = mul_mod(*x, lb, p);
            }
            for (x, &bj) in a[shift..].iter_mut().zip(&b) {
                let (u, t) = (mul_mod(*x, lb, p), mul_mod(f, bj, p));
                *x = if u >= t { u - t } else { u + p - t };
            }
            debug_assert_eq!(a[top], 0);
            a.pop();
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// Whether `gcd(q mod p, q' mod p) = 1` over `F_p` for one of three primes keeping the degrees of
/// `q` and `q'`: a proof that the integer polynomial `q` (degree >= 1) is square-free (see the
/// module documentation). `false` means "not proved", not "not square-free".
pub(super) fn is_square_free_mod_p(q: &[BigInt]) -> bool {
    let n = q.len() - 1;
    PRIMES.iter().any(|&p| {
        let a: Vec<u64> = q.iter().map(|c| big_mod(c, p)).collect();
        let d: Vec<u64> = (1..=n).map(|i| mul_mod(a[i], i as u64 % p, p)).collect();
        if a[n] == 0 || d[n - 1] == 0 {
            return false;
        }
        gcd_degree_mod_p(a, d, p) == 0
    })
}

/// The gcd of the integers `q` (non-negative): each step reduces the next number modulo the
/// running gcd first (a word remainder while the gcd fits in a word), and stops at 1.
fn content(q: &[BigInt]) -> BigInt {
    let mut g = BigInt::zero();
    for c in q {
        if g.is_one() {
            break;
        }
        if c.is_zero() {
            continue;
        }
        g = match g.to_u64() {
            Some(0) => c.abs(),
            Some(w) => BigInt::from(num_integer::Integer::gcd(&w, &rem_small(c, w))),
            None => num_integer::Integer::gcd(&g, &(c % &g)),
        };
    }
    g
}

/// The primitive square-free part with a positive leading coefficient, as integers.
fn square_free_integer(coeffs: &[BigInt]) -> Vec<BigInt> {
    let g = content(coeffs);
    let mut q: Vec<BigInt> = match g.to_u64() {
        Some(1) => coeffs.to_vec(),
        // A word content (the usual case): exact division by a word, on `i128` when the
        // coefficient fits, by Jebelean's exact division on its limbs otherwise.
        Some(w) => coeffs
            .iter()
            .map(|c| match c.to_i128() {
                Some(v) => BigInt::from(v / i128::from(w)),
                None => {
                    let m = crate::bigint::divexact_1(&c.magnitude().to_u64_digits(), w);
                    let m = BigInt::from(crate::bigint::biguint_from_limbs(&m));
                    if c.is_negative() {
                        -m
                    } else {
                        m
                    }
                }
            })
            .collect(),
        None => coeffs.iter().map(|c| c / &g).collect(),
    };
    if q.last().is_some_and(|c| c.is_negative()) {
        for c in &mut q {
            *c = -std::mem::take(c);
        }
    }
    if q.len() <= 2 || is_square_free_mod_p(&q) {
        return q;
    }
    let u = UPoly::from_coeffs(q.iter().cloned().map(Rational::from).collect());
    let s = u.square_free_part().primitive_part();
    let mut out: Vec<BigInt> = s
        .coeffs()
        .iter()
        .map(|c| {
            debug_assert!(c.is_integer());
            c.numer()
        })
        .collect();
    if out.last().is_some_and(|c| c.is_negative()) {
        for c in &mut out {
            *c = -&*c;
        }
    }
    out
}

// ------------------------------------------------------------------------------ Bernstein

/// Number of sign changes, zeros skipped (the Sturm code's [`isolate::count_variations`]).
fn variations(b: &[BigInt]) -> usize {
    isolate::count_variations(b.iter().map(|c| match c.sign() {
        BigSign::Minus => Sign::Negative,
        BigSign::NoSign => Sign::Zero,
        BigSign::Plus => Sign::Positive,
    }))
}

/// `p(x + 1)` in place (`n(n+1)/2` additions).
fn taylor_shift_1(a: &mut [BigInt]) {
    let n = a.len() - 1;
    for i in 0..n {
        for j in (i..n).rev() {
            let (lo, hi) = a.split_at_mut(j + 1);
            lo[j] += &hi[0];
        }
    }
}

/// `L * b_i`: the Bernstein coefficients on `[0, 1]` of the polynomial `p` (degree exactly
/// `n = p.len() - 1` is not required: a zero leading coefficient is allowed), times
/// `L = lcm_i C(n, i)`.
fn to_bernstein_integer(p: &[BigInt]) -> Vec<BigInt> {
    let n = p.len() - 1;
    let mut c: Vec<BigInt> = p.iter().rev().cloned().collect();
    if n >= 8 {
        // On fixed-width limbs (the coefficients of p(x + 1) have at most n more bits).
        let mut l = Limbs::from_bigints_with_room(&c, n + 1);
        l.taylor_shift_1();
        c = l.to_bigints();
    } else {
        taylor_shift_1(&mut c);
    }
    bernstein_multipliers(n)
        .iter()
        .enumerate()
        .map(|(i, m)| &c[n - i] * m)
        .collect()
}

/// The multipliers `m_i = L / C(n, i)`, `L = lcm_i C(n, i) = lcm(1, ..., n + 1) / (n + 1)`, by
/// `m_{i+1} = m_i (i + 1) / (n - i)` (exact: both are integers), word divisions only.
fn bernstein_multipliers(n: usize) -> Vec<BigInt> {
    let mut l = BigInt::one();
    for k in 2..=(n as u64 + 1) {
        let g = num_integer::Integer::gcd(&rem_small(&l, k), &k);
        l *= k / g;
    }
    l /= n as u64 + 1;
    let mut m = l;
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        out.push(m.clone());
        if i < n {
            m *= i as u64 + 1;
            m /= (n - i) as u64;
        }
    }
    out
}

/// [`to_bernstein_integer`] on limbs from the Taylor-shifted reversal `shifted` (the
/// coefficients `c` of `(1 + y)^n p(1 / (1 + y))`, constant term first): `L b_i = c_(n-i) m_i`,
/// by word multiplications when every multiplier fits a word (degree at most 44), else through
/// `BigInt`s.
fn bernstein_from_shifted(shifted: &Limbs) -> Limbs {
    let n = shifted.len() - 1;
    let m = bernstein_multipliers(n);
    let words: Option<Vec<u64>> = m.iter().map(ToPrimitive::to_u64).collect();
    match words {
        Some(words) => shifted.reversed_times_words(&words),
        None => {
            let c = shifted.to_bigints();
            Limbs::from_bigints(
                &m.iter()
                    .enumerate()
                    .map(|(i, m)| &c[n - i] * m)
                    .collect::<Vec<_>>(),
            )
        }
    }
}

/// Divides all coefficients by their common power of two.
fn remove_common_twos(b: &mut [BigInt]) {
    let tz = b
        .iter()
        .filter_map(|c| c.trailing_zeros())
        .min()
        .unwrap_or(0);
    if tz > 0 {
        for c in b.iter_mut() {
            *c >>= tz;
        }
    }
}

/// de Casteljau at `1/2` on integers: the two halves, each `2^n` times the true coefficients,
/// over their common power of two.
fn split_half(b: &[BigInt]) -> (Vec<BigInt>, Vec<BigInt>) {
    let n = b.len() - 1;
    let mut work = b.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = vec![BigInt::zero(); n + 1];
    left.push(&b[0] << n);
    right[n] = &b[n] << n;
    for k in 1..=n {
        for i in 0..=n - k {
            let (lo, hi) = work.split_at_mut(i + 1);
            lo[i] += &hi[0];
        }
        left.push(&work[0] << (n - k));
        right[n - k] = &work[n - k] << (n - k);
    }
    remove_common_twos(&mut left);
    remove_common_twos(&mut right);
    (left, right)
}

/// A root of a unit problem: `Exact(c, j)` is `c / 2^j`; `Open` an open interval `(a, b)` with
/// dyadic ends holding exactly one root, with an estimate of the root when there is one: for
/// a subdivision leaf from its Bernstein coefficients ([`bernstein_root_estimate`]), for the
/// halves of a split pair from the parabola through the split point ([`PairSplitter`]).
enum UnitRoot {
    Exact(BigInt, u64),
    Open {
        a: Rational,
        b: Rational,
        estimate: Option<UnitEstimate>,
    },
}

/// The roots in the open interval `(0, 1)` of the square-free integer polynomial `p` (given by
/// its coefficients; the degree may be below `p.len() - 1`). With `pairs`, a node with two sign
/// variations and equal end signs is first offered to [`split_close_pair`].
fn unit_roots(p: &[BigInt], opts: Options) -> Vec<UnitRoot> {
    if p.len() < 2 {
        return Vec::new();
    }
    if opts.filtered && p.len() - 1 <= filtered::MAX_FILTERED_DEGREE {
        return filtered::unit_roots_filtered(p, opts.pairs).0;
    }
    let b = to_bernstein_integer(p);
    let root = (BigInt::zero(), 0);
    if opts.limbs {
        unit_roots_from(Limbs::from_bigints(&b), p, opts.pairs, root)
    } else {
        unit_roots_from(b, p, opts.pairs, root)
    }
}

/// The integer Bernstein coefficients of a subdivision node: `BigInt`s (the reference) or
/// fixed-width limbs ([`Limbs`]); the filtered subdivision keeps `f64` ones ([`filtered`]).
trait NodeCoeffs: Sized {
    fn degree(&self) -> usize;
    fn sign_at(&self, i: usize) -> Sign;
    fn halves(&self) -> (Self, Self);
    /// The numbers times a common power of two, in `f64` (approximately: for estimates only).
    fn scaled_f64s(&self) -> Vec<f64>;
    fn variations(&self) -> usize {
        isolate::count_variations((0..=self.degree()).map(|i| self.sign_at(i)))
    }
}

impl NodeCoeffs for Vec<BigInt> {
    fn degree(&self) -> usize {
        self.len() - 1
    }
    fn sign_at(&self, i: usize) -> Sign {
        sign_of(&self[i])
    }
    fn halves(&self) -> (Self, Self) {
        split_half(self)
    }
    fn scaled_f64s(&self) -> Vec<f64> {
        let shift = f64_shift(self);
        self.iter().map(|c| scaled_f64(c, shift)).collect()
    }
    fn variations(&self) -> usize {
        variations(self)
    }
}

impl NodeCoeffs for Limbs {
    fn degree(&self) -> usize {
        self.len() - 1
    }
    fn sign_at(&self, i: usize) -> Sign {
        match self.sign(i) {
            -1 => Sign::Negative,
            0 => Sign::Zero,
            _ => Sign::Positive,
        }
    }
    fn halves(&self) -> (Self, Self) {
        self.split_half()
    }
    fn scaled_f64s(&self) -> Vec<f64> {
        self.scaled_f64s()
    }
}

/// The subdivision of [`unit_roots`] below the node `start = (c, j)`, the interval
/// `(c / 2^j, (c + 1) / 2^j)`, from that node's coefficients `b` (the whole unit interval is
/// `(0, 0)`; the filtered subdivision hands nodes over with their own `(c, j)`).
fn unit_roots_from<C: NodeCoeffs>(
    b: C,
    p: &[BigInt],
    pairs: bool,
    start: (BigInt, u64),
) -> Vec<UnitRoot> {
    let mut out = Vec::new();
    let mut pair_splitter: Option<PairSplitter> = None;
    let binoms = binomials_f64(b.degree());
    // (node, c, j, the parent's V was 2, the left end is a split point that is a root).
    let mut stack = vec![(b, start.0, start.1, false, false)];
    while let Some((b, c, j, parent_v2, left_root)) = stack.pop() {
        // Reported after the roots of the left sibling's subtree: the roots come out in
        // increasing order.
        if left_root {
            out.push(UnitRoot::Exact(c.clone(), j));
        }
        let v = b.variations();
        if v == 0 {
            continue;
        }
        let n = b.degree();
        let (s0, sn) = (b.sign_at(0), b.sign_at(n));
        if v == 1 && s0 != Sign::Zero && sn != Sign::Zero {
            out.push(leaf_root(&c, j, b.scaled_f64s(), &binoms));
            continue;
        }
        if pairs && v == 2 && parent_v2 && j >= 2 && s0 != Sign::Zero && s0 == sn {
            let splitter = pair_splitter.get_or_insert_with(|| PairSplitter::new(p));
            if let Some(split) = splitter.split(&c, j, s0) {
                out.extend(pair_roots(&c, j, split));
                continue;
            }
        }
        let (left, right) = b.halves();
        let c2: BigInt = &c << 1;
        let mid_root = right.sign_at(0) == Sign::Zero;
        stack.push((right, &c2 + 1, j + 1, v == 2, mid_root));
        stack.push((left, c2, j + 1, v == 2, false));
    }
    out
}

/// The isolating leaf `(c / 2^j, (c + 1) / 2^j)` with the estimate of its root from the node's
/// Bernstein coefficients `g` in `f64` (any common positive scale).
fn leaf_root(c: &BigInt, j: u64, g: Vec<f64>, binoms: &[f64]) -> UnitRoot {
    let estimate = bernstein_root_estimate(g, binoms).map(|t| UnitEstimate {
        num: c.clone(),
        exp: j,
        off: t * pow2f(-(j.min(2000) as i64)),
    });
    UnitRoot::Open {
        a: dyadic(c, j),
        b: dyadic(&(c + 1), j),
        estimate,
    }
}

/// The two isolating halves of the node `(c, j)` split at the point `x` of a close pair, with
/// the estimates `x -/+ delta` ([`PairSplitter::split`]).
fn pair_roots(c: &BigInt, j: u64, (x, delta): (Dyadic, Option<f64>)) -> [UnitRoot; 2] {
    let (a, m, e) = (dyadic(c, j), x.to_rational(), dyadic(&(c + 1), j));
    let d = delta.filter(|d| d.is_finite());
    let estimate = |off: f64| UnitEstimate {
        num: x.num.clone(),
        exp: x.exp,
        off,
    };
    [
        UnitRoot::Open {
            a,
            b: m.clone(),
            estimate: d.map(|d| estimate(-d)),
        },
        UnitRoot::Open {
            estimate: d.map(estimate),
            a: m,
            b: e,
        },
    ]
}

/// An estimate `num / 2^exp + off` of a root of a unit problem: an exact dyadic (a node's end,
/// or a pair's split point) and an `f64` offset (the leaf's estimate within its node, or the
/// pair's half-distance), kept apart so that a root recognised as rational never pays for the
/// exact rational ([`UnitEstimate::to_rational`] is called only by the refinement).
#[derive(Clone, Debug)]
struct UnitEstimate {
    num: BigInt,
    exp: u64,
    off: f64,
}

impl UnitEstimate {
    /// The value in `f64` (approximately).
    fn to_f64(&self) -> f64 {
        let base = match approx(&self.num) {
            None => 0.0,
            Some((m, e)) => m * pow2f(e.saturating_sub(self.exp as i64)),
        };
        base + self.off
    }

    /// The exact value (`None` when the offset is not finite).
    fn to_rational(&self) -> Option<Rational> {
        let base = Rational::from_dyadic(&self.num, self.exp);
        Some(if self.off == 0.0 {
            base
        } else {
            base + rational_of_f64(self.off)?
        })
    }
}

/// A [`UnitEstimate`] of a root of unit problem `which` of [`isolate_square_free`], read as
/// an estimate of the root of `q`: `x`, `1/x`, `-x`, `-1/x`.
#[derive(Clone, Debug)]
struct Estimate {
    unit: UnitEstimate,
    which: usize,
}

impl Estimate {
    fn map_f64(&self, x: f64) -> f64 {
        match self.which {
            0 => x,
            1 => 1.0 / x,
            2 => -x,
            _ => -1.0 / x,
        }
    }

    /// The estimate in `f64` (for the rational-root candidates).
    fn to_f64(&self) -> f64 {
        self.map_f64(self.unit.to_f64())
    }

    /// The exact estimate (for the refinement's first window); `None` at zero.
    fn to_rational(&self) -> Option<Rational> {
        let x = self.unit.to_rational().filter(|x| !x.is_zero())?;
        Some(match self.which {
            0 => x,
            1 => x.recip().expect("non-zero"),
            2 => -x,
            _ => -x.recip().expect("non-zero"),
        })
    }
}

/// The finite `f64` `x` as an exact rational.
fn rational_of_f64(x: f64) -> Option<Rational> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some(Rational::ZERO);
    }
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    let m = Rational::from(BigInt::from(m));
    let r = if e >= 0 {
        m * pow2(e as u64)
    } else {
        m / pow2((-e) as u64)
    };
    Some(if x < 0.0 { -r } else { r })
}

/// `x 2^-shift` in `f64` for an integer `x` (approximately; `0` on underflow).
/// The common shift that brings the largest of `cs` to about 60 bits before [`scaled_f64`],
/// so that the scaled values stay in `f64`'s range whatever the coefficients' size.
fn f64_shift(cs: &[BigInt]) -> u64 {
    cs.iter()
        .map(BigInt::bits)
        .max()
        .unwrap_or(0)
        .saturating_sub(60)
}

fn scaled_f64(x: &BigInt, shift: u64) -> f64 {
    match approx(x) {
        None => 0.0,
        Some((m, e)) => m * pow2f(e - shift as i64),
    }
}

/// `C(n, i)` for `i = 0..=n` in `f64` by the recurrence `C(n, i + 1) = C(n, i) (n - i) /
/// (i + 1)` (`2i` roundings: a relative error below `2.01 n 2^-53` for `n <= 1000`, and no
/// overflow there: `C(1000, 500) < 2^996`), computed once per unit problem: the chain of
/// dependent divisions is the slow part of the leaf estimate otherwise.
fn binomials_f64(n: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(n + 1);
    let mut binom = 1f64;
    for i in 0..=n {
        out.push(binom);
        binom = binom * (n - i) as f64 / (i + 1) as f64;
    }
    out
}

/// An `f64` estimate of the root in `(0, 1)` of the Bernstein polynomial with these
/// coefficients (one sign variation, non-zero ends): safeguarded Newton (Newton inside a
/// bracket, bisection when a step leaves it or does not halve the step before last) on
/// `B(t) / (1 - t)^n = sum b_i C(n, i) s^i`, `s = t / (1 - t)`, for `t <= 1/2` and on
/// `B(t) / t^n` (Horner in `(1 - t) / t`) above, a smooth function with the sign of `B`
/// evaluated with every power at most 1, from the control polygon's crossing of the axis.
/// Only a candidate generator for [`RationalRoots::recognise`] and the refinement's first window
/// (nothing is decided on it); `None` beyond degree 1000 (the binomials leave the `f64` range).
fn bernstein_root_estimate(mut g: Vec<f64>, binoms: &[f64]) -> Option<f64> {
    let n = g.len().checked_sub(1)?;
    if n > 1000 || n == 0 {
        return None;
    }
    debug_assert_eq!(binoms.len(), n + 1);
    let (mut a, fa0, mut c, fc0) = (0.0f64, g[0], 1.0f64, g[n]);
    if !(fa0.is_finite() && fc0.is_finite())
        || fa0 == 0.0
        || fc0 == 0.0
        || (fa0 > 0.0) == (fc0 > 0.0)
    {
        return None;
    }
    // The control polygon (i / n, b_i) crosses the axis once (one sign variation).
    let mut x = 0.5;
    if let Some(k) = (0..n).find(|&k| g[k] != 0.0 && (g[k] > 0.0) != (g[k + 1] > 0.0)) {
        let cross = (k as f64 + g[k] / (g[k] - g[k + 1])) / n as f64;
        if cross > 0.0 && cross < 1.0 {
            x = cross;
        }
    }
    for (v, b) in g.iter_mut().zip(binoms) {
        *v *= b;
    }
    if !g.iter().all(|v| v.is_finite()) {
        return None;
    }
    // The function and its derivative in t.
    let eval = |t: f64| -> (f64, f64) {
        if t <= 0.5 {
            let w = 1.0 - t;
            let s = t / w;
            let (mut p, mut dp) = (0.0, 0.0);
            for &gi in g.iter().rev() {
                dp = dp * s + p;
                p = p * s + gi;
            }
            (p, dp / (w * w))
        } else {
            let u = (1.0 - t) / t;
            let (mut q, mut dq) = (0.0, 0.0);
            for &gi in &g {
                dq = dq * u + q;
                q = q * u + gi;
            }
            (q, -dq / (t * t))
        }
    };
    let negative_left = fa0 < 0.0;
    let (mut step, mut step_before) = (c - a, c - a);
    for _ in 0..200 {
        let (f, df) = eval(x);
        if f == 0.0 {
            return Some(x);
        }
        if !f.is_finite() {
            return None;
        }
        if (f < 0.0) == negative_left {
            a = x;
        } else {
            c = x;
        }
        if c - a <= 16.0 * f64::EPSILON * c {
            return Some(0.5 * (a + c));
        }
        let newton = x - f / df;
        if (newton - x).abs() <= 4.0 * f64::EPSILON * x.abs() {
            return Some(newton);
        }
        let next = if newton > a && newton < c && (newton - x).abs() < 0.5 * step_before {
            newton
        } else {
            0.5 * (a + c)
        };
        step_before = step;
        step = (next - x).abs();
        x = next;
    }
    Some(0.5 * (a + c))
}

/// The continued-fraction convergents `p / q` of `x` with `0 < q <= 2^40` (at most 64), lazily
/// (the caller usually stops at the first that passes its tests; no allocation).
fn convergents(x: f64) -> impl Iterator<Item = (i64, i64)> {
    let (mut h1, mut h2, mut k1, mut k2) = (1i128, 0i128, 0i128, 1i128);
    let mut y = x;
    let mut left = if !x.is_finite() || x.abs() > 1e15 {
        0
    } else {
        64
    };
    std::iter::from_fn(move || {
        if left == 0 {
            return None;
        }
        left -= 1;
        let a = y.floor();
        // Saturating; |h1|, k1 <= 2^62 keep the products inside i128.
        let ai = i128::from(a as i64);
        let (h, k) = (ai * h1 + h2, ai * k1 + k2);
        if k > 1 << 40 || h.abs() > 1 << 62 {
            left = 0;
            return None;
        }
        // Word-sized now: the conversions to f64 are single instructions.
        let (h64, k64) = (h as i64, k as i64);
        let frac = y - a;
        if frac <= 0.0 || (h64 as f64 / k64 as f64 - x).abs() <= 2.0 * f64::EPSILON * x.abs() {
            left = 0;
        }
        y = 1.0 / frac;
        (h2, h1, k2, k1) = (h1, h, k1, k);
        Some((h64, k64))
    })
}

/// `x mod m` for `m > 0` (non-negative).
fn rem_small(x: &BigInt, m: u64) -> u64 {
    // Up to 128 bits without copying the limbs.
    if let Some(v) = x.magnitude().to_u128() {
        return (v % u128::from(m)) as u64;
    }
    crate::bigint::rem_1(&x.magnitude().to_u64_digits(), m)
}

/// The quotient `a / (q x - p)` when `q x - p` divides the integer polynomial `a` (`q > 0`):
/// synthetic division with every quotient coefficient an exact integer division by the word
/// `q`, stopping at the first non-zero remainder. The reference of the tests for the limb
/// kernel [`Limbs::divide_by_linear`].
#[cfg(test)]
fn divide_by_linear_factor(a: &[BigInt], p: i64, q: i64) -> Option<Vec<BigInt>> {
    let n = a.len() - 1;
    let qu = q as u64;
    // a = (q x - p) s: a_n = q s_{n-1}, a_k = q s_{k-1} - p s_k, a_0 = -p s_0.
    let mut quotient = vec![BigInt::zero(); n];
    let mut s = BigInt::zero();
    for k in (1..=n).rev() {
        s *= p;
        s += &a[k];
        if rem_small(&s, qu) != 0 {
            return None;
        }
        s /= qu;
        quotient[k - 1] = s.clone();
    }
    s *= p;
    s += &a[0];
    s.is_zero().then_some(quotient)
}

/// Whether `q x - p` divides `a` ([`divide_by_linear_factor`]).
#[cfg(test)]
fn linear_factor_divides(a: &[BigInt], p: i64, q: i64) -> bool {
    divide_by_linear_factor(a, p, q).is_some()
}

/// The rational root in the open interval `(lo, hi)` of the primitive square-free `q`, found
/// among the continued-fraction convergents `p / q` of the estimate `est` (module
/// documentation, "Rational roots"): a convergent is tried when it lies in the interval and
/// passes the rational root theorem's tests `q | lc`, `p | a_k` (`a_k` the lowest non-zero
/// coefficient); it is a root exactly when `q x - p` divides the polynomial.
#[cfg(test)]
fn recognise_rational(poly: &[BigInt], est: f64, lo: &Rational, hi: &Rational) -> Option<Rational> {
    let mut r = RationalRoots::new(poly);
    r.recognise(est, lo, hi)
}

/// The rational-root recognition of one polynomial (module documentation, "Rational roots"):
/// the polynomial with the roots found so far divided out, in fixed-width limbs wide enough
/// for every factor ([`super::limbs::linear_factor_width`]), and the magnitudes of the
/// original leading and lowest non-zero coefficients for the rational root theorem's filters.
struct RationalRoots {
    deflated: Limbs,
    lc: Vec<u64>,
    low: Vec<u64>,
}

impl RationalRoots {
    /// For the primitive square-free `q` (degree >= 1).
    fn new(q: &[BigInt]) -> RationalRoots {
        let w = super::limbs::linear_factor_width(q);
        let low = q.iter().find(|c| !c.is_zero()).expect("q is not zero");
        RationalRoots {
            deflated: Limbs::from_bigints_width(q, w),
            lc: q[q.len() - 1].magnitude().to_u64_digits(),
            low: low.magnitude().to_u64_digits(),
        }
    }

    /// The rational root in `(lo, hi)` among the convergents of `est`, divided out of the
    /// polynomial when found.
    fn recognise(&mut self, est: f64, lo: &Rational, hi: &Rational) -> Option<Rational> {
        if self.deflated.len() < 2 {
            return None;
        }
        // A candidate clearly outside `(lo, hi)` is skipped before its divisibility tests:
        // `p / q` in `f64` (p rounded, one division) and the converted ends are each within a
        // relative `2^-52` of the true values, so `p / q < lo_f - delta` proves `p / q < lo`
        // (and symmetrically); a comparison with an infinity or a NaN never skips.
        let (lo_f, hi_f) = (lo.to_f64(), hi.to_f64());
        let delta = (lo_f.abs() + hi_f.abs()) * pow2f(-48);
        for (p, q) in convergents(est) {
            let pq = p as f64 / q as f64;
            if p == 0
                || pq < lo_f - delta
                || pq > hi_f + delta
                || crate::bigint::rem_1(&self.lc, q as u64) != 0
                || crate::bigint::rem_1(&self.low, p.unsigned_abs()) != 0
            {
                continue;
            }
            let r = Rational::new(p, q).expect("q > 0");
            if r > *lo && r < *hi {
                if let Some(quotient) = self.deflated.divide_by_linear(p, q) {
                    self.deflated = quotient;
                    return Some(r);
                }
            }
        }
        None
    }
}

/// Separates a close root pair (module documentation, "Close pairs"): on the dyadic node
/// `(c / 2^j, (c + 1) / 2^j)` of a unit problem `p`, where Descartes' bound is 2 and the end
/// signs are both `s`, a point strictly inside at which `p` has the sign `-s`, found by Newton's
/// method on `p'` (in `f64`, then exact dyadic steps doubling the precision) and verified by an
/// exact sign. `None` when none was found (the node is then subdivided).
struct PairSplitter<'a> {
    p: &'a [BigInt],
    pf: Vec<f64>,
    d1f: Vec<f64>,
    d2f: Vec<f64>,
    /// `p'` and `p''` exactly, built on the first exact Newton step.
    exact: std::cell::OnceCell<(Vec<BigInt>, Vec<BigInt>)>,
}

/// The precision cap (bits after the binary point) of the exact Newton steps.
const PAIR_MAX_BITS: u64 = 4096;

impl<'a> PairSplitter<'a> {
    /// The `f64` images of `p`, `p'`, `p''` (one common scaling); the exact derivatives wait
    /// for the first pair that passes the `f64` test.
    fn new(p: &'a [BigInt]) -> PairSplitter<'a> {
        let shift = f64_shift(p);
        let pf: Vec<f64> = p.iter().map(|c| scaled_f64(c, shift)).collect();
        let d1f = pf
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * i as f64)
            .collect();
        let d2f = pf
            .iter()
            .enumerate()
            .skip(2)
            .map(|(i, c)| c * (i * (i - 1)) as f64)
            .collect();
        PairSplitter {
            p,
            pf,
            d1f,
            d2f,
            exact: std::cell::OnceCell::new(),
        }
    }

    /// `(p', p'')` exactly (each at least the zero constant).
    fn derivatives(&self) -> &(Vec<BigInt>, Vec<BigInt>) {
        self.exact.get_or_init(|| {
            let deriv = |a: &[BigInt]| -> Vec<BigInt> {
                let mut d: Vec<BigInt> = a
                    .iter()
                    .enumerate()
                    .skip(1)
                    .map(|(i, c)| c * BigInt::from(i))
                    .collect();
                if d.is_empty() {
                    d.push(BigInt::zero());
                }
                d
            };
            let d1 = deriv(self.p);
            let d2 = deriv(&d1);
            (d1, d2)
        })
    }

    /// `a(x) 2^(k deg)` for `x = m / 2^k` (`deg = a.len() - 1`).
    fn eval(a: &[BigInt], x: &Dyadic) -> BigInt {
        let n = a.len() - 1;
        let mut v = a[n].clone();
        for (i, c) in a[..n].iter().enumerate().rev() {
            v = v * &x.num + (c << (x.exp * (n - i) as u64));
        }
        v
    }

    /// The split point and, when it can be computed, the estimate `delta = sqrt(2 |p(x) /
    /// p''(x)|)` of the distance from it to either root (the roots of the parabola through the
    /// split point, which is a near-critical point). Only attempted when the `f64` value of
    /// `delta` at the `f64` critical point is below `1/256` of the node width (a pair that
    /// subdivision would not separate in a few levels).
    fn split(&self, c: &BigInt, j: u64, s: Sign) -> Option<(Dyadic, Option<f64>)> {
        let horner = |a: &[f64], x: f64| a.iter().rev().fold(0.0, |acc, &ai| acc * x + ai);
        let scale = pow2f(-(j.min(2000) as i64));
        let (lo_f, hi_f) = (c.to_f64()? * scale, (c.to_f64()? + 1.0) * scale);
        let mut x = 0.5 * (lo_f + hi_f);
        let mut last = f64::INFINITY;
        for _ in 0..60 {
            let step = horner(&self.d1f, x) / horner(&self.d2f, x);
            if !step.is_finite() {
                return None;
            }
            // Newton's corrections shrink until rounding noise takes over (the power-basis
            // values cancel near the roots): a correction that does not shrink ends it.
            if step.abs() >= last.abs() {
                break;
            }
            last = step;
            let next = x - step;
            if !(next > lo_f && next < hi_f) {
                return None;
            }
            x = next;
            if step.abs() <= 4.0 * f64::EPSILON * x.abs() {
                break;
            }
        }
        let delta_f = (2.0 * (horner(&self.pf, x) / horner(&self.d2f, x)).abs()).sqrt();
        if delta_f.is_nan() || delta_f >= (hi_f - lo_f) / 256.0 {
            return None;
        }
        // x as an exact dyadic, then exact Newton steps.
        let mut k: u64 = 60u64.max(j + 8);
        let mut xd = Dyadic {
            num: BigInt::from((x * pow2f(k as i64)).round() as i128),
            exp: k,
        };
        if !(xd.num > (c << (k - j)) && xd.num < ((c + 1) << (k - j))) {
            return None;
        }
        let mut last_step: Option<BigInt> = None;
        loop {
            let pv = Self::eval(self.p, &xd);
            let v = sign_of(&pv);
            if v == sign_neg(s) {
                let p2 = Self::eval(&self.derivatives().1, &xd);
                let delta = match (approx(&pv), approx(&p2)) {
                    (Some((m0, e0)), Some((m2, e2))) => {
                        // p / p'' = (m0 / m2) 2^(e0 - e2 - 2k).
                        let ex = e0 - e2 - 2 * k as i64;
                        let half_ex = ex.div_euclid(2);
                        let odd = ex.rem_euclid(2);
                        let d = (2.0 * (m0 / m2).abs() * pow2f(odd)).sqrt() * pow2f(half_ex);
                        (d.is_finite() && d > 0.0).then_some(d)
                    }
                    _ => None,
                };
                return Some((xd, delta));
            }
            if v == Sign::Zero || 2 * k > PAIR_MAX_BITS {
                // An exact root is not a split point of this kind (the subdivision finds it).
                return None;
            }
            // Newton on p': x - p'(x) / p''(x) at precision 2k.
            let p1 = Self::eval(&self.derivatives().0, &xd); // p'(x) 2^(k (n-1))
            let p2 = Self::eval(&self.derivatives().1, &xd); // p''(x) 2^(k (n-2))
            if p2.is_zero() {
                return None;
            }
            let kk = 2 * k;
            // step 2^kk = p'/p'' 2^kk = p1 2^(kk - k) / p2 (p1 / p2 carries one factor 2^k).
            let step = (&p1 << (kk - k)) / &p2;
            let num = (&xd.num << (kk - k)) - &step;
            let (lo_n, hi_n) = (c << (kk - j), (c + 1) << (kk - j));
            if !(num > lo_n && num < hi_n) {
                return None;
            }
            // Quadratic convergence: the step must shrink (in the finer unit, by far more than
            // the factor 2^k of the unit change).
            if let Some(prev) = &last_step {
                if step.magnitude() > &(prev.magnitude() << (kk - k)) {
                    return None;
                }
            }
            last_step = Some(step);
            xd = Dyadic { num, exp: kk };
            k = kk;
        }
    }
}

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
/// [`RationalRoots::recognise`] and the first window of the refinement).
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
    let one = positive && q.iter().sum::<BigInt>().is_zero();
    let neg: Vec<BigInt> = if negative {
        q.iter()
            .enumerate()
            .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
            .collect()
    } else {
        Vec::new()
    };
    let minus_one = negative && neg.iter().sum::<BigInt>().is_zero();
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

// ------------------------------------------------------------------------------ refinement

/// A dyadic number `num / 2^exp`.
#[derive(Clone, Debug)]
struct Dyadic {
    num: BigInt,
    exp: u64,
}

impl Dyadic {
    fn to_rational(&self) -> Rational {
        dyadic(&self.num, self.exp)
    }

    /// The dyadic `floor(x 2^e) / 2^e`.
    fn floor_of(x: &Rational, e: u64) -> Dyadic {
        let scaled = x.mul_ref(&pow2(e));
        Dyadic {
            num: floor(&scaled),
            exp: e,
        }
    }

    fn to_f64(&self) -> Option<f64> {
        if self.exp > 1000 || self.num.bits() > 1000 {
            return None;
        }
        Some(self.num.to_f64()? * pow2f(-(self.exp.min(2000) as i64)))
    }
}

/// The prepared square-free polynomial of the refinement.
struct Refiner<'a> {
    q: &'a [BigInt],
    qf: Option<Vec<f64>>,
}

/// `(m, e)` with `x ~ m 2^e`, `m` in `[2^63, 2^64)` as `f64` (`None` for zero).
fn approx(x: &BigInt) -> Option<(f64, i64)> {
    let bits = x.bits();
    if bits == 0 {
        return None;
    }
    // The top 64 bits straight from the limbs (no shifted copy).
    let shift = bits.saturating_sub(64);
    let (q, r) = ((shift / 64) as usize, shift % 64);
    let mut limbs = x.magnitude().iter_u64_digits().skip(q);
    let lo = limbs.next().expect("a limb holds the top bits");
    let top = match (r, limbs.next()) {
        (0, _) | (_, None) => lo >> r,
        (_, Some(hi)) => (lo >> r) | (hi << (64 - r)),
    };
    let m = top as f64;
    Some((if x.is_negative() { -m } else { m }, shift as i64))
}

impl Refiner<'_> {
    fn new(q: &[BigInt]) -> Refiner<'_> {
        let qf: Option<Vec<f64>> = q
            .iter()
            .map(|c| c.to_f64().filter(|f| f.is_finite()))
            .collect();
        Refiner { q, qf }
    }

    /// The sign of `q(x)` from `f64` arithmetic when the error bound of the module
    /// documentation allows it.
    fn filtered_sign(&self, x: &Dyadic) -> Option<Sign> {
        let qf = self.qf.as_ref()?;
        let xf = x.to_f64()?;
        let n = qf.len() - 1;
        let ax = xf.abs();
        let mut r = qf[n];
        let mut s = qf[n].abs();
        for &c in qf[..n].iter().rev() {
            r = r * xf + c;
            s = s * ax + c.abs();
        }
        if !s.is_finite() {
            return None;
        }
        let bound = (3 * n + 6) as f64 * f64::EPSILON * s + pow2f(-1000);
        if r > bound {
            Some(Sign::Positive)
        } else if r < -bound {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    /// `q(x) 2^(k n)` for `x = c / 2^k`.
    fn value_exact(&self, x: &Dyadic) -> BigInt {
        PairSplitter::eval(self.q, x)
    }

    /// `(q(x) 2^(k n), q'(x) 2^(k (n-1)))` for `x = c / 2^k`.
    fn eval_exact(&self, x: &Dyadic) -> (BigInt, BigInt) {
        let q = self.q;
        let n = q.len() - 1;
        let mut p = q[n].clone();
        let mut d = BigInt::zero();
        for (i, a) in q[..n].iter().enumerate().rev() {
            d = d * &x.num + &p;
            p = p * &x.num + (a << (x.exp * (n - i) as u64));
        }
        (p, d)
    }

    /// Refines `(lo, hi)` (end signs `s_lo`, `-s_lo`) to width at most `w`: filtered bisection,
    /// then safeguarded Newton steps with a final two-point verification (module documentation).
    fn refine(
        &self,
        lo: Rational,
        hi: Rational,
        s_lo: Sign,
        w: &Rational,
        estimate: Option<Rational>,
    ) -> RootInterval {
        let (mut lo, mut hi) = (lo, hi);
        if hi.sub_ref(&lo) <= *w {
            return RootInterval { lo, hi };
        }
        // The least k >= 0 with 4 2^-k <= w: 2 - k <= floor(log2 w).
        let kk: u64 = (2 - floor_log2(w)).max(0) as u64;
        // With an estimate e of the root, rounded to the grid h = 2^-kk: first the window
        // [e - 2h, e + 2h] (width 4h <= w; exact signs at its ends, each inside the bracket).
        // A miss on one side is followed by the grid points e -/+ 2^m 2h, m = 1, 2, ..., 6, on
        // that side, until the sign flips (the estimate is usually off by a few h).
        if let Some(e) = estimate {
            let scaled = e.mul_ref(&pow2(kk));
            let en = floor(&scaled.add_ref(&half()));
            let at = |k: i64| Dyadic {
                num: &en + BigInt::from(k),
                exp: kk,
            };
            let mut below = false;
            let mut above = false;
            for k in [-2i64, 2] {
                let x = at(k);
                let xr = x.to_rational();
                if xr > lo && xr < hi {
                    match sign_of(&self.value_exact(&x)) {
                        Sign::Zero => return RootInterval::exact(xr),
                        s if s == s_lo => {
                            lo = xr;
                            above = k == 2;
                        }
                        _ => {
                            hi = xr;
                            below = k == -2;
                        }
                    }
                }
            }
            let mut m: i64 = 4;
            for _ in 0..6 {
                let k = if below {
                    -m
                } else if above {
                    m
                } else {
                    break;
                };
                m *= 2;
                let x = at(k);
                let xr = x.to_rational();
                if !(xr > lo && xr < hi) {
                    break;
                }
                match sign_of(&self.value_exact(&x)) {
                    Sign::Zero => return RootInterval::exact(xr),
                    s if s == s_lo => {
                        lo = xr;
                        if below {
                            break;
                        }
                    }
                    _ => {
                        hi = xr;
                        if above {
                            break;
                        }
                    }
                }
            }
            if hi.sub_ref(&lo) <= *w {
                return RootInterval { lo, hi };
            }
        }
        // h = 2^-kk, the largest power of two with 4h <= w (h = 1 when w >= 4).
        let scale = pow2f(kk as i64);
        let s_hi = sign_neg(s_lo);
        // The last exact evaluation (x, q(x) 2^(k n), q'(x) 2^(k (n-1))).
        let mut newton: Option<(Dyadic, BigInt, BigInt)> = None;
        // The size of the last step in units of h (Newton correction or half bracket).
        let mut last_step = f64::INFINITY;
        let mut filter_ok = true;
        loop {
            let width = hi.sub_ref(&lo);
            if width <= *w {
                return RootInterval { lo, hi };
            }
            let width_h = width.to_f64() * scale;
            // The Newton correction t = (q / q') 2^kk from the last exact evaluation, and the
            // Newton point g = x 2^kk - t on the grid h.
            let mut proposal: Option<(f64, BigInt)> = None;
            if let Some((x, p, d)) = newton.take() {
                if let (Some((pm, pe)), Some((dm, de))) = (approx(&p), approx(&d)) {
                    let e = pe - de + kk as i64 - x.exp as i64;
                    if e < 62 {
                        let t = (pm / dm) * pow2f(e);
                        if t.abs() < 4.0e18 {
                            let g = (&x.num << (kk - x.exp)) - (t.round() as i64);
                            proposal = Some((t.abs(), g));
                        }
                    }
                }
            }
            let mut next: Option<Dyadic> = None;
            if let Some((t, g)) = proposal {
                if t <= 1024.0 {
                    // Converged: certify [g - 2h, g + 2h] by the signs at its ends.
                    let a = Dyadic {
                        num: &g - 2,
                        exp: kk,
                    };
                    let b = Dyadic {
                        num: g + 2,
                        exp: kk,
                    };
                    let (ar, br) = (a.to_rational(), b.to_rational());
                    let mut left_ok = true;
                    if ar > lo && ar < hi {
                        let (p, d) = self.eval_exact(&a);
                        match sign_of(&p) {
                            Sign::Zero => return RootInterval::exact(ar),
                            s if s == s_lo => lo = ar,
                            _ => {
                                hi = ar;
                                left_ok = false;
                            }
                        }
                        newton = Some((a, p, d));
                    }
                    if left_ok && br > lo && br < hi {
                        let (p, d) = self.eval_exact(&b);
                        match sign_of(&p) {
                            Sign::Zero => return RootInterval::exact(br),
                            s if s == s_hi => hi = br,
                            _ => lo = br,
                        }
                        newton = Some((b, p, d));
                    }
                    if hi.sub_ref(&lo) > *w {
                        // The verification failed: bisect next.
                        newton = None;
                        last_step = f64::INFINITY;
                    }
                    continue;
                }
                let gd = Dyadic { num: g, exp: kk };
                let gr = gd.to_rational();
                if t <= last_step / 2.0 && gr > lo && gr < hi {
                    last_step = t;
                    next = Some(gd);
                }
            }
            let x = match next {
                Some(g) => g,
                None => {
                    last_step = width_h / 2.0;
                    // A dyadic point in the middle half: 2^-e <= width / 4, so
                    // floor(mid 2^e) / 2^e > mid - 2^-e >= mid - width / 4 > lo, and e <= kk
                    // because 2^-kk <= w / 4 < width / 4.
                    let mid = midpoint(&lo, &hi);
                    // The least e >= 0 with 2^-e <= width / 4.
                    let e = (2 - floor_log2(&width)).max(0) as u64;
                    Dyadic::floor_of(&mid, e)
                }
            };
            let xr = x.to_rational();
            debug_assert!(xr > lo && xr < hi);
            let s = match filter_ok.then(|| self.filtered_sign(&x)).flatten() {
                Some(s) => s,
                None => {
                    filter_ok = false;
                    let (p, d) = self.eval_exact(&x);
                    let s = sign_of(&p);
                    newton = Some((x, p, d));
                    s
                }
            };
            match s {
                Sign::Zero => return RootInterval::exact(xr),
                s if s == s_lo => lo = xr,
                _ => hi = xr,
            }
        }
    }
}

/// `floor(log2 x)` for a positive rational `x`.
fn floor_log2(x: &Rational) -> i64 {
    let (u, v) = (x.numer(), x.denom());
    debug_assert!(u.sign() == BigSign::Plus);
    // 2^(bu - 1) <= u < 2^bu and likewise v: log2 x lies in (b - 1, b + 1), b = bu - bv.
    let b = u.bits() as i64 - v.bits() as i64;
    let at_least_2b = if b >= 0 {
        u >= (v << b as u64)
    } else {
        (u << (-b) as u64) >= v
    };
    if at_least_2b {
        b
    } else {
        b - 1
    }
}

/// The exact sign of the integer polynomial `q` at the rational `x = u / v` (`v > 0`): the sign
/// of `sum q_i u^i v^(n-i)`.
#[cfg(test)]
fn sign_at_rational(q: &[BigInt], x: &Rational) -> Sign {
    let (u, v) = (x.numer(), x.denom());
    let n = q.len() - 1;
    let mut acc = q[n].clone();
    let mut vpow = BigInt::one();
    for a in q[..n].iter().rev() {
        vpow *= &v;
        acc = acc * &u + a * &vpow;
    }
    sign_of(&acc)
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
    let refiner = Refiner::new(&q);
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
        if let (true, Some(est)) = (opts.rationals, &estimate) {
            if let Some(r) = rationals.recognise(est.to_f64(), &ri.lo, &ri.hi) {
                out.push(RootInterval::exact(r));
                continue;
            }
        }
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

#[cfg(test)]
mod unit_tests {
    use super::*;
    use exactcheck_core::bernstein::Bernstein;
    use exactcheck_core::Rng;
    use exactcheck_core::Sign;

    fn bigs(c: &[i64]) -> Vec<BigInt> {
        c.iter().map(|&x| BigInt::from(x)).collect()
    }

    fn rationals(c: &[BigInt]) -> Vec<Rational> {
        c.iter().cloned().map(Rational::from).collect()
    }

    /// `a` is a positive multiple of `b` (coefficientwise, zeros included).
    fn positive_multiple(a: &[BigInt], b: &[Rational]) {
        assert_eq!(a.len(), b.len());
        let mut ratio: Option<Rational> = None;
        for (x, y) in a.iter().zip(b) {
            assert_eq!(x.is_zero(), y.is_zero(), "{a:?} vs {b:?}");
            if !y.is_zero() {
                let r = Rational::from(x.clone()) / y.clone();
                assert_eq!(r.signum(), Sign::Positive);
                if let Some(q) = &ratio {
                    assert_eq!(&r, q);
                }
                ratio = Some(r);
            }
        }
    }

    fn random_poly(rng: &mut Rng, n: usize) -> Vec<BigInt> {
        let mut c: Vec<BigInt> = (0..=n)
            .map(|_| BigInt::from(rng.below(2001) as i64 - 1000))
            .collect();
        if c[n].is_zero() {
            c[n] = BigInt::one();
        }
        c
    }

    #[test]
    fn integer_bernstein_form_and_split_match_the_rational_ones() {
        let mut rng = Rng::new(14);
        for n in 1..=12 {
            let p = random_poly(&mut rng, n);
            let b = to_bernstein_integer(&p);
            let exact = Bernstein::from_power(&rationals(&p)).expect("non-empty");
            positive_multiple(&b, exact.coeffs());
            let (l, r) = split_half(&b);
            // The fixed-width kernel is the BigInt one exactly, twice over.
            let (ll, lr) = Limbs::from_bigints(&b).split_half();
            assert_eq!(ll.to_bigints(), l);
            assert_eq!(lr.to_bigints(), r);
            let (lll, llr) = ll.split_half();
            assert_eq!((lll.to_bigints(), llr.to_bigints()), split_half(&l));
            let (el, er) = exact.split(&half());
            positive_multiple(&l, el.coeffs());
            positive_multiple(&r, er.coeffs());
        }
    }

    #[test]
    fn limb_kernel_matches_bigint_kernel_on_wide_numbers() {
        let mut rng = Rng::new(4141);
        for n in [1usize, 2, 5, 20, 41, 70] {
            for bits in [3u32, 63, 64, 65, 130, 400] {
                let p: Vec<BigInt> = (0..=n)
                    .map(|_| {
                        let x = (BigInt::from(rng.below(1 << 62)) << (bits.saturating_sub(62)))
                            + BigInt::from(rng.below(1 << 20));
                        if rng.below(2) == 0 {
                            -x
                        } else {
                            x
                        }
                    })
                    .collect();
                let b = to_bernstein_integer(&p);
                let mut big = b.clone();
                let mut limbs = Limbs::from_bigints(&b);
                assert_eq!(limbs.to_bigints(), b);
                // Down one path of ten levels, alternating sides.
                for level in 0..10 {
                    let (bl, br) = split_half(&big);
                    let (ll, lr) = limbs.split_half();
                    assert_eq!(ll.to_bigints(), bl, "n {n}, bits {bits}, level {level}");
                    assert_eq!(lr.to_bigints(), br, "n {n}, bits {bits}, level {level}");
                    (big, limbs) = if level % 2 == 0 { (bl, ll) } else { (br, lr) };
                    for (i, c) in big.iter().enumerate() {
                        assert_eq!(limbs.sign_at(i), sign_of(c));
                    }
                }
            }
        }
        // The f64 images of the limbs and of the BigInts agree up to a common power of two.
        for bits in [5u32, 64, 200] {
            let b: Vec<BigInt> = (0..9)
                .map(|i| (BigInt::from(i * 7919 - 30000) << bits) - BigInt::from(i))
                .collect();
            let (x, y) = (Limbs::from_bigints(&b).scaled_f64s(), b.scaled_f64s());
            let ratio = x[0] / y[0];
            assert_eq!(ratio, ratio.log2().round().exp2(), "a power of two");
            for (u, v) in x.iter().zip(&y) {
                assert!(
                    (u - v * ratio).abs() <= 1e-15 * u.abs().max(1e-300),
                    "{u} {v}"
                );
            }
        }
        // The Taylor shift on limbs is the BigInt one (widths 1, 2, 3, 4 and 6 limbs: the
        // fixed-width kernels and the general loop).
        let mut widths = Vec::new();
        for n in [8usize, 20, 40, 57, 90] {
            let c: Vec<BigInt> = (0..=n)
                .map(|i| (BigInt::from(i as i64 * 977 - 20_000) << (i * 3)) - 5)
                .collect();
            let mut reference = c.clone();
            taylor_shift_1(&mut reference);
            let mut l = Limbs::from_bigints_with_room(&c, n + 1);
            let w = l.width();
            l.taylor_shift_1();
            assert_eq!(l.to_bigints(), reference, "width {w}");
            widths.push(w);
        }
        assert_eq!(widths, [1, 2, 3, 4, 6]);
        // The multipliers L / C(n, i) by the recurrence equal the lcm of the binomials over
        // each binomial.
        for n in [1usize, 6, 30, 61] {
            let p: Vec<BigInt> = (0..=n).map(|i| BigInt::from(i as i64 - 3)).collect();
            let mut binom = vec![BigInt::one(); n + 1];
            for i in 1..=n {
                binom[i] = &binom[i - 1] * BigInt::from(n - i + 1) / BigInt::from(i);
            }
            let l = binom
                .iter()
                .fold(BigInt::one(), |l, b| num_integer::Integer::lcm(&l, b));
            let mut c: Vec<BigInt> = p.iter().rev().cloned().collect();
            taylor_shift_1(&mut c);
            let expect: Vec<BigInt> = (0..=n).map(|i| &c[n - i] * (&l / &binom[i])).collect();
            assert_eq!(to_bernstein_integer(&p), expect);
        }
    }

    #[test]
    fn approx_is_the_top_64_bits() {
        let mut rng = Rng::new(7);
        for bits in [1u64, 2, 63, 64, 65, 127, 128, 129, 191, 192, 193, 500] {
            for _ in 0..20 {
                let x: BigInt = (0..bits.div_ceil(64)).fold(BigInt::zero(), |acc, _| {
                    (acc << 64) + BigInt::from(rng.next_u64())
                }) >> (bits.div_ceil(64) * 64 - bits);
                let x = x | (BigInt::one() << (bits - 1));
                for v in [x.clone(), -x.clone()] {
                    let shift = v.bits().saturating_sub(64);
                    let top = (v.magnitude() >> shift).to_u64().expect("64 bits");
                    let m = if v.is_negative() {
                        -(top as f64)
                    } else {
                        top as f64
                    };
                    assert_eq!(approx(&v), Some((m, shift as i64)), "{v}");
                }
            }
        }
        assert_eq!(approx(&BigInt::zero()), None);
    }

    #[test]
    fn word_contents_divide_out_of_big_coefficients() {
        // 3 (x - 2^100) (x + 5): coefficients beyond i128 and a word content of 3 and 6.
        let big: BigInt = BigInt::one() << 100u32;
        for k in [3i64, -6] {
            let k = BigInt::from(k);
            let five = BigInt::from(5);
            let p = [-(&big * &five) * &k, (&five - &big) * &k, k.clone()];
            let q = square_free_integer(&p);
            assert_eq!(q, vec![-(&big * &five), &five - &big, BigInt::one()]);
        }
    }

    #[test]
    fn content_is_the_gcd() {
        let mut rng = Rng::new(99);
        for _ in 0..50 {
            let k = BigInt::from(rng.below(1 << 40) + 1) * BigInt::from(rng.below(1 << 40) + 1);
            let c: Vec<BigInt> = (0..6)
                .map(|_| &k * BigInt::from(rng.below(2001) as i64 - 1000))
                .collect();
            let expect = c
                .iter()
                .fold(BigInt::zero(), |g, x| num_integer::Integer::gcd(&g, x));
            assert_eq!(content(&c), expect);
        }
        assert_eq!(content(&bigs(&[0, 0])), BigInt::zero());
        assert_eq!(content(&bigs(&[0, -6, 0, 9])), BigInt::from(3));
    }

    #[test]
    fn modular_square_free_test() {
        // (x - 1)^2 (x + 2) is not square-free: never "proved".
        assert!(!is_square_free_mod_p(&bigs(&[2, -3, 0, 1])));
        assert!(is_square_free_mod_p(&bigs(&[1, 0, 1])));
        assert!(is_square_free_mod_p(&super::super::w4::wilkinson(30)));
        // The square-free part of (x - 1)^2 (x + 2) is x^2 + x - 2.
        assert_eq!(
            square_free_integer(&bigs(&[-4, 6, 0, -2])),
            bigs(&[-2, 1, 1])
        );
    }

    #[test]
    fn the_filter_never_contradicts_the_exact_sign() {
        let mut rng = Rng::new(53);
        let polys = [
            super::super::w4::wilkinson(20),
            super::super::w4::mignotte(30),
            super::super::w4::random(40),
            random_poly(&mut rng, 25),
        ];
        let mut decided = 0;
        for q in &polys {
            let r = Refiner::new(q);
            for _ in 0..400 {
                let exp = rng.below(60);
                let num = BigInt::from(rng.below(1 << 62) as i64 - (1 << 61)) >> (62 - exp.min(62));
                let x = Dyadic { num, exp };
                let (p, _) = r.eval_exact(&x);
                if let Some(s) = r.filtered_sign(&x) {
                    decided += 1;
                    assert_eq!(s, sign_of(&p), "{x:?}");
                }
                let xr = x.to_rational();
                let v = upoly_of(q).eval(&xr);
                assert_eq!(sign_of(&p), v.signum());
            }
        }
        assert!(decided > 100, "the filter decided only {decided} signs");
    }

    fn upoly_of(q: &[BigInt]) -> UPoly {
        UPoly::from_coeffs(rationals(q))
    }

    /// Checks `found` (refined to width `w`) against the Sturm isolation of `c`: the same count,
    /// sorted and disjoint closed intervals, each of width at most `w` and overlapping exactly
    /// one Sturm interval, each exact one a root, each open one with end values of opposite
    /// non-zero signs of the square-free part.
    fn check_refined_against_sturm(c: &[BigInt], found: &[RootInterval], w: &Rational) {
        check_against_sturm_with(c, found, w, true);
    }

    /// `strict`: the closed intervals are disjoint (refined); otherwise they may share an end
    /// (isolating intervals).
    fn check_against_sturm_with(c: &[BigInt], found: &[RootInterval], w: &Rational, strict: bool) {
        let p = upoly_of(c);
        let sturm = p.isolate_roots();
        assert_eq!(found.len(), sturm.len(), "{p}: {found:?} vs {sturm:?}");
        let sqf = p.square_free_part();
        for pair in found.windows(2) {
            assert!(
                pair[0].hi < pair[1].lo || (!strict && pair[0].hi == pair[1].lo),
                "{pair:?} of {p}"
            );
        }
        for (f, s) in found.iter().zip(&sturm) {
            assert!(f.width() <= *w, "{f:?} of {p} wider than {w}");
            if f.is_exact() {
                assert!(p.eval(&f.lo).is_zero(), "{f:?} is not a root of {p}");
                assert!(s.lo <= f.lo && f.lo <= s.hi, "{f:?} vs {s:?} of {p}");
            } else {
                let (a, b) = (sqf.sign_at(&f.lo), sqf.sign_at(&f.hi));
                assert!(a != Sign::Zero && b != Sign::Zero && a != b, "{f:?} of {p}");
                let lo = f.lo.clone().max(s.lo.clone());
                let hi = f.hi.clone().min(s.hi.clone());
                assert!(lo <= hi, "{f:?} vs {s:?} of {p}");
            }
        }
    }

    fn product(factors: &[(i64, i64)], rest: &[i64]) -> Vec<BigInt> {
        let mut p = UPoly::from_i64_coeffs(rest);
        for &(q, r) in factors {
            p *= UPoly::from_i64_coeffs(&[-r, q]);
        }
        p.integer_coefficients()
    }

    /// Runs the fast and the reference isolator, checks both against Sturm, returns the fast
    /// answer.
    fn both(c: &[BigInt], w: &Rational) -> Vec<RootInterval> {
        let fast = real_roots_to_with(c, w, Options::FAST).expect("non-zero");
        let reference = real_roots_to_with(c, w, Options::REFERENCE).expect("non-zero");
        check_refined_against_sturm(c, &fast, w);
        check_refined_against_sturm(c, &reference, w);
        let coarse = integer_real_roots(c).expect("non-zero");
        check_against_sturm_with(c, &coarse, &Rational::from(BigInt::one() << 4000u32), false);
        fast
    }

    #[test]
    fn rational_roots_are_recognised_exactly() {
        let w = super::super::w4::target_width();
        let mut rng = Rng::new(1414);
        for round in 0..24 {
            // Distinct rational roots r / q with denominators up to 60, some dividing a small
            // leading coefficient, some dyadic, some at 0 and +-1, times an irreducible
            // quadratic (x^2 + 2 or x^2 - 3: irrational or complex roots).
            let k = 1 + rng.below(9) as usize;
            let mut roots: Vec<(i64, i64)> = Vec::new();
            while roots.len() < k {
                let q = 1 + rng.below(if round % 2 == 0 { 60 } else { 8 }) as i64;
                let r = rng.below(8 * q as u64 + 1) as i64 - 4 * q;
                let g = num_integer::Integer::gcd(&r, &q);
                let (r, q) = (r / g.max(1), q / g.max(1));
                if !roots.contains(&(q, r)) {
                    roots.push((q, r));
                }
            }
            let rest: &[i64] = if round % 3 == 0 {
                &[-3, 0, 1]
            } else {
                &[2, 0, 1]
            };
            let c = product(&roots, rest);
            let fast = both(&c, &w);
            let exact = fast.iter().filter(|r| r.is_exact()).count();
            assert_eq!(exact, roots.len(), "{roots:?}: {fast:?}");
        }
        // The Wilkinson products: every root exact.
        for n in [5usize, 20, 40] {
            let fast = both(&super::super::w4::wilkinson(n), &w);
            assert!(fast.iter().all(RootInterval::is_exact), "wilkinson({n})");
        }
    }

    #[test]
    fn recognition_needs_the_divisibility_and_the_exact_test() {
        // x^2 - 2 (roots +-sqrt 2): the convergents 3/2, 7/5, 17/12, ... of sqrt 2 pass
        // neither p | 2 with q | 1 nor the exact test: nothing is recognised.
        let c = bigs(&[-2, 0, 1]);
        let lo = Rational::from_integer(1);
        let hi = Rational::from_integer(2);
        assert_eq!(
            recognise_rational(&c, std::f64::consts::SQRT_2, &lo, &hi),
            None
        );
        // 3 x^2 - 2 x - 1 = (3 x + 1)(x - 1): an estimate near -1/3 finds it, one near 1 too.
        let c = bigs(&[-1, -2, 3]);
        let third = Rational::new(-1, 3).expect("3");
        assert_eq!(
            recognise_rational(
                &c,
                -0.333_333_3,
                &Rational::from_integer(-1),
                &Rational::ZERO
            ),
            Some(third)
        );
        // A candidate outside the interval is not returned.
        assert_eq!(
            recognise_rational(
                &c,
                -0.333_333_3,
                &Rational::ZERO,
                &Rational::from_integer(2)
            ),
            None
        );
        assert!(linear_factor_divides(&c, -1, 3));
        assert!(linear_factor_divides(&c, 1, 1));
        assert!(!linear_factor_divides(&c, 1, 3));
        assert_eq!(
            convergents(0.75).collect::<Vec<_>>(),
            vec![(0, 1), (1, 1), (3, 4)]
        );
        assert_eq!(convergents(f64::NAN).count(), 0);
        assert_eq!(convergents(2.0).collect::<Vec<_>>(), vec![(2, 1)]);
    }

    /// The Bernstein form from the shifted limbs equals the `BigInt` one, with word
    /// multipliers (degree up to 44) and with big ones (above).
    #[test]
    fn bernstein_from_shifted_limbs_agrees() {
        let mut rng = Rng::new(77);
        for n in [1usize, 2, 8, 20, 44, 45, 60, 90] {
            let p: Vec<BigInt> = (0..=n)
                .map(|_| BigInt::from(rng.next_u64() as i64) << (rng.below(90) as u32))
                .collect();
            let rev: Vec<BigInt> = p.iter().rev().cloned().collect();
            let mut shifted = Limbs::from_bigints_with_room(&rev, n + 1);
            shifted.taylor_shift_1();
            assert_eq!(
                bernstein_from_shifted(&shifted).to_bigints(),
                to_bernstein_integer(&p),
                "degree {n}"
            );
        }
    }

    /// `BigInt`s through limbs and back: signs, zero, `-2^(64k)`, `2^(64k) - 1`, with room.
    #[test]
    fn limbs_round_trip() {
        let mut cs: Vec<BigInt> = vec![BigInt::zero(), BigInt::one(), -BigInt::one()];
        for k in [1u32, 2, 3] {
            let p = BigInt::one() << (64 * k);
            cs.extend([p.clone(), -p.clone(), &p - 1, 1 - &p, -(&p >> 1u32)]);
        }
        for extra in [0, 1, 63, 64, 200] {
            let l = Limbs::from_bigints_with_room(&cs, extra);
            assert_eq!(l.to_bigints(), cs, "room {extra}");
        }
        assert_eq!(Limbs::from_bigints_width(&cs, 6).to_bigints(), cs);
    }

    /// The limb synthetic division ([`Limbs::divide_by_linear`]) against the `BigInt` one:
    /// products `(q x - p) g` with random `g` (coefficients up to 200 bits, both parities of
    /// `q` and `p`, signs, words near 2^63) give the quotient `g`, and other linear factors
    /// are refused exactly when the reference refuses them.
    #[test]
    fn limb_division_agrees_with_the_bigint_reference() {
        let mut rng = Rng::new(2611);
        let word = |rng: &mut Rng| -> i64 {
            match rng.below(4) {
                0 => 1 + rng.below(7) as i64,
                1 => 1 + rng.below(1 << 20) as i64,
                2 => (rng.next_u64() >> 1) as i64,
                _ => i64::MAX - rng.below(5) as i64,
            }
        };
        for round in 0..400 {
            let deg = 1 + rng.below(12) as usize;
            let bits = [3u64, 64, 200][round % 3];
            let g: Vec<BigInt> = (0..=deg)
                .map(|_| {
                    let mut x = BigInt::from(rng.next_u64());
                    for _ in 0..bits / 64 {
                        x = (x << 64u32) + BigInt::from(rng.next_u64());
                    }
                    x >>= (64 - bits % 64) % 64;
                    if rng.below(2) == 0 {
                        -x
                    } else {
                        x
                    }
                })
                .collect();
            if g[deg].is_zero() {
                continue;
            }
            let (mut p, mut q) = (word(&mut rng), word(&mut rng));
            let gc = num_integer::Integer::gcd(&p, &q);
            (p, q) = (p / gc, q / gc);
            if rng.below(2) == 0 {
                p = -p;
            }
            // a = (q x - p) g.
            let mut a = vec![BigInt::zero(); deg + 2];
            for (i, c) in g.iter().enumerate() {
                a[i + 1] += c * q;
                a[i] -= c * p;
            }
            let w = super::super::limbs::linear_factor_width(&a);
            let l = Limbs::from_bigints_width(&a, w);
            let got = l
                .divide_by_linear(p, q)
                .expect("a true factor is certified");
            assert_eq!(got.to_bigints(), g, "round {round}: ({q} x - {p})");
            // Other candidates: the reference decides.
            for (p2, q2) in [(p + 1, q), (p, q + 2), (p + q, q), (1, 1), (-1, 2)] {
                if p2 == 0 || q2 <= 0 || num_integer::Integer::gcd(&p2, &q2) != 1 {
                    continue;
                }
                let expected = divide_by_linear_factor(&a, p2, q2);
                let got = l.divide_by_linear(p2, q2).map(|x| x.to_bigints());
                assert_eq!(got, expected, "round {round}: ({q2} x - {p2})");
            }
        }
    }

    #[test]
    fn close_pairs_are_split_and_agree_with_the_reference() {
        let w = super::super::w4::target_width();
        // Mignotte-type x^n - 2 (a x - 1)^2 with other parameters, and (x - a)(x - a - eps) g.
        for (n, a) in [(12usize, 7i64), (25, 10), (33, 3), (40, 13), (50, 10)] {
            let mut c = vec![BigInt::zero(); n + 1];
            c[n] += 1;
            c[2] -= 2 * a * a;
            c[1] += 4 * a;
            c[0] -= 2;
            // Both checked against Sturm (4 real roots for even n, 3 for odd n).
            let fast = both(&c, &w);
            assert_eq!(fast.len(), 4 - n % 2, "n {n}, a {a}");
        }
        for e in [20u32, 45, 70, 120] {
            let a = Rational::new(2, 7).expect("7");
            let eps = Rational::from(BigInt::one()) / Rational::from(BigInt::one() << e);
            let g = UPoly::from_i64_coeffs(&[5, -1, 0, 3, 0, 1]);
            let p = UPoly::from_roots(&[a.clone(), a + eps]) * g;
            let fast = both(&p.integer_coefficients(), &w);
            assert_eq!(fast.len(), 3, "eps 2^-{e}");
        }
    }

    #[test]
    fn pair_splitter_verifies_its_point() {
        // x^2 - 2 (4 x - 1)^2 on the node (0, 1/2) at depth 1, ends negative... use the
        // Mignotte polynomial x^30 - 2 (10 x - 1)^2 on (1/16, 1/8): the split point has the
        // opposite sign and lies strictly inside.
        let p = super::super::w4::mignotte(30);
        let s = PairSplitter::new(&p);
        let (x, delta) = s
            .split(&BigInt::from(1), 4, Sign::Negative)
            .expect("a pair");
        let xr = x.to_rational();
        assert!(xr > Rational::new(1, 16).expect("16") && xr < Rational::new(1, 8).expect("8"));
        assert_eq!(sign_at_rational(&p, &xr), Sign::Positive);
        let d = delta.expect("an estimate");
        assert!(d > 0.0 && d < 1e-10, "{d}");
        // x^2 + 1 shifted: (8x - 1)^2 + 1 has no real root; V may be 2 but no split point.
        let q = bigs(&[2, -16, 64]);
        let s = PairSplitter::new(&q);
        assert!(s.split(&BigInt::from(0), 2, Sign::Positive).is_none());
    }

    #[test]
    fn random_polynomials_agree_with_the_reference() {
        let w = super::super::w4::target_width();
        let mut rng = Rng::new(77);
        for n in [1usize, 2, 3, 7, 15, 31] {
            for _ in 0..4 {
                let c = random_poly(&mut rng, n);
                both(&c, &w);
            }
        }
        // Repeated roots (the square-free part), roots at 0 and +-1, huge and tiny coefficients.
        let cases = [
            product(&[(1, 0), (1, 1), (1, -1), (3, 1), (3, 1), (2, 1)], &[1]),
            product(&[(7, 3), (7, 3), (7, 3), (1, 5)], &[1, 1, 1]),
            product(&[(1, 1 << 40), (1 << 40, 1), (3, -(1 << 35))], &[1]),
            bigs(&[-(1 << 62), 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]),
            bigs(&[1, 0, 0, -(1 << 62)]),
        ];
        for c in &cases {
            both(c, &w);
        }
        for (family, degree, count) in super::super::w4::COMPARISON {
            let c = family.polynomial(degree);
            let fast = real_roots_to_with(&c, &w, Options::FAST).expect("non-zero");
            assert_eq!(fast.len(), count);
            if degree <= 50 {
                check_refined_against_sturm(&c, &fast, &w);
            }
        }
    }

    /// One comparison instance through the fast path: the pinned count, width and order (one
    /// test per instance, so each can be profiled alone: `valgrind --tool=callgrind
    /// target/release/deps/exactcheck_exact-* --exact univariate::descartes::unit_tests::w4_wilkinson_20`).
    fn w4_instance(index: usize) {
        let (family, degree, count) = super::super::w4::COMPARISON[index];
        let w = super::super::w4::target_width();
        let roots = super::super::w4::solve(&family.polynomial(degree));
        assert_eq!(roots.len(), count);
        assert!(roots.iter().all(|r| r.width() <= w));
        assert!(roots.windows(2).all(|p| p[0].hi < p[1].lo));
    }

    #[test]
    fn w4_wilkinson_20() {
        w4_instance(0);
    }

    #[test]
    fn w4_wilkinson_40() {
        w4_instance(1);
    }

    #[test]
    fn w4_random_50() {
        w4_instance(2);
    }

    #[test]
    fn w4_random_100() {
        w4_instance(3);
    }

    #[test]
    fn w4_mignotte_20() {
        w4_instance(4);
    }

    #[test]
    fn w4_mignotte_40() {
        w4_instance(5);
    }

    #[test]
    fn refinement_brackets_roots_of_close_pairs() {
        // Roots 1/3 and 1/3 + 2^-40.
        let third = Rational::new(1, 3).expect("3");
        let p = UPoly::from_roots(&[
            Rational::new(1, 3).expect("3"),
            Rational::new(1, 3).expect("3")
                + Rational::from(BigInt::one()) / Rational::from(BigInt::one() << 40u32),
        ]);
        let w = super::super::w4::target_width();
        let roots = p.isolate_real_roots_to(&w);
        assert_eq!(roots.len(), 2);
        assert!(roots[0].hi < roots[1].lo);
        for r in &roots {
            assert!(r.is_exact() || r.width() <= w);
        }
        assert!(roots[0].lo <= third && third <= roots[0].hi);
        assert!(roots[1].lo > third);
    }
}
