//! Input generators for the regression harness: where the random inputs come from.
//!
//! A generator draws one input vector (the formula's arguments, all finite doubles) from a
//! [`Rng`]. The built-ins cover the three regimes a float kernel should be regressed on:
//!
//! * [`UniformBox`] — uniform in an axis-aligned box: the typical case;
//! * [`LogUniform`] — magnitudes spread evenly over many binades, random signs: scaling,
//!   underflow and overflow behaviour;
//! * [`NearDegenerate`] — a degenerate base point (from any generator: [`Fixed`], [`Diagonal`],
//!   ...) plus tiny relative perturbations, some coordinates left exactly on the degeneracy:
//!   the inputs where cancellation happens and where exact and float answers part ways.
//!
//! Constructors validate their parameters and return a [`GenError`] instead of panicking.

use exactcheck_core::Rng;

/// Invalid parameters for a built-in generator.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GenError(pub String);

impl std::fmt::Display for GenError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid input generator: {}", self.0)
    }
}

impl std::error::Error for GenError {}

/// A source of random input vectors for a formula.
///
/// `sample` must return `arity()` finite doubles; the harness counts and skips any sample that
/// does not (see [`crate::Report::invalid_inputs`]). It must depend only on the draws it makes
/// from `rng`, so that runs are reproducible from their seed.
pub trait InputGen {
    /// The length of every input vector.
    fn arity(&self) -> usize;
    /// One input vector.
    fn sample(&self, rng: &mut Rng) -> Vec<f64>;
    /// A one-line description for reports.
    fn describe(&self) -> String {
        format!("custom generator ({} inputs)", self.arity())
    }
    /// Whether `x` lies in the set this generator samples (its box, its domain): a worst case
    /// is shrunk only to inputs inside it, so a shrunk case stays a case of the sweep. By
    /// default every input vector of the right length.
    fn contains(&self, x: &[f64]) -> bool {
        x.len() == self.arity()
    }
}

impl<G: InputGen + ?Sized> InputGen for &G {
    fn arity(&self) -> usize {
        (**self).arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        (**self).sample(rng)
    }
    fn describe(&self) -> String {
        (**self).describe()
    }
    fn contains(&self, x: &[f64]) -> bool {
        (**self).contains(x)
    }
}

impl<G: InputGen + ?Sized> InputGen for Box<G> {
    fn arity(&self) -> usize {
        (**self).arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        (**self).sample(rng)
    }
    fn describe(&self) -> String {
        (**self).describe()
    }
    fn contains(&self, x: &[f64]) -> bool {
        (**self).contains(x)
    }
}

fn check_finite(what: &str, xs: &[f64]) -> Result<(), GenError> {
    match xs.iter().position(|x| !x.is_finite()) {
        Some(i) => Err(GenError(format!("{what}[{i}] = {} is not finite", xs[i]))),
        None => Ok(()),
    }
}

