//! `solve` kind `ruled_line`: where a line `P + lambda D` meets the ruled surface
//! `S(s,t) = B(t) + s V(t)` (Chiang, section II.B).
//!
//! # Method
//! The ruling `t` meets the line iff `B(t) - P`, `V(t)` and `D` are linearly dependent:
//! `f(t) = det(B(t) - P, V(t), D) = 0`, a polynomial of degree `m + n`
//! ([`RuledSurface::line_polynomial`]; Chiang's `B_y V_z - B_z V_y` after moving the line onto
//! the x axis, claim `chiang.line`). Its distinct real roots in `[0, 1]` are isolated exactly by
//! Bernstein–Descartes subdivision ([`exactcheck_core::roots`]): a rational root (in the field of
//! the input) is found `Exact`, any other is an isolating interval refined to width `2^-60`.
//! At each root, with `W(t) = V(t) x D` and `U(t) = (B(t) - P) x D`:
//! * `W(t) != 0` (the ruling is not parallel to the line): one point, with
//!   `s = -((B - P) x D) . W / |W|^2` and `lambda = (X - P) . D / |D|^2` — exact at an exact
//!   root, approximations (computed at the midpoint of the refined interval) at an interval root;
//! * `W(t) = 0`, `V(t) != 0` (the ruling is parallel to the line, so `f(t) = 0` without a
//!   meeting point): the whole ruling is the line when `U(t) = 0`, otherwise no point;
//! * `V(t) = 0` (the ruling degenerates to the point `B(t)`): the point `B(t)` when it lies on
//!   the line (`U(t) = 0`; `s` is arbitrary), otherwise no point.
//!
//! At an interval root "`W(t) = 0`" is decided exactly: `gcd(f, W_x, W_y, W_z)` divides `f`, so
//! it can vanish in the isolating interval only at `f`'s one root there, and it does iff its
//! square-free part changes sign across the interval. Nothing divides by a quantity that may be
//! zero.
//!
//! A root with status `ruling_on_line` puts the whole line on the surface: the outcome is then
//! `line_on_surface`; otherwise `points` when some root gives a point, else `no_points`.
//!
//! # The covered part (when `f` is identically zero)
//! Then every ruling meets the line or is parallel to it, possibly all at one point (a cone
//! whose apex is on the line). The answer is the set of `lambda` covered by the rulings
//! `t` in `[0, 1]` (`covered`: disjoint intervals, increasing, each end exact or enclosed at an
//! irrational parameter, `closed` when covered itself, `null` when unbounded; `lambda_at_ends`
//! its least and largest end), decided exactly:
//! * If `W` is identically zero too, every ruling is parallel to the line
//!   (`parallel_to_every_ruling`): at a common zero `z` of `U` the ruling is the line when
//!   `V(z) != 0` (listed in `rulings_on_line`; the whole line is covered), and only the point
//!   `B(z)` when `V(z) = 0`.
//! * Otherwise, off the zeros of `W`, the ruling `t` meets the line at
//!   `lambda(t) = N / Q`, `N = -((B - P) x V) . W`, `Q = |W|^2`, reduced by `gcd(N, Q)` to
//!   `N1 / Q1`. At a zero `z` of `W` the ruling is the line (`V(z) != 0`, `U(z) = 0`: the whole
//!   line), the point `B(z)` (`V(z) = 0`, `U(z) = 0`), or nothing. The breakpoints are the
//!   zeros in `[0, 1]` of `c1 = N1' Q1 - N1 Q1'` and of `W` (one polynomial, isolated exactly),
//!   and `0`, `1`; between two of them `lambda` is continuous and strictly monotone (the sign of
//!   `c1` at a point between them), so each stretch covers the interval between its end values:
//!   `lambda` itself at a breakpoint off the zeros of `W` (covered), its limit `N1 / Q1` at a
//!   zero of `W` (not covered by that stretch), unbounded at a pole (`Q1 = 0`). If `c1` is zero,
//!   `lambda` is one constant. The stretches and the points `B(z)` are merged into disjoint
//!   intervals; end values are compared exactly (equal at one breakpoint; at one zero of `W` by
//!   the sign of the cross-multiplied difference there; otherwise by enclosures from the
//!   Bernstein coefficients of `N1`, `Q1` on the parameter's interval, narrowed until they
//!   separate). Two irrational end values still not ordered after [`COMPARE_STEPS`] halvings
//!   give the outcome `undecided` with a note.
//!
//! The outcome then names the covered part: `line_on_surface` (all of the line),
//! `line_segment_on_surface` (an interval of positive length, possibly unbounded, possibly
//! several), `single_point`, `isolated_points`.
//!
//! # Limits and modes
//! `m + n <= 60` ([`MAX_DEGREE`]): the Bernstein conversions use binomials `C(m+n, k)` as `u64`,
//! exact only up to `C(67, 33)`, and the exact subdivision grows quickly beyond that degree.
//! Exact mode is further held to the `ruled-work` limit, checked before any work: `m + n` times
//! the dimension `2^k` of the square-root field of the input's numbers (the subdivision's cost
//! grows about as the sixth power of the degree and several-fold per square root).
//! Exact mode reads [`ExactNumber`]s and runs over `Q` when every number is rational, over the
//! radical field otherwise. `--float` runs the same generic code over `f64`; there the zero
//! tests and the root isolation are heuristics (f64 rounding), and the answer says `mode: float`.
//!
//! Hand-written because it is the workspace's own construction (the generic surface and the
//! generic root isolation); no crate solves it exactly.

use super::number::{Coords, ExactNumber, FloatNumber};
use super::scalar::Scalar;
use super::{FloatKind, Kind};
use crate::Error;
use exactcheck_core::roots::{
    self, exact_quotient, gcd, multiplicity, refine, restrict, square_free, vanishes_at_root,
    IsolatedRoot,
};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Bernstein, Field, OrderedField, Ring, Sign, Vec3};
use exactcheck_exact::{Radical, Rational};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::cmp::Ordering;

