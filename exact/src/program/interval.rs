//! Intervals with dyadic endpoints at a working precision: the approximate half of the exact
//! evaluator (`real`), used downstream of an irrational square root.
//!
//! A [`Dy`] is `m * 2^e` with a big integer `m`; an [`Iv`] is `[lo, hi]` with `lo <= hi`, a
//! rigorous enclosure of one real number. Every operation computes its endpoints exactly and
//! rounds them **outward** (the lower one down, the upper one up) to `p` significant bits, so
//! the enclosure stays rigorous and the endpoints stay `p` bits long whatever the magnitude
//! (floating intervals: a relative precision, subnormal-sized and huge values alike). Square
//! roots take the integer square root of the mantissa scaled to `2p` bits (floor for the lower
//! end, ceiling for the upper). A sum whose smaller operand lies entirely below the rounding
//! position of the larger is not aligned bit by bit: the small operand is replaced by one unit
//! at a position below the result's last bit, in the rounding direction, which keeps the
//! enclosure and bounds every shift by about `2p` bits.
//!
//! Hand-written because the workspace has no multiple-precision float or interval dependency
//! (MPFR bindings need a C library); the operations needed are few and all reduce to big-integer
//! shifts, products, divisions and square roots of num-bigint.
use crate::rational::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// A rounding direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Dir {
    /// Towards minus infinity.
    Down,
    /// Towards plus infinity.
    Up,
}

/// The dyadic number `m * 2^e`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Dy {
    pub(crate) m: BigInt,
    pub(crate) e: i64,
}

/// `floor(m / 2^s)` (or the ceiling, `Up`).
fn shr_dir(m: &BigInt, s: u64, dir: Dir) -> BigInt {
    if s == 0 {
        return m.clone();
    }
    let a = m.abs();
    let q = &a >> s;
    let inexact = (&q << s) != a;
    // Truncation of |m| rounds towards zero; fix up the side away from zero when needed.
    let away = inexact && ((dir == Dir::Up) == m.is_positive());
    let q = if away { q + 1u32 } else { q };
    if m.is_negative() {
        -q
    } else {
        q
    }
}

/// `num / den` rounded in `dir` (`den != 0`).
fn div_dir(num: &BigInt, den: &BigInt, dir: Dir) -> BigInt {
    match dir {
        Dir::Down => num.div_floor(den),
        Dir::Up => -((-num).div_floor(den)),
    }
}

impl Dy {
    /// Zero.
    pub(crate) fn zero() -> Dy {
        Dy {
            m: BigInt::zero(),
            e: 0,
        }
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.m.is_zero()
    }

    /// The sign as an ordering against zero.
    pub(crate) fn sign(&self) -> Ordering {
        self.m.sign_ord()
    }

    /// The position just above the leading bit: `2^(top-1) <= |x| < 2^top` (for `x != 0`).
    pub(crate) fn top(&self) -> i64 {
        self.e + self.m.bits() as i64
    }

    /// `m * 2^e` rounded in `dir` to at most `p` significant bits.
    pub(crate) fn rounded(m: BigInt, e: i64, p: u64, dir: Dir) -> Dy {
        let bits = m.bits();
        if bits > p {
            let s = bits - p;
            Dy {
                m: shr_dir(&m, s, dir),
                e: e + s as i64,
            }
        } else {
            Dy { m, e }
        }
    }

    pub(crate) fn neg(&self) -> Dy {
        Dy {
            m: -&self.m,
            e: self.e,
        }
    }

    /// The rational `q` rounded in `dir` to `p` bits.
    pub(crate) fn from_rational(q: &Rational, p: u64, dir: Dir) -> Dy {
        let n = q.numer();
        let d = q.denom();
        if (&d & (&d - 1u32)).is_zero() {
            // A dyadic rational: exact before rounding.
            return Dy::rounded(n, -(d.bits() as i64 - 1), p, dir);
        }
        Dy::div(&Dy { m: n, e: 0 }, &Dy { m: d, e: 0 }, p, dir)
    }

    /// The exact value.
    pub(crate) fn to_big_rational(&self) -> BigRational {
        if self.e >= 0 {
            BigRational::from_integer(&self.m << self.e as u64)
        } else {
            BigRational::new(self.m.clone(), BigInt::one() << (-self.e) as u64)
        }
    }

