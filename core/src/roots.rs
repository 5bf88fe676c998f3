//! Exact real roots in `[0, 1]` of a polynomial in Bernstein form: Bernstein–Descartes
//! subdivision, generic over the scalar.
//!
//! # The algorithm
//!
//! 1. **Square-free part.** The distinct roots of `p` are the roots of its square-free part
//!    `q = p / gcd(p, p')` (characteristic 0). The gcd is computed in the power basis
//!    ([`Bernstein::to_power`]) by Euclid's algorithm with a monic remainder sequence: the
//!    field is exact, so a remainder is zero exactly when it should be, and making each
//!    remainder monic keeps the coefficients of rational polynomials from growing by the
//!    leading-coefficient powers of the naive sequence. `q` goes back to Bernstein form on
//!    `[0, 1]` with [`Bernstein::from_power`].
//! 2. **End points.** `q(0) = c_0` and `q(1) = c_n` are the first and last Bernstein
//!    coefficients; a zero there is an [`IsolatedRoot::Exact`] root.
//! 3. **Descartes' rule in Bernstein form.** The Bernstein coefficients of `q` over `[a, b]` are
//!    (up to positive binomial factors) the power coefficients of
//!    `(1 + x)^n q((a + b x) / (1 + x))`, which maps `x in (0, inf)` onto `t in (a, b)`. So the
//!    number `V` of sign changes of the coefficients ([`Bernstein::sign_changes`], zeros
//!    skipped) bounds the number of roots in the *open* interval `(a, b)` and has its parity.
//!    `V = 0`: no root. `V = 1`: exactly one root; when moreover `q(a) q(b) != 0` (then the
//!    signs are opposite) it is reported as [`IsolatedRoot::Between`]. Otherwise the interval
//!    is split at its midpoint by de Casteljau ([`Bernstein::split`] at `1/2`, which gives the
//!    coefficients of `q` over both halves directly); a zero coefficient `c_n` of the left half
//!    is the exact value `q(m) = 0`, reported as [`IsolatedRoot::Exact`]`(m)`. Halves are
//!    processed left before right, so the roots come out increasing.
//!
//!    An end point that is a root does not disturb the rule: it contributes the factor `x` (or
//!    a vanishing leading coefficient) in the transformed polynomial, which removes a zero
//!    coefficient and no sign change; it is simply not counted in the open interval.
//!
//! # Termination (the Vincent / Collins–Akritas bound)
//!
//! For a square-free `q`, the one-circle theorem (Collins–Akritas; Krandick–Mehlhorn) says
//! `V = 0` on `[a, b]` when the open disc with diameter `[a, b]` contains no complex root, and
//! the two-circle theorem says `V = 1` when the union of the two discs through `a` and `b`
//! bounded by the circles at `±60°` contains exactly one root, which is simple. Every root of a
//! square-free polynomial is simple and the roots are separated by some `sep > 0`, so once the
//! bisection width is below about `sep / 2` every interval has `V <= 1`; an interval with
//! `V = 1` and a root at an end point shrinks further until its ends are dyadic points that are
//! not roots (a different root is at least `sep` away). The depth is thus
//! `O(log(1 / sep))`, and `sep` is bounded below in terms of degree and coefficient size
//! (Mahler), so the subdivision terminates. Without the square-free step a double root would
//! keep `V >= 2` forever, which is why step 1 is not optional.
//!
//! # Scalars
//!
//! Everything is generic over [`OrderedField`] and exact for exact fields: the test rationals,
//! `exactcheck_exact::Rational`, and `exactcheck_exact::Radical` (coefficients with `sqrt 2`,
//! `sqrt 6`, ...; exact sign). For `f64` it compiles and is a **heuristic**: the gcd sees
//! rounding noise (usually gcd 1, so double roots are not merged), signs of coefficients near a
//! root may be wrong, and bisection stops at the resolution of `f64` (see [`unit_roots`]).
//!
//! # Why hand-written
//!
//! No crate isolates roots in the Bernstein basis exactly and generically over a scalar trait
//! (the crates at hand are `f64`-only root finders or Sturm/Descartes over their own integer
//! types); the algorithm is short and reuses this crate's de Casteljau subdivision.

