//! The regression harness on formulas whose float behaviour is known in advance: it must pass
//! the well-conditioned ones, find the planted ill-conditioned ones, count domain errors and float
//! failures without crashing, and be reproducible from its seed.

use exactcheck_core::{OrderedField, ZeroDivisor};
use exactcheck_exact::PlainRational;
use exactcheck_float::{
    check, regress, sample_inputs, significant_bits, Diagonal, Fixed, Formula, InputGen,
    LogUniform, NearDegenerate, Options, Rng, UniformBox,
};
use proptest::prelude::*;

/// `sum_i a_i b_i` over `n` pairs, inputs `(a_0, b_0, a_1, b_1, ...)`, summed left to right.
struct Dot(usize);

impl Formula for Dot {
    fn name(&self) -> String {
        format!("dot product of length {}", self.0)
    }
    fn arity(&self) -> usize {
        2 * self.0
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        let mut acc = T::zero();
        for pair in x.chunks(2) {
            acc += pair[0].mul_ref(&pair[1]);
        }
        Ok(vec![acc])
    }
}

/// The planted absorption: `(x + y) - x` equals `y` exactly, but `y` is rounded away in `x + y`.
struct AddSub;

impl Formula for AddSub {
    fn name(&self) -> String {
        "(x + y) - x".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].add_ref(&x[1]).sub_ref(&x[0])])
    }
}

/// The planted cancellation: `a*a - b*b` at `a ≈ b`.
struct DiffOfSquares;

impl Formula for DiffOfSquares {
    fn name(&self) -> String {
        "a*a - b*b".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].square() - x[1].square()])
    }
}

/// `1/(x - y)`: undefined at `x = y`; in f64 `x - y` is exact near the diagonal (Sterbenz), so
/// the only rounding is the division's.
struct InvDiff;

impl Formula for InvDiff {
    fn name(&self) -> String {
        "1/(x - y)".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].sub_ref(&x[1]).inv()?])
    }
}

/// `1/((x + y) - x)`: exactly `1/y`, but f64 divides by zero wherever `y` is absorbed in `x + y`.
struct InvAbsorbed;

impl Formula for InvAbsorbed {
    fn name(&self) -> String {
        "1/((x + y) - x)".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].add_ref(&x[1]).sub_ref(&x[0]).inv()?])
    }
}

/// Three correctly rounded operations as three outputs: each must stay within half an ulp.
struct Basic;

impl Formula for Basic {
    fn name(&self) -> String {
        "x*y, x + y, x/y".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![
            x[0].mul_ref(&x[1]),
            x[0].add_ref(&x[1]),
            x[0].checked_div(&x[1])?,
        ])
    }
}

fn quick() -> Options {
    Options {
        shrink: false,
        worst: 1,
        ..Options::default()
    }
}

fn total_bits(x: &[f64]) -> u32 {
    x.iter().map(|&v| significant_bits(v)).sum()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, ..ProptestConfig::default() })]

    /// A dot product of `n <= 3` positive pairs is well conditioned: each product and partial sum
    /// carries a relative error of at most `u = 2^-53`, so the result is within `γ_n·s` of the
    /// exact sum `s` (`γ_n = n·u / (1 - n·u)`, Higham, *Accuracy and Stability*, §3.1), and
    /// `ulp(round(s)) > s·2^-53`; hence the error is below `γ_n·2^53 ≈ n` ulps, and **at most
    /// 4 ulps** is the stated bound (no underflow or overflow for magnitudes in `[2^-100, 2^100]`).
    #[test]
    fn positive_dot_products_stay_within_four_ulps(
        seed in any::<u64>(),
        n in 1usize..=3,
        lo in 1e-30f64..1e30,
        widen in 1.0f64..1e6,
        log_uniform in any::<bool>(),
    ) {
        let f = Dot(n);
        let report = if log_uniform {
            let g = LogUniform::new(2 * n, -100, 100).expect("valid").positive();
            regress::<PlainRational>(&f, &g, 150, seed, &quick())
        } else {
            let g = UniformBox::cube(2 * n, lo, lo * widen).expect("valid");
            regress::<PlainRational>(&f, &g, 150, seed, &quick())
        }.expect("runs");
        prop_assert_eq!(report.compared, 150);
        prop_assert_eq!(report.float_failures + report.domain_errors + report.invalid_inputs, 0);
        prop_assert!(report.max_ulps <= 4.0, "{}", report);
        prop_assert!(report.max_rel <= 4.0 * f64::EPSILON);
    }
}

