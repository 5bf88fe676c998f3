//! Definitions and functions of a claims file, resolved by rewriting expression trees.
//!
//! A formula of a claims file is parsed with [`parse_expr_with_calls`]; then every defined name
//! is replaced by its value and every call by what the function computes, so the tree handed to
//! the proof engine ([`Expr::to_poly`], the random test, exact evaluation) contains only numbers,
//! variables, `+ - * / ^` and `sqrt`. A value is a scalar (one tree) or a vector (one tree per
//! coordinate); vectors add, subtract, negate and scale by scalars, everything else about them
//! goes through the functions:
//!
//! | function | value |
//! | --- | --- |
//! | `vec(a, b, ...)` | the vector with these coordinates |
//! | `dot(u, v)` | `sum u_i v_i` (same length) |
//! | `cross(u, v)` | the cross product of two 3-vectors |
//! | `norm2(v)` | `dot(v, v)` |
//! | `x(v)`, `y(v)`, `z(v)`, `at(v, i)` | a coordinate (`at` counts from 1) |
//! | `bernstein(i, n, t)` | `C(n, i) t^i (1 - t)^(n - i)` (integer constants `0 <= i <= n`) |
//! | `bezier(t, p0, ..., pn)` | `sum_i bernstein(i, n, t) p_i`, scalars or vectors |
//! | `subs(e, v, w)` | `e` with the variable `v` replaced by `w` (e.g. a coefficient: `subs(F, u, 0)`) |
//!
//! Definitions may refer to one another in any order; each is resolved once (memoized) and a
//! cycle is an error naming it (`A -> B -> A`). A substituted value takes the position of the
//! name it replaces, so a later error (division by a non-constant, ...) points into the text the
//! user typed. The size of a resolved tree is bounded ([`MAX_NODES`]): definitions that double
//! at each level cannot expand without limit. Its nesting (parentheses, signs and calls of its
//! printed form) is bounded by the `depth` limit, as a typed formula's is, and so is the number of definitions resolved inside one another: a long chain or cycle of definitions
//! is an error naming the limit or the cycle, not a stack overflow.
//!
//! Hand-written: the rewriting is a small recursion over the expression grammar of
//! `exactcheck_exact::expr`; no crate knows that grammar.

use exactcheck_core::limits;
use exactcheck_exact::expr::{parse_expr_with_calls, AddOp, Expr, ExprKind, MulOp};
use exactcheck_exact::Rational;
use std::collections::{HashMap, HashSet};

/// The largest number of nodes of a resolved expression.
pub const MAX_NODES: usize = 500_000;

/// The functions: name, number of arguments, and whether more may follow (then it is the least).
const FUNCTIONS: [(&str, usize, bool); 10] = [
    ("vec", 1, true),
    ("dot", 2, false),
    ("cross", 2, false),
    ("norm2", 1, false),
    ("x", 1, false),
    ("y", 1, false),
    ("z", 1, false),
    ("at", 2, false),
    ("bernstein", 3, false),
    ("bezier", 2, true),
];

/// A resolved value: a scalar or a vector of scalars.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// One expression.
    Scalar(Expr),
    /// One expression per coordinate.
    Vector(Vec<Expr>),
}

impl Val {
    /// The components (one for a scalar).
    pub fn components(&self) -> Vec<Expr> {
        match self {
            Val::Scalar(e) => vec![e.clone()],
            Val::Vector(v) => v.clone(),
        }
    }

    /// `scalar` or `vector of n`.
    pub fn shape(&self) -> String {
        match self {
            Val::Scalar(_) => "a scalar".into(),
            Val::Vector(v) => format!("a vector of {}", v.len()),
        }
    }
}

/// The definitions of a file: names with their text, resolved on demand.
pub struct Defs {
    /// `(name, text(s))` in file order; a vector has one text per coordinate.
    entries: Vec<(String, DefText)>,
    /// The position in `entries` of each name.
    index: HashMap<String, usize>,
    resolved: HashMap<String, Val>,
}

/// The text of a definition.
#[derive(Clone, Debug)]
pub enum DefText {
    /// A scalar formula.
    Scalar(String),
    /// A vector: one formula per coordinate.
    Vector(Vec<String>),
}