/// The largest `m + n` answered (module doc, "Limits").
pub const MAX_DEGREE: usize = 60;

/// The problem, with numbers of type `N` ([`ExactNumber`] in exact mode, [`FloatNumber`] with
/// `--float`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(
    title = "ruled_line",
    description = "A ruled surface S(s,t) = B(t) + s V(t) (Bezier base curve B of degree n, Bezier direction field V of degree m) and a line P + lambda D (Chiang): the parameters t in [0,1] whose ruling meets the line (roots of det(B(t) - P, V(t), D), degree m+n <= 60), with s, lambda and the point. Outcomes: points, no_points, line_on_surface (a ruling is the line, or the rulings cover all of it), line_segment_on_surface / single_point / isolated_points (det vanishes identically: the covered part of the line, decided exactly, in `covered` and `lambda_at_ends`), parallel_to_every_ruling, undecided (with a note)."
)]
pub struct Input<N> {
    /// `"ruled_line"`.
    #[schemars(extend("const" = "ruled_line"))]
    pub kind: String,
    /// The control points `p_0..p_n` of the base curve `B` (at least one).
    pub base: Vec<Coords<N, 3>>,
    /// The control vectors `q_0..q_m` of the direction field `V` (at least one).
    pub directions: Vec<Coords<N, 3>>,
    /// The line.
    pub line: LineInput<N>,
}

/// The line `point + lambda direction`.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LineInput<N> {
    /// A point `P` of the line.
    pub point: Coords<N, 3>,
    /// The direction `D` (not zero).
    pub direction: Coords<N, 3>,
}

/// What happens at one root of the line polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Status {
    /// The ruling crosses the line at one point.
    Point,
    /// The ruling is parallel to the line and is the line itself.
    RulingOnLine,
    /// The ruling is parallel to the line and apart from it: no point.
    RulingParallel,
    /// `V(t) = 0`: the ruling is the point `B(t)`, which lies on the line (`s` arbitrary).
    DegenerateRulingOnLine,
    /// `V(t) = 0` and `B(t)` is not on the line: no point.
    DegenerateRulingOffLine,
}

impl Status {
    fn name(self) -> &'static str {
        match self {
            Status::Point => "point",
            Status::RulingOnLine => "ruling_on_line",
            Status::RulingParallel => "ruling_parallel",
            Status::DegenerateRulingOnLine => "degenerate_ruling_on_line",
            Status::DegenerateRulingOffLine => "degenerate_ruling_off_line",
        }
    }
}

/// One root with what was computed there (exact when `exact`, else at the refined midpoint).
struct RootReport<T> {
    root: IsolatedRoot<T>,
    multiplicity: usize,
    status: Status,
    /// Whether `s`, `lambda` and the point are exact.
    exact: bool,
    s: Option<T>,
    lambda: Option<T>,
    point: Option<Vec3<T>>,
}

enum Outcome<T> {
    /// `f` is not identically zero: its roots in [0, 1].
    Roots(Vec<RootReport<T>>),
    /// `f = 0` and `W = 0`: every ruling is parallel to the line; the line is the ruling at
    /// these roots of `U` (all `t` when `U = 0` too, `None`).
    ParallelToEveryRuling(Option<Vec<IsolatedRoot<T>>>, Covered<T>),
    /// `f = 0`, `W != 0`: every ruling meets the line or is parallel to it; the part of the
    /// line they cover.
    Covered(Covered<T>),
}

struct Analysis<T> {
    m: usize,
    n: usize,
    polynomial: Bernstein<T>,
    outcome: Outcome<T>,
}

fn dot3<T: Ring>(a: &[Bernstein<T>; 3], d: &Vec3<T>) -> [Bernstein<T>; 3] {
    // a x d, componentwise polynomials.
    let comb = |p: &Bernstein<T>, s: &T, q: &Bernstein<T>, r: &T| {
        Bernstein::new(
            p.coeffs()
                .iter()
                .zip(q.coeffs())
                .map(|(x, y)| x.mul_ref(s) - y.mul_ref(r))
                .collect(),
        )
    };
    [
        comb(&a[1], &d.z, &a[2], &d.y),
        comb(&a[2], &d.x, &a[0], &d.z),
        comb(&a[0], &d.y, &a[1], &d.x),
    ]
}

