//! Tests of the compiler and the two evaluators of float programs.
use super::interval::{Dir, Dy, Iv};
use super::*;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n, d).unwrap()
}

/// The exact value of a finite double.
fn exact(x: f64) -> Rational {
    Rational::from(BigRational::from_float(x).expect("finite"))
}

fn prog(text: &str) -> Program {
    Program::parse(text, None).unwrap()
}

fn vars(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| s.to_string()).collect()
}

fn b(n: Node) -> Box<Node> {
    Box::new(n)
}

fn c(n: i64) -> Node {
    Node::Const(Rational::from_integer(n))
}

fn one_output(nodes: Node, inputs: &[&str]) -> Program {
    Program {
        name: "test".into(),
        inputs: vars(inputs),
        slots: 0,
        pre: None,
        outputs: vec![nodes],
        precision: Format::Binary64,
        input_precision: Vec::new(),
    }
}

fn exact_value(p: &Program, x: &[Rational]) -> BigRational {
    let r = p.eval_exact(x).unwrap();
    assert!(r[0].exact, "{} not exact", p.name);
    r[0].value.clone()
}

/// `10^-digits`-accurate lower bound of `sqrt(n)`, by integer square root, and its error bound.
fn sqrt_reference(n: u64, digits: u32) -> (BigRational, BigRational) {
    let scale = BigInt::from(10).pow(digits);
    let r = (BigInt::from(n) * &scale * &scale).sqrt();
    (
        BigRational::new(r, scale.clone()),
        BigRational::new(BigInt::one(), scale),
    )
}

/// Asserts that `r` meets the accuracy contract for a true value known as `t` to within `err`:
/// `|value - t| + err <= 2^-REL_BITS (|t| - err)`, which implies it for the true value.
fn assert_contract(r: &Reference, t: &BigRational, err: &BigRational) {
    if r.exact {
        assert!((&r.value - t).abs() <= *err, "exact {} vs {}", r.value, t);
        return;
    }
    let dist = (&r.value - t).abs() + err;
    let rel = BigRational::new(BigInt::one(), BigInt::one() << REL_BITS);
    assert!(
        dist <= rel * (t.abs() - err),
        "value {} too far from {}",
        r.value,
        t
    );
}

// ------------------------------------------------------------------ compiler

#[test]
fn sums_and_products_chain_from_the_left_in_the_order_written() {
    let p = Program::parse("x - y + z", None).unwrap();
    assert_eq!(
        p.outputs[0],
        Node::Chain(
            b(Node::Input(0)),
            vec![
                (ChainOp::Sub, Node::Input(1)),
                (ChainOp::Add, Node::Input(2))
            ]
        )
    );
    let p = Program::parse("x / y * z", None).unwrap();
    assert_eq!(
        p.outputs[0],
        Node::Chain(
            b(Node::Input(0)),
            vec![
                (ChainOp::Div, Node::Input(1)),
                (ChainOp::Mul, Node::Input(2))
            ]
        )
    );
    // Division by a non-constant is allowed; juxtaposition multiplies; -x^2 = -(x^2).
    let p = Program::parse("2x / (y - 1) - z^2", None).unwrap();
    assert_eq!(
        p.outputs[0],
        Node::Sub(
            b(Node::Chain(
                b(c(2)),
                vec![
                    (ChainOp::Mul, Node::Input(0)),
                    (ChainOp::Div, Node::Sub(b(Node::Input(1)), b(c(1))))
                ]
            )),
            b(Node::Pow(b(Node::Input(2)), 2, PowStyle::Multiply))
        )
    );
    let p = Program::parse("-sqrt(x)^-3", None).unwrap();
    assert_eq!(
        p.outputs[0],
        Node::Neg(b(Node::Pow(
            b(Node::Sqrt(b(Node::Input(0)))),
            -3,
            PowStyle::Multiply
        )))
    );
    assert_eq!(p.name, "-sqrt(x)^-3");
    assert_eq!((p.slots, p.pre.clone(), p.outputs.len()), (0, None, 1));
}

#[test]
fn long_sums_and_products_are_flat_chains_evaluated_without_deep_recursion() {
    // On a thread with a small stack: a left-deep tree of binary nodes recursed once per term
    // in the walk, the clone and the drop, and overflowed the stack of a rayon worker at a few
    // thousand terms.
    let run = || {
        let n = 20_000;
        let sum = vec!["x"; n].join(" + ");
        let p = Program::parse(&format!("{sum} - x"), None).unwrap();
        assert!(matches!(&p.outputs[0], Node::Chain(_, ops) if ops.len() == n));
        assert_eq!(p.operation_count(), n);
        let q = p.clone();
        assert_eq!(q.eval_f64(&[0.5]), vec![0.5 * (n - 1) as f64]);
        let exact = exact_value(&q, &[Rational::from_integer(3)]);
        assert_eq!(exact, BigRational::from_integer(BigInt::from(3 * (n - 1))));
        let prod = vec!["y"; n].join(" * ");
        let p = Program::parse(&format!("{prod} / y"), None).unwrap();
        assert_eq!(p.eval_f64(&[1.0]), vec![1.0]);
        assert_eq!(exact_value(&p, &[Rational::ONE]), BigRational::one());
    };
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(run)
        .unwrap()
        .join()
        .unwrap();
}

