//! The Descartes subdivision of a unit problem on `f64` Bernstein coefficients with one rigorous
//! error bound per node, exact where `f64` cannot decide (floating-point filtering in the sense
//! of exact geometric computation: nothing is decided on an unverified float).
//!
//! # Nodes
//! A node `(c, j)` is the interval `(c / 2^j, (c + 1) / 2^j)` of the unit problem `p`. It
//! carries
//! * `g_0, ..., g_n` in `f64`: approximations of `2^s` times the Bernstein coefficients `b_i` of
//!   `p` on the node, `2^s > 0` a scale of the node's own (so the signs are the `b_i`'s);
//! * one bound `E` with `|g_i - 2^s b_i| <= E` for every `i`;
//! * the **exact** signs `s_lo`, `s_hi` of `p` at the two ends (the end coefficients are the
//!   end values, `b_0 = p(c / 2^j)`, `b_n = p((c + 1) / 2^j)`); `Zero` is a root already
//!   reported as exact.
//!
//! # Error analysis (`u = 2^-53`)
//! * **Root node.** The Bernstein coefficients on `[0, 1]` are `b_i = c_(n-i) / C(n, i)`, `c`
//!   the coefficients of `(1 + y)^n p(1 / (1 + y))` (module `descartes`): the reversal of `p`
//!   shifted by 1. Everything is computed in `f64`, with no big-integer arithmetic: the inputs
//!   `x_m = p_(n-m) 2^-k` (`k` the largest bit length) from the top 64 bits of each coefficient
//!   (truncation: relative error below `2^-63`) rounded to `f64` (relative `u`; absolute
//!   `2^-1074` when subnormal); the Taylor shift `x(y + 1)` by the triangle of `n(n+1)/2`
//!   additions, where a term of `x_m` passes through at most `m + 1 <= n + 1` roundings on its
//!   way to `c_k`, so `|c^_k - c_k| <= (gamma_(n+1) + 2u) T_k` with `T` the same shift of the
//!   `|x_m|` (computed alongside; its computed value is below the true one by a factor at least
//!   `(1 - u)^(n+1)`), plus `2^(n+1) 2^-1074 <= 2^-73` from subnormal inputs (additions are
//!   exact in the subnormal range, and nothing overflows: `T_k < (n + 1) 2^n`); `C(n, i)` by
//!   the recurrence `C(n, i+1) = C(n, i) (n - i) / (i + 1)` in `f64` (`2i` roundings: relative
//!   `2.01 n u` for `n <= 1000`, and no overflow: `C(1000, 500) < 2^996`); the division one more
//!   rounding. With `|c_k| <= T_k` that is an error below `(3n + 4) u T_(n-i) / C(n, i)` (to
//!   first order; the second-order terms are below `2^-30` of it for `n <= 1000`) plus
//!   `2^-72`, so `E_0 = ((3n + 8) u max_i T_(n-i) / C(n, i) + 2^-71)` (evaluated in `f64` and
//!   multiplied by `(1 + 2^-40)^2`, which covers its own roundings) bounds every error. All
//!   values and `E_0` are then multiplied by the power of two `2^t` that brings the largest
//!   into `[1/2, 1)` (`t` may be negative: the shifted values reach `(n + 1) 2^n`; a value or
//!   `E_0` made subnormal by it is rounded by at most `2^-1075`, and `2^-1073` is added to
//!   `E_0`). The end signs are exact: those of `p(0) = p_0` and of
//!   `p(1)`, the sum of the coefficients. Against the exact shift on limbs this is
//!   `n(n+1)/2` additions of (value, bound) pairs in a loop without a dependency chain instead
//!   of `n(n+1)/2` carry chains over the coefficients' limbs and the conversions. Where the shift cancels (the values far below
//!   `T`, as for Wilkinson's product: `E_0 > 2^-38 M`, which would exhaust the precision a few
//!   splits down; predicted from the coefficients before the `f64` shift is tried, see
//!   [`shift_predicted_to_cancel`]) the root node is made from the exact
//!   shift on [`Limbs`] instead: each `c_k 2^-K` (`K` the largest bit length) from the top 64
//!   bits of `|c_k|` (truncation: relative error below `2^-63`), rounded to `f64` (`u`), divided
//!   by the `f64` binomials, so each value has a relative error below `rho = (3n + 8) u` and an
//!   absolute one below `2^-1073`; scaled by `2^t` (`t >= 0`) into `[1/2, 1)`, with `M` the
//!   largest value, `E_0 = rho (1 + 2 rho) M + 2^(t - 1072)`; its end signs are those of `c_n`
//!   and `c_0`, and the exact shift is kept for the exact coefficients of re-anchored nodes.
//! * **Re-anchored node.** Exact integer coefficients `B_i` (times a positive constant) are
//!   converted to `B_i 2^-k`, `k` the largest bit length, as the `c_k` above: relative error
//!   below `u + 2^-63`, absolute `2^-1074`, so with `M >= 1/2 - 2^-53` the largest computed
//!   value, `E_0 = 2^-52 M` bounds the error.
//! * **Split at 1/2.** de Casteljau with the halvings, `w = fl(fl(x + y) / 2)`: the true
//!   triangle is `T^(k)_i = (T^(k-1)_i + T^(k-1)_(i+1)) / 2`, the left child `T^(k)_0`, the right
//!   one `T^(n-k)_k` (the Bernstein coefficients of `p` on the halves, no `2^n` factor in this
//!   form). With `A_k` the largest computed value of level `k` (`A_0 = M`, the parent's largest
//!   `|g_i|`) the sum rounds by at most `u |x + y| <= 2 u A_(k-1)` and the halving is exact
//!   barring underflow (`2^-1075`), so the error grows per level by at most
//!   `u A_(k-1) + 2^-1075`, and `A_k <= (1 + u) A_(k-1) + 2^-1075`. Over `n` levels, with
//!   `(1 + u)^n <= 2` (`n <= ` [`MAX_FILTERED_DEGREE`]):
//!   `E_child <= E + 2 n u M + n 2^-1074 <= E + (n + 1) 2^-52 M + (n + 1) 2^-1074`. The bound is
//!   evaluated in `f64` in at most four roundings to nearest of non-negative terms (each at
//!   worst a factor `1 - u`) and multiplied by `1 + 2^-40`, which more than makes up for them:
//!   the computed `E_child` is not below the true bound.
//! * **Renormalisation.** A child whose largest `|g_i|` is below `1/2` is multiplied, `E` with
//!   it, by the power of two `2^t` that brings it into `[1/2, 1)` (exact: `t >= 0` and no value
//!   reaches 1), so the values never drift into the subnormal range on the way down.
//!
//! # Decisions
//! A coefficient's sign is **certain** when `|g_i| > E` (then `2^s b_i` lies on the same side of
//! zero). Descartes' bound `V` (sign changes of `s_lo, b_1, ..., b_(n-1), s_hi`, zeros skipped)
//! is at most `V_max`, the largest number of changes over every choice `+`, `-`, `0` for the
//! uncertain coefficients (one pass over the sequence keeping the largest count per last
//! non-zero sign). With non-zero ends every choice, the true one included, has the parity of
//! `s_lo != s_hi`, so:
//! * `V_max = 0`: no root in the node;
//! * `V_max = 1`, non-zero ends: `V = 1`, an isolating leaf (its root estimate from the node's
//!   `g` directly, [`bernstein_root_estimate`]);
//! * `V_max = 2`, equal non-zero ends, depth at least 2, and the parent's `V_max` was 2 as
//!   well (both variations survived a split: a pair that one split separates never pays for
//!   the attempt): the close-pair attempt (exact, [`PairSplitter`]; it needs only `V <= 2`);
//! * otherwise a split. The split's middle value `g` (the children's shared end) is its exact
//!   sign when `|g| > E_child`; otherwise `p` is evaluated exactly at the dyadic midpoint
//!   `m / 2^(j+1)`, `m = 2c + 1` (the sign of `sum a_i m^i 2^((j+1)(n-i))`), and a zero is an
//!   exact root, reported as the exact subdivision reports it.
//!
//! # Re-anchoring and fallback
//! The root conversion's error is relative to the largest coefficient on `[0, 1]`, and the
//! Bernstein coefficients of a polynomial can be many orders of magnitude above its values on a
//! subinterval (Wilkinson's product of degree 40: `2^50` and more between the ends and the
//! middle of `[0, 1]`), so after a few renormalised levels `E` may approach `M`. When `E > M /
//! 256` (also when `M` is zero or a value is not finite) and the node is neither empty nor a
//! leaf by the rule above (those decisions hold at any precision), it is **re-anchored**: its exact
//! integer Bernstein coefficients are computed (on [`Limbs`], one exact split per level from
//! its deepest ancestor whose exact coefficients are known, keeping the half on the path along
//! the bits of `c`; both halves of every exact split are kept, so no exact split is done twice)
//! and converted afresh, `E = 2^-52 M` again, which passes the test: every node makes progress.
//! A node deeper than [`MAX_FILTERED_DEPTH`] is handed, with its exact coefficients, to the
//! exact subdivision (`unit_roots_from`) in its own coordinates `(c, j)`. Splitting is always
//! correct, so the float path only decides earlier where it can prove the exact decision;
//! termination comes from the depth cap and the exact subdivision (square-free input, module
//! `descartes`). Degrees above [`MAX_FILTERED_DEGREE`] run the exact subdivision alone.
//!
//! A split costs `n(n+1)/2` `f64` additions and no allocation (the nodes' coefficients live in
//! one flat stack of blocks of `n + 1`, the triangle in place in the parent's block, which
//! becomes the right child's; the node indices in four words), against `n(n+1)/2` carry chains
//! over limbs growing by `n` bits per level on the exact path.
//!
//! Hand-written because the workspace has no interval or filtered arithmetic; the kernels are
//! the few lines of de Casteljau and a sign count.