fn analyse<T: Scalar>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
) -> Analysis<T> {
    let (m, n) = surface.degrees();
    let f = surface.line_polynomial(point, direction);
    let v = surface.directions().coordinates();
    let b = surface.base().coordinates();
    let shifted = [
        shift(&b[0], &point.x),
        shift(&b[1], &point.y),
        shift(&b[2], &point.z),
    ];
    let w = dot3(&v, direction);
    let u = dot3(&shifted, direction);
    let dd = direction.norm_squared();
    let lambda_of = |x: &Vec3<T>| {
        x.add_scaled(&T::from_i64(-1), point)
            .dot(direction)
            .checked_div(&dd)
            .expect("the direction was checked to be non-zero")
    };
    let outcome = match T::unit_roots(&f) {
        Err(_) => {
            if w.iter().all(Bernstein::is_zero) {
                parallel_to_every_ruling(direction, &shifted, &v, &u)
            } else {
                Outcome::Covered(covered(surface, direction, &shifted, &w, &u))
            }
        }
        Ok(roots) => {
            let width = T::from_ratio(1, 1 << 60).expect("2^60 is not zero");
            let mut reports = Vec::new();
            for root in roots {
                let root = refine(&f, &root, &width);
                let parallel = vanishes_at_root(&f, &w, &root);
                let zero_v = parallel && vanishes_at_root(&f, &v, &root);
                let on_line = parallel && vanishes_at_root(&f, &u, &root);
                let status = match (parallel, zero_v, on_line) {
                    (false, _, _) => Status::Point,
                    (true, false, true) => Status::RulingOnLine,
                    (true, false, false) => Status::RulingParallel,
                    (true, true, true) => Status::DegenerateRulingOnLine,
                    (true, true, false) => Status::DegenerateRulingOffLine,
                };
                let t = root.midpoint();
                let (s, lambda, x) = match status {
                    Status::Point => {
                        let s = ruling_parameter(surface, point, direction, &t);
                        match s {
                            Some(s) => {
                                let x = surface.eval(&s, &t);
                                (Some(s), Some(lambda_of(&x)), Some(x))
                            }
                            // Only at an interval midpoint of a root whose W is tiny in f64.
                            None => (None, None, None),
                        }
                    }
                    Status::DegenerateRulingOnLine => {
                        let x = surface.base().eval(&t);
                        (None, Some(lambda_of(&x)), Some(x))
                    }
                    _ => (None, None, None),
                };
                reports.push(RootReport {
                    multiplicity: multiplicity(&f, &root),
                    exact: root.exact().is_some(),
                    root,
                    status,
                    s,
                    lambda,
                    point: x,
                });
            }
            Outcome::Roots(reports)
        }
    };
    Analysis {
        m,
        n,
        polynomial: f,
        outcome,
    }
}

fn shift<T: Ring>(p: &Bernstein<T>, c: &T) -> Bernstein<T> {
    Bernstein::new(p.coeffs().iter().map(|x| x.sub_ref(c)).collect())
}

/// `s = -((B - P) x D) . (V x D) / |V x D|^2` at `t`: the ruling parameter of the meeting point;
/// `None` when `V(t) x D = 0` at this `t`.
fn ruling_parameter<T: Field>(
    surface: &RuledSurface<T>,
    point: &Vec3<T>,
    direction: &Vec3<T>,
    t: &T,
) -> Option<T> {
    let w = surface.directions().eval(t).cross(direction);
    let u = surface
        .base()
        .eval(t)
        .add_scaled(&T::from_i64(-1), point)
        .cross(direction);
    u.dot(&w).neg_ref().checked_div(&w.norm_squared()).ok()
}

// ------------------------------------------------------------------ the covered part of the line

/// Halvings of a parameter interval tried when two values of `lambda` are compared (module doc,
/// "The covered part"); two irrational values still not separated after them are reported as
/// undecided.
const COMPARE_STEPS: usize = 48;

/// A value of `lambda`: `num(t) / den(t)` at the root `t` of `root_of` (exact, or an isolating
/// interval refined on demand): the meeting point of the ruling `t` when `closed`, otherwise the
/// limit of the meeting points as the parameter tends to `t` (not itself covered).
#[derive(Clone)]
struct LambdaAt<T> {
    t: IsolatedRoot<T>,
    root_of: Bernstein<T>,
    num: Bernstein<T>,
    den: Bernstein<T>,
    /// Values with one key are equal (one breakpoint).
    key: usize,
    /// The index of the parameter in the zeros of `W` (where a limit and a degenerate ruling's
    /// point sit at one parameter), if it is one.
    zero_of_w: Option<usize>,
    closed: bool,
}

impl<T: Scalar> LambdaAt<T> {
    fn exact(&self) -> Option<T> {
        let t = self.t.exact()?;
        self.num.eval(t).checked_div(&self.den.eval(t)).ok()
    }

    /// `lo <= lambda <= hi`, from the coefficients of `num` and `den` restricted to the
    /// parameter's interval; `None` while `den` has no strict sign there.
    fn enclosure(&self) -> Option<(T, T)> {
        let (lo, hi) = match &self.t {
            IsolatedRoot::Exact(_) => {
                let x = self.exact()?;
                return Some((x.clone(), x));
            }
            IsolatedRoot::Between(lo, hi) => (lo, hi),
        };
        let n = restrict(&self.num, lo, hi);
        let d = restrict(&self.den, lo, hi);
        let sign = d.coeffs()[0].sign();
        if sign == Sign::Zero || d.coeffs().iter().any(|c| c.sign() != sign) {
            return None;
        }
        let (nmin, nmax) = min_max(n.coeffs());
        let (dmin, dmax) = min_max(d.coeffs());
        let ratios = [
            nmin.clone() / dmin.clone(),
            nmin / dmax.clone(),
            nmax.clone() / dmin,
            nmax / dmax,
        ];
        Some(min_max(&ratios))
    }

    /// Halves the parameter interval; false when it cannot (exact, or f64 resolution).
    fn narrow(&mut self) -> bool {
        let IsolatedRoot::Between(lo, hi) = &self.t else {
            return false;
        };
        let half = hi.sub_ref(lo) / T::from_i64(2);
        if half.sign() != Sign::Positive {
            return false;
        }
        let next = refine(&self.root_of, &self.t, &half);
        let progressed = next != self.t;
        self.t = next;
        progressed
    }

    /// The value at the midpoint of the parameter's interval (exact at an exact parameter).
    fn approx_value(&self) -> Option<T> {
        let t = self.t.midpoint();
        self.num.eval(&t).checked_div(&self.den.eval(&t)).ok()
    }
}

fn min_max<T: OrderedField>(xs: &[T]) -> (T, T) {
    let mut lo = xs[0].clone();
    let mut hi = xs[0].clone();
    for x in &xs[1..] {
        if *x < lo {
            lo = x.clone();
        }
        if *x > hi {
            hi = x.clone();
        }
    }
    (lo, hi)
}

