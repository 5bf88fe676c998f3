//! Powers of polynomials with few terms: the power recurrence, and the cost model that chooses
//! between it and binary powering.
//!
//! # The recurrence
//! For `Q = P^e` and any derivation `D`, `P D(Q) = e Q D(P)`. Take for `D` the Euler operator of
//! a linear weight `w` on monomials (`D(m) = w(m) m`), write `P = sum a_i m_i` with `m_0` its
//! leading monomial, and compare the coefficients of a monomial `mu` on both sides: with
//! `W = w(mu)`,
//!
//! ```text
//!     sum over m_i n = mu of  a_i q_n ((e + 1) w(m_i) - W) = 0.
//! ```
//!
//! The term `i = 0` has `n = mu / m_0`, every other term `n = mu / m_i > mu / m_0` (the order is
//! a monoid order). So the coefficients of `Q` come out in decreasing order, each from the
//! earlier ones and the other `t - 1` terms of `P`, with one exact division:
//!
//! ```text
//!     q_(mu / m_0) = sum over i >= 1 of a_i q_(mu / m_i) ((e + 1) w_i - W)
//!                    / (a_0 (W - (e + 1) w_0)),             q_(m_0^e) = a_0^e.
//! ```
//!
//! This is J. C. P. Miller's recurrence for the powers of a power series (Knuth, TAOCP 2,
//! 4.7), in its multivariate form with a leading term. The divisor is not zero when `m_0` is
//! the **only** monomial of `P` of largest weight: then every monomial `n != m_0^e` of `Q` has
//! `w(n) < e w_0`. Such a weight exists because the leading monomial is a vertex of the Newton
//! polytope; it is built variable by variable from the top of the order
//! (`w = x_top`, then `w <- (d + 1) w + x_next` while other terms tie with `m_0`, `d` the largest
//! exponent of the next variable), which stops as soon as `m_0` is alone, so for most bases it is
//! just the degree in the top variable.
//!
//! The products `m_i q_n` are merged by a heap of the `t - 1` streams `i >= 1` (as in Johnson's
//! multiplication), each walking down the terms of `Q` computed so far; a stream that reaches
//! the end of `Q` waits until the next term is known, which is always smaller than what it
//! waits for, so every monomial leaves the heap with all its products. A monomial whose sum is
//! zero has no term (and when `m_0` does not divide it, the sum is zero by the identity; the
//! division is checked anyway). The cost is about `(t - 1) N` products of an output coefficient
//! by a machine word and `N` exact divisions by two machine words, for `N` terms of `P^e`: one
//! pass, linear in the output, where binary powering's last squaring alone takes about
//! `N_(e/2)^2 / 2` products of two large coefficients. For `P = 16 (t + x^2 + y + 3 x y_x)` and
//! `e = 74` (a fuzz input) that is 220,000 word products instead of 34 million big ones.
//!
//! It runs for `Rational` coefficients (after [`Poly::split_content`] the base is primitive with
//! integer coefficients, so every `q` is an integer and the divisions are exact integer
//! divisions; here done on 64-bit limbs with a two's complement accumulator) whose base
//! coefficients fit in 63 bits, and for `ModP` (the divisor is below `p` in absolute value and
//! not zero, so it is invertible). Other coefficient types take binary powering.
//!
//! # The choice
//! Squares, and powers too small to matter (at most [`SMALL_POWER`] recurrence steps by the
//! multiset bound below), are binary powering without further estimates. Otherwise binary
//! powering costs the sum of its squarings and multiplications, `N_a N_b` coefficient
//! products each (`N (N + 1) / 2` for a square), each priced by what the kernels will do: a word
//! product when both operands' coefficients fit in 63 bits (bounded by `k log2 sum |a_i|` bits
//! for `P^k`; always for `ModP`), a big one otherwise, plus a heap level per `log2` of the
//! shorter operand unless the exponent box is small enough for the dense kernels. The
//! recurrence costs `t N_e` steps, each about a big product plus a heap of `t` streams. The
//! sizes `N_k` are estimated before any work by the smallest of three upper bounds on the terms
//! of `P^k`: the multisets of `k` terms of `P` (`C(t - 1 + k, k)`, exact for a "generic" sparse
//! base), the exponent box (`prod (k d_v + 1)`), and the monomials of total degree at most
//! `k deg P`. The prices ([`WORD_NS`] and the others) were measured on this machine by the
//! calibration example `power_calibration` (`cargo run --release -p exactcheck-exact --example
//! power_calibration`: it prints both timings for each case and asserts only that both agree). On those cases binary
//! powering wins for dense bases whose powers stay in words (`(1 + x + y + z + w)^k`, `k <= 16`:
//! 1.5 to 2x) and for many-term bases with small exponents (a 10-term base, `e <= 6`: 2.5 to 7x);
//! the recurrence wins once the coefficients pass 63 bits (`(1 + 3x + 5x^2 + ... + 19x^9)^40`:
//! 50x, the fuzz base at `e = 50`: 100x, a 4-term base at `e = 60`: 800x). The model picks the
//! faster one in all but one case measured (within 1.3x there).
//!
//! Repeated multiplication by the base (`P^k = P^(k-1) P`) costs `t` products per term of
//! every intermediate power, `t sum N_k`: never less than the recurrence's `(t - 1) N_e` plus
//! divisions once `e > 2`, so it is not a candidate. The multinomial expansion needs every
//! composition of `e` into `t` parts and a sort of the terms; the recurrence yields the same
//! terms sorted and combined.
//!
//! Why hand-written: no crate offers sparse multivariate powering over these coefficient types.