#[test]
fn correctly_rounded_operations_are_within_half_an_ulp() {
    let g = LogUniform::new(2, -300, 300).expect("valid");
    let report = regress::<PlainRational>(&Basic, &g, 2000, 3, &quick()).expect("runs");
    assert_eq!(report.max_ulps_per_output.len(), 3);
    assert!(report.max_ulps <= 0.5, "{report}");
    assert!(report.median_ulps > 0.0 && report.median_ulps < 0.5);
    assert_eq!(report.above[0].count, 0);
    assert_eq!(report.float_failures, 0);
}

#[test]
fn finds_planted_absorption_and_shrinks_it() {
    let g = UniformBox::new(vec![1.0, 1e-12], vec![2.0, 1e-9]).expect("valid");
    let report =
        regress::<PlainRational>(&AddSub, &g, 2000, 42, &Options::default()).expect("runs");
    println!("{report}");
    assert!(report.max_ulps > 1e6, "{report}");
    assert!(report.median_ulps > 1e6);
    assert_eq!(
        report.above.iter().map(|t| t.ulps).collect::<Vec<_>>(),
        [1.0, 4.0, 1e3]
    );
    assert!(report.above[2].count > 1900);
    assert_eq!(report.worst.len(), 5);
    for pair in report.worst.windows(2) {
        assert!(pair[0].original.ulps >= pair[1].original.ulps);
    }
    for w in &report.worst {
        // Reproducible from the seed and the index.
        assert_eq!(sample_inputs(&g, 42, w.index), w.original.inputs);
        let again = check::<PlainRational>(&AddSub, &w.original.inputs).expect("defined");
        assert_eq!(again, w.original);
        // The shrunk case is still bad (at least half the original error) and short.
        let s = w.shrunk.as_ref().expect("shrunk");
        assert!(s.ulps >= 0.5 * w.original.ulps && s.ulps > 1e6, "{w}");
        assert!(total_bits(&s.inputs) <= 28, "{w}");
        assert!(total_bits(&s.inputs) < total_bits(&w.original.inputs));
        assert_eq!(check::<PlainRational>(&AddSub, &s.inputs).as_ref(), Ok(s));
    }
}

#[test]
fn finds_planted_cancellation_and_shrinks_it() {
    let g =
        NearDegenerate::new(Diagonal::new(2, 1.0, 4.0).expect("valid"), -45, -20).expect("valid");
    // The worst case is an extreme outlier (both squares rounded by nearly half an ulp, inputs
    // 53 bits long and equal in their first 44); keeping half of its error pins the inputs near
    // 90 bits (the default fraction shrinks them to 86-90 bits only). Asking for a still huge
    // error (a millionth of 9e12 ulps) lets them shrink to (1 - 2^-27, 1) and the like.
    let opts = Options {
        shrink_fraction: 1e-6,
        ..Options::default()
    };
    let report = regress::<PlainRational>(&DiffOfSquares, &g, 2000, 7, &opts).expect("runs");
    println!("{report}");
    assert!(report.max_ulps > 1e6, "{report}");
    // Exactly equal inputs give 0 both ways: they are compared, not domain errors.
    assert_eq!(report.domain_errors, 0);
    assert_eq!(report.float_failures, 0);
    let w = &report.worst[0];
    let s = w.shrunk.as_ref().expect("shrunk");
    assert!(
        s.ulps >= opts.shrink_fraction * w.original.ulps && s.ulps > 1e6,
        "{w}"
    );
    assert!(total_bits(&s.inputs) <= 40, "{w}");
    assert!(s.inputs.iter().all(|&v| significant_bits(v) <= 30), "{w}");
}

