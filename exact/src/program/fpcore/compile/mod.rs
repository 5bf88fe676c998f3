//! From s-expressions to [`Benchmark`]s: the benchmark's frame (identifier, arguments,
//! properties, body) and the expression compiler, here; the domain extracted from `:pre` in
//! `pre`; the scopes (`let`, loops) in `scope` (see the parent module for the supported subset).
use super::sexpr::{check_literal_size, pow_rational, Pos, SExpr, MAX_LITERAL_EXPONENT};
use super::{Benchmark, FpCoreError, Range, Unsupported};
use crate::program::{CmpOp, Cond, Format, Func, Node, PowStyle, Program};
use crate::rational::Rational;
use num_bigint::BigInt;
use pre::{cmp_op, conjuncts, domain, inline_lets, pre_pairs, PrePair};

mod pre;
mod scope;

/// Why compiling stopped: a malformed benchmark (an error for the whole file) or a construct
/// outside the supported subset (only this benchmark).
enum Fail {
    Syntax(FpCoreError),
    Unsupported(String),
}

impl From<FpCoreError> for Fail {
    fn from(e: FpCoreError) -> Fail {
        Fail::Syntax(e)
    }
}

fn syntax(pos: Pos, message: impl Into<String>) -> Fail {
    Fail::Syntax(err(pos, message))
}

fn err(pos: Pos, message: impl Into<String>) -> FpCoreError {
    FpCoreError {
        line: pos.line,
        col: pos.col,
        message: message.into(),
    }
}

fn unsupported(op: impl Into<String>) -> Fail {
    Fail::Unsupported(op.into())
}

/// The `(:key, value)` pairs of a property list.
type Props<'a> = Vec<(&'a str, &'a SExpr)>;

/// A compiled expression: a number or a truth value.
#[derive(Clone, Debug)]
enum Value {
    Num(Node),
    Bool(Cond),
}

/// The mathematical constants of FPCore 2.0: `PI` and `E` are [`Func`] constants, the others
/// (derived constants and the non-finite ones) are unsupported.
const CONSTANTS: &[&str] = &[
    "E",
    "LOG2E",
    "LOG10E",
    "LN2",
    "LN10",
    "PI",
    "PI_2",
    "PI_4",
    "M_1_PI",
    "M_2_PI",
    "M_2_SQRTPI",
    "SQRT2",
    "SQRT1_2",
    "INFINITY",
    "NAN",
];

/// A one-line rendering of a datum (for `not supported: precision ...`).
fn render(e: &SExpr) -> String {
    match e {
        SExpr::Num(q, _) => q.to_string(),
        SExpr::Sym(s, _) => s.clone(),
        SExpr::Str(s, _) => format!("{s:?}"),
        SExpr::List(items, _) => {
            let inner: Vec<String> = items.iter().map(render).collect();
            format!("({})", inner.join(" "))
        }
    }
}

fn list_items(e: &SExpr) -> Option<&[SExpr]> {
    match e {
        SExpr::List(items, _) => Some(items),
        _ => None,
    }
}

/// Splits `props` (the elements of a `!` annotation or of a benchmark after its arguments)
/// into `(:key, value)` pairs.
fn property_pairs(props: &[SExpr]) -> Result<Props<'_>, FpCoreError> {
    let mut out = Vec::new();
    let mut it = props.iter();
    while let Some(key) = it.next() {
        let Some(name) = key.sym().filter(|k| k.starts_with(':') && k.len() > 1) else {
            // A stray datum where a property name belongs: skipped as metadata, since FPBench's
            // own suite has one (`:cite (hamming-1987) herbie-2015` in hamming-ch3.fpcore). The
            // properties that matter (`:pre`, `:precision`, ...) are all `:key value` pairs.
            continue;
        };
        let Some(value) = it.next() else {
            return Err(err(
                key.pos(),
                format!("expected a value after the property `{name}`"),
            ));
        };
        out.push((name, value));
    }
    Ok(out)
}

/// The benchmark's format: its `:precision` (binary64 when absent); a precision other than
/// binary64 and binary32 is unsupported.
fn benchmark_format(pairs: &[(&str, &SExpr)]) -> Result<Format, Fail> {
    let mut format = Format::Binary64;
    for (key, value) in pairs {
        if matches!(*key, ":precision" | ":type") {
            format = value
                .sym()
                .and_then(Format::from_name)
                .ok_or_else(|| unsupported(format!("precision {}", render(value))))?;
        }
    }
    Ok(format)
}

