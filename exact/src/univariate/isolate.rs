//! Isolating intervals in the canonical bisection shape (the Descartes isolator's roots laid out
//! on the dyadic bisection of `(-B, B)`), counts of roots, refinement and comparisons of
//! isolating intervals, sign charts (on the production isolator, [`isolate_real_roots`]), and
//! the root intervals themselves.
//!
//! # The bisection shape
//! [`UPoly::isolate_roots`] answers with the intervals the Sturm bisection would find (module
//! `sturm`, the reference): a node of the bisection of `(-B, B)`, `B` a power of two above
//! Cauchy's bound, that holds exactly one root, narrowed below `1 / (2 l)` and tested for a
//! rational root ([`exactify`]). The shape depends only on the polynomial, not on how the roots
//! were found, so the intervals printed with algebraic numbers (`Root(f, lo, hi)`) stay the same
//! whichever isolator runs. The roots come from the Descartes isolator; the number of roots in a
//! node is read off by comparing each root with the midpoint (one sign of `p` at most, and none
//! once the root's own interval lies on one side), which narrows the root's interval as the
//! bisection descends. No Sturm chain is computed.

use super::*;
use std::cmp::Ordering;
use std::fmt;

// ------------------------------------------------------------------------------ bisection

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

/// A power of two strictly above Cauchy's bound `1 + max |a_i / a_n|` of the non-constant `p`:
/// every real root lies strictly inside `(-b, b)`.
pub(super) fn bisection_bound(p: &UPoly) -> Rational {
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

/// `ri`, an isolating interval of a root of `p` (primitive, square-free, positive leading
/// coefficient `l`), made exact if its root is rational and otherwise narrowed below `1 / (2 l)`:
/// a rational root `k / l` (rational root theorem) is then the one candidate in the narrowed
/// interval, evaluated exactly. The narrowing is the quadratic refinement of [`refine_simple`]
/// (bisection would need `log2 l` steps, thousands for coefficients of a thousand digits).
pub(super) fn exactify(p: &UPoly, ri: RootInterval) -> RootInterval {
    if ri.is_exact() {
        return ri;
    }
    let l = p.leading_coefficient();
    let narrow = refine_simple(
        p,
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

/// The real roots of a primitive square-free polynomial with a positive leading coefficient, as
/// the Descartes isolator finds them, each interval narrowed in place as the root is compared
/// with rational points.
struct Located<'a> {
    p: &'a UPoly,
    roots: Vec<RootInterval>,
    /// The sign of `p` just below each root: all roots are simple and `p` is positive beyond the
    /// last, so below root `i` of `k` it is `(-1)^(k - i)`.
    below: Vec<Sign>,
}

impl<'a> Located<'a> {
    /// For `p` of degree at least 1 and at most [`MAX_DESCARTES_DEGREE`].
    fn new(p: &'a UPoly) -> Located<'a> {
        let roots = p.real_roots_descartes();
        let k = roots.len();
        let below = (0..k)
            .map(|i| {
                if (k - i) % 2 == 0 {
                    Sign::Positive
                } else {
                    Sign::Negative
                }
            })
            .collect();
        Located { p, roots, below }
    }

    /// `x` compared with root `i` (`Less`: `x` is below the root). An open interval is cut at
    /// `x` to the side holding the root, or made the point `x` when `x` is the root.
    fn compare(&mut self, i: usize, x: &Rational) -> Ordering {
        let ri = &mut self.roots[i];
        if ri.is_exact() {
            return x.cmp(&ri.lo);
        }
        if *x <= ri.lo {
            return Ordering::Less;
        }
        if *x >= ri.hi {
            return Ordering::Greater;
        }
        let s = self.p.sign_at(x);
        if s == Sign::Zero {
            *ri = RootInterval::exact(x.clone());
            Ordering::Equal
        } else if s == self.below[i] {
            ri.lo = x.clone();
            Ordering::Less
        } else {
            ri.hi = x.clone();
            Ordering::Greater
        }
    }
}

/// The isolating intervals of the bisection shape (module documentation) of the roots of `p`,
/// primitive, square-free, with a positive leading coefficient and of degree at least 1 and at
/// most [`MAX_DESCARTES_DEGREE`]: the intervals of the Sturm reference, each node's count taken
/// from the located roots instead of a Sturm chain.
fn bisection_intervals(p: &UPoly) -> Vec<RootInterval> {
    let mut roots = Located::new(p);
    let b = bisection_bound(p);
    let mut out = Vec::with_capacity(roots.roots.len());
    // (a, c, the roots in the open interval (a, c)); a and c are never roots.
    let mut stack = vec![(b.neg_ref(), b, (0..roots.roots.len()).collect::<Vec<_>>())];
    while let Some((a, c, inside)) = stack.pop() {
        match inside[..] {
            [] => {}
            [i] if roots.roots[i].is_exact() => out.push(roots.roots[i].clone()),
            [_] => out.push(exactify(p, RootInterval { lo: a, hi: c })),
            _ => {
                let m = midpoint(&a, &c);
                let (mut below, mut above, mut at_m) = (Vec::new(), Vec::new(), false);
                for i in inside {
                    match roots.compare(i, &m) {
                        Ordering::Less => above.push(i),
                        Ordering::Greater => below.push(i),
                        Ordering::Equal => at_m = true,
                    }
                }
                if !at_m {
                    stack.push((m.clone(), c, above));
                    stack.push((a, m, below));
                    continue;
                }
                // The midpoint is a root: record it exactly, and split at `ml < m < mr` close
                // enough that `[ml, mr]` holds no other root (the Sturm reference's choice).
                out.push(RootInterval::exact(m.clone()));
                let mut d = c.sub_ref(&m).mul_ref(&half());
                let (ml, mr) = loop {
                    let (ml, mr) = (m.sub_ref(&d), m.add_ref(&d));
                    if below
                        .iter()
                        .all(|&j| roots.compare(j, &ml) == Ordering::Greater)
                        && above
                            .iter()
                            .all(|&j| roots.compare(j, &mr) == Ordering::Less)
                    {
                        break (ml, mr);
                    }
                    d *= half();
                };
                stack.push((mr, c, above));
                stack.push((a, ml, below));
            }
        }
    }
    out.sort_by(|x, y| x.lo.cmp(&y.lo).then_with(|| x.hi.cmp(&y.hi)));
    out
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
pub(crate) fn compare_simple(p: &UPoly, ri: &RootInterval, x: &Rational) -> Ordering {
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
    /// The number of **distinct** real roots in the half-open interval `(lo, hi]` (0 when
    /// `lo >= hi`, and for the zero polynomial, whose roots are not isolated): the roots of the
    /// Descartes isolator compared with `lo` and `hi`.
    pub fn count_roots(&self, lo: &Rational, hi: &Rational) -> usize {
        if self.is_constant() || lo >= hi {
            return 0;
        }
        if self.degree() > MAX_DESCARTES_DEGREE {
            return sturm::SquareFree::new(self).count(lo, hi);
        }
        let p = self.primitive_square_free_part();
        let mut roots = Located::new(&p);
        (0..roots.roots.len())
            .filter(|&i| {
                roots.compare(i, lo) == Ordering::Less && roots.compare(i, hi) != Ordering::Less
            })
            .count()
    }

    /// The number of distinct real roots (0 for constants and for the zero polynomial): the
    /// Descartes isolator's.
    pub fn count_real_roots(&self) -> usize {
        if self.is_constant() {
            return 0;
        }
        if self.degree() > MAX_DESCARTES_DEGREE {
            return sturm::SquareFree::new(self).count_all();
        }
        self.real_roots_descartes().len()
    }

    /// Isolating intervals of all distinct real roots in the bisection shape (module
    /// documentation of `isolate`): sorted, pairwise disjoint, each holding exactly one root;
    /// exact (`lo == hi`) **exactly when the root is rational**; the same intervals as the
    /// Sturm reference ([`isolate_real_roots_sturm`]), found by the Descartes isolator. Empty
    /// for constants and for the zero polynomial.
    pub fn isolate_roots(&self) -> Vec<RootInterval> {
        if self.is_constant() {
            return Vec::new();
        }
        if self.degree() > MAX_DESCARTES_DEGREE {
            return isolate_real_roots_sturm(self);
        }
        bisection_intervals(&self.primitive_square_free_part())
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
    /// A [`LimitError`](exactcheck_core::limits::LimitError) of `bisection` when more halvings than the limit would be needed.
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
        sign_chart_from(self.roots(), self.sign_at_pos_inf())
    }

    /// The set `{x in R : self(x) >= 0}` as a union of disjoint closed intervals, increasing:
    /// the whole line for zero and for positive constants, empty for negative constants;
    /// isolated points (touching points, [`UPoly::touching_points`]) are degenerate intervals
    /// with `lo == hi`.
    pub fn nonnegative_set(&self) -> Vec<RootBoundedInterval> {
        if self.is_zero() {
            return vec![RootBoundedInterval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            }];
        }
        nonnegative_in_chart(self.sign_chart())
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
    /// constants included) or a real root of odd multiplicity (a sign change): the product of the
    /// odd-multiplicity factors of the square-free decomposition is tested for real roots
    /// ([`UPoly::count_real_roots`]).
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

/// The sign chart of a non-zero polynomial from its distinct real roots (increasing, with
/// multiplicities) and its sign at `+inf`: the sign flips across a root of odd multiplicity.
/// Shared by [`UPoly::sign_chart`] and the polynomials over a number field, whose roots are
/// found differently but whose chart follows the same way.
pub(crate) fn sign_chart_from(roots: Vec<Root>, at_pos_inf: Sign) -> SignChart {
    let mut gaps = vec![Sign::Zero; roots.len() + 1];
    let mut s = at_pos_inf;
    gaps[roots.len()] = s;
    for (i, r) in roots.iter().enumerate().rev() {
        if r.multiplicity % 2 == 1 {
            s = sign_neg(s);
        }
        gaps[i] = s;
    }
    SignChart { roots, gaps }
}

/// The set where a non-zero polynomial is `>= 0`, from its sign chart (see
/// [`UPoly::nonnegative_set`]).
pub(crate) fn nonnegative_in_chart(chart: SignChart) -> Vec<RootBoundedInterval> {
    let SignChart { roots, gaps } = chart;
    let mut out = Vec::new();
    let mut start = (gaps[0] == Sign::Positive).then_some(Bound::NegInf);
    for (i, r) in roots.into_iter().enumerate() {
        let start_here = start
            .take()
            .unwrap_or_else(|| Bound::Root(r.interval.clone()));
        if gaps[i + 1] == Sign::Positive {
            start = Some(start_here);
        } else {
            out.push(RootBoundedInterval {
                lo: start_here,
                hi: Bound::Root(r.interval),
            });
        }
    }
    if let Some(lo) = start {
        out.push(RootBoundedInterval {
            lo,
            hi: Bound::PosInf,
        });
    }
    out
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

impl fmt::Display for RootBoundedInterval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{}, {}]", self.lo, self.hi)
    }
}

impl RootBoundedInterval {
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