#[test]
fn division_near_the_diagonal_counts_domain_errors() {
    let g = NearDegenerate::new(Diagonal::new(2, -8.0, 8.0).expect("valid"), -60, -10)
        .expect("valid")
        .with_keep_probability(0.5)
        .expect("valid");
    let report =
        regress::<PlainRational>(&InvDiff, &g, 2000, 11, &Options::default()).expect("runs");
    // x == y exactly about a quarter of the time: counted, not crashed on.
    assert!(report.domain_errors > 300, "{report}");
    assert_eq!(report.compared + report.domain_errors, 2000);
    // Near the diagonal x - y is exact in f64 (Sterbenz), so 1/(x - y) is correctly rounded:
    // the harness certifies the float code rather than flagging it.
    assert!(report.max_ulps <= 0.5, "{report}");
}

#[test]
fn division_by_a_cancelled_difference_reports_float_failures() {
    // y = 0 exactly a quarter of the time (outside the domain), otherwise y = ±2^t, t in
    // [-70, -40]: absorbed in x + y (x near 1.5) for t below -53 or so.
    let g =
        NearDegenerate::new(Fixed::new(vec![1.5, 0.0]).expect("valid"), -70, -40).expect("valid");
    let report =
        regress::<PlainRational>(&InvAbsorbed, &g, 2000, 5, &Options::default()).expect("runs");
    println!("{report}");
    assert!(report.domain_errors > 300, "{report}");
    assert!(report.float_failures > 300, "{report}");
    assert_eq!(report.max_ulps, f64::INFINITY);
    assert_eq!(report.median_ulps, f64::INFINITY);
    let w = &report.worst[0];
    assert!(w.original.float_failure && w.original.float_outputs.is_none());
    let s = w.shrunk.as_ref().expect("shrunk");
    assert!(s.float_failure, "a failure shrinks to a failure");
    assert!(total_bits(&s.inputs) <= 2, "{w}");
}

#[test]
fn same_seed_same_report() {
    let g =
        NearDegenerate::new(Diagonal::new(2, 1.0, 4.0).expect("valid"), -45, -20).expect("valid");
    let opts = Options {
        worst: 3,
        ..Options::default()
    };
    let a = regress::<PlainRational>(&DiffOfSquares, &g, 500, 99, &opts).expect("runs");
    let b = regress::<PlainRational>(&DiffOfSquares, &g, 500, 99, &opts).expect("runs");
    assert_eq!(a, b);
    assert_eq!(a.to_string(), b.to_string());
    let c = regress::<PlainRational>(&DiffOfSquares, &g, 500, 100, &opts).expect("runs");
    assert_ne!(a.worst[0].original.inputs, c.worst[0].original.inputs);
}

/// A user generator that misbehaves on every third sample.
struct Sloppy;

impl InputGen for Sloppy {
    fn arity(&self) -> usize {
        2
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        match rng.below(3) {
            0 => vec![1.0, f64::NAN],
            1 => vec![1.0],
            _ => vec![rng.next_f64(), rng.next_f64()],
        }
    }
}

#[test]
fn bad_generator_samples_are_counted_not_fatal() {
    let report =
        regress::<PlainRational>(&AddSub, &Sloppy, 300, 1, &Options::default()).expect("runs");
    assert!(
        report.invalid_inputs > 150 && report.compared > 50,
        "{report}"
    );
    assert_eq!(report.invalid_inputs + report.compared, 300);
}

#[test]
fn fixed_point_regression() {
    // One pinned input, as a regression test named after what it pins would use.
    let g = Fixed::new(vec![1.0, 1e-17]).expect("valid");
    let report = regress::<PlainRational>(&AddSub, &g, 1, 0, &Options::default()).expect("runs");
    assert_eq!(report.worst[0].original.float_outputs, Some(vec![0.0]));
    assert_eq!(report.max_rel, 1.0);
}