#[test]
fn leading_divide_means_reciprocal() {
    // The parser never builds it; a program built by hand may.
    let e = crate::expr::Expr::new(crate::expr::ExprKind::Product(vec![(
        crate::expr::MulOp::Divide,
        crate::expr::parse_expr("x").unwrap(),
    )]));
    let p = Program::from_expr(&e, None).unwrap();
    assert_eq!(
        p.outputs[0],
        Node::Div(b(Node::Const(Rational::ONE)), b(Node::Input(0)))
    );
}

#[test]
fn variables_in_order_of_appearance_or_as_listed() {
    let p = Program::parse("b*a + c - a", None).unwrap();
    assert_eq!(p.inputs, vars(&["b", "a", "c"]));
    assert_eq!(p.arity(), 3);
    let p = Program::parse("b*a + c - a", Some(&vars(&["a", "b", "c", "d"]))).unwrap();
    assert_eq!(p.inputs, vars(&["a", "b", "c", "d"]));
    assert_eq!(
        p.outputs[0],
        Node::Chain(
            b(Node::Mul(b(Node::Input(1)), b(Node::Input(0)))),
            vec![
                (ChainOp::Add, Node::Input(2)),
                (ChainOp::Sub, Node::Input(0))
            ]
        )
    );
    assert_eq!(
        p.eval_f64(&[1.0, 2.0, 3.0, 4.0]),
        vec![2.0 * 1.0 + 3.0 - 1.0]
    );
}

#[test]
fn unknown_variable_names_it_and_the_list() {
    let e = Program::parse("x + yy", Some(&vars(&["x", "y"]))).unwrap_err();
    assert_eq!(
        e.to_string(),
        "unknown variable 'yy' at 4: the variables are x, y"
    );
    assert_eq!(e.position(), 4);
    let e = Program::parse("x", Some(&[])).unwrap_err();
    assert_eq!(
        e.to_string(),
        "unknown variable 'x' at 0: the variables are (none)"
    );
    let e = Program::parse("x", Some(&vars(&["x", "x"]))).unwrap_err();
    assert_eq!(e.to_string(), "variable 'x' is listed twice");
}

#[test]
fn variable_lists_hold_variable_names_only() {
    // `--vars 'x,,y'` splits into an empty name, which no formula can use.
    let e = Program::parse("x + y", Some(&vars(&["x", "", "y"]))).unwrap_err();
    assert_eq!(
        e.to_string(),
        "\"\" in the variable list is not a variable name"
    );
    for bad in ["2x", " x", "x y", "x+1", "sqrt(x)"] {
        let e = Program::parse("x", Some(&vars(&["x", bad]))).unwrap_err();
        assert!(
            matches!(e, CompileError::BadVariable { .. }),
            "{bad:?}: {e}"
        );
    }
    assert!(Program::parse("x_1 + y", Some(&vars(&["y", "x_1"]))).is_ok());
}

#[test]
fn exponents_are_bounded_integer_constants() {
    assert!(Program::parse("x^1024 + x^-1024 + x^(2*512)", None).is_ok());
    let e = Program::parse("x^1025", None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "exponent at 2: exponent of a power in a regressed formula exceeds the limit \
         formula-exponent = 1024 (found 1025; raise it with --limit formula-exponent=N)"
    );
    let e = Program::parse("1 + x^-(2^11)", None).unwrap_err();
    assert!(
        matches!(e, CompileError::ExponentTooLarge { pos: 6, .. }),
        "{e}"
    );
    let e = Program::parse("x^y", None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "exponent at 2 must be an integer constant, found y"
    );
    let e = Program::parse("x^(1/3)", None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "exponent at 2 must be an integer constant, found 1/3"
    );
    // A half-integer exponent is read as a power of the square root, as in every formula.
    assert_eq!(
        Program::parse("x^(3/2)", None).unwrap().operation_count(),
        prog("sqrt(x)^3").operation_count()
    );
    // Syntax errors keep their position.
    let e = Program::parse("x + * 2", None).unwrap_err();
    assert_eq!(e.position(), 4);
    assert!(matches!(e, CompileError::Expr(_)));
}

#[test]
fn operation_count_and_arity() {
    let p = prog("((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y");
    assert_eq!(p.operation_count(), 11);
    assert_eq!(p.arity(), 4);
    let p = Program {
        name: "t".into(),
        inputs: vars(&["x"]),
        slots: 1,
        pre: Some(Cond::And(vec![Cond::Cmp(
            CmpOp::Gt,
            Node::Input(0),
            Node::Neg(b(c(1))),
        )])),
        outputs: vec![Node::Let(
            vec![(0, Node::Sqrt(b(Node::Input(0))))],
            b(Node::If(
                Box::new(Cond::Cmp(CmpOp::Lt, Node::Slot(0), c(1))),
                b(Node::Slot(0)),
                b(c(0)),
            )),
        )],
        precision: Format::Binary64,
        input_precision: Vec::new(),
    };
    // neg, sqrt, two comparisons.
    assert_eq!(p.operation_count(), 4);
}

