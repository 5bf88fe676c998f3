//! Claims of Juettler's paper on rational curves and surfaces on quadrics (seed 002, SPEC §1).

use super::{Claim, Outcome};

/// The `juttler.*` claims.
pub fn claims() -> Vec<Claim> {
    Vec::new()
}

#[allow(dead_code)]
fn placeholder() -> Result<Outcome, String> {
    Err(String::new())
}