use super::words::cast;
use super::*;
use crate::{ModP, Rational};
use exactcheck_core::{Field, Ring};
use num_bigint::{BigInt, BigUint, Sign};

/// The cost model's prices, in nanoseconds on the project machine (measured with the
/// calibration example `power_calibration`): a product of two coefficients in
/// the word kernels, a product of two coefficients beyond 63 bits, each level of a product
/// heap, and one step of the recurrence (a product of an output coefficient by a word with its
/// share of the division).
const WORD_NS: f64 = 4.0;
const BIG_NS: f64 = 45.0;
const HEAP_NS: f64 = 4.0;
const RECURRENCE_NS: f64 = 40.0;

/// Below this many recurrence steps (`t C(t - 1 + e, e)`, a bound) a power is binary powering
/// without estimates: both take microseconds.
const SMALL_POWER: f64 = 4096.0;

/// A power by the recurrence: `None` when it does not apply to `C` or this base, `Some(None)`
/// past the cap on the terms.
type RecurrenceFn<C> = fn(&Poly<C>, u64, usize) -> Option<Option<Poly<C>>>;

impl<C: Ring> Poly<C> {
    /// `self^e` (`e >= 2`, at least two terms, content already split off) by the recurrence of
    /// the module documentation when the cost model prefers it and the coefficient type allows
    /// it: `None` otherwise (binary powering then), `Some(None)` as soon as the power has more
    /// than `max(words)` terms (`words` the words of one of its packed monomials).
    pub(super) fn pow_by_recurrence(
        &self,
        e: u64,
        max: impl Fn(usize) -> usize,
    ) -> Option<Option<Self>> {
        let run = recurrence_of::<C>()?;
        if self.len() < 2 || e < 2 || !recurrence_preferred(self, e) {
            return None;
        }
        let words = self.power_shape(e)?.words;
        run(self, e, max(words))
    }

    /// The shape of `self^e`: fields that hold `e` times the largest exponent (`None` beyond
    /// [`MAX_EXP`]).
    fn power_shape(&self, e: u64) -> Option<Shape> {
        let need = u64::from(self.max_exponent()).checked_mul(e)?;
        Some(self.widened_shape(bits_for(need)?, 0))
    }
}

/// The recurrence for `C` when it has one (`Rational`, `ModP`).
fn recurrence_of<C: Ring>() -> Option<RecurrenceFn<C>> {
    let q: RecurrenceFn<Rational> = power_rational;
    let m: RecurrenceFn<ModP> = power_modp;
    cast::<RecurrenceFn<Rational>, RecurrenceFn<C>>(q)
        .or_else(|| cast::<RecurrenceFn<ModP>, RecurrenceFn<C>>(m))
}

// ------------------------------------------------------------------------------ cost model

/// `C(n, k)` as a float (saturating to infinity).
fn binomial(n: u64, k: u64) -> f64 {
    let k = k.min(n - k.min(n));
    let mut r = 1f64;
    for i in 0..k {
        r = r * (n - i) as f64 / (i + 1) as f64;
    }
    r
}