    /// `a + b` rounded in `dir` to `p` bits.
    pub(crate) fn add(a: &Dy, b: &Dy, p: u64, dir: Dir) -> Dy {
        if a.is_zero() {
            return Dy::rounded(b.m.clone(), b.e, p, dir);
        }
        if b.is_zero() {
            return Dy::rounded(a.m.clone(), a.e, p, dir);
        }
        let (big, small) = if a.top() >= b.top() { (a, b) } else { (b, a) };
        // Every bit of `big` and of the rounded result lies above `limit`.
        let limit = big.e.min(big.top() - p as i64) - 4;
        let small = if small.top() < limit {
            // |small| < 2^limit: only its sign matters, as one unit at `limit` in the rounding
            // direction (or nothing, when it pushes the other way).
            match (small.sign(), dir) {
                (Ordering::Greater, Dir::Up) => Dy {
                    m: BigInt::one(),
                    e: limit,
                },
                (Ordering::Less, Dir::Down) => Dy {
                    m: -BigInt::one(),
                    e: limit,
                },
                _ => return Dy::rounded(big.m.clone(), big.e, p, dir),
            }
        } else {
            small.clone()
        };
        let e = big.e.min(small.e);
        let m = (&big.m << (big.e - e) as u64) + (&small.m << (small.e - e) as u64);
        Dy::rounded(m, e, p, dir)
    }

    /// `a * b`, exact.
    pub(crate) fn mul_exact(a: &Dy, b: &Dy) -> Dy {
        Dy {
            m: &a.m * &b.m,
            e: a.e + b.e,
        }
    }

    /// `a / b` (`b != 0`) rounded in `dir` to `p` bits.
    pub(crate) fn div(a: &Dy, b: &Dy, p: u64, dir: Dir) -> Dy {
        debug_assert!(!b.is_zero());
        if a.is_zero() {
            return Dy::zero();
        }
        // A quotient of at least p + 1 bits.
        let k = p as i64 + b.m.bits() as i64 - a.m.bits() as i64 + 2;
        let (num, den) = if k >= 0 {
            (&a.m << k as u64, b.m.clone())
        } else {
            (a.m.clone(), &b.m << (-k) as u64)
        };
        Dy::rounded(div_dir(&num, &den, dir), a.e - b.e - k, p, dir)
    }

    /// `sqrt(a)` for `a >= 0`, rounded in `dir` to `p` bits.
    pub(crate) fn sqrt(a: &Dy, p: u64, dir: Dir) -> Dy {
        debug_assert!(!a.m.is_negative());
        if a.is_zero() {
            return Dy::zero();
        }
        let mut s = (2 * p + 2).saturating_sub(a.m.bits());
        if (a.e - s as i64).rem_euclid(2) != 0 {
            s += 1;
        }
        let m = &a.m << s;
        let mut r = m.sqrt();
        if dir == Dir::Up && &r * &r != m {
            r += 1u32;
        }
        Dy::rounded(r, (a.e - s as i64) / 2, p, dir)
    }

    /// The exact order.
    pub(crate) fn cmp(a: &Dy, b: &Dy) -> Ordering {
        let (sa, sb) = (a.sign(), b.sign());
        if sa != sb || sa == Ordering::Equal {
            return sa.cmp(&sb);
        }
        if a.top() != b.top() {
            let mag = a.top().cmp(&b.top());
            return if sa == Ordering::Greater {
                mag
            } else {
                mag.reverse()
            };
        }
        // Equal tops: the exponents differ by at most the mantissa lengths.
        let e = a.e.min(b.e);
        (&a.m << (a.e - e) as u64).cmp(&(&b.m << (b.e - e) as u64))
    }
}

trait SignOrd {
    fn sign_ord(&self) -> Ordering;
}

impl SignOrd for BigInt {
    fn sign_ord(&self) -> Ordering {
        if self.is_positive() {
            Ordering::Greater
        } else if self.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
}

fn min_dy(a: Dy, b: Dy) -> Dy {
    if Dy::cmp(&a, &b) == Ordering::Greater {
        b
    } else {
        a
    }
}

fn max_dy(a: Dy, b: Dy) -> Dy {
    if Dy::cmp(&a, &b) == Ordering::Less {
        b
    } else {
        a
    }
}

/// The enclosure `[lo, hi]` of a real number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Iv {
    pub(crate) lo: Dy,
    pub(crate) hi: Dy,
}

impl Iv {
    /// The enclosure of the rational `q` at `p` bits (a point when `q` is dyadic and short).
    pub(crate) fn from_rational(q: &Rational, p: u64) -> Iv {
        Iv {
            lo: Dy::from_rational(q, p, Dir::Down),
            hi: Dy::from_rational(q, p, Dir::Up),
        }
    }

    /// The sign of every point, if they share one: `Some(Equal)` only for the point zero.
    pub(crate) fn sign(&self) -> Option<Ordering> {
        match (self.lo.sign(), self.hi.sign()) {
            (Ordering::Greater, _) => Some(Ordering::Greater),
            (_, Ordering::Less) => Some(Ordering::Less),
            (Ordering::Equal, Ordering::Equal) => Some(Ordering::Equal),
            _ => None,
        }
    }

    /// The largest exponent magnitude of the endpoints (for the size limit).
    pub(crate) fn max_exponent(&self) -> u64 {
        self.lo.e.unsigned_abs().max(self.hi.e.unsigned_abs())
    }

