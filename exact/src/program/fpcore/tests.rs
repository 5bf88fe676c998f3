use super::*;
use crate::program::Format;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).expect("nonzero denominator")
}

fn x(i: usize) -> Node {
    Node::Input(i)
}

fn c(n: i64) -> Node {
    Node::Const(Rational::from_integer(n))
}

fn b(n: Node) -> Box<Node> {
    Box::new(n)
}

fn one(text: &str) -> Benchmark {
    let mut all = parse_file(text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(all.len(), 1, "{text}");
    all.pop().expect("one benchmark")
}

fn program(text: &str) -> Program {
    one(text)
        .program
        .unwrap_or_else(|u| panic!("{u} in {text}"))
}

fn body(text: &str) -> Node {
    let p = program(text);
    assert_eq!(p.outputs.len(), 1);
    p.outputs[0].clone()
}

fn unsupported_op(text: &str) -> String {
    match one(text).program {
        Err(u) => u.op,
        Ok(p) => panic!("{text} compiled to {p:?}"),
    }
}

fn syntax_error(text: &str) -> FpCoreError {
    match parse_file(text) {
        Err(e) => e,
        Ok(b) => panic!("{text} parsed to {b:?}"),
    }
}

const SPEC: &str = include_str!("../../../tests/fpcore/spec_examples.fpcore");

#[test]
fn spec_examples_parse_and_are_classified() {
    let all = parse_file(SPEC).unwrap_or_else(|e| panic!("{e}"));
    let verdicts: Vec<(String, Result<(), String>)> = all
        .iter()
        .map(|bm| {
            (
                bm.display_name(),
                bm.program.as_ref().map(|_| ()).map_err(|u| u.to_string()),
            )
        })
        .collect();
    let ns = |s: &str| Err(format!("not supported: {s}"));
    let expected: Vec<(&str, Result<(), String>)> = vec![
        ("NMSE example 3.1", Ok(())),
        ("round with addition", Ok(())),
        ("rounding: lexical scoping", Ok(())),
        ("cast 1", Ok(())),
        ("cast 2", Ok(())),
        ("cast 3", Ok(())),
        ("cast 4", Ok(())),
        ("foo", Ok(())),
        ("inherit 1", ns("round toZero")),
        ("inherit 2", ns("round toPositive")),
        ("identity array", ns("array")),
        ("identity tensor", ns("tensor")),
        ("zeros", ns("tensor")),
        ("FPCore at line 60", ns("tensor")),
        ("matmul", ns("tensor")),
        ("parsum-1d", ns("tensor")),
    ];
    let expected: Vec<(String, Result<(), String>)> = expected
        .into_iter()
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    assert_eq!(verdicts, expected);

    let nmse = &all[0];
    assert_eq!(nmse.line, 9);
    assert_eq!(nmse.args, vec!["x"]);
    assert_eq!(
        nmse.domain,
        vec![Range {
            lo: Bound::Closed(Rational::ZERO),
            hi: Bound::Unbounded
        }]
    );
    let p = nmse.program.as_ref().expect("supported");
    assert_eq!(p.name, "NMSE example 3.1");
    assert_eq!(p.pre, None);
    assert_eq!(
        p.outputs,
        vec![Node::Sub(
            b(Node::Sqrt(b(Node::Add(b(x(0)), b(c(1)))))),
            b(Node::Sqrt(b(x(0))))
        )]
    );

    let round = all[1].program.as_ref().expect("supported");
    assert_eq!(round.slots, 1);
    assert_eq!(
        round.outputs,
        vec![Node::Let(
            vec![(0, c(6_755_399_441_055_744))],
            b(Node::Sub(
                b(Node::Add(b(x(0)), b(Node::Slot(0)))),
                b(Node::Slot(0))
            ))
        )]
    );

    // The tensor benchmark with a dimension argument: `k` gets its bound from `(<= 0 k n)`;
    // `n` is a dimension, not an argument, so `(<= k n)` is no interval bound.
    let tensor = &all[13];
    assert_eq!(tensor.args, vec!["A", "k"]);
    assert_eq!(tensor.domain[1].lo, Bound::Closed(Rational::ZERO));
    assert_eq!(tensor.domain[1].hi, Bound::Unbounded);
    assert_eq!(all[14].ident.as_deref(), Some("matmul"));
    assert_eq!(all[14].name, None);
}

#[test]
fn every_arithmetic_operation_compiles_to_its_node() {
    let cases: Vec<(&str, Node)> = vec![
        ("(+ x y)", Node::Add(b(x(0)), b(x(1)))),
        ("(- x y)", Node::Sub(b(x(0)), b(x(1)))),
        ("(* x y)", Node::Mul(b(x(0)), b(x(1)))),
        ("(/ x y)", Node::Div(b(x(0)), b(x(1)))),
        ("(- x)", Node::Neg(b(x(0)))),
        ("(neg y)", Node::Neg(b(x(1)))),
        ("(sqrt x)", Node::Sqrt(b(x(0)))),
        ("(fabs x)", Node::Abs(b(x(0)))),
        ("(fma x y 2)", Node::Fma(b(x(0)), b(x(1)), b(c(2)))),
        ("(fmin x y)", Node::Min(b(x(0)), b(x(1)))),
        ("(fmax x y)", Node::Max(b(x(0)), b(x(1)))),
        ("(pow x 3)", Node::Pow(b(x(0)), 3, PowStyle::Libm)),
        ("(pow x -2)", Node::Pow(b(x(0)), -2, PowStyle::Libm)),
        ("(pow x (- 2))", Node::Pow(b(x(0)), -2, PowStyle::Libm)),
        ("(pow x 2.0)", Node::Pow(b(x(0)), 2, PowStyle::Libm)),
        (
            "(! :precision binary64 (+ x y))",
            Node::Add(b(x(0)), b(x(1))),
        ),
        (
            "(if (< x y) x y)",
            Node::If(Box::new(Cond::Cmp(CmpOp::Lt, x(0), x(1))), b(x(0)), b(x(1))),
        ),
    ];
    for (expr, node) in cases {
        let text = format!("(FPCore (x y) :precision binary64 {expr})");
        assert_eq!(body(&text), node, "{expr}");
    }
}

#[test]
fn literals_are_exact() {
    let lit = |s: &str| body(&format!("(FPCore () {s})"));
    assert_eq!(lit("0.1"), Node::Const(q(1, 10)));
    assert_eq!(lit("-1.5e-3"), Node::Const(q(-3, 2000)));
    assert_eq!(lit("+.25"), Node::Const(q(1, 4)));
    assert_eq!(lit("1e3"), c(1000));
    assert_eq!(lit("1/3"), Node::Const(q(1, 3)));
    assert_eq!(lit("-6/4"), Node::Const(q(-3, 2)));
    assert_eq!(lit("0x1.8p3"), c(12));
    assert_eq!(lit("0x.8"), Node::Const(q(1, 2)));
    assert_eq!(lit("-0x10p-5"), Node::Const(q(-1, 2)));
    assert_eq!(lit("(digits 3 -2 10)"), Node::Const(q(3, 100)));
    assert_eq!(lit("(digits -5 3 2)"), c(-40));
    let tiny = lit("4.9406564584124654e-324");
    let Node::Const(t) = tiny else {
        panic!("a constant")
    };
    assert_eq!(t.to_f64(), 5e-324);
    assert!(t.denom() > num_bigint::BigInt::from(10).pow(300));
}

#[test]
fn comparisons_are_chained_and_ne_is_all_pairs() {
    let cond = |s: &str| match body(&format!("(FPCore (x y z) (if {s} 1 0))")) {
        Node::If(c, _, _) => *c,
        other => panic!("{other:?}"),
    };
    use CmpOp::*;
    assert_eq!(
        cond("(<= x y z)"),
        Cond::And(vec![Cond::Cmp(Le, x(0), x(1)), Cond::Cmp(Le, x(1), x(2))])
    );
    assert_eq!(
        cond("(!= x y z)"),
        Cond::And(vec![
            Cond::Cmp(Ne, x(0), x(1)),
            Cond::Cmp(Ne, x(0), x(2)),
            Cond::Cmp(Ne, x(1), x(2))
        ])
    );
    assert_eq!(cond("(> x 1)"), Cond::Cmp(Gt, x(0), c(1)));
    assert_eq!(cond("(>= x 1)"), Cond::Cmp(Ge, x(0), c(1)));
    assert_eq!(cond("(== x y)"), Cond::Cmp(Eq, x(0), x(1)));
    assert_eq!(
        cond("(and (< x y) (or TRUE (not FALSE)))"),
        Cond::And(vec![
            Cond::Cmp(Lt, x(0), x(1)),
            Cond::Or(vec![
                Cond::Bool(true),
                Cond::Not(Box::new(Cond::Bool(false)))
            ])
        ])
    );
}

#[test]
fn let_is_parallel_and_let_star_sequential() {
    // The two examples of the standard: `(let ([a b] [b a]) (- a b))` is `(- b a)`, and
    // `(let* ([a b] [b a]) (- a b))` is `(- b b)`.
    let par = program("(FPCore (a b) (let ([a b] [b a]) (- a b)))");
    assert_eq!(par.slots, 2);
    assert_eq!(
        par.outputs[0],
        Node::Let(
            vec![(0, x(1)), (1, x(0))],
            b(Node::Sub(b(Node::Slot(0)), b(Node::Slot(1))))
        )
    );
    let seq = program("(FPCore (a b) (let* ([a b] [b a]) (- a b)))");
    assert_eq!(
        seq.outputs[0],
        Node::Let(
            vec![(0, x(1)), (1, Node::Slot(0))],
            b(Node::Sub(b(Node::Slot(0)), b(Node::Slot(1))))
        )
    );
    // `(let ([a 1] [b a]) b)` sees the outer `a`; with `let*` the inner one.
    let outer = program("(FPCore (a) (let ([a 1] [b a]) b))");
    assert_eq!(
        outer.outputs[0],
        Node::Let(vec![(0, c(1)), (1, x(0))], b(Node::Slot(1)))
    );
    let inner = program("(FPCore (a) (let* ([a 1] [b a]) b))");
    assert_eq!(
        inner.outputs[0],
        Node::Let(vec![(0, c(1)), (1, Node::Slot(0))], b(Node::Slot(1)))
    );
    // The scope ends with the body.
    let after = program("(FPCore (a) (+ (let ([a 2]) a) a))");
    assert_eq!(
        after.outputs[0],
        Node::Add(b(Node::Let(vec![(0, c(2))], b(Node::Slot(0)))), b(x(0)))
    );
    // Boolean bindings and a boolean `let` body are substituted.
    let boolean = program("(FPCore (x) (let ([t (* x x)]) (if (let ([c (< t 1)]) c) t 0)))");
    assert_eq!(
        boolean.outputs[0],
        Node::Let(
            vec![(0, Node::Mul(b(x(0)), b(x(0))))],
            b(Node::If(
                Box::new(Cond::Cmp(CmpOp::Lt, Node::Slot(0), c(1))),
                b(Node::Slot(0)),
                b(c(0))
            ))
        )
    );
    let bool_body = program("(FPCore (x) (if (let* ([u (+ x 1)] [v (* u u)]) (< v 4)) 1 0))");
    let Node::If(cond, _, _) = &bool_body.outputs[0] else {
        panic!("an if")
    };
    let u = Node::Add(b(x(0)), b(c(1)));
    assert_eq!(
        **cond,
        Cond::Cmp(CmpOp::Lt, Node::Mul(b(u.clone()), b(u)), c(4))
    );
}

#[test]
fn functions_and_constants_compile_to_calls() {
    let call = |f: Func, args: Vec<Node>| Node::Fun(f, args);
    let cases = [
        ("(sin x)", call(Func::Sin, vec![x(0)])),
        ("(+ x PI)", Node::Add(b(x(0)), b(call(Func::Pi, vec![])))),
        ("(* E x)", Node::Mul(b(call(Func::E, vec![])), b(x(0)))),
        ("(cbrt x)", call(Func::Cbrt, vec![x(0)])),
        ("(hypot x y)", call(Func::Hypot, vec![x(0), x(1)])),
        ("(atan2 y x)", call(Func::Atan2, vec![x(1), x(0)])),
        (
            "(pow x 0.5)",
            call(
                Func::Pow,
                vec![x(0), Node::Const(Rational::new(1, 2).unwrap())],
            ),
        ),
        ("(pow x y)", call(Func::Pow, vec![x(0), x(1)])),
        ("(pow x 3)", Node::Pow(b(x(0)), 3, PowStyle::Libm)),
    ];
    for (expr, want) in cases {
        let p = program(&format!("(FPCore (x y) {expr})"));
        assert_eq!(p.outputs, vec![want], "{expr}");
    }
    // A wrong number of arguments is a syntax error of the file.
    let e = syntax_error("(FPCore (x) (atan2 x))");
    assert!(
        e.message.contains("`atan2` takes 2 arguments, found 1"),
        "{e}"
    );
    // The float side is the C library, the exact side the certified value.
    let p = program("(FPCore (x) (- (exp x) 1))");
    let r = p.eval_exact(&[Rational::new(1, 1 << 20).unwrap()]).unwrap();
    let want = (1.0f64 / 1048576.0).exp_m1();
    assert_eq!(crate::to_f64::rational_to_f64(&r[0].value), want);
    assert_eq!(
        p.eval_f64(&[1.0 / 1048576.0])[0],
        (1.0f64 / 1048576.0).exp() - 1.0
    );
}

#[test]
fn arrays_give_several_outputs() {
    let p = program("(FPCore (x y) (array (+ x y) (- x y)))");
    assert_eq!(
        p.outputs,
        vec![Node::Add(b(x(0)), b(x(1))), Node::Sub(b(x(0)), b(x(1)))]
    );
}

#[test]
fn unsupported_operations_mark_only_their_benchmark() {
    let text = "(FPCore (x) :name \"a\" (erf x))\n(FPCore (x) :name \"b\" (+ x 1))\n(FPCore (x) :name \"c\" (for ([i 3]) ([y x (* 2 y)]) y))";
    let all = parse_file(text).expect("valid syntax");
    assert_eq!(all.len(), 3);
    assert_eq!(
        all[0].program.as_ref().unwrap_err().to_string(),
        "not supported: erf"
    );
    assert!(all[1].program.is_ok());
    assert_eq!(all[2].program.as_ref().unwrap_err().op, "for");
    assert_eq!(all[2].line, 3);

    let cases = [
        ("(tgamma x)", "tgamma"),
        ("(+ x LN2)", "LN2"),
        ("(pow x 1e10)", "pow with an exponent beyond 32 bits"),
        ("(! :precision real (+ x y))", "precision real"),
        ("(if (isnan x) 0 x)", "isnan"),
        ("(tensor ([i 3]) i)", "tensor"),
        ("(for ([i 3]) ([s 0 (+ s i)]) s)", "for"),
        ("(< x y)", "boolean result"),
        ("(my-other-fpcore x)", "my-other-fpcore"),
        ("(+ x INFINITY)", "INFINITY"),
    ];
    for (expr, op) in cases {
        assert_eq!(
            unsupported_op(&format!("(FPCore (x y) {expr})")),
            op,
            "{expr}"
        );
    }
    // An argument of another FPCore precision than binary64 and binary32 (binary32 arguments
    // of a binary64 benchmark are supported: `argument_precision_tests`).
    assert_eq!(
        unsupported_op("(FPCore ((! :precision binary80 x)) (+ x 1))"),
        "precision binary80"
    );
    // Another precision inside the benchmark's is a scope of the program (`mixed_tests`).
    assert_eq!(
        body("(FPCore (x) :precision binary32 (! :precision binary64 (+ x 1)))"),
        Node::Precision(
            Format::Binary64,
            Box::new(Node::Add(
                Box::new(Node::Input(0)),
                Box::new(Node::Const(Rational::ONE))
            ))
        )
    );
    assert_eq!(
        unsupported_op("(FPCore (x) (! :precision binary80 (+ x 1)))"),
        "precision binary80"
    );
    assert_eq!(
        unsupported_op("(FPCore (x) :precision binary80 (+ x 1))"),
        "precision binary80"
    );
    // One precision throughout, binary32 included: `cast` to it changes nothing.
    let p = program(
        "(FPCore ((! :precision binary32 x)) :precision binary32 (cast (! :precision binary32 (+ x 1))))",
    );
    assert_eq!(p.precision, Format::Binary32);
    assert_eq!(
        p.outputs,
        vec![Node::Add(
            Box::new(Node::Input(0)),
            Box::new(Node::Const(Rational::ONE))
        )]
    );
    assert_eq!(program("(FPCore (x) (cast x))").precision, Format::Binary64);
    assert_eq!(unsupported_op("(FPCore (x) :pre (< (erf x) 2) x)"), "erf");
    // An annotated binary64 argument is fine.
    let p = program("(FPCore ((! :precision binary64 x) y) :round nearestEven (+ x y))");
    assert_eq!(p.inputs, vec!["x", "y"]);
}

#[test]
fn syntax_errors_have_line_column_and_what_was_expected() {
    let cases: Vec<(&str, usize, usize, &str)> = vec![
        (
            "(FPCore (x) :pre x)",
            1,
            13,
            "expected a value after the property `:pre`",
        ),
        (
            "(FPCore (x)\n  (+ x 1)",
            2,
            10,
            "expected `)` to close the `(` at 1:1",
        ),
        (
            "(FPCore (x) (+ x 1]))",
            1,
            19,
            "expected `)` to close the `(` at 1:13, found `]`",
        ),
        ("(FPCore (x) x))", 1, 15, "unexpected `)`"),
        ("(FPCore (x)\n (+ x 1.2.3))", 2, 7, "expected a number"),
        (
            "(FPCore (x) :name \"abc",
            1,
            23,
            "expected `\"` to end the string at 1:19",
        ),
        (
            "(FPCore (x) :name)",
            1,
            13,
            "expected a value after the property `:name`",
        ),
        ("(FPCore (x))", 1, 1, "expected the benchmark's body"),
        ("(FPC (x) x)", 1, 1, "expected `(FPCore ...)`"),
        ("; c\n(FPCore (x) (+ x y))", 2, 18, "unbound variable `y`"),
        (
            "(FPCore (x) (sqrt x x))",
            1,
            13,
            "`sqrt` takes 1 argument, found 2",
        ),
        ("(FPCore (x x) x)", 1, 12, "duplicate argument `x`"),
        (
            "(FPCore (x) (let ([a 1] [a 2]) a))",
            1,
            25,
            "`a` is bound twice",
        ),
    ];
    for (text, line, col, what) in cases {
        let e = syntax_error(text);
        assert_eq!((e.line, e.col), (line, col), "{text}: {e}");
        assert!(e.message.contains(what), "{text}: {e}");
        let shown = e.to_string();
        assert!(!shown.contains('\n'), "{shown}");
        assert!(
            shown.starts_with(&format!("FPCore {line}:{col}: ")),
            "{shown}"
        );
    }
    // Nesting is limited instead of overflowing the stack.
    let deep = format!(
        "(FPCore (x) {}x{})",
        "(- ".repeat(100_000),
        ")".repeat(100_000)
    );
    let e = syntax_error(&deep);
    assert!(e.message.contains("exceeds the limit depth = "), "{e}");
    let fine = format!("(FPCore (x) {}x{})", "(- ".repeat(200), ")".repeat(200));
    assert!(one(&fine).program.is_ok());
    // A later benchmark's syntax error fails the whole file.
    assert!(parse_file("(FPCore (x) x)\n(FPCore (x) (+ x 1 2))").is_err());
    // Mixed number/condition misuse.
    assert!(syntax_error("(FPCore (x) (+ x (< x 1)))")
        .message
        .contains("expected a number"));
    assert!(syntax_error("(FPCore (x) (if x 1 2))")
        .message
        .contains("expected a condition"));
}

#[test]
fn comments_strings_and_properties() {
    let text = "; leading comment\n(FPCore name-here (x) ; trailing\n :name \"with \\\"quotes\\\" and \\\\ slash\"\n :cite (a b c) :description \"ignored\"\n [+ x 1])\n";
    let bm = one(text);
    assert_eq!(bm.name.as_deref(), Some("with \"quotes\" and \\ slash"));
    assert_eq!(bm.ident.as_deref(), Some("name-here"));
    assert_eq!(bm.line, 2);
    assert_eq!(program(text).outputs[0], Node::Add(b(x(0)), b(c(1))));
    assert!(parse_file("").expect("empty file").is_empty());
    // Non-ASCII letters in symbols; other characters are refused.
    assert_eq!(program("(FPCore (α β) (+ α β))").inputs, vec!["α", "β"]);
    let e = syntax_error("(FPCore (x) (+ x#y 1))");
    assert!(e.message.contains("the character `#`"), "{e}");
    // A stray datum among the properties is skipped (FPBench's hamming-ch3.fpcore has
    // `:cite (hamming-1987) herbie-2015`).
    let bm = one("(FPCore (x) :cite (hamming-1987) herbie-2015 :pre (!= x 0) (/ 1 x))");
    assert_eq!(
        bm.program.expect("supported").pre,
        Some(Cond::Cmp(CmpOp::Ne, x(0), c(0)))
    );
}

#[test]
fn pre_bounds_become_the_domain_and_the_rest_the_precondition() {
    let bm = one(
        "(FPCore (x y z w v) :pre (and (<= -1 x 1/3) (and (< 0 y) (>= z 0) (> 5 z)) (< x 1) (<= x 1) (== w 2) (< y x) (!= v 0)) (+ x y))",
    );
    let cl = |n, d| Bound::Closed(q(n, d));
    let op = |n, d| Bound::Open(q(n, d));
    assert_eq!(
        bm.domain,
        vec![
            Range {
                lo: cl(-1, 1),
                hi: cl(1, 3)
            },
            Range {
                lo: op(0, 1),
                hi: Bound::Unbounded
            },
            Range {
                lo: cl(0, 1),
                hi: op(5, 1)
            },
            Range {
                lo: cl(2, 1),
                hi: cl(2, 1)
            },
            Range::UNBOUNDED,
        ]
    );
    let p = bm.program.expect("supported");
    assert_eq!(
        p.pre,
        Some(Cond::And(vec![
            Cond::Cmp(CmpOp::Lt, x(1), x(0)),
            Cond::Cmp(CmpOp::Ne, x(4), c(0)),
        ]))
    );
    // Strictness wins at equal bounds, the tighter value otherwise.
    let d = one("(FPCore (x) :pre (and (<= 0 x 2) (< 0 x) (<= x 1) (< x 3)) x)").domain;
    assert_eq!(
        d,
        vec![Range {
            lo: op(0, 1),
            hi: cl(1, 1)
        }]
    );
    // A pair between a number and a non-argument, or two numbers, stays a condition.
    let p = program("(FPCore (x) :pre (<= 0 (* x x) 1) x)");
    assert_eq!(
        p.pre,
        Some(Cond::And(vec![
            Cond::Cmp(CmpOp::Le, c(0), Node::Mul(b(x(0)), b(x(0)))),
            Cond::Cmp(CmpOp::Le, Node::Mul(b(x(0)), b(x(0))), c(1)),
        ]))
    );
    let bm = one("(FPCore (x) :pre (<= 0 x 1 2) x)");
    assert_eq!(
        bm.domain,
        vec![Range {
            lo: cl(0, 1),
            hi: cl(1, 1)
        }]
    );
    assert_eq!(
        bm.program.expect("supported").pre,
        Some(Cond::Cmp(CmpOp::Le, c(1), c(2)))
    );
    // `TRUE` adds no precondition.
    assert_eq!(program("(FPCore (x) :pre (and TRUE (>= x 0)) x)").pre, None);
    // Negated literals and `digits` are literals.
    let d = one("(FPCore (x) :pre (<= (- 2) x (digits 3 2 10)) x)").domain;
    assert_eq!(
        d,
        vec![Range {
            lo: cl(-2, 1),
            hi: cl(300, 1)
        }]
    );
}

/// Every supported operation evaluated both ways, after the merge with the evaluators: the f64
/// side equals the same operations written in Rust, the exact side the value computed by hand.
#[test]
fn every_supported_operation_evaluates_both_ways() {
    let p = program(
        "(FPCore (a b c)
           :precision binary64
           (let* ((s (+ a b)) (d (- s c)) (m (* a (/ b 3))))
             (let ((t (fma a b (neg c))) (u (fmin a (fmax b c))))
               (if (and (< a b) (not (== a c)) (or (>= c 0) (!= b 1)))
                   (+ (+ (+ (fabs d) (sqrt (* s s))) (pow m 2)) (- t u))
                   (* (digits 3 -1 10) 0.1)))))",
    );
    let f = |a: f64, b: f64, c: f64| -> f64 {
        let s = a + b;
        let d = s - c;
        let m = a * (b / 3.0);
        let t = a.mul_add(b, -c);
        let u = a.min(b.max(c));
        if a < b && a != c && (c >= 0.0 || b != 1.0) {
            ((d.abs() + (s * s).sqrt()) + m.powf(2.0)) + (t - u)
        } else {
            0.3 * 0.1
        }
    };
    for (a, b, c) in [(0.5, 3.0, 2.0), (3.0, 0.5, 2.0), (-1.25, 7.5, -0.75)] {
        assert_eq!(p.eval_f64(&[a, b, c]), vec![f(a, b, c)], "{a} {b} {c}");
    }
    // Exactly at (1/2, 3, 2): s = 7/2, d = 3/2, m = 1/2, t = -1/2, u = 1/2:
    // 3/2 + 7/2 + 1/4 + (-1/2 - 1/2) = 17/4; on the other branch (digits 3 -1 10) * 1/10 = 3/100.
    let r = |v: f64| Rational::from(num_rational::BigRational::from_float(v).expect("finite"));
    let exact = p.eval_exact(&[r(0.5), r(3.0), r(2.0)]).expect("defined");
    assert_eq!(exact.len(), 1);
    assert!(exact[0].exact);
    assert_eq!(exact[0].value, q(17, 4).to_big_rational());
    let other = p.eval_exact(&[r(3.0), r(0.5), r(2.0)]).expect("defined");
    assert_eq!(other[0].value, q(3, 100).to_big_rational());
}