/// An upper bound on the terms of `P^k` (see the module documentation).
fn terms_bound(t: usize, nvars: usize, degree: u64, max_exps: &[u64], k: u64) -> f64 {
    if k == 0 {
        return 1.0;
    }
    let multisets = binomial(t as u64 - 1 + k, k);
    let cells: f64 = max_exps
        .iter()
        .filter(|&&d| d > 0)
        .map(|&d| (k * d + 1) as f64)
        .product();
    let simplex = binomial(nvars as u64 + k * degree, nvars as u64);
    multisets.min(cells).min(simplex).max(1.0)
}

/// Whether the recurrence is predicted cheaper than binary powering for `p^e`.
fn recurrence_preferred<C: Ring>(p: &Poly<C>, e: u64) -> bool {
    // A square is one squaring: t (t + 1) / 2 products, against the recurrence's t N_2 >= t^2
    // steps.
    if e <= 2 {
        return false;
    }
    // A small power either way (at most a few thousand products whichever runs): not worth
    // the estimates below, which cost about as much.
    let t = p.len();
    if t as f64 * binomial(t as u64 - 1 + e, e) <= SMALL_POWER {
        return false;
    }
    let max_exps = p.max_exponents();
    let nvars = max_exps.iter().filter(|&&d| d > 0).count();
    let degree = p.total_degree();
    // The bounds for the few exponents binary powering meets, computed once each.
    let memo = std::cell::RefCell::new(Vec::<(u64, f64)>::new());
    let n = |k: u64| -> f64 {
        if let Some(&(_, v)) = memo.borrow().iter().find(|(j, _)| *j == k) {
            return v;
        }
        let v = terms_bound(t, nvars, degree, &max_exps, k);
        memo.borrow_mut().push((k, v));
        v
    };
    let cells = |k: u64| -> f64 {
        max_exps
            .iter()
            .filter(|&&d| d > 0)
            .map(|&d| (k * d + 1) as f64)
            .product()
    };
    // The bits of the largest coefficient of p^k are at most k log2(sum |a_i|).
    let bits = coefficient_bits(p);
    // One product of p^a by p^b (pairs: the products the kernel forms): in words when both
    // operands' coefficients fit, through the heap unless the exponent box is small (the
    // dense kernels' rule).
    let product = |a: u64, b: u64, pairs: f64| -> f64 {
        let word = bits.is_some_and(|x| x * a.max(b) as f64 <= 62.0);
        let dense = cells(a + b) <= (4.0 * n(a) * n(b)).min((1u64 << 22) as f64);
        let heap = if dense {
            0.0
        } else {
            HEAP_NS * n(a).min(n(b)).log2().max(1.0)
        };
        pairs * (if word { WORD_NS } else { BIG_NS } + heap)
    };
    // Binary powering as `pow_u64` runs it: the squarings of the base, the products into the
    // accumulator.
    let mut binary = 0f64;
    let (mut acc, mut base) = (0u64, 1u64);
    let mut rest = e;
    loop {
        if rest & 1 == 1 {
            if acc > 0 {
                binary += product(acc, base, n(acc) * n(base));
            }
            acc += base;
        }
        rest >>= 1;
        if rest == 0 {
            break;
        }
        binary += product(base, base, n(base) * (n(base) + 1.0) / 2.0);
        base *= 2;
    }
    let recurrence = (RECURRENCE_NS + HEAP_NS * (t as f64).log2()) * t as f64 * n(e);
    recurrence < binary
}

/// `log2 sum |a_i|` for a base whose coefficients are small integers, 0 for `ModP` (every
/// product in words), `None` otherwise.
fn coefficient_bits<C: Ring>(p: &Poly<C>) -> Option<f64> {
    if std::any::TypeId::of::<C>() == std::any::TypeId::of::<ModP>() {
        return Some(0.0);
    }
    let words = super::words::word_hooks::<C>()?;
    let (w, d) = (words.to_words)(&p.coeffs)?;
    (d == 1).then(|| {
        w.iter()
            .map(|x| x.unsigned_abs() as f64)
            .sum::<f64>()
            .log2()
    })
}

// ------------------------------------------------------------------------------ the weight

