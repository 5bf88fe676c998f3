//! The benchmark lab of exactcheck (the workspace member `bench/`, not published): the timed
//! workloads behind the binary `exactcheck-bench`, each printing its check values as text or as
//! the one JSON line that the anchor scripts in `bench/scripts/anchors` print for other tools, so
//! that `bench/scripts/compare.py` can run them side by side; the criterion benchmarks (the
//! package `exactcheck-criterion` in `bench/criterion/`) and the probes (`bench/examples`) use
//! the same workloads. Nothing here is part of the product: the mathematics it times lives in
//! the product crates.

pub mod chiang_identity;
pub mod cli;
pub mod dense_product;
pub mod formula;
pub mod rational_sum;
pub mod real_roots;
pub mod sample_sphere;
pub mod stopwatch;

pub use stopwatch::{process_cpu_seconds, Elapsed, Stopwatch};