use crate::bernstein::Bernstein;
use crate::scalar::{Field, OrderedField, Sign};

/// An isolated real root in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub enum IsolatedRoot<T> {
    /// The root itself (found exactly, e.g. at a subdivision point or an end point).
    Exact(T),
    /// The open interval (lo, hi), lo < hi, holding exactly one root, where the polynomial's
    /// square-free part has opposite non-zero signs at lo and hi.
    Between(T, T),
}

impl<T: OrderedField> IsolatedRoot<T> {
    /// The lower end of the isolating interval (the root itself when exact).
    pub fn lo(&self) -> &T {
        match self {
            IsolatedRoot::Exact(x) => x,
            IsolatedRoot::Between(lo, _) => lo,
        }
    }

    /// The upper end of the isolating interval (the root itself when exact).
    pub fn hi(&self) -> &T {
        match self {
            IsolatedRoot::Exact(x) => x,
            IsolatedRoot::Between(_, hi) => hi,
        }
    }

    /// The exact value, if known.
    pub fn exact(&self) -> Option<&T> {
        match self {
            IsolatedRoot::Exact(x) => Some(x),
            IsolatedRoot::Between(..) => None,
        }
    }

    /// `hi - lo` (zero for an exact root).
    pub fn width(&self) -> T {
        self.hi().sub_ref(self.lo())
    }

    /// The midpoint `(lo + hi) / 2` (the root itself when exact): an approximation within
    /// `width / 2`.
    pub fn midpoint(&self) -> T {
        match self {
            IsolatedRoot::Exact(x) => x.clone(),
            IsolatedRoot::Between(lo, hi) => midpoint(lo, hi),
        }
    }
}

/// The polynomial is identically zero (every t is a root).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ZeroPolynomial;

impl core::fmt::Display for ZeroPolynomial {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the polynomial is identically zero (every parameter is a root)")
    }
}

impl std::error::Error for ZeroPolynomial {}

/// All distinct real roots of p in the closed interval [0, 1], increasing, each isolated.
///
/// # Errors
/// [`ZeroPolynomial`] when `p` is identically zero.
///
/// For an inexact scalar (`f64`), an interval whose midpoint rounds to one of its ends cannot be
/// halved: it is returned as a `Between` cluster that may hold several roots (or, after
/// rounding, none) — the float result is a heuristic, never a panic.
///
/// ```
/// use exactcheck_core::bernstein::Bernstein;
/// use exactcheck_core::roots::{unit_roots, IsolatedRoot};
/// // (t - 1/2)^2 (t - 1) = t^3 - 2t^2 + 5/4 t - 1/4
/// let p = Bernstein::from_power(&[-0.25, 1.25, -2.0, 1.0]).unwrap();
/// assert_eq!(
///     unit_roots(&p).unwrap(),
///     vec![IsolatedRoot::Exact(0.5), IsolatedRoot::Exact(1.0)]
/// );
/// ```
pub fn unit_roots<T: OrderedField>(
    p: &Bernstein<T>,
) -> Result<Vec<IsolatedRoot<T>>, ZeroPolynomial> {
    let q = square_free(p)?;
    Ok(isolate_square_free(&q))
}

/// The roots in `[0, 1]` of a polynomial **already known to be square-free** and non-zero (for
/// example the output of [`square_free`], or a square-free part computed by a faster gcd of
/// the caller's own, as `exactcheck_exact::univariate` does with its primitive remainder
/// sequence): step 2 onwards of the module's algorithm, without the gcd.
///
/// # Panics
/// When `q` is the zero polynomial. A `q` with a multiple root in `[0, 1]` breaks the
/// termination argument: in debug builds this is checked (by a gcd) and panics; in release
/// builds the subdivision around the multiple root does not end.
pub fn unit_roots_square_free<T: OrderedField>(q: &Bernstein<T>) -> Vec<IsolatedRoot<T>> {
    assert!(!q.is_zero(), "unit_roots_square_free: the zero polynomial");
    debug_assert!(
        {
            let a = trim(q.to_power());
            let d = derivative(&a);
            d.is_empty() || poly_gcd(&a, &d).len() == 1
        },
        "unit_roots_square_free: the polynomial is not square-free"
    );
    isolate_square_free(q)
}