// ------------------------------------------------------------------ sqrt-free programs

/// The test formula, in f64 as written and in rationals.
fn f_f64(x: f64, y: f64, z: f64, w: f64) -> f64 {
    ((x + y) * (z - w) - x * z / (y + 2.0)) * (w + 1.0) + x * y
}

fn f_exact(x: &Rational, y: &Rational, z: &Rational, w: &Rational) -> Rational {
    let two = Rational::from_integer(2);
    ((x + y) * (z - w) - (x * z).checked_div(&(y + &two)).unwrap()) * (w + &Rational::ONE) + x * y
}

const F: &str = "((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y";

proptest! {
    #[test]
    fn prop_sqrt_free_formula_both_sides(
        x in -1e3f64..1e3, y in -1.0f64..1.0, z in -1e-3f64..1e-3, w in -1e30f64..1e30
    ) {
        let p = Program::parse(F, Some(&vars(&["x", "y", "z", "w"]))).unwrap();
        let f = p.eval_f64(&[x, y, z, w]);
        prop_assert_eq!(f[0].to_bits(), f_f64(x, y, z, w).to_bits());
        let xs = [exact(x), exact(y), exact(z), exact(w)];
        let r = p.eval_exact(&xs).unwrap();
        prop_assert!(r[0].exact);
        prop_assert_eq!(
            &r[0].value,
            &f_exact(&xs[0], &xs[1], &xs[2], &xs[3]).to_big_rational()
        );
    }

    #[test]
    fn prop_division_chain_and_powers(x in -10.0f64..10.0, y in 0.5f64..4.0) {
        let p = Program::parse("x / y / 3 - 0.1 * x^3 + (x - y)^-2", None).unwrap();
        let f = p.eval_f64(&[x, y]);
        let want = x / y / 3.0 - 0.1 * (x * x * x) + 1.0 / ((x - y) * (x - y));
        prop_assert_eq!(f[0].to_bits(), want.to_bits());
        let (qx, qy) = (exact(x), exact(y));
        let d = &qx - &qy;
        let want = qx.checked_div(&qy).unwrap().checked_div(&Rational::from_integer(3)).unwrap()
            - q(1, 10) * &qx * &qx * &qx
            + (&d * &d).recip().unwrap();
        prop_assert_eq!(exact_value(&p, &[qx, qy]), want.to_big_rational());
    }

    /// The interval operations enclose the exact results.
    #[test]
    fn prop_intervals_enclose(
        a in -1_000_000i64..1_000_000, b in 1i64..1000, c in 1i64..1_000_000, d in 1i64..1000,
        p in 8u64..200
    ) {
        let (x, y) = (q(a, b), q(c, d));
        let (ix, iy) = (Iv::from_rational(&x, p), Iv::from_rational(&y, p));
        let inside = |iv: &Iv, v: &Rational| {
            let v = v.to_big_rational();
            iv.lo.to_big_rational() <= v && v <= iv.hi.to_big_rational()
        };
        prop_assert!(inside(&ix, &x));
        prop_assert!(inside(&Iv::add(&ix, &iy, p), &(&x + &y)));
        prop_assert!(inside(&Iv::sub(&ix, &iy, p), &(&x - &y)));
        prop_assert!(inside(&Iv::mul(&ix, &iy, p), &(&x * &y)));
        prop_assert!(inside(&Iv::div(&ix, &iy, p), &x.checked_div(&y).unwrap()));
        let s = Iv::sqrt(&iy, p);
        let (lo, hi) = (s.lo.to_big_rational(), s.hi.to_big_rational());
        let yy = y.to_big_rational();
        prop_assert!(&lo * &lo <= yy && yy <= &hi * &hi);
        prop_assert!(s.lo.m.bits() <= p && s.hi.m.bits() <= p);
    }
}