/// An error of resolution: the definition it arose in (if not the formula itself) and the
/// message (which carries the position in that text).
#[derive(Debug)]
pub struct ResolveError {
    /// The definition whose text is at fault, `None` for the formula being resolved.
    pub def: Option<String>,
    /// What is wrong.
    pub message: String,
}

type R<T> = Result<T, ResolveError>;

fn err<T>(message: String) -> R<T> {
    Err(ResolveError { def: None, message })
}

impl Defs {
    /// Definitions from `(name, text)` pairs in file order.
    ///
    /// # Errors
    /// A name that is not a variable name or shadows a function.
    pub fn new(entries: Vec<(String, DefText)>) -> Result<Defs, (String, String)> {
        for (name, _) in &entries {
            let ok = name
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && name != "sqrt";
            if !ok {
                return Err((
                    name.clone(),
                    format!("{name:?} is not a name (letters, digits, '_'; not 'sqrt')"),
                ));
            }
        }
        let index = entries
            .iter()
            .enumerate()
            .map(|(i, (n, _))| (n.clone(), i))
            .collect();
        Ok(Defs {
            entries,
            index,
            resolved: HashMap::new(),
        })
    }

    /// The names in file order.
    pub fn names(&self) -> Vec<String> {
        self.entries.iter().map(|(n, _)| n.clone()).collect()
    }

    /// Resolves every definition (so an error in one is reported at that definition).
    ///
    /// # Errors
    /// The first definition that does not resolve.
    pub fn resolve_all(&mut self) -> R<()> {
        for name in self.names() {
            self.definition(&name, &mut Vec::new())?;
        }
        Ok(())
    }

    /// Parses and resolves a formula of the file.
    ///
    /// # Errors
    /// A syntax error, an unknown function, a wrong arity, a vector where a scalar is needed, a
    /// cycle or an expansion beyond [`MAX_NODES`].
    pub fn resolve_text(&mut self, text: &str) -> R<Val> {
        let e = parse_expr_with_calls(text).map_err(|e| ResolveError {
            def: None,
            message: e.to_string(),
        })?;
        self.resolve(&e, &mut Vec::new())
    }

    /// [`Defs::resolve_text`] for a formula that must be a scalar.
    ///
    /// # Errors
    /// As [`Defs::resolve_text`]; a vector value.
    pub fn resolve_scalar(&mut self, text: &str) -> R<Expr> {
        match self.resolve_text(text)? {
            Val::Scalar(e) => Ok(e),
            v => err(format!("{} where a scalar is expected", v.shape())),
        }
    }

    fn definition(&mut self, name: &str, stack: &mut Vec<String>) -> R<Val> {
        if let Some(v) = self.resolved.get(name) {
            return Ok(v.clone());
        }
        if let Some(i) = stack.iter().position(|n| n == name) {
            let mut cycle = stack[i..].to_vec();
            cycle.push(name.to_string());
            return Err(ResolveError {
                def: Some(stack[i].clone()),
                message: format!(
                    "the definitions refer to themselves: {}",
                    cycle.join(" -> ")
                ),
            });
        }
        if stack.len() >= limits::DEPTH.get_usize() {
            return Err(self.too_deep(stack));
        }
        let text = self
            .text(name)
            .expect("definition() is called for defined names only")
            .clone();
        stack.push(name.to_string());
        let in_def = |e: ResolveError| ResolveError {
            def: Some(e.def.unwrap_or_else(|| name.to_string())),
            message: e.message,
        };
        let parse = |t: &str| {
            parse_expr_with_calls(t).map_err(|e| ResolveError {
                def: Some(name.to_string()),
                message: e.to_string(),
            })
        };
        let value = match &text {
            DefText::Scalar(t) => self.resolve(&parse(t)?, stack).map_err(in_def)?,
            DefText::Vector(ts) => {
                let mut out = Vec::new();
                for (k, t) in ts.iter().enumerate() {
                    match self.resolve(&parse(t)?, stack).map_err(in_def)? {
                        Val::Scalar(e) => out.push(e),
                        v => {
                            return Err(ResolveError {
                                def: Some(name.to_string()),
                                message: format!(
                                    "coordinate {} is {} where a scalar is expected",
                                    k + 1,
                                    v.shape()
                                ),
                            })
                        }
                    }
                }
                if out.is_empty() {
                    return Err(ResolveError {
                        def: Some(name.to_string()),
                        message: "a vector needs at least one coordinate".into(),
                    });
                }
                Val::Vector(out)
            }
        };
        stack.pop();
        self.resolved.insert(name.to_string(), value.clone());
        Ok(value)
    }