/// A linear weight (per variable) under which the leading monomial of `p` is the only one of
/// largest weight, as in the module documentation; `None` if the weights would pass `limit`.
fn leading_weight<C>(p: &Poly<C>, limit: u64) -> Option<Vec<u64>> {
    let nv = p.nvars_used();
    let mut weight = vec![0u64; nv];
    let exps: Vec<Vec<u64>> = (0..p.len())
        .map(|i| {
            let mut v = vec![0u64; nv];
            p.shape.for_each(p.mono(i), |var, x| v[var] = x);
            v
        })
        .collect();
    // The terms that tie with the leading one so far.
    let mut ties: Vec<usize> = (1..p.len()).collect();
    let mut top = 0u64; // the leading monomial's weight
    for v in (0..nv).rev() {
        if ties.is_empty() {
            break;
        }
        let lead = exps[0][v];
        if ties.iter().all(|&i| exps[i][v] == lead) {
            continue;
        }
        let d = exps.iter().map(|m| m[v]).max().unwrap_or(0);
        for x in weight.iter_mut() {
            *x = x.checked_mul(d + 1)?;
        }
        weight[v] = 1;
        top = top.checked_mul(d + 1)?.checked_add(lead)?;
        if top > limit {
            return None;
        }
        ties.retain(|&i| exps[i][v] == lead);
    }
    Some(weight)
}

/// The weight of every term of `p` under `weight`.
fn term_weights<C>(p: &Poly<C>, weight: &[u64]) -> Vec<u64> {
    (0..p.len())
        .map(|i| {
            let mut s = 0u64;
            p.shape.for_each(p.mono(i), |v, x| s += weight[v] * x);
            s
        })
        .collect()
}

// ------------------------------------------------------------------------------ the driver

/// The coefficient arithmetic of the recurrence: it holds the base's coefficients `a_i` and the
/// power's coefficients `q_j` found so far, and one exact sum.
trait RecurrenceArith {
    /// Starts the sum of a new monomial.
    fn start(&mut self);
    /// `sum += a_i q_j f`.
    fn add(&mut self, i: usize, j: usize, f: i128);
    /// Whether the sum is zero.
    fn sum_is_zero(&self) -> bool;
    /// Appends the next coefficient of the power, `sum / (a_0 k)` (exact, `k != 0`).
    fn finish(&mut self, k: i128);
}

/// The monomials of `p^e` (`e >= 2`, `p` of at least two terms), computed by the recurrence
/// with the coefficient arithmetic `ar` (which holds `q_0 = a_0^e` already) and the term
/// weights `w` (the leading term alone of largest weight, `(e + 1) w_0 < 2^63`), in the shape
/// `out`; `None` past `max` terms.
fn recurrence<R: RecurrenceArith>(
    p: &Poly<impl Ring>,
    e: u64,
    w: &[u64],
    ar: &mut R,
    out: Shape,
    max: usize,
) -> Option<Vec<u64>> {
    // Products m_i n_j have exponents up to (e + 1) times p's: the working shape holds them.
    // (Below 2^63, as e times them is at most MAX_EXP.)
    let need = u64::from(p.max_exponent()) * (e + 1);
    let bits = bits_for(need).unwrap_or(64);
    let sh = p.widened_shape(bits.max(out.bits), 0);
    let ws = sh.words;
    let t = p.len();
    let pe = p.exps_in(sh);
    let m = |i: usize| &pe[i * ws..(i + 1) * ws];
    let e1 = i128::from(e + 1);
    let w0 = i128::from(w[0]);

    // The power's monomials and weights.
    let mut qe: Vec<u64> = Vec::with_capacity(ws * 64);
    let mut qw: Vec<u64> = vec![w[0] * e];
    let mut lead = vec![0u64; ws];
    p.shape
        .for_each(p.mono(0), |v, x| sh.set(&mut lead, v, x * e));
    qe.extend_from_slice(&lead);

    let mut slots = vec![0u64; t * ws];
    let mut js = vec![0usize; t];
    let mut heap = Heap::with_capacity(t);
    for i in 1..t {
        add_mono(&mut slots[i * ws..(i + 1) * ws], m(i), &qe[0..ws]);
        heap.push(i as u32, &slots, ws);
    }
    let mut waiting: Vec<usize> = Vec::with_capacity(t);
    let mut cur = vec![0u64; ws];
    let mut n = vec![0u64; ws];
    let guard = sh.guard();
    while let Some(top) = heap.pop(&slots, ws) {
        let top = top as usize;
        cur.copy_from_slice(&slots[top * ws..(top + 1) * ws]);
        let big_w = i128::from(w[top] + qw[js[top]]);
        ar.start();
        let mut take = |i: usize, heap: &mut Heap, slots: &mut [u64], qe: &[u64]| {
            let j = js[i];
            ar.add(i, j, e1 * i128::from(w[i]) - big_w);
            js[i] = j + 1;
            if j + 1 < qw.len() {
                add_mono(
                    &mut slots[i * ws..(i + 1) * ws],
                    m(i),
                    &qe[(j + 1) * ws..(j + 2) * ws],
                );
                heap.push(i as u32, slots, ws);
            } else {
                waiting.push(i);
            }
        };
        take(top, &mut heap, &mut slots, &qe);
        while let Some(i) = heap.pop_if_key(&slots, ws, &cur) {
            take(i, &mut heap, &mut slots, &qe);
        }
        if ar.sum_is_zero() {
            continue;
        }
        assert!(
            divides(m(0), &cur, guard),
            "power recurrence: a non-zero sum at a monomial the leading term does not divide"
        );
        for ((o, &x), &y) in n.iter_mut().zip(&cur).zip(m(0)) {
            *o = x - y;
        }
        let k = big_w - e1 * w0;
        assert!(
            k < 0,
            "power recurrence: the leading weight is not the only largest"
        );
        ar.finish(k);
        qe.extend_from_slice(&n);
        qw.push((big_w - w0) as u64);
        if qw.len() > max {
            return None;
        }
        for i in waiting.drain(..) {
            add_mono(&mut slots[i * ws..(i + 1) * ws], m(i), &n);
            heap.push(i as u32, &slots, ws);
        }
    }
    Some(if out == sh {
        qe
    } else {
        repack(&qe, qw.len(), sh, out)
    })
}

