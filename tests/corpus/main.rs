//! The timed corpora: the malformed-input corpus (`tests/malformed/`) and the stress cases of the
//! resource limits (`tests/stress/`), each case a run of the binary under a kill-timeout. One
//! test binary, apart from the others so that no other test competes with its deadlines.

#[path = "../common/mod.rs"]
mod common;
#[path = "../common/timed.rs"]
mod timed;

mod limits_stress;
mod malformed;