    /// Whether `name` is defined.
    pub fn is_defined(&self, name: &str) -> bool {
        self.index.contains_key(name)
    }

    /// The text of the definition `name`.
    fn text(&self, name: &str) -> Option<&DefText> {
        self.index.get(name).map(|&i| &self.entries[i].1)
    }

    /// The definitions `name`'s text refers to (none when it does not parse: resolving it
    /// reports that).
    fn references(&self, name: &str) -> Vec<String> {
        let texts = match self.text(name) {
            Some(DefText::Scalar(t)) => std::slice::from_ref(t),
            Some(DefText::Vector(ts)) => ts.as_slice(),
            None => &[],
        };
        let mut vars = Vec::new();
        for t in texts {
            if let Ok(e) = parse_expr_with_calls(t) {
                e.collect_variables(&mut vars);
            }
        }
        vars.retain(|v| self.is_defined(v));
        vars
    }

    /// The error for definitions resolved inside one another deeper than the `depth` limit
    /// (`stack` holds them, outermost first): the cycle they lead into when there is one,
    /// otherwise the limit.
    fn too_deep(&self, stack: &[String]) -> ResolveError {
        let outer = stack[0].clone();
        let message = match self.find_cycle(&outer) {
            Some(cycle) => {
                let n = cycle.len();
                let shown = if n <= 12 {
                    cycle.join(" -> ")
                } else {
                    format!(
                        "{} -> ... -> {}",
                        cycle[..6].join(" -> "),
                        cycle[n - 3..].join(" -> ")
                    )
                };
                format!(
                    "the definitions refer to themselves: {shown} -> {} (a cycle of {n} definitions)",
                    cycle[0]
                )
            }
            None => format!(
                "definitions used inside one another ({outer} -> ...): {}",
                limits::DEPTH.exceeded(format!("more than {}", stack.len()))
            ),
        };
        ResolveError {
            def: Some(outer),
            message,
        }
    }

    /// A cycle of definitions reachable from `start`, in order: a depth-first walk with its own
    /// stack, so that a long chain cannot overflow the thread's.
    fn find_cycle(&self, start: &str) -> Option<Vec<String>> {
        let mut done: HashSet<String> = HashSet::new();
        let mut on_path: HashMap<String, usize> = HashMap::new();
        // (name, its references, the next one to follow)
        let mut path: Vec<(String, Vec<String>, usize)> = Vec::new();
        on_path.insert(start.to_string(), 0);
        path.push((start.to_string(), self.references(start), 0));
        while let Some((_, refs, next)) = path.last_mut() {
            let Some(r) = refs.get(*next).cloned() else {
                let (name, _, _) = path.pop().expect("the path is not empty");
                on_path.remove(&name);
                done.insert(name);
                continue;
            };
            *next += 1;
            if let Some(&i) = on_path.get(&r) {
                return Some(path[i..].iter().map(|(n, _, _)| n.clone()).collect());
            }
            if !done.contains(&r) {
                on_path.insert(r.clone(), path.len());
                let refs = self.references(&r);
                path.push((r, refs, 0));
            }
        }
        None
    }

    /// Resolves a parsed expression.
    fn resolve(&mut self, e: &Expr, stack: &mut Vec<String>) -> R<Val> {
        let v = self.resolve_inner(e, stack)?;
        let components = match &v {
            Val::Scalar(x) => std::slice::from_ref(x),
            Val::Vector(xs) => xs.as_slice(),
        };
        let n: usize = components.iter().map(count_nodes).sum();
        if n > MAX_NODES {
            return err(format!(
                "the expression at {} expands to more than {MAX_NODES} nodes (MAX_NODES) after substituting the definitions",
                e.pos
            ));
        }
        let depth = components.iter().map(Expr::nesting).max().unwrap_or(0);
        if let Err(error) = limits::DEPTH.check_usize(depth) {
            return err(format!(
                "the expression at {} after substituting the definitions: {error}",
                e.pos
            ));
        }
        Ok(v)
    }

