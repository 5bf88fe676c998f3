//! The Bernstein form on integers and its subdivision (steps 3 to 5 of the parent module's
//! documentation): sign variations, the Taylor shift by 1, de Casteljau halves on `BigInt`s
//! and on fixed-width limbs, and the subdivision of one unit problem into isolating nodes.

use super::*;

/// Number of sign changes, zeros skipped ([`isolate::count_variations`]).
pub(super) fn variations(b: &[BigInt]) -> usize {
    isolate::count_variations(b.iter().map(|c| match c.sign() {
        BigSign::Minus => Sign::Negative,
        BigSign::NoSign => Sign::Zero,
        BigSign::Plus => Sign::Positive,
    }))
}

/// `p(x + 1)` in place (`n(n+1)/2` additions).
pub(super) fn taylor_shift_1(a: &mut [BigInt]) {
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
pub(super) fn to_bernstein_integer(p: &[BigInt]) -> Vec<BigInt> {
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
pub(super) fn bernstein_multipliers(n: usize) -> Vec<BigInt> {
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
pub(super) fn bernstein_from_shifted(shifted: &Limbs) -> Limbs {
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
pub(super) fn remove_common_twos(b: &mut [BigInt]) {
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
pub(super) fn split_half(b: &[BigInt]) -> (Vec<BigInt>, Vec<BigInt>) {
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
pub(super) enum UnitRoot {
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
pub(super) fn unit_roots(p: &[BigInt], opts: Options) -> Vec<UnitRoot> {
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
pub(super) trait NodeCoeffs: Sized {
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
pub(super) fn unit_roots_from<C: NodeCoeffs>(
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
/// Bernstein coefficients `g` in `f64` (any common positive scale), at first a coarse one
/// ([`UnitEstimate::of_leaf`]).
pub(super) fn leaf_root(c: &BigInt, j: u64, g: Vec<f64>, binoms: &[f64]) -> UnitRoot {
    UnitRoot::Open {
        a: dyadic(c, j),
        b: dyadic(&(c + 1), j),
        estimate: UnitEstimate::of_leaf(c, j, g, binoms),
    }
}

/// The two isolating halves of the node `(c, j)` split at the point `x` of a close pair, with
/// the estimates `x -/+ delta` ([`PairSplitter::split`]).
pub(super) fn pair_roots(c: &BigInt, j: u64, (x, delta): (Dyadic, Option<f64>)) -> [UnitRoot; 2] {
    let (a, m, e) = (dyadic(c, j), x.to_rational(), dyadic(&(c + 1), j));
    let d = delta.filter(|d| d.is_finite());
    let estimate = |off: f64| UnitEstimate {
        num: x.num.clone(),
        exp: x.exp,
        off,
        newton: None,
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
