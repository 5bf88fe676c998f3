//! Unit tests of the parser, the conversion, the evaluator and the printer.

use super::*;
use crate::poly::{Poly, Vars};

type P = Poly<Rational>;

fn poly(s: &str, vars: &mut Vars) -> P {
    parse_poly(s, vars).unwrap_or_else(|e| panic!("{s:?}: {e}"))
}

fn err(s: &str) -> String {
    match parse_poly::<Rational>(s, &mut Vars::new()) {
        Ok(p) => panic!("{s:?} parsed to {p:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn precedence_and_associativity() {
    let mut v = Vars::new();
    let x = poly("x", &mut v);
    assert_eq!(poly("-x^2", &mut v), -x.square());
    assert_eq!(poly("x^2^3", &mut v), x.pow(8));
    assert_eq!(poly("(x^2)^3", &mut v), x.pow(6));
    assert_eq!(poly("2^3^2", &mut v), P::from_i64(512));
    assert_eq!(poly("1 - 2 - 3", &mut v), P::from_i64(-4));
    assert_eq!(poly("12/3/2", &mut v), P::from_i64(2));
    assert_eq!(poly("3/4*x*4", &mut v), x.scale_i64(3));
    assert_eq!(poly(" 0.1 * 10 ", &mut v), P::one());
    assert_eq!(poly("x^(1+1)", &mut v), x.square());
    assert_eq!(poly("x^0", &mut v), P::one());
    assert_eq!(poly("--x", &mut v), x);
    assert_eq!(poly("+x", &mut v), x);
    assert_eq!(poly("sqrt(9/4)*2", &mut v), P::from_i64(3));
    assert_eq!(poly("x/(1+1)*2", &mut v), x);
}

#[test]
fn error_messages() {
    assert_eq!(
        err("(a + b) * (c))"),
        "unexpected ')' at 13: expected an operator or end of input"
    );
    assert_eq!(
        err("1 + )"),
        "unexpected ')' at 4: expected a number, a variable or '('"
    );
    assert_eq!(err("x/y"), "division by a non-constant expression at 2");
    assert_eq!(err("x/(1-1)"), "division by zero at 2");
    assert_eq!(
        err("sqrt(2)"),
        "sqrt(2) at 0 does not lie in the coefficient field (it is irrational: a radical \
         coefficient field is needed)"
    );
    assert_eq!(err("sqrt(x)"), "sqrt of a non-constant expression at 4");
    assert_eq!(
        err("sqrt + 1"),
        "unexpected '+' at 5: expected '(' after sqrt"
    );
    assert_eq!(
        err("x^-1"),
        "negative exponent at 2: only a non-zero constant can be raised to a negative power"
    );
    assert_eq!(
        err("x^*2"),
        "unexpected '*' at 2: expected an integer exponent (a number, a sign or '(')"
    );
    assert_eq!(err("0^-1"), "division by zero at 2");
    assert_eq!(
        err("x^(1/3)"),
        "exponent at 2 must be a non-negative integer constant (or half of one: x^(1/2) is \
         sqrt(x); a constant takes any rational exponent: 2^(1/3)), found 1/3 of the non-constant x"
    );
    assert_eq!(
        err("x^y"),
        "exponent at 2 must be a non-negative integer constant (or half of one: x^(1/2) is \
         sqrt(x); a constant takes any rational exponent: 2^(1/3)), found y"
    );
    assert_eq!(
        err("x^10001"),
        "at 2: exponent exceeds the limit exponent = 10000 (found 10001; raise it with --limit \
         exponent=N)"
    );
    assert_eq!(
        err("2^-10001"),
        "at 2: exponent exceeds the limit exponent = 10000 (found 10001; raise it with --limit \
         exponent=N)"
    );
    assert_eq!(
        err("x^100000000000000000000"),
        "at 2: exponent exceeds the limit exponent = 10000 (found an integer of 67 bits; raise \
         it with --limit exponent=N)"
    );
    assert_eq!(
        err("1 # 2"),
        "unexpected character '#' at 2: expected an operator or end of input"
    );
    assert_eq!(
        err(""),
        "unexpected end of input at 0: expected a number, a variable or '('"
    );
    assert_eq!(
        err("1."),
        "unexpected character '.' at 1: expected an operator or end of input"
    );
    assert_eq!(
        err("(1"),
        "unexpected end of input at 2: expected an operator or ')'"
    );
    let too_deep = "nesting depth exceeds the limit depth = 256 levels (found 257; raise it with \
                    --limit depth=N)";
    // A parenthesis is two levels (the group and its signed content), a sign one.
    assert_eq!(err(&"(".repeat(1000)), format!("at 128: {too_deep}"));
    assert_eq!(err(&"-".repeat(1000)), format!("at 256: {too_deep}"));
    let deep_pow = format!("x{}", "^1".repeat(1000));
    assert!(err(&deep_pow).ends_with(too_deep));
    // 256 levels are within the limit: 127 parentheses around a signed x, or 255 signs.
    let at_limit = "(".repeat(127) + "x" + &")".repeat(127);
    assert!(parse_expr(&at_limit).is_ok());
    assert!(parse_expr(&("-".repeat(255) + "x")).is_ok());
    assert_eq!(err(&("-".repeat(256) + "x")), format!("at 256: {too_deep}"));
    // Old: "exponent overflow"; the degree limit (10^8 > 100000) is predicted first.
    assert_eq!(
        err("((x^10000)^10000)^10000"),
        "at 0: polynomial degree exceeds the limit degree = 100000 (found 100000000; raise it \
         with --limit degree=N)"
    );
}

#[test]
fn scientific_notation_and_juxtaposition() {
    let mut v = Vars::new();
    // Regression: "1e3" was the product 1*e3 of a variable e3, "1e5" likewise.
    assert_eq!(poly("1e3", &mut v), P::from_i64(1000));
    assert_eq!(poly("1e5", &mut v), P::from_i64(100_000));
    assert!(v.is_empty(), "no variable e3 or e5: {v:?}");
    let x = poly("x", &mut v);
    assert_eq!(poly("x + 2.5e-3", &mut v), poly("x + 0.0025", &mut v));
    assert_eq!(
        poly("2.5e-3", &mut v),
        P::constant(Rational::new(1, 400).unwrap())
    );
    assert_eq!(poly("1E+5", &mut v), P::from_i64(100_000));
    assert_eq!(poly("5e0", &mut v), P::from_i64(5));
    assert_eq!(poly("2e3x", &mut v), x.scale_i64(2000));
    // Without digits after it, `e` is a variable: 2e = 2*e, 2e+x = 2*e + x.
    let e = poly("e", &mut v);
    assert_eq!(poly("2e", &mut v), e.scale_i64(2));
    assert_eq!(poly("2e+x", &mut v), e.scale_i64(2) + x.clone());
    assert_eq!(poly("2E-x", &mut v), poly("2*E - x", &mut v));
    assert_eq!(poly("2 sqrt(4) x", &mut v), x.scale_i64(4));
    assert_eq!(poly("(x+1)(x-1)", &mut v), x.square() - P::one());
    assert_eq!(poly("2^-2*4x", &mut v), x);
    // The digits limit counts the written digits and the decimal exponent.
    assert_eq!(
        err("1e10000"),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found 10001; raise it \
         with --limit digits=N)"
    );
    assert_eq!(
        err("1.5e-9999"),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found 10001; raise it \
         with --limit digits=N)"
    );
    assert!(parse_poly::<Rational>("1e-9999 x", &mut v).is_ok());
    assert_eq!(
        err(&"7".repeat(10_001)),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found 10001; raise it \
         with --limit digits=N)"
    );
    assert!(parse_poly::<Rational>(&"7".repeat(10_000), &mut v).is_ok());
    assert_eq!(
        err("1e99999999999999999999999"),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found more than \
         9223372036854775807; raise it with --limit digits=N)"
    );
    // A number may not be juxtaposed after a factor: `2 3` is a typo, not 6.
    assert_eq!(
        err("2 3"),
        "unexpected '3' at 2: expected an operator or end of input"
    );
    assert_eq!(
        err("x 2"),
        "unexpected '2' at 2: expected an operator or end of input"
    );
}