/// The weights for `p^e` and the check that the recurrence's integers fit: `(e + 1) w_0` below
/// `limit`.
fn weights_for<C: Ring>(p: &Poly<C>, e: u64, limit: u64) -> Option<Vec<u64>> {
    let weight = leading_weight(p, limit / (e + 1))?;
    let w = term_weights(p, &weight);
    (w[0].checked_mul(e + 1)? < limit).then_some(w)
}

// ------------------------------------------------------------------------------ integers

/// An integer as a sign and its magnitude in 64-bit limbs (least significant first, no
/// leading zero limb; zero has none).
#[derive(Clone, Debug, Default)]
struct Int {
    neg: bool,
    mag: Vec<u64>,
}

impl Int {
    fn from_bigint(x: &BigInt) -> Int {
        Int {
            neg: x.sign() == Sign::Minus,
            mag: x.magnitude().to_u64_digits(),
        }
    }

    fn to_rational(&self) -> Rational {
        if self.mag.len() <= 2 {
            let lo = self.mag.first().copied().unwrap_or(0) as u128;
            let hi = self.mag.get(1).copied().unwrap_or(0) as u128;
            let v = (hi << 64) | lo;
            if v < 1 << 126 {
                let v = v as i128;
                return Rational::from_i128_ratio(if self.neg { -v } else { v }, 1)
                    .expect("1 is not zero");
            }
        }
        let digits: Vec<u32> = self
            .mag
            .iter()
            .flat_map(|&l| [l as u32, (l >> 32) as u32])
            .collect();
        let sign = if self.neg { Sign::Minus } else { Sign::Plus };
        Rational::from(BigInt::from_biguint(sign, BigUint::new(digits)))
    }
}

/// The recurrence over the integers: base coefficients in `i64`, the sum in a two's complement
/// accumulator of `q`'s size plus four limbs (a sum of fewer than `2^63` products of a `q` by
/// an `i128` cannot overflow it).
struct IntArith {
    a: Vec<i64>,
    q: Vec<Int>,
    acc: Vec<u64>,
    max_limbs: usize,
}

