//! Linear-time kernels on little-endian 64-bit limb slices: remainder by one limb, exact
//! division by one limb, and the linear combination `A*m1 ± B*m2` of two big numbers with
//! one-limb multipliers, fused into one pass.
//!
//! These are the operations of adding a word-sized rational `c/d` to a big one `a/b` by
//! Henrici's method ([`crate::rational`]): `b mod d`, `b / g` (exact, `g = gcd(b, d)`),
//! `a (d/g) + c (b/g)`, and its remainder by `g`. The benchmark rational-sum `seq` (the running sum
//! `s += disc`, whose denominator grows to tens of thousands of digits while every `disc` fits
//! in machine words) spends nearly all its time there. num-bigint 0.4 does them with a clone of
//! the big operand and one hardware (or `u128` library) division per limb, which profiled at
//! roughly four times GMP's cost per limb. num-bigint keeps `BigInt`/`BigUint` as the public
//! types; no maintained crate with a compatible licence offers these kernels on its limbs (GMP
//! bindings are LGPL and C), so they are written here, on the limbs read by
//! `BigUint::to_u64_digits`.
//!
//! # Algorithms
//! * **Remainder by a limb `d < 2^61`** ([`rem_1`]): the folding method of GMP's
//!   `mpn_mod_1s_4p` (Möller and Granlund, "Improved division by invariant integers", IEEE Trans.
//!   Computers 60 (2011), section 8 and GMP's implementation notes): with `c_i = 2^(64 i) mod d`
//!   precomputed, four limbs and the two-limb running residue `(rh, rl)` are folded per step
//!   into `w0 + w1 c1 + w2 c2 + w3 c3 + rl c4 + rh c5`, which stays below `2^64 (1 + 5 d) <
//!   2^128`; no division happens inside the loop (the dependency chain is one multiply-add per
//!   four limbs), and one `u128` remainder finishes. Larger `d` use Möller–Granlund's
//!   division by an invariant normalised divisor with a precomputed reciprocal (their
//!   Algorithm 4), one limb per step.
//! * **Exact division by a limb** ([`divexact_1`]): Jebelean's exact division ("An algorithm
//!   for exact division", J. Symbolic Computation 15 (1993)) in the form of GMP's
//!   `mpn_divexact_1`: the quotient is produced from the least significant limb upwards as
//!   `q_i = (x_i - borrow) * d^(-1) mod 2^64` — multiplications only; the factor `2^s` of an
//!   even divisor is shifted out on the fly.
//! * **Paired exact division** ([`divexact_1_pair_in_place`]): the same step on two numbers in
//!   one loop (a sum's numerator and denominator divided by the same `g2`), in place: each
//!   quotient limb waits on two dependent multiplications, so two independent chains run in
//!   the time of one.
//! * **Limb copies** ([`limbs_of`], [`rem_1_big`]): the operands are read out of num-bigint
//!   through a zeroed buffer (a plain copy), not `to_u64_digits` (an iterator collected limb by
//!   limb, several times slower), and small ones onto the stack.
//! * **Fixed-width ring operations** ([`hensel_div_1_in_place`], [`mul_1_add_in_place`], and
//!   the two fused in one pass, [`mul_1_add_hensel_in_place`]): the same Jebelean step and a
//!   multiply-accumulate by a word, modulo `2^(64 len)` on two's complement numbers, for the
//!   synthetic division of `univariate::limbs` (exactness is certified there by a size
//!   argument, not by the kernels).
//! * **The fused addition pass** ([`add_word_pass`]): one pass over both big operands computes
//!   the exact quotient `b/g` limb by limb, the linear combination `a (d/g) ± c (b/g)` with a
//!   signed two-limb carry (negated by a two's-complement pass when the result is negative),
//!   and the new denominator `b (d/g)`.
//!
//! Every kernel is tested against num-bigint's `%`, `/`, `*` and `+`/`-` (module tests).

use num_bigint::BigUint;

/// Largest divisor handled by the folding remainder ([`rem_1`] uses the reciprocal method
/// above it): keeps the folded sum `w0 + 5 (2^64 - 1) (d - 1)` below `2^128`.
const FOLD_MAX: u64 = 1 << 61;

