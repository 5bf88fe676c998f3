//! The workload `formula`: the exact side of `exactcheck regress --formula` alone, on the inputs
//! and with the check values of `scripts/regress_baseline.py`.

use crate::{Elapsed, Stopwatch};
use exactcheck_exact::Rational;

/// The largest `--n` (about 300,000 exact evaluations/s per core).
pub const MAX_FORMULA_N: usize = 10_000_000;

/// The formula of the workload and of `scripts/regress_baseline.py`: 11 operations.
pub const BASELINE_FORMULA: &str = "((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y";

/// Runs the workload: the exact side of [`BASELINE_FORMULA`] on `n` samples of four doubles
/// uniform in [-1, 1] (`sample_inputs(UniformBox::cube(4, -1, 1), seed, i)`, the inputs of
/// `regress --formula ... --domain 'x in [-1, 1], ...'` and of the Python baseline), timed
/// (inputs drawn outside the timed region), with the baseline's check values: the sums of the
/// results' numerators and denominators mod `2^61 - 1`, and the correctly rounded sum of their
/// correctly rounded doubles.
pub fn run(n: usize, seed: u64, serial: bool) -> String {
    use exactcheck_exact::program::Program;
    use exactcheck_float::{sample_inputs, ExactScalar, UniformBox};
    use num_bigint::BigInt;
    use num_traits::{ToPrimitive, Zero};
    use rayon::prelude::*;
    let vars: Vec<String> = ["x", "y", "z", "w"].map(String::from).to_vec();
    let program = Program::parse(BASELINE_FORMULA, Some(&vars)).expect("the formula parses");
    let gen = UniformBox::cube(4, -1.0, 1.0).expect("a valid box");
    let inputs: Vec<Vec<Rational>> = (0..n)
        .map(|i| {
            sample_inputs(&gen, seed, i)
                .iter()
                .map(|&v| Rational::from_f64_exact(v).expect("finite"))
                .collect()
        })
        .collect();
    let eval = |x: &Vec<Rational>| {
        program
            .eval_exact(x)
            .ok()
            .and_then(|r| r.into_iter().next())
    };
    let watch = Stopwatch::start();
    let values: Vec<_> = if serial {
        inputs.iter().map(eval).collect()
    } else {
        inputs.par_iter().map(eval).collect()
    };
    let Elapsed { wall: seconds, cpu } = watch.elapsed();
    let p = BigInt::from((1u64 << 61) - 1);
    let (mut num, mut den) = (BigInt::zero(), BigInt::zero());
    let mut doubles = Vec::with_capacity(n);
    let mut defined = 0usize;
    for v in values.into_iter().flatten() {
        defined += 1;
        num = (num + v.value.numer()) % &p;
        den = (den + v.value.denom()) % &p;
        doubles.push(exactcheck_float::rational_to_f64(&v.value));
    }
    let modp = |x: BigInt| ((x % &p + &p) % &p).to_u64().expect("below p");
    format!(
        "formula {BASELINE_FORMULA}: {n} samples ({defined} defined) in {seconds:.3} s = {:.0} samples/s on {} thread(s), {cpu:.3} s CPU; sum_num_mod_p {}, sum_den_mod_p {}, fsum {:?}",
        n as f64 / seconds,
        if serial { 1 } else { rayon::current_num_threads() },
        modp(num),
        modp(den),
        exactcheck_float::convert::fsum(&doubles)
    )
}
