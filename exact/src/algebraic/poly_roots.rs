//! Real roots of a polynomial whose coefficients lie in a real number field `Q(theta)`
//! ([`FieldElement`]): the same answers as for rational coefficients ([`Root`], [`SignChart`],
//! [`RootBoundedInterval`]), isolating intervals with rational ends, exact exactly when the root is
//! rational.
//!
//! # Method
//! * Square-free decomposition over the field (Yun's algorithm with monic gcds computed over
//!   the field; exact, the field's zero test is exact): `p = a_1 a_2^2 ... a_k^k`, the `a_i`
//!   square-free and pairwise coprime, so a root of `a_i` is a root of `p` of multiplicity `i`,
//!   and `q = a_1 ... a_k` has the distinct roots of `p`, all simple.
//! * The norm `N(t) = Res_theta(m(theta), q(theta, t)) = prod_j q(theta_j, t)` over the conjugates
//!   `theta_j` of the generator (`m` the monic minimal polynomial) has rational coefficients, and
//!   every real root of `q` is one of its roots. It is computed by evaluating the resultant at
//!   `deg N + 1` integer points and interpolating ([`UPoly::resultant`], [`UPoly::interpolate`]).
//! * The real roots of `N` are isolated by the workspace's rational isolator
//!   ([`isolate_real_roots`]): disjoint intervals, each holding exactly one root of `N`, exact
//!   exactly when that root is rational. A root `alpha` of `N` is a root of `q` when
//!   - its interval is exact: `q(alpha) = 0`, decided in the field;
//!   - its interval `(lo, hi)` is open: `q` has no root in `[lo, hi]` other than possibly
//!     `alpha` (the ends are no roots of `N`), and `alpha` would be a simple root of `q`, so
//!     `q(alpha) = 0` exactly when `q(lo)` and `q(hi)` have opposite signs. The signs are exact
//!     field signs at rational points ([`FieldElement::signum`]).
//!
//!   The multiplicity is read off the factor `a_i` that vanishes there, by the same test. A
//!   rational root of `q` is a rational root of `N`, so its interval is exact; an irrational
//!   one is not.
//! * The sign on each gap between roots follows from the exact sign of the leading coefficient
//!   and the parities of the multiplicities, as for rational polynomials.
//! * Refinement narrows an interval as an isolating interval of the root of `N` it came from
//!   ([`UPoly::try_refine`]): to any width, within the `bisection` limit.
//!
//! The degree of `N` is the field's degree times the degree of the square-free part of `p`;
//! the field's degree is bounded by the `algebraic-degree` limit where a field is built.
//!
//! Hand-written: no crate of the dependency set isolates real roots over number fields.
//!
//! # Shared with the rational polynomials
//! What is the same logic is [`crate::univariate`]'s: the root isolation of the norm and its
//! refinement, the sign chart from the roots and the sign at `+inf` (`sign_chart_from`), the
//! set where the polynomial is `>= 0` (`nonnegative_in_chart`) and the printed layout
//! (`write_terms`; here a coefficient that is not rational is written in parentheses). What is
//! only the same shape over another coefficient type stays here: the division, gcd, Yun's
//! square-free decomposition and the multiplicity test ([`UPoly`]'s work over Q with primitive
//! remainder sequences and rational signs; these over the field, with its inverses and exact
//! field signs).

use super::{FieldElement, NumberField};
use crate::univariate::{isolate_real_roots, nonnegative_in_chart, sign_chart_from, write_terms};
use crate::univariate::{Bound, Root, RootBoundedInterval, RootInterval, SignChart, UPoly};
use crate::Rational;
use exactcheck_core::limits::LimitError;
use exactcheck_core::{Field, Ring, Sign};
use std::fmt;
use std::sync::{Arc, OnceLock};