    fn scalar(&mut self, e: &Expr, stack: &mut Vec<String>, what: &str) -> R<Expr> {
        match self.resolve(e, stack)? {
            Val::Scalar(x) => Ok(x),
            v => err(format!(
                "{} at {} where a scalar is expected ({what})",
                v.shape(),
                e.pos
            )),
        }
    }

    fn resolve_inner(&mut self, e: &Expr, stack: &mut Vec<String>) -> R<Val> {
        let pos = e.pos;
        let node = |kind: ExprKind| Expr { kind, pos };
        Ok(match &e.kind {
            ExprKind::Number(_) => Val::Scalar(e.clone()),
            ExprKind::Var(name) => {
                if self.is_defined(name) {
                    match self.definition(name, stack)? {
                        Val::Scalar(x) => Val::Scalar(at_pos(&x, pos)),
                        Val::Vector(xs) => Val::Vector(xs.iter().map(|x| at_pos(x, pos)).collect()),
                    }
                } else {
                    Val::Scalar(e.clone())
                }
            }
            ExprKind::Neg(x) => match self.resolve(x, stack)? {
                Val::Scalar(x) => Val::Scalar(node(ExprKind::Neg(Box::new(x)))),
                Val::Vector(xs) => Val::Vector(
                    xs.into_iter()
                        .map(|x| node(ExprKind::Neg(Box::new(x))))
                        .collect(),
                ),
            },
            ExprKind::Sqrt(x) => {
                let x = self.scalar(x, stack, "the argument of sqrt")?;
                Val::Scalar(node(ExprKind::Sqrt(Box::new(x))))
            }
            ExprKind::Pow(b, k) => {
                let b = self.scalar(b, stack, "a power's base; for |v|^2 write norm2(v)")?;
                let k = self.scalar(k, stack, "an exponent")?;
                Val::Scalar(node(ExprKind::Pow(Box::new(b), Box::new(k))))
            }
            ExprKind::Sum(terms) => {
                let mut vals = Vec::new();
                for (op, t) in terms {
                    vals.push((*op, self.resolve(t, stack)?, t.pos));
                }
                let dim = vals.iter().find_map(|(_, v, _)| match v {
                    Val::Vector(xs) => Some(xs.len()),
                    Val::Scalar(_) => None,
                });
                match dim {
                    None => Val::Scalar(node(ExprKind::Sum(
                        vals.into_iter()
                            .map(|(op, v, _)| (op, v.components().remove(0)))
                            .collect(),
                    ))),
                    Some(n) => {
                        for (_, v, p) in &vals {
                            match v {
                                Val::Vector(xs) if xs.len() == n => {}
                                v => {
                                    return err(format!(
                                        "{} at {p} added to a vector of {n}",
                                        v.shape()
                                    ))
                                }
                            }
                        }
                        Val::Vector(
                            (0..n)
                                .map(|i| {
                                    node(ExprKind::Sum(
                                        vals.iter()
                                            .map(|(op, v, _)| (*op, v.components().remove(i)))
                                            .collect(),
                                    ))
                                })
                                .collect(),
                        )
                    }
                }
            }
            ExprKind::Product(factors) => {
                let mut scalars = Vec::new();
                let mut vector: Option<Vec<Expr>> = None;
                for (op, f) in factors {
                    match self.resolve(f, stack)? {
                        Val::Scalar(x) => scalars.push((*op, x)),
                        Val::Vector(xs) => {
                            if vector.is_some() {
                                return err(format!(
                                    "a product of two vectors at {}: write dot(u, v) or cross(u, v)",
                                    f.pos
                                ));
                            }
                            if *op == MulOp::Divide {
                                return err(format!("division by a vector at {}", f.pos));
                            }
                            vector = Some(xs);
                        }
                    }
                }
                let with = |x: Option<Expr>| {
                    let mut fs = scalars.clone();
                    if let Some(x) = x {
                        fs.insert(0, (MulOp::Times, x));
                    }
                    node(ExprKind::Product(fs))
                };
                match vector {
                    None => Val::Scalar(with(None)),
                    Some(xs) => Val::Vector(xs.into_iter().map(|x| with(Some(x))).collect()),
                }
            }
            ExprKind::Call(name, args) => self.call(name, args, pos, stack)?,
        })
    }

