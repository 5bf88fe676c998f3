//! f64 against exact for Chiang's plane section (the generic `RuledSurface::plane_section` at
//! `f64` and at `Rational`, inputs converted exactly).
//!
//! # The bound
//! The weights are sums of products evaluated without division until the last step: each
//! `w_k = [sum_{i+j=k} C(m,i) C(n,j) (N.q_i)] / C(m+n,k)`. For such an expression the standard
//! forward error bound is `|fl(w) - w| <= gamma_K * A_k`, where `A_k` is the same expression with
//! every input replaced by its absolute value (and every subtraction by an addition) and
//! `gamma_K = K u / (1 - K u)`, `u = 2^-53`, `K` the number of rounded operations on the longest
//! path: 3 for the dot product, 1 for the binomial factor, at most `m + 1` for the sum over `i`,
//! 1 for the division: `K = m + 6`. In ulps of `w_k` that is at most `K * kappa_k`, with the
//! condition number `kappa_k = A_k / |w_k|` (an ulp of `x` is at least `2^-53 |x|`). So on
//! well-conditioned inputs (`kappa <= 4`) a weight is within `4 (m + 6)` ulps — the stated bound
//! — and on any input within `(m + 6) kappa` ulps, which the proptest checks too. The test fails
//! if the f64 code path changes its accuracy (e.g. a different summation, a division too early).

use exactcheck::regress::ruled::{decode, random_gen, Part, RuledPlaneKernel};
use exactcheck_core::Vec3;
use exactcheck_exact::Rational;
use exactcheck_float::{
    check, regress, sample_inputs, ulps_error, ExactScalar, Formula, InputGen, Options, Rng,
    UniformBox,
};
use num_rational::BigRational;
use num_traits::Signed;
use proptest::prelude::*;

fn binom(n: usize, k: usize) -> i64 {
    (0..k).fold(1i64, |acc, i| acc * (n - i) as i64 / (i + 1) as i64)
}

/// `A_k`, the absolute-value expression of the weight `w_k`, exactly.
fn weight_abs(m: usize, n: usize, x: &[f64]) -> Vec<BigRational> {
    let q: Vec<Rational> = x
        .iter()
        .map(|&v| Rational::from_f64_exact(v).unwrap())
        .collect();
    let (s, plane) = decode(m, n, &q);
    let abs = |v: &Vec3<Rational>| {
        Vec3::new(
            v.x.to_big_rational().abs(),
            v.y.to_big_rational().abs(),
            v.z.to_big_rational().abs(),
        )
    };
    let nn = abs(&plane.normal);
    let dot = |a: &Vec3<BigRational>| &a.x * &nn.x + &a.y * &nn.y + &a.z * &nn.z;
    (0..=m + n)
        .map(|k| {
            let mut sum = BigRational::from_integer(0.into());
            for (i, qi) in s.directions().control_points().iter().enumerate() {
                if k >= i && k - i <= n {
                    let c = BigRational::from_integer((binom(m, i) * binom(n, k - i)).into());
                    sum += c * dot(&abs(qi));
                }
            }
            sum / BigRational::from_integer(binom(m + n, k).into())
        })
        .collect()
}

/// `(ulps error, condition number)` of every weight at `x`.
fn weight_errors(m: usize, n: usize, x: &[f64]) -> Vec<(f64, f64)> {
    let kernel = RuledPlaneKernel {
        m,
        n,
        part: Part::Weights,
    };
    let f = kernel.eval::<f64>(x).unwrap();
    let xq: Vec<Rational> = x
        .iter()
        .map(|&v| Rational::from_f64_exact(v).unwrap())
        .collect();
    let e = kernel.eval::<Rational>(&xq).unwrap();
    let a = weight_abs(m, n, x);
    f.iter()
        .zip(&e)
        .zip(&a)
        .map(|((fv, ev), av)| {
            let ev = ev.to_big_rational();
            let kappa = if ev == BigRational::from_integer(0.into()) {
                f64::INFINITY
            } else {
                exactcheck_float::rational_to_f64(&(av / ev.abs()))
            };
            (ulps_error(*fv, &ev), kappa)
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn weights_within_the_stated_bound(seed in any::<u64>(), shape in 0usize..3) {
        let (m, n) = exactcheck::regress::ruled::SHAPES[shape];
        let x = random_gen(m, n).unwrap().sample(&mut Rng::new(seed));
        let k_ops = (m + 6) as f64;
        for (ulps, kappa) in weight_errors(m, n, &x) {
            // Any input: (m + 6) kappa ulps (first order; 1% slack for the gamma_K factor).
            prop_assert!(ulps <= 1.01 * k_ops * kappa, "{ulps} ulps, kappa {kappa}, x = {x:?}");
            // Well-conditioned inputs: the stated bound 4 (m + 6) ulps.
            if kappa <= 4.0 {
                prop_assert!(ulps <= 4.0 * k_ops, "{ulps} ulps, kappa {kappa}, x = {x:?}");
            }
        }
    }
}

/// Random surfaces of shape (1, 2), and with probability 1/50 the planted ill-conditioned one.
struct Planted {
    random: UniformBox,
    planted: Vec<f64>,
}

impl InputGen for Planted {
    fn arity(&self) -> usize {
        self.random.arity()
    }
    fn sample(&self, rng: &mut Rng) -> Vec<f64> {
        if rng.chance(0.02) {
            self.planted.clone()
        } else {
            self.random.sample(rng)
        }
    }
}

#[test]
fn the_report_finds_the_planted_ill_conditioned_case() {
    let random = random_gen(1, 2).unwrap();
    // q_0 = (0.3, 0.7 + 2^-45, 0.5), N = (0.7, -0.3, 0): w_0 = N.q_0 = 0.7 * 0.3 - 0.3 * (0.7 +
    // 2^-45) cancels nearly to zero after both products were rounded, so w_0 and
    // r_0 = (w_0 r_0) / w_0 carry relative errors of about 2^-53 / 2^-47.
    let mut planted = sample_inputs(&random, 77, 0);
    planted[9..12].copy_from_slice(&[0.3, 0.7 + 2f64.powi(-45), 0.5]);
    planted[15..19].copy_from_slice(&[0.7, -0.3, 0.0, 0.3]);
    let gen = Planted {
        random,
        planted: planted.clone(),
    };
    let kernel = RuledPlaneKernel {
        m: 1,
        n: 2,
        part: Part::Points,
    };
    let options = Options {
        worst: 3,
        shrink: false,
        ..Options::default()
    };
    let report = regress::<Rational>(&kernel, &gen, 400, 5, &options).unwrap();
    let hits = (0..400)
        .filter(|&i| sample_inputs(&gen, 5, i) == planted)
        .count();
    assert!(hits > 0, "the seed must draw the planted case");
    let worst = &report.worst[0];
    assert_eq!(worst.original.inputs, planted, "{report}");
    // Well above every random case, and reproducible from (seed, index).
    assert!(worst.original.ulps > 1e3, "{report}");
    assert_eq!(sample_inputs(&gen, 5, worst.index), planted);
    let second = report.worst.iter().find(|w| w.original.inputs != planted);
    if let Some(s) = second {
        assert!(worst.original.ulps > 10.0 * s.original.ulps, "{report}");
    }
    let again = check::<Rational>(&kernel, &planted).unwrap();
    assert_eq!(again.ulps, worst.original.ulps);
}