/// The precision a `!` annotation with properties `pairs` sets inside the precision `outer`:
/// binary64 or binary32 (`outer` when it names none), rounding to nearest-even only.
fn context_format(pairs: &[(&str, &SExpr)], outer: Format) -> Result<Format, Fail> {
    let mut format = outer;
    for (key, value) in pairs {
        match *key {
            ":precision" | ":type" => {
                format = value
                    .sym()
                    .and_then(Format::from_name)
                    .ok_or_else(|| unsupported(format!("precision {}", render(value))))?;
            }
            ":round" if value.sym() == Some("nearestEven") => {}
            ":round" => return Err(unsupported(format!("round {}", render(value)))),
            _ => {}
        }
    }
    Ok(format)
}

/// Whether `e` has a `!` annotation setting a supported precision other than `format` (the
/// program then mixes precisions, and its `cast`s round).
fn mixes_precisions(e: &SExpr, format: Format) -> bool {
    let SExpr::List(items, _) = e else {
        return false;
    };
    if items.first().and_then(SExpr::sym) == Some("!") {
        let other = items.windows(2).any(|w| {
            matches!(w[0].sym(), Some(":precision" | ":type"))
                && w[1]
                    .sym()
                    .and_then(Format::from_name)
                    .is_some_and(|f| f != format)
        });
        if other {
            return true;
        }
    }
    items.iter().any(|i| mixes_precisions(i, format))
}

/// Checks the rounding-context properties of a benchmark against its `format`: its own
/// precision and round-to-nearest-even only.
fn check_context(pairs: &[(&str, &SExpr)], format: Format) -> Result<(), Fail> {
    for (key, value) in pairs {
        let (what, wanted) = match *key {
            ":precision" | ":type" => ("precision", format.name()),
            ":round" => ("round", "nearestEven"),
            _ => continue,
        };
        match value.sym() {
            Some(v) if v == wanted => {}
            _ => return Err(unsupported(format!("{what} {}", render(value)))),
        }
    }
    Ok(())
}

/// The value of a literal: a number, `(digits m e b)`, `(- literal)` or `(! props literal)`.
/// `Ok(None)` when `e` is not a literal.
fn literal(e: &SExpr) -> Result<Option<Rational>, FpCoreError> {
    match e {
        SExpr::Num(q, _) => Ok(Some(q.clone())),
        SExpr::List(items, pos) => match items.first().and_then(SExpr::sym) {
            Some("digits") => digits(&items[1..], *pos).map(Some),
            Some("-") if items.len() == 2 => Ok(literal(&items[1])?.map(|q| -q)),
            _ => Ok(None),
        },
        _ => Ok(None),
    }
}

/// `(digits m e b)` = `m·b^e` exactly.
fn digits(args: &[SExpr], pos: Pos) -> Result<Rational, FpCoreError> {
    let ints: Vec<BigInt> = args
        .iter()
        .filter_map(|a| match a {
            SExpr::Num(q, _) if q.is_integer() => Some(q.numer()),
            _ => None,
        })
        .collect();
    if args.len() != 3 || ints.len() != 3 {
        return Err(err(
            pos,
            "expected `(digits m e b)` with three integers (significand, exponent, base)",
        ));
    }
    let exp = i64::try_from(&ints[1])
        .ok()
        .filter(|e| e.abs() <= MAX_LITERAL_EXPONENT);
    let base = u32::try_from(&ints[2]).ok().filter(|&b| b >= 2);
    match (exp, base) {
        (Some(e), Some(b)) => {
            check_literal_size("`(digits m e b)`", ints[0].bits(), None, b, e)
                .map_err(|m| err(pos, m))?;
            Ok(Rational::from(
                num_rational::BigRational::from_integer(ints[0].clone()) * pow_rational(b, e),
            ))
        }
        (None, _) => Err(err(
            pos,
            format!("the exponent of `(digits ...)` is beyond ±{MAX_LITERAL_EXPONENT}"),
        )),
        (_, None) => Err(err(
            pos,
            "the base of `(digits m e b)` must be an integer >= 2",
        )),
    }
}