/// Compares two values of `lambda` exactly: equal keys are equal; two values at one zero of `W`
/// are compared by the sign of `num_a den_b - num_b den_a` there
/// ([`roots::sign_at_root`]); otherwise enclosures are narrowed until they separate.
/// `None`: two different irrational values not separated within [`COMPARE_STEPS`] halvings.
fn compare<T: Scalar>(
    a: &mut LambdaAt<T>,
    b: &mut LambdaAt<T>,
    zeros_of_w: &Bernstein<T>,
) -> Option<Ordering> {
    if a.key == b.key {
        return Some(Ordering::Equal);
    }
    if let (Some(i), Some(j)) = (a.zero_of_w, b.zero_of_w) {
        if i == j {
            // The same parameter z: sign of (num_a den_b - num_b den_a)(z) / (den_a den_b)(z).
            let (t, p) = if a.root_of == *zeros_of_w {
                (&a.t, &a.root_of)
            } else {
                (&b.t, &b.root_of)
            };
            if p == zeros_of_w {
                let diff = sub_poly(&a.num.mul(&b.den), &b.num.mul(&a.den));
                let dens = a.den.mul(&b.den);
                let s = roots::sign_at_root(&diff, p, t) * roots::sign_at_root(&dens, p, t);
                return Some(match s {
                    Sign::Negative => Ordering::Less,
                    Sign::Zero => Ordering::Equal,
                    Sign::Positive => Ordering::Greater,
                });
            }
        }
    }
    for _ in 0..COMPARE_STEPS {
        if let (Some(x), Some(y)) = (a.exact(), b.exact()) {
            return x.partial_cmp(&y);
        }
        if let (Some((al, ah)), Some((bl, bh))) = (a.enclosure(), b.enclosure()) {
            if ah < bl {
                return Some(Ordering::Less);
            }
            if bh < al {
                return Some(Ordering::Greater);
            }
        }
        let moved_a = a.narrow();
        let moved_b = b.narrow();
        if !moved_a && !moved_b {
            if T::EXACT {
                return None;
            }
            // f64: the intervals cannot shrink; compare the values at their midpoints.
            return a.approx_value()?.partial_cmp(&b.approx_value()?);
        }
    }
    None
}

/// One end of a covered interval: `None` is unbounded.
type End<T> = Option<LambdaAt<T>>;

/// A covered interval of the line, `from <= to` (in `lambda`).
#[derive(Clone)]
struct Piece<T> {
    from: End<T>,
    to: End<T>,
}

/// The covered part of the line (module doc, "The covered part").
enum Covered<T> {
    /// Every point of the line (a ruling is the line).
    WholeLine,
    /// Disjoint intervals, increasing (a point is an interval with equal closed ends).
    Pieces(Vec<Piece<T>>),
    /// Two irrational end values could not be ordered.
    Undecided,
}

fn sub_poly<T: Field>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let d = a.degree().max(b.degree());
    a.elevate_by(d - a.degree())
        .checked_sub(&b.elevate_by(d - b.degree()))
        .expect("elevated to one degree")
}

fn add_poly<T: Field>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let d = a.degree().max(b.degree());
    a.elevate_by(d - a.degree())
        .checked_add(&b.elevate_by(d - b.degree()))
        .expect("elevated to one degree")
}

/// `a x b` for polynomial vectors.
fn cross_poly<T: Field>(a: &[Bernstein<T>; 3], b: &[Bernstein<T>; 3]) -> [Bernstein<T>; 3] {
    [
        sub_poly(&a[1].mul(&b[2]), &a[2].mul(&b[1])),
        sub_poly(&a[2].mul(&b[0]), &a[0].mul(&b[2])),
        sub_poly(&a[0].mul(&b[1]), &a[1].mul(&b[0])),
    ]
}

fn dot_poly<T: Field>(a: &[Bernstein<T>; 3], b: &[Bernstein<T>; 3]) -> Bernstein<T> {
    add_poly(
        &add_poly(&a[0].mul(&b[0]), &a[1].mul(&b[1])),
        &a[2].mul(&b[2]),
    )
}

/// The single covered point `B(z)` of a degenerate ruling (`V(z) = 0`) on the line, at the
/// root `z` of `root_of`: `lambda = (B(z) - P) . D / |D|^2`.
fn base_point<T: Scalar>(
    direction: &Vec3<T>,
    shifted: &[Bernstein<T>; 3],
    root_of: &Bernstein<T>,
    z: &IsolatedRoot<T>,
    key: usize,
    zero_of_w: Option<usize>,
) -> Piece<T> {
    let num = add_poly(
        &add_poly(
            &shifted[0].scale(&direction.x),
            &shifted[1].scale(&direction.y),
        ),
        &shifted[2].scale(&direction.z),
    );
    let at = LambdaAt {
        t: z.clone(),
        root_of: root_of.clone(),
        num,
        den: Bernstein::constant(direction.norm_squared(), 0),
        key,
        zero_of_w,
        closed: true,
    };
    Piece {
        from: Some(at.clone()),
        to: Some(at),
    }
}

/// `det(B - P, V, D)` and `W = V x D` vanish identically: every ruling is parallel to the line
/// or degenerates to the point `B(t)` (`V(t) = 0`). At the common zeros `z` of `U = (B - P) x D`
/// the ruling is the line (`V(z) != 0`) or its point `B(z)` lies on it (`V(z) = 0`).
fn parallel_to_every_ruling<T: Scalar>(
    direction: &Vec3<T>,
    shifted: &[Bernstein<T>; 3],
    v: &[Bernstein<T>; 3],
    u: &[Bernstein<T>; 3],
) -> Outcome<T> {
    let Ok(zeros_of_u) = gcd(u) else {
        // U = 0: every ruling is the line or a point of it; V is not identically zero.
        return Outcome::ParallelToEveryRuling(None, Covered::WholeLine);
    };
    let zs = if zeros_of_u.degree() == 0 {
        Vec::new()
    } else {
        T::unit_roots(&zeros_of_u).expect("a gcd is not zero")
    };
    let mut on_line = Vec::new();
    let mut pieces = Vec::new();
    for (i, z) in zs.into_iter().enumerate() {
        if vanishes_at_root(&zeros_of_u, v, &z) {
            pieces.push(base_point(direction, shifted, &zeros_of_u, &z, i, None));
        } else {
            on_line.push(z);
        }
    }
    let covered = if !on_line.is_empty() {
        Covered::WholeLine
    } else {
        match merge(pieces, &zeros_of_u) {
            Some(p) => Covered::Pieces(p),
            None => Covered::Undecided,
        }
    };
    Outcome::ParallelToEveryRuling(Some(on_line), covered)
}

