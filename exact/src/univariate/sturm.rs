//! Sturm sequences, and the reference isolator built on them: bisection of `(-B, B)` driven by
//! Sturm counts. Production isolates by Descartes' rule (module `descartes`) and lays the
//! intervals out in the same bisection shape without Sturm chains (module `isolate`); this
//! isolator is what the tests compare both with ([`super::isolate_real_roots_sturm`]), and the
//! fallback beyond [`MAX_DESCARTES_DEGREE`], where the Descartes isolator refuses.

use super::isolate::{bisection_bound, count_variations, exactify};
use super::*;

/// The Sturm sequence of a non-zero polynomial, normalised to primitive parts after `p`.
fn sturm_chain(p: &UPoly) -> Vec<UPoly> {
    let mut seq = vec![p.clone()];
    let d = p.derivative();
    if d.is_zero() {
        return seq;
    }
    seq.push(d.primitive_part());
    loop {
        let n = seq.len();
        let r = seq[n - 2].rem(&seq[n - 1]);
        if r.is_zero() {
            return seq;
        }
        seq.push(r.neg_impl().primitive_part());
    }
}

/// The number of sign variations of a Sturm sequence at `x`.
pub fn sign_variations(seq: &[UPoly], x: &Rational) -> usize {
    count_variations(seq.iter().map(|p| p.sign_at(x)))
}

/// The square-free part of a polynomial prepared for root finding: primitive, positive leading
/// coefficient, with its Sturm chain.
pub(super) struct SquareFree {
    chain: Vec<UPoly>,
}

impl SquareFree {
    /// For a non-zero polynomial.
    pub(super) fn new(p: &UPoly) -> SquareFree {
        let sqf = p.square_free_part().primitive_part();
        SquareFree {
            chain: sturm_chain(&sqf),
        }
    }

    fn poly(&self) -> &UPoly {
        &self.chain[0]
    }

    /// The number of distinct roots in `(lo, hi]` (`lo < hi`): `V(lo) - V(hi)`.
    pub(super) fn count(&self, lo: &Rational, hi: &Rational) -> usize {
        self.var_at(lo) - self.var_at(hi)
    }

    /// The number of distinct real roots.
    pub(super) fn count_all(&self) -> usize {
        self.var_neg_inf() - self.var_pos_inf()
    }

    fn var_neg_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_neg_inf))
    }

    fn var_pos_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_pos_inf))
    }

    fn var_at(&self, x: &Rational) -> usize {
        sign_variations(&self.chain, x)
    }

    /// Isolating intervals of all real roots, sorted; rational roots exact. The bisection of
    /// `(-B, B)` ([`bisection_bound`]): a node with one root is a leaf, made exact or narrowed
    /// by [`exactify`]; a midpoint that is a root is recorded exactly and the bisection
    /// continues from non-roots on either side of it (so no interval ever ends at a root).
    pub(super) fn isolate(&self) -> Vec<RootInterval> {
        let p = self.poly();
        if p.is_constant() {
            return Vec::new();
        }
        let b = bisection_bound(p);
        let lo = b.neg_ref();
        let (vlo, vhi) = (self.var_neg_inf(), self.var_pos_inf());
        let mut out = Vec::new();
        // (a, b, V(a), V(b), number of roots in the open interval); endpoints are never roots.
        let mut stack = vec![(lo, b, vlo, vhi, vlo - vhi)];
        while let Some((a, c, va, vc, count)) = stack.pop() {
            match count {
                0 => {}
                1 => out.push(RootInterval { lo: a, hi: c }),
                _ => {
                    let m = midpoint(&a, &c);
                    let vm = self.var_at(&m);
                    if p.sign_at(&m) != Sign::Zero {
                        stack.push((m.clone(), c, vm, vc, vm - vc));
                        stack.push((a, m, va, vm, va - vm));
                        continue;
                    }
                    // The midpoint is a root: record it exactly, and split at non-roots `ml < m <
                    // mr` close enough that `[ml, mr]` holds no other root. (`V(m)` ignores the
                    // zero at `m`, so it counts the roots in `(m, +inf)`.)
                    out.push(RootInterval::exact(m.clone()));
                    let mut d = c.sub_ref(&m).mul_ref(&half());
                    let (ml, vml, mr, vmr) = loop {
                        let (ml, mr) = (m.sub_ref(&d), m.add_ref(&d));
                        if p.sign_at(&ml) != Sign::Zero && p.sign_at(&mr) != Sign::Zero {
                            let (vml, vmr) = (self.var_at(&ml), self.var_at(&mr));
                            if vml - vmr == 1 {
                                break (ml, vml, mr, vmr);
                            }
                        }
                        d *= half();
                    };
                    stack.push((mr, c, vmr, vc, vmr - vc));
                    stack.push((a, ml, va, vml, va - vml));
                }
            }
        }
        out.sort_by(|x, y| x.lo.cmp(&y.lo).then_with(|| x.hi.cmp(&y.hi)));
        out.into_iter().map(|ri| exactify(p, ri)).collect()
    }
}

impl UPoly {
    /// The Sturm sequence of `self`: `self`, its derivative, then the negated remainders of
    /// Euclid's algorithm, each after the first replaced by its primitive part (a positive
    /// multiple, so the sign variations are those of the classical sequence). Its last element
    /// is `gcd(self, self')` up to a constant. Empty for the zero polynomial.
    pub fn sturm_sequence(&self) -> Vec<UPoly> {
        if self.is_zero() {
            return Vec::new();
        }
        sturm_chain(self)
    }
}
