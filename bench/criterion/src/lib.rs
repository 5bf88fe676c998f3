//! The criterion benchmarks of exactcheck (`benches/`, run with
//! `cargo bench -p exactcheck-criterion --bench NAME`). They time the workloads of
//! `exactcheck-bench` and the kernels of `exactcheck-exact`, and assert their check values before
//! timing. The library is empty: criterion is a dev-dependency, so that `cargo test --workspace`
//! does not build it.