/// The covered part of the line when `det(B - P, V, D)` vanishes identically and `W = V x D`
/// does not (module doc, "The covered part").
fn covered<T: Scalar>(
    surface: &RuledSurface<T>,
    direction: &Vec3<T>,
    shifted: &[Bernstein<T>; 3],
    w: &[Bernstein<T>; 3],
    u: &[Bernstein<T>; 3],
) -> Covered<T> {
    let v = surface.directions().coordinates();
    let zeros_of_w = gcd(w).expect("W is not identically zero");
    let zs = if zeros_of_w.degree() == 0 {
        Vec::new()
    } else {
        T::unit_roots(&zeros_of_w).expect("a gcd is not zero")
    };
    let mut key = 0;
    let mut next_key = || {
        key += 1;
        key
    };
    let mut pieces: Vec<Piece<T>> = Vec::new();
    // The rulings at the zeros of W: parallel to the line (its whole line when on it) or, where
    // V = 0, the single point B(z) (covered when on the line).
    for (i, z) in zs.iter().enumerate() {
        if !vanishes_at_root(&zeros_of_w, u, z) {
            continue;
        }
        if !vanishes_at_root(&zeros_of_w, &v, z) {
            return Covered::WholeLine;
        }
        pieces.push(base_point(
            direction,
            shifted,
            &zeros_of_w,
            z,
            next_key(),
            Some(i),
        ));
    }
    // Elsewhere the ruling t meets the line at lambda = N / Q, N = -((B - P) x V) . W,
    // Q = |W|^2, reduced by their gcd to N1 / Q1 (continuous where Q1 != 0).
    let a = cross_poly(shifted, &v);
    let n = dot_poly(&a, w).scale(&T::from_i64(-1));
    let q = dot_poly(w, w);
    let g = gcd(&[n.clone(), q.clone()]).expect("Q is not identically zero");
    let (n1, q1) = (exact_quotient(&n, &g), exact_quotient(&q, &g));
    let c1 = sub_poly(&n1.derivative().mul(&q1), &n1.mul(&q1.derivative()));
    let value =
        |t: IsolatedRoot<T>, root_of: &Bernstein<T>, key: usize, z: Option<usize>| LambdaAt {
            t,
            root_of: root_of.clone(),
            num: n1.clone(),
            den: q1.clone(),
            key,
            zero_of_w: z,
            closed: z.is_none(),
        };
    if c1.is_zero() {
        // lambda is constant off the zeros of W: any parameter where Q1 != 0 gives it.
        let d = q1.degree() + 1;
        let t0 = (0..=d as i64)
            .map(|k| T::from_i64(k) / T::from_i64(d as i64))
            .find(|t| !q1.eval(t).is_zero())
            .expect("Q1 has at most deg Q1 zeros");
        let at = value(IsolatedRoot::Exact(t0), &q1, next_key(), None);
        pieces.push(Piece {
            from: Some(at.clone()),
            to: Some(at),
        });
    } else {
        // Breakpoints: the zeros of c1 (critical points of lambda) and of W, and 0 and 1.
        // Between two of them lambda is continuous and strictly monotone.
        let bp = c1.mul(&zeros_of_w);
        let mut marks: Vec<End<T>> = Vec::new();
        let mut params: Vec<IsolatedRoot<T>> = Vec::new();
        let mut found = T::unit_roots(&bp).expect("c1 and W's gcd are not zero");
        if found.first().and_then(IsolatedRoot::exact) != Some(&T::zero()) {
            found.insert(0, IsolatedRoot::Exact(T::zero()));
        }
        if found.last().and_then(IsolatedRoot::exact) != Some(&T::one()) {
            found.push(IsolatedRoot::Exact(T::one()));
        }
        for r in found {
            let z = zs.iter().position(|z| same_root(&zeros_of_w, z, &bp, &r));
            let pole = z.is_some()
                && q1.degree() > 0
                && vanishes_at_root(&bp, std::slice::from_ref(&q1), &r);
            marks.push((!pole).then(|| value(r.clone(), &bp, next_key(), z)));
            params.push(r);
        }
        for k in 0..params.len() - 1 {
            let inside = upper(&params[k]).add_ref(lower(&params[k + 1])) / T::from_i64(2);
            let increasing = c1.eval(&inside).sign() == Sign::Positive;
            let (left, right) = (marks[k].clone(), marks[k + 1].clone());
            pieces.push(if increasing {
                Piece {
                    from: left,
                    to: right,
                }
            } else {
                Piece {
                    from: right,
                    to: left,
                }
            });
        }
    }
    match merge(pieces, &zeros_of_w) {
        Some(p) => Covered::Pieces(p),
        None => Covered::Undecided,
    }
}