/// Compiles one top-level s-expression, which must be `(FPCore ...)`.
pub(super) fn benchmark(tree: &SExpr) -> Result<Benchmark, FpCoreError> {
    let items = match tree {
        SExpr::List(items, _) if items.first().and_then(SExpr::sym) == Some("FPCore") => items,
        other => {
            return Err(err(
                other.pos(),
                format!("expected `(FPCore ...)`, found {}", other.describe()),
            ))
        }
    };
    let open = tree.pos();
    let mut k = 1;
    let ident = match items.get(k) {
        Some(SExpr::Sym(s, _)) => {
            k += 1;
            Some(s.clone())
        }
        _ => None,
    };
    let arg_list = match items.get(k) {
        Some(SExpr::List(a, _)) => a,
        Some(other) => {
            return Err(err(
                other.pos(),
                format!(
                    "expected the argument list `(x ...)`, found {}",
                    other.describe()
                ),
            ))
        }
        None => {
            return Err(err(
                open,
                "expected the argument list `(x ...)` after `FPCore`",
            ))
        }
    };
    k += 1;
    let Some((body, props)) = items[k..].split_last() else {
        return Err(err(
            open,
            "expected the benchmark's body after its arguments",
        ));
    };
    if let Some(key) = body.sym().filter(|s| s.starts_with(':')) {
        return Err(err(
            body.pos(),
            format!("expected a value after the property `{key}`, then the benchmark's body"),
        ));
    }
    let props = property_pairs(props)?;
    let format = benchmark_format(&props);

    // Arguments: names, their own precisions, plus the first unsupported annotation if any.
    let mut args: Vec<String> = Vec::new();
    let mut arg_formats: Vec<Option<Format>> = Vec::new();
    let mut arg_unsupported: Option<String> = None;
    for a in arg_list {
        let Argument { name, own, problem } =
            argument(a, *format.as_ref().unwrap_or(&Format::Binary64))?;
        if args.contains(&name) {
            return Err(err(a.pos(), format!("duplicate argument `{name}`")));
        }
        args.push(name);
        arg_formats.push(own);
        if arg_unsupported.is_none() {
            arg_unsupported = problem;
        }
    }
    let mixed_args = arg_formats.iter().any(Option::is_some);

    let mut name = None;
    let mut pre = None;
    for (key, value) in &props {
        match *key {
            ":name" => {
                name = Some(match value {
                    SExpr::Str(s, _) | SExpr::Sym(s, _) => s.clone(),
                    other => render(other),
                })
            }
            ":pre" => pre = Some(*value),
            _ => {}
        }
    }

    // A `:pre` written with `let`s of literals and names reads as the same condition written
    // directly: its interval bounds become the sampling domain either way.
    let pre = pre.map(inline_lets);
    let pre = pre.as_ref();
    let domain = match pre {
        Some(p) => domain(p, &args)?,
        None => vec![Range::UNBOUNDED; args.len()],
    };

    let display = name
        .clone()
        .or_else(|| ident.clone())
        .unwrap_or_else(|| format!("FPCore at line {}", open.line));
    let compiled = match arg_unsupported {
        Some(op) => Err(unsupported(op)),
        None => format.and_then(|format| {
            check_context(&props, format)?;
            let mut c = Compiler {
                format,
                mixed: mixed_args || mixes_precisions(body, format),
                slots: 0,
                env: args
                    .iter()
                    .enumerate()
                    .map(|(i, n)| (n.clone(), Value::Num(Node::Input(i))))
                    .collect(),
                results: None,
            };
            let pre = match pre {
                Some(p) => c.precondition(p, &args)?,
                None => None,
            };
            let outputs = c.outputs(body)?;
            Ok(Program {
                name: display,
                inputs: args.clone(),
                slots: c.slots,
                pre,
                outputs,
                precision: format,
                input_precision: if mixed_args {
                    arg_formats.clone()
                } else {
                    Vec::new()
                },
            })
        }),
    };
    let program = match compiled {
        Ok(p) => Ok(p),
        Err(Fail::Unsupported(op)) => Err(Unsupported { op }),
        Err(Fail::Syntax(e)) => return Err(e),
    };
    Ok(Benchmark {
        name,
        ident,
        line: open.line,
        args,
        program,
        domain,
    })
}

/// The precision names of FPCore 2.0 beyond binary64 and binary32: a benchmark or argument
/// that uses one is unsupported (not malformed). The parameterised ones are lists
/// (`(float es nbits)`, `(posit es nbits)`, `(fixed nbits scale)`).
const OTHER_PRECISIONS: &[&str] = &[
    "binary16",
    "binary80",
    "binary128",
    "posit8",
    "posit16",
    "posit32",
    "posit64",
    "real",
    "integer",
];