proptest! {
    /// sqrt of random rationals against an independent integer square root (2^-400 accurate).
    #[test]
    fn prop_sqrt_of_rationals_meets_the_contract(a in 1u64..u64::MAX, b in 1u64..u64::MAX) {
        let x = Rational::from(BigRational::new(a.into(), b.into()));
        let r = &prog("sqrt(x)").eval_exact(std::slice::from_ref(&x)).unwrap()[0];
        // sqrt(a/b) = sqrt(a b 4^200) / (b 2^200).
        let scale = BigInt::one() << 200u32;
        let root = (BigInt::from(a) * BigInt::from(b) * &scale * &scale).sqrt();
        let den = BigInt::from(b) * &scale;
        let t = BigRational::new(root, den.clone());
        let err = BigRational::new(BigInt::one(), den);
        assert_contract(r, &t, &err);
    }

    /// An accurate formula is accurate: the double is within 2 ulps of the reference.
    #[test]
    fn prop_accurate_formula_is_close_to_its_reference(x in 0.0f64..1e300) {
        let p = prog("1/(sqrt(x + 1) + sqrt(x))");
        let f = p.eval_f64(&[x])[0];
        let r = &p.eval_exact(&[exact(x)]).unwrap()[0];
        let diff = (BigRational::from_float(f).unwrap() - &r.value).abs();
        let ulp = BigRational::from_float(f64::EPSILON).unwrap() * r.value.abs();
        prop_assert!(diff <= ulp * BigInt::from(2), "x = {}, f = {}", x, f);
        // The cancelling form is far off for large x, and the reference says so.
        if x > 1e20 {
            let d = prog("sqrt(x + 1) - sqrt(x)");
            let fd = d.eval_f64(&[x])[0];
            let rd = &d.eval_exact(&[exact(x)]).unwrap()[0];
            prop_assert!((&rd.value - &r.value).abs() < &r.value / BigInt::from(1u64 << 60));
            prop_assert_eq!(fd, 0.0);
        }
    }
}

#[test]
fn hidden_zero_under_a_root_is_exactly_zero() {
    // sqrt(2)^2 - 2 straddles zero as an enclosure; the radical test says it is 0.
    let r = &prog("sqrt(sqrt(2)*sqrt(2) - 2) + 1")
        .eval_exact(&[])
        .unwrap()[0];
    assert_eq!(
        r,
        &Reference {
            value: BigRational::one(),
            exact: true
        }
    );
    // A negative argument hidden below the first precision is outside the domain.
    assert_eq!(
        prog("sqrt(sqrt(2)*sqrt(2) - 2 - 2^-1000)").eval_exact(&[]),
        Err(ExactStop::OutsideDomain)
    );
}

#[test]
fn huge_and_tiny_summands_stay_rigorous() {
    // 2^1000 + 2^-1000 rounded at 64 bits: down gives 2^1000, up gives just above it.
    let big = Dy {
        m: BigInt::one(),
        e: 1000,
    };
    let tiny = Dy {
        m: BigInt::one(),
        e: -1000,
    };
    let down = Dy::add(&big, &tiny, 64, Dir::Down);
    let up = Dy::add(&big, &tiny, 64, Dir::Up);
    let truth = big.to_big_rational() + tiny.to_big_rational();
    assert_eq!(down.to_big_rational(), big.to_big_rational());
    assert!(up.to_big_rational() > truth);
    let ulp = Dy {
        m: BigInt::one(),
        e: 1000 - 60,
    };
    assert!(up.to_big_rational() - big.to_big_rational() <= ulp.to_big_rational());
    assert!(up.m.bits() <= 64);
    let down = Dy::add(&big, &tiny.neg(), 64, Dir::Down);
    assert!(down.to_big_rational() < big.to_big_rational() - tiny.to_big_rational());
    assert!(down.m.bits() <= 64);
}

// ------------------------------------------------------------------ float side

#[test]
fn literals_round_once_to_nearest() {
    let p = prog("0.1 + 0.2");
    assert_eq!(p.eval_f64(&[])[0], 0.1f64 + 0.2f64);
    assert_eq!(p.eval_f64(&[])[0], 0.30000000000000004);
    assert_eq!(exact_value(&p, &[]), q(3, 10).to_big_rational());
    // 1/3 is a double division, not the rounded third (which is the same here), and 1e400
    // overflows to inf as a literal.
    assert_eq!(prog("1/3").eval_f64(&[])[0], 1.0 / 3.0);
    assert_eq!(prog("1e400 - x").eval_f64(&[1.0])[0], f64::INFINITY);
    // Literals near half the smallest subnormal (2^-1075 = 2.47032822920623272088e-324)
    // round to 0 below it and to 2^-1074 above it.
    assert_eq!(prog("2.4703282292062327e-324").eval_f64(&[])[0], 0.0);
    assert_eq!(
        prog("2.4703282292062328e-324").eval_f64(&[])[0],
        f64::from_bits(1)
    );
}