/// Whether the root `a` of `p` and the root `b` of `q` are one number.
fn same_root<T: Scalar>(
    p: &Bernstein<T>,
    a: &IsolatedRoot<T>,
    q: &Bernstein<T>,
    b: &IsolatedRoot<T>,
) -> bool {
    match (a, b) {
        (IsolatedRoot::Exact(x), IsolatedRoot::Exact(y)) => x == y,
        (IsolatedRoot::Exact(x), _) => q.eval(x).is_zero() && lower(b) < x && x < upper(b),
        (_, IsolatedRoot::Exact(y)) => p.eval(y).is_zero() && lower(a) < y && y < upper(a),
        _ => {
            // Both isolate a root of gcd(p, q) in their intersection, or neither does.
            upper(a) > lower(b) && upper(b) > lower(a) && {
                let lo = if lower(a) > lower(b) {
                    lower(a)
                } else {
                    lower(b)
                };
                let hi = if upper(a) < upper(b) {
                    upper(a)
                } else {
                    upper(b)
                };
                let common = gcd(&[p.clone(), q.clone()]).expect("p, q are not zero");
                common.degree() > 0 && {
                    let sq = square_free(&common).expect("not zero");
                    // One root of sq in [lo, hi] at most (it divides q, isolated by b);
                    // a sign change or a zero at an end shows it.
                    let (x, y) = (sq.eval(lo).sign(), sq.eval(hi).sign());
                    x != y || x == Sign::Zero
                }
            }
        }
    }
}

fn lower<T: OrderedField>(r: &IsolatedRoot<T>) -> &T {
    r.lo()
}

fn upper<T: OrderedField>(r: &IsolatedRoot<T>) -> &T {
    r.hi()
}

/// Compares two lower (or two upper) ends; unbounded is below every lower end and above every
/// upper end.
fn compare_ends<T: Scalar>(
    a: &mut End<T>,
    b: &mut End<T>,
    lower_ends: bool,
    zeros_of_w: &Bernstein<T>,
) -> Option<Ordering> {
    let unbounded = if lower_ends {
        Ordering::Less
    } else {
        Ordering::Greater
    };
    match (a, b) {
        (None, None) => Some(Ordering::Equal),
        (None, Some(_)) => Some(unbounded),
        (Some(_), None) => Some(unbounded.reverse()),
        (Some(x), Some(y)) => compare(x, y, zeros_of_w),
    }
}

/// The union of the pieces as disjoint increasing intervals; `None` when two ends could not be
/// ordered.
fn merge<T: Scalar>(mut pieces: Vec<Piece<T>>, zeros_of_w: &Bernstein<T>) -> Option<Vec<Piece<T>>> {
    // Insertion sort by the lower end (a fallible comparison).
    for i in 1..pieces.len() {
        let mut j = i;
        while j > 0 {
            let (head, tail) = pieces.split_at_mut(j);
            let ord = compare_ends(&mut head[j - 1].from, &mut tail[0].from, true, zeros_of_w)?;
            if ord != Ordering::Greater {
                break;
            }
            pieces.swap(j - 1, j);
            j -= 1;
        }
    }
    let mut out: Vec<Piece<T>> = Vec::new();
    for mut p in pieces {
        let Some(cur) = out.last_mut() else {
            out.push(p);
            continue;
        };
        // Does p start inside cur (or touch it at a covered point)?
        let joins = match (&mut cur.to, &mut p.from) {
            (None, _) | (_, None) => true,
            (Some(x), Some(y)) => match compare(y, x, zeros_of_w)? {
                Ordering::Less => true,
                Ordering::Equal => x.closed || y.closed,
                Ordering::Greater => false,
            },
        };
        if !joins {
            out.push(p);
            continue;
        }
        if let (Some(x), Some(y)) = (&mut cur.from, &mut p.from) {
            if compare(x, y, zeros_of_w)? == Ordering::Equal && y.closed {
                x.closed = true;
            }
        }
        match compare_ends(&mut p.to, &mut cur.to, false, zeros_of_w)? {
            Ordering::Greater => cur.to = p.to,
            Ordering::Equal => {
                if let (Some(x), Some(y)) = (&mut cur.to, &p.to) {
                    x.closed |= y.closed;
                }
            }
            Ordering::Less => {}
        }
    }
    Some(out)
}

// ------------------------------------------------------------------ input checks

struct Problem<T> {
    surface: RuledSurface<T>,
    point: Vec3<T>,
    direction: Vec3<T>,
}

fn vec3<N: Clone, T>(c: &Coords<N, 3>, f: impl Fn(&N) -> T) -> Vec3<T> {
    let [x, y, z] = &c.0;
    Vec3::new(f(x), f(y), f(z))
}

fn build<N: Clone, T: OrderedField>(
    input: &Input<N>,
    f: impl Fn(&N) -> T + Copy,
) -> Result<Problem<T>, Error> {
    if input.base.is_empty() {
        return Err(Error::Input(
            "base: at least one control point is required".into(),
        ));
    }
    if input.directions.is_empty() {
        return Err(Error::Input(
            "directions: at least one control vector is required".into(),
        ));
    }
    let (n, m) = (input.base.len() - 1, input.directions.len() - 1);
    if m + n > MAX_DEGREE {
        return Err(Error::Input(format!(
            "base, directions: the degree m + n = {m} + {n} = {} exceeds the limit {MAX_DEGREE}",
            m + n
        )));
    }
    let direction = vec3(&input.line.direction, f);
    if direction.is_zero() {
        return Err(Error::Input(
            "line.direction: the zero vector gives no line".into(),
        ));
    }
    let base: Vec<Vec3<T>> = input.base.iter().map(|c| vec3(c, f)).collect();
    let dirs: Vec<Vec3<T>> = input.directions.iter().map(|c| vec3(c, f)).collect();
    if dirs.iter().all(Vec3::is_zero) {
        return Err(Error::Input(
            "directions: every control vector is zero, so the surface is the curve B, not a ruled surface".into(),
        ));
    }
    let surface =
        RuledSurface::from_control(base, dirs).expect("both lists were checked to be non-empty");
    Ok(Problem {
        surface,
        point: vec3(&input.line.point, f),
        direction,
    })
}

