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
//! A quadratic with a close pair of roots, real or complex (`q` nearly a square, as the weight
//! of a conic section near a parabola), would need `log2(1 / sep)` levels: thousands for a
//! separation of `10^-1000`, each on numbers that grow with the depth. Past
//! [`QUADRATIC_SHORTCUT_DEPTH`] levels an interval whose `q` is a quadratic is therefore decided
//! by its discriminant: `c_1^2 - c_0 c_2 < 0` (Bernstein coefficients over the interval) means no
//! real root; otherwise the interval is split at the vertex `(c_0 - c_1) / (c_0 - 2 c_1 + c_2)`
//! when it lies inside (where `q != 0`, the discriminant being non-zero), and on an interval
//! without the vertex `q` is monotone, so it has a root exactly when its end values have
//! opposite signs. The intervals of ordinary polynomials are decided before that depth, so
//! their isolating intervals do not change.
//!
//! # Refinement (quadratic interval refinement)
//!
//! An isolating interval `(a, b)` of a simple root of `q` (opposite signs at the ends) is
//! narrowed by Abbott's *quadratic interval refinement* ([`refine_isolating`]): the interval is
//! cut into `N` equal parts (`N` a power of two, at first 4), the secant through `(a, q(a))`
//! and `(b, q(b))` predicts the part holding the root, and the signs at that part's ends
//! confirm it; on success the interval shrinks by the factor `N` and `N` is squared (the secant
//! converges quadratically near a simple root, so the bits gained double each step), on
//! failure the interval is bisected once and `N` goes back to its square root. Every new end is
//! `a + i (b - a) / N`, so dyadic ends stay dyadic and the numbers grow only with the bits
//! gained, unlike the secant's own iterates. A width of `2^-10240` takes a few dozen sign
//! evaluations instead of 10,240 bisections. `N` is kept at or below `2^32` in a generic ordered
//! field (the part index is found by comparisons) and grows freely where the caller can round
//! ([`refine_isolating_with`], rationals); it never exceeds what the target width asks for.
//! Before refining,
//! [`Refiner::try_refine`] checks the halvings the width asks for (`log2` of the interval width
//! over the target, an upper bound on the steps taken) against the `bisection` limit.
//!
//! # Scalars
//!
//! Everything is generic over [`OrderedField`] and exact for exact fields: the test rationals,
//! `exactcheck_exact::Rational`, and `exactcheck_exact::Radical` (coefficients with `sqrt 2`,
//! `sqrt 6`, ...; exact sign). For `f64` it compiles and is a **heuristic**: the gcd sees
//! rounding noise (usually gcd 1, so double roots are not merged), signs of coefficients near a
//! root may be wrong, and bisection stops at the resolution of `f64` (see [`unit_roots`]).
//!
//! # Which isolator where
//!
//! This is the workspace's isolator for scalars other than the rationals: the radical field
//! (`exactcheck_exact::Radical`), `f64`, and the generic geometry of this crate, which cannot
//! name the exact crate's types. Polynomials over `Q` are isolated by
//! `exactcheck_exact::univariate::isolate_real_roots` (Descartes' rule on the integer
//! coefficients, filtered by `f64`, every rational root exact): `solve` routes its rational
//! scalar there, and `exact::univariate` keeps no Bernstein subdivision of its own over `Q`.
//! The integer algorithm needs a common denominator and word-size modular arithmetic, which a
//! generic field does not have; this one needs only field operations and exact signs. The
//! quadratic interval refinement below ([`refine_isolating_with`]) is the one refinement of
//! both: the exact crate's `UPoly::refine` calls it.
//!
//! # Why hand-written
//!
//! No crate isolates roots in the Bernstein basis exactly and generically over a scalar trait
//! (the crates at hand are `f64`-only root finders or Sturm/Descartes over their own integer
//! types); the algorithm is short and reuses this crate's de Casteljau subdivision.

use crate::bernstein::Bernstein;
use crate::limits::{self, LimitError};
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