#[test]
fn unknown_functions_are_errors() {
    // Regression: `sin(x)` was the product sin*x of a variable sin.
    assert_eq!(
        err("exp(x)"),
        "unknown function 'exp' at 0: the functions are sqrt, abs, diff, integrate, \
         sum, binomial, factorial, sin, cos, tan (write 'exp*(...)' for a product)"
    );
    assert_eq!(
        err("2 exp(2x)"),
        "unknown function 'exp' at 2: the functions are sqrt, abs, diff, integrate, \
         sum, binomial, factorial, sin, cos, tan (write 'exp*(...)' for a product)"
    );
    assert!(err("x(y+1)").starts_with("unknown function 'x' at 0"));
    let mut v = Vars::new();
    assert_eq!(poly("x*(y+1)", &mut v), poly("x y + x", &mut v));
    // With a space, as printed, a name before `(` multiplies, unless it names a function.
    assert_eq!(poly("x (y+1)", &mut v), poly("x y + x", &mut v));
    assert_eq!(
        poly("t (1 - t) + 2 t^2 (1-t)", &mut v),
        poly("t - t^2 + 2 t^2 - 2 t^3", &mut v)
    );
    assert!(err("exp (x)").starts_with("unknown function 'exp' at 0"));
    assert!(err("2 log (x)").starts_with("unknown function 'log' at 2"));
}

