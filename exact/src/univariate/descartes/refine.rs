//! The refinement of isolating intervals to a given width (the parent module's documentation,
//! "Refinement"): filtered signs at dyadic points, estimate windows, bisection and verified
//! Newton steps.

use super::*;

/// A dyadic number `num / 2^exp`.
#[derive(Clone, Debug)]
pub(super) struct Dyadic {
    pub(super) num: BigInt,
    pub(super) exp: u64,
}

impl Dyadic {
    pub(super) fn to_rational(&self) -> Rational {
        dyadic(&self.num, self.exp)
    }

    /// The dyadic `floor(x 2^e) / 2^e`.
    pub(super) fn floor_of(x: &Rational, e: u64) -> Dyadic {
        let scaled = x.mul_ref(&pow2(e));
        Dyadic {
            num: floor(&scaled),
            exp: e,
        }
    }

    pub(super) fn to_f64(&self) -> Option<f64> {
        if self.exp > 1000 || self.num.bits() > 1000 {
            return None;
        }
        Some(self.num.to_f64()? * pow2f(-(self.exp.min(2000) as i64)))
    }
}

/// The prepared square-free polynomial of the refinement.
pub(super) struct Refiner<'a> {
    pub(super) q: &'a [BigInt],
    pub(super) qf: Option<Vec<f64>>,
    /// `q` for exact evaluation on limbs at points with a word numerator.
    horner: DyadicHorner,
}

/// `(m, e)` with `x ~ m 2^e`, `m` in `[2^63, 2^64)` as `f64` (`None` for zero).
pub(super) fn approx(x: &BigInt) -> Option<(f64, i64)> {
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
    pub(super) fn new(q: &[BigInt]) -> Refiner<'_> {
        let qf: Option<Vec<f64>> = q
            .iter()
            .map(|c| c.to_f64().filter(|f| f.is_finite()))
            .collect();
        Refiner {
            q,
            qf,
            horner: DyadicHorner::new(q),
        }
    }

    /// The sign of `q(x)` from `f64` arithmetic when the error bound of the module
    /// documentation allows it.
    pub(super) fn filtered_sign(&self, x: &Dyadic) -> Option<Sign> {
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
    pub(super) fn value_exact(&self, x: &Dyadic) -> BigInt {
        match self.horner.eval(&x.num, x.exp, false) {
            Some((v, _)) => v,
            None => PairSplitter::eval(self.q, x),
        }
    }

    /// The sign of `q(x)`, exact: the truncated limb scheme ([`DyadicHorner::sign_truncated`])
    /// when its error bound decides, else the exact value.
    pub(super) fn sign_exact(&self, x: &Dyadic) -> Sign {
        match self.horner.sign_truncated(&x.num, x.exp) {
            Some(s) if s < 0 => Sign::Negative,
            Some(_) => Sign::Positive,
            None => sign_of(&self.value_exact(x)),
        }
    }

    /// `(q(x) 2^(k n), q'(x) 2^(k (n-1)))` for `x = c / 2^k`.
    pub(super) fn eval_exact(&self, x: &Dyadic) -> (BigInt, BigInt) {
        if let Some(pd) = self.horner.eval(&x.num, x.exp, true) {
            return pd;
        }
        self.eval_exact_bigint(x)
    }

    /// [`Refiner::eval_exact`] on `BigInt`s (any numerator; the tests' reference).
    pub(super) fn eval_exact_bigint(&self, x: &Dyadic) -> (BigInt, BigInt) {
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
    pub(super) fn refine(
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
                    match self.sign_exact(&x) {
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
                match self.sign_exact(&x) {
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
pub(super) fn floor_log2(x: &Rational) -> i64 {
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
pub(super) fn sign_at_rational(q: &[BigInt], x: &Rational) -> Sign {
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
