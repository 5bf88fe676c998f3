//! Inputs near a degenerate set `{x : g(x) = 0}`: where float code decides wrongly (orient2d
//! near collinear points, a discriminant near tangency), uniform inputs almost never land.
//!
//! [`NearSet`] draws a point of a base generator (a [`crate::SampleDomain`], a box), chooses one
//! coordinate `j`, and moves `x_j` onto the set by bisection on the doubles between `x_j` and a
//! value where `g` has the other sign, every sign decided exactly by the caller's `sign`
//! function; the result is a double within one ulp of a root along `x_j`, or an exact root. That
//! point is then perturbed by [`NearDegenerate`]: each coordinate kept exactly with probability
//! 1/4, otherwise moved by a relative `2^t`, `t` uniform in `[-53, -49]` (a few ulps). A
//! perturbed point outside the base set is replaced by the unperturbed one.
//!
//! The set must be crossed: `g` must change sign along some coordinate inside the base set (a
//! set where `g` touches zero without changing sign, as `x^2 + y^2 = 0`, cannot be reached by
//! bisection). A draw that finds no crossing is retried from a fresh base point, up to
//! [`NEAR_TRIES`] times; a sample that still has no point returns NaN inputs, which the harness
//! counts as invalid inputs. [`NearSet::place`] reports the first failure before a sweep.
//!
//! Hand-written: the bisection works on the ordinal indices of doubles with exact signs, which
//! no root-finding crate offers.

use crate::gen::{InputGen, NearDegenerate};
use exactcheck_core::Rng;
use std::cmp::Ordering;

/// Base points tried per sample before it is given up.
pub const NEAR_TRIES: usize = 64;

/// The smallest and largest relative perturbation exponents after placement.
const PERTURB_EXP: (i32, i32) = (-53, -49);

/// The exact sign of `g` at an input vector; `None` where `g` is undefined (or its sign
/// undecided): such a point is never chosen.
pub type SignFn<'a> = dyn Fn(&[f64]) -> Option<Ordering> + Sync + 'a;

/// Points of `base` moved onto `g = 0` along one coordinate and perturbed by a few ulps (see
/// the module docs).
pub struct NearSet<'a, G> {
    base: G,
    sign: Box<SignFn<'a>>,
    set: String,
}

/// The ordinal index of a double (order-preserving, consecutive for adjacent doubles).
fn ordinal(x: f64) -> i64 {
    let bits = x.abs().to_bits() as i64;
    if x.is_sign_negative() {
        -bits
    } else {
        bits
    }
}

fn from_ordinal(k: i64) -> f64 {
    let mag = f64::from_bits(k.unsigned_abs());
    if k < 0 {
        -mag
    } else {
        mag
    }
}