#[test]
fn constant_size_limits() {
    let too_large = |found: &str| {
        format!(
            "at 0: size of a constant exceeds the limit constant-bits = 1000000 bits (found \
             {found}; raise it with --limit constant-bits=N)"
        )
    };
    // Regression: this aborted the process allocating; now refused before computing.
    assert_eq!(
        err("((2^10000)^10000)^10000"),
        too_large("at least 100000000")
    );
    assert_eq!(err("(2^10000)^10000"), too_large("at least 100000000"));
    assert_eq!(err("(3/2^10000)^10000 x"), too_large("at least 100010000"));
    assert_eq!(
        err("(2^10000 x + 1)^10000"),
        too_large("at least 100000000")
    );
    // The limit is on bits: 2^999999 fits, 2^1000001 does not.
    let mut v = Vars::new();
    assert!(parse_poly::<Rational>("(2^1000)^999 * 2^999", &mut v).is_ok());
    assert_eq!(
        err("(2^1000)^1000 * 2^1000"),
        too_large("more than 1000000")
    );
    assert_eq!(
        err("(2^1000 x)^1000 * (2^1000 y)^1000"),
        too_large("more than 1000000")
    );
    let long = "9".repeat(301_100);
    assert_eq!(
        err(&long),
        "at 0: digits of a number exceeds the limit digits = 10000 digits (found 301100; raise \
         it with --limit digits=N)"
    );
    // A product of literals within the digits limit is still checked: 31 * 33,216 bits.
    assert_eq!(
        err(&vec!["1e-9999"; 31].join(" * ")),
        too_large("more than 1000000")
    );
    // The evaluator has the same limits.
    let e = parse_expr("((2^1024)^1024)^1024").unwrap();
    assert_eq!(
        e.eval_constant::<Rational>().unwrap_err().to_string(),
        too_large("at least 1048576")
    );
    // An exponent is a constant expression too, evaluated with the limits.
    assert!(err("x^((2^10000)^10000)").starts_with("at 2: size of a constant exceeds"));
}

#[test]
fn constant_evaluation() {
    let ev = |s: &str| parse_expr(s).unwrap().eval_constant::<Rational>();
    assert_eq!(ev("3/4 - 1/4").unwrap(), Rational::new(1, 2).unwrap());
    assert_eq!(ev("(1/2)^-3 + 2^0").unwrap(), Rational::from_integer(9));
    assert_eq!(ev("2 sqrt(1e4)").unwrap(), Rational::from_integer(200));
    assert_eq!(
        ev("1 + y^2").unwrap_err().to_string(),
        "variable 'y' at 4 where a constant number is expected"
    );
    assert_eq!(
        ev("1/(2-2)").unwrap_err().to_string(),
        "division by zero at 2"
    );
    assert_eq!(
        ev("2^x").unwrap_err().to_string(),
        "exponent at 2 must be a non-negative integer constant (or half of one: x^(1/2) is \
         sqrt(x); a constant takes any rational exponent: 2^(1/3)), found x"
    );
}