/// `x mod d` for a number given by its limbs (least significant first); `d != 0`.
///
/// # Panics
/// If `d == 0` (a caller bug: the remainder is undefined).
pub fn rem_1(x: &[u64], d: u64) -> u64 {
    assert!(d != 0, "rem_1: division by zero");
    if d == 1 {
        return 0;
    }
    // One or two limbs: a single `u128` remainder (the folding constants would cost more).
    match *x {
        [] => return 0,
        [lo] => return lo % d,
        [lo, hi] => return ((u128::from(hi) << 64 | u128::from(lo)) % u128::from(d)) as u64,
        _ => {}
    }
    if d < FOLD_MAX {
        rem_1_fold(x, d)
    } else {
        rem_1_preinv(x.iter().copied(), d)
    }
}

/// The folding remainder for `2 <= d < 2^61` (see the module documentation).
fn rem_1_fold(x: &[u64], d: u64) -> u64 {
    let dd = u128::from(d);
    // c[i] = 2^(64 i) mod d for i = 0..=5.
    let mut c = [0u64; 6];
    c[0] = 1 % d;
    c[1] = ((u128::from(u64::MAX) + 1) % dd) as u64;
    for i in 2..6 {
        c[i] = (u128::from(c[i - 1]) * u128::from(c[1]) % dd) as u64;
    }
    let m = |a: u64, b: u64| u128::from(a) * u128::from(b);
    let (mut rh, mut rl) = (0u64, 0u64);
    // Blocks of four limbs from the most significant end, then the k < 4 least significant
    // limbs, folded with the weights of a k-limb block.
    let mut blocks = x.rchunks_exact(4);
    for w in blocks.by_ref() {
        let s = u128::from(w[0])
            + m(w[1], c[1])
            + m(w[2], c[2])
            + m(w[3], c[3])
            + m(rl, c[4])
            + m(rh, c[5]);
        rh = (s >> 64) as u64;
        rl = s as u64;
    }
    let low = blocks.remainder();
    let k = low.len();
    if k > 0 {
        let mut s = m(rl, c[k]) + m(rh, c[k + 1]);
        for (j, &w) in low.iter().enumerate() {
            s += m(w, c[j]);
        }
        rh = (s >> 64) as u64;
        rl = s as u64;
    }
    ((m(rh, c[1]) + u128::from(rl)) % dd) as u64
}

/// The reciprocal `floor((2^128 - 1) / d) - 2^64` of a normalised divisor (`d >= 2^63`).
#[inline]
fn reciprocal(d: u64) -> u64 {
    debug_assert!(d >> 63 == 1);
    (u128::MAX / u128::from(d) - (1u128 << 64)) as u64
}

/// Möller–Granlund Algorithm 4: `(<u1, u0> div d, <u1, u0> mod d)` for a normalised `d` with
/// reciprocal `v` and `u1 < d`.
#[inline]
fn div_2by1(u1: u64, u0: u64, d: u64, v: u64) -> (u64, u64) {
    let q = (u128::from(v) * u128::from(u1)).wrapping_add(u128::from(u1) << 64 | u128::from(u0));
    let mut q1 = ((q >> 64) as u64).wrapping_add(1);
    let q0 = q as u64;
    let mut r = u0.wrapping_sub(q1.wrapping_mul(d));
    if r > q0 {
        q1 = q1.wrapping_sub(1);
        r = r.wrapping_add(d);
    }
    if r >= d {
        q1 = q1.wrapping_add(1);
        r -= d;
    }
    (q1, r)
}

/// `x mod d` for any `d >= 2` by division with a precomputed reciprocal, one limb per step:
/// the stream `x 2^s` is divided by the normalised `d 2^s` and the remainder shifted back.
fn rem_1_preinv<I>(x: I, d: u64) -> u64
where
    I: DoubleEndedIterator<Item = u64> + ExactSizeIterator,
{
    let s = d.leading_zeros();
    let dn = d << s;
    let v = reciprocal(dn);
    let mut x = x.rev();
    let Some(top) = x.next() else {
        return 0;
    };
    if s == 0 {
        let mut r = div_2by1(0, top, dn, v).1;
        for w in x {
            r = div_2by1(r, w, dn, v).1;
        }
        return r;
    }
    // r starts as the s bits shifted out of the top limb (< 2^s <= 2^63 <= dn); each step
    // divides the next limb of the stream x 2^s.
    let mut r = top >> (64 - s);
    let mut cur = top;
    for w in x {
        r = div_2by1(r, cur << s | w >> (64 - s), dn, v).1;
        cur = w;
    }
    r = div_2by1(r, cur << s, dn, v).1;
    r >> s
}