/// A univariate polynomial with coefficients in a real number field (or rational ones), with
/// its real roots: see the [module documentation](self).
#[derive(Clone)]
pub struct FieldUPoly {
    /// Coefficients from degree 0 up; the last one (if any) is non-zero.
    coeffs: Vec<FieldElement>,
    /// The real roots with their multiplicities and the norm their intervals isolate roots of,
    /// computed on first use.
    roots: OnceLock<(Vec<Root>, UPoly)>,
}

impl FieldUPoly {
    /// The polynomial with these coefficients (from the constant up; trailing zeros dropped).
    pub fn from_coeffs(mut coeffs: Vec<FieldElement>) -> FieldUPoly {
        while coeffs.last().is_some_and(Ring::is_zero) {
            coeffs.pop();
        }
        FieldUPoly {
            coeffs,
            roots: OnceLock::new(),
        }
    }

    /// The rational polynomial `p` with its coefficients taken in `field`.
    pub fn lift(p: &UPoly, field: &Arc<NumberField>) -> FieldUPoly {
        FieldUPoly::from_coeffs(
            p.coeffs()
                .iter()
                .map(|c| FieldElement::new(field, &UPoly::constant(c.clone())))
                .collect(),
        )
    }

    /// The coefficients from the constant up.
    pub fn coeffs(&self) -> &[FieldElement] {
        &self.coeffs
    }

    /// The coefficient of `t^k` (zero beyond the degree).
    pub fn coeff(&self, k: usize) -> FieldElement {
        self.coeffs
            .get(k)
            .cloned()
            .unwrap_or_else(FieldElement::zero)
    }

    /// The degree (0 for constants and for the zero polynomial).
    pub fn degree(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Whether this is a constant (zero included).
    pub fn is_constant(&self) -> bool {
        self.coeffs.len() <= 1
    }

    /// The value at a rational point, exactly.
    pub fn eval(&self, x: &Rational) -> FieldElement {
        let x = FieldElement::rational(x.clone());
        self.coeffs
            .iter()
            .rev()
            .fold(FieldElement::zero(), |acc, c| acc * &x + c)
    }

    /// The sign at a rational point, exactly.
    pub fn sign_at(&self, x: &Rational) -> Sign {
        self.eval(x).signum()
    }

    /// The sign for large positive arguments (that of the leading coefficient).
    pub fn sign_at_pos_inf(&self) -> Sign {
        self.coeffs.last().map_or(Sign::Zero, FieldElement::signum)
    }

    /// The derivative.
    pub fn derivative(&self) -> FieldUPoly {
        FieldUPoly::from_coeffs(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.scale_i64(k as i64))
                .collect(),
        )
    }

    /// The field of the coefficients, `None` when they are all rational without one.
    fn field(&self) -> Option<&Arc<NumberField>> {
        self.coeffs.iter().find_map(FieldElement::field)
    }

    /// Quotient and remainder by the non-zero `d`, over the field.
    fn div_rem(&self, d: &FieldUPoly) -> (FieldUPoly, FieldUPoly) {
        let dd = d.degree();
        let lc_inv = d
            .coeffs
            .last()
            .expect("division by the zero polynomial")
            .inv()
            .expect("a leading coefficient is not zero");
        let mut r = self.coeffs.clone();
        let mut q = vec![FieldElement::zero(); r.len().saturating_sub(dd)];
        while r.len() > dd && !r.is_empty() {
            let top = r.len() - 1;
            let c = r[top].mul_ref(&lc_inv);
            let shift = top - dd;
            for (j, dj) in d.coeffs.iter().enumerate() {
                r[shift + j] -= &c.mul_ref(dj);
            }
            q[shift] = c;
            r.pop();
            while r.last().is_some_and(Ring::is_zero) {
                r.pop();
            }
        }
        (FieldUPoly::from_coeffs(q), FieldUPoly::from_coeffs(r))
    }

    /// The exact quotient by `d` (a divisor).
    fn div_exact(&self, d: &FieldUPoly) -> FieldUPoly {
        self.div_rem(d).0
    }