impl IntArith {
    /// `acc += x * m` (`neg`: `acc -= x * m`) for a magnitude `x` and a 64-bit `m`, from limb
    /// `at` up.
    #[inline]
    fn mul_add(acc: &mut [u64], x: &[u64], m: u64, at: usize, neg: bool) {
        let mut carry: u128 = 0;
        let mut k = at;
        if neg {
            for &d in x {
                let p = d as u128 * m as u128 + carry;
                let (s, b) = acc[k].overflowing_sub(p as u64);
                acc[k] = s;
                carry = (p >> 64) + b as u128;
                k += 1;
            }
            while carry != 0 && k < acc.len() {
                let (s, b) = acc[k].overflowing_sub(carry as u64);
                acc[k] = s;
                carry = b as u128;
                k += 1;
            }
        } else {
            for &d in x {
                let p = d as u128 * m as u128 + acc[k] as u128 + carry;
                acc[k] = p as u64;
                carry = p >> 64;
                k += 1;
            }
            while carry != 0 && k < acc.len() {
                let (s, c) = acc[k].overflowing_add(carry as u64);
                acc[k] = s;
                carry = c as u128;
                k += 1;
            }
        }
    }

    /// `x / d` for a magnitude `x` that `d != 0` divides exactly (`bigint`'s Jebelean
    /// division, no division instruction per limb; the exactness, the recurrence's invariant,
    /// is checked by one folding remainder pass).
    fn div_exact(x: &mut Vec<u64>, d: u64) {
        assert_eq!(
            crate::bigint::rem_1(x, d),
            0,
            "power recurrence: an inexact division (the powers of an integer polynomial are integer)"
        );
        *x = crate::bigint::divexact_1(x, d);
    }
}

impl RecurrenceArith for IntArith {
    fn start(&mut self) {
        self.acc.clear();
        self.acc.resize(self.max_limbs + 4, 0);
    }

    #[inline]
    fn add(&mut self, i: usize, j: usize, f: i128) {
        // |a_i f| < 2^127: checked when the weights were chosen.
        let m = i128::from(self.a[i]) * f;
        if m == 0 {
            return;
        }
        let q = &self.q[j];
        let neg = q.neg ^ (m < 0);
        let m = m.unsigned_abs();
        Self::mul_add(&mut self.acc, &q.mag, m as u64, 0, neg);
        if m >> 64 != 0 {
            Self::mul_add(&mut self.acc, &q.mag, (m >> 64) as u64, 1, neg);
        }
    }

    fn sum_is_zero(&self) -> bool {
        self.acc.iter().all(|&l| l == 0)
    }

    fn finish(&mut self, k: i128) {
        let mut mag = std::mem::take(&mut self.acc);
        let neg = mag.last().is_some_and(|&l| l >> 63 == 1);
        if neg {
            crate::bigint::negate_twos_complement(&mut mag);
        }
        crate::bigint::trim(&mut mag);
        let a0 = self.a[0];
        Self::div_exact(&mut mag, a0.unsigned_abs());
        let k_abs = u64::try_from(k.unsigned_abs()).expect("the weights keep k below 2^63");
        Self::div_exact(&mut mag, k_abs);
        self.max_limbs = self.max_limbs.max(mag.len());
        self.q.push(Int {
            neg: neg ^ (a0 < 0) ^ (k < 0),
            mag,
        });
    }
}

/// `p^e` over the rationals by the recurrence, for a base with integer coefficients of at most
/// 63 bits (`None` otherwise, or when the weights do not fit).
fn power_rational(p: &Poly<Rational>, e: u64, max: usize) -> Option<Option<Poly<Rational>>> {
    let mut a = Vec::with_capacity(p.len());
    for c in &p.coeffs {
        let (n, d) = c.inline_parts()?;
        if d != 1 {
            return None;
        }
        a.push(i64::try_from(n).ok().filter(|&x| x != i64::MIN)?);
    }
    let amax = a.iter().map(|x| x.unsigned_abs()).max().unwrap_or(1);
    // (e + 1) w_0 bounds |f| and |k|; |a_i f| must stay below 2^127.
    let limit =
        (u64::MAX >> 1).min(((1u128 << 126) / u128::from(amax)).min(u64::MAX as u128) as u64);
    let w = weights_for(p, e, limit)?;
    let out = p.power_shape(e)?;
    let lead = num_traits::Pow::pow(BigInt::from(a[0]), BigUint::from(e));
    let lead = Int::from_bigint(&lead);
    let mut ar = IntArith {
        max_limbs: lead.mag.len(),
        q: vec![lead],
        a,
        acc: Vec::new(),
    };
    let Some(exps) = recurrence(p, e, &w, &mut ar, out, max) else {
        return Some(None);
    };
    let coeffs = ar.q.iter().map(Int::to_rational).collect();
    Some(Some(Poly {
        shape: out,
        exps,
        coeffs,
    }))
}

