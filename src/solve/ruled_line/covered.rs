//! The part of the line covered by the rulings when `f` is identically zero (the module doc of
//! `ruled_line`, "The covered part").

use super::analysis::Outcome;
use crate::solve::scalar::Scalar;
use exactcheck_core::roots::{
    self, exact_quotient, gcd, refine, restrict, square_free, vanishes_at_root, IsolatedRoot,
};
use exactcheck_core::ruled::RuledSurface;
use exactcheck_core::{Bernstein, Field, OrderedField, Sign, Vec3};
use std::cmp::Ordering;

/// Halvings of a parameter interval tried when two values of `lambda` are compared (module doc,
/// "The covered part"); two irrational values still not separated after them are reported as
/// undecided.
pub(super) const COMPARE_STEPS: usize = 48;

/// A value of `lambda`: `num(t) / den(t)` at the root `t` of `root_of` (exact, or an isolating
/// interval refined on demand): the meeting point of the ruling `t` when `closed`, otherwise the
/// limit of the meeting points as the parameter tends to `t` (not itself covered).
#[derive(Clone)]
pub(super) struct LambdaAt<T> {
    pub(super) t: IsolatedRoot<T>,
    pub(super) root_of: Bernstein<T>,
    pub(super) num: Bernstein<T>,
    pub(super) den: Bernstein<T>,
    /// Values with one key are equal (one breakpoint).
    pub(super) key: usize,
    /// The index of the parameter in the zeros of `W` (where a limit and a degenerate ruling's
    /// point sit at one parameter), if it is one.
    pub(super) zero_of_w: Option<usize>,
    pub(super) closed: bool,
}

impl<T: Scalar> LambdaAt<T> {
    pub(super) fn exact(&self) -> Option<T> {
        let t = self.t.exact()?;
        self.num.eval(t).checked_div(&self.den.eval(t)).ok()
    }

    /// `lo <= lambda <= hi`, from the coefficients of `num` and `den` restricted to the
    /// parameter's interval; `None` while `den` has no strict sign there.
    pub(super) fn enclosure(&self) -> Option<(T, T)> {
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
    pub(super) fn narrow(&mut self) -> bool {
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
    pub(super) fn approx_value(&self) -> Option<T> {
        let t = self.t.midpoint();
        self.num.eval(&t).checked_div(&self.den.eval(&t)).ok()
    }
}

pub(super) fn min_max<T: OrderedField>(xs: &[T]) -> (T, T) {
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
pub(super) fn compare<T: Scalar>(
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
pub(super) type End<T> = Option<LambdaAt<T>>;

/// A covered interval of the line, `from <= to` (in `lambda`).
#[derive(Clone)]
pub(super) struct Piece<T> {
    pub(super) from: End<T>,
    pub(super) to: End<T>,
}

/// The covered part of the line (module doc, "The covered part").
pub(super) enum Covered<T> {
    /// Every point of the line (a ruling is the line).
    WholeLine,
    /// Disjoint intervals, increasing (a point is an interval with equal closed ends).
    Pieces(Vec<Piece<T>>),
    /// Two irrational end values could not be ordered.
    Undecided,
}

pub(super) fn sub_poly<T: Field>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let d = a.degree().max(b.degree());
    a.elevate_by(d - a.degree())
        .checked_sub(&b.elevate_by(d - b.degree()))
        .expect("elevated to one degree")
}

pub(super) fn add_poly<T: Field>(a: &Bernstein<T>, b: &Bernstein<T>) -> Bernstein<T> {
    let d = a.degree().max(b.degree());
    a.elevate_by(d - a.degree())
        .checked_add(&b.elevate_by(d - b.degree()))
        .expect("elevated to one degree")
}

/// `a x b` for polynomial vectors.
pub(super) fn cross_poly<T: Field>(
    a: &[Bernstein<T>; 3],
    b: &[Bernstein<T>; 3],
) -> [Bernstein<T>; 3] {
    [
        sub_poly(&a[1].mul(&b[2]), &a[2].mul(&b[1])),
        sub_poly(&a[2].mul(&b[0]), &a[0].mul(&b[2])),
        sub_poly(&a[0].mul(&b[1]), &a[1].mul(&b[0])),
    ]
}

pub(super) fn dot_poly<T: Field>(a: &[Bernstein<T>; 3], b: &[Bernstein<T>; 3]) -> Bernstein<T> {
    add_poly(
        &add_poly(&a[0].mul(&b[0]), &a[1].mul(&b[1])),
        &a[2].mul(&b[2]),
    )
}

/// The single covered point `B(z)` of a degenerate ruling (`V(z) = 0`) on the line, at the
/// root `z` of `root_of`: `lambda = (B(z) - P) . D / |D|^2`.
pub(super) fn base_point<T: Scalar>(
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
pub(super) fn parallel_to_every_ruling<T: Scalar>(
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
pub(super) fn covered<T: Scalar>(
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
pub(super) fn same_root<T: Scalar>(
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

pub(super) fn lower<T: OrderedField>(r: &IsolatedRoot<T>) -> &T {
    r.lo()
}

pub(super) fn upper<T: OrderedField>(r: &IsolatedRoot<T>) -> &T {
    r.hi()
}

/// Compares two lower (or two upper) ends; unbounded is below every lower end and above every
/// upper end.
pub(super) fn compare_ends<T: Scalar>(
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
pub(super) fn merge<T: Scalar>(
    mut pieces: Vec<Piece<T>>,
    zeros_of_w: &Bernstein<T>,
) -> Option<Vec<Piece<T>>> {
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
