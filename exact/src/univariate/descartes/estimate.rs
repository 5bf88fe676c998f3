//! Root estimates of subdivision leaves and the recognition of rational roots (the parent
//! module's documentation, "Rational roots"): `f64` estimates from a leaf's Bernstein
//! coefficients, their continued-fraction convergents as candidates, and the exact test that
//! a linear factor divides the polynomial.

use super::*;

/// An estimate `num / 2^exp + off` of a root of a unit problem: an exact dyadic (a node's end,
/// or a pair's split point) and an `f64` offset (the leaf's estimate within its node, or the
/// pair's half-distance), kept apart so that a root recognised as rational never pays for the
/// exact rational ([`UnitEstimate::to_rational`] is called only by the refinement).
#[derive(Clone, Debug)]
pub(super) struct UnitEstimate {
    pub(super) num: BigInt,
    pub(super) exp: u64,
    pub(super) off: f64,
    /// A leaf's iteration stopped at its coarse point (`off` is `t 2^-exp` for that point's
    /// `t`), to be resumed by [`UnitEstimate::sharpened`]; `None` when `off` is final.
    pub(super) newton: Option<Box<LeafNewton>>,
}

impl UnitEstimate {
    /// The estimate of the leaf `(c / 2^j, (c + 1) / 2^j)` from its Bernstein coefficients `g`
    /// in `f64` (any common positive scale): the iteration of [`bernstein_root_estimate`]
    /// stopped at its coarse point ([`COARSE_CORRECTION`]) when it gets there before the end.
    pub(super) fn of_leaf(c: &BigInt, j: u64, g: Vec<f64>, binoms: &[f64]) -> Option<UnitEstimate> {
        let (t, newton) = match LeafNewton::start(g, binoms) {
            Err(t) => (t?, None),
            Ok(mut newton) => match newton.run(COARSE_CORRECTION) {
                NewtonStop::Coarse(t) => (t, Some(Box::new(newton))),
                NewtonStop::Done(t) => (t?, None),
            },
        };
        Some(UnitEstimate {
            num: c.clone(),
            exp: j,
            off: t * pow2f(-(j.min(2000) as i64)),
            newton,
        })
    }

    /// Whether the estimate is a leaf's coarse point.
    pub(super) fn is_coarse(&self) -> bool {
        self.newton.is_some()
    }

    /// The final estimate: a coarse point's iteration run to its end (`None` when it ends
    /// without one, as [`bernstein_root_estimate`] would have).
    pub(super) fn sharpened(mut self) -> Option<UnitEstimate> {
        if let Some(mut newton) = self.newton.take() {
            let t = loop {
                if let NewtonStop::Done(t) = newton.run(0.0) {
                    break t;
                }
            }?;
            self.off = t * pow2f(-(self.exp.min(2000) as i64));
        }
        Some(self)
    }

    /// The value in `f64` (approximately).
    pub(super) fn to_f64(&self) -> f64 {
        let base = match approx(&self.num) {
            None => 0.0,
            Some((m, e)) => m * pow2f(e.saturating_sub(self.exp as i64)),
        };
        base + self.off
    }

