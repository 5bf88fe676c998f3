//! `exactcheck prove` end to end through its library entry point (`prove_cmd::run`, what the
//! binary calls): exact mode over Q or Q(sqrt), with relations and domains, and `--random` mode
//! with a fixed seed. Any input gives a verdict or a one-line error, never a panic.
//!
//! Input: lines. The first line chooses the mode (`r...`: `--random 8 --seed 1`, `j...`:
//! exact with `--json`, anything else: exact), the second is LHS, the third RHS (absent or
//! empty: none), each further line (at most 4) a `--where` relation or domain, or, after
//! `def `, a `--define NAME = VALUE` (`def u = [u1, u2, u3]`). Run it with
//! `-close_fd_mask=1`: the verdicts go to standard output.
#![no_main]
use exactcheck::prove_cmd::{run, ProveArgs};
use exactcheck_fuzz::{small_limits, text};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    small_limits();
    let mut lines = text(data).split('\n');
    let mode = lines.next().unwrap_or("");
    let Some(lhs) = lines.next() else {
        return;
    };
    let rhs = lines.next().filter(|r| !r.is_empty());
    let (defines, relations): (Vec<String>, Vec<String>) = lines
        .take(4)
        .map(str::to_string)
        .partition(|l| l.starts_with("def "));
    let defines = defines.into_iter().map(|l| l[4..].to_string()).collect();
    let random = mode.starts_with('r');
    let args = ProveArgs {
        lhs: lhs.to_string(),
        rhs: rhs.map(str::to_string),
        relations,
        defines,
        random: random.then_some(8),
        seed: random.then_some(1),
        json: mode.starts_with('j'),
    };
    if let Err(e) = run(&args) {
        let line = e.to_string();
        assert!(
            !line.contains('\n'),
            "a multi-line error for {args:?}: {line:?}"
        );
    }
});