#[test]
fn ieee_semantics_without_errors() {
    let p = prog("1/(x - x)");
    assert_eq!(p.eval_f64(&[3.0])[0], f64::INFINITY);
    assert!(prog("sqrt(x)").eval_f64(&[-1.0])[0].is_nan());
    assert_eq!(prog("x^-1").eval_f64(&[0.0])[0], f64::INFINITY);
    assert_eq!(prog("x^-1").eval_f64(&[-0.0])[0], f64::NEG_INFINITY);
    assert_eq!(prog("x^0").eval_f64(&[f64::NAN])[0], 1.0);
    // NaN comparisons: false except !=.
    let nan_if = |op| {
        one_output(
            Node::If(
                Box::new(Cond::Cmp(op, Node::Input(0), Node::Input(0))),
                b(c(1)),
                b(c(0)),
            ),
            &["x"],
        )
    };
    for op in [
        CmpOp::Lt,
        CmpOp::Le,
        CmpOp::Gt,
        CmpOp::Ge,
        CmpOp::Eq,
        CmpOp::Ne,
    ] {
        let want = if op == CmpOp::Ne { 1.0 } else { 0.0 };
        assert_eq!(nan_if(op).eval_f64(&[f64::NAN])[0], want, "{op:?}");
    }
    // fmin/fmax ignore a NaN operand, as C's do.
    let p = one_output(Node::Min(b(Node::Input(0)), b(c(2))), &["x"]);
    assert_eq!(p.eval_f64(&[f64::NAN])[0], 2.0);
    let p = one_output(Node::Max(b(Node::Input(0)), b(c(2))), &["x"]);
    assert_eq!(p.eval_f64(&[1.0])[0], 2.0);
}

#[test]
fn pow_styles_differ_where_multiplication_rounds_more() {
    let mul = one_output(Node::Pow(b(Node::Input(0)), 7, PowStyle::Multiply), &["x"]);
    let libm = one_output(Node::Pow(b(Node::Input(0)), 7, PowStyle::Libm), &["x"]);
    let mut found = None;
    for i in 0..1000 {
        let x = 1.0 + f64::from(i) * 0.001_234_567;
        let (a, b) = (mul.eval_f64(&[x])[0], libm.eval_f64(&[x])[0]);
        assert_eq!(a, x * x * x * x * x * x * x);
        assert_eq!(b, x.powf(7.0));
        if a != b {
            found = Some(x);
            break;
        }
    }
    let x = found.expect("six roundings differ from pow's one somewhere");
    // The exact side ignores the style: both are x^7.
    let want = Rational::powi(&exact(x), 7).unwrap().to_big_rational();
    assert_eq!(exact_value(&mul, &[exact(x)]), want);
    assert_eq!(exact_value(&libm, &[exact(x)]), want);
    // Negative exponents: one division after the multiplications.
    let p = one_output(Node::Pow(b(Node::Input(0)), -3, PowStyle::Multiply), &["x"]);
    assert_eq!(p.eval_f64(&[x])[0], 1.0 / (x * x * x));
}

#[test]
fn fma_is_fused_on_the_float_side_and_exact_on_the_other() {
    let a = 1.0 + f64::EPSILON;
    let rounded = a * a; // 1 + 2 eps, the 2^-104 term lost
    let p = one_output(
        Node::Fma(b(Node::Input(0)), b(Node::Input(0)), b(Node::Input(1))),
        &["a", "c"],
    );
    let f = p.eval_f64(&[a, -rounded])[0];
    assert_eq!(f, f64::EPSILON * f64::EPSILON);
    assert_eq!(a * a - rounded, 0.0);
    let want = exact(a) * exact(a) - exact(rounded);
    assert_eq!(
        exact_value(&p, &[exact(a), exact(-rounded)]),
        want.to_big_rational()
    );
}

#[test]
fn let_slots_and_many_slots() {
    // let s0 = x + 1, s1 = s0 * s0 in s1 - s0
    let p = Program {
        name: "let".into(),
        inputs: vars(&["x"]),
        slots: 2,
        pre: None,
        outputs: vec![
            Node::Let(
                vec![
                    (0, Node::Add(b(Node::Input(0)), b(c(1)))),
                    (1, Node::Mul(b(Node::Slot(0)), b(Node::Slot(0)))),
                ],
                b(Node::Sub(b(Node::Slot(1)), b(Node::Slot(0)))),
            ),
            Node::Abs(b(Node::Neg(b(Node::Input(0))))),
        ],
        precision: Format::Binary64,
        input_precision: Vec::new(),
    };
    let x = 0.3;
    let s0 = x + 1.0;
    assert_eq!(p.eval_f64(&[x]), vec![s0 * s0 - s0, 0.3]);
    let r = p.eval_exact(&[exact(x)]).unwrap();
    let e0 = exact(x) + Rational::ONE;
    assert_eq!(r[0].value, (&e0 * &e0 - &e0).to_big_rational());
    assert_eq!(r[1].value, exact(x).to_big_rational());
    // Beyond STACK_SLOTS the slots live on the heap: a chain s_i = s_{i-1} + 1.
    let n = STACK_SLOTS + 8;
    let mut bindings = vec![(0, Node::Input(0))];
    for i in 1..n {
        bindings.push((i, Node::Add(b(Node::Slot(i - 1)), b(c(1)))));
    }
    let p = Program {
        name: "chain".into(),
        inputs: vars(&["x"]),
        slots: n,
        pre: None,
        outputs: vec![Node::Let(bindings, b(Node::Slot(n - 1)))],
        precision: Format::Binary64,
        input_precision: Vec::new(),
    };
    assert_eq!(p.eval_f64(&[0.5]), vec![0.5 + (n - 1) as f64]);
    let mut out = Vec::new();
    p.eval_f64_into(&[1.5], &mut out);
    p.eval_f64_into(&[0.5], &mut out);
    assert_eq!(out, vec![0.5 + (n - 1) as f64]);
    assert_eq!(
        exact_value(&p, &[q(1, 2)]),
        (q(1, 2) + Rational::from_integer(n as i64 - 1)).to_big_rational()
    );
}