#[test]
fn expression_printing_round_trips() {
    for s in [
        "-x^2",
        "(a + b)*(c - d)/3",
        "x^2^3",
        "(x^2)^3",
        "-(a - b)",
        "a - -b",
        "a*-b",
        "sqrt(4)*x + 0.25",
        "2*(x + 1)^3 - 1/2*y",
        "2^-3*x + 2.5e-3",
        "(1/2)^-(1+1)",
    ] {
        let e = parse_expr(s).unwrap();
        let printed = e.to_string();
        let mut v1 = Vars::new();
        let mut v2 = Vars::new();
        let p1: P = e.to_poly(&mut v1).unwrap();
        let p2: P = parse_poly(&printed, &mut v2).unwrap();
        assert_eq!(v1, v2, "{s} -> {printed}");
        assert_eq!(p1, p2, "{s} -> {printed}");
    }
}

#[test]
fn calls_only_in_the_call_grammar() {
    let e = parse_expr_with_calls("dot(u, cross(v, w)) + sqrt(2) x").unwrap();
    assert_eq!(e.to_string(), "dot(u, cross(v, w)) + sqrt(2)*x");
    assert!(matches!(
        &e.kind,
        ExprKind::Sum(ts) if matches!(&ts[0].1.kind, ExprKind::Call(n, a) if n == "dot" && a.len() == 2)
    ));
    // The plain grammar still refuses calls, and an unresolved call does not convert.
    assert!(matches!(
        parse_expr("dot(u, v)"),
        Err(ExprError::UnknownFunction { pos: 0, .. })
    ));
    let mut vars = Vars::new();
    assert!(matches!(
        e.to_poly::<Rational>(&mut vars),
        Err(ExprError::UnknownFunction { pos: 0, .. })
    ));
    assert!(matches!(
        parse_expr_with_calls("f(x,)"),
        Err(ExprError::Unexpected { pos: 4, .. })
    ));
    assert!(matches!(
        parse_expr_with_calls("f(x y"),
        Err(ExprError::Unexpected { .. })
    ));
    assert!(parse_expr_with_calls("f()").is_err());
}

#[test]
fn powers_of_binomials_by_the_binomial_theorem() {
    // The binomial path (k + 1 terms from exact ratios) agrees with repeated multiplication,
    // for monomials in several variables, signs, fractions and big coefficients.
    let mut v = Vars::new();
    for (base, k) in [
        ("2x - 3y/2", 37u32),
        ("x^3 y - 7", 12),
        ("x + 1", 2),
        ("-a b^2 + 2^100 c", 9),
        ("x^2 + x", 25),
    ] {
        let b: Poly<Rational> = parse_poly(base, &mut v).unwrap();
        let mut want = Poly::one();
        for _ in 0..k {
            want *= b.clone();
        }
        let got: Poly<Rational> = parse_poly(&format!("({base})^{k}"), &mut v).unwrap();
        assert_eq!(got, want, "({base})^{k}");
        assert_eq!(got.len(), k as usize + 1);
    }
    // (x+y)^5000: 5001 terms, the middle binomial exact.
    let p: Poly<Rational> = parse_poly("(x+y)^5000", &mut v).unwrap();
    assert_eq!(p.len(), 5001);
    let mid = (1..=2500u32).fold(num_bigint::BigInt::from(1u32), |acc, i| {
        acc * (5000 - 2500 + i) / i
    });
    let (x, y) = (v.get("x").unwrap(), v.get("y").unwrap());
    assert_eq!(p.coefficient(&[(x, 2500), (y, 2500)]), Rational::from(mid));
}

/// With calls, a name in an exponent followed by `(` is a call only when it is a built-in or
/// library function; otherwise it is the exponent and the parenthesis the next factor.
#[test]
fn exponents_call_only_known_functions() {
    let e = parse_expr_with_calls("t^i (1-t)").unwrap();
    let want = parse_expr_with_calls("t^i * (1-t)").unwrap();
    assert_eq!(e.to_string(), want.to_string());
    let e = parse_expr_with_calls("2^det([[2, 0], [0, 1]])").unwrap();
    assert!(e.to_string().contains("det("), "{e}");
    // outside an exponent every name before `(` is a call
    let e = parse_expr_with_calls("f(x)").unwrap();
    assert!(matches!(e.kind, ExprKind::Call(ref n, _) if n == "f"));
}

