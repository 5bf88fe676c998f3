//! The harness on two planted ill-conditioned formulas: prints their reports.
//!
//! `cargo run -p exactcheck-float --release --example planted [SAMPLES] [SEED]`

use exactcheck_core::{OrderedField, ZeroDivisor};
use exactcheck_exact::PlainRational;
use exactcheck_float::{regress, Diagonal, Formula, NearDegenerate, Options, UniformBox};

/// `(x + y) - x`: exactly `y`, but `y` is partly absorbed in `x + y` when `|y| << |x|`.
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

/// `a*a - b*b`: catastrophic cancellation at `a ≈ b`.
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

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let samples: usize = args.next().map_or(Ok(2000), |s| s.parse())?;
    let seed: u64 = args.next().map_or(Ok(42), |s| s.parse())?;
    let opts = Options {
        worst: 3,
        ..Options::default()
    };

    let gen = UniformBox::new(vec![1.0, 1e-12], vec![2.0, 1e-9])?;
    println!(
        "{}",
        regress::<PlainRational>(&AddSub, &gen, samples, seed, &opts)?
    );

    let gen = NearDegenerate::new(Diagonal::new(2, 1.0, 4.0)?, -45, -20)?;
    let opts = Options {
        shrink_fraction: 1e-6,
        ..opts
    };
    println!(
        "{}",
        regress::<PlainRational>(&DiffOfSquares, &gen, samples, seed, &opts)?
    );
    Ok(())
}