    /// The exact value (`None` when the offset is not finite).
    pub(super) fn to_rational(&self) -> Option<Rational> {
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
pub(super) struct Estimate {
    pub(super) unit: UnitEstimate,
    pub(super) which: usize,
}

impl Estimate {
    pub(super) fn map_f64(&self, x: f64) -> f64 {
        match self.which {
            0 => x,
            1 => 1.0 / x,
            2 => -x,
            _ => -1.0 / x,
        }
    }

    /// Whether the estimate is a leaf's coarse point ([`UnitEstimate::is_coarse`]).
    pub(super) fn is_coarse(&self) -> bool {
        self.unit.is_coarse()
    }

    /// The final estimate ([`UnitEstimate::sharpened`]).
    pub(super) fn sharpened(self) -> Option<Estimate> {
        let which = self.which;
        self.unit.sharpened().map(|unit| Estimate { unit, which })
    }

    /// The estimate in `f64` (for the rational-root candidates).
    pub(super) fn to_f64(&self) -> f64 {
        self.map_f64(self.unit.to_f64())
    }

    /// The exact estimate (for the refinement's first window); `None` at zero.
    pub(super) fn to_rational(&self) -> Option<Rational> {
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
pub(super) fn rational_of_f64(x: f64) -> Option<Rational> {
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
pub(super) fn f64_shift(cs: &[BigInt]) -> u64 {
    cs.iter()
        .map(BigInt::bits)
        .max()
        .unwrap_or(0)
        .saturating_sub(60)
}

pub(super) fn scaled_f64(x: &BigInt, shift: u64) -> f64 {
    match approx(x) {
        None => 0.0,
        Some((m, e)) => m * pow2f(e - shift as i64),
    }
}

/// `C(n, i)` for `i = 0..=n` in `f64` by the recurrence `C(n, i + 1) = C(n, i) (n - i) /
/// (i + 1)` (`2i` roundings: a relative error below `2.01 n 2^-53` for `n <= 1000`, and no
/// overflow there: `C(1000, 500) < 2^996`), computed once per unit problem: the chain of
/// dependent divisions is the slow part of the leaf estimate otherwise.
pub(super) fn binomials_f64(n: usize) -> Vec<f64> {
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
/// Only a candidate generator for [`RationalRoots::recognise_in`] and the refinement's first
/// window (nothing is decided on it); `None` beyond degree 1000 (the binomials leave the `f64`
/// range).
/// The leaves run it through [`UnitEstimate::of_leaf`] and [`UnitEstimate::sharpened`] (the
/// same steps, stopped once at a coarse point); this is the uninterrupted reference of the tests.
#[cfg(test)]
pub(super) fn bernstein_root_estimate(g: Vec<f64>, binoms: &[f64]) -> Option<f64> {
    match LeafNewton::start(g, binoms) {
        Ok(mut newton) => match newton.run(0.0) {
            NewtonStop::Coarse(_) => unreachable!("no coarse stop was asked for"),
            NewtonStop::Done(t) => t,
        },
        Err(t) => t,
    }
}

/// The iteration of [`bernstein_root_estimate`] as a state that can stop at a coarse point and
/// resume: a rational root with a small denominator is recognised from the coarse point
/// (a correction below [`COARSE_CORRECTION`], so the Newton point is within about its square
/// of the root), and the full iteration, whose every step is the same as without the stop, is
/// run only when it is not (module `descartes`, "Rational roots").
#[derive(Clone, Debug)]
pub(super) struct LeafNewton {
    /// `b_i C(n, i)`.
    g: Vec<f64>,
    /// The bracket `(a, c)` and the current point.
    a: f64,
    c: f64,
    x: f64,
    step: f64,
    step_before: f64,
    negative_left: bool,
    /// Points taken so far.
    iterations: u32,
    /// The Newton point from `x`, computed but not yet taken.
    pending: Option<f64>,
}

/// Where [`LeafNewton::run`] stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum NewtonStop {
    /// A Newton point whose correction was below the coarse tolerance; the iteration can go on.
    Coarse(f64),
    /// The final estimate (`None`: none, as [`bernstein_root_estimate`]).
    Done(Option<f64>),
}

/// The Newton correction (in the leaf's coordinate `t`) below which a leaf's estimate is
/// coarse enough to recognise the rational roots of denominator up to [`COARSE_DENOMINATOR`]:
/// the Newton point is then within about `2^-48` of the root (quadratic convergence), far
/// inside Legendre's `1 / (2 q^2)`.
pub(super) const COARSE_CORRECTION: f64 = 1.0 / (1u64 << 24) as f64;

/// The largest denominator tried at a coarse estimate.
pub(super) const COARSE_DENOMINATOR: i64 = 1 << 10;

impl LeafNewton {
    /// The iteration's start from the leaf's coefficients, or its result when there is nothing
    /// to iterate (`Err(None)`: no estimate).
    pub(super) fn start(mut g: Vec<f64>, binoms: &[f64]) -> Result<LeafNewton, Option<f64>> {
        let Some(n) = g.len().checked_sub(1) else {
            return Err(None);
        };
        if n > 1000 || n == 0 {
            return Err(None);
        }
        debug_assert_eq!(binoms.len(), n + 1);
        let (fa0, fc0) = (g[0], g[n]);
        if !(fa0.is_finite() && fc0.is_finite())
            || fa0 == 0.0
            || fc0 == 0.0
            || (fa0 > 0.0) == (fc0 > 0.0)
        {
            return Err(None);
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
            return Err(None);
        }
        Ok(LeafNewton {
            g,
            a: 0.0,
            c: 1.0,
            x,
            step: 1.0,
            step_before: 1.0,
            negative_left: fa0 < 0.0,
            iterations: 0,
            pending: None,
        })
    }

    /// The function and its derivative in `t`.
    fn eval(&self, t: f64) -> (f64, f64) {
        if t <= 0.5 {
            let w = 1.0 - t;
            let s = t / w;
            let (mut p, mut dp) = (0.0, 0.0);
            for &gi in self.g.iter().rev() {
                dp = dp * s + p;
                p = p * s + gi;
            }
            (p, dp / (w * w))
        } else {
            let u = (1.0 - t) / t;
            let (mut q, mut dq) = (0.0, 0.0);
            for &gi in &self.g {
                dq = dq * u + q;
                q = q * u + gi;
            }
            (q, -dq / (t * t))
        }
    }

    /// Runs the iteration until it ends, or until a Newton correction is at most `coarse`
    /// (`0` never stops early); a later call resumes where this one stopped. Not to be called
    /// again after [`NewtonStop::Done`].
    pub(super) fn run(&mut self, coarse: f64) -> NewtonStop {
        loop {
            if let Some(newton) = self.pending.take() {
                let next = if newton > self.a
                    && newton < self.c
                    && (newton - self.x).abs() < 0.5 * self.step_before
                {
                    newton
                } else {
                    0.5 * (self.a + self.c)
                };
                self.step_before = self.step;
                self.step = (next - self.x).abs();
                self.x = next;
                self.iterations += 1;
            }
            if self.iterations >= 200 {
                return NewtonStop::Done(Some(0.5 * (self.a + self.c)));
            }
            let x = self.x;
            let (f, df) = self.eval(x);
            if f == 0.0 {
                return NewtonStop::Done(Some(x));
            }
            if !f.is_finite() {
                return NewtonStop::Done(None);
            }
            if (f < 0.0) == self.negative_left {
                self.a = x;
            } else {
                self.c = x;
            }
            if self.c - self.a <= 16.0 * f64::EPSILON * self.c {
                return NewtonStop::Done(Some(0.5 * (self.a + self.c)));
            }
            let newton = x - f / df;
            let correction = (newton - x).abs();
            if correction <= 4.0 * f64::EPSILON * x.abs() {
                return NewtonStop::Done(Some(newton));
            }
            self.pending = Some(newton);
            if correction <= coarse {
                return NewtonStop::Coarse(newton);
            }
        }
    }
}

/// The continued-fraction convergents `p / q` of `x` with `0 < q <= 2^40` (at most 64), lazily
/// (the caller usually stops at the first that passes its tests; no allocation).
pub(super) fn convergents(x: f64) -> impl Iterator<Item = (i64, i64)> {
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
pub(super) fn rem_small(x: &BigInt, m: u64) -> u64 {
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
pub(super) fn divide_by_linear_factor(a: &[BigInt], p: i64, q: i64) -> Option<Vec<BigInt>> {
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
pub(super) fn linear_factor_divides(a: &[BigInt], p: i64, q: i64) -> bool {
    divide_by_linear_factor(a, p, q).is_some()
}

/// The rational root in the open interval `(lo, hi)` of the primitive square-free `q`, found
/// among the continued-fraction convergents `p / q` of the estimate `est` (module
/// documentation, "Rational roots"): a convergent is tried when it lies in the interval and
/// passes the rational root theorem's tests `q | lc`, `p | a_k` (`a_k` the lowest non-zero
/// coefficient); it is a root exactly when `q x - p` divides the polynomial.
#[cfg(test)]
pub(super) fn recognise_rational(
    poly: &[BigInt],
    est: f64,
    lo: &Rational,
    hi: &Rational,
) -> Option<Rational> {
    let mut r = RationalRoots::new(poly);
    r.recognise(est, lo, hi)
}

/// The rational-root recognition of one polynomial (module documentation, "Rational roots"):
/// the polynomial with the roots found so far divided out ([`Deflated`]), the limb width
/// wide enough for every factor ([`super::limbs::linear_factor_width`]), and the magnitudes of
/// the original leading and lowest non-zero coefficients for the rational root theorem's
/// filters.
pub(super) struct RationalRoots {
    pub(super) deflated: Deflated,
    /// The convergents tried at the last coarse estimate ([`RationalRoots::recognise_in`]).
    tried: Vec<(i64, i64)>,
    pub(super) width: usize,
    pub(super) lc: Vec<u64>,
    pub(super) low: Vec<u64>,
}

impl RationalRoots {
    /// For the primitive square-free `q` (degree >= 1).
    pub(super) fn new(q: &[BigInt]) -> RationalRoots {
        let width = super::limbs::linear_factor_width(q);
        let low = q.iter().find(|c| !c.is_zero()).expect("q is not zero");
        RationalRoots {
            deflated: Deflated::new(q, width),
            tried: Vec::with_capacity(64),
            width,
            lc: q[q.len() - 1].magnitude().to_u64_digits(),
            low: low.magnitude().to_u64_digits(),
        }
    }

    /// The rational root in `(lo, hi)` among the convergents of `est`, divided out of the
    /// polynomial when found (the tests' entry; the isolator goes through
    /// [`RationalRoots::recognise_in`]).
    #[cfg(test)]
    pub(super) fn recognise(&mut self, est: f64, lo: &Rational, hi: &Rational) -> Option<Rational> {
        self.recognise_in(est, &Window::new(lo, hi), Phase::Only)
    }

    /// The rational root in `window` among the convergents of `est`: at a coarse estimate
    /// ([`Phase::Coarse`]) those of denominator up to [`COARSE_DENOMINATOR`] (it is accurate
    /// enough for those only), each remembered; at the final estimate after a coarse one
    /// ([`Phase::Final`]) the `i`-th convergent is skipped when it is the coarse one's `i`-th
    /// (already tried, with the same outcome).
    pub(super) fn recognise_in(
        &mut self,
        est: f64,
        window: &Window<'_>,
        phase: Phase,
    ) -> Option<Rational> {
        if phase == Phase::Coarse {
            self.tried.clear();
        }
        if self.deflated.len() < 2 {
            return None;
        }
        let max_den = if phase == Phase::Coarse {
            COARSE_DENOMINATOR
        } else {
            i64::MAX
        };
        let Window {
            lo,
            hi,
            lo_f,
            hi_f,
            delta,
        } = *window;
        for (i, (p, q)) in convergents(est)
            .take_while(|&(_, q)| q <= max_den)
            .enumerate()
        {
            if phase == Phase::Coarse {
                self.tried.push((p, q));
            }
            let pq = p as f64 / q as f64;
            if (phase == Phase::Final && self.tried.get(i) == Some(&(p, q)))
                || p == 0
                || pq < lo_f - delta
                || pq > hi_f + delta
                || crate::bigint::rem_1(&self.lc, q as u64) != 0
                || crate::bigint::rem_1(&self.low, p.unsigned_abs()) != 0
            {
                continue;
            }
            // Inside `(lo, hi)`: by the same `f64` margins when clearly so, else exactly.
            let clearly_inside = pq > lo_f + delta && pq < hi_f - delta;
            if !clearly_inside {
                let r = Rational::new(p, q).expect("q > 0");
                if !(r > *lo && r < *hi) {
                    continue;
                }
            }
            if self.deflated.divide(p, q, self.width) {
                return Some(Rational::new(p, q).expect("q > 0"));
            }
        }
        None
    }
}

/// Which estimate [`RationalRoots::recognise_in`] tries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Phase {
    /// A leaf's coarse point.
    Coarse,
    /// The final estimate after a coarse point.
    Final,
    /// A final estimate with no coarse point before it.
    Only,
}

/// An isolating interval `(lo, hi)` with its ends in `f64` for the candidates' quick test: `p
/// / q` in `f64` (p rounded, one division) and the converted ends are each within a relative
/// `2^-52` of the true values, so `p / q < lo_f - delta` proves `p / q < lo` and `p / q >
/// lo_f + delta` proves `p / q > lo` (and symmetrically at `hi`); a comparison with an
/// infinity or a NaN proves nothing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Window<'a> {
    lo: &'a Rational,
    hi: &'a Rational,
    lo_f: f64,
    hi_f: f64,
    delta: f64,
}

impl<'a> Window<'a> {
    pub(super) fn new(lo: &'a Rational, hi: &'a Rational) -> Window<'a> {
        let (lo_f, hi_f) = (lo.to_f64(), hi.to_f64());
        Window {
            lo,
            hi,
            lo_f,
            hi_f,
            delta: (lo_f.abs() + hi_f.abs()) * pow2f(-48),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The Bernstein coefficients on `[0, 1]` of `prod (x - r_i)` times `rest` (as `f64`).
    fn bernstein_of(roots: &[f64], rest: &[f64]) -> Vec<f64> {
        let mut p = rest.to_vec();
        for &r in roots {
            let mut next = vec![0.0; p.len() + 1];
            for (i, &c) in p.iter().enumerate() {
                next[i + 1] += c;
                next[i] -= c * r;
            }
            p = next;
        }
        // b_i = sum_{k <= i} C(i, k) / C(n, k) p_k.
        let n = p.len() - 1;
        let binom =
            |n: usize, k: usize| (0..k).fold(1.0f64, |b, j| b * (n - j) as f64 / (j + 1) as f64);
        (0..=n)
            .map(|i| (0..=i).map(|k| binom(i, k) / binom(n, k) * p[k]).sum())
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]
        /// Stopping at the coarse point and resuming gives the uninterrupted estimate, bit for
        /// bit, and the coarse point is near it.
        #[test]
        fn a_coarse_stop_resumes_to_the_same_estimate(
            root in 0.01f64..0.99,
            others in proptest::collection::vec(-3.0f64..4.0, 0..12),
            rest in proptest::collection::vec(0.5f64..2.0, 1..3),
        ) {
            let others: Vec<f64> = others.into_iter().filter(|r| !(-0.05..=1.05).contains(r)).collect();
            let mut roots = vec![root];
            roots.extend(others);
            let g = bernstein_of(&roots, &rest);
            let n = g.len() - 1;
            let binoms = binomials_f64(n);
            let whole = bernstein_root_estimate(g.clone(), &binoms);
            let c = BigInt::from(3);
            let leaf = UnitEstimate::of_leaf(&c, 2, g, &binoms);
            match (&whole, &leaf) {
                (None, None) => {}
                (Some(t), Some(e)) => {
                    if e.is_coarse() {
                        prop_assert!((e.off / 0.25 - t).abs() < 1e-6, "{} vs {}", e.off / 0.25, t);
                    }
                    let done = leaf.clone().and_then(UnitEstimate::sharpened);
                    let done = done.expect("the uninterrupted iteration found one");
                    prop_assert!(!done.is_coarse());
                    prop_assert_eq!(done.off.to_bits(), (t * 0.25).to_bits());
                }
                (Some(_), None) => prop_assert!(false, "the leaf lost the estimate"),
                (None, Some(e)) => {
                    // Only a coarse point whose iteration ends without an estimate.
                    prop_assert!(e.is_coarse());
                    prop_assert!(leaf.clone().and_then(UnitEstimate::sharpened).is_none());
                }
            }
            if let Some(t) = whole {
                prop_assert!((t - root).abs() < 1e-6, "{t} vs {root}");
            }
        }
    }
}