/// Whether `v` is an FPCore precision that is not binary64 or binary32.
fn other_precision(v: &SExpr) -> bool {
    match v {
        SExpr::Sym(s, _) => OTHER_PRECISIONS.contains(&s.as_str()),
        SExpr::List(items, _) => matches!(
            items.first().and_then(SExpr::sym),
            Some("float" | "posit" | "fixed")
        ),
        _ => false,
    }
}

/// One argument of a benchmark of precision `format`.
struct Argument {
    name: String,
    /// The precision of its values when it is not `format` (`(! :precision binary32 x)` in a
    /// binary64 benchmark, or the reverse).
    own: Option<Format>,
    /// What is unsupported about it (another FPCore precision, another rounding, a tensor).
    problem: Option<String>,
}

/// One argument: `x`, `(! props x)`, or a tensor `(x dims...)` / `(! props x dims...)`.
///
/// # Errors
/// No name, or a `:precision` that names no FPCore precision (one line with its position).
fn argument(a: &SExpr, format: Format) -> Result<Argument, FpCoreError> {
    match a {
        SExpr::Sym(s, _) => Ok(Argument {
            name: s.clone(),
            own: None,
            problem: None,
        }),
        SExpr::List(items, pos) => {
            let (props, rest) = if items.first().and_then(SExpr::sym) == Some("!") {
                // `(! :p v ... name dims...)`: properties come in pairs before the name.
                let mut j = 1;
                while items
                    .get(j)
                    .and_then(SExpr::sym)
                    .is_some_and(|s| s.starts_with(':'))
                {
                    j += 2;
                }
                let j = j.min(items.len());
                (property_pairs(&items[1..j])?, &items[j..])
            } else {
                (Vec::new(), &items[..])
            };
            let Some(name) = rest.first().and_then(SExpr::sym) else {
                return Err(err(*pos, "expected an argument name"));
            };
            let mut own = None;
            let mut problem = None;
            for (key, value) in &props {
                match *key {
                    ":precision" | ":type" => match value.sym().and_then(Format::from_name) {
                        Some(f) => own = (f != format).then_some(f),
                        None if other_precision(value) => {
                            problem.get_or_insert(format!("precision {}", render(value)));
                        }
                        None => {
                            return Err(err(
                                value.pos(),
                                format!(
                                    "unknown precision `{}` of the argument `{name}` (FPCore's are binary16, binary32, binary64, binary80, binary128, posit8 to posit64, real, integer, (float es nbits), (posit es nbits), (fixed nbits scale))",
                                    render(value)
                                ),
                            ))
                        }
                    },
                    ":round" if value.sym() == Some("nearestEven") => {}
                    ":round" => {
                        problem.get_or_insert(format!("round {}", render(value)));
                    }
                    _ => {}
                }
            }
            if rest.len() > 1 && problem.is_none() {
                problem = Some("tensor".to_string());
            }
            Ok(Argument {
                name: name.to_string(),
                own,
                problem,
            })
        }
        other => Err(err(
            other.pos(),
            format!("expected an argument name, found {}", other.describe()),
        )),
    }
}

/// The expression compiler: the precision in scope (the benchmark's outside every `!`
/// annotation), whether the program mixes precisions, the slot counter and the scope
/// (innermost binding last).
struct Compiler {
    format: Format,
    mixed: bool,
    slots: usize,
    env: Vec<(String, Value)>,
    /// The result slots of the marked tail arrays while a shared body is compiled
    /// ([`Compiler::shared_outputs`]).
    results: Option<Vec<usize>>,
}

impl Compiler {
    /// The part of `:pre` that is not interval bounds, as one condition.
    fn precondition(&mut self, pre: &SExpr, args: &[String]) -> Result<Option<Cond>, Fail> {
        let mut cs = Vec::new();
        conjuncts(pre, &mut cs);
        let mut rest = Vec::new();
        for c in cs {
            match pre_pairs(c, args)? {
                Some(pairs) => {
                    for pair in pairs {
                        if let PrePair::Other(op, a, b) = pair {
                            let a = self.num(a)?;
                            let b = self.num(b)?;
                            rest.push(Cond::Cmp(op, a, b));
                        }
                    }
                }
                None => match self.cond(c)? {
                    Cond::Bool(true) => {}
                    other => rest.push(other),
                },
            }
        }
        Ok(match rest.len() {
            0 => None,
            1 => rest.pop(),
            _ => Some(Cond::And(rest)),
        })
    }