/// The inverse of an odd `d` modulo `2^64` (Newton's iteration, doubling the correct bits from
/// the 3 that `d` itself gives).
#[inline]
pub fn inverse_mod_2_64(d: u64) -> u64 {
    debug_assert!(d & 1 == 1);
    let mut inv = d;
    for _ in 0..5 {
        inv = inv.wrapping_mul(2u64.wrapping_sub(d.wrapping_mul(inv)));
    }
    inv
}

/// `x / d` when `d` divides `x` exactly (`d != 0`), by Jebelean's exact division (see the
/// module documentation); the result has no leading zero limbs. The result is meaningless
/// (but the call is safe) when `d` does not divide `x`.
///
/// # Panics
/// If `d == 0`.
pub fn divexact_1(x: &[u64], d: u64) -> Vec<u64> {
    assert!(d != 0, "divexact_1: division by zero");
    let s = d.trailing_zeros();
    let odd = d >> s;
    let inv = inverse_mod_2_64(odd);
    let mut out = vec![0u64; x.len()];
    let mut c = 0u64;
    let mut step = |y: u64, q: &mut u64| *q = hensel_limb(y, &mut c, odd, inv);
    if s == 0 {
        for (q, &w) in out.iter_mut().zip(x) {
            step(w, q);
        }
    } else if let Some((&top, _)) = x.split_last() {
        // The stream x / 2^s: each limb takes its high bits from the next one.
        for (q, w) in out.iter_mut().zip(x.windows(2)) {
            step(w[0] >> s | w[1] << (64 - s), q);
        }
        if let Some(q) = out.last_mut() {
            step(top >> s, q);
        }
    }
    trim(&mut out);
    out
}

/// `x d^(-1) mod 2^(64 len)` in place for an odd `d` with `inv = d^(-1) mod 2^64`
/// ([`inverse_mod_2_64`]): the 2-adic (Hensel) division of Jebelean's scheme over the whole
/// fixed width, a ring operation modulo `2^(64 len)`. When `d` divides `x` (read as a two's
/// complement number that fits) it is the exact quotient; otherwise it is the unique residue
/// `y` with `y d = x` modulo `2^(64 len)`, which callers must not mistake for a quotient.
#[inline]
pub fn hensel_div_1_in_place(x: &mut [u64], d: u64, inv: u64) {
    debug_assert!(d & 1 == 1 && d.wrapping_mul(inv) == 1);
    let mut c = 0u64;
    for w in x.iter_mut() {
        *w = hensel_limb(*w, &mut c, d, inv);
    }
}

/// One limb of Jebelean's exact (Hensel) division by the odd `d` (`inv = d^(-1) mod 2^64`):
/// the quotient limb `q = (y - c) inv mod 2^64` of the limb `y` less the running borrow `c`,
/// and the borrow into the next limb, `floor(q d / 2^64)` plus the subtraction's own.
#[inline(always)]
fn hensel_limb(y: u64, c: &mut u64, d: u64, inv: u64) -> u64 {
    let (l, borrow) = y.overflowing_sub(*c);
    let q = l.wrapping_mul(inv);
    *c = ((u128::from(q) * u128::from(d)) >> 64) as u64 + u64::from(borrow);
    q
}

/// `acc + x m` (or `acc - x m` with `sub`) modulo `2^(64 len)`, in place, for equal-length
/// slices: two's complement numbers times a word.
#[inline]
pub fn mul_1_add_in_place(acc: &mut [u64], x: &[u64], m: u64, sub: bool) {
    debug_assert_eq!(acc.len(), x.len());
    let (mut carry, mut borrow) = (0u64, false);
    for (a, &w) in acc.iter_mut().zip(x) {
        *a = mul_add_limb(*a, w, m, sub, &mut carry, &mut borrow);
    }
}

/// One limb of `acc ± x m`: `a ± (w m + carry mod 2^64) ± borrow`, the multiplication's carry
/// and the addition's (subtraction's) carry (borrow) updated for the next limb.
#[inline(always)]
fn mul_add_limb(a: u64, w: u64, m: u64, sub: bool, carry: &mut u64, borrow: &mut bool) -> u64 {
    let p = u128::from(w) * u128::from(m) + u128::from(*carry);
    *carry = (p >> 64) as u64;
    let lo = p as u64;
    if sub {
        let (d1, b1) = a.overflowing_sub(lo);
        let (d2, b2) = d1.overflowing_sub(u64::from(*borrow));
        *borrow = b1 | b2;
        d2
    } else {
        let (s1, c1) = a.overflowing_add(lo);
        let (s2, c2) = s1.overflowing_add(u64::from(*borrow));
        *borrow = c1 | c2;
        s2
    }
}