use super::*;
use std::collections::HashMap;

/// The largest degree of the filtered subdivision (the leaf estimate's limit; it also keeps
/// `(1 + u)^n <= 2` in the error bound).
pub(super) const MAX_FILTERED_DEGREE: usize = 1000;

/// Nodes deeper than this are handed to the exact subdivision (a bound on the float tree; the
/// exact subdivision separates a close pair without it by [`PairSplitter`] or by depth).
const MAX_FILTERED_DEPTH: u64 = 200;

/// A node with `E > M * FALLBACK_RATIO` is handed to the exact subdivision.
const FALLBACK_RATIO: f64 = 1.0 / 256.0;

/// `2^-1074`, the least positive subnormal (`2^-1022 * 2^-52`, exact).
const TINY: f64 = f64::MIN_POSITIVE * f64::EPSILON;

/// `1 + 2^-40`, the safety factor on the evaluated error bounds.
const SAFETY: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;

/// What the filtered subdivision did (CGAL's filter-failure counters): for the tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct FilterStats {
    /// `f64` splits.
    pub(super) splits: usize,
    /// Split midpoints whose sign was decided by an exact evaluation.
    pub(super) exact_midpoints: usize,
    /// Nodes whose `f64` coefficients were recomputed from their exact ones.
    pub(super) anchors: usize,
    /// Nodes handed to the exact subdivision.
    pub(super) fallbacks: usize,
}

