//! Shared set-up of the exactcheck fuzz targets (see docs/testing.md, "Fuzzing").
//!
//! Every target first lowers the named limits of `exactcheck_core::limits` so that one input
//! runs in milliseconds: the fuzzer then explores the error paths of every limit (an input past a
//! lowered limit must give a `LimitError`, never a panic, a hang or an allocation beyond
//! libFuzzer's `-rss_limit_mb`) instead of spending its time in legitimate but long work.
//! Inputs are also cut to a few hundred bytes (`MAX_INPUT`): a short input can already ask for
//! a billion digits, so nothing is lost by not mutating megabytes.
use exactcheck_core::limits;

/// The longest input (in bytes) a target looks at; the rest is ignored.
pub const MAX_INPUT: usize = 8192;

/// Sets the lowered limits (idempotent; called at the start of every run of a target).
pub fn small_limits() {
    exactcheck::limits::FILE_SIZE.set(MAX_INPUT as u64);
    limits::DEPTH.set(64);
    limits::DIGITS.set(500);
    limits::EXPONENT.set(200);
    limits::CONSTANT_BITS.set(20_000);
    limits::RADICANDS.set(4);
    limits::VARIABLES.set(20);
    limits::TERMS.set(20_000);
    limits::DEGREE.set(400);
    limits::GROEBNER_STEPS.set(200);
    limits::GROEBNER_BASIS.set(50);
    limits::BISECTION.set(2_000);
    exactcheck::limits::PRECISION_BITS.set(2_000);
    exactcheck::limits::SAMPLES.set(50);
}

/// Runs `f` with every lowered limit raised fourfold (depth by 4 levels per level plus 8): for
/// re-checking the printed form of something that was accepted, whose measures (parentheses
/// added by the printer, a product regrouped) may be slightly larger than the original's.
pub fn with_raised_limits<T>(f: impl FnOnce() -> T) -> T {
    let all = [
        &limits::DEPTH,
        &limits::DIGITS,
        &limits::EXPONENT,
        &limits::CONSTANT_BITS,
        &limits::RADICANDS,
        &limits::VARIABLES,
        &limits::TERMS,
        &limits::DEGREE,
    ];
    let saved: Vec<u64> = all.iter().map(|l| l.get()).collect();
    for l in all {
        l.set(l.get().saturating_mul(4).saturating_add(8));
    }
    let out = f();
    for (l, v) in all.iter().zip(saved) {
        l.set(v);
    }
    out
}

/// The input as text: invalid UTF-8 is cut at the first invalid byte (the readers of
/// exactcheck take `&str`; `read_problem` refuses non-UTF-8 files before any of them runs).
pub fn text(data: &[u8]) -> &str {
    let data = &data[..data.len().min(MAX_INPUT)];
    match std::str::from_utf8(data) {
        Ok(s) => s,
        Err(e) => std::str::from_utf8(&data[..e.valid_up_to()]).expect("valid up to here"),
    }
}