// ------------------------------------------------------------------------------ ModP

/// The recurrence modulo `p = 2^61 - 1`.
struct ModPArith {
    a: Vec<ModP>,
    q: Vec<ModP>,
    sum: ModP,
}

/// The residue of an `i128`.
fn modp_of_i128(x: i128) -> ModP {
    let r = ModP::from_u128(x.unsigned_abs());
    if x < 0 {
        -r
    } else {
        r
    }
}

impl RecurrenceArith for ModPArith {
    fn start(&mut self) {
        self.sum = ModP::ZERO;
    }

    #[inline]
    fn add(&mut self, i: usize, j: usize, f: i128) {
        self.sum += self.a[i] * self.q[j] * modp_of_i128(f);
    }

    fn sum_is_zero(&self) -> bool {
        self.sum == ModP::ZERO
    }

    fn finish(&mut self, k: i128) {
        // 0 < |k| < p and a_0 != 0: the divisor is invertible.
        let d = self.a[0] * modp_of_i128(k);
        let inv = d
            .inv()
            .expect("a_0 k is not zero modulo p (|k| < p, a_0 a non-zero residue)");
        self.q.push(self.sum * inv);
    }
}

/// `p^e` modulo `2^61 - 1` by the recurrence (`None` when the weights do not fit below `p`).
fn power_modp(p: &Poly<ModP>, e: u64, max: usize) -> Option<Option<Poly<ModP>>> {
    let w = weights_for(p, e, crate::modp::P)?;
    let out = p.power_shape(e)?;
    let mut ar = ModPArith {
        q: vec![p.coeffs[0].pow_u64(e)],
        a: p.coeffs.clone(),
        sum: ModP::ZERO,
    };
    let exps = recurrence(p, e, &w, &mut ar, out, max);
    Some(exps.map(|exps| Poly {
        shape: out,
        exps,
        coeffs: ar.q,
    }))
}

// ------------------------------------------------------------------------------ reference

impl<C: Ring> Poly<C> {
    /// The reference power: binary powering on the generic kernels (never the word kernels nor
    /// the recurrence), for tests.
    #[cfg(test)]
    pub(super) fn pow_reference(&self, e: u64) -> Self {
        if e == 0 {
            return Poly::one();
        }
        super::ring::binary_power(self, e, |a, b| a.mul_reference(b), Poly::square_reference)
    }

    /// `self^e` by the recurrence whatever the cost model says, after splitting off the content
    /// as the powers do (`None` where it does not apply): for the tests and the calibration
    /// example `power_calibration`.
    #[doc(hidden)]
    pub fn pow_recurrence_forced(&self, e: u64) -> Option<Self> {
        if let Some((c, prim)) = self.split_content() {
            return Some(prim.pow_recurrence_forced(e)?.scale(&pow_coeff(&c, e)));
        }
        let run = recurrence_of::<C>()?;
        if self.len() < 2 || e < 2 {
            return None;
        }
        run(self, e, usize::MAX).map(|r| r.expect("no cap"))
    }

    /// `self^e` by binary powering on the fast kernels (the content split off): for the tests
    /// and the calibration example `power_calibration`.
    #[doc(hidden)]
    pub fn pow_binary(&self, mut e: u64) -> Self {
        if let Some((c, prim)) = self.split_content() {
            return prim.pow_binary(e).scale(&pow_coeff(&c, e));
        }
        let mut acc = Poly::one();
        let mut base = self.clone();
        loop {
            if e & 1 == 1 {
                acc = acc.mul_ref(&base);
            }
            e >>= 1;
            if e == 0 {
                return acc;
            }
            base = base.square_impl();
        }
    }

    /// Whether the cost model picks the recurrence for `self^e`: for the tests and the
    /// calibration example `power_calibration`.
    #[doc(hidden)]
    pub fn recurrence_is_preferred(&self, e: u64) -> bool {
        recurrence_preferred(self, e)
    }
}