/// The index `c` of a node `(c, j)` (`0 <= c < 2^j`) in four words, least significant
/// first: the filtered nodes are at most [`MAX_FILTERED_DEPTH`]` + 1 < 256` deep, so a split
/// makes its children's indices without allocating (a `BigInt` only where one is needed: a
/// leaf, an exact root, an exact evaluation past a word, the exact path).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct NodeIndex([u64; 4]);

const _: () = assert!(MAX_FILTERED_DEPTH < 255, "a node index has 256 bits");

impl NodeIndex {
    const ZERO: NodeIndex = NodeIndex([0; 4]);

    /// `2 c` (the left child's index).
    fn doubled(self) -> NodeIndex {
        let w = self.0;
        debug_assert!(w[3] >> 63 == 0, "a node index stays below 2^256");
        NodeIndex([
            w[0] << 1,
            w[1] << 1 | w[0] >> 63,
            w[2] << 1 | w[1] >> 63,
            w[3] << 1 | w[2] >> 63,
        ])
    }

    /// `c + 1` for an even `c` (the right child's index from the left one's).
    fn odd(self) -> NodeIndex {
        debug_assert!(!self.is_odd());
        let mut w = self.0;
        w[0] |= 1;
        NodeIndex(w)
    }

    fn is_odd(self) -> bool {
        self.0[0] & 1 == 1
    }

    /// The index as a word, when it is one.
    fn word(self) -> Option<u64> {
        (self.0[1..].iter().all(|&x| x == 0)).then_some(self.0[0])
    }

    fn to_bigint(self) -> BigInt {
        match self.word() {
            Some(w) => BigInt::from(w),
            None => BigInt::from(crate::bigint::biguint_from_limbs(&self.0)),
        }
    }
}

/// A node waiting on the stack; its coefficients are the block of the same index.
struct Node {
    c: NodeIndex,
    j: u64,
    e: f64,
    /// The largest magnitude of the block (known from the split that made it).
    m: f64,
    /// The parent's `V_max` was 2.
    parent_v2: bool,
    lo: Sign,
    hi: Sign,
}

/// The roots in `(0, 1)` of the square-free integer polynomial `p` (degree from 1 to
/// [`MAX_FILTERED_DEGREE`]): the same contract as [`unit_roots_from`] from the whole
/// interval, and what was done.
pub(super) fn unit_roots_filtered(p: &[BigInt], pairs: bool) -> (Vec<UnitRoot>, FilterStats) {
    subdivide(p, pairs, MAX_FILTERED_DEPTH)
}

