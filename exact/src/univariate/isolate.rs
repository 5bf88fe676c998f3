//! Real root isolation by Sturm chains (bisection driven by Sturm counts, exact rational roots:
//! the reference of the tests), refinement and comparisons of isolating intervals, sign charts
//! (on the production isolator, [`isolate_real_roots`]), and the root intervals themselves.

use super::*;
use std::cmp::Ordering;
use std::fmt;

// ------------------------------------------------------------------------------ Sturm chains

/// The Sturm sequence of a non-zero polynomial, normalised to primitive parts after `p`.
pub(super) fn sturm_chain(p: &UPoly) -> Vec<UPoly> {
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

/// Number of sign changes of a sequence of signs, zeros skipped.
pub(super) fn count_variations(signs: impl IntoIterator<Item = Sign>) -> usize {
    let mut last = Sign::Zero;
    let mut n = 0;
    for s in signs {
        if s == Sign::Zero {
            continue;
        }
        if last != Sign::Zero && s != last {
            n += 1;
        }
        last = s;
    }
    n
}

/// The number of sign variations of a Sturm sequence at `x`.
pub fn sign_variations(seq: &[UPoly], x: &Rational) -> usize {
    count_variations(seq.iter().map(|p| p.sign_at(x)))
}

/// The square-free part of a polynomial prepared for root finding: primitive, positive leading
/// coefficient, with its Sturm chain.
pub(super) struct SquareFree {
    pub(super) chain: Vec<UPoly>,
}

impl SquareFree {
    /// For a non-zero polynomial.
    pub(super) fn new(p: &UPoly) -> SquareFree {
        let sqf = p.square_free_part().primitive_part();
        SquareFree {
            chain: sturm_chain(&sqf),
        }
    }

    pub(super) fn poly(&self) -> &UPoly {
        &self.chain[0]
    }

    pub(super) fn var_at(&self, x: &Rational) -> usize {
        sign_variations(&self.chain, x)
    }

    pub(super) fn var_neg_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_neg_inf))
    }

    pub(super) fn var_pos_inf(&self) -> usize {
        count_variations(self.chain.iter().map(UPoly::sign_at_pos_inf))
    }

    /// A power of two strictly above Cauchy's bound `1 + max |a_i / a_n|`: every real root lies
    /// strictly inside `(-b, b)`.
    pub(super) fn root_bound(&self) -> Rational {
        let p = self.poly();
        let lc = p.leading_coefficient();
        let lc_abs = if lc.signum() == Sign::Negative {
            -lc
        } else {
            lc
        };
        let mut m = Rational::ZERO;
        for c in &p.coeffs[..p.coeffs.len() - 1] {
            let a = if c.signum() == Sign::Negative {
                c.neg_ref()
            } else {
                c.clone()
            };
            if a > m {
                m = a;
            }
        }
        let bound = Rational::ONE + m / lc_abs;
        let mut b = Rational::ONE;
        let two = Rational::from_integer(2);
        while b <= bound {
            b *= &two;
        }
        b
    }

    /// Isolating intervals of all real roots, sorted; rational roots exact.
    pub(super) fn isolate(&self) -> Vec<RootInterval> {
        let p = self.poly();
        if p.is_constant() {
            return Vec::new();
        }
        let b = self.root_bound();
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
                    // mr` close enough that `[ml, mr]` holds no other root, so that no interval
                    // ever has a root as an end. (`V(m)` ignores the zero at `m`, so it counts
                    // the roots in `(m, +inf)`.)
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
        out.into_iter().map(|ri| self.exactify(ri)).collect()
    }

    /// Makes the interval exact if its root is rational (see the module documentation).
    pub(super) fn exactify(&self, ri: RootInterval) -> RootInterval {
        if ri.is_exact() {
            return ri;
        }
        let p = self.poly();
        let l = p.leading_coefficient(); // a positive integer
                                         // Narrow the interval below 1/l by quadratic refinement (`refine`): bisection needed
                                         // log2(l) steps, thousands for coefficients of a thousand digits.
        let narrow = self.refine(
            &ri,
            &(Rational::ONE / l.mul_ref(&Rational::from_integer(2))),
        );
        if narrow.is_exact() {
            return narrow;
        }
        let RootInterval { lo, hi } = narrow;
        // At most one integer k with lo * l < k < hi * l.
        let k = floor(&lo.mul_ref(&l)) + 1;
        let cand = Rational::from(k) / &l;
        if cand < hi && p.sign_at(&cand) == Sign::Zero {
            return RootInterval::exact(cand);
        }
        RootInterval { lo, hi }
    }

    /// Refines an isolating interval to width at most `width` ([`refine_simple`]).
    pub(super) fn refine(&self, ri: &RootInterval, width: &Rational) -> RootInterval {
        refine_simple(self.poly(), ri, width)
    }
}