/// Narrow an isolated root of p to width <= `width` (quadratic interval refinement on the
/// square-free part, module documentation; exact grid hits become Exact).
///
/// `root` must be one returned by [`unit_roots`] (or an earlier `refine`) for the same `p`. An
/// `Exact` root is returned unchanged, as is anything when `p` is identically zero. For `f64`
/// the refinement stops when the interval no longer shrinks.
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
        self.refine_with(root, width, |_: &T| None)
    }

    /// [`Refiner::refine`] with a rounding of the scalar (see [`refine_isolating_with`]):
    /// `round(x)` is the nearest integer to `x`, or `None` where the scalar cannot tell.
    ///
    /// # Panics
    /// When `width` is not positive.
    pub fn refine_with(
        &self,
        root: &IsolatedRoot<T>,
        width: &T,
        round: impl Fn(&T) -> Option<T>,
    ) -> IsolatedRoot<T> {
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
        refine_isolating_with(|x| q.eval(x), round, lo, hi, width)
    }

    /// [`Refiner::refine`] within the `bisection` limit: the halvings from the root's
    /// interval width down to `width` ([`halvings_within_limit`]) are checked first.
    ///
    /// # Errors
    /// A [`LimitError`] of `bisection` when more halvings than the limit would be needed.
    ///
    /// # Panics
    /// When `width` is not positive.
    pub fn try_refine(
        &self,
        root: &IsolatedRoot<T>,
        width: &T,
    ) -> Result<IsolatedRoot<T>, LimitError> {
        if let IsolatedRoot::Between(lo, hi) = root {
            halvings_within_limit(&hi.sub_ref(lo), width)?;
        }
        Ok(self.refine(root, width))
    }
}

/// Checks that halving an interval of width `span` down to `width` (positive) takes at most
/// the `bisection` limit of halvings: `span <= width * 2^limit`. The halvings are an upper
/// bound on the steps of [`refine_isolating`] (each step at least halves the interval).
///
/// # Errors
/// A [`LimitError`] of `bisection` naming the halvings needed (counted up to the limit + 1).
pub fn halvings_within_limit<T: OrderedField>(span: &T, width: &T) -> Result<(), LimitError> {
    let limit = &limits::BISECTION;
    let max = limit.get();
    let two = T::one() + T::one();
    // span <= width * 2^max, tested as one power (capped at u32 exponents).
    let cap = u32::try_from(max).unwrap_or(u32::MAX);
    if *span <= width.mul_ref(&two.pow(cap)) {
        return Ok(());
    }
    Err(limit.exceeded(format!("more than {max} halvings")))
}

/// Refines the isolating interval `(lo, hi)` of a simple root of `f` (`f(lo)` and `f(hi)` of
/// opposite, non-zero signs) to width `<= width` by quadratic interval refinement (module
/// documentation) with at most `2^32` parts; exact when a grid point is the root. For `f64` it
/// stops when the interval no longer shrinks.
pub fn refine_isolating<T: OrderedField>(
    f: impl Fn(&T) -> T,
    lo: T,
    hi: T,
    width: &T,
) -> IsolatedRoot<T> {
    refine_isolating_with(f, |_: &T| None, lo, hi, width)
}