    pub(crate) fn neg(&self) -> Iv {
        Iv {
            lo: self.hi.neg(),
            hi: self.lo.neg(),
        }
    }

    pub(crate) fn add(a: &Iv, b: &Iv, p: u64) -> Iv {
        Iv {
            lo: Dy::add(&a.lo, &b.lo, p, Dir::Down),
            hi: Dy::add(&a.hi, &b.hi, p, Dir::Up),
        }
    }

    pub(crate) fn sub(a: &Iv, b: &Iv, p: u64) -> Iv {
        Iv::add(a, &b.neg(), p)
    }

    pub(crate) fn mul(a: &Iv, b: &Iv, p: u64) -> Iv {
        let c = [
            Dy::mul_exact(&a.lo, &b.lo),
            Dy::mul_exact(&a.lo, &b.hi),
            Dy::mul_exact(&a.hi, &b.lo),
            Dy::mul_exact(&a.hi, &b.hi),
        ];
        let lo = c.iter().cloned().reduce(min_dy).expect("four products");
        let hi = c.into_iter().reduce(max_dy).expect("four products");
        Iv {
            lo: Dy::rounded(lo.m, lo.e, p, Dir::Down),
            hi: Dy::rounded(hi.m, hi.e, p, Dir::Up),
        }
    }

    /// `a / b` for `b` of one sign (not containing zero).
    pub(crate) fn div(a: &Iv, b: &Iv, p: u64) -> Iv {
        debug_assert!(matches!(b.sign(), Some(Ordering::Less | Ordering::Greater)));
        let pairs = [
            (&a.lo, &b.lo),
            (&a.lo, &b.hi),
            (&a.hi, &b.lo),
            (&a.hi, &b.hi),
        ];
        let lo = pairs
            .iter()
            .map(|(x, y)| Dy::div(x, y, p, Dir::Down))
            .reduce(min_dy)
            .expect("four quotients");
        let hi = pairs
            .iter()
            .map(|(x, y)| Dy::div(x, y, p, Dir::Up))
            .reduce(max_dy)
            .expect("four quotients");
        Iv { lo, hi }
    }

    /// `sqrt` of an enclosure with `lo >= 0`.
    pub(crate) fn sqrt(a: &Iv, p: u64) -> Iv {
        debug_assert!(!a.lo.m.is_negative());
        Iv {
            lo: Dy::sqrt(&a.lo, p, Dir::Down),
            hi: Dy::sqrt(&a.hi, p, Dir::Up),
        }
    }

    pub(crate) fn abs(&self) -> Iv {
        if !self.lo.m.is_negative() {
            self.clone()
        } else if !self.hi.m.is_positive() {
            self.neg()
        } else {
            Iv {
                lo: Dy::zero(),
                hi: max_dy(self.lo.neg(), self.hi.clone()),
            }
        }
    }

    pub(crate) fn min(a: &Iv, b: &Iv) -> Iv {
        Iv {
            lo: min_dy(a.lo.clone(), b.lo.clone()),
            hi: min_dy(a.hi.clone(), b.hi.clone()),
        }
    }

    pub(crate) fn max(a: &Iv, b: &Iv) -> Iv {
        Iv {
            lo: max_dy(a.lo.clone(), b.lo.clone()),
            hi: max_dy(a.hi.clone(), b.hi.clone()),
        }
    }

    /// `a / 2`, exact.
    pub(crate) fn half(&self) -> Iv {
        Iv {
            lo: Dy {
                m: self.lo.m.clone(),
                e: self.lo.e - 1,
            },
            hi: Dy {
                m: self.hi.m.clone(),
                e: self.hi.e - 1,
            },
        }
    }

    /// Whether `lo == hi` (the enclosure is the value).
    pub(crate) fn is_point(&self) -> bool {
        Dy::cmp(&self.lo, &self.hi) == Ordering::Equal
    }

    /// Whether the midpoint meets the relative accuracy contract: the enclosure has one sign
    /// and the midpoint's distance to any point of it is at most `2^-rel` times the smallest
    /// magnitude in it (a point always does). Checked with an upper bound of the width, so
    /// "true" is sure.
    pub(crate) fn narrow(&self, rel: u32) -> bool {
        let w = Dy::add(&self.hi, &self.lo.neg(), 64, Dir::Up);
        if w.is_zero() {
            return true;
        }
        let smallest = match self.sign() {
            Some(Ordering::Greater) => &self.lo,
            Some(Ordering::Less) => &self.hi,
            _ => return false,
        };
        // w < 2^top(w) <= 2^(top(smallest) - 1 - rel) <= 2^-rel |smallest|.
        w.top() <= smallest.top() - 1 - i64::from(rel)
    }

    /// The midpoint, exactly.
    pub(crate) fn midpoint(&self) -> BigRational {
        (self.lo.to_big_rational() + self.hi.to_big_rational()) / BigInt::from(2)
    }
}