/// [`unit_roots_filtered`] with nodes deeper than `max_depth` handed to the exact subdivision.
fn subdivide(p: &[BigInt], pairs: bool, max_depth: u64) -> (Vec<UnitRoot>, FilterStats) {
    let n = p.len() - 1;
    debug_assert!((1..=MAX_FILTERED_DEGREE).contains(&n));
    assert!(
        max_depth <= MAX_FILTERED_DEPTH,
        "the node indices have room for this depth"
    );
    let mut run = Run {
        p,
        pairs,
        // At most n roots: one allocation, no regrowth (the entries are large).
        out: Vec::with_capacity(n),
        stats: FilterStats::default(),
        splitter: None,
        exact_nodes: HashMap::new(),
        shifted: None,
        p_limbs: None,
    };
    let w = n + 1;
    let binoms = binomials_f64(n);
    // Room for the blocks of a path of depth 7 (grown on demand below).
    let mut blocks: Vec<f64> = Vec::with_capacity(w * 8);
    let (root, _) = if shift_predicted_to_cancel(p) {
        root_from_exact_shift(p, &binoms, &mut blocks)
    } else {
        root_f64_coefficients(p, &binoms, &mut blocks)
    };
    // From the exact shift, the root's signs are exact: no variation, no root; one, with
    // non-zero ends, one root. Otherwise the root node's decisions are the loop's.
    if let Some(v) = root.v {
        if v == 0 {
            return (run.out, run.stats);
        }
        if v == 1 && root.lo != Sign::Zero && root.hi != Sign::Zero {
            run.out.push(leaf_root(&BigInt::zero(), 0, blocks, &binoms));
            return (run.out, run.stats);
        }
    }
    run.shifted = root.shifted;
    let mut stack = vec![Node {
        c: NodeIndex::ZERO,
        j: 0,
        e: root.e,
        m: max_abs(&blocks),
        parent_v2: false,
        lo: root.lo,
        hi: root.hi,
    }];
    while let Some(mut node) = stack.pop() {
        let base = stack.len() * w;
        debug_assert_eq!(blocks.len(), base + w);
        // A right child (odd `c`) whose left end is a root: reported here, after the roots of
        // its left sibling's subtree, so the roots come out in increasing order.
        if node.lo == Sign::Zero && node.c.is_odd() {
            run.out.push(UnitRoot::Exact(node.c.to_bigint(), node.j));
        }
        if node.j > max_depth {
            blocks.truncate(base);
            run.exact_subtree(&node);
            continue;
        }
        let mut m = node.m;
        debug_assert_eq!(m.to_bits(), max_abs(&blocks[base..]).to_bits());
        let ends = node.lo != Sign::Zero && node.hi != Sign::Zero;
        let v_max = loop {
            let g = &blocks[base..];
            let v_max = max_variations(node.lo, &g[1..n], node.e, node.hi);
            // A decision without a split stands whatever the precision; `!(a <= b)` also
            // catches a NaN.
            if v_max == 0 || (v_max == 1 && ends) || node.e <= m * FALLBACK_RATIO {
                break v_max;
            }
            // Out of precision: restart from the node's exact coefficients, whose fresh error
            // bound `2^-52 M` passes the test.
            run.stats.anchors += 1;
            let exact = run.exact_coefficients(&node.c.to_bigint(), node.j);
            blocks.truncate(base);
            node.e = f64_coefficients_limbs(&exact, &mut blocks);
            m = max_abs(&blocks[base..]);
            assert!(
                node.e <= m * FALLBACK_RATIO,
                "exact coefficients of a non-zero polynomial are not all zero"
            );
        };
        let g = &blocks[base..];
        if v_max == 0 {
            blocks.truncate(base);
            continue;
        }
        if v_max == 1 && ends {
            run.out
                .push(leaf_root(&node.c.to_bigint(), node.j, g.to_vec(), &binoms));
            blocks.truncate(base);
            continue;
        }
        if run.pairs && v_max == 2 && node.parent_v2 && node.j >= 2 && ends && node.lo == node.hi {
            let splitter = run.splitter.get_or_insert_with(|| PairSplitter::new(p));
            let c = node.c.to_bigint();
            if let Some(split) = splitter.split(&c, node.j, node.lo) {
                run.out.extend(pair_roots(&c, node.j, split));
                blocks.truncate(base);
                continue;
            }
        }
        // Split: the right child in the parent's block, the left one in a new block above.
        run.stats.splits += 1;
        blocks.resize(base + 2 * w, 0.0);
        let (right, left) = blocks[base..].split_at_mut(w);
        de_casteljau_half(right, left);
        let nf = w as f64;
        let e = (node.e + nf * f64::EPSILON * m + nf * TINY) * SAFETY;
        let c2 = node.c.doubled();
        let mid = c2.odd();
        let s_mid = if left[n].abs() > e {
            sign_f64(left[n])
        } else {
            run.stats.exact_midpoints += 1;
            run.sign_at(mid, node.j + 1)
        };
        let (e_right, m_right) = renormalise(right, e);
        let (e_left, m_left) = renormalise(left, e);
        stack.push(Node {
            c: mid,
            j: node.j + 1,
            e: e_right,
            m: m_right,
            parent_v2: v_max == 2,
            lo: s_mid,
            hi: node.hi,
        });
        stack.push(Node {
            c: c2,
            j: node.j + 1,
            e: e_left,
            m: m_left,
            parent_v2: v_max == 2,
            lo: node.lo,
            hi: s_mid,
        });
    }
    (run.out, run.stats)
}

/// The state of one filtered subdivision beside its node stack.
struct Run<'a> {
    p: &'a [BigInt],
    pairs: bool,
    out: Vec<UnitRoot>,
    stats: FilterStats,
    splitter: Option<PairSplitter<'a>>,
    /// The exact integer Bernstein coefficients of the nodes `(j, c)` computed so far (both
    /// halves of every exact split), so that no exact split is done twice.
    exact_nodes: HashMap<(u64, BigInt), Limbs>,
    /// The root's exact Taylor-shifted reversal when the root node was made from it.
    shifted: Option<Limbs>,
    /// `p` on limbs, for the exact signs at split points.
    p_limbs: Option<Limbs>,
}