// ------------------------------------------------------------------ answers

/// A root parameter: exact value or isolating interval, with an approximation.
#[derive(Debug, Serialize)]
struct ParamOut<S> {
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<S>,
    #[serde(skip_serializing_if = "Option::is_none")]
    interval: Option<[S; 2]>,
    approx: f64,
}

#[derive(Debug, Serialize)]
struct RootOut<S> {
    t: ParamOut<S>,
    multiplicity: usize,
    status: &'static str,
    /// Whether `s`, `lambda` and `point` are exact (else approximations at the midpoint of
    /// the isolating interval of width <= 2^-60).
    exact: bool,
    s: Option<S>,
    lambda: Option<S>,
    point: Option<[S; 3]>,
    approx: PointApprox,
}

#[derive(Debug, Serialize)]
struct PointApprox {
    s: Option<f64>,
    lambda: Option<f64>,
    point: Option<[f64; 3]>,
}

#[derive(Debug, Serialize)]
pub(crate) struct AnswerOut<S> {
    kind: &'static str,
    mode: &'static str,
    m: usize,
    n: usize,
    degree: usize,
    /// The Bernstein coefficients of `det(B(t) - P, V(t), D)`, degree `m + n`.
    polynomial: Vec<S>,
    outcome: &'static str,
    points: Vec<RootOut<S>>,
    /// `parallel_to_every_ruling`: the roots `t` whose ruling is the line (`null`: every ruling).
    #[serde(skip_serializing_if = "Option::is_none")]
    rulings_on_line: Option<Option<Vec<ParamOut<S>>>>,
    /// The covered part of the line when every ruling meets the line or a ruling is the line:
    /// disjoint intervals of `lambda`, increasing (`null` ends are unbounded).
    #[serde(skip_serializing_if = "Option::is_none")]
    covered: Option<Vec<PieceOut<S>>>,
    /// The least and the largest `lambda` of `covered` (`null`: unbounded).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_at_ends: Option<[Option<EndOut<S>>; 2]>,
    /// `undecided`: what was tried.
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<Box<AnswerOut<f64>>>,
}

/// An end of a covered interval: `lambda` exactly (`value`) or enclosed (`interval`, at an
/// irrational parameter), whether it is covered itself (`closed`), and the parameter `t` of the
/// ruling through it or whose neighbours' meeting points tend to it.
#[derive(Debug, Serialize)]
struct EndOut<S> {
    #[serde(skip_serializing_if = "Option::is_none")]
    value: Option<S>,
    #[serde(skip_serializing_if = "Option::is_none")]
    interval: Option<[S; 2]>,
    approx: f64,
    closed: bool,
    t: ParamOut<S>,
}

#[derive(Debug, Serialize)]
struct PieceOut<S> {
    from: Option<EndOut<S>>,
    to: Option<EndOut<S>>,
}

fn end_out<T: Scalar, S>(end: &End<T>, out: &impl Fn(&T) -> S) -> Option<EndOut<S>> {
    let mut e = end.clone()?;
    let exact = e.exact();
    let (value, interval) = match exact {
        Some(x) => (Some(x), None),
        None => {
            // Narrow the parameter until lambda is enclosed to 2^-50 (relative to 1 + |lambda|).
            let mut enclosure = e.enclosure();
            for _ in 0..200 {
                if let Some((lo, hi)) = &enclosure {
                    let scale = T::one() + lo.abs() + hi.abs();
                    if hi.sub_ref(lo) <= scale / T::from_ratio(1 << 50, 1).expect("not zero") {
                        break;
                    }
                }
                if !e.narrow() {
                    break;
                }
                enclosure = e.enclosure();
            }
            (None, enclosure)
        }
    };
    let approx = match (&value, &interval) {
        (Some(x), _) => x.approx(),
        (None, Some((lo, hi))) => (lo.add_ref(hi) / T::from_i64(2)).approx(),
        (None, None) => e.approx_value().map_or(0.0, |x| x.approx()),
    };
    Some(EndOut {
        value: value.map(|x| out(&x)),
        interval: interval.map(|(lo, hi)| [out(&lo), out(&hi)]),
        approx,
        closed: e.closed,
        t: param(&e.t, out),
    })
}

/// Sets `outcome`, `covered`, `lambda_at_ends` (and `note`) from the covered part of the line.
fn describe<T: Scalar, S>(answer: &mut AnswerOut<S>, covered: &Covered<T>, out: &impl Fn(&T) -> S) {
    match covered {
        Covered::WholeLine => {
            answer.outcome = "line_on_surface";
            answer.covered = Some(vec![PieceOut {
                from: None,
                to: None,
            }]);
            answer.lambda_at_ends = Some([None, None]);
        }
        Covered::Undecided => {
            answer.outcome = "undecided";
            answer.note = Some(format!(
                "the rulings meet the line in a set of parameters or limits whose end values were compared exactly where possible; two irrational end values were still not ordered after {COMPARE_STEPS} halvings of their parameters (they may be equal)"
            ));
        }
        Covered::Pieces(pieces) => {
            let points = pieces.iter().all(|p| match (&p.from, &p.to) {
                (Some(a), Some(b)) => a.key == b.key,
                _ => false,
            });
            answer.outcome =
                if pieces.len() == 1 && pieces[0].from.is_none() && pieces[0].to.is_none() {
                    "line_on_surface"
                } else if pieces.is_empty() {
                    "no_points"
                } else if !points {
                    "line_segment_on_surface"
                } else if pieces.len() == 1 {
                    "single_point"
                } else {
                    "isolated_points"
                };
            let first = pieces.first().and_then(|p| end_out(&p.from, out));
            let last = pieces.last().and_then(|p| end_out(&p.to, out));
            answer.lambda_at_ends = Some([first, last]);
            answer.covered = Some(
                pieces
                    .iter()
                    .map(|p| PieceOut {
                        from: end_out(&p.from, out),
                        to: end_out(&p.to, out),
                    })
                    .collect(),
            );
        }
    }
}