    /// The polynomial divided by its leading coefficient (zero stays zero).
    fn monic(&self) -> FieldUPoly {
        match self.coeffs.last() {
            None => self.clone(),
            Some(lc) => {
                let inv = lc.inv().expect("a leading coefficient is not zero");
                FieldUPoly::from_coeffs(self.coeffs.iter().map(|c| c.mul_ref(&inv)).collect())
            }
        }
    }

    /// The monic gcd over the field (zero for two zero polynomials).
    pub fn gcd(&self, other: &FieldUPoly) -> FieldUPoly {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let r = a.div_rem(&b).1;
            a = b;
            b = r;
        }
        a.monic()
    }

    /// Yun's square-free decomposition over the field: the non-constant monic `a_i` with
    /// `p = lc * prod a_i^i`, square-free and pairwise coprime, with their exponents `i`.
    pub fn square_free_decomposition(&self) -> Vec<(FieldUPoly, u32)> {
        let mut out = Vec::new();
        if self.is_constant() {
            return out;
        }
        let dp = self.derivative();
        let b = self.gcd(&dp);
        let mut c = self.div_exact(&b);
        let mut d = dp.div_exact(&b).sub(&c.derivative());
        let mut i = 1;
        while !c.is_constant() {
            let a = c.gcd(&d);
            c = c.div_exact(&a);
            d = d.div_exact(&a).sub(&c.derivative());
            if !a.is_constant() {
                out.push((a, i));
            }
            i += 1;
        }
        out
    }

    fn sub(&self, other: &FieldUPoly) -> FieldUPoly {
        let n = self.coeffs.len().max(other.coeffs.len());
        FieldUPoly::from_coeffs((0..n).map(|k| self.coeff(k) - other.coeff(k)).collect())
    }

    /// The product.
    pub fn mul(&self, other: &FieldUPoly) -> FieldUPoly {
        if self.is_zero() || other.is_zero() {
            return FieldUPoly::from_coeffs(Vec::new());
        }
        let mut out = vec![FieldElement::zero(); self.coeffs.len() + other.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in other.coeffs.iter().enumerate() {
                out[i + j] += &a.mul_ref(b);
            }
        }
        FieldUPoly::from_coeffs(out)
    }

    /// The norm `prod_j p(theta_j, t)` over the conjugates of the field's generator: a rational
    /// polynomial of degree `deg(field) * deg(p)` whose roots include those of `p` (`p` itself
    /// when no coefficient carries a field).
    pub fn norm(&self) -> UPoly {
        let Some(field) = self.field() else {
            return UPoly::from_coeffs(self.coeffs.iter().map(|c| c.poly().coeff(0)).collect());
        };
        let m = field.modulus();
        let points: Vec<(Rational, Rational)> = (0..=field.degree() * self.degree())
            .map(|k| {
                let t = Rational::from_integer(k as i64);
                let g = self
                    .coeffs
                    .iter()
                    .rev()
                    .fold(UPoly::zero(), |acc, c| acc.scale(&t).add_ref(c.poly()));
                (t, m.resultant(&g))
            })
            .collect();
        UPoly::interpolate(&points)
    }

    /// The distinct real roots with their multiplicities, increasing, and the norm whose roots
    /// their intervals isolate (see the [module documentation](self)).
    fn roots_and_norm(&self) -> &(Vec<Root>, UPoly) {
        self.roots.get_or_init(|| {
            let factors = self.square_free_decomposition();
            let q = factors.iter().fold(
                FieldUPoly::from_coeffs(vec![FieldElement::one()]),
                |acc, (a, _)| acc.mul(a),
            );
            if q.is_constant() {
                return (Vec::new(), UPoly::one());
            }
            let norm = q.norm();
            let vanishes = |f: &FieldUPoly, ri: &RootInterval| {
                if ri.is_exact() {
                    f.eval(&ri.lo).is_zero()
                } else {
                    f.sign_at(&ri.lo) != f.sign_at(&ri.hi)
                }
            };
            let roots = isolate_real_roots(&norm)
                .into_iter()
                .filter(|ri| vanishes(&q, ri))
                .map(|interval| {
                    let multiplicity = factors
                        .iter()
                        .find(|(a, _)| vanishes(a, &interval))
                        .map(|(_, i)| *i)
                        .expect("a root of the square-free part is a root of one factor");
                    Root {
                        interval,
                        multiplicity,
                    }
                })
                .collect();
            (roots, norm)
        })
    }

    /// The distinct real roots with their multiplicities, increasing; each interval is exact
    /// exactly when the root is rational. Empty for constants and for the zero polynomial.
    pub fn roots(&self) -> Vec<Root> {
        self.roots_and_norm().0.clone()
    }

    /// The number of distinct real roots.
    pub fn count_real_roots(&self) -> usize {
        self.roots_and_norm().0.len()
    }

    /// A refinement of width at most `width` of the interval `ri` of one of [`FieldUPoly::roots`]
    /// (or of an earlier refinement of it), holding the same root.
    ///
    /// # Errors
    /// A [`LimitError`] of `bisection` when more halvings than the limit would be needed.
    pub fn try_refine(
        &self,
        ri: &RootInterval,
        width: &Rational,
    ) -> Result<RootInterval, LimitError> {
        if ri.is_exact() {
            return Ok(ri.clone());
        }
        self.roots_and_norm().1.try_refine(ri, width)
    }

    /// The roots with multiplicities and the sign on every gap between them.
    pub fn sign_chart(&self) -> SignChart {
        sign_chart_from(self.roots(), self.sign_at_pos_inf())
    }

    /// The set `{t : p(t) >= 0}` as disjoint closed intervals, increasing (as
    /// [`UPoly::nonnegative_set`]).
    pub fn nonnegative_set(&self) -> Vec<RootBoundedInterval> {
        if self.is_zero() {
            return vec![RootBoundedInterval {
                lo: Bound::NegInf,
                hi: Bound::PosInf,
            }];
        }
        nonnegative_in_chart(self.sign_chart())
    }

    /// Whether `p(t) > 0` for some real `t`: a positive leading coefficient or a real root of
    /// odd multiplicity.
    pub fn positive_somewhere(&self) -> bool {
        self.sign_at_pos_inf() == Sign::Positive
            || self
                .roots_and_norm()
                .0
                .iter()
                .any(|r| r.multiplicity % 2 == 1)
    }

    /// The polynomial printed in the variable `var`: its terms from the highest degree down, a
    /// coefficient that is not a plain rational in parentheses.
    pub fn display<'a>(&'a self, var: &'a str) -> FieldUPolyDisplay<'a> {
        FieldUPolyDisplay { poly: self, var }
    }
}

impl PartialEq for FieldUPoly {
    fn eq(&self, other: &FieldUPoly) -> bool {
        self.coeffs == other.coeffs
    }
}

impl fmt::Debug for FieldUPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "FieldUPoly({})", self.display("t"))
    }
}

/// A [`FieldUPoly`] with its variable name, for printing ([`FieldUPoly::display`]).
pub struct FieldUPolyDisplay<'a> {
    poly: &'a FieldUPoly,
    var: &'a str,
}

impl fmt::Display for FieldUPolyDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let terms = self.poly.coeffs.iter().enumerate().rev();
        write_terms(
            f,
            self.var,
            terms.filter(|(_, c)| !c.is_zero()).map(|(k, c)| {
                let text = c.to_string();
                match (c.is_rational(), text.strip_prefix('-')) {
                    (true, Some(rest)) => (k, true, rest.to_string()),
                    (true, None) => (k, false, text),
                    (false, _) => (k, false, format!("({text})")),
                }
            }),
        )
    }
}