/// Refines `ri`, an isolating interval of a root of the square-free `p`, to width at most
/// `width`: Abbott's quadratic interval refinement on the sign of `p`, which changes across the
/// root (`exactcheck_core::roots::refine_isolating_with`, rounding to the nearest integer).
///
/// # Panics
/// When `ri` is not exact and `p` has no opposite non-zero signs at its ends, or when
/// `width <= 0` and the interval is wider than that.
pub(super) fn refine_simple(p: &UPoly, ri: &RootInterval, width: &Rational) -> RootInterval {
    if ri.is_exact() {
        return ri.clone();
    }
    let s_lo = p.sign_at(&ri.lo);
    let s_hi = p.sign_at(&ri.hi);
    assert!(
        s_lo != Sign::Zero && s_hi == sign_neg(s_lo),
        "UPoly::refine: {ri} is not an isolating interval of a root of this polynomial"
    );
    if ri.width() <= *width {
        return ri.clone();
    }
    assert!(
        width.signum() == Sign::Positive,
        "UPoly::refine: the width must be positive"
    );
    match exactcheck_core::roots::refine_isolating_with(
        |x| p.eval(x),
        |x| Some(Rational::from(floor(&(x.add_ref(&half()))))),
        ri.lo.clone(),
        ri.hi.clone(),
        width,
    ) {
        IsolatedRoot::Exact(r) => RootInterval::exact(r),
        IsolatedRoot::Between(lo, hi) => RootInterval { lo, hi },
    }
}

/// `x` compared with the root of the square-free `p` isolated by `ri`: the sign of `p` changes
/// across that root only.
pub(super) fn compare_simple(p: &UPoly, ri: &RootInterval, x: &Rational) -> Ordering {
    if ri.is_exact() {
        return x.cmp(&ri.lo);
    }
    if *x <= ri.lo {
        return Ordering::Less;
    }
    if *x >= ri.hi {
        return Ordering::Greater;
    }
    match p.sign_at(x) {
        Sign::Zero => Ordering::Equal,
        s if s == p.sign_at(&ri.lo) => Ordering::Less,
        _ => Ordering::Greater,
    }
}