/// Inputs uniform in the box `[lo_0, hi_0] × ... × [lo_{n-1}, hi_{n-1}]`.
#[derive(Clone, Debug, PartialEq)]
pub struct UniformBox {
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl UniformBox {
    /// The box with corners `lo` and `hi`.
    ///
    /// # Errors
    /// When the corners differ in length, or hold a non-finite bound or `lo[i] > hi[i]`.
    pub fn new(lo: Vec<f64>, hi: Vec<f64>) -> Result<UniformBox, GenError> {
        if lo.len() != hi.len() {
            return Err(GenError(format!(
                "box corners of lengths {} and {}",
                lo.len(),
                hi.len()
            )));
        }
        check_finite("lo", &lo)?;
        check_finite("hi", &hi)?;
        if let Some(i) = (0..lo.len()).find(|&i| lo[i] > hi[i]) {
            return Err(GenError(format!(
                "lo[{i}] = {} > hi[{i}] = {}",
                lo[i], hi[i]
            )));
        }
        Ok(UniformBox { lo, hi })
    }

    /// The cube `[lo, hi]^arity`.
    ///
    /// # Errors
    /// As [`UniformBox::new`].
    pub fn cube(arity: usize, lo: f64, hi: f64) -> Result<UniformBox, GenError> {
        UniformBox::new(vec![lo; arity], vec![hi; arity])
    }
}

impl InputGen for UniformBox {
    fn arity(&self) -> usize {
        self.lo.len()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        self.lo
            .iter()
            .zip(&self.hi)
            .map(|(&lo, &hi)| rng.uniform(lo, hi))
            .collect()
    }
    fn describe(&self) -> String {
        let lo_all = self.lo.iter().all(|&x| Some(&x) == self.lo.first());
        let hi_all = self.hi.iter().all(|&x| Some(&x) == self.hi.first());
        match (self.lo.first(), self.hi.first()) {
            (Some(lo), Some(hi)) if lo_all && hi_all => {
                format!("uniform in [{lo:?}, {hi:?}]^{}", self.lo.len())
            }
            _ => format!("uniform in the box {:?} .. {:?}", self.lo, self.hi),
        }
    }
    fn contains(&self, x: &[f64]) -> bool {
        x.len() == self.lo.len()
            && x.iter()
                .zip(self.lo.iter().zip(&self.hi))
                .all(|(v, (lo, hi))| lo <= v && v <= hi)
    }
}

/// Inputs with magnitudes `2^t`, `t` uniform in `[min_exp, max_exp]`, and random signs
/// (or positive only, see [`LogUniform::positive`]).
#[derive(Clone, Debug, PartialEq)]
pub struct LogUniform {
    arity: usize,
    min_exp: f64,
    max_exp: f64,
    signed: bool,
}

impl LogUniform {
    /// `arity` inputs with magnitudes log-uniform between `2^min_exp` and `2^max_exp`.
    ///
    /// # Errors
    /// When `min_exp > max_exp` or either lies outside `[-1074, 1023]` (the binades of f64).
    pub fn new(arity: usize, min_exp: i32, max_exp: i32) -> Result<LogUniform, GenError> {
        if min_exp > max_exp || min_exp < -1074 || max_exp > 1023 {
            return Err(GenError(format!(
                "log-uniform exponents [{min_exp}, {max_exp}] must be ordered and within [-1074, 1023]"
            )));
        }
        Ok(LogUniform {
            arity,
            min_exp: f64::from(min_exp),
            max_exp: f64::from(max_exp),
            signed: true,
        })
    }