/// Narrow an isolated root of p to width <= `width` (bisection on the square-free part, exact
/// midpoint hits become Exact).
///
/// `root` must be one returned by [`unit_roots`] (or an earlier `refine`) for the same `p`. An
/// `Exact` root is returned unchanged, as is anything when `p` is identically zero. For `f64`
/// the bisection stops when the midpoint no longer lies strictly inside the interval.
///
/// # Panics
/// When `width` is not positive (no bisection reaches width 0).
pub fn refine<T: OrderedField>(
    p: &Bernstein<T>,
    root: &IsolatedRoot<T>,
    width: &T,
) -> IsolatedRoot<T> {
    Refiner::new(p).refine(root, width)
}

/// [`refine`] for many roots of one polynomial: its square-free part (a gcd) is computed once,
/// not once per root.
pub struct Refiner<T> {
    /// The square-free part, `None` for the zero polynomial.
    square_free: Option<Bernstein<T>>,
}

impl<T: OrderedField> Refiner<T> {
    /// Prepares the refinement of roots of `p`.
    pub fn new(p: &Bernstein<T>) -> Self {
        Refiner {
            square_free: square_free(p).ok(),
        }
    }

    /// [`refine`] of one root of the polynomial.
    ///
    /// # Panics
    /// When `width` is not positive.
    pub fn refine(&self, root: &IsolatedRoot<T>, width: &T) -> IsolatedRoot<T> {
        assert!(
            width.sign() == Sign::Positive,
            "refine: the target width must be positive"
        );
        let (lo, hi) = match root {
            IsolatedRoot::Exact(_) => return root.clone(),
            IsolatedRoot::Between(lo, hi) => (lo.clone(), hi.clone()),
        };
        let Some(q) = &self.square_free else {
            return root.clone();
        };
        if q.degree() == 1 {
            // A line: its root is exact (see `isolate_square_free`).
            let c = q.coeffs();
            return IsolatedRoot::Exact(c[0].clone() / c[0].sub_ref(&c[1]));
        }
        let (mut lo, mut hi) = (lo, hi);
        let s_lo = q.eval(&lo).sign();
        while hi.sub_ref(&lo) > *width {
            let m = midpoint(&lo, &hi);
            if !(lo < m && m < hi) {
                break;
            }
            let s = q.eval(&m).sign();
            if s == Sign::Zero {
                return IsolatedRoot::Exact(m);
            }
            if s == s_lo {
                lo = m;
            } else {
                hi = m;
            }
        }
        IsolatedRoot::Between(lo, hi)
    }
}

/// The common real roots in [0, 1] of several polynomials (via their gcd), isolated.
///
/// Zero polynomials in the list impose no condition.
///
/// # Errors
/// [`ZeroPolynomial`] when every polynomial is identically zero (or the list is empty): then
/// every `t` is a common root.
pub fn common_unit_roots<T: OrderedField>(
    ps: &[Bernstein<T>],
) -> Result<Vec<IsolatedRoot<T>>, ZeroPolynomial> {
    let g = gcd_all(ps)?;
    let q = Bernstein::from_power(&square_free_of_power(&g))
        .expect("a non-zero polynomial has a coefficient");
    Ok(isolate_square_free(&q))
}

/// The monic gcd of the non-zero polynomials among `ps`, in Bernstein form of its exact degree.
///
/// # Errors
/// [`ZeroPolynomial`] when every polynomial is identically zero (or the list is empty).
pub fn gcd<T: OrderedField>(ps: &[Bernstein<T>]) -> Result<Bernstein<T>, ZeroPolynomial> {
    let g = gcd_all(ps)?;
    Ok(Bernstein::from_power(&g).expect("a non-zero polynomial has a coefficient"))
}

/// The square-free part `p / gcd(p, p')` (monic in the power basis), in Bernstein form of its
/// exact degree: the same distinct roots as `p`, each simple.
///
/// # Errors
/// [`ZeroPolynomial`] when `p` is identically zero.
///
/// When `p` is already square-free and of exact degree `p.degree()`, `p` itself is returned
/// (no round trip through the power basis, which matters for `f64`).
pub fn square_free<T: OrderedField>(p: &Bernstein<T>) -> Result<Bernstein<T>, ZeroPolynomial> {
    let a = trim(p.to_power());
    if a.is_empty() {
        return Err(ZeroPolynomial);
    }
    let d = derivative(&a);
    let g = if d.is_empty() {
        vec![T::one()]
    } else {
        poly_gcd(&a, &d)
    };
    let q = if g.len() == 1 {
        if a.len() == p.coeffs().len() {
            return Ok(p.clone());
        }
        monic(&a)
    } else {
        monic(&div_rem(&a, &g).0)
    };
    Ok(Bernstein::from_power(&q).expect("a non-zero polynomial has a coefficient"))
}