impl Run<'_> {
    /// The exact sign of `p` at `m / 2^k` (`0 < m < 2^k`): on limbs when `m` fits a word
    /// ([`Limbs::sign_at_dyadic`]), by `BigInt` Horner otherwise.
    fn sign_at(&mut self, m: NodeIndex, k: u64) -> Sign {
        match m.word() {
            Some(word) if k < 64 => {
                let p = self.p;
                let limbs = self.p_limbs.get_or_insert_with(|| Limbs::from_bigints(p));
                match limbs.sign_at_dyadic(word, k) {
                    -1 => Sign::Negative,
                    0 => Sign::Zero,
                    _ => Sign::Positive,
                }
            }
            _ => sign_at_dyadic(self.p, &m.to_bigint(), k),
        }
    }

    /// The exact coefficients of the node `(c, j)`: one exact split per level from its deepest
    /// ancestor with known exact coefficients (the root node when none), keeping the half on
    /// the path along the bits of `c`; every node computed on the way is kept.
    fn exact_coefficients(&mut self, c: &BigInt, j: u64) -> Limbs {
        let start = (0..=j)
            .rev()
            .find(|&d| d == 0 || self.exact_nodes.contains_key(&(d, c >> (j - d))))
            .expect("d = 0 is always found");
        let (p, shifted) = (self.p, &self.shifted);
        let mut limbs = self
            .exact_nodes
            .entry((start, c >> (j - start)))
            .or_insert_with(|| match shifted {
                Some(s) => bernstein_from_shifted(s),
                None => bernstein_from_shifted(&exact_shifted_reversal(p)),
            })
            .clone();
        for d in start + 1..=j {
            let (left, right) = limbs.split_half();
            let here: BigInt = c >> (j - d);
            let (next, other) = if here.bit(0) {
                (right, left)
            } else {
                (left, right)
            };
            self.exact_nodes.insert((d, &here ^ BigInt::one()), other);
            self.exact_nodes.insert((d, here), next.clone());
            limbs = next;
        }
        limbs
    }

    /// The exact subdivision of `node` in its coordinates ([`unit_roots_from`]).
    fn exact_subtree(&mut self, node: &Node) {
        self.stats.fallbacks += 1;
        let c = node.c.to_bigint();
        let limbs = self.exact_coefficients(&c, node.j);
        self.out
            .extend(unit_roots_from(limbs, self.p, self.pairs, (c, node.j)));
    }
}

/// Pushes `g_i = B_i 2^-k` for the exact coefficients `B_i` of a node (module documentation,
/// "Re-anchored node") onto `blocks` and returns their error bound `E_0`.
fn f64_coefficients_limbs(b: &Limbs, blocks: &mut Vec<f64>) -> f64 {
    let mut bits = Vec::with_capacity(b.len());
    b.leading_bits(|neg, top, shift| bits.push((neg, top, shift)));
    f64_of_leading_bits(bits, blocks)
}

/// The root node in `f64` ([`root_f64_coefficients`]).
struct Root {
    /// The error bound `E_0`.
    e: f64,
    /// The exact signs of `p(0)` and `p(1)`.
    lo: Sign,
    hi: Sign,
    /// The exact Taylor-shifted reversal when the values were made from it.
    shifted: Option<Limbs>,
    /// Then also the exact number of sign variations of the coefficients.
    v: Option<usize>,
}

/// The coefficients of `(1 + y)^n p(1 / (1 + y))` (the reversal of `p` shifted by 1), exactly
/// on [`Limbs`], for the root's exact Bernstein coefficients.
fn exact_shifted_reversal(p: &[BigInt]) -> Limbs {
    let n = p.len() - 1;
    let mut shifted = Limbs::from_bigints_reversed_with_room(p, n + 1);
    shifted.taylor_shift_1();
    shifted
}

/// The sign, the 64 leading bits `t` and their position `s` of an integer: `|x| = t 2^s + r`,
/// `0 <= r < 2^s`, `t >= 2^63` when `s > 0` (the form of [`Limbs::leading_bits`]).
fn big_leading_bits(x: &BigInt) -> (bool, u64, u64) {
    let bits = x.bits();
    let mut limbs = x.magnitude().iter_u64_digits().rev();
    let hi = limbs.next().unwrap_or(0);
    if bits <= 64 {
        return (x.is_negative(), hi, 0);
    }
    let lo = limbs.next().unwrap_or(0);
    let lz = hi.leading_zeros();
    let top = if lz == 0 {
        hi
    } else {
        (hi << lz) | (lo >> (64 - lz))
    };
    (x.is_negative(), top, bits - 64)
}

/// The root node from the `f64` shift is kept when `E_0 <= M * ROOT_ACCEPT` (`2^-38`; the
/// exact shift's bound is about `2^-45` to `2^-47` at degrees 20 to 100): a larger bound would
/// send its nodes to exact re-anchoring after a few splits.
const ROOT_ACCEPT: f64 = 1.0 / (1u64 << 38) as f64;