impl<'a, G: InputGen> NearSet<'a, G> {
    /// Points of `base` near the set where `sign` is zero; `set` describes it for reports
    /// (`x*y - 1 = 0`).
    pub fn new(base: G, set: impl Into<String>, sign: Box<SignFn<'a>>) -> NearSet<'a, G> {
        NearSet {
            base,
            sign,
            set: set.into(),
        }
    }

    /// A point of the set (within an ulp along one coordinate), before perturbation: up to
    /// [`NEAR_TRIES`] base points are tried.
    ///
    /// # Errors
    /// No base point could be moved onto the set: the message says how many were tried.
    pub fn place(&self, rng: &mut Rng) -> Result<Vec<f64>, String> {
        let n = self.base.arity();
        for _ in 0..NEAR_TRIES {
            let x = self.base.sample(rng);
            let j = rng.below(n.max(1) as u64) as usize;
            let other = self.base.sample(rng);
            if let Some(y) = self.onto(x, j, &other, rng) {
                return Ok(y);
            }
        }
        Err(format!(
            "no input near {} could be placed in {NEAR_TRIES} tries: it does not change sign \
             along any input inside the domain (an empty set, a set it only touches, or an \
             expression undefined there)",
            self.set
        ))
    }

    /// `x` moved along coordinate `j` to a double next to a sign change of `g`, or `None`.
    fn onto(&self, mut x: Vec<f64>, j: usize, other: &[f64], rng: &mut Rng) -> Option<Vec<f64>> {
        if j >= x.len() {
            return None;
        }
        let s0 = (self.sign)(&x)?;
        if s0 == Ordering::Equal {
            return Some(x);
        }
        let start = x[j];
        let at = |x: &mut Vec<f64>, t: f64| -> Option<Ordering> {
            x[j] = t;
            if !self.base.contains(x) {
                return None;
            }
            (self.sign)(x)
        };
        // A value of the other sign: the other base point's coordinate, then steps of doubling
        // size on both sides.
        let scale = start.abs().max(1.0);
        let mut far = None;
        let mut candidates = vec![other.get(j).copied().unwrap_or(start)];
        for k in -40..=80 {
            let d = scale * 2f64.powi(k);
            candidates.push(start + d);
            candidates.push(start - d);
        }
        for t in candidates {
            if !t.is_finite() || t == start {
                continue;
            }
            match at(&mut x, t) {
                Some(Ordering::Equal) => return Some(x),
                Some(s) if s != s0 => {
                    far = Some(t);
                    break;
                }
                _ => {}
            }
        }
        let far = far?;
        // Bisection on the ordinal indices: `lo` keeps the sign s0, `hi` the other.
        let (mut lo, mut hi) = (ordinal(start), ordinal(far));
        while (hi - lo).abs() > 1 {
            let mid = from_ordinal(((i128::from(lo) + i128::from(hi)) / 2) as i64);
            match at(&mut x, mid)? {
                Ordering::Equal => return Some(x),
                s if s == s0 => lo = ordinal(mid),
                _ => hi = ordinal(mid),
            }
        }
        x[j] = from_ordinal(if rng.chance(0.5) { lo } else { hi });
        Some(x)
    }
}

/// The placed point, before [`NearDegenerate`]'s perturbation.
struct Placed<'s, 'a, G>(&'s NearSet<'a, G>);

impl<G: InputGen> InputGen for Placed<'_, '_, G> {
    fn arity(&self) -> usize {
        self.0.base.arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        self.0
            .place(rng)
            .unwrap_or_else(|_| vec![f64::NAN; self.arity()])
    }
}

impl<G: InputGen> InputGen for NearSet<'_, G> {
    fn arity(&self) -> usize {
        self.base.arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        let near = NearDegenerate::new(Placed(self), PERTURB_EXP.0, PERTURB_EXP.1)
            .expect("valid perturbation exponents");
        // The perturbation draws from a stream split off this one, so the placed point is the
        // same with or without it.
        let mut inner = Rng::new(rng.next_u64());
        let on_set = Placed(self).sample(rng);
        if on_set.iter().any(|v| v.is_nan()) {
            return on_set;
        }
        let perturbed = near.perturb(on_set.clone(), &mut inner);
        if self.base.contains(&perturbed) {
            perturbed
        } else {
            on_set
        }
    }
    fn describe(&self) -> String {
        format!(
            "near {}: points of {} moved onto the set along one random input (exact-sign \
             bisection to within an ulp), then each input kept w.p. 1/4 or moved by relative \
             2^[{}, {}]",
            self.set,
            self.base.describe(),
            PERTURB_EXP.0,
            PERTURB_EXP.1
        )
    }
    fn contains(&self, x: &[f64]) -> bool {
        self.base.contains(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::UniformBox;

    /// The exact sign of orient2d at six doubles.
    fn orient_sign(x: &[f64]) -> Option<Ordering> {
        let q: Vec<num_rational::BigRational> = x
            .iter()
            .map(|&v| crate::convert::f64_to_rational(v))
            .collect::<Option<_>>()?;
        let d = (&q[2] - &q[0]) * (&q[5] - &q[1]) - (&q[3] - &q[1]) * (&q[4] - &q[0]);
        Some(d.cmp(&num_rational::BigRational::from_integer(0.into())))
    }

    fn orient_f64(x: &[f64]) -> f64 {
        (x[2] - x[0]) * (x[5] - x[1]) - (x[3] - x[1]) * (x[4] - x[0])
    }

    #[test]
    fn placed_points_are_next_to_the_line() {
        let gen = UniformBox::cube(6, -1.0, 1.0).unwrap();
        let near = NearSet::new(gen, "orient2d = 0", Box::new(orient_sign));
        let mut rng = Rng::new(3);
        for _ in 0..200 {
            let x = near.place(&mut rng).unwrap();
            assert!(x.iter().all(|v| (-1.0..=1.0).contains(v)), "{x:?}");
            // Within an ulp of a sign change along one coordinate: at x the sign is zero, or
            // a neighbouring double of some coordinate has the other sign.
            let s = orient_sign(&x).unwrap();
            let crossed = s == Ordering::Equal
                || (0..6).any(|j| {
                    [-1, 1].iter().any(|d| {
                        let mut y = x.clone();
                        y[j] = from_ordinal(ordinal(x[j]) + d);
                        orient_sign(&y).is_some_and(|t| t != s)
                    })
                });
            assert!(crossed, "{x:?}");
            assert!(orient_f64(&x).abs() < 1e-12, "{x:?}");
        }
    }

    #[test]
    fn samples_are_reproducible_and_inside_the_box() {
        let gen = UniformBox::cube(6, 0.0, 1.0).unwrap();
        let near = NearSet::new(gen, "orient2d = 0", Box::new(orient_sign));
        let a = crate::sample_inputs(&near, 5, 17);
        assert_eq!(a, crate::sample_inputs(&near, 5, 17));
        assert!(near.contains(&a), "{a:?}");
        assert!(near.describe().starts_with("near orient2d = 0: points of"));
    }

    #[test]
    fn a_set_without_a_crossing_is_reported() {
        let gen = UniformBox::cube(2, -1.0, 1.0).unwrap();
        // x^2 + y^2 + 1 > 0 everywhere: no point, and the message says why.
        let near = NearSet::new(
            gen,
            "x^2 + y^2 + 1 = 0",
            Box::new(|_: &[f64]| Some(Ordering::Greater)),
        );
        let e = near.place(&mut Rng::new(1)).unwrap_err();
        assert!(e.starts_with("no input near x^2 + y^2 + 1 = 0 could be placed in 64 tries"));
        assert!(crate::sample_inputs(&near, 1, 0).iter().all(|v| v.is_nan()));
        // Undefined everywhere: the same.
        let near = NearSet::new(
            UniformBox::cube(1, 0.0, 1.0).unwrap(),
            "1/0 = 0",
            Box::new(|_: &[f64]| None),
        );
        assert!(near.place(&mut Rng::new(1)).is_err());
    }
}