    /// The outputs of the body: one, or one per element of an array it returns (`array`).
    fn outputs(&mut self, body: &SExpr) -> Result<Vec<Node>, Fail> {
        match body {
            SExpr::List(items, p) if items.first().and_then(SExpr::sym) == Some("!") => {
                let (e, pairs) = annotation(items, *p)?;
                let (outer, inner) = (self.format, context_format(&pairs, self.format)?);
                self.format = inner;
                let outs = self.outputs(e);
                self.format = outer;
                return Ok(outs?
                    .into_iter()
                    .map(|n| in_context(n, inner, outer))
                    .collect());
            }
            _ => {}
        }
        if let Some((n, marked)) = super::array::shared(body, syntax)? {
            return self.shared_outputs(n, &marked);
        }
        if let Some(outs) = super::array::elements(body, |e| self.num(e), syntax)? {
            return Ok(outs);
        }
        match self.expr(body)? {
            Value::Num(n) => Ok(vec![n]),
            Value::Bool(_) => Err(unsupported("boolean result")),
        }
    }

    /// The `n` outputs of a body with a loop whose tail arrays are marked
    /// ([`super::array::shared`]): the body is evaluated once, by the first output, each of its
    /// tail arrays binding its elements to `n` fresh result slots; output `k` reads slot `k`
    /// (the evaluators run the outputs in order on one set of slots). The loop then runs once
    /// per evaluation, and its iterations count once against `loop-iterations`.
    fn shared_outputs(&mut self, n: usize, marked: &SExpr) -> Result<Vec<Node>, Fail> {
        let first = self.slots;
        self.slots += n + 1;
        let results: Vec<usize> = (first..first + n).collect();
        let body_slot = first + n;
        let outer = self.results.replace(results.clone());
        let body = self.num(marked);
        self.results = outer;
        let mut outs = vec![Node::Let(
            vec![(body_slot, body?)],
            Box::new(Node::Slot(results[0])),
        )];
        outs.extend(results[1..].iter().map(|&s| Node::Slot(s)));
        Ok(outs)
    }

    /// A marked tail array `(RESULTS e0 e1 ...)` of [`Compiler::shared_outputs`]: its elements
    /// bound to the result slots; its own value is never read.
    fn bind_results(&mut self, elements: &[SExpr]) -> Result<Value, Fail> {
        let results = self
            .results
            .clone()
            .expect("only a shared body has marked arrays");
        let mut bindings = Vec::with_capacity(elements.len());
        for (slot, e) in results.into_iter().zip(elements) {
            bindings.push((slot, self.num(e)?));
        }
        Ok(Value::Num(Node::Let(
            bindings,
            Box::new(Node::Const(Rational::ZERO)),
        )))
    }

    fn num(&mut self, e: &SExpr) -> Result<Node, Fail> {
        match self.expr(e)? {
            Value::Num(n) => Ok(n),
            Value::Bool(_) => Err(syntax(
                e.pos(),
                format!("expected a number, found a truth value ({})", e.describe()),
            )),
        }
    }

    fn cond(&mut self, e: &SExpr) -> Result<Cond, Fail> {
        match self.expr(e)? {
            Value::Bool(c) => Ok(c),
            Value::Num(_) => Err(syntax(
                e.pos(),
                format!("expected a condition, found a number ({})", e.describe()),
            )),
        }
    }

    fn expr(&mut self, e: &SExpr) -> Result<Value, Fail> {
        match e {
            SExpr::Num(q, _) => Ok(Value::Num(Node::Const(q.clone()))),
            SExpr::Str(..) => Err(syntax(
                e.pos(),
                format!("expected an expression, found {}", e.describe()),
            )),
            SExpr::Sym(s, pos) => {
                if let Some((_, v)) = self.env.iter().rev().find(|(n, _)| n == s) {
                    return Ok(v.clone());
                }
                match s.as_str() {
                    "TRUE" => Ok(Value::Bool(Cond::Bool(true))),
                    "FALSE" => Ok(Value::Bool(Cond::Bool(false))),
                    "PI" => Ok(Value::Num(Node::Fun(Func::Pi, Vec::new()))),
                    "E" => Ok(Value::Num(Node::Fun(Func::E, Vec::new()))),
                    c if CONSTANTS.contains(&c) => Err(unsupported(c)),
                    _ => Err(syntax(*pos, format!("unbound variable `{s}`"))),
                }
            }
            SExpr::List(items, pos) => self.application(items, *pos),
        }
    }