// ------------------------------------------------------------------ exact side with roots

#[test]
fn sqrt2_meets_the_contract() {
    let r = &prog("sqrt(2)").eval_exact(&[]).unwrap()[0];
    assert!(!r.exact);
    let (t, err) = sqrt_reference(2, 200);
    assert_contract(r, &t, &err);
    // A perfect square stays exact.
    let r = &prog("sqrt(x)").eval_exact(&[q(9, 4)]).unwrap()[0];
    assert_eq!(
        r,
        &Reference {
            value: q(3, 2).to_big_rational(),
            exact: true
        }
    );
}

#[test]
fn conjugate_product_is_one_within_the_contract() {
    let p = prog("(sqrt(x+1)-sqrt(x))*(sqrt(x+1)+sqrt(x))");
    let one = BigRational::one();
    for x in [3.0, 1e15, 0.1, 1e-300, 123_456.789, 2.0f64.powi(-1070)] {
        let r = &p.eval_exact(&[exact(x)]).unwrap()[0];
        assert_contract(r, &one, &BigRational::zero());
    }
}

#[test]
fn cancellation_is_refined_to_full_relative_accuracy() {
    // sqrt(x+1) - sqrt(x) = 1/(sqrt(x+1) + sqrt(x)); at x = 1e30 the difference cancels ~50
    // bits at p = 128, so the pass is repeated at higher precision.
    let d = prog("sqrt(x + 1) - sqrt(x)");
    let s = prog("1/(sqrt(x + 1) + sqrt(x))");
    for x in [1e15, 1e30, 1e60] {
        let a = &d.eval_exact(&[exact(x)]).unwrap()[0];
        let b = &s.eval_exact(&[exact(x)]).unwrap()[0];
        // Both are within 2^-80 relative of the same number.
        let tol = BigRational::new(BigInt::one(), BigInt::one() << (REL_BITS - 2));
        assert!(
            (&a.value - &b.value).abs() <= tol * b.value.abs(),
            "x = {x}"
        );
    }
}

#[test]
fn tiny_roots_keep_relative_accuracy() {
    // sqrt of the smallest subnormal, 2^-1074 = (2^-537)^2: exact. Of 2^-1073: irrational.
    let p = prog("sqrt(x)");
    let r = &p.eval_exact(&[exact(f64::from_bits(1))]).unwrap()[0];
    assert!(r.exact);
    assert_eq!(
        r.value,
        BigRational::new(BigInt::one(), BigInt::one() << 537u32)
    );
    let r = &p.eval_exact(&[exact(f64::from_bits(2))]).unwrap()[0];
    let (t, err) = sqrt_reference(2, 200);
    let scale = BigRational::new(BigInt::one(), BigInt::one() << 537u32);
    assert_contract(r, &(t * &scale), &(err * &scale));
}

#[test]
fn root_times_root_minus_x_is_zero() {
    let r = &prog("sqrt(x)*sqrt(x) - x").eval_exact(&[q(2, 1)]).unwrap()[0];
    // The radical zero test makes it exact.
    assert!(r.exact);
    assert!(r.value.is_zero());
}

#[test]
fn radical_zero_test_puts_a_hidden_zero_divisor_outside_the_domain() {
    assert_eq!(
        prog("1/(sqrt(2)*sqrt(2) - 2)").eval_exact(&[]),
        Err(ExactStop::OutsideDomain)
    );
    assert_eq!(
        prog("1/(sqrt(x)*sqrt(4x) - 2x)").eval_exact(&[q(5, 7)]),
        Err(ExactStop::OutsideDomain)
    );
    // The same with a non-zero divisor is fine.
    let r = &prog("1/(sqrt(2)*sqrt(3) - 2)").eval_exact(&[]).unwrap()[0];
    assert!(!r.exact);
    assert!(r.value > BigRational::from_integer(2.into()));
}

fn if_eq(lhs: Node, rhs: Node, then: Node) -> Program {
    one_output(
        Node::If(Box::new(Cond::Cmp(CmpOp::Eq, lhs, rhs)), b(then), b(c(0))),
        &[],
    )
}

fn sqrt_c(n: i64) -> Node {
    Node::Sqrt(b(c(n)))
}

