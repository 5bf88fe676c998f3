//! The separation of close root pairs (the parent module's documentation, "Close pairs").

use super::*;

/// Separates a close root pair (module documentation, "Close pairs"): on the dyadic node
/// `(c / 2^j, (c + 1) / 2^j)` of a unit problem `p`, where Descartes' bound is 2 and the end
/// signs are both `s`, a point strictly inside at which `p` has the sign `-s`, found by Newton's
/// method on `p'` (in `f64`, then exact dyadic steps doubling the precision) and verified by an
/// exact sign. `None` when none was found (the node is then subdivided).
pub(super) struct PairSplitter<'a> {
    pub(super) p: &'a [BigInt],
    pub(super) pf: Vec<f64>,
    pub(super) d1f: Vec<f64>,
    pub(super) d2f: Vec<f64>,
    /// `p'` and `p''` exactly, built on the first exact Newton step.
    pub(super) exact: std::cell::OnceCell<(Vec<BigInt>, Vec<BigInt>)>,
}

/// The precision cap (bits after the binary point) of the exact Newton steps.
pub(super) const PAIR_MAX_BITS: u64 = 4096;

impl<'a> PairSplitter<'a> {
    /// The `f64` images of `p`, `p'`, `p''` (one common scaling); the exact derivatives wait
    /// for the first pair that passes the `f64` test.
    pub(super) fn new(p: &'a [BigInt]) -> PairSplitter<'a> {
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
    pub(super) fn derivatives(&self) -> &(Vec<BigInt>, Vec<BigInt>) {
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
    pub(super) fn eval(a: &[BigInt], x: &Dyadic) -> BigInt {
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
    pub(super) fn split(&self, c: &BigInt, j: u64, s: Sign) -> Option<(Dyadic, Option<f64>)> {
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
