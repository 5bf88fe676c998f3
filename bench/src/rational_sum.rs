//! The workload `rational-sum`: the exact Spaeth discriminant at many rational parameters (the
//! benchmark of the exact rational field; the criterion benchmark `rational_sum`, anchors
//! `rational_sum.py` and `rational_sum_gmp.py`).
//!
//! Cylinder about the axis point `(1/3, -2/7)`, radius 5, rotations `cos b = 3/5, sin b = 4/5`,
//! `cos g = 5/13, sin g = -12/13`; sphere centre `(1, 2, 4)`, radius 5. At `T_k = k/1000 - 50`,
//! `k = 0..N-1`, the angle is the rational circle point of `T_k` and the value is
//! `disc = A^2 - B` ([`exactcheck_core::cylinder_sphere`]).

use crate::Stopwatch;
use exactcheck_core::cylinder_sphere::{unit_circle_point, Angle, CylinderSphere};
use exactcheck_core::{pairwise_sum, Field, Sign, Vec3};
use exactcheck_exact::RationalScalar;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};

/// How the discriminants are consumed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Mode {
    /// Evaluate every discriminant and count the non-negative ones.
    Eval,
    /// As `eval`, then sum all values exactly by pairwise (balanced) summation.
    Tree,
    /// Accumulate `s += disc` sequentially (the sum grows with every step).
    Seq,
}

fn q<T: Field>(n: i64, d: i64) -> T {
    T::from_ratio(n, d).expect("the workload's constants and parameters have non-zero denominators")
}

/// The configuration of the workload over any field.
pub fn problem<T: Field>() -> CylinderSphere<T> {
    CylinderSphere {
        a: q(1, 3),
        b: q(-2, 7),
        r: T::from_i64(5),
        beta: Angle {
            cos: q(3, 5),
            sin: q(4, 5),
        },
        gamma: Angle {
            cos: q(5, 13),
            sin: q(-12, 13),
        },
        center: Vec3::from_i64(1, 2, 4),
        radius: T::from_i64(5),
    }
}

/// The parameter `T_k = k/1000 - 50`.
pub fn parameter<T: Field>(k: usize) -> T {
    q::<T>(k as i64, 1000) - T::from_i64(50)
}

/// `disc(T)` for the configuration of the workload.
pub fn discriminant<T: Field>(cs: &CylinderSphere<T>, tau: &T) -> T {
    let p = unit_circle_point(tau).expect("1 + T^2 > 0 for every rational T");
    cs.discriminant_at(&p.cos, &p.sin)
}

/// What a run computed.
#[derive(Clone, Debug)]
pub struct Outcome<T> {
    /// Parameters with `disc >= 0`.
    pub count_nonneg: usize,
    /// The exact sum of all discriminants (modes `tree` and `seq`).
    pub sum: Option<T>,
    /// Seconds spent in the timed region (evaluation and summation).
    pub seconds: f64,
    /// Process CPU seconds in the same region.
    pub cpu_seconds: f64,
}

/// Runs the workload with `n` parameters in the given mode over the scalar `T`, timing the same region as
/// the anchor scripts (evaluation and summation, not the check values).
pub fn run<T: Field + exactcheck_core::OrderedField>(n: usize, mode: Mode) -> Outcome<T> {
    let cs = problem::<T>();
    let watch = Stopwatch::start();
    let mut count_nonneg = 0;
    let mut count = |d: &T| {
        if d.sign() != Sign::Negative {
            count_nonneg += 1;
        }
    };
    let sum = match mode {
        Mode::Eval => {
            for k in 0..n {
                count(&discriminant(&cs, &parameter::<T>(k)));
            }
            None
        }
        Mode::Seq => {
            let mut s = T::zero();
            for k in 0..n {
                let d = discriminant(&cs, &parameter::<T>(k));
                count(&d);
                s += d;
            }
            Some(s)
        }
        Mode::Tree => {
            let mut values = Vec::with_capacity(n);
            for k in 0..n {
                let d = discriminant(&cs, &parameter::<T>(k));
                count(&d);
                values.push(d);
            }
            Some(pairwise_sum(values))
        }
    };
    let elapsed = watch.elapsed();
    Outcome {
        count_nonneg,
        sum,
        seconds: elapsed.wall,
        cpu_seconds: elapsed.cpu,
    }
}