/// Whether the root's `f64` Taylor shift ([`root_f64_coefficients`]) is predicted to cancel
/// beyond [`ROOT_ACCEPT`], so that the exact shift is taken at once instead of after a wasted
/// `f64` attempt. The prediction compares a lower bound of the shift's error bound,
/// `(3n + 8) u sum |p_m|` (the shift of the absolute values at `y = 0`, where the largest
/// `T / C(n, i)` is at least `T_0`), with `ROOT_ACCEPT` times `max(|p_0|, |p_n|)` as the
/// estimate of the largest Bernstein coefficient (`|p_0|` is the first one; `|p_n|` stands for
/// the size of the interior ones), and asks for it only when the coefficients have `n` sign
/// variations: a polynomial whose roots may all be positive, like a product of linear factors
/// with roots in the unit interval, whose shift cancels (Wilkinson's product loses 28 bits at
/// degree 20). Random coefficients have about `n / 2` variations and are never predicted to
/// cancel. A wrong prediction costs time, not correctness: both root nodes carry a rigorous
/// bound.
fn shift_predicted_to_cancel(p: &[BigInt]) -> bool {
    let n = p.len() - 1;
    if n < 2 || variations(p) < n {
        return false;
    }
    // Every |p_m| 2^-k (k the largest bit length) from its 64 leading bits.
    let bits: Vec<(bool, u64, u64)> = p.iter().map(big_leading_bits).collect();
    let k = bits
        .iter()
        .map(|&(_, top, shift)| shift + u64::from(64 - top.leading_zeros()))
        .max()
        .unwrap_or(0);
    let scaled = |(_, top, shift): (bool, u64, u64)| {
        top as f64
            * pow2f(
                i64::try_from(shift).expect("a bit count") - i64::try_from(k).expect("a bit count"),
            )
    };
    let sum: f64 = bits.iter().map(|&b| scaled(b)).sum();
    let ends = scaled(bits[0]).max(scaled(bits[n]));
    let u = f64::EPSILON / 2.0;
    (3 * n + 8) as f64 * u * sum > ROOT_ACCEPT * ends
}

/// `2^-71`: the absolute error of the root node's values from underflow (module
/// documentation, "Root node").
const ROOT_ABSOLUTE: f64 = 1.0 / (1u128 << 71) as f64;

/// Pushes the root node's coefficients onto `blocks`: `g_i ~ 2^scale c_(n-i) / C(n, i)`, `c`
/// the coefficients of `(1 + y)^n p(1 / (1 + y))` (module documentation of `descartes`) by a
/// Taylor shift in `f64` alongside the same shift of the absolute values, which bounds its
/// error, and the binomials in `f64`; no big-integer arithmetic beyond reading the leading
/// bits of the coefficients and the exact sign of `p(1)`. Also `scale`.
fn root_f64_coefficients(p: &[BigInt], binoms: &[f64], blocks: &mut Vec<f64>) -> (Root, i64) {
    let n = p.len() - 1;
    let start = blocks.len();
    // x_m = p_(n-m) 2^-k, k the largest bit length.
    let k = push_scaled(p.iter().rev().map(big_leading_bits).collect(), blocks);
    // Each value beside its absolute value: one two-lane addition per step of the triangle.
    let mut xt: Vec<[f64; 2]> = blocks[start..].iter().map(|&v| [v, v.abs()]).collect();
    // The Taylor shift's triangle a_j <- a_j + a_(j+1) (pass i for j = n-1 down to i), run by
    // anti-diagonals: step d updates j = n-1-d, ..., n-1, each from the values before the
    // step (the ascending loop reads a_(j+1) before it is overwritten), a loop without a
    // dependency chain. The same additions as pass by pass.
    for d in 0..n {
        let row = &mut xt[n - 1 - d..];
        for j in 0..row.len() - 1 {
            let next = row[j + 1];
            row[j][0] += next[0];
            row[j][1] += next[1];
        }
    }
    // g_i = c_(n-i) / C(n, i), and the largest T_(n-i) / C(n, i).
    let mut worst = 0.0f64;
    for ((g, b), &[c, t]) in blocks[start..].iter_mut().zip(binoms).zip(xt.iter().rev()) {
        *g = c / b;
        worst = worst.max(t / b);
    }
    let u = f64::EPSILON / 2.0;
    let e = ((3 * n + 8) as f64 * u * worst + ROOT_ABSOLUTE) * SAFETY * SAFETY;
    // Into [1/2, 1) by a power of two (the shifted values reach (n + 1) 2^n, so it may be
    // below 1: then a value that becomes subnormal is rounded, by at most 2^-1075, and so may
    // be `E` itself; the two `TINY` cover both). Nothing to scale when every value cancelled
    // to zero (then `E > M / 256` and the node is re-anchored).
    let m = max_abs(&blocks[start..]);
    let t = if m >= f64::MIN_POSITIVE {
        1022 - ((m.to_bits() >> 52) & 0x7ff) as i64
    } else {
        0
    };
    let f = pow2f(t);
    for g in blocks[start..].iter_mut() {
        *g *= f;
    }
    let e = e * f + 2.0 * TINY;
    // `false` also for a NaN.
    let accepted = e <= max_abs(&blocks[start..]) * ROOT_ACCEPT;
    if !accepted {
        // The shift cancelled (the values far below the shift of the absolute values): the
        // exact shift now, rather than nodes re-anchored a few levels down.
        blocks.truncate(start);
        return root_from_exact_shift(p, binoms, blocks);
    }
    // The exact end signs only now: p(1) is a big-integer sum when a coefficient exceeds
    // `i128`, wasted on a rejected shift (whose exact shift gives both signs anyway).
    let (lo, hi) = (sign_of(&p[0]), super::sign_of_sum(p));
    (
        Root {
            e,
            lo,
            hi,
            shifted: None,
            v: None,
        },
        t - k,
    )
}