#[test]
fn degrees_are_a_postfix_times_pi_over_180() {
    use crate::Radical;
    let v = |s: &str| parse_expr(s).unwrap().eval_constant::<Radical>().unwrap();
    assert_eq!(v("cos(45°)"), v("cos(pi/4)"));
    assert_eq!(v("sin(30°)"), v("1/2"));
    assert_eq!(v("cos(90°/2)"), v("sqrt(2)/2"));
    assert_eq!(v("tan((10 + 5)°)"), v("2 - sqrt(3)"));
    // As a factor: 2*30° is 60°; a ° binds before a power.
    assert_eq!(v("cos(2*30°)"), v("1/2"));
    assert!(parse_expr("°").is_err());
    assert!(parse_expr("45°°").is_err());
}

/// A square root of a non-constant formula is one variable per expanded radicand, and the table
/// keeps the radicand's formula as written (an opaque payload of the polynomials' table).
#[test]
fn square_root_variables_keep_their_formula() {
    let mut vars = Vars::new();
    assert!(parse_expr("sqrt(x^2 + 1)")
        .unwrap()
        .to_poly::<Rational>(&mut vars)
        .is_err());
    vars.allow_roots();
    let p: Poly<Rational> = parse_expr("sqrt(x^2 + 1) - sqrt(1 + x*x)")
        .unwrap()
        .to_poly(&mut vars)
        .unwrap();
    assert!(p.is_zero());
    let roots = vars.roots();
    assert_eq!(roots.len(), 1);
    assert_eq!(roots[0].radicand_expr().to_string(), "x^2 + 1");
    // The position of the argument (its opening parenthesis) in the source, for messages.
    assert_eq!(roots[0].radicand_expr().pos, 4);
    assert_eq!(vars.name(roots[0].var), Some("sqrt(x^2 + 1)"));
    let copy = vars.clone();
    assert_eq!(copy, vars);
    let mut other = Vars::new();
    other.allow_roots();
    let _: Poly<Rational> = parse_expr("sqrt(x^2 + 2)")
        .unwrap()
        .to_poly(&mut other)
        .unwrap();
    assert_ne!(other, vars);
}

#[test]
fn half_integer_exponents_are_powers_of_the_square_root() {
    for (text, as_root) in [
        ("x^(1/2)", "sqrt(x)"),
        ("(1 + t^2)^(3/2)", "sqrt(1 + t^2)^3"),
        ("x^0.5", "sqrt(x)"),
        ("x^(-1/2)", "sqrt(x)^-1"),
        ("2^(5/2)", "sqrt(2)^5"),
    ] {
        let parsed = parse_expr(text).unwrap();
        let expected = parse_expr(as_root).unwrap();
        assert_eq!(parsed.to_string(), expected.to_string(), "{text}");
    }
    // Constants take their exact values: 8^(-3/2) = 1/(16 sqrt(2)) = sqrt(2)/32.
    let r: crate::Radical = parse_expr("8^(-3/2)").unwrap().eval_constant().unwrap();
    let expected: crate::Radical = parse_expr("sqrt(2)/32").unwrap().eval_constant().unwrap();
    assert_eq!(r, expected);
    // Integer exponents, and exponents that are not constants, stay powers.
    assert_eq!(parse_expr("x^(4/2)").unwrap().to_string(), "x^(4/2)");
    assert!(parse_expr("x^y").unwrap().to_string().contains('^'));
}