    fn call(&mut self, name: &str, args: &[Expr], pos: usize, stack: &mut Vec<String>) -> R<Val> {
        if name == "subs" {
            if args.len() != 3 {
                return err(format!(
                    "subs at {pos} takes 3 arguments (expression, variable, value), not {}",
                    args.len()
                ));
            }
            let ExprKind::Var(v) = &args[1].kind else {
                return err(format!(
                    "the second argument of subs at {} must be a variable name",
                    args[1].pos
                ));
            };
            if self.is_defined(v) {
                return err(format!(
                    "subs at {pos}: {v} is a defined name, not a variable"
                ));
            }
            let value = self.scalar(&args[2], stack, "the value of subs")?;
            return Ok(match self.resolve(&args[0], stack)? {
                Val::Scalar(e) => Val::Scalar(substitute(&e, v, &value)),
                Val::Vector(xs) => {
                    Val::Vector(xs.iter().map(|e| substitute(e, v, &value)).collect())
                }
            });
        }
        if exactcheck_exact::expr::FUNCTIONS.contains(&name) {
            // A function of the expression language (`diff`): its arguments resolved, the call
            // kept for the conversion, which checks them.
            let mut resolved = Vec::new();
            for a in args {
                resolved.push(self.scalar(a, stack, &format!("an argument of {name}"))?);
            }
            return Ok(Val::Scalar(Expr {
                kind: ExprKind::Call(name.to_string(), resolved),
                pos,
            }));
        }
        let Some(&(_, arity, variadic)) = FUNCTIONS.iter().find(|(n, _, _)| *n == name) else {
            let mut names: Vec<&str> = FUNCTIONS.iter().map(|(n, _, _)| *n).collect();
            names.extend(["subs", "sqrt"]);
            names.extend(exactcheck_exact::expr::FUNCTIONS);
            return err(format!(
                "unknown function '{name}' at {pos} (functions: {}; write '{name}*(...)' for a product)",
                names.join(", ")
            ));
        };
        if (variadic && args.len() < arity) || (!variadic && args.len() != arity) {
            return err(format!(
                "{name} at {pos} takes {}{arity} argument{}, not {}",
                if variadic { "at least " } else { "" },
                if arity == 1 { "" } else { "s" },
                args.len()
            ));
        }
        if name == "bezier" {
            limits::BERNSTEIN_DEGREE
                .check_usize(args.len() - 2)
                .map_err(|e| ResolveError {
                    def: None,
                    message: format!("bezier at {pos}: {e}"),
                })?;
        }
        let mut vals = Vec::new();
        for a in args {
            vals.push((self.resolve(a, stack)?, a.pos));
        }
        let node = |kind: ExprKind| Expr { kind, pos };
        let vector = |v: &(Val, usize), what: &str| -> R<Vec<Expr>> {
            match &v.0 {
                Val::Vector(xs) => Ok(xs.clone()),
                Val::Scalar(_) => err(format!(
                    "a scalar at {} where a vector is expected ({what} of {name})",
                    v.1
                )),
            }
        };
        let scalar = |v: &(Val, usize), what: &str| -> R<Expr> {
            match &v.0 {
                Val::Scalar(x) => Ok(x.clone()),
                Val::Vector(xs) => err(format!(
                    "a vector of {} at {} where a scalar is expected ({what} of {name})",
                    xs.len(),
                    v.1
                )),
            }
        };
        let int = |v: &(Val, usize), what: &str| -> R<u32> {
            let x = scalar(v, what)?;
            let q = x
                .eval_constant::<Rational>()
                .ok()
                .filter(|q| q.is_integer());
            match q.and_then(|q| q.to_string().parse::<u32>().ok()) {
                Some(k) => Ok(k),
                _ => err(format!(
                    "{what} of {name} at {} must be a non-negative integer constant",
                    v.1
                )),
            }
        };
        let times = |a: Expr, b: Expr| {
            node(ExprKind::Product(vec![
                (MulOp::Times, a),
                (MulOp::Times, b),
            ]))
        };
        let plus = |xs: Vec<Expr>| {
            node(ExprKind::Sum(
                xs.into_iter().map(|x| (AddOp::Plus, x)).collect(),
            ))
        };
        let dot = |u: Vec<Expr>, v: Vec<Expr>, p: usize| -> R<Expr> {
            if u.len() != v.len() {
                return err(format!(
                    "{name} at {p}: vectors of {} and {} coordinates",
                    u.len(),
                    v.len()
                ));
            }
            Ok(plus(
                u.into_iter().zip(v).map(|(a, b)| times(a, b)).collect(),
            ))
        };
        let coordinate = |v: &(Val, usize), i: usize| -> R<Val> {
            let xs = vector(v, "the argument")?;
            match xs.get(i) {
                Some(x) => Ok(Val::Scalar(x.clone())),
                None => err(format!(
                    "{name} at {pos}: coordinate {} of a vector of {}",
                    i + 1,
                    xs.len()
                )),
            }
        };
        Ok(match name {
            "vec" => Val::Vector(
                vals.iter()
                    .map(|v| scalar(v, "a coordinate"))
                    .collect::<R<_>>()?,
            ),
            "dot" => Val::Scalar(dot(
                vector(&vals[0], "the first argument")?,
                vector(&vals[1], "the second argument")?,
                pos,
            )?),
            "norm2" => {
                let v = vector(&vals[0], "the argument")?;
                Val::Scalar(dot(v.clone(), v, pos)?)
            }
            "cross" => {
                let u = vector(&vals[0], "the first argument")?;
                let v = vector(&vals[1], "the second argument")?;
                if u.len() != 3 || v.len() != 3 {
                    return err(format!(
                        "cross at {pos} takes two 3-vectors, not vectors of {} and {}",
                        u.len(),
                        v.len()
                    ));
                }
                let minus = |a: Expr, b: Expr| {
                    node(ExprKind::Sum(vec![(AddOp::Plus, a), (AddOp::Minus, b)]))
                };
                let c = |i: usize, j: usize| {
                    minus(
                        times(u[i].clone(), v[j].clone()),
                        times(u[j].clone(), v[i].clone()),
                    )
                };
                Val::Vector(vec![c(1, 2), c(2, 0), c(0, 1)])
            }
            "x" => coordinate(&vals[0], 0)?,
            "y" => coordinate(&vals[0], 1)?,
            "z" => coordinate(&vals[0], 2)?,
            "at" => {
                let i = int(&vals[1], "the index")?;
                if i == 0 {
                    return err(format!(
                        "at at {pos}: coordinates count from 1 (at(v, 1) is the first)"
                    ));
                }
                coordinate(&vals[0], i as usize - 1)?
            }
            "bernstein" => {
                let i = int(&vals[0], "i")?;
                let n = int(&vals[1], "n")?;
                limits::BERNSTEIN_DEGREE
                    .check(u64::from(n))
                    .map_err(|e| ResolveError {
                        def: None,
                        message: format!("bernstein at {pos}: {e}"),
                    })?;
                if i > n {
                    return err(format!("bernstein at {pos}: i = {i} > n = {n}"));
                }
                let t = scalar(&vals[2], "t")?;
                Val::Scalar(bernstein(i, n, &t, pos))
            }
            "bezier" => {
                let t = scalar(&vals[0], "t")?;
                let n = (vals.len() - 2) as u32;
                let shapes: Vec<Option<usize>> = vals[1..]
                    .iter()
                    .map(|(v, _)| match v {
                        Val::Scalar(_) => None,
                        Val::Vector(xs) => Some(xs.len()),
                    })
                    .collect();
                if shapes.iter().any(|s| *s != shapes[0]) {
                    return err(format!(
                        "bezier at {pos}: the control points must all be scalars or all vectors of one length"
                    ));
                }
                let dim = shapes[0];
                let weights: Vec<Expr> = (0..=n).map(|i| bernstein(i, n, &t, pos)).collect();
                let comb = |k: Option<usize>| {
                    plus(
                        vals[1..]
                            .iter()
                            .zip(&weights)
                            .map(|((v, _), w)| {
                                let c = match (v, k) {
                                    (Val::Scalar(x), _) => x.clone(),
                                    (Val::Vector(xs), Some(k)) => xs[k].clone(),
                                    (Val::Vector(_), None) => {
                                        unreachable!("all control points have one shape")
                                    }
                                };
                                // The weight of a degree-0 curve is 1: the point alone.
                                if matches!(&w.kind, ExprKind::Number(q) if *q == Rational::ONE) {
                                    c
                                } else {
                                    times(w.clone(), c)
                                }
                            })
                            .collect(),
                    )
                };
                match dim {
                    None => Val::Scalar(comb(None)),
                    Some(d) => Val::Vector((0..d).map(|k| comb(Some(k))).collect()),
                }
            }
            other => unreachable!("{other} is in FUNCTIONS and handled above"),
        })
    }
}

