//! `exactcheck-bench`: the benchmark workloads of exactcheck (see `docs/benchmarks.md`).

use std::process::ExitCode;

fn main() -> ExitCode {
    exactcheck_bench::cli::main()
}