/// `(acc + x m) d^(-1)` (or `(acc - x m) d^(-1)` with `sub`) modulo `2^(64 len)`, in place, in
/// one pass: [`mul_1_add_in_place`] then [`hensel_div_1_in_place`] fused, each limb of the sum
/// divided as soon as it is final (both go from the least significant limb up). The step of
/// synthetic division by a linear factor on fixed-width limbs.
#[inline]
pub fn mul_1_add_hensel_in_place(acc: &mut [u64], x: &[u64], m: u64, sub: bool, d: u64, inv: u64) {
    debug_assert_eq!(acc.len(), x.len());
    debug_assert!(d & 1 == 1 && d.wrapping_mul(inv) == 1);
    let (mut carry, mut borrow, mut c) = (0u64, false, 0u64);
    for (a, &w) in acc.iter_mut().zip(x) {
        let t = mul_add_limb(*a, w, m, sub, &mut carry, &mut borrow);
        *a = hensel_limb(t, &mut c, d, inv);
    }
}

/// The fused pass of adding a word-sized rational to a big one (see
/// [`crate::rational`]): for `g | b` and `g | d`, returns `t = ±A (d/g) ± (b/g) cm` (signs
/// `an`, `cn`, as `(magnitude, negative)`) and `den = B (d/g)`, reading `A` and `B` once. The
/// quotient `b/g` is produced limb by limb by exact division as the pass goes.
/// The operands are taken as owned limb vectors (the caller's copies), zero-extended in place.
pub fn add_word_pass(
    mut az: Vec<u64>,
    an: bool,
    mut bz: Vec<u64>,
    cn: bool,
    cm: u64,
    d: u64,
    g: u64,
) -> (Vec<u64>, bool, Vec<u64>) {
    let mut out = (Vec::new(), Vec::new());
    let negative = add_word_pass_into(&mut az, an, &mut bz, (cn, cm, d), g, &mut out);
    (out.0, negative, out.1)
}

/// [`add_word_pass`] into reused buffers: the word operand `(cn, cm, d)`, `t` and `den`
/// written to `out` (cleared first), the operands `az`, `bz` zero-extended in place; returns
/// whether `t` is negative.
pub fn add_word_pass_into(
    az: &mut Vec<u64>,
    an: bool,
    bz: &mut Vec<u64>,
    (cn, cm, d): (bool, u64, u64),
    g: u64,
    out: &mut (Vec<u64>, Vec<u64>),
) -> bool {
    let n = az.len().max(bz.len());
    // Equal length n (b with one more zero limb, read by the shift).
    az.resize(n, 0);
    bz.resize(n + 1, 0);
    let (t, den) = (&mut out.0, &mut out.1);
    t.clear();
    den.clear();
    t.reserve(n + 2);
    den.reserve(n + 1);
    let carry = if an == cn {
        add_word_loop::<false>(az, bz, t, den, cm, d, g)
    } else {
        add_word_loop::<true>(az, bz, t, den, cm, d, g)
    };
    trim(den);
    t.push(carry as u64);
    t.push((carry >> 64) as u64);
    let t_negative = carry < 0;
    if t_negative {
        negate_twos_complement(t);
    }
    trim(t);
    // The sign: an when A d1 dominates (or magnitudes were added), cn otherwise.
    !t.is_empty() && if t_negative { cn } else { an }
}