/// [`refine_isolating`] for a scalar that can round (`round(x)` = the nearest integer, as a
/// scalar; `None` when it cannot): the number of parts then grows without the `2^32` cap, so
/// the bits gained double at every successful step (rationals: a width of `2^-100000` in a few
/// dozen steps).
pub fn refine_isolating_with<T: OrderedField>(
    f: impl Fn(&T) -> T,
    round: impl Fn(&T) -> Option<T>,
    mut lo: T,
    mut hi: T,
    width: &T,
) -> IsolatedRoot<T> {
    let rounds = round(&T::zero()).is_some();
    let max_log: u32 = if rounds { u32::MAX / 2 } else { 32 };
    let two = T::one() + T::one();
    let mut f_lo = f(&lo);
    let mut f_hi = f(&hi);
    let s_lo = f_lo.sign();
    // log2 of the number of parts N.
    let mut log_n: u32 = 2;
    while hi.sub_ref(&lo) > *width {
        let w = hi.sub_ref(&lo);
        // No more parts than the width asks for: N <= 2 w / width.
        while log_n > 2 && w.checked_div(&two.pow(log_n - 1)).expect("2^k != 0") < *width {
            log_n -= 1;
        }
        let n = two.pow(log_n);
        let step = w.checked_div(&n).expect("N > 0");
        // The secant's zero is lo + w * f_lo / (f_lo - f_hi), in (lo, hi); its part index,
        // rounded, is i = round(N * f_lo / (f_lo - f_hi)) in [0, N].
        // Exactly, the end values have opposite signs, so their difference is not zero; a
        // rounding scalar can make them equal (f64 at a double root): then bisect.
        let ratio = f_lo
            .mul_ref(&n)
            .checked_div(&f_lo.sub_ref(&f_hi))
            .unwrap_or_else(|_| n.checked_div(&two).expect("2 != 0"));
        let i = match round(&ratio) {
            Some(i) if i < T::zero() => T::zero(),
            Some(i) if i > n => n.clone(),
            Some(i) => i,
            None => T::from_i64(round_index(&ratio, 1_i64 << log_n)),
        };
        let m = lo.add_ref(&step.mul_ref(&i));
        let f_m = f(&m);
        let s_m = f_m.sign();
        if s_m == Sign::Zero {
            return IsolatedRoot::Exact(m);
        }
        // The part next to m on the side of the root.
        let (a, b) = if s_m == s_lo {
            (m.clone(), m.add_ref(&step))
        } else {
            (m.sub_ref(&step), m.clone())
        };
        let inside = lo <= a && a < b && b <= hi && b.sub_ref(&a) < w;
        if inside {
            let (f_a, f_b) = if s_m == s_lo {
                (f_m, f(&b))
            } else {
                (f(&a), f_m)
            };
            let (sa, sb) = (f_a.sign(), f_b.sign());
            if sa == Sign::Zero {
                return IsolatedRoot::Exact(a);
            }
            if sb == Sign::Zero {
                return IsolatedRoot::Exact(b);
            }
            if sa == s_lo && sb != s_lo {
                (lo, hi, f_lo, f_hi) = (a, b, f_a, f_b);
                log_n = (2 * log_n).min(max_log);
                continue;
            }
        }
        // The prediction failed: bisect once and fall back to fewer parts.
        log_n = (log_n / 2).max(2);
        let mid = midpoint(&lo, &hi);
        if !(lo < mid && mid < hi) {
            break;
        }
        let f_mid = f(&mid);
        match f_mid.sign() {
            Sign::Zero => return IsolatedRoot::Exact(mid),
            s if s == s_lo => (lo, f_lo) = (mid, f_mid),
            _ => (hi, f_hi) = (mid, f_mid),
        }
    }
    IsolatedRoot::Between(lo, hi)
}