/// A shrunk worst case stays inside the sampled domain: `(x + y) - x` on
/// `x in [1000, 1010], y in [1e-3, 2e-3]` loses the most bits at the largest `x`, and the
/// simpler `x = 512` (or `y = 2^-9`) would be as bad, but outside the domain.
#[test]
fn shrunk_cases_stay_in_the_domain() {
    let names = vec!["x".to_string(), "y".to_string()];
    let dom = exactcheck_float::SampleDomain::named(
        exactcheck_float::parse_domain("x in [1000, 1010], y in [1e-3, 2e-3]", &names)
            .expect("valid"),
        &names,
    )
    .expect("valid");
    let report =
        regress::<PlainRational>(&AddSub, &dom, 3000, 1, &Options::default()).expect("runs");
    assert!(report.max_ulps > 1e3, "{report}");
    assert_eq!(report.worst.len(), 5);
    let mut shrunk_some = false;
    for w in &report.worst {
        let s = w.shrunk.as_ref().expect("shrunk");
        let [x, y] = s.inputs[..] else {
            panic!("two inputs: {w}")
        };
        assert!((1000.0..=1010.0).contains(&x), "{w}");
        assert!((1e-3..=2e-3).contains(&y), "{w}");
        assert!(dom.contains(&s.inputs));
        shrunk_some |= w.shrink_steps > 0;
    }
    // Shrinking still simplifies within the domain.
    assert!(shrunk_some, "{report}");
}

#[test]
fn generators_contain_what_they_sample() {
    let mut rng = Rng::new(5);
    let gens: Vec<Box<dyn InputGen>> = vec![
        Box::new(UniformBox::new(vec![-1.0, 3.0], vec![1.0, 4.0]).expect("valid")),
        Box::new(LogUniform::new(2, -20, 20).expect("valid")),
        Box::new(LogUniform::new(2, -1074, 1023).expect("valid").positive()),
        Box::new(Diagonal::new(2, -5.0, 5.0).expect("valid")),
        Box::new(Fixed::new(vec![1.5, -2.0]).expect("valid")),
    ];
    for g in &gens {
        for _ in 0..2000 {
            let x = g.sample(&mut rng);
            assert!(g.contains(&x), "{}: {x:?}", g.describe());
        }
        // Not the wrong arity, and not something far away.
        assert!(!g.contains(&[1.5]), "{}", g.describe());
        assert!(!g.contains(&[1e300, -1e-300]), "{}", g.describe());
    }
    assert!(!gens[1].contains(&[0.0, 1.0]));
    assert!(!gens[2].contains(&[-1.0, 1.0]));
    assert!(!gens[3].contains(&[1.0, 2.0]));
}

/// `x * y`, with a float side that answers `+inf` for `x * y` at or above `f64::MAX` and NaN
/// for `x = 0`.
struct Overflowing;

impl Formula for Overflowing {
    fn name(&self) -> String {
        "x * y".into()
    }
    fn arity(&self) -> usize {
        2
    }
    fn eval<T: OrderedField>(&self, x: &[T]) -> Result<Vec<T>, ZeroDivisor> {
        Ok(vec![x[0].mul_ref(&x[1])])
    }
    fn eval_f64(&self, x: &[f64]) -> Result<Vec<f64>, ZeroDivisor> {
        let p = x[0] * x[1];
        Ok(vec![if x[0] == 0.0 {
            f64::NAN
        } else if p >= f64::MAX {
            f64::INFINITY
        } else {
            p
        }])
    }
}

/// Herbie's bits count the infinities as the doubles past `±f64::MAX`: a correctly rounded
/// overflow is 0 bits, `+inf` for `f64::MAX` is one double off; a NaN is 64. In ulps both
/// infinities stay float failures.
#[test]
fn infinities_count_by_ordinal_distance_in_bits() {
    let case = check::<PlainRational>(&Overflowing, &[1e200, 1e200]).expect("defined");
    assert!(case.float_failure && case.ulps.is_infinite());
    assert_eq!(case.bits, 0.0, "{case:?}");
    let case = check::<PlainRational>(&Overflowing, &[f64::MAX, 1.0]).expect("defined");
    assert!(case.float_failure);
    assert_eq!(case.bits, 1.0, "{case:?}");
    let case = check::<PlainRational>(&Overflowing, &[0.0, 1.0]).expect("defined");
    assert_eq!(case.bits, 64.0, "{case:?}");
    let case = check::<PlainRational>(&Overflowing, &[3.0, 0.5]).expect("defined");
    assert_eq!((case.bits, case.float_failure), (0.0, false));
}
