//! The workloads of `bench/scripts/compare_algebraic.py`: the minimal polynomials of `cos(2 pi / n)`
//! for `n = 1..=60`, and the defining polynomial of a sum of four nested radicals. Prints one
//! JSON line with the polynomials (integer coefficients from the constant term up) and the
//! seconds of the timed region, so the script can check them against python-flint and SymPy.
//!
//! Usage: `algebraic_minpoly cos|sum`.

use exactcheck_exact::algebraic::Algebraic;
use exactcheck_exact::univariate::UPoly;
use std::time::Instant;

/// The terms of the nested-radical sum.
const SUM: [&str; 4] = [
    "sqrt(2 + sqrt(2))",
    "sqrt(2 - sqrt(2))",
    "sqrt(3 + sqrt(3))",
    "sqrt(5 + sqrt(5))",
];

fn coeffs(p: &UPoly) -> String {
    let c: Vec<String> = p.coeffs().iter().map(|c| format!("\"{c}\"")).collect();
    format!("[{}]", c.join(","))
}

fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "cos".into());
    let start = Instant::now();
    let out = match which.as_str() {
        "cos" => {
            let polys: Vec<String> = (1..=60)
                .map(|n| {
                    let c = Algebraic::cos_pi(2, n).expect("within the default degree limit");
                    coeffs(c.defining_polynomial())
                })
                .collect();
            format!("\"polys\":[{}]", polys.join(","))
        }
        "sum" => {
            let mut acc = Algebraic::from_integer(0);
            for s in SUM {
                acc += s.parse::<Algebraic>().expect("a constant expression");
            }
            format!(
                "\"poly\":{},\"decimal\":\"{}\"",
                coeffs(acc.defining_polynomial()),
                acc.to_decimal(30)
            )
        }
        other => {
            eprintln!("algebraic_minpoly: unknown workload {other:?} (cos or sum)");
            std::process::exit(2);
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    println!("{{\"seconds\":{seconds},{out}}}");
}