    /// The same magnitudes, all positive.
    pub fn positive(mut self) -> LogUniform {
        self.signed = false;
        self
    }
}

/// `2^t` for real `t` in `[-1074, 1024)`, finite and positive or zero.
fn exp2_finite(t: f64) -> f64 {
    let whole = t.floor();
    let mag = (t - whole).exp2() * crate::convert::pow2(whole as i32);
    if mag.is_finite() {
        mag
    } else {
        f64::MAX
    }
}

impl InputGen for LogUniform {
    fn arity(&self) -> usize {
        self.arity
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        (0..self.arity)
            .map(|_| {
                let mag = exp2_finite(rng.uniform(self.min_exp, self.max_exp));
                if self.signed {
                    rng.sign() * mag
                } else {
                    mag
                }
            })
            .collect()
    }
    fn describe(&self) -> String {
        format!(
            "log-uniform |x| in [2^{}, 2^{}]{}, {} inputs",
            self.min_exp,
            self.max_exp,
            if self.signed {
                " with random signs"
            } else {
                ", positive"
            },
            self.arity
        )
    }
    /// Magnitudes in `[2^min_exp, 2^max_exp]`, positive when the generator is.
    fn contains(&self, x: &[f64]) -> bool {
        // The exponents are integers in [-1074, 1023]: both powers are doubles.
        let lo = crate::convert::pow2(self.min_exp as i32);
        let hi = crate::convert::pow2(self.max_exp as i32);
        x.len() == self.arity
            && x.iter()
                .all(|&v| (self.signed || v > 0.0) && lo <= v.abs() && v.abs() <= hi)
    }
}

/// Always the same input vector (a base point for [`NearDegenerate`], or a single regression).
#[derive(Clone, Debug, PartialEq)]
pub struct Fixed(Vec<f64>);

impl Fixed {
    /// The constant generator of `point`.
    ///
    /// # Errors
    /// When a coordinate is not finite.
    pub fn new(point: Vec<f64>) -> Result<Fixed, GenError> {
        check_finite("point", &point)?;
        Ok(Fixed(point))
    }
}

impl InputGen for Fixed {
    fn arity(&self) -> usize {
        self.0.len()
    }
    fn sample(&self, _rng: &mut Rng) -> Vec<f64> {
        self.0.clone()
    }
    fn describe(&self) -> String {
        format!("the point {:?}", self.0)
    }
    fn contains(&self, x: &[f64]) -> bool {
        x == self.0.as_slice()
    }
}

/// `arity` copies of one value uniform in `[lo, hi]`: points on the diagonal `x_0 = ... = x_{n-1}`,
/// the degenerate base of "nearly equal inputs" (`a*a - b*b` at `a ≈ b`, `1/(x - y)` at `x ≈ y`).
#[derive(Clone, Debug, PartialEq)]
pub struct Diagonal {
    arity: usize,
    lo: f64,
    hi: f64,
}

impl Diagonal {
    /// The diagonal generator.
    ///
    /// # Errors
    /// When a bound is not finite or `lo > hi`.
    pub fn new(arity: usize, lo: f64, hi: f64) -> Result<Diagonal, GenError> {
        check_finite("bounds", &[lo, hi])?;
        if lo > hi {
            return Err(GenError(format!("lo = {lo} > hi = {hi}")));
        }
        Ok(Diagonal { arity, lo, hi })
    }
}

impl InputGen for Diagonal {
    fn arity(&self) -> usize {
        self.arity
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        vec![rng.uniform(self.lo, self.hi); self.arity]
    }
    fn describe(&self) -> String {
        format!(
            "the diagonal x_i = t, t uniform in [{:?}, {:?}], {} inputs",
            self.lo, self.hi, self.arity
        )
    }
    fn contains(&self, x: &[f64]) -> bool {
        x.len() == self.arity && x.iter().all(|&v| v == x[0] && self.lo <= v && v <= self.hi)
    }
}

/// A base point from another generator plus tiny perturbations.
///
/// Each coordinate `b` of the base point is left unchanged with probability `keep` (so exactly
/// degenerate inputs occur too), and otherwise becomes the double nearest to
/// `b ± |b|·2^t` (`b ± 2^t` when `b = 0`) with `t` uniform in `[min_exp, max_exp]` and a random
/// sign. A perturbation that would not be finite leaves the coordinate unchanged.
#[derive(Clone, Debug, PartialEq)]
pub struct NearDegenerate<G> {
    base: G,
    min_exp: f64,
    max_exp: f64,
    keep: f64,
}

impl<G: InputGen> NearDegenerate<G> {
    /// Perturbations of relative size between `2^min_exp` and `2^max_exp` around points of
    /// `base`, each coordinate kept exact with probability 1/4.
    ///
    /// # Errors
    /// When `min_exp > max_exp` or either lies outside `[-1074, 1023]`.
    pub fn new(base: G, min_exp: i32, max_exp: i32) -> Result<NearDegenerate<G>, GenError> {
        if min_exp > max_exp || min_exp < -1074 || max_exp > 1023 {
            return Err(GenError(format!(
                "perturbation exponents [{min_exp}, {max_exp}] must be ordered and within [-1074, 1023]"
            )));
        }
        Ok(NearDegenerate {
            base,
            min_exp: f64::from(min_exp),
            max_exp: f64::from(max_exp),
            keep: 0.25,
        })
    }

