//! Integration tests of `exactcheck-float` through its public API: exact `f64` conversion, the
//! regression harness and its shards, FPCore domains driving the sampler, and external programs
//! as float subjects. One test binary; each module is one area
//! (`cargo test --release -p exactcheck-float --test regress shards::`).

mod convert;
mod external;
mod fpcore_domain;
mod harness;
mod shards;
