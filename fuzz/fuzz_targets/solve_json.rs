//! The JSON problem reader and every `solve` kind: any text given to `exactcheck solve` gives an
//! answer or a one-line error, never a panic, in exact, float and both modes. The seed corpus
//! (fuzz/seeds/solve_json) holds a problem of every kind, so mutations stay mostly well-formed
//! and reach the solvers.
#![no_main]
use exactcheck::solve::{solve, Mode};
use exactcheck_fuzz::{small_limits, text};
use libfuzzer_sys::fuzz_target;

fn check(source: &str, mode: Mode) {
    match solve(source, mode) {
        Ok(answer) => {
            // What the CLI prints: it must parse back as JSON.
            let out = serde_json::to_string_pretty(&answer).expect("a JSON value serializes");
            if let Err(e) = serde_json::from_str::<serde_json::Value>(&out) {
                panic!("solve printed invalid JSON for {source:?}: {e}: {out}");
            }
        }
        Err(e) => {
            let line = e.to_string();
            assert!(
                !line.contains('\n'),
                "a multi-line error for {source:?}: {line:?}"
            );
        }
    }
}

fuzz_target!(|data: &[u8]| {
    small_limits();
    let source = text(data);
    // `Both` runs the exact solver and then the float one; `Float` alone covers the float
    // solver when the exact one refuses the input.
    check(source, Mode::Both);
    check(source, Mode::Float);
});