#[test]
fn if_decides_root_squared_equals_two_exactly() {
    let p = if_eq(Node::Mul(b(sqrt_c(2)), b(sqrt_c(2))), c(2), c(1));
    assert_eq!(
        p.eval_exact(&[]).unwrap()[0],
        Reference {
            value: BigRational::one(),
            exact: true
        }
    );
    // The float side says false: sqrt(2)^2 = 2.0000000000000004.
    assert_eq!(p.eval_f64(&[]), vec![0.0]);
    // The radical path also refines an irrational output to the contract.
    let p = if_eq(Node::Mul(b(sqrt_c(2)), b(sqrt_c(2))), c(2), sqrt_c(3));
    let r = &p.eval_exact(&[]).unwrap()[0];
    let (t, err) = sqrt_reference(3, 200);
    assert_contract(r, &t, &err);
    // A comparison intervals can decide needs no radicals.
    let p = one_output(
        Node::If(
            Box::new(Cond::Cmp(CmpOp::Lt, sqrt_c(2), Node::Const(q(1415, 1000)))),
            b(c(1)),
            b(c(0)),
        ),
        &[],
    );
    assert_eq!(p.eval_exact(&[]).unwrap()[0].value, BigRational::one());
}

#[test]
fn outside_the_domain() {
    assert_eq!(
        prog("sqrt(x)").eval_exact(&[q(-1, 1)]),
        Err(ExactStop::OutsideDomain)
    );
    assert_eq!(
        prog("sqrt(-1)").eval_exact(&[]),
        Err(ExactStop::OutsideDomain)
    );
    assert_eq!(
        prog("1/(x - x)").eval_exact(&[q(3, 1)]),
        Err(ExactStop::OutsideDomain)
    );
    assert_eq!(
        prog("x^-1").eval_exact(&[Rational::ZERO]),
        Err(ExactStop::OutsideDomain)
    );
    // An approximate negative argument: sqrt(2) - 2 < 0 by intervals.
    assert_eq!(
        prog("sqrt(sqrt(2) - 2)").eval_exact(&[]),
        Err(ExactStop::OutsideDomain)
    );
    // A precondition that is false.
    let mut p = prog("sqrt(x)");
    p.pre = Some(Cond::Cmp(CmpOp::Ge, Node::Input(0), c(1)));
    assert_eq!(p.eval_exact(&[q(1, 2)]), Err(ExactStop::OutsideDomain));
    assert_eq!(
        p.eval_exact(&[q(4, 1)]).unwrap()[0].value,
        BigRational::from_integer(2.into())
    );
    // The float side ignores it.
    assert_eq!(p.eval_f64(&[0.25]), vec![0.5]);
}

#[test]
fn an_undecidable_equality_is_undecided_not_guessed() {
    // sqrt(sqrt(2))^2 == sqrt(2) is true, but sqrt(sqrt 2) is not multi-quadratic, so neither
    // intervals nor the radical field can decide it.
    let r4 = Node::Sqrt(b(sqrt_c(2)));
    let p = if_eq(Node::Mul(b(r4.clone()), b(r4)), sqrt_c(2), c(1));
    assert_eq!(p.eval_exact(&[]), Err(ExactStop::Undecided));
}

#[test]
fn size_limit_is_an_error_not_an_abort() {
    // (2^-1074)^1024 has more than the constant-bits limit (1,000,000 bits).
    assert_eq!(
        prog("x^1024").eval_exact(&[exact(f64::from_bits(1))]),
        Err(ExactStop::TooLarge)
    );
    assert_eq!(
        prog("(x^1024)^1024").eval_exact(&[q(3, 1)]),
        Err(ExactStop::TooLarge)
    );
    // Through intervals: sqrt(3)^... with a huge binary exponent.
    assert_eq!(
        prog("((sqrt(2) * 2^1000)^1024)^1024").eval_exact(&[]),
        Err(ExactStop::TooLarge)
    );
    assert!(prog("x^1024").eval_exact(&[q(3, 1)]).unwrap()[0].exact);
}

#[test]
fn min_max_abs_of_enclosures() {
    let m = one_output(Node::Min(b(sqrt_c(2)), b(Node::Const(q(3, 2)))), &[]);
    let r = &m.eval_exact(&[]).unwrap()[0];
    let (t, err) = sqrt_reference(2, 200);
    assert_contract(r, &t, &err);
    let m = one_output(Node::Max(b(sqrt_c(2)), b(Node::Const(q(3, 2)))), &[]);
    let r = &m.eval_exact(&[]).unwrap()[0];
    assert_eq!(r.value, q(3, 2).to_big_rational());
    let a = one_output(Node::Abs(b(Node::Sub(b(sqrt_c(2)), b(c(2))))), &[]);
    let r = &a.eval_exact(&[]).unwrap()[0];
    let two = BigRational::from_integer(2.into());
    assert_contract(r, &(&two - &t), &err);
}

#[test]
fn rational_bits_counts_both_parts_on_both_tiers() {
    assert_eq!(Rational::ZERO.bits(), 1);
    assert_eq!(q(-3, 4).bits(), 2 + 3);
    let big = Rational::from(BigRational::new(BigInt::one() << 200u32, BigInt::from(3)));
    assert!(!big.is_inline());
    assert_eq!(big.bits(), 201 + 2);
    let inline_max = Rational::from(BigRational::new(
        (BigInt::one() << 126u32) + 1u32,
        BigInt::from(7),
    ));
    assert!(inline_max.is_inline());
    assert_eq!(inline_max.bits(), 127 + 3);
}

