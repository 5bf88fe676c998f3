//! The FPCore reader (`exactcheck_exact::program::fpcore::parse_file`) on arbitrary text, and
//! every benchmark that compiles evaluated at a few points in f64 and exactly (the two sides of
//! `exactcheck regress`). A syntax error is an `Err` with a line and column, an unsupported
//! operation marks its benchmark; nothing panics, and the exact side answers a value or an
//! `ExactStop`.
#![no_main]
use exactcheck_exact::program::fpcore::parse_file;
use exactcheck_exact::Rational;
use exactcheck_fuzz::{small_limits, text};
use libfuzzer_sys::fuzz_target;

/// Sample inputs: doubles, so the f64 side and the exact side see the same values.
const POINTS: [(i64, i64); 6] = [(0, 1), (1, 1), (-1, 2), (3, 1), (-7, 4), (1, 1024)];

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Ok(benchmarks) = parse_file(text(data)) else {
        return;
    };
    for b in benchmarks.iter().take(4) {
        let _ = b.display_name();
        let Ok(program) = &b.program else {
            continue;
        };
        assert_eq!(
            program.arity(),
            b.args.len(),
            "arity of {}",
            b.display_name()
        );
        let _ = program.operation_count();
        for shift in 0..3 {
            let exact: Vec<Rational> = (0..program.arity())
                .map(|i| {
                    let (n, d) = POINTS[(i + shift) % POINTS.len()];
                    Rational::new(n, d).expect("non-zero denominators")
                })
                .collect();
            let float: Vec<f64> = exact.iter().map(Rational::to_f64).collect();
            let f = program.eval_f64(&float);
            assert_eq!(
                f.len(),
                program.outputs.len(),
                "outputs of {}",
                b.display_name()
            );
            if let Ok(values) = program.eval_exact(&exact) {
                assert_eq!(
                    values.len(),
                    program.outputs.len(),
                    "outputs of {}",
                    b.display_name()
                );
            }
        }
    }
});