/// The loop of [`add_word_pass`] on `a` (n limbs), `b` (n + 1 limbs, the last zero), pushing
/// the n low limbs of `t` and the n + 1 limbs of `den`; returns the final signed carry of `t`.
#[inline(always)]
fn add_word_loop<const SUB: bool>(
    a: &[u64],
    b: &[u64],
    t: &mut Vec<u64>,
    den: &mut Vec<u64>,
    cm: u64,
    d: u64,
    g: u64,
) -> i128 {
    let n = a.len();
    let (a, b) = (&a[..n], &b[..n + 1]);
    let d1 = d / g;
    let s = g.trailing_zeros();
    let odd = g >> s;
    let inv = inverse_mod_2_64(odd);
    let (mut c, mut den_carry, mut carry) = (0u64, 0u64, 0i128);
    for i in 0..n {
        let bw = b[i];
        // den = B d1.
        let p = u128::from(bw) * u128::from(d1) + u128::from(den_carry);
        den.push(p as u64);
        den_carry = (p >> 64) as u64;
        // b1 = b / g, exactly (Jebelean), on the stream b / 2^s.
        let y = if s == 0 {
            bw
        } else {
            bw >> s | b[i + 1] << (64 - s)
        };
        let (l, borrow) = y.overflowing_sub(c);
        let q1 = l.wrapping_mul(inv);
        c = ((u128::from(q1) * u128::from(odd)) >> 64) as u64 + u64::from(borrow);
        // t = A d1 +- b1 cm with a signed carry (|carry| < 2^66).
        let p = u128::from(a[i]) * u128::from(d1);
        let q = u128::from(q1) * u128::from(cm);
        let lo = if SUB {
            i128::from(p as u64) - i128::from(q as u64) + carry
        } else {
            i128::from(p as u64) + i128::from(q as u64) + carry
        };
        t.push(lo as u64);
        carry = if SUB {
            (p >> 64) as i128 - (q >> 64) as i128 + (lo >> 64)
        } else {
            (p >> 64) as i128 + (q >> 64) as i128 + (lo >> 64)
        };
    }
    den.push(den_carry);
    carry
}

/// In-place two's complement negation of a limb vector (its value modulo `2^(64 len)`).
pub fn negate_twos_complement(x: &mut [u64]) {
    let mut add = true;
    for w in x.iter_mut() {
        let (v, o) = (!*w).overflowing_add(u64::from(add));
        *w = v;
        add = o;
    }
}

/// `x / d` and `y / d` in place for a `d` dividing both exactly (`d != 0`): Jebelean's exact
/// division as in [`divexact_1`], the two quotients computed in one loop. Each quotient limb
/// waits for the borrow of the one below it (two dependent multiplications), so one chain
/// alone leaves the multiplier idle; two independent chains interleaved fill it. Both results
/// are trimmed. The results are meaningless (but the call is safe) when `d` does not divide
/// them.
///
/// # Panics
/// If `d == 0`.
pub fn divexact_1_pair_in_place(x: &mut Vec<u64>, y: &mut Vec<u64>, d: u64) {
    assert!(d != 0, "divexact_1_pair_in_place: division by zero");
    let n = x.len().max(y.len());
    // One zero limb on top of both: the stream x / 2^s reads limb i + 1.
    x.resize(n + 1, 0);
    y.resize(n + 1, 0);
    let s = d.trailing_zeros();
    let odd = d >> s;
    let inv = inverse_mod_2_64(odd);
    if s == 0 {
        divexact_pair_loop::<false>(&mut x[..n + 1], &mut y[..n + 1], 0, odd, inv);
    } else {
        divexact_pair_loop::<true>(&mut x[..n + 1], &mut y[..n + 1], s, odd, inv);
    }
    trim(x);
    trim(y);
}

/// The loop of [`divexact_1_pair_in_place`] over `n + 1` limbs (the top one zero); with
/// `SHIFT`, limb `i` of the stream `x / 2^s` (`0 < s < 64`) is taken from limbs `i` and
/// `i + 1`, read before limb `i + 1` is overwritten.
#[inline(always)]
fn divexact_pair_loop<const SHIFT: bool>(x: &mut [u64], y: &mut [u64], s: u32, odd: u64, inv: u64) {
    let n = x.len() - 1;
    let y = &mut y[..n + 1];
    let (mut cx, mut cy) = (0u64, 0u64);
    for i in 0..n {
        let (wx, wy) = if SHIFT {
            (
                x[i] >> s | x[i + 1] << (64 - s),
                y[i] >> s | y[i + 1] << (64 - s),
            )
        } else {
            (x[i], y[i])
        };
        x[i] = hensel_limb(wx, &mut cx, odd, inv);
        y[i] = hensel_limb(wy, &mut cy, odd, inv);
    }
    x[n] = 0;
    y[n] = 0;
}

