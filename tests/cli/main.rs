//! End-to-end tests of the commands through the binary and the library: `verify` and claims
//! files, `report` and its browser check, `regress`, the command-line contract and its
//! robustness. One test binary; each module is one area, the helpers come from `tests/common`.

#[path = "../common/mod.rs"]
mod common;

mod browser;
mod claims_file;
mod claims_file_printed;
mod cli;
mod errata;
mod float_nonfinite;
mod fuzz_regressions;
mod module_cycles;
mod regress_argument_precision;
mod regress_calculus_as_printed;
mod regress_done_when;
mod regress_explain;
mod regress_fpbench;
mod regress_inputs;
mod regress_language;
mod regress_text;
mod report;
mod robust_cli;
mod verify;