/// The root node from the exact Taylor shift on [`Limbs`] (for a shift that cancels in `f64`):
/// `g_i ~ 2^scale c_(n-i) / C(n, i)` from the leading bits of the exact `c` (relative error
/// below `rho = (3n + 8) u` each, module documentation, "Root node"), and `scale`.
fn root_from_exact_shift(p: &[BigInt], binoms: &[f64], blocks: &mut Vec<f64>) -> (Root, i64) {
    let n = p.len() - 1;
    let start = blocks.len();
    let shifted = exact_shifted_reversal(p);
    let mut bits = Vec::with_capacity(n + 1);
    shifted.leading_bits(|neg, top, shift| bits.push((neg, top, shift)));
    let sign = |(neg, top, _): (bool, u64, u64)| match (top, neg) {
        (0, _) => Sign::Zero,
        (_, true) => Sign::Negative,
        (_, false) => Sign::Positive,
    };
    let (lo, hi) = (sign(bits[n]), sign(bits[0]));
    // The Bernstein coefficients are these times positive multipliers: the same signs.
    let v = isolate::count_variations(bits.iter().map(|&b| sign(b)));
    bits.reverse();
    // c_(n-i) 2^-k, k the largest bit length, divided by C(n, i) (recurrence in f64).
    let k = push_scaled(bits, blocks);
    for (g, b) in blocks[start..].iter_mut().zip(binoms) {
        *g /= b;
    }
    // Into [1/2, 1): the largest value is at least 2^-1 / C(n, i) > 2^-1002.
    let m = max_abs(&blocks[start..]);
    assert!(
        m >= f64::MIN_POSITIVE,
        "the largest value is above 2^-1002 (degree at most 1000)"
    );
    let biased = ((m.to_bits() >> 52) & 0x7ff) as i64;
    let t = (1022 - biased).max(0);
    let f = pow2f(t);
    for g in blocks[start..].iter_mut() {
        *g *= f;
    }
    let m = max_abs(&blocks[start..]);
    let rho = (3 * n + 8) as f64 * (f64::EPSILON / 2.0);
    let e = (rho * (1.0 + 2.0 * rho) * m + pow2f(t - 1072)) * SAFETY;
    (
        Root {
            e,
            lo,
            hi,
            shifted: Some(shifted),
            v: Some(v),
        },
        t - k,
    )
}

/// Pushes `B 2^-k` for numbers `B` given by their sign, 64 leading bits `t` and their position
/// `s` (`|B| = t 2^s + r`, `0 <= r < 2^s`, `t >= 2^63` when `s > 0`), `k` the largest bit
/// length, and returns `k`. Each value has a relative error below `2^-53 + 2^-63` (the
/// truncation and one rounding of `t`) and an absolute one below `2^-1074` (underflow).
fn push_scaled(bits: Vec<(bool, u64, u64)>, blocks: &mut Vec<f64>) -> i64 {
    let k = bits
        .iter()
        .map(|&(_, top, shift)| shift + u64::from(64 - top.leading_zeros()))
        .max()
        .unwrap_or(0);
    let k = i64::try_from(k).expect("a bit count");
    let top_scale = pow2f(-64);
    for (neg, top, shift) in bits {
        // |B| 2^-k ~ (t 2^-64) 2^(s + 64 - k): t rounded once, the rest exact powers of two
        // (the exponent at most 64, when k < 64).
        let exp = i64::try_from(shift).expect("a bit count") + 64 - k;
        let v = top as f64 * top_scale * pow2f(exp);
        blocks.push(if neg { -v } else { v });
    }
    k
}

/// The conversion of [`f64_coefficients_limbs`] from each number's sign, 64 leading bits `t` and
/// their position `s` (`|B| = t 2^s + r`, `0 <= r < 2^s`, `t >= 2^63` when `s > 0`).
fn f64_of_leading_bits(bits: Vec<(bool, u64, u64)>, blocks: &mut Vec<f64>) -> f64 {
    let start = blocks.len();
    push_scaled(bits, blocks);
    let m = max_abs(&blocks[start..]);
    f64::EPSILON * m * SAFETY
}

/// The largest magnitude among `g` (NaNs ignored: `f64::max`).
fn max_abs(g: &[f64]) -> f64 {
    g.iter().fold(0.0f64, |acc, x| acc.max(x.abs()))
}

fn sign_f64(x: f64) -> Sign {
    if x > 0.0 {
        Sign::Positive
    } else if x < 0.0 {
        Sign::Negative
    } else {
        Sign::Zero
    }
}