    fn application(&mut self, items: &[SExpr], pos: Pos) -> Result<Value, Fail> {
        let Some(head) = items.first() else {
            return Err(syntax(pos, "expected an operation, found `()`"));
        };
        let Some(op) = head.sym() else {
            return Err(syntax(
                head.pos(),
                format!("expected an operation name, found {}", head.describe()),
            ));
        };
        let args = &items[1..];
        let arity = |n: usize| -> Result<(), Fail> {
            if args.len() == n {
                Ok(())
            } else {
                Err(syntax(
                    pos,
                    format!(
                        "`{op}` takes {n} argument{}, found {}",
                        if n == 1 { "" } else { "s" },
                        args.len()
                    ),
                ))
            }
        };
        let num = |n: Node| Ok(Value::Num(n));
        match op {
            "digits" => num(Node::Const(digits(args, pos)?)),
            "if" => {
                arity(3)?;
                let c = self.cond(&args[0])?;
                let t = self.expr(&args[1])?;
                let f = self.expr(&args[2])?;
                match (t, f) {
                    (Value::Num(t), Value::Num(f)) => {
                        num(Node::If(Box::new(c), Box::new(t), Box::new(f)))
                    }
                    (Value::Bool(t), Value::Bool(f)) => Ok(Value::Bool(Cond::Or(vec![
                        Cond::And(vec![c.clone(), t]),
                        Cond::And(vec![Cond::Not(Box::new(c)), f]),
                    ]))),
                    _ => Err(syntax(
                        pos,
                        "the branches of `if` must both be numbers or both be conditions",
                    )),
                }
            }
            "let" | "let*" => {
                arity(2)?;
                self.let_expr(op == "let*", &args[0], &args[1])
            }
            "while" | "while*" => self.while_expr(op == "while*", args, pos),
            "array" => Err(unsupported("array")),
            super::array::RESULTS => self.bind_results(args),
            "!" => {
                let (e, pairs) = annotation(items, pos)?;
                let (outer, inner) = (self.format, context_format(&pairs, self.format)?);
                self.format = inner;
                let v = self.expr(e);
                self.format = outer;
                Ok(match v? {
                    Value::Num(n) => Value::Num(in_context(n, inner, outer)),
                    Value::Bool(c) => Value::Bool(cond_in_context(c, inner, outer)),
                })
            }
            // Rounds to the precision in scope; in a program of one precision every value
            // already is a value of it, and the cast changes nothing.
            "cast" => {
                arity(1)?;
                let a = self.num(&args[0])?;
                num(if self.mixed {
                    Node::Cast(Box::new(a))
                } else {
                    a
                })
            }
            "+" | "*" | "/" => {
                arity(2)?;
                let (l, r) = (self.num(&args[0])?, self.num(&args[1])?);
                num(match op {
                    "+" => Node::Add(Box::new(l), Box::new(r)),
                    "*" => Node::Mul(Box::new(l), Box::new(r)),
                    _ => Node::Div(Box::new(l), Box::new(r)),
                })
            }
            "-" => match args.len() {
                1 => num(Node::Neg(Box::new(self.num(&args[0])?))),
                2 => {
                    let (l, r) = (self.num(&args[0])?, self.num(&args[1])?);
                    num(Node::Sub(Box::new(l), Box::new(r)))
                }
                n => Err(syntax(
                    pos,
                    format!("`-` takes 1 argument (negation) or 2, found {n}"),
                )),
            },
            "neg" | "sqrt" | "fabs" => {
                arity(1)?;
                let a = Box::new(self.num(&args[0])?);
                num(match op {
                    "neg" => Node::Neg(a),
                    "sqrt" => Node::Sqrt(a),
                    _ => Node::Abs(a),
                })
            }
            "fmin" | "fmax" => {
                arity(2)?;
                let (l, r) = (self.num(&args[0])?, self.num(&args[1])?);
                num(if op == "fmin" {
                    Node::Min(Box::new(l), Box::new(r))
                } else {
                    Node::Max(Box::new(l), Box::new(r))
                })
            }
            "fma" => {
                arity(3)?;
                let x = self.num(&args[0])?;
                let y = self.num(&args[1])?;
                let z = self.num(&args[2])?;
                num(Node::Fma(Box::new(x), Box::new(y), Box::new(z)))
            }
            "pow" => {
                arity(2)?;
                let base = self.num(&args[0])?;
                match literal(&args[1])? {
                    Some(q) if q.is_integer() => match i32::try_from(&q.numer()) {
                        Ok(n) => num(Node::Pow(Box::new(base), n, PowStyle::Libm)),
                        Err(_) => Err(unsupported("pow with an exponent beyond 32 bits")),
                    },
                    // Any other exponent: C's pow of two doubles, `exp(y log x)` exactly.
                    _ => {
                        let exp = self.num(&args[1])?;
                        num(Node::Fun(Func::Pow, vec![base, exp]))
                    }
                }
            }
            "<" | "<=" | ">" | ">=" | "==" | "!=" => {
                let cmp = cmp_op(op).expect("a comparison");
                if args.is_empty() {
                    return Err(syntax(pos, format!("`{op}` takes at least 1 argument")));
                }
                let nodes = args
                    .iter()
                    .map(|a| self.num(a))
                    .collect::<Result<Vec<_>, _>>()?;
                let mut pairs = Vec::new();
                if cmp == CmpOp::Ne {
                    for i in 0..nodes.len() {
                        for j in i + 1..nodes.len() {
                            pairs.push(Cond::Cmp(cmp, nodes[i].clone(), nodes[j].clone()));
                        }
                    }
                } else {
                    for w in nodes.windows(2) {
                        pairs.push(Cond::Cmp(cmp, w[0].clone(), w[1].clone()));
                    }
                }
                Ok(Value::Bool(if pairs.len() == 1 {
                    pairs.pop().expect("one pair")
                } else {
                    Cond::And(pairs)
                }))
            }
            "and" | "or" => {
                let cs = args
                    .iter()
                    .map(|a| self.cond(a))
                    .collect::<Result<Vec<_>, _>>()?;
                Ok(Value::Bool(if op == "and" {
                    Cond::And(cs)
                } else {
                    Cond::Or(cs)
                }))
            }
            "not" => {
                arity(1)?;
                Ok(Value::Bool(Cond::Not(Box::new(self.cond(&args[0])?))))
            }
            // The C library's mathematical functions (the constants are symbols, above).
            name if Func::from_name(name).is_some_and(|f| f.arity() > 0) => {
                let f = Func::from_name(name).expect("a function");
                arity(f.arity())?;
                let args = args
                    .iter()
                    .map(|a| self.num(a))
                    .collect::<Result<Vec<_>, _>>()?;
                num(Node::Fun(f, args))
            }
            // Everything else — loops, tensors, casts, predicates on special values, the
            // functions without a certified enclosure (`erf`, `tgamma`, `fmod`, ...), calls of
            // named FPCores — is outside the supported subset.
            other => Err(unsupported(other)),
        }
    }
}