// ------------------------------------------------------------------------------ root finding

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

    /// The number of **distinct** real roots in the half-open interval `(lo, hi]` (0 when
    /// `lo >= hi`, and for the zero polynomial, whose roots are not isolated).
    pub fn count_roots(&self, lo: &Rational, hi: &Rational) -> usize {
        if self.is_zero() || lo >= hi {
            return 0;
        }
        let s = SquareFree::new(self);
        s.var_at(lo) - s.var_at(hi)
    }

    /// The number of distinct real roots (0 for the zero polynomial).
    pub fn count_real_roots(&self) -> usize {
        if self.is_constant() {
            return 0;
        }
        let s = SquareFree::new(self);
        s.var_neg_inf() - s.var_pos_inf()
    }

    /// Isolating intervals of all distinct real roots: sorted, pairwise disjoint, each holding
    /// exactly one root; exact (`lo == hi`) **exactly when the root is rational**. Empty for
    /// constants and for the zero polynomial.
    pub fn isolate_roots(&self) -> Vec<RootInterval> {
        if self.is_constant() {
            return Vec::new();
        }
        SquareFree::new(self).isolate()
    }

    /// The distinct real roots with their multiplicities, increasing: the intervals of
    /// [`isolate_real_roots`] (Descartes' rule; exact exactly when the root is rational), each
    /// root's multiplicity read off the square-free decomposition.
    pub fn roots(&self) -> Vec<Root> {
        if self.is_constant() {
            return Vec::new();
        }
        let intervals = isolate_real_roots(self);
        let factors = self.square_free_decomposition();
        intervals
            .into_iter()
            .map(|interval| {
                let multiplicity = multiplicity_in(&factors, &interval);
                Root {
                    interval,
                    multiplicity,
                }
            })
            .collect()
    }

    /// The multiplicity of the root isolated by `ri` (an interval from [`UPoly::isolate_roots`]
    /// of this polynomial, or any interval satisfying the [`RootInterval`] contract); 0 if `ri`
    /// holds no root.
    pub fn multiplicity(&self, ri: &RootInterval) -> u32 {
        multiplicity_in(&self.square_free_decomposition(), ri)
    }

    /// A refinement of the isolating interval `ri` of width at most `width`, containing the same
    /// root (exact if a bisection point hits it).
    ///
    /// # Panics
    /// When `ri` is not exact and its endpoints are not of opposite signs for the square-free
    /// part of `self` (so it does not isolate one of its roots, e.g. for the zero polynomial), or
    /// when `width <= 0` and the interval is not exact.
    pub fn refine(&self, ri: &RootInterval, width: &Rational) -> RootInterval {
        if ri.is_exact() {
            return ri.clone();
        }
        assert!(!self.is_zero(), "UPoly::refine: the zero polynomial");
        refine_simple(&self.primitive_square_free_part(), ri, width)
    }

    /// [`UPoly::refine`] within the `bisection` limit: the halvings from the width of `ri` down
    /// to `width` (an upper bound on the refinement steps) are checked before any work.
    ///
    /// # Errors
    /// A [`LimitError`] of `bisection` when more halvings than the limit would be needed.
    ///
    /// # Panics
    /// As [`UPoly::refine`].
    pub fn try_refine(
        &self,
        ri: &RootInterval,
        width: &Rational,
    ) -> Result<RootInterval, exactcheck_core::limits::LimitError> {
        if !ri.is_exact() && width.signum() == Sign::Positive {
            exactcheck_core::roots::halvings_within_limit(&ri.width(), width)?;
        }
        Ok(self.refine(ri, width))
    }

    /// The rational `x` compared with the root isolated by `ri` (an isolating interval of a root
    /// of `self`): `Less` when `x` is below the root.
    pub fn compare_with_root(&self, ri: &RootInterval, x: &Rational) -> Ordering {
        if ri.is_exact() || self.is_zero() {
            return x.cmp(&ri.lo);
        }
        compare_simple(&self.primitive_square_free_part(), ri, x)
    }

    /// The roots with multiplicities and the sign on every gap between them (see
    /// [`SignChart`]). The gap signs follow from the sign at `+inf` and the parity of the
    /// multiplicities.
    pub fn sign_chart(&self) -> SignChart {
        let roots = self.roots();
        let mut gaps = vec![Sign::Zero; roots.len() + 1];
        let mut s = self.sign_at_pos_inf();
        gaps[roots.len()] = s;
        for (i, r) in roots.iter().enumerate().rev() {
            if r.multiplicity % 2 == 1 {
                s = sign_neg(s);
            }
            gaps[i] = s;
        }
        SignChart { roots, gaps }
    }

    /// The set `{x in R : self(x) >= 0}` as a union of disjoint closed intervals, increasing:
    /// the whole line for zero and for positive constants, empty for negative constants;
    /// isolated points (touching points, [`UPoly::touching_points`]) are degenerate intervals
    /// with `lo == hi`.
    pub fn nonnegative_set(&self) -> Vec<Interval> {
        let SignChart { roots, gaps } = self.sign_chart();
        let mut out = Vec::new();
        if self.is_zero() {
            out.push(Interval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            });
            return out;
        }
        let mut start = (gaps[0] == Sign::Positive).then_some(Bound::NegInf);
        for (i, r) in roots.into_iter().enumerate() {
            let start_here = start
                .take()
                .unwrap_or_else(|| Bound::Root(r.interval.clone()));
            if gaps[i + 1] == Sign::Positive {
                start = Some(start_here);
            } else {
                out.push(Interval {
                    lo: start_here,
                    hi: Bound::Root(r.interval),
                });
            }
        }
        if let Some(lo) = start {
            out.push(Interval {
                lo,
                hi: Bound::PosInf,
            });
        }
        out
    }

    /// The touching points: roots where `self <= 0` on both sides (necessarily of even
    /// multiplicity), i.e. the isolated points of [`UPoly::nonnegative_set`]. For the claim list's
    /// discriminant they are the tangencies of the two surfaces.
    pub fn touching_points(&self) -> Vec<Root> {
        let SignChart { roots, gaps } = self.sign_chart();
        roots
            .into_iter()
            .enumerate()
            .filter(|(i, _)| gaps[*i] == Sign::Negative && gaps[i + 1] == Sign::Negative)
            .map(|(_, r)| r)
            .collect()
    }

    /// Whether `self(x) > 0` for some real `x`: a positive leading coefficient (positive
    /// constants included) or a real root of odd multiplicity (a sign change). No isolation is
    /// needed: the odd-multiplicity factors of the square-free decomposition are tested for real
    /// roots by a Sturm count.
    pub fn positive_somewhere(&self) -> bool {
        if self.sign_at_pos_inf() == Sign::Positive {
            return true;
        }
        if self.is_constant() {
            return false;
        }
        let odd = self
            .square_free_decomposition()
            .into_iter()
            .filter(|(_, i)| i % 2 == 1)
            .fold(UPoly::one(), |acc, (f, _)| acc.mul_impl(&f));
        odd.count_real_roots() > 0
    }

    /// Whether `self(x) >= 0` for some real `x`: zero, a positive leading coefficient, or any
    /// real root.
    pub fn nonnegative_somewhere(&self) -> bool {
        if self.is_zero() || self.sign_at_pos_inf() == Sign::Positive {
            return true;
        }
        self.count_real_roots() > 0
    }
}