#[test]
fn typeset_notation_reads_as_the_ascii_it_stands_for() {
    for (typeset, ascii) in [
        ("x²", "x^2"),
        ("(1 + t²)⁻¹", "(1 + t^2)^-1"),
        ("x¹⁰", "x^10"),
        // Dot and cross are kept as written: the products of vectors, of scalars `*`.
        ("a·b − c", "a · b - c"),
        ("a ⋅ b × c ∗ d", "a · b × c*d"),
        ("a ÷ b ∕ c", "a/b/c"),
        ("2πr", "2*pi*r"),
        ("π/4", "pi/4"),
        ("√2", "sqrt(2)"),
        ("√2 x", "sqrt(2)*x"),
        ("√(x² + y²)", "sqrt(x^2 + y^2)"),
        ("√(x + 1)²", "sqrt(x + 1)^2"),
        ("3√x", "3*sqrt(x)"),
        ("60°", "60*pi/180"),
    ] {
        let parsed = parse_expr(typeset).unwrap_or_else(|e| panic!("{typeset}: {e}"));
        let expected = parse_expr(ascii).unwrap();
        assert_eq!(parsed.to_string(), expected.to_string(), "{typeset}");
    }
    // `√x²` means `√(x²)` or `(√x)²` depending on the typesetting: refused, naming both.
    for ambiguous in ["√x²", "√x^2", "√2³"] {
        let e = parse_expr(ambiguous).unwrap_err().to_string();
        assert!(e.contains("√(x²) or (√x)²"), "{ambiguous}: {e}");
    }
    for bad in ["x⁻", "x²⁻¹", "√", "x ⁺"] {
        assert!(parse_expr(bad).is_err(), "{bad}");
    }
}

/// `text` with calls, printed.
fn printed(text: &str) -> String {
    parse_expr_with_calls(text)
        .unwrap_or_else(|e| panic!("{text:?}: {e}"))
        .to_string()
}

fn call_err(text: &str) -> String {
    match parse_expr_with_calls(text) {
        Ok(e) => panic!("{text:?} parsed to {e}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bars_are_the_absolute_value() {
    assert_eq!(printed("|x|^2"), "abs(x)^2");
    assert_eq!(printed("|a|*|b|"), "abs(a)*abs(b)");
    assert_eq!(printed("||x| - 1|"), "abs(abs(x) - 1)");
    assert_eq!(printed("2|x| + |x - y|/2"), "2*abs(x) + abs(x - y)/2");
    assert_eq!(printed("|a b|"), "abs(a*b)");
    assert_eq!(printed("|a| - b|c|"), "abs(a) - b*abs(c)");
    assert_eq!(printed("|x|(1 + |y|)"), "abs(x)*(1 + abs(y))");
    assert_eq!(printed("f(|x|, |y|)"), "f(abs(x), abs(y))");
    assert_eq!(printed("(|x|)"), "abs(x)");
    // A bar inside parentheses does not close one opened outside them.
    assert!(parse_expr_with_calls("|x (y|)").is_err());
    assert!(call_err("|x").contains("'|' at 0"));
    assert!(parse_expr_with_calls("x|").is_err());
    // Ambiguous: |a|*b*|c| or |a*|b|*c|; the position of the closing bar.
    let e = call_err("|a|b|c|");
    assert!(e.contains("'|' at 2") && e.contains("ambiguous"), "{e}");
    assert!(call_err("|a||b|").contains("ambiguous"));
    assert!(!call_err("|a|b|c|").contains('\n'));
}

#[test]
fn factorial_is_postfix() {
    let mut v = Vars::new();
    assert_eq!(poly("5!", &mut v), P::from_i64(120));
    assert_eq!(poly("0!", &mut v), P::one());
    assert_eq!(poly("3!^2", &mut v), P::from_i64(36));
    assert_eq!(poly("-3!", &mut v), P::from_i64(-6));
    assert_eq!(poly("(2+1)! x", &mut v), poly("6x", &mut v));
    assert_eq!(poly("10!/(3!*7!)", &mut v), P::from_i64(120));
    assert_eq!(poly("(3!)!", &mut v), P::from_i64(720));
    assert_eq!(
        printed("n!/(k!(n - k)!)"),
        "factorial(n)/(factorial(k)*factorial(n - k))"
    );
    assert_eq!(printed("|n|!"), "factorial(abs(n))");
    assert!(err("3!!").contains("double factorial"));
    assert!(err("2^3!").contains("exponent"));
    assert!(err("(-1)!").contains("negative"));
    // A symbolic argument is not a polynomial: refused, naming factorial.
    let e = err("n!/(n-1)!");
    assert!(e.contains("factorial"), "{e}");
}