/// `n` computed in the precision `inner` inside `outer`.
fn in_context(n: Node, inner: Format, outer: Format) -> Node {
    if inner == outer {
        n
    } else {
        Node::Precision(inner, Box::new(n))
    }
}

/// `c` with the operands of its comparisons computed in the precision `inner` inside `outer`.
fn cond_in_context(c: Cond, inner: Format, outer: Format) -> Cond {
    match c {
        Cond::Bool(b) => Cond::Bool(b),
        Cond::Cmp(op, a, b) => {
            Cond::Cmp(op, in_context(a, inner, outer), in_context(b, inner, outer))
        }
        Cond::And(cs) => Cond::And(
            cs.into_iter()
                .map(|c| cond_in_context(c, inner, outer))
                .collect(),
        ),
        Cond::Or(cs) => Cond::Or(
            cs.into_iter()
                .map(|c| cond_in_context(c, inner, outer))
                .collect(),
        ),
        Cond::Not(c) => Cond::Not(Box::new(cond_in_context(*c, inner, outer))),
    }
}

/// The expression of `(! props... e)` and its property pairs.
fn annotation(items: &[SExpr], pos: Pos) -> Result<(&SExpr, Props<'_>), Fail> {
    let Some((e, props)) = items[1..].split_last() else {
        return Err(syntax(pos, "expected an expression in `(! ...)`"));
    };
    Ok((e, property_pairs(props)?))
}