/// The limbs of `x` (least significant first), zero-extended to at least `min_len`. A copy
/// through a zeroed buffer, several times faster than `BigUint::to_u64_digits` (which collects
/// an iterator limb by limb).
pub fn limbs_of(x: &BigUint, min_len: usize) -> Vec<u64> {
    let digits = x.iter_u64_digits();
    let mut out = vec![0u64; digits.len().max(min_len)];
    for (o, w) in out.iter_mut().zip(digits) {
        *o = w;
    }
    out
}

/// [`limbs_of`] into a reused buffer (cleared first).
/// Only the buffer's growth is zeroed before the copy (a reused buffer is mostly overwritten).
pub fn limbs_into(x: &BigUint, min_len: usize, out: &mut Vec<u64>) {
    let digits = x.iter_u64_digits();
    let k = digits.len();
    out.truncate(k.max(min_len));
    out.resize(k.max(min_len), 0);
    for (o, w) in out.iter_mut().zip(digits) {
        *o = w;
    }
    out[k..].fill(0);
}

/// The 32-bit digits of the number with these limbs (least significant first) into a reused
/// buffer (cleared first): the form num-bigint's `assign_from_slice` takes, which sets a
/// number in its own allocation (num-bigint has no constructor from 64-bit limbs).
pub fn u32_digits_into(limbs: &[u64], out: &mut Vec<u32>) {
    // Every digit is overwritten: only the growth is zeroed.
    out.truncate(2 * limbs.len());
    out.resize(2 * limbs.len(), 0);
    for (pair, &w) in out.chunks_exact_mut(2).zip(limbs) {
        pair[0] = w as u32;
        pair[1] = (w >> 32) as u32;
    }
}

/// `x mod d` for a [`BigUint`] (`d != 0`) by [`rem_1`], without allocating for operands of up
/// to eight limbs (copied to the stack) and with the fast copy of [`limbs_of`] above that.
///
/// # Panics
/// If `d == 0`.
pub fn rem_1_big(x: &BigUint, d: u64) -> u64 {
    let digits = x.iter_u64_digits();
    let n = digits.len();
    if n <= 8 {
        let mut buf = [0u64; 8];
        for (b, w) in buf.iter_mut().zip(digits) {
            *b = w;
        }
        rem_1(&buf[..n], d)
    } else {
        rem_1(&limbs_of(x, 0), d)
    }
}