/// de Casteljau at `1/2` with the halvings, in place: `b` holds the node's coefficients and
/// becomes the right half's, `left` receives the left half's: `left_k = T^(k)_0`, `right_(n-k)
/// = T^(k)_(n-k)`. Level `k` overwrites `b_0, ..., b_(n-k)` (each entry reads its right
/// neighbour before that one is overwritten, so the loop vectorizes), leaving `b_(n-k+1) =
/// T^(k-1)_(n-k+1)`, the right half's entry, behind; no second row, no copy of the parent.
fn de_casteljau_half(b: &mut [f64], left: &mut [f64]) {
    let n = b.len() - 1;
    debug_assert_eq!(left.len(), n + 1);
    left[0] = b[0];
    for (k, out) in left.iter_mut().enumerate().skip(1) {
        let m = n - k + 1;
        let row = &mut b[..=m];
        for i in 0..m {
            row[i] = 0.5 * (row[i] + row[i + 1]);
        }
        *out = row[0];
    }
}

/// Scales `g` by the power of two that brings its largest magnitude into `[1/2, 1)` when it
/// is below `1/2` (and not so small that the node falls back anyway), and returns `e` scaled
/// alike and the largest magnitude after the scaling. Exact: the factor is at least 1 and no
/// value reaches 1.
fn renormalise(g: &mut [f64], e: f64) -> (f64, f64) {
    let m = max_abs(g);
    if !(m < 0.5 && m >= pow2f(-600)) {
        return (e, m);
    }
    let biased = ((m.to_bits() >> 52) & 0x7ff) as i64;
    // m in [2^(biased - 1023), 2^(biased - 1022)): times 2^(1022 - biased) in [1/2, 1).
    let f = pow2f(1022 - biased);
    for x in g.iter_mut() {
        *x *= f;
    }
    (e * f, m * f)
}

/// The largest number of sign changes of `lo, mid..., hi` (zeros skipped) over every sign
/// (`+`, `-`, `0`) of the entries `x` of `mid` with `|x| <= e`, the others having their own:
/// one pass keeping, per last non-zero sign (none, `+`, `-`), the largest count reaching it.
fn max_variations(lo: Sign, mid: &[f64], e: f64, hi: Sign) -> usize {
    // Every sign certain (the common case; a NaN is not): a plain count, the neighbours'
    // changes read off their sign bits, in loops without branches.
    if mid.iter().fold(true, |ok, x| ok & (x.abs() > e)) {
        return certain_variations(lo, mid, hi);
    }
    max_variations_uncertain(lo, mid, e, hi)
}

/// The sign changes of `lo, mid..., hi` (zeros skipped) when no entry of `mid` is zero.
fn certain_variations(lo: Sign, mid: &[f64], hi: Sign) -> usize {
    let negative = |s: Sign| s == Sign::Negative;
    let (Some(&first), Some(&last)) = (mid.first(), mid.last()) else {
        return usize::from(lo != Sign::Zero && hi != Sign::Zero && lo != hi);
    };
    let inner: usize = mid
        .iter()
        .zip(&mid[1..])
        .map(|(a, b)| ((a.to_bits() ^ b.to_bits()) >> 63) as usize)
        .sum();
    inner
        + usize::from(lo != Sign::Zero && negative(lo) != (first < 0.0))
        + usize::from(hi != Sign::Zero && negative(hi) != (last < 0.0))
}

/// [`max_variations`] when some entry is uncertain.
fn max_variations_uncertain(lo: Sign, mid: &[f64], e: f64, hi: Sign) -> usize {
    /// Index 0: no non-zero sign yet, 1: last `+`, 2: last `-`; `None`: unreachable.
    type State = [Option<usize>; 3];
    fn feed(st: State, s: Sign) -> State {
        let k = match s {
            Sign::Zero => return st,
            Sign::Positive => 1,
            Sign::Negative => 2,
        };
        let best = st
            .iter()
            .enumerate()
            .filter_map(|(from, v)| v.map(|v| v + usize::from(from != 0 && from != k)))
            .max();
        let mut out = [None; 3];
        out[k] = best;
        out
    }
    let mut st = feed([Some(0), None, None], lo);
    for &x in mid {
        st = if x > e {
            feed(st, Sign::Positive)
        } else if x < -e {
            feed(st, Sign::Negative)
        } else {
            // Zero keeps the state; + and - move it.
            let (p, q) = (feed(st, Sign::Positive), feed(st, Sign::Negative));
            [0, 1, 2].map(|i| st[i].max(p[i]).max(q[i]))
        };
    }
    feed(st, hi)
        .into_iter()
        .flatten()
        .max()
        .expect("a state is always reachable")
}

/// The exact sign of `p(m / 2^k)`: the sign of `sum a_i m^i 2^(k(n-i))` (Horner on big
/// integers).
fn sign_at_dyadic(p: &[BigInt], m: &BigInt, k: u64) -> Sign {
    let n = p.len() - 1;
    let mut v = p[n].clone();
    for (i, a) in p[..n].iter().enumerate().rev() {
        v = v * m + (a << (k * (n - i) as u64));
    }
    sign_of(&v)
}

#[cfg(test)]
mod tests;