#[test]
fn a_pre_written_with_let_reads_as_written_directly() {
    let direct = one("(FPCore (x y) :pre (and (<= 1/2 x 3) (< y x) (> y -1)) (+ x y))");
    for with_let in [
        "(FPCore (x y) :pre (let ([lo 1/2] [hi 3]) (and (<= lo x hi) (< y x) (> y -1))) (+ x y))",
        "(FPCore (x y) :pre (let* ([a x] [lo 1/2] [hi 3]) (and (<= lo a hi) (< y a) (> y (- 1)))) (+ x y))",
        "(FPCore (x y) :pre (let ([t x]) (let ([x y]) (and (<= 1/2 t 3) (< x t) (> x -1)))) (+ x y))",
    ] {
        let bm = one(with_let);
        assert_eq!(bm.domain[0], direct.domain[0], "{with_let}");
        assert_eq!(bm.domain[1], direct.domain[1], "{with_let}");
        assert_eq!(
            bm.program.as_ref().expect("supported").pre,
            direct.program.as_ref().expect("supported").pre,
            "{with_let}"
        );
    }
    // A binding that is not a literal or a name stays a `let` (its bounds are conditions), and
    // a substitution that an inner `let` would capture is not made.
    let kept = one("(FPCore (x) :pre (let ([s (* x x)]) (<= s 4)) x)");
    assert_eq!(kept.domain, vec![Range::UNBOUNDED]);
    assert!(kept.program.expect("supported").pre.is_some());
    let captured = one("(FPCore (x y) :pre (let ([a x]) (let ([x (+ y 1)]) (< a x))) x)");
    assert_eq!(captured.domain, vec![Range::UNBOUNDED; 2]);
    assert_eq!(
        captured.program.expect("supported").pre,
        Some(Cond::Cmp(CmpOp::Lt, x(0), Node::Add(b(x(1)), b(c(1)))))
    );
}

#[path = "loop_tests.rs"]
mod loop_tests;
