//! The range of a variable for the counter-example search ([`VarDomain`]).

use super::small_rational;
use crate::{Radical, Rational};
use exactcheck_core::Rng;
use std::fmt;

/// The range of a variable: optional lower and upper bounds, each with a flag "strict", and
/// whether the variable takes only integer values (the variables of the bounds of a sum).
///
/// `VarDomain { lower: Some((0, true)), upper: None }` is `v > 0`; `lower: Some((0, false)), upper:
/// Some((1, false))` is `0 <= v <= 1`. Sampling draws from the box: with both bounds
/// `lo + (hi - lo) k/16` (`k` in `1..16`, the ends too when not strict), with one bound
/// `lo + n/d` or `hi - n/d` (`n/d` a small positive rational, or 0 when not strict); an
/// integer variable takes the integer at or above that value.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VarDomain {
    /// The lower bound and whether it is strict (`>`), if any.
    pub lower: Option<(Rational, bool)>,
    /// The upper bound and whether it is strict (`<`), if any.
    pub upper: Option<(Rational, bool)>,
    /// Whether only integers are in the domain.
    pub integer: bool,
}

impl VarDomain {
    /// The whole real line.
    pub fn all() -> VarDomain {
        VarDomain::default()
    }

    /// Whether no real number (no integer, for an integer domain) satisfies the bounds.
    pub fn is_empty(&self) -> bool {
        if let (true, Some((lo, _)), Some(_)) = (self.integer, &self.lower, &self.upper) {
            // The least integer above the lower bound is in the domain unless none is.
            let first = self.integer_at_or_above(lo);
            if !self.contains(&Radical::from(&first)) {
                return true;
            }
        }
        match (&self.lower, &self.upper) {
            (Some((lo, ls)), Some((hi, hs))) => lo > hi || (lo == hi && (*ls || *hs)),
            _ => false,
        }
    }

    /// The least integer of the domain's lower bound at or above `x` (above it when `x` is
    /// the strict lower bound).
    fn integer_at_or_above(&self, x: &Rational) -> Rational {
        let (n, d) = (x.numer(), x.denom());
        let mut ceil = num_integer::Integer::div_ceil(&n, &d);
        if x.is_integer() && matches!(&self.lower, Some((lo, true)) if lo == x) {
            ceil += 1;
        }
        Rational::from(ceil)
    }

    /// Whether `x` satisfies the bounds (exactly), and is an integer for an integer domain.
    pub fn contains(&self, x: &Radical) -> bool {
        if self.integer && !x.to_rational().is_some_and(|q| q.is_integer()) {
            return false;
        }
        let above = match &self.lower {
            None => true,
            Some((lo, strict)) => {
                let lo = Radical::from(lo);
                if *strict {
                    *x > lo
                } else {
                    *x >= lo
                }
            }
        };
        let below = match &self.upper {
            None => true,
            Some((hi, strict)) => {
                let hi = Radical::from(hi);
                if *strict {
                    *x < hi
                } else {
                    *x <= hi
                }
            }
        };
        above && below
    }

    /// A value of the domain (see the type's documentation); unbounded: [`small_rational`].
    pub(super) fn sample(&self, rng: &mut Rng) -> Rational {
        let x = self.sample_real(rng);
        if self.integer {
            self.integer_at_or_above(&x)
        } else {
            x
        }
    }

    fn sample_real(&self, rng: &mut Rng) -> Rational {
        let small_positive = |rng: &mut Rng, strict: bool| loop {
            let n = rng.below(10) as i64;
            let d = rng.below(4) as i64 + 1;
            if n > 0 || !strict {
                return Rational::new(n, d).expect("the denominator is at least 1");
            }
        };
        match (&self.lower, &self.upper) {
            (None, None) => small_rational(rng),
            (Some((lo, strict)), None) => lo + &small_positive(rng, *strict),
            (None, Some((hi, strict))) => hi - &small_positive(rng, *strict),
            (Some((lo, ls)), Some((hi, hs))) => {
                let k = loop {
                    let k = rng.below(17) as i64;
                    if !((k == 0 && *ls) || (k == 16 && *hs)) {
                        break k;
                    }
                };
                let frac = Rational::new(k, 16).expect("16 is not zero");
                lo + &((hi - lo) * &frac)
            }
        }
    }
}

impl fmt::Display for VarDomain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let op = |strict: bool| if strict { "<" } else { "<=" };
        match (&self.lower, &self.upper) {
            (None, None) => write!(f, "any value"),
            (Some((lo, s)), None) => write!(f, "{lo} {} v", op(*s)),
            (None, Some((hi, s))) => write!(f, "v {} {hi}", op(*s)),
            (Some((lo, ls)), Some((hi, hs))) => write!(f, "{lo} {} v {} {hi}", op(*ls), op(*hs)),
        }?;
        if self.integer {
            write!(f, ", v an integer")?;
        }
        Ok(())
    }
}
