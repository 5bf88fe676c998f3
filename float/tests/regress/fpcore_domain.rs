//! FPCore benchmarks to sampling domains: the `:pre` interval bounds read by
//! `exactcheck_exact::program::fpcore` drive `exactcheck_float::SampleDomain`, and every sample
//! satisfies the benchmark's whole precondition.
use exactcheck_exact::program::fpcore::parse_file;
use exactcheck_exact::Rational;
use exactcheck_float::{f64_to_rational, Bound, InputGen, Range, Rng, SampleDomain};

fn exact(x: f64) -> Rational {
    Rational::from(f64_to_rational(x).expect("finite"))
}

fn satisfies(x: f64, iv: &Range) -> bool {
    let e = exact(x);
    let lo = match &iv.lo {
        Bound::Unbounded => true,
        Bound::Closed(q) => &e >= q,
        Bound::Open(q) => &e > q,
    };
    let hi = match &iv.hi {
        Bound::Unbounded => true,
        Bound::Closed(q) => &e <= q,
        Bound::Open(q) => &e < q,
    };
    lo && hi
}

#[test]
fn fpcore_preconditions_drive_the_sampler() {
    let text = r#"
(FPCore (x)
 :name "NMSE example 3.1"
 :pre (>= x 0)
 (- (sqrt (+ x 1)) (sqrt x)))
(FPCore (a b c)
 :name "quadratic root"
 :pre (and (< 1/3 a 1e9) (<= -1e3 b 1e3) (> c 0) (< c 1/10))
 (/ (- (sqrt (- (* b b) (* 4 (* a c)))) b) (* 2 a)))
"#;
    let benches = parse_file(text).expect("valid FPCore");
    let mut rng = Rng::new(11);
    for bm in &benches {
        let program = bm.program.as_ref().expect("supported");
        assert_eq!(program.pre, None, "all of :pre is interval bounds");
        let dom = SampleDomain::named(bm.domain.clone(), &bm.args).expect("non-empty domain");
        assert_eq!(dom.arity(), bm.args.len());
        for _ in 0..5000 {
            let s = dom.sample(&mut rng);
            for (x, iv) in s.iter().zip(&bm.domain) {
                assert!(
                    satisfies(*x, iv),
                    "{}: {x} outside {iv:?}",
                    bm.display_name()
                );
            }
        }
    }
    let quad = SampleDomain::new(benches[1].domain.clone())
        .and_then(|d| d.with_names(&benches[1].args))
        .expect("non-empty");
    assert_eq!(
        quad.describe(),
        "a in (1/3, 1e9) (uniform), b in [-1000, 1000] (uniform), c in (0, 1/10) (uniform)"
    );
}

#[test]
fn an_fpcore_domain_without_doubles_is_an_error() {
    let bm = parse_file("(FPCore (x) :pre (== x 1/3) x)").expect("valid");
    let e = SampleDomain::new(bm[0].domain.clone()).expect_err("1/3 is no double");
    assert!(e.to_string().contains("input 0"), "{e}");
}