fn param<T: Scalar, S>(r: &IsolatedRoot<T>, out: &impl Fn(&T) -> S) -> ParamOut<S> {
    match r {
        IsolatedRoot::Exact(t) => ParamOut {
            value: Some(out(t)),
            interval: None,
            approx: t.approx(),
        },
        IsolatedRoot::Between(lo, hi) => ParamOut {
            value: None,
            interval: Some([out(lo), out(hi)]),
            approx: r.midpoint().approx(),
        },
    }
}

fn render<T: Scalar, S>(
    a: &Analysis<T>,
    mode: &'static str,
    out: impl Fn(&T) -> S,
) -> AnswerOut<S> {
    let v3 = |x: &Vec3<T>| [out(&x.x), out(&x.y), out(&x.z)];
    let a3 = |x: &Vec3<T>| [x.x.approx(), x.y.approx(), x.z.approx()];
    let mut answer = AnswerOut {
        kind: "ruled_line",
        mode,
        m: a.m,
        n: a.n,
        degree: a.m + a.n,
        polynomial: a.polynomial.coeffs().iter().map(&out).collect(),
        outcome: "",
        points: Vec::new(),
        rulings_on_line: None,
        covered: None,
        lambda_at_ends: None,
        note: None,
        float: None,
    };
    match &a.outcome {
        Outcome::Roots(reports) => {
            answer.outcome = if reports.iter().any(|r| r.status == Status::RulingOnLine) {
                // A ruling is the line: the whole line lies on the surface.
                describe(&mut answer, &Covered::<T>::WholeLine, &out);
                answer.outcome
            } else if reports.iter().any(|r| r.point.is_some()) {
                "points"
            } else {
                "no_points"
            };
            answer.points = reports
                .iter()
                .map(|r| RootOut {
                    t: param(&r.root, &out),
                    multiplicity: r.multiplicity,
                    status: r.status.name(),
                    exact: r.exact,
                    s: r.s.as_ref().filter(|_| r.exact).map(&out),
                    lambda: r.lambda.as_ref().filter(|_| r.exact).map(&out),
                    point: r.point.as_ref().filter(|_| r.exact).map(v3),
                    approx: PointApprox {
                        s: r.s.as_ref().map(Scalar::approx),
                        lambda: r.lambda.as_ref().map(Scalar::approx),
                        point: r.point.as_ref().map(a3),
                    },
                })
                .collect();
        }
        Outcome::ParallelToEveryRuling(roots, covered) => {
            answer.rulings_on_line = Some(
                roots
                    .as_ref()
                    .map(|rs| rs.iter().map(|r| param(r, &out)).collect()),
            );
            describe(&mut answer, covered, &out);
            answer.outcome = "parallel_to_every_ruling";
        }
        Outcome::Covered(covered) => describe(&mut answer, covered, &out),
    }
    answer
}

fn exact_answer(input: Input<ExactNumber>) -> Result<AnswerOut<String>, Error> {
    let all_rational = input
        .base
        .iter()
        .chain(&input.directions)
        .chain([&input.line.point, &input.line.direction])
        .all(|c| c.0.iter().all(|x| x.0.is_rational()));
    let k = Radical::independent_radicals_together(
        input
            .base
            .iter()
            .chain(&input.directions)
            .chain([&input.line.point, &input.line.direction])
            .flat_map(|c| c.0.iter().map(|x| &x.0)),
    );
    // Checked before the work; an empty list or a degree past MAX_DEGREE is refused by `build`.
    let degree = (input.base.len() + input.directions.len()).saturating_sub(2);
    if !input.base.is_empty() && !input.directions.is_empty() && degree <= MAX_DEGREE {
        let work = (degree as u64).saturating_mul(1u64 << k.min(62));
        exactcheck_core::limits::RULED_WORK
            .check(work)
            .map_err(|e| {
                Error::Input(format!(
                    "base, directions: m + n = {degree} with {k} independent square roots: {e}"
                ))
            })?;
    }
    if all_rational {
        let p = build(&input, |x: &ExactNumber| {
            x.0.to_rational().expect("is_rational was checked")
        })?;
        let a: Analysis<Rational> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", ToString::to_string))
    } else {
        let p = build(&input, |x: &ExactNumber| x.0.clone())?;
        let a: Analysis<Radical> = analyse(&p.surface, &p.point, &p.direction);
        Ok(render(&a, "exact", ToString::to_string))
    }
}

fn float_answer(input: Input<FloatNumber>) -> Result<AnswerOut<f64>, Error> {
    let p = build(&input, |x: &FloatNumber| x.0)?;
    let a: Analysis<f64> = analyse(&p.surface, &p.point, &p.direction);
    Ok(render(&a, "float", |x: &f64| *x + 0.0))
}

/// The kind.
pub struct RuledLine;

impl Kind for RuledLine {
    const NAME: &'static str = "ruled_line";
    type Input = Input<ExactNumber>;
    type Answer = AnswerOut<String>;

    fn compute(input: Self::Input) -> Result<Self::Answer, Error> {
        exact_answer(input)
    }
}

impl FloatKind for RuledLine {
    type FloatInput = Input<FloatNumber>;
    type FloatAnswer = AnswerOut<f64>;

    fn compute_float(input: Self::FloatInput) -> Result<Self::FloatAnswer, Error> {
        float_answer(input)
    }

    fn attach(
        answer: &mut Self::Answer,
        float: Result<Self::FloatAnswer, Error>,
    ) -> Result<(), Error> {
        answer.float = Some(Box::new(float?));
        Ok(())
    }
}