/// `C(n, i) t^i (1 - t)^(n - i)` as a tree.
fn bernstein(i: u32, n: u32, t: &Expr, pos: usize) -> Expr {
    let node = |kind: ExprKind| Expr { kind, pos };
    let num = |q: Rational| node(ExprKind::Number(q));
    let int = |k: u64| num(Rational::from_integer(k as i64));
    // C(n, i) exactly: C(n, k + 1) = C(n, k) (n - k) / (k + 1), an exact integer division.
    let mut c = num_bigint::BigInt::from(1u32);
    for k in 0..i {
        c = c * (n - k) / (k + 1);
    }
    let c = Rational::from(c);
    let one_minus_t = node(ExprKind::Sum(vec![
        (AddOp::Plus, int(1)),
        (AddOp::Minus, t.clone()),
    ]));
    // Factors 1, t^0 and (1 - t)^0 are left out and exponents 1 not written, so the tree
    // prints as a formula would be written (`3 t (1 - t)^2`, `t^3`).
    let mut factors = Vec::new();
    if c != Rational::ONE {
        factors.push(num(c));
    }
    for (base, k) in [(t.clone(), i), (one_minus_t, n - i)] {
        match k {
            0 => {}
            1 => factors.push(base),
            k => factors.push(node(ExprKind::Pow(
                Box::new(base),
                Box::new(int(u64::from(k))),
            ))),
        }
    }
    match factors.len() {
        0 => int(1),
        1 => factors.pop().expect("one factor"),
        _ => node(ExprKind::Product(
            factors.into_iter().map(|f| (MulOp::Times, f)).collect(),
        )),
    }
}