/// Removes leading (most significant) zero limbs.
#[inline]
pub fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// The [`BigUint`] with the given limbs (least significant first).
pub fn biguint_from_limbs(limbs: &[u64]) -> BigUint {
    let mut digits = Vec::new();
    u32_digits_into(limbs, &mut digits);
    BigUint::new(digits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_core::Rng;
    use num_bigint::BigInt;
    use num_traits::Zero;
    use proptest::prelude::*;

    fn limbs(x: &BigUint) -> Vec<u64> {
        x.to_u64_digits()
    }

    fn arb_limbs(max: usize) -> impl Strategy<Value = Vec<u64>> {
        prop::collection::vec(any::<u64>(), 0..max)
    }

    /// Divisors of every size: random u64 shifted right by 0..63 bits, never zero.
    fn arb_divisor() -> impl Strategy<Value = u64> {
        (any::<u64>(), 0u32..64).prop_map(|(d, s)| (d >> s).max(1))
    }

    fn signed(mag: &[u64], neg: bool) -> BigInt {
        let m = BigInt::from(biguint_from_limbs(mag));
        if neg {
            -m
        } else {
            m
        }
    }

    proptest! {
        #[test]
        fn prop_rem_1(x in arb_limbs(30), d in arb_divisor()) {
            let big = biguint_from_limbs(&x);
            let expected = &big % BigUint::from(d);
            prop_assert_eq!(BigUint::from(rem_1(&x, d)), expected.clone());
            // Both methods on every divisor below the folding bound.
            if (2..FOLD_MAX).contains(&d) {
                prop_assert_eq!(BigUint::from(rem_1_preinv(x.iter().copied(), d)), expected);
                prop_assert_eq!(rem_1(&big.to_u64_digits(), d), rem_1(&x, d));
            }
        }

        #[test]
        fn prop_divexact_1(q in arb_limbs(30), d in arb_divisor()) {
            let x = biguint_from_limbs(&q) * BigUint::from(d);
            let got = divexact_1(&limbs(&x), d);
            prop_assert_eq!(biguint_from_limbs(&got), &x / BigUint::from(d));
            prop_assert!(got.last() != Some(&0));
        }

        /// The Hensel division is the ring division modulo 2^(64 len): y d = x there, and
        /// y is the exact quotient when d divides x.
        #[test]
        fn prop_hensel_div_1(x in prop::collection::vec(any::<u64>(), 1..8), d in arb_divisor()) {
            let d = d | 1;
            let inv = inverse_mod_2_64(d);
            let modulus = BigUint::from(1u8) << (64 * x.len());
            let mut y = x.clone();
            hensel_div_1_in_place(&mut y, d, inv);
            prop_assert_eq!(
                biguint_from_limbs(&y) * BigUint::from(d) % &modulus,
                biguint_from_limbs(&x)
            );
            // An exact multiple: the true quotient.
            let q = biguint_from_limbs(&x) >> 64;
            let mut m = limbs(&(&q * BigUint::from(d)));
            m.resize(x.len() + 1, 0);
            hensel_div_1_in_place(&mut m, d, inv);
            let mut expected = limbs(&q);
            expected.resize(x.len() + 1, 0);
            prop_assert_eq!(m, expected);
        }

        /// acc +- x m modulo 2^(64 len).
        #[test]
        fn prop_mul_1_add(
            acc in prop::collection::vec(any::<u64>(), 1..8),
            seed in any::<u64>(),
            m in any::<u64>(),
            sub in any::<bool>(),
        ) {
            let x: Vec<u64> = acc.iter().map(|&a| a.rotate_left(17) ^ seed).collect();
            let modulus = BigInt::from(BigUint::from(1u8) << (64 * acc.len()));
            let expected = {
                let (a, b) = (signed(&acc, false), signed(&x, false) * BigInt::from(m));
                let v = if sub { a - b } else { a + b };
                ((v % &modulus) + &modulus) % &modulus
            };
            let mut got = acc.clone();
            mul_1_add_in_place(&mut got, &x, m, sub);
            prop_assert_eq!(signed(&got, false), expected);
        }
    }

    proptest! {
        /// The fused kernel is the composition of the two it fuses.
        #[test]
        fn prop_mul_1_add_hensel(
            acc in prop::collection::vec(any::<u64>(), 1..8),
            seed in any::<u64>(),
            m in any::<u64>(),
            sub in any::<bool>(),
            d in arb_divisor(),
        ) {
            let d = d | 1;
            let inv = inverse_mod_2_64(d);
            let x: Vec<u64> = acc.iter().map(|&a| a.rotate_left(29) ^ seed).collect();
            let mut expected = acc.clone();
            mul_1_add_in_place(&mut expected, &x, m, sub);
            hensel_div_1_in_place(&mut expected, d, inv);
            let mut got = acc.clone();
            mul_1_add_hensel_in_place(&mut got, &x, m, sub, d, inv);
            prop_assert_eq!(got, expected);
        }
    }

    proptest! {
        #[test]
        fn prop_add_word_pass(
            a in arb_limbs(20), an in any::<bool>(), b1 in arb_limbs(20), cn in any::<bool>(),
            cm in any::<u64>(), d1 in arb_divisor(), g in arb_divisor()
        ) {
            // b = b1 g and d = d1 g, so that g divides both, as the caller guarantees.
            let Some(d) = d1.checked_mul(g) else { return Ok(()); };
            let b = limbs(&(biguint_from_limbs(&b1) * BigUint::from(g)));
            let (t, tn, den) = add_word_pass(a.clone(), an, b.clone(), cn, cm, d, g);
            let expected = signed(&a, an) * BigInt::from(d1) + signed(&b1, cn) * BigInt::from(cm);
            prop_assert!(t.last() != Some(&0) && den.last() != Some(&0));
            prop_assert!(!(t.is_empty() && tn));
            prop_assert_eq!(signed(&t, tn), expected);
            prop_assert_eq!(biguint_from_limbs(&den), biguint_from_limbs(&b) * BigUint::from(d1));
        }
    }

    proptest! {
        #[test]
        fn prop_divexact_1_pair(p in arb_limbs(20), q in arb_limbs(20), d in arb_divisor()) {
            let (x, y) = (biguint_from_limbs(&p) * BigUint::from(d), biguint_from_limbs(&q) * BigUint::from(d));
            let (mut xl, mut yl) = (limbs(&x), limbs(&y));
            divexact_1_pair_in_place(&mut xl, &mut yl, d);
            prop_assert_eq!(biguint_from_limbs(&xl), &x / BigUint::from(d));
            prop_assert_eq!(biguint_from_limbs(&yl), &y / BigUint::from(d));
            prop_assert!(xl.last() != Some(&0) && yl.last() != Some(&0));
        }

        #[test]
        fn prop_limbs_of_and_rem_1_big(p in arb_limbs(20), min_len in 0usize..24, d in arb_divisor()) {
            let x = biguint_from_limbs(&p);
            let l = limbs_of(&x, min_len);
            prop_assert!(l.len() >= min_len);
            prop_assert_eq!(biguint_from_limbs(&l), x.clone());
            prop_assert_eq!(BigUint::from(rem_1_big(&x, d)), &x % BigUint::from(d));
        }

        /// The reused-buffer forms against num-bigint's own digits: `limbs_into` over a dirty
        /// buffer, `u32_digits_into` against `to_u32_digits`, and `add_word_pass_into` over dirty
        /// output buffers against `add_word_pass`.
        #[test]
        fn prop_reused_buffers(
            p in arb_limbs(20), min_len in 0usize..24, junk in arb_limbs(30),
            an in any::<bool>(), cn in any::<bool>(), cm in any::<u64>(), d in arb_divisor(),
        ) {
            let x = biguint_from_limbs(&p);
            let mut buf = junk.clone();
            limbs_into(&x, min_len, &mut buf);
            prop_assert_eq!(&buf, &limbs_of(&x, min_len));
            let mut digits: Vec<u32> = junk.iter().map(|&w| w as u32).collect();
            u32_digits_into(&p, &mut digits);
            let mut expected = x.to_u32_digits();
            expected.resize(2 * p.len(), 0);
            prop_assert_eq!(&digits, &expected);
            // b = p d: g = d divides both b and d.
            let b = limbs(&(&x * BigUint::from(d)));
            let (t, tn, den) = add_word_pass(junk.clone(), an, b.clone(), cn, cm, d, d);
            let mut out = (junk.clone(), junk.clone());
            let (mut az, mut bz) = (junk.clone(), b);
            let negative = add_word_pass_into(&mut az, an, &mut bz, (cn, cm, d), d, &mut out);
            prop_assert_eq!((out.0, negative, out.1), (t, tn, den));
        }
    }

    #[test]
    fn fixed_cases() {
        assert_eq!(rem_1(&[], 7), 0);
        assert_eq!(rem_1(&[5], 1), 0);
        assert_eq!(rem_1(&[u64::MAX; 9], u64::MAX), 0);
        assert_eq!(
            rem_1(&[u64::MAX; 9], (1 << 61) - 1),
            rem_1_preinv([u64::MAX; 9].into_iter(), (1 << 61) - 1)
        );
        assert_eq!(divexact_1(&[], 3), Vec::<u64>::new());
        assert_eq!(divexact_1(&[0, 1], 1 << 63), vec![2]);
        let pass = |a: &[u64], an, b: &[u64], cn, cm, d, g| {
            let (t, tn, _) = add_word_pass(a.to_vec(), an, b.to_vec(), cn, cm, d, g);
            (t, tn)
        };
        assert_eq!(pass(&[3], false, &[6], true, 1, 2, 1), (vec![], false));
        assert_eq!(pass(&[3], false, &[7], true, 1, 2, 1), (vec![1], true));
        assert_eq!(pass(&[], true, &[], true, 1, 2, 1), (vec![], false));
        // 3*(6/3) - (9/3)*1 = 3 and den = 9*2.
        assert_eq!(
            add_word_pass(vec![3], false, vec![9], true, 1, 6, 3),
            (vec![3], false, vec![18])
        );
    }

    #[test]
    fn large_operands() {
        // 10^5-limb operands (6.4 million bits) against num-bigint.
        let mut st = Rng::new(99);
        let x: Vec<u64> = (0..100_000).map(|_| st.next_u64()).collect();
        let big = biguint_from_limbs(&x);
        for d in [
            3u64,
            1_000_000_007,
            (1 << 61) - 1,
            (1 << 61) + 1,
            u64::MAX,
            1 << 40,
        ] {
            assert_eq!(
                BigUint::from(rem_1(&x, d)),
                &big % BigUint::from(d),
                "d = {d}"
            );
            let prod = &big * BigUint::from(d);
            assert_eq!(biguint_from_limbs(&divexact_1(&limbs(&prod), d)), big);
        }
        assert!(!big.is_zero());
    }
}
