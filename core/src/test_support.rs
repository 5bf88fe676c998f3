//! Exact test scalars shared by the crate's unit tests: rationals
//! over `i128` (a field), polynomials over `i128` in one variable (a ring: a symbolic check), and
//! a deterministic pseudo-random generator.

use crate::scalar::{Field, Ring, ZeroDivisor};

/// The workspace's seeded generator, with the two draws these tests use.
pub struct Rng(crate::rng::Rng);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(crate::rng::Rng::new(seed))
    }
    /// Uniform in `lo..=hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.0.below((hi - lo + 1) as u64) as i64
    }
    pub fn below(&mut self, n: usize) -> usize {
        self.0.below(n as u64) as usize
    }
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// An exact rational `n / d` in lowest terms with `d > 0` (overflow panics).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Q(pub i128, pub i128);

impl Default for Q {
    fn default() -> Q {
        Q(0, 1)
    }
}

impl Q {
    pub fn new(n: i128, d: i128) -> Q {
        assert!(d != 0, "zero denominator");
        let g = gcd(n, d).max(1);
        let s = if d < 0 { -1 } else { 1 };
        Q(s * n / g, s * d / g)
    }
    pub fn int(n: i64) -> Q {
        Q(n as i128, 1)
    }
    fn add_q(&self, r: &Q) -> Q {
        let g = gcd(self.1, r.1);
        let (a, b) = (self.1 / g, r.1 / g);
        let n = self
            .0
            .checked_mul(b)
            .and_then(|x| x.checked_add(r.0.checked_mul(a)?));
        Q::new(
            n.expect("Q overflow"),
            self.1.checked_mul(b).expect("Q overflow"),
        )
    }
    fn sub_q(&self, r: &Q) -> Q {
        self.add_q(&Q(-r.0, r.1))
    }
    fn mul_q(&self, r: &Q) -> Q {
        let g1 = gcd(self.0, r.1).max(1);
        let g2 = gcd(r.0, self.1).max(1);
        let n = (self.0 / g1).checked_mul(r.0 / g2).expect("Q overflow");
        let d = (self.1 / g2).checked_mul(r.1 / g1).expect("Q overflow");
        Q::new(n, d)
    }
    fn div_q(&self, r: &Q) -> Q {
        assert!(r.0 != 0, "division by zero");
        self.mul_q(&Q::new(r.1, r.0))
    }
}

crate::ring_ops! {
    impl[] Q;
    Neg::neg: |a| Q(-a.0, a.1);
    Add::add, AddAssign::add_assign: |a, b| a.add_q(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_q(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_q(b);
    Div::div, DivAssign::div_assign: |a, b| a.div_q(b);
}

impl Ring for Q {
    fn zero() -> Self {
        Q(0, 1)
    }
    fn one() -> Self {
        Q(1, 1)
    }
    fn from_i64(n: i64) -> Self {
        Q::int(n)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
}

impl Field for Q {
    fn inv(&self) -> Result<Self, ZeroDivisor> {
        if self.0 == 0 {
            Err(ZeroDivisor)
        } else {
            Ok(Q::new(self.1, self.0))
        }
    }
}

impl PartialOrd for Q {
    fn partial_cmp(&self, o: &Q) -> Option<core::cmp::Ordering> {
        (self.0 * o.1).partial_cmp(&(o.0 * self.1))
    }
}

impl crate::scalar::OrderedField for Q {}

/// A polynomial `sum a_k x^k` over `i128` (no trailing zeros; overflow panics): a ring that
/// is not a field, standing in for the symbolic scalars.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Poly(pub Vec<i128>);

impl Poly {
    pub fn x() -> Poly {
        Poly(vec![0, 1])
    }
    pub fn constant(c: i128) -> Poly {
        Poly(vec![c]).trim()
    }
    fn trim(mut self) -> Poly {
        while self.0.last() == Some(&0) {
            self.0.pop();
        }
        self
    }
    fn zip(&self, r: &Poly, f: impl Fn(i128, i128) -> i128) -> Poly {
        let len = self.0.len().max(r.0.len());
        let get = |p: &Poly, i: usize| p.0.get(i).copied().unwrap_or(0);
        Poly((0..len).map(|i| f(get(self, i), get(r, i))).collect()).trim()
    }
    fn add_p(&self, r: &Poly) -> Poly {
        self.zip(r, |a, b| a.checked_add(b).expect("Poly overflow"))
    }
    fn sub_p(&self, r: &Poly) -> Poly {
        self.zip(r, |a, b| a.checked_sub(b).expect("Poly overflow"))
    }
    fn mul_p(&self, r: &Poly) -> Poly {
        if self.0.is_empty() || r.0.is_empty() {
            return Poly(vec![]);
        }
        let mut out = vec![0i128; self.0.len() + r.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in r.0.iter().enumerate() {
                let p = a.checked_mul(*b).expect("Poly overflow");
                out[i + j] = out[i + j].checked_add(p).expect("Poly overflow");
            }
        }
        Poly(out).trim()
    }
}

crate::ring_ops! {
    impl[] Poly;
    Neg::neg: |a| Poly(a.0.iter().map(|c| -c).collect());
    Add::add, AddAssign::add_assign: |a, b| a.add_p(b);
    Sub::sub, SubAssign::sub_assign: |a, b| a.sub_p(b);
    Mul::mul, MulAssign::mul_assign: |a, b| a.mul_p(b);
}

impl Ring for Poly {
    fn zero() -> Self {
        Poly(vec![])
    }
    fn one() -> Self {
        Poly(vec![1])
    }
    fn from_i64(n: i64) -> Self {
        Poly::constant(n as i128)
    }
    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }
}

/// A random integer coefficient list of length `len` with entries in `-r..=r`.
pub fn ints(rng: &mut Rng, len: usize, r: i64) -> Vec<i64> {
    (0..len).map(|_| rng.int(-r, r)).collect()
}

/// A random rational with numerator in `-r..=r` and denominator in `1..=d`.
pub fn rational(rng: &mut Rng, r: i64, d: i64) -> Q {
    Q::new(rng.int(-r, r) as i128, rng.int(1, d) as i128)
}