/// `e` with every position set to `pos`.
fn at_pos(e: &Expr, pos: usize) -> Expr {
    map_tree(e, &|mut x| {
        x.pos = pos;
        x
    })
}

/// `e` with the variable `v` replaced by `value`.
pub fn substitute(e: &Expr, v: &str, value: &Expr) -> Expr {
    map_tree(e, &|x| match &x.kind {
        ExprKind::Var(n) if n == v => at_pos(value, x.pos),
        _ => x,
    })
}

/// Rebuilds `e` bottom-up, handing every rebuilt node (its children done) to `f`.
fn map_tree(e: &Expr, f: &dyn Fn(Expr) -> Expr) -> Expr {
    let b = |x: &Expr| Box::new(map_tree(x, f));
    let kind = match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => e.kind.clone(),
        ExprKind::Neg(x) => ExprKind::Neg(b(x)),
        ExprKind::Sqrt(x) => ExprKind::Sqrt(b(x)),
        ExprKind::Pow(x, k) => ExprKind::Pow(b(x), b(k)),
        ExprKind::Sum(ts) => ExprKind::Sum(ts.iter().map(|(o, t)| (*o, map_tree(t, f))).collect()),
        ExprKind::Product(fs) => {
            ExprKind::Product(fs.iter().map(|(o, t)| (*o, map_tree(t, f))).collect())
        }
        ExprKind::Call(n, args) => {
            ExprKind::Call(n.clone(), args.iter().map(|a| map_tree(a, f)).collect())
        }
    };
    f(Expr { kind, pos: e.pos })
}

/// The number of nodes of a tree.
pub fn count_nodes(e: &Expr) -> usize {
    1 + match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => 0,
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => count_nodes(x),
        ExprKind::Pow(x, k) => count_nodes(x) + count_nodes(k),
        ExprKind::Sum(ts) => ts.iter().map(|(_, t)| count_nodes(t)).sum(),
        ExprKind::Product(fs) => fs.iter().map(|(_, t)| count_nodes(t)).sum(),
        ExprKind::Call(_, args) => args.iter().map(count_nodes).sum(),
    }
}