/// The check values of an exact sum, as the anchor scripts print them.
#[derive(Clone, Debug, PartialEq)]
pub struct CheckValues {
    /// Decimal digits of `|numerator|`.
    pub num_digits: usize,
    /// Decimal digits of the denominator.
    pub den_digits: usize,
    /// Numerator mod 1e9+7 (non-negative residue).
    pub num_mod_p: u64,
    /// Denominator mod 1e9+7.
    pub den_mod_p: u64,
    /// The value as f64 (for orientation only).
    pub approx: f64,
}

const P: u64 = 1_000_000_007;

/// The check values of an exact sum.
pub fn check_values<T: RationalScalar>(sum: &T) -> CheckValues {
    let big: BigRational = sum.to_big_rational();
    let (n, d) = (big.numer(), big.denom());
    let p = BigInt::from(P);
    let residue = |x: &BigInt| {
        x.mod_floor(&p)
            .to_u64()
            .expect("a residue mod 1e9+7 fits in u64")
    };
    CheckValues {
        num_digits: n.abs().to_string().len(),
        den_digits: d.to_string().len(),
        num_mod_p: residue(n),
        den_mod_p: residue(d),
        approx: big.to_f64().unwrap_or(f64::NAN),
    }
}

/// Runs the workload with `n` parameters over the scalar `T` and formats it like
/// `rational_sum.py` (one JSON line) or as text.
pub fn report<T: RationalScalar>(n: usize, mode: Mode, scalar: &str, json: bool) -> String {
    let out = run::<T>(n, mode);
    let checks = out.sum.as_ref().map(check_values);
    let mode_name = format!("{mode:?}").to_lowercase();
    if json {
        let mut s = format!(
            "{{\"tool\": \"exactcheck\", \"scalar\": \"{scalar}\", \"mode\": \"{mode_name}\", \"N\": {n}, \"seconds\": {}, \"cpu_seconds\": {}, \"samples_per_s\": {}, \"count_nonneg\": {}",
            out.seconds,
            out.cpu_seconds,
            n as f64 / out.seconds,
            out.count_nonneg
        );
        if let Some(c) = &checks {
            s += &format!(
                ", \"sum_num_digits\": {}, \"sum_den_digits\": {}, \"sum_num_mod_p\": {}, \"sum_den_mod_p\": {}, \"sum_approx\": {:?}",
                c.num_digits, c.den_digits, c.num_mod_p, c.den_mod_p, c.approx
            );
        }
        s + "}"
    } else {
        let mut s = format!(
            "rational-sum (exact Spaeth discriminant), N = {n}, mode {mode_name}, scalar {scalar}\n  parameters with disc >= 0: {}\n",
            out.count_nonneg
        );
        if let Some(c) = &checks {
            s += &format!(
                "  exact sum: numerator {} digits, denominator {} digits\n  numerator mod 1e9+7 = {}, denominator mod 1e9+7 = {}\n  value ~ {:?}\n",
                c.num_digits, c.den_digits, c.num_mod_p, c.den_mod_p, c.approx
            );
        }
        s + &format!(
            "  time: {:.3} s ({:.0} parameters/s)",
            out.seconds,
            n as f64 / out.seconds
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_exact::{PlainRational, Rational};

    #[test]
    fn fast_and_plain_rationals_agree() {
        for mode in [Mode::Eval, Mode::Seq, Mode::Tree] {
            let a = run::<Rational>(300, mode);
            let b = run::<PlainRational>(300, mode);
            assert_eq!(a.count_nonneg, b.count_nonneg);
            assert_eq!(
                a.sum.map(|s| s.to_big_rational()),
                b.sum.map(|s| s.to_big_rational())
            );
        }
    }

    #[test]
    fn seq_sum_matches_the_anchors_at_2000() {
        // The running sum grows to 12,783 digits through the big + word-sized addition kernel;
        // the check values are those printed by gmpy2, FLINT and Fraction
        // (bench/scripts/anchors/rational_sum.py TOOL seq 2000).
        let out = run::<Rational>(2000, Mode::Seq);
        assert_eq!(out.count_nonneg, 0);
        let cv = check_values(&out.sum.expect("seq mode returns the sum"));
        assert_eq!(
            (cv.num_digits, cv.den_digits, cv.num_mod_p, cv.den_mod_p),
            (12_783, 12_779, 288_945_042, 303_592_070)
        );
    }

    #[test]
    fn tree_and_seq_sums_agree() {
        let t = run::<Rational>(500, Mode::Tree).sum.unwrap();
        let s = run::<Rational>(500, Mode::Seq).sum.unwrap();
        assert_eq!(t, s);
        assert!(t.is_canonical());
    }
}
