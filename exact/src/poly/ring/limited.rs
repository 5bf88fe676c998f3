//! Products and powers of [`Poly`] within the `degree`, `terms` and `memory` limits.

use super::*;

/// Why a product or power within the limits was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SizeError {
    /// An exponent of a variable would exceed `u32::MAX`.
    #[error("a variable's exponent would exceed {max}", max = u32::MAX)]
    ExponentOverflow,
    /// A named limit: `degree` (predicted), `terms` (counted as the terms are produced), or
    /// `memory` (the terms would take more than a quarter of it).
    #[error(transparent)]
    Limit(#[from] LimitError),
}

/// The cap on the terms of a product whose monomials take `words` words: the `terms` limit, and
/// the number of terms (packed monomial and coefficient) that fit in a quarter of the `memory`
/// limit. With the flag: whether the memory bound is the smaller one.
fn term_cap<C>(words: usize) -> (usize, bool) {
    let per_term = (8 * words + std::mem::size_of::<C>()).max(1);
    let budget = limits::MEMORY.get_usize().saturating_mul(1 << 20) / 4;
    let by_memory = budget / per_term;
    let terms = limits::TERMS.get_usize();
    (terms.min(by_memory), by_memory < terms)
}

/// The error for a product stopped at the cap of [`term_cap`].
fn cap_error<C>(words: usize) -> SizeError {
    let (cap, by_memory) = term_cap::<C>(words);
    if by_memory {
        let per_term = 8 * words + std::mem::size_of::<C>();
        SizeError::Limit(limits::MEMORY.exceeded(format!(
            "a polynomial of more than {cap} terms of {per_term} bytes each, over a quarter of the limit"
        )))
    } else {
        SizeError::Limit(limits::TERMS.exceeded(format!("more than {cap}")))
    }
}

impl<C: Ring> Poly<C> {
    /// `self * rhs` within the limits: the total degree of the product (the sum of the degrees)
    /// is checked against `degree` before any work, and the product's terms are counted as the
    /// kernels produce them, stopping past `terms` (or past what fits in a quarter of `memory`).
    ///
    /// # Errors
    /// [`SizeError::Limit`] for the `degree`, `terms` or `memory` limit,
    /// [`SizeError::ExponentOverflow`] for an exponent above `u32::MAX`.
    pub fn try_mul(&self, rhs: &Self) -> Result<Self, SizeError> {
        if self.is_empty() || rhs.is_empty() {
            return Ok(Poly::zero());
        }
        limits::DEGREE.check(self.total_degree().saturating_add(rhs.total_degree()))?;
        if self.product_exponent_overflows(rhs) {
            return Err(SizeError::ExponentOverflow);
        }
        let words = std::cell::Cell::new(0);
        self.mul_capped(rhs, |w| {
            words.set(w);
            term_cap::<C>(w).0
        })
        .ok_or_else(|| cap_error::<C>(words.get()))
    }

    /// `self^e` within the limits: the degree `e * deg(self)` is checked before any work; the
    /// power recurrence counts the power's terms as it produces them, and every squaring and
    /// multiplication of binary powering counts its own (as [`Poly::try_mul`]).
    ///
    /// # Errors
    /// As [`Poly::try_mul`].
    pub fn try_pow(&self, e: u32) -> Result<Self, SizeError> {
        let e = u64::from(e);
        if e == 0 {
            return Ok(Poly::one());
        }
        limits::DEGREE.check(self.total_degree().saturating_mul(e))?;
        if e > 1 && u64::from(self.max_exponent()) * e > MAX_EXP {
            return Err(SizeError::ExponentOverflow);
        }
        if self.len() <= 1 {
            return Ok(self.pow_term(e));
        }
        if let Some((c, prim)) = self.split_content() {
            let e32 = u32::try_from(e).expect("e came from a u32");
            return Ok(prim.try_pow(e32)?.scale(&pow_coeff(&c, e)));
        }
        let words = std::cell::Cell::new(0);
        let capped = self.pow_by_recurrence(e, |w| {
            words.set(w);
            term_cap::<C>(w).0
        });
        if let Some(p) = capped {
            return p.ok_or_else(|| cap_error::<C>(words.get()));
        }
        let mut e = e;
        let mut acc: Option<Poly<C>> = None;
        let mut base = self.clone();
        loop {
            if e & 1 == 1 {
                acc = Some(match acc {
                    None => base.clone(),
                    Some(a) => a.try_mul(&base)?,
                });
            }
            e >>= 1;
            if e == 0 {
                return Ok(acc.unwrap_or_else(Poly::one));
            }
            let words = std::cell::Cell::new(0);
            base = base
                .square_capped(|w| {
                    words.set(w);
                    term_cap::<C>(w).0
                })
                .ok_or_else(|| cap_error::<C>(words.get()))?;
        }
    }
}