/// Whether the tree contains `sqrt` (then the radical coefficient field is needed).
pub fn has_sqrt(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Sqrt(_) => true,
        ExprKind::Number(_) | ExprKind::Var(_) => false,
        ExprKind::Neg(x) => has_sqrt(x),
        ExprKind::Pow(x, k) => has_sqrt(x) || has_sqrt(k),
        ExprKind::Sum(ts) => ts.iter().any(|(_, t)| has_sqrt(t)),
        ExprKind::Product(fs) => fs.iter().any(|(_, t)| has_sqrt(t)),
        ExprKind::Call(_, args) => args.iter().any(has_sqrt),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exactcheck_exact::poly::Vars;

    fn defs(list: &[(&str, &str)]) -> Defs {
        Defs::new(
            list.iter()
                .map(|(n, t)| {
                    let text = if let Some(inner) = t.strip_prefix('[') {
                        DefText::Vector(
                            inner
                                .trim_end_matches(']')
                                .split(';')
                                .map(str::to_string)
                                .collect(),
                        )
                    } else {
                        DefText::Scalar(t.to_string())
                    };
                    (n.to_string(), text)
                })
                .collect(),
        )
        .unwrap()
    }

    fn poly(d: &mut Defs, text: &str) -> String {
        let e = d.resolve_scalar(text).unwrap();
        let mut vars = Vars::new();
        let p = e.to_poly::<Rational>(&mut vars).unwrap();
        p.display(&vars).to_string()
    }

    #[test]
    fn vectors_and_functions() {
        let mut d = defs(&[
            ("u", "[1;2;3]"),
            ("v", "[x0;y0;z0]"),
            ("w", "cross(u, v)"),
            ("A", "2*B"),
            ("B", "t + 1"),
        ]);
        assert_eq!(poly(&mut d, "dot(u, v)"), poly(&mut d, "x0 + 2*y0 + 3*z0"));
        assert_eq!(poly(&mut d, "dot(w, u)"), "0");
        assert_eq!(poly(&mut d, "dot(w, v)"), "0");
        assert_eq!(poly(&mut d, "norm2(u)"), "14");
        assert_eq!(poly(&mut d, "at(2*u - v, 3) + z(v)"), "6");
        assert_eq!(poly(&mut d, "A"), poly(&mut d, "2*t + 2"));
        assert_eq!(poly(&mut d, "subs(A, t, 3)"), "8");
        assert_eq!(
            poly(&mut d, "bezier(s, 0, 1, 1)"),
            poly(&mut d, "2*s - s^2")
        );
        assert_eq!(
            poly(&mut d, "bernstein(1, 3, s)"),
            poly(&mut d, "3*s*(1 - s)^2")
        );
        let b = d.resolve_text("bezier(s, u, v)").unwrap();
        assert_eq!(b.components().len(), 3);
    }

    #[test]
    fn errors_name_what_is_wrong() {
        let mut d = defs(&[("u", "[1;2;3]"), ("P", "Q + 1"), ("Q", "2*P")]);
        let m = |d: &mut Defs, t: &str| d.resolve_text(t).unwrap_err().message;
        assert!(m(&mut d, "sin(x)").contains("unknown function 'sin' at 0"));
        assert!(m(&mut d, "dot(u)").contains("dot at 0 takes 2 arguments, not 1"));
        assert!(m(&mut d, "u*u").contains("product of two vectors"));
        assert!(d
            .resolve_scalar("u + u")
            .unwrap_err()
            .message
            .contains("a vector of 3 where a scalar is expected"));
        assert!(m(&mut d, "1 + u").contains("a scalar at 0 added to a vector of 3"));
        let e = d.resolve_text("P").unwrap_err();
        assert_eq!(e.def.as_deref(), Some("P"));
        assert!(e.message.contains("P -> Q -> P"), "{}", e.message);
    }

    #[test]
    fn expansion_is_bounded() {
        let mut list = vec![("a0".to_string(), DefText::Scalar("x".into()))];
        for k in 1..30 {
            list.push((
                format!("a{k}"),
                DefText::Scalar(format!("a{0} + a{0}", k - 1)),
            ));
        }
        let mut d = Defs::new(list).unwrap();
        let e = d.resolve_text("a29").unwrap_err();
        assert!(e.message.contains("MAX_NODES"), "{}", e.message);
    }
}