// ------------------------------------------------------------------ tiny values, zeros, ties

#[test]
fn tiny_values_are_refined_relatively() {
    // NMSE example 3.6 at x = 1e308: 1/sqrt(x) - 1/sqrt(x + 1) is about x^-1.5 / 2 = 5e-463,
    // far below the smallest double, after a cancellation of about 1024 bits.
    let d = prog("1/sqrt(x) - 1/sqrt(x + 1)");
    let x = exact(1e308);
    let r = &d.eval_exact(std::slice::from_ref(&x)).unwrap()[0];
    assert!(!r.exact);
    // value^2 * 4 x^3 = (1 - 3/(4x) + ...)^2: within 1e-300 of 1, checked in rationals.
    let xb = x.to_big_rational();
    let ratio = &r.value * &r.value * BigRational::from_integer(4.into()) * &xb * &xb * &xb;
    let tol = BigRational::new(BigInt::one(), BigInt::from(10).pow(300));
    assert!((ratio - BigRational::one()).abs() < tol, "{}", r.value);
    // And within 2^-80 of the same number written without cancellation.
    let s = prog("1/(sqrt(x) * sqrt(x + 1) * (sqrt(x) + sqrt(x + 1)))");
    let b = &s.eval_exact(&[x]).unwrap()[0];
    let tol = BigRational::new(BigInt::one(), BigInt::one() << (REL_BITS - 2));
    assert!((&r.value - &b.value).abs() <= tol * b.value.abs());
}

#[test]
fn zeros_are_exact_or_undecided_never_tiny() {
    // A zero in the multi-quadratic field: decided exactly.
    let r = &prog("sqrt(x + 1) * sqrt(x + 1) - x - 1")
        .eval_exact(&[exact(1e15)])
        .unwrap()[0];
    assert!(r.exact && r.value.is_zero(), "{r:?}");
    // A zero behind a fourth root (not multi-quadratic): intervals never prove it zero, so the
    // sample is undecided rather than a tiny approximation.
    assert_eq!(
        prog("sqrt(sqrt(x)) * sqrt(sqrt(x)) - sqrt(x)").eval_exact(&[q(2, 1)]),
        Err(ExactStop::Undecided)
    );
}

#[test]
fn ties_through_square_roots_round_exactly() {
    // m = 1 + 2^-53 is the midpoint of 1 and its successor: sqrt(m) * sqrt(m) = m rounds to
    // even, 1, which an approximation within 2^-80 may miss.
    let m = BigRational::one() + BigRational::new(BigInt::one(), BigInt::one() << 53u32);
    let p = prog("sqrt(x) * sqrt(x)");
    let r = &p.eval_exact(&[Rational::from(m.clone())]).unwrap()[0];
    assert!(r.exact, "{r:?}");
    assert_eq!(r.value, m);
    assert_eq!(crate::to_f64::rational_to_f64(&r.value), 1.0);
    // Just above the tie (irrational): refined until the rounding is decided, upward.
    let above = &m + BigRational::new(BigInt::one(), BigInt::one() << 200u32);
    let r = &p.eval_exact(&[Rational::from(above)]).unwrap()[0];
    assert_eq!(
        crate::to_f64::rational_to_f64(&r.value),
        1.0 + f64::EPSILON,
        "{r:?}"
    );
}

proptest! {
    /// The reference of `sqrt(x) * sqrt(y)` rounds to the double nearest to the true value,
    /// checked independently: `d` is the correctly rounded double of `t = sqrt(x y)` iff
    /// `(d - u/2)^2 <= x y <= (d + u/2)^2` with the right tie rule (u the spacing around `d`).
    #[test]
    fn references_round_like_the_true_value(a in 1u64..1 << 40, b in 1u64..1 << 40) {
        let (xq, yq) = (q(a as i64, 1 << 20), q(b as i64, 1 << 10));
        let r = &prog("sqrt(x) * sqrt(y)").eval_exact(&[xq.clone(), yq.clone()]).unwrap()[0];
        let d = crate::to_f64::rational_to_f64(&r.value);
        let t2 = (xq * yq).to_big_rational();
        let dq = BigRational::from_float(d).unwrap();
        let below = BigRational::from_float(d - f64::EPSILON * d.abs()).map(|v| (&dq + v) / BigInt::from(2));
        let above = BigRational::from_float(d + f64::EPSILON * d.abs()).map(|v| (&dq + v) / BigInt::from(2));
        // Strictly between the neighbouring midpoints (a tie would be rational: then exact).
        if let Some(lo) = below {
            prop_assert!(&lo * &lo <= t2 || r.exact);
        }
        if let Some(hi) = above {
            prop_assert!(t2 <= &hi * &hi || r.exact);
        }
    }
}