/// Multiplicity of an isolated root of p.
///
/// For `Exact(x)` the number of derivatives `p, p', p'', ...` vanishing at `x`; for
/// `Between(lo, hi)` (an interval from [`unit_roots`] for this `p`, so the root `r` is the only
/// root of the square-free part there) the largest `k` with `r` a root of
/// `gcd(p, p', ..., p^(k-1))`, decided by a sign change of the square-free part of that gcd over
/// `(lo, hi)`. Zero when the root is not a root of `p`, and zero for the zero polynomial (whose
/// roots have no finite multiplicity).
pub fn multiplicity<T: OrderedField>(p: &Bernstein<T>, root: &IsolatedRoot<T>) -> usize {
    if p.is_zero() {
        return 0;
    }
    match root {
        IsolatedRoot::Exact(x) => {
            let mut d = p.clone();
            let mut k = 0;
            while d.eval(x).is_zero() {
                k += 1;
                if d.degree() == 0 {
                    // A vanishing constant derivative of a non-zero p: inexact scalars only.
                    break;
                }
                d = d.derivative();
            }
            k
        }
        IsolatedRoot::Between(lo, hi) => {
            let mut deriv = trim(p.to_power());
            let mut g = deriv.clone();
            let mut k = 0;
            loop {
                let h = square_free_of_power(&g);
                let changes = horner(&h, lo).sign() * horner(&h, hi).sign() == Sign::Negative;
                if !changes {
                    return k;
                }
                k += 1;
                deriv = derivative(&deriv);
                if deriv.is_empty() {
                    return k;
                }
                g = poly_gcd(&g, &deriv);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Isolation of a square-free polynomial in Bernstein form.

/// `(a + b) / 2`.
fn midpoint<T: Field>(a: &T, b: &T) -> T {
    let two = T::one() + T::one();
    a.add_ref(b) / two
}

enum Work<T> {
    /// The coefficients of `q` over `[a, b]`.
    Interval(T, T, Bernstein<T>),
    /// A root to report once everything to its left has been.
    Emit(IsolatedRoot<T>),
}

/// The roots in `[0, 1]` of a square-free, non-zero `q`, increasing.
fn isolate_square_free<T: OrderedField>(q: &Bernstein<T>) -> Vec<IsolatedRoot<T>> {
    let mut out = Vec::new();
    let c = q.coeffs();
    let zero_at_0 = c[0].is_zero();
    let zero_at_1 = c[c.len() - 1].is_zero();
    if q.degree() == 0 {
        return out;
    }
    if zero_at_0 {
        out.push(IsolatedRoot::Exact(T::zero()));
    }
    let half = midpoint(&T::zero(), &T::one());
    let mut stack = vec![Work::Interval(T::zero(), T::one(), q.clone())];
    while let Some(w) = stack.pop() {
        let (a, b, poly) = match w {
            Work::Emit(r) => {
                out.push(r);
                continue;
            }
            Work::Interval(a, b, poly) => (a, b, poly),
        };
        let v = poly.sign_changes();
        if v == 0 {
            continue;
        }
        let pc = poly.coeffs();
        if v == 1 && poly.degree() == 1 {
            // A line: the root a + (b - a) c_0 / (c_0 - c_1) is exact.
            let frac = pc[0].clone() / pc[0].sub_ref(&pc[1]);
            out.push(IsolatedRoot::Exact(a.add_ref(&(b.sub_ref(&a) * frac))));
            continue;
        }
        if v == 1 && !pc[0].is_zero() && !pc[pc.len() - 1].is_zero() {
            out.push(IsolatedRoot::Between(a, b));
            continue;
        }
        let m = midpoint(&a, &b);
        if !(a < m && m < b) {
            // Only an inexact scalar (f64) gets here: the interval cannot be halved any more,
            // so its roots cannot be separated. Report the cluster as one interval (it may hold
            // several roots or none) instead of failing; exact scalars always halve.
            out.push(IsolatedRoot::Between(a, b));
            continue;
        }
        let (left, right) = poly.split(&half);
        let root_at_m = left.coeffs()[left.degree()].is_zero();
        stack.push(Work::Interval(m.clone(), b, right));
        if root_at_m {
            stack.push(Work::Emit(IsolatedRoot::Exact(m.clone())));
        }
        stack.push(Work::Interval(a, m, left));
    }
    if zero_at_1 {
        out.push(IsolatedRoot::Exact(T::one()));
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Power-basis arithmetic over a field: coefficient vectors `a_0..a_n`, low degree first, with no
// trailing zeros (the zero polynomial is the empty vector).

fn trim<T: Field>(mut a: Vec<T>) -> Vec<T> {
    while a.last().is_some_and(|c| c.is_zero()) {
        a.pop();
    }
    a
}

fn horner<T: Field>(a: &[T], x: &T) -> T {
    let mut acc = T::zero();
    for c in a.iter().rev() {
        acc = acc * x + c;
    }
    acc
}

fn derivative<T: Field>(a: &[T]) -> Vec<T> {
    trim(
        a.iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c.scale_i64(k as i64))
            .collect(),
    )
}

fn monic<T: Field>(a: &[T]) -> Vec<T> {
    let lc = a
        .last()
        .expect("monic of the zero polynomial")
        .inv()
        .expect("a trimmed polynomial has a non-zero leading coefficient");
    let mut m: Vec<T> = a.iter().map(|c| c.mul_ref(&lc)).collect();
    *m.last_mut().expect("non-empty") = T::one();
    m
}

/// Quotient and remainder of `a` by a non-zero `b`.
fn div_rem<T: Field>(a: &[T], b: &[T]) -> (Vec<T>, Vec<T>) {
    let db = b.len() - 1;
    if a.len() < b.len() {
        return (Vec::new(), a.to_vec());
    }
    let inv = b[db]
        .inv()
        .expect("a trimmed polynomial has a non-zero leading coefficient");
    let mut r = a.to_vec();
    let mut q = vec![T::zero(); a.len() - db];
    for k in (0..q.len()).rev() {
        let c = r[k + db].mul_ref(&inv);
        if !c.is_zero() {
            for (i, bi) in b.iter().enumerate() {
                r[k + i] -= c.mul_ref(bi);
            }
        }
        // Exact fields give zero here; set it so f64 rounding cannot leave a stray term.
        r[k + db] = T::zero();
        q[k] = c;
    }
    r.truncate(db);
    (trim(q), trim(r))
}

/// The monic gcd of two polynomials, not both zero (Euclid with monic remainders).
fn poly_gcd<T: Field>(a: &[T], b: &[T]) -> Vec<T> {
    let (mut a, mut b) = if a.len() >= b.len() {
        (a.to_vec(), b.to_vec())
    } else {
        (b.to_vec(), a.to_vec())
    };
    while !b.is_empty() {
        let (_, r) = div_rem(&a, &b);
        a = b;
        b = if r.is_empty() { r } else { monic(&r) };
    }
    monic(&a)
}

fn gcd_all<T: OrderedField>(ps: &[Bernstein<T>]) -> Result<Vec<T>, ZeroPolynomial> {
    let mut g: Option<Vec<T>> = None;
    for p in ps {
        let a = trim(p.to_power());
        if a.is_empty() {
            continue;
        }
        g = Some(match g {
            None => monic(&a),
            Some(g) => poly_gcd(&g, &a),
        });
    }
    g.ok_or(ZeroPolynomial)
}

/// `a / gcd(a, a')` for a non-zero `a`, monic.
fn square_free_of_power<T: Field>(a: &[T]) -> Vec<T> {
    let d = derivative(a);
    if d.is_empty() {
        return monic(a);
    }
    let g = poly_gcd(a, &d);
    if g.len() == 1 {
        return monic(a);
    }
    let (q, _) = div_rem(a, &g);
    monic(&q)
}

#[cfg(test)]
mod tests;
