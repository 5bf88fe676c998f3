//! The real-roots probe: times successive calls of `bench_instances::solve` on one instance in one process, with
//! the minor page faults of each call (Linux), to separate the first execution of the code
//! from the steady state; and a target for instruction counts of one call:
//!
//! ```sh
//! cargo build --release -p exactcheck-bench --example real_roots_probe
//! target/release/examples/real_roots_probe wilkinson 20 4
//! valgrind --tool=callgrind --toggle-collect='*bench_instances*solve*' \
//!     target/release/examples/real_roots_probe wilkinson 20 1 --no-warm-up
//! ```
//!
//! Arguments: `FAMILY` (`wilkinson`, `random`, `mignotte`), `DEGREE` (1 to 2000), `CALLS`
//! (default 4), and `--no-warm-up` to skip the untimed solve of `x^2 - 2` that
//! `exactcheck-bench real-roots` and the anchors do first (it is inside the callgrind toggle too).

use exactcheck_exact::univariate::bench_instances;
use num_bigint::BigInt;
use std::process::ExitCode;
use std::time::Instant;

/// The minor page faults of this process so far (`None` where `/proc` has no such field).
fn minor_faults() -> Option<u64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name in parentheses; minflt is the 8th of them.
    stat.rsplit(')')
        .next()?
        .split_whitespace()
        .nth(7)?
        .parse()
        .ok()
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let warm_up = !args.iter().any(|a| a == "--no-warm-up");
    let plain: Vec<&String> = args.iter().filter(|a| *a != "--no-warm-up").collect();
    let usage = "usage: real_roots_probe FAMILY DEGREE [CALLS] [--no-warm-up] \
                 (FAMILY: wilkinson, random, mignotte; DEGREE 1 to 2000)";
    let family = match plain.first().map(|s| s.as_str()) {
        Some("wilkinson") => bench_instances::Family::Wilkinson,
        Some("random") => bench_instances::Family::Random,
        Some("mignotte") => bench_instances::Family::Mignotte,
        other => {
            let got = other.unwrap_or("nothing");
            eprintln!("real_roots_probe: unknown family `{got}`; {usage}");
            return ExitCode::from(2);
        }
    };
    let degree = match plain.get(1).map(|s| s.parse::<usize>()) {
        Some(Ok(d)) if (1..=2000).contains(&d) => d,
        _ => {
            eprintln!("real_roots_probe: DEGREE must be an integer from 1 to 2000; {usage}");
            return ExitCode::from(2);
        }
    };
    let calls = match plain.get(2).map(|s| s.parse::<usize>()) {
        None => 4,
        Some(Ok(c)) => c,
        Some(Err(_)) => {
            eprintln!("real_roots_probe: CALLS must be a non-negative integer; {usage}");
            return ExitCode::from(2);
        }
    };
    if plain.len() > 3 {
        eprintln!("real_roots_probe: too many arguments; {usage}");
        return ExitCode::from(2);
    }
    let coeffs = family.polynomial(degree);
    if warm_up {
        let _ = bench_instances::solve(&[BigInt::from(-2), BigInt::from(0), BigInt::from(1)]);
    }
    for call in 1..=calls {
        let before = minor_faults();
        let start = Instant::now();
        let roots = bench_instances::solve(&coeffs);
        let elapsed = start.elapsed();
        let faults = match (before, minor_faults()) {
            (Some(a), Some(b)) => (b - a).to_string(),
            _ => "-".to_string(),
        };
        println!(
            "call {call}: {} roots, {:.1} us, {faults} minor page faults",
            roots.len(),
            elapsed.as_secs_f64() * 1e6
        );
    }
    ExitCode::SUCCESS
}