/// `round(x)` clamped to `[0, n]`, found by bisection on comparisons (works in any ordered
/// field; `n <= 2^32`).
fn round_index<T: OrderedField>(x: &T, n: i64) -> i64 {
    // Invariant: the rounding of x is in [a, b].
    let (mut a, mut b) = (0_i64, n);
    let half = T::one()
        .checked_div(&(T::one() + T::one()))
        .expect("2 != 0");
    while a < b {
        let mid = a + (b - a) / 2;
        // round(x) <= mid  iff  x < mid + 1/2.
        if *x < T::from_i64(mid).add_ref(&half) {
            b = mid;
        } else {
            a = mid + 1;
        }
    }
    a
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
    let g = if d.len() <= 1 {
        // Degree at most 1: square-free.
        vec![T::one()]
    } else if a.len() == 3 {
        // A quadratic c + b t + a t^2 is square-free exactly when its discriminant is not
        // zero (`gcd(p, p')` is `p` at `t = -b / 2a`, which is `-disc / 4a`); otherwise its
        // square-free part is `t + b / 2a`. Three products instead of a gcd with inverses (the
        // weights of the conic sections are quadratics over the radical field).
        let disc = a[1]
            .mul_ref(&a[1])
            .sub_ref(&T::from_i64(4).mul_ref(&a[0]).mul_ref(&a[2]));
        if disc.is_zero() {
            vec![a[1].clone() / T::from_i64(2).mul_ref(&a[2]), T::one()]
        } else {
            vec![T::one()]
        }
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

/// Whether every polynomial of `others` vanishes at the root `root` of `p` (`p` not identically
/// zero; `root` exact or an isolating interval of `p`'s distinct roots).
///
/// At an interval root this is decided exactly: `g = gcd(p, others)` divides `p`, so it can
/// vanish in the interval only at `p`'s one root there, and it does iff its square-free part
/// changes sign across the interval.
pub fn vanishes_at_root<T: OrderedField>(
    p: &Bernstein<T>,
    others: &[Bernstein<T>],
    root: &IsolatedRoot<T>,
) -> bool {
    if others.iter().all(Bernstein::is_zero) {
        return true;
    }
    match root {
        IsolatedRoot::Exact(t) => others.iter().all(|q| q.eval(t).is_zero()),
        IsolatedRoot::Between(lo, hi) => {
            let mut all = vec![p.clone()];
            all.extend(others.iter().cloned());
            let Ok(g) = gcd(&all) else {
                return true;
            };
            if g.degree() == 0 {
                return false;
            }
            let q = square_free(&g).expect("a gcd of non-zero polynomials is not zero");
            let (a, b) = (q.eval(lo).sign(), q.eval(hi).sign());
            a != b && a != Sign::Zero && b != Sign::Zero
        }
    }
}

/// The quotient `a / b` of a polynomial by a non-zero divisor of it (for example a gcd
/// from [`gcd`]), in Bernstein form of its exact degree; the remainder is dropped.
///
/// # Panics
/// When `b` is identically zero.
pub fn exact_quotient<T: Field>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let d = trim(b.to_power());
    assert!(
        !d.is_empty(),
        "exact_quotient: division by the zero polynomial"
    );
    let (q, _) = div_rem(&trim(a.to_power()), &d);
    if q.is_empty() {
        return Bernstein::constant(T::zero(), 0);
    }
    Bernstein::from_power(&q).expect("a non-empty coefficient list")
}

/// The coefficients of `p` restricted to `[lo, hi]` (`0 <= lo < hi <= 1`): the Bernstein form
/// of `p(lo + (hi - lo) s)`, `s` in `[0, 1]`, by two de Casteljau splits. Their least and
/// largest values bound `p` on the interval.
pub fn restrict<T: OrderedField>(p: &Bernstein<T>, lo: &T, hi: &T) -> Bernstein<T> {
    let (left, _) = p.split(hi);
    let (_, piece) = left.split(&(lo.clone() / hi.clone()));
    piece
}

/// The sign of `g` at the root `root` of `p` (`p` not identically zero; `root` exact or an
/// isolating interval of `p`'s distinct roots), decided exactly: zero when `gcd(p, g)` vanishes
/// at the root ([`vanishes_at_root`]); otherwise the interval is refined as a root of `p`
/// until the coefficients of `g` restricted to it ([`restrict`]) all have one strict sign,
/// which ends because they tend to `g`'s non-zero value at the root. For `f64` the refinement
/// stops where the interval no longer shrinks and the sign at its midpoint is taken.
pub fn sign_at_root<T: OrderedField>(
    g: &Bernstein<T>,
    p: &Bernstein<T>,
    root: &IsolatedRoot<T>,
) -> Sign {
    let (mut lo, mut hi) = match root {
        IsolatedRoot::Exact(t) => return g.eval(t).sign(),
        IsolatedRoot::Between(lo, hi) => (lo.clone(), hi.clone()),
    };
    if g.is_zero() || vanishes_at_root(p, std::slice::from_ref(g), root) {
        return Sign::Zero;
    }
    let refiner = Refiner::new(p);
    let two = T::one() + T::one();
    // The interval shrinks by a factor that squares after every undecided round (2, 4, 16,
    // 256, 65536, then 2^32 each round): a sign decided early costs few refinements, a value
    // close to zero needs few rounds however small it is.
    let mut factor = two.clone();
    let cap = T::from_i64(1 << 32);
    loop {
        let piece = restrict(g, &lo, &hi);
        let first = piece.coeffs()[0].sign();
        if first != Sign::Zero && piece.coeffs().iter().all(|c| c.sign() == first) {
            return first;
        }
        let target = hi.sub_ref(&lo) / factor.clone();
        if factor < cap {
            factor = factor.mul_ref(&factor);
        }
        match refiner.refine(&IsolatedRoot::Between(lo.clone(), hi.clone()), &target) {
            IsolatedRoot::Exact(t) => return g.eval(&t).sign(),
            IsolatedRoot::Between(a, b) => {
                if a == lo && b == hi {
                    // No progress: only an inexact scalar stops halving.
                    return g.eval(&(lo.add_ref(&hi) / two)).sign();
                }
                lo = a;
                hi = b;
            }
        }
    }
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

/// The depth from which a quadratic's close pair of roots is decided by its discriminant and
/// vertex instead of further halvings (module documentation): `2^-64` is below the separation
/// of the roots of every quadratic with moderate coefficients.
pub const QUADRATIC_SHORTCUT_DEPTH: u32 = 64;

enum Work<T> {
    /// The coefficients of `q` over `[a, b]`, and the number of splits that made the interval.
    Interval(T, T, Bernstein<T>, u32),
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
    let mut stack = vec![Work::Interval(T::zero(), T::one(), q.clone(), 0)];
    while let Some(w) = stack.pop() {
        let (a, b, poly, depth) = match w {
            Work::Emit(r) => {
                out.push(r);
                continue;
            }
            Work::Interval(a, b, poly, depth) => (a, b, poly, depth),
        };
        let v = poly.sign_changes();
        if v == 0 {
            continue;
        }
        let pc = poly.coeffs();
        if v >= 2 && depth >= QUADRATIC_SHORTCUT_DEPTH && poly.degree() == 2 {
            // A close pair of roots of a quadratic (module documentation).
            let (c0, c1, c2) = (&pc[0], &pc[1], &pc[2]);
            let lead = c0.sub_ref(&c1.add_ref(c1)).add_ref(c2);
            let disc = c1.square().sub_ref(&c0.mul_ref(c2)).sign();
            if disc == Sign::Negative {
                continue;
            }
            if disc == Sign::Positive && !lead.is_zero() {
                let s = c0.sub_ref(c1) / lead;
                if s.sign() == Sign::Positive && s < T::one() {
                    let m = a.add_ref(&b.sub_ref(&a).mul_ref(&s));
                    if a < m && m < b {
                        let (left, right) = poly.split(&s);
                        stack.push(Work::Interval(m.clone(), b, right, depth + 1));
                        stack.push(Work::Interval(a, m, left, depth + 1));
                        continue;
                    }
                } else {
                    // Monotone on [a, b]: a root inside exactly when the ends' signs differ (an
                    // end that is a root was reported where the interval was cut).
                    if c0.sign() * c2.sign() == Sign::Negative {
                        out.push(IsolatedRoot::Between(a, b));
                    }
                    continue;
                }
            }
        }
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
        stack.push(Work::Interval(m.clone(), b, right, depth + 1));
        if root_at_m {
            stack.push(Work::Emit(IsolatedRoot::Exact(m.clone())));
        }
        stack.push(Work::Interval(a, m, left, depth + 1));
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