/// The multiplicity of the root isolated by `ri` from a square-free decomposition.
pub(super) fn multiplicity_in(factors: &[(UPoly, u32)], ri: &RootInterval) -> u32 {
    for (f, i) in factors {
        let holds = if ri.is_exact() {
            f.sign_at(&ri.lo) == Sign::Zero
        } else {
            // f is square-free and divides the square-free part: it changes sign across the
            // root exactly when the root is one of its own.
            f.sign_at(&ri.lo) * f.sign_at(&ri.hi) == Sign::Negative
        };
        if holds {
            return *i;
        }
    }
    0
}

// ------------------------------------------------------------------------------ intervals

impl RootInterval {
    /// The exact root `r` (`lo == hi == r`).
    pub fn exact(r: Rational) -> RootInterval {
        RootInterval {
            lo: r.clone(),
            hi: r,
        }
    }

    /// Whether the root is given exactly (`lo == hi`).
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }

    /// The root, when it is given exactly.
    pub fn exact_value(&self) -> Option<&Rational> {
        self.is_exact().then_some(&self.lo)
    }

    /// `hi - lo`.
    pub fn width(&self) -> Rational {
        self.hi.sub_ref(&self.lo)
    }

    /// `(lo + hi) / 2`.
    pub fn midpoint(&self) -> Rational {
        midpoint(&self.lo, &self.hi)
    }

    /// A floating-point approximation of the midpoint, **for display only**.
    pub fn to_f64(&self) -> f64 {
        self.midpoint().to_f64()
    }
}

impl fmt::Display for RootInterval {
    /// `r` for an exact root, `(lo, hi)` otherwise.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_exact() {
            write!(f, "{}", self.lo)
        } else {
            write!(f, "({}, {})", self.lo, self.hi)
        }
    }
}

impl fmt::Debug for RootInterval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self} ~ {}", self.to_f64())
    }
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Bound::NegInf => f.write_str("-inf"),
            Bound::PosInf => f.write_str("+inf"),
            Bound::Root(r) if r.is_exact() => write!(f, "{r}"),
            Bound::Root(r) => write!(f, "root in {r}"),
        }
    }
}

impl Bound {
    /// A floating-point approximation (infinities included), **for display only**.
    pub fn to_f64(&self) -> f64 {
        match self {
            Bound::NegInf => f64::NEG_INFINITY,
            Bound::PosInf => f64::INFINITY,
            Bound::Root(r) => r.to_f64(),
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{}, {}]", self.lo, self.hi)
    }
}

impl Interval {
    /// Whether the interval is a single point (both ends the same root).
    pub fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    /// Whether the rational `x` lies in the interval; `poly` is the polynomial whose roots the
    /// finite ends are (the one [`UPoly::nonnegative_set`] was called on).
    pub fn contains(&self, poly: &UPoly, x: &Rational) -> bool {
        let above_lo = match &self.lo {
            Bound::NegInf => true,
            Bound::PosInf => false,
            Bound::Root(r) => poly.compare_with_root(r, x) != Ordering::Less,
        };
        let below_hi = match &self.hi {
            Bound::NegInf => false,
            Bound::PosInf => true,
            Bound::Root(r) => poly.compare_with_root(r, x) != Ordering::Greater,
        };
        above_lo && below_hi
    }
}