    /// The same generator keeping each coordinate unperturbed with probability `keep`.
    ///
    /// # Errors
    /// When `keep` is not in `[0, 1]`.
    pub fn with_keep_probability(mut self, keep: f64) -> Result<NearDegenerate<G>, GenError> {
        if !(0.0..=1.0).contains(&keep) {
            return Err(GenError(format!(
                "keep probability {keep} is not in [0, 1]"
            )));
        }
        self.keep = keep;
        Ok(self)
    }
}

impl<G: InputGen> InputGen for NearDegenerate<G> {
    fn arity(&self) -> usize {
        self.base.arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        let x = self.base.sample(rng);
        self.perturb(x, rng)
    }
    fn describe(&self) -> String {
        format!(
            "near-degenerate: {}, perturbed by relative 2^[{}, {}] (kept exact w.p. {})",
            self.base.describe(),
            self.min_exp,
            self.max_exp,
            self.keep
        )
    }
    // `contains` is the default: the perturbations reach every input near the base set (any
    // relative size down to `2^min_exp`, exact coordinates kept), which is no simpler set to
    // test, so shrinking is not restricted.
}

impl<G> NearDegenerate<G> {
    /// The perturbation of [`InputGen::sample`] applied to a given point `x`.
    pub fn perturb(&self, mut x: Vec<f64>, rng: &mut Rng) -> Vec<f64> {
        for b in &mut x {
            // Draw the same number of values whatever the branch, so that coordinates do not
            // shift each other's streams.
            let keep = rng.chance(self.keep);
            let t = rng.uniform(self.min_exp, self.max_exp);
            let sign = rng.sign();
            if keep || !b.is_finite() {
                continue;
            }
            let scale = if *b == 0.0 { 1.0 } else { b.abs() };
            let y = *b + sign * scale * exp2_finite(t);
            if y.is_finite() {
                *b = y;
            }
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_ins_sample_finite_inputs_of_their_arity() {
        let gens: Vec<Box<dyn InputGen>> = vec![
            Box::new(UniformBox::new(vec![-1.0, 0.0], vec![1.0, 1e300]).unwrap()),
            Box::new(UniformBox::cube(3, -f64::MAX, f64::MAX).unwrap()),
            Box::new(LogUniform::new(4, -1074, 1023).unwrap()),
            Box::new(LogUniform::new(2, -10, 10).unwrap().positive()),
            Box::new(
                NearDegenerate::new(Diagonal::new(2, -1e308, 1e308).unwrap(), -60, 2).unwrap(),
            ),
            Box::new(
                NearDegenerate::new(Fixed::new(vec![0.0, 1.0, f64::MAX]).unwrap(), -1074, 1023)
                    .unwrap(),
            ),
        ];
        let mut rng = Rng::new(1);
        for g in &gens {
            for _ in 0..500 {
                let x = g.sample(&mut rng);
                assert_eq!(x.len(), g.arity());
                assert!(
                    x.iter().all(|v| v.is_finite()),
                    "{} gave {x:?}",
                    g.describe()
                );
            }
        }
    }

    #[test]
    fn ranges_are_respected() {
        let mut rng = Rng::new(2);
        let b = UniformBox::new(vec![1.0, -5.0], vec![2.0, -4.0]).unwrap();
        let l = LogUniform::new(1, -3, 3).unwrap().positive();
        for _ in 0..500 {
            let x = b.sample(&mut rng);
            assert!((1.0..=2.0).contains(&x[0]) && (-5.0..=-4.0).contains(&x[1]));
            let y = l.sample(&mut rng)[0];
            assert!((0.125..=8.0).contains(&y), "{y}");
        }
    }

    #[test]
    fn near_degenerate_is_near_and_sometimes_exact() {
        let mut rng = Rng::new(3);
        let g = NearDegenerate::new(Diagonal::new(2, 1.0, 2.0).unwrap(), -40, -20).unwrap();
        let (mut equal, mut near) = (0, 0);
        for _ in 0..1000 {
            let x = g.sample(&mut rng);
            if x[0] == x[1] {
                equal += 1;
            } else {
                assert!(((x[0] - x[1]) / x[0]).abs() < 3.0 * 2f64.powi(-20));
                near += 1;
            }
        }
        assert!(equal > 20 && near > 500, "{equal} {near}");
    }

    #[test]
    fn invalid_parameters_are_errors() {
        assert!(UniformBox::new(vec![1.0], vec![0.0]).is_err());
        assert!(UniformBox::new(vec![1.0], vec![]).is_err());
        assert!(UniformBox::cube(2, f64::NAN, 1.0).is_err());
        assert!(LogUniform::new(1, 5, 4).is_err());
        assert!(LogUniform::new(1, -2000, 4).is_err());
        assert!(Fixed::new(vec![f64::INFINITY]).is_err());
        assert!(Diagonal::new(2, 1.0, 0.0).is_err());
        let nd = NearDegenerate::new(Fixed::new(vec![1.0]).unwrap(), -3, -1).unwrap();
        assert!(nd.clone().with_keep_probability(1.5).is_err());
        assert!(nd.with_keep_probability(0.0).is_ok());
        assert!(NearDegenerate::new(Fixed::new(vec![1.0]).unwrap(), 0, -1).is_err());
    }
}
