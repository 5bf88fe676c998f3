//! The function library of the expression language: definitions, functions with parameters,
//! vectors, matrices and the vector/Bezier functions, resolved by rewriting expression trees.
//!
//! A formula is parsed with [`parse_expr_with_calls`]; then every defined name is replaced by
//! its value and every call by what the function computes, so the tree handed to the
//! conversions ([`Expr::to_poly`], [`Expr::to_ratfun`], exact evaluation) contains only numbers,
//! variables, `+ - * / ^`, `sqrt` and the calls of the core language ([`super::FUNCTIONS`],
//! whose arguments are resolved and which the conversions decide). `prove` resolves its sides
//! here without definitions; a claims file with its `[define]` table ([`Defs`]).
//!
//! A value ([`Val`]) is a scalar (one tree), a vector (one tree per coordinate) or a matrix (one
//! tree per entry, by rows). Vectors and matrices of one shape add and subtract, everything
//! scales by scalars, a matrix multiplies a vector or a matrix of matching size
//! (`M*v`, `M*N`); everything else about them goes through the functions:
//!
//! | function | value |
//! | --- | --- |
//! | `vec(a, b, ...)`, `[a, b, ...]` | the vector with these coordinates |
//! | `[[a, b], [c, d]]` | the matrix with these rows |
//! | `dot(u, v)` | `sum u_i v_i` (same length) |
//! | `cross(u, v)` | the cross product of two 3-vectors; of two 2-vectors the scalar `u1 v2 - u2 v1` |
//! | `norm2(v)` | `dot(v, v)` |
//! | `x(v)`, `y(v)`, `z(v)`, `at(v, i)` | a coordinate (`at` counts from 1) |
//! | `det(M)` | the determinant of a square matrix (cofactor expansion) |
//! | `transpose(M)` | the transposed matrix |
//! | `bernstein(i, n, t)` | `C(n, i) t^i (1 - t)^(n - i)` (integer constants `0 <= i <= n`) |
//! | `bezier(t, p0, ..., pn)` | `sum_i bernstein(i, n, t) p_i`, scalars or vectors |
//! | `subs(e, v, w)` | `e` with the variable `v` replaced by `w` (e.g. a coefficient: `subs(F, u, 0)`) |
//!
//! Definitions may refer to one another in any order; each name without parameters is resolved
//! once (memoized) and a cycle is an error naming it (`A -> B -> A`). A function definition
//! (`f(t)`, `cross2(u, v)`) is resolved at each call with its parameters bound to the values of
//! the arguments (scalars, vectors or matrices); a parameter shadows a defined name of the same
//! spelling, and the body sees only its parameters and the definitions. A substituted value takes
//! the position of the name or call it replaces, so a later error (a bad exponent, ...) points
//! into the text the user typed. The size of a resolved tree is bounded ([`MAX_NODES`]):
//! definitions that double at each level cannot expand without limit, and a determinant whose
//! cofactor expansion would exceed the bound is refused before it is built. Its nesting
//! (parentheses, signs and calls of its printed form) is bounded by the `depth` limit, as a
//! typed formula's is, and so is the number of definitions resolved inside one another: a long
//! chain or cycle of definitions is an error naming the limit or the cycle, not a stack overflow.
//!
//! The determinant is a cofactor expansion (skipping literal zero entries) rather than Bareiss
//! elimination: the entries are trees, which the polynomial conversion divides only by constants,
//! so a fraction-free tree without divisions is what every later step accepts.
//!
//! Hand-written: the rewriting is a small recursion over the expression grammar of this
//! module's parent; no crate knows that grammar.

use super::parse::LIST;
use super::{parse_expr_with_calls, AddOp, Expr, ExprKind, MulOp};
use crate::rational::Rational;
use exactcheck_core::limits;
use std::collections::{HashMap, HashSet};
use std::fmt;

/// The largest number of nodes of a resolved expression.
pub const MAX_NODES: usize = 500_000;

/// The functions of the library: name, number of arguments, and whether more may follow (then
/// it is the least).
const LIBRARY: [(&str, usize, bool); 12] = [
    ("vec", 1, true),
    ("dot", 2, false),
    ("cross", 2, false),
    ("norm2", 1, false),
    ("x", 1, false),
    ("y", 1, false),
    ("z", 1, false),
    ("at", 2, false),
    ("det", 1, false),
    ("transpose", 1, false),
    ("bernstein", 3, false),
    ("bezier", 2, true),
];

/// The names of the library's functions (`subs` included), for help texts and error messages.
pub fn function_names() -> Vec<&'static str> {
    let mut names: Vec<&str> = LIBRARY.iter().map(|(n, _, _)| *n).collect();
    names.push("subs");
    names
}

/// A resolved value: a scalar, a vector or a matrix of scalars.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// One expression.
    Scalar(Expr),
    /// One expression per coordinate.
    Vector(Vec<Expr>),
    /// One expression per entry, by rows (at least one row, all of one non-zero length).
    Matrix(Vec<Vec<Expr>>),
}

impl Val {
    /// The components (one for a scalar; a matrix's entries by rows).
    pub fn components(&self) -> Vec<Expr> {
        match self {
            Val::Scalar(e) => vec![e.clone()],
            Val::Vector(v) => v.clone(),
            Val::Matrix(rows) => rows.iter().flatten().cloned().collect(),
        }
    }

    /// `a scalar`, `a vector of n` or `a 2x3 matrix`.
    pub fn shape(&self) -> String {
        match self {
            Val::Scalar(_) => "a scalar".into(),
            Val::Vector(v) => format!("a vector of {}", v.len()),
            Val::Matrix(rows) => format!("a {}x{} matrix", rows.len(), rows[0].len()),
        }
    }

    /// The value with `f` applied to every component.
    fn map(self, f: impl Fn(Expr) -> Expr) -> Val {
        match self {
            Val::Scalar(e) => Val::Scalar(f(e)),
            Val::Vector(xs) => Val::Vector(xs.into_iter().map(f).collect()),
            Val::Matrix(rows) => Val::Matrix(
                rows.into_iter()
                    .map(|r| r.into_iter().map(&f).collect())
                    .collect(),
            ),
        }
    }

    /// The components, borrowed.
    fn parts(&self) -> Vec<&Expr> {
        match self {
            Val::Scalar(e) => vec![e],
            Val::Vector(v) => v.iter().collect(),
            Val::Matrix(rows) => rows.iter().flatten().collect(),
        }
    }

    /// Whether `self` and `other` have the same shape.
    fn same_shape(&self, other: &Val) -> bool {
        match (self, other) {
            (Val::Scalar(_), Val::Scalar(_)) => true,
            (Val::Vector(a), Val::Vector(b)) => a.len() == b.len(),
            (Val::Matrix(a), Val::Matrix(b)) => a.len() == b.len() && a[0].len() == b[0].len(),
            _ => false,
        }
    }
}

/// The text of a definition.
#[derive(Clone, Debug)]
pub enum DefText {
    /// A scalar formula (or any formula: it may compute a vector or matrix).
    Scalar(String),
    /// A vector: one formula per coordinate.
    Vector(Vec<String>),
}

/// A definition: its parameters (empty for a plain name) and text.
#[derive(Clone, Debug)]
struct Def {
    /// The key as written (`f(t)`), for the caller to locate the definition.
    head: String,
    name: String,
    params: Vec<String>,
    text: DefText,
}

/// An error of resolution: the definition it arose in (if not the formula itself) and the
/// message (which carries the position in that text).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ResolveError {
    /// The definition whose text is at fault, `None` for the formula being resolved.
    pub def: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ResolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.def {
            Some(d) => write!(f, "in the definition of {d}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for ResolveError {}

type R<T> = Result<T, ResolveError>;

fn err<T>(message: String) -> R<T> {
    Err(ResolveError { def: None, message })
}

/// Whether `s` is a name: letters, digits and `_`, not starting with a digit.
fn is_name(s: &str) -> bool {
    s.chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Splits `f(a, b)` into the name and the parameters (none for a plain name).
fn split_head(head: &str) -> Result<(String, Vec<String>), String> {
    let head = head.trim();
    let bad = || {
        format!("{head:?} is not a name (letters, digits, '_') or a function head such as \"f(t)\" or \"cross2(u, v)\"")
    };
    let Some(open) = head.find('(') else {
        return if is_name(head) {
            Ok((head.to_string(), Vec::new()))
        } else {
            Err(bad())
        };
    };
    let name = head[..open].trim();
    let Some(inner) = head[open + 1..].strip_suffix(')') else {
        return Err(bad());
    };
    let params: Vec<String> = inner.split(',').map(|p| p.trim().to_string()).collect();
    if !is_name(name) || params.iter().any(|p| !is_name(p)) {
        return Err(bad());
    }
    for (k, p) in params.iter().enumerate() {
        if params[..k].contains(p) {
            return Err(format!("{head:?}: the parameter {p} appears twice"));
        }
    }
    Ok((name.to_string(), params))
}

/// Definitions: names (and functions) with their text, resolved on demand. The empty set
/// ([`Defs::default`]) resolves the library functions alone, as `prove` does.
#[derive(Default)]
pub struct Defs {
    /// In file order.
    entries: Vec<Def>,
    /// The position in `entries` of each name.
    index: HashMap<String, usize>,
    /// The values of the definitions without parameters resolved so far.
    resolved: HashMap<String, Val>,
    /// The parameters of the function whose body is being resolved.
    scope: HashMap<String, Val>,
}

impl Defs {
    /// Definitions from `(head, text)` pairs in file order; a head is a name (`A`) or a function
    /// with its parameters (`f(t)`, `cross2(u, v)`).
    ///
    /// # Errors
    /// `(head, message)`: a head that is not a name or a function head, a name given twice, a
    /// function that would shadow one of the language (`sqrt`, `dot`, `diff`, ...), a function
    /// given as a vector of formulas.
    pub fn new(entries: Vec<(String, DefText)>) -> Result<Defs, (String, String)> {
        let mut defs = Defs::default();
        for (head, text) in entries {
            let (name, params) = split_head(&head).map_err(|m| (head.clone(), m))?;
            if name == "sqrt" {
                return Err((
                    head,
                    format!("{name:?} is the square root, not a name to define"),
                ));
            }
            let builtin = function_names().contains(&name.as_str())
                || super::FUNCTIONS.contains(&name.as_str());
            if builtin && !params.is_empty() {
                return Err((
                    head,
                    format!("{name} is a function of the language and cannot be redefined"),
                ));
            }
            if !params.is_empty() && matches!(text, DefText::Vector(_)) {
                return Err((
                    head,
                    "a function's body is one formula (write vec(...) or [...] for a vector)"
                        .into(),
                ));
            }
            if defs.index.contains_key(&name) {
                return Err((head, format!("{name} is defined twice")));
            }
            defs.index.insert(name.clone(), defs.entries.len());
            defs.entries.push(Def {
                head,
                name,
                params,
                text,
            });
        }
        Ok(defs)
    }

    /// The names in file order.
    pub fn names(&self) -> Vec<String> {
        self.entries.iter().map(|d| d.name.clone()).collect()
    }

    /// Resolves every definition without parameters and parses every function's body (so an
    /// error in one is reported at that definition).
    ///
    /// # Errors
    /// The first definition that does not resolve.
    pub fn resolve_all(&mut self) -> R<()> {
        for k in 0..self.entries.len() {
            let def = self.entries[k].clone();
            if def.params.is_empty() {
                self.definition(&def.name, &mut Vec::new())?;
            } else if let DefText::Scalar(t) = &def.text {
                parse_expr_with_calls(t).map_err(|e| ResolveError {
                    def: Some(def.name.clone()),
                    message: e.to_string(),
                })?;
            }
        }
        Ok(())
    }

    /// Parses and resolves a formula.
    ///
    /// # Errors
    /// A syntax error, an unknown function, a wrong arity, a shape that does not fit (a vector
    /// where a scalar is needed, matrices of different sizes, ...), a cycle or an expansion
    /// beyond [`MAX_NODES`].
    pub fn resolve_text(&mut self, text: &str) -> R<Val> {
        let e = parse_expr_with_calls(text).map_err(|e| ResolveError {
            def: None,
            message: e.to_string(),
        })?;
        self.resolve_expr(&e)
    }

    /// Resolves a parsed formula.
    ///
    /// # Errors
    /// As [`Defs::resolve_text`] (without the syntax errors).
    pub fn resolve_expr(&mut self, e: &Expr) -> R<Val> {
        self.resolve(e, &mut Vec::new())
    }

    /// [`Defs::resolve_text`] for a formula that must be a scalar.
    ///
    /// # Errors
    /// As [`Defs::resolve_text`]; a vector or matrix value.
    pub fn resolve_scalar(&mut self, text: &str) -> R<Expr> {
        match self.resolve_text(text)? {
            Val::Scalar(e) => Ok(e),
            v => err(format!("{} where a scalar is expected", v.shape())),
        }
    }

    /// The key a definition was given with (`f(t)` for the function `f`).
    pub fn head(&self, name: &str) -> Option<&str> {
        self.def(name).map(|d| d.head.as_str())
    }

    /// Whether `name` is defined (with or without parameters).
    pub fn is_defined(&self, name: &str) -> bool {
        self.index.contains_key(name)
    }

    fn def(&self, name: &str) -> Option<&Def> {
        self.index.get(name).map(|&i| &self.entries[i])
    }

    /// The value of the definition `name` (without parameters).
    fn definition(&mut self, name: &str, stack: &mut Vec<String>) -> R<Val> {
        if let Some(v) = self.resolved.get(name) {
            return Ok(v.clone());
        }
        // The definitions see no parameters of the function being resolved.
        let scope = std::mem::take(&mut self.scope);
        let r = self.body(name, &[], stack);
        self.scope = scope;
        let value = r?;
        self.resolved.insert(name.to_string(), value.clone());
        Ok(value)
    }

    /// The value of the body of `name` with its parameters bound to `args` (in `self.scope`,
    /// which the caller saves and restores).
    fn body(&mut self, name: &str, args: &[Val], stack: &mut Vec<String>) -> R<Val> {
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
        let def = self
            .def(name)
            .expect("body() is called for defined names only")
            .clone();
        self.scope = def
            .params
            .iter()
            .cloned()
            .zip(args.iter().cloned())
            .collect();
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
        let value = match &def.text {
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
        Ok(value)
    }

    /// The definitions `name`'s text refers to, as names or calls (none when it does not
    /// parse: resolving it reports that); its parameters shadow definitions.
    fn references(&self, name: &str) -> Vec<String> {
        let Some(def) = self.def(name) else {
            return Vec::new();
        };
        let texts = match &def.text {
            DefText::Scalar(t) => std::slice::from_ref(t),
            DefText::Vector(ts) => ts.as_slice(),
        };
        let mut refs = Vec::new();
        for t in texts {
            if let Ok(e) = parse_expr_with_calls(t) {
                e.collect_variables(&mut refs);
                collect_calls(&e, &mut refs);
            }
        }
        refs.retain(|v| self.is_defined(v) && !def.params.contains(v));
        refs
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

    /// Resolves a parsed expression and checks the size and nesting of the result.
    fn resolve(&mut self, e: &Expr, stack: &mut Vec<String>) -> R<Val> {
        let v = self.resolve_inner(e, stack)?;
        let components = v.parts();
        let n: usize = components.iter().map(|x| count_nodes(x)).sum();
        // Only an expansion is refused: a formula typed at this size is the conversion's to
        // bound (its `terms`, `degree`, ... limits).
        if n > MAX_NODES && n > count_nodes(e) {
            return err(too_many_nodes(e.pos));
        }
        let depth = components.iter().map(|x| x.nesting()).max().unwrap_or(0);
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
                if let Some(v) = self.scope.get(name) {
                    v.clone().map(|x| at_pos(&x, pos))
                } else if let Some(def) = self.def(name) {
                    if !def.params.is_empty() {
                        let n = def.params.len();
                        return err(format!(
                            "{name} at {pos} is a function: call it with {n} argument{}",
                            if n == 1 { "" } else { "s" }
                        ));
                    }
                    self.definition(name, stack)?.map(|x| at_pos(&x, pos))
                } else {
                    Val::Scalar(e.clone())
                }
            }
            ExprKind::Neg(x) => self
                .resolve(x, stack)?
                .map(|x| node(ExprKind::Neg(Box::new(x)))),
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
                let first = vals
                    .iter()
                    .find(|(_, v, _)| !matches!(v, Val::Scalar(_)))
                    .map_or_else(|| vals[0].1.clone(), |(_, v, _)| v.clone());
                for (_, v, p) in &vals {
                    if !v.same_shape(&first) {
                        return err(format!("{} at {p} added to {}", v.shape(), first.shape()));
                    }
                }
                let sum = |parts: Vec<(AddOp, Expr)>| node(ExprKind::Sum(parts));
                let split: Vec<(AddOp, Vec<&Expr>)> =
                    vals.iter().map(|(op, v, _)| (*op, v.parts())).collect();
                let comps: Vec<Vec<(AddOp, Expr)>> = (0..split[0].1.len())
                    .map(|i| split.iter().map(|(op, xs)| (*op, xs[i].clone())).collect())
                    .collect();
                let mut comps = comps.into_iter().map(sum);
                match &first {
                    Val::Scalar(_) => Val::Scalar(comps.next().expect("one component")),
                    Val::Vector(_) => Val::Vector(comps.collect()),
                    Val::Matrix(rows) => {
                        let c = rows[0].len();
                        let flat: Vec<Expr> = comps.collect();
                        Val::Matrix(flat.chunks(c).map(<[Expr]>::to_vec).collect())
                    }
                }
            }
            ExprKind::Product(factors) => {
                let mut scalars = Vec::new();
                let mut other: Option<(Val, usize)> = None;
                for (op, f) in factors {
                    let v = self.resolve(f, stack)?;
                    if let Val::Scalar(x) = v {
                        scalars.push((*op, x));
                        continue;
                    }
                    if *op == MulOp::Divide {
                        return err(format!("division by {} at {}", v.shape(), f.pos));
                    }
                    other = Some(match other {
                        None => (v, f.pos),
                        Some((left, p)) => (multiply(left, v, p, f.pos)?, p),
                    });
                }
                let with = |x: Option<Expr>| {
                    let mut fs = scalars.clone();
                    if let Some(x) = x {
                        fs.insert(0, (MulOp::Times, x));
                    }
                    node(ExprKind::Product(fs))
                };
                match other {
                    None => Val::Scalar(with(None)),
                    Some((v, _)) if scalars.is_empty() => v,
                    Some((v, _)) => v.map(|x| with(Some(x))),
                }
            }
            ExprKind::Call(name, args) => self.call(name, args, pos, stack)?,
        })
    }

    /// A call of a defined function: the arguments resolved in the caller's scope, the body in
    /// a scope of the parameters.
    fn call_defined(
        &mut self,
        name: &str,
        args: &[Expr],
        pos: usize,
        stack: &mut Vec<String>,
    ) -> R<Val> {
        let n = self.def(name).map_or(0, |d| d.params.len());
        if n == 0 {
            return err(format!(
                "{name} at {pos} is a defined name without parameters, not a function (write {name}*(...) for a product)"
            ));
        }
        if args.len() != n {
            return err(format!(
                "{name} at {pos} takes {n} argument{}, not {}",
                if n == 1 { "" } else { "s" },
                args.len()
            ));
        }
        let mut vals = Vec::new();
        for a in args {
            vals.push(self.resolve(a, stack)?);
        }
        let scope = std::mem::take(&mut self.scope);
        let r = self.body(name, &vals, stack);
        self.scope = scope;
        // An error inside the body names the function and the call (its position is in the
        // body's text).
        let r = r.map_err(|e| ResolveError {
            message: format!(
                "in {} (called at {pos}): {}",
                e.def.as_deref().unwrap_or(name),
                e.message
            ),
            def: e.def,
        })?;
        Ok(r.map(|x| at_pos(&x, pos)))
    }

    fn call(&mut self, name: &str, args: &[Expr], pos: usize, stack: &mut Vec<String>) -> R<Val> {
        if self.is_defined(name) {
            return self.call_defined(name, args, pos, stack);
        }
        if name == LIST {
            return self.list(args, pos, stack);
        }
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
            if self.is_defined(v) || self.scope.contains_key(v) {
                return err(format!(
                    "subs at {pos}: {v} is a defined name, not a variable"
                ));
            }
            let value = self.scalar(&args[2], stack, "the value of subs")?;
            let failed = std::cell::RefCell::new(None);
            let out = self.resolve(&args[0], stack)?.map(|e| {
                substitute_free(&e, v, &value).unwrap_or_else(|why| {
                    failed.borrow_mut().get_or_insert(why);
                    e
                })
            });
            return match failed.into_inner() {
                Some(why) => err(format!("subs at {pos}: {why}")),
                None => Ok(out),
            };
        }
        if super::FUNCTIONS.contains(&name) {
            // A function of the core language: its arguments resolved, the call kept for the
            // conversion, which checks them.
            let mut resolved = Vec::new();
            for a in args {
                resolved.push(self.scalar(a, stack, &format!("an argument of {name}"))?);
            }
            return Ok(Val::Scalar(Expr {
                kind: ExprKind::Call(name.to_string(), resolved),
                pos,
            }));
        }
        let Some(&(_, arity, variadic)) = LIBRARY.iter().find(|(n, _, _)| *n == name) else {
            let mut names = function_names();
            names.push("sqrt");
            names.extend(super::FUNCTIONS);
            let last = names.pop().unwrap_or("sqrt");
            return err(format!(
                "unknown function '{name}' at {pos}: the functions are {} and {last} (write '{name}*(...)' for a product)",
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
        library_call(name, &vals, pos)
    }

    /// `[a, b, ...]`: a vector of scalars or a matrix of rows.
    fn list(&mut self, items: &[Expr], pos: usize, stack: &mut Vec<String>) -> R<Val> {
        let mut vals = Vec::new();
        for a in items {
            vals.push((self.resolve(a, stack)?, a.pos));
        }
        match &vals[0].0 {
            Val::Scalar(_) => Ok(Val::Vector(
                vals.into_iter()
                    .map(|(v, p)| match v {
                        Val::Scalar(x) => Ok(x),
                        v => err(format!(
                            "{} at {p} in a list of scalars (the list at {pos}; a matrix is [[a, b], [c, d]])",
                            v.shape()
                        )),
                    })
                    .collect::<R<_>>()?,
            )),
            Val::Vector(first) => {
                let n = first.len();
                Ok(Val::Matrix(
                    vals.into_iter()
                        .enumerate()
                        .map(|(k, (v, p))| match v {
                            Val::Vector(xs) if xs.len() == n => Ok(xs),
                            v => err(format!(
                                "row {} of the matrix at {pos} (at {p}) is {}, row 1 a vector of {n}",
                                k + 1,
                                v.shape()
                            )),
                        })
                        .collect::<R<_>>()?,
                ))
            }
            v @ Val::Matrix(_) => err(format!(
                "{} at {} in a list (the list at {pos}): entries are scalars, rows are vectors",
                v.shape(),
                vals[0].1
            )),
        }
    }
}

fn too_many_nodes(pos: usize) -> String {
    format!(
        "the expression at {pos} expands to more than {MAX_NODES} nodes (MAX_NODES) after substituting the definitions"
    )
}

fn times(a: Expr, b: Expr, pos: usize) -> Expr {
    Expr {
        kind: ExprKind::Product(vec![(MulOp::Times, a), (MulOp::Times, b)]),
        pos,
    }
}

fn plus(xs: Vec<Expr>, pos: usize) -> Expr {
    Expr {
        kind: ExprKind::Sum(xs.into_iter().map(|x| (AddOp::Plus, x)).collect()),
        pos,
    }
}

/// `sum a_i b_i`.
fn inner(a: &[Expr], b: &[Expr], pos: usize) -> Expr {
    plus(
        a.iter()
            .zip(b)
            .map(|(x, y)| times(x.clone(), y.clone(), pos))
            .collect(),
        pos,
    )
}

fn transposed(rows: &[Vec<Expr>]) -> Vec<Vec<Expr>> {
    (0..rows[0].len())
        .map(|j| rows.iter().map(|r| r[j].clone()).collect())
        .collect()
}

/// The product of two non-scalar values (`left` at `lp`, `right` at `rp`): matrix times
/// vector or matrix.
fn multiply(left: Val, right: Val, lp: usize, rp: usize) -> R<Val> {
    let mismatch = |l: &Val, r: &Val| {
        err(format!(
            "a product of {} at {lp} and {} at {rp}: the sizes do not match",
            l.shape(),
            r.shape()
        ))
    };
    match (&left, &right) {
        (Val::Vector(_), Val::Vector(_)) => err(format!(
            "a product of two vectors at {rp}: write dot(u, v) or cross(u, v)"
        )),
        (Val::Vector(_), Val::Matrix(_)) => err(format!(
            "a product of {} at {lp} and {} at {rp}: a vector multiplies no matrix from the left (write transpose(M)*v)",
            left.shape(),
            right.shape()
        )),
        (Val::Matrix(m), Val::Vector(v)) => {
            if m[0].len() != v.len() {
                return mismatch(&left, &right);
            }
            Ok(Val::Vector(m.iter().map(|r| inner(r, v, lp)).collect()))
        }
        (Val::Matrix(a), Val::Matrix(b)) => {
            if a[0].len() != b.len() {
                return mismatch(&left, &right);
            }
            let cols = transposed(b);
            Ok(Val::Matrix(
                a.iter()
                    .map(|r| cols.iter().map(|c| inner(r, c, lp)).collect())
                    .collect(),
            ))
        }
        _ => unreachable!("multiply() is called for vectors and matrices"),
    }
}

/// Whether `e` is the literal number 0.
fn is_zero(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Number(q) if *q == Rational::ZERO)
}

/// An upper bound of the nodes of the cofactor expansion of an `n x n` matrix whose entries have
/// at most `entry` nodes (saturating).
fn det_nodes(n: usize, entry: usize) -> usize {
    let mut nodes = entry;
    for k in 2..=n {
        // A sum of k signed products of an entry and a minor's expansion.
        nodes = k
            .saturating_mul(entry.saturating_add(nodes).saturating_add(2))
            .saturating_add(1);
    }
    nodes
}

/// The determinant by cofactor expansion along the first row (literal zero entries skipped).
/// `cols` are the columns of the minor, `row` its first row.
fn det(m: &[Vec<Expr>], row: usize, cols: &[usize], pos: usize) -> Expr {
    if cols.len() == 1 {
        return m[row][cols[0]].clone();
    }
    let mut terms = Vec::new();
    for (k, &c) in cols.iter().enumerate() {
        let a = &m[row][c];
        if is_zero(a) {
            continue;
        }
        let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
        let op = if k % 2 == 0 {
            AddOp::Plus
        } else {
            AddOp::Minus
        };
        terms.push((op, times(a.clone(), det(m, row + 1, &rest, pos), pos)));
    }
    if terms.is_empty() {
        return Expr {
            kind: ExprKind::Number(Rational::ZERO),
            pos,
        };
    }
    Expr {
        kind: ExprKind::Sum(terms),
        pos,
    }
}

/// A library function applied to resolved arguments (`vals`: value and position).
fn library_call(name: &str, vals: &[(Val, usize)], pos: usize) -> R<Val> {
    let node = |kind: ExprKind| Expr { kind, pos };
    let vector = |v: &(Val, usize), what: &str| -> R<Vec<Expr>> {
        match &v.0 {
            Val::Vector(xs) => Ok(xs.clone()),
            other => err(format!(
                "{} at {} where a vector is expected ({what} of {name})",
                other.shape(),
                v.1
            )),
        }
    };
    let matrix = |v: &(Val, usize)| -> R<Vec<Vec<Expr>>> {
        match &v.0 {
            Val::Matrix(rows) => Ok(rows.clone()),
            other => err(format!(
                "{} at {} where a matrix is expected (the argument of {name}; a matrix is [[a, b], [c, d]])",
                other.shape(),
                v.1
            )),
        }
    };
    let scalar = |v: &(Val, usize), what: &str| -> R<Expr> {
        match &v.0 {
            Val::Scalar(x) => Ok(x.clone()),
            other => err(format!(
                "{} at {} where a scalar is expected ({what} of {name})",
                other.shape(),
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
    let same_length = |u: &[Expr], v: &[Expr]| -> R<()> {
        if u.len() == v.len() {
            Ok(())
        } else {
            err(format!(
                "{name} at {pos}: vectors of {} and {} coordinates",
                u.len(),
                v.len()
            ))
        }
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
        "dot" => {
            let u = vector(&vals[0], "the first argument")?;
            let v = vector(&vals[1], "the second argument")?;
            same_length(&u, &v)?;
            Val::Scalar(inner(&u, &v, pos))
        }
        "norm2" => {
            let v = vector(&vals[0], "the argument")?;
            Val::Scalar(inner(&v, &v, pos))
        }
        "cross" => {
            let u = vector(&vals[0], "the first argument")?;
            let v = vector(&vals[1], "the second argument")?;
            let minus =
                |a: Expr, b: Expr| node(ExprKind::Sum(vec![(AddOp::Plus, a), (AddOp::Minus, b)]));
            let c = |i: usize, j: usize| {
                minus(
                    times(u[i].clone(), v[j].clone(), pos),
                    times(u[j].clone(), v[i].clone(), pos),
                )
            };
            match (u.len(), v.len()) {
                (2, 2) => Val::Scalar(c(0, 1)),
                (3, 3) => Val::Vector(vec![c(1, 2), c(2, 0), c(0, 1)]),
                (a, b) => {
                    return err(format!(
                        "cross at {pos} takes two 2-vectors or two 3-vectors, not vectors of {a} and {b}"
                    ))
                }
            }
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
        "det" => {
            let m = matrix(&vals[0])?;
            let (r, c) = (m.len(), m[0].len());
            if r != c {
                return err(format!(
                    "det at {pos} takes a square matrix, not a {r}x{c} matrix"
                ));
            }
            let entry = m.iter().flatten().map(count_nodes).max().unwrap_or(1);
            if det_nodes(r, entry) > MAX_NODES {
                return err(format!(
                    "det at {pos} of a {r}x{r} matrix: {}",
                    too_many_nodes(pos)
                ));
            }
            let cols: Vec<usize> = (0..c).collect();
            Val::Scalar(det(&m, 0, &cols, pos))
        }
        "transpose" => Val::Matrix(transposed(&matrix(&vals[0])?)),
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
            let points = &vals[1..];
            if points.iter().any(|(v, _)| matches!(v, Val::Matrix(_)))
                || points.iter().any(|(v, _)| !v.same_shape(&points[0].0))
            {
                return err(format!(
                    "bezier at {pos}: the control points must all be scalars or all vectors of one length"
                ));
            }
            let weights: Vec<Expr> = (0..=n).map(|i| bernstein(i, n, &t, pos)).collect();
            let split: Vec<Vec<&Expr>> = points.iter().map(|(v, _)| v.parts()).collect();
            let comb = |k: usize| {
                plus(
                    split
                        .iter()
                        .zip(&weights)
                        .map(|(xs, w)| {
                            // The weight of a degree-0 curve is 1: the point alone.
                            if matches!(&w.kind, ExprKind::Number(q) if *q == Rational::ONE) {
                                xs[k].clone()
                            } else {
                                times(w.clone(), xs[k].clone(), pos)
                            }
                        })
                        .collect(),
                    pos,
                )
            };
            match &points[0].0 {
                Val::Vector(xs) => Val::Vector((0..xs.len()).map(comb).collect()),
                _ => Val::Scalar(comb(0)),
            }
        }
        other => unreachable!("{other} is in LIBRARY and handled above"),
    })
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

/// Appends the names of the calls in `e` to `out` (each once).
fn collect_calls(e: &Expr, out: &mut Vec<String>) {
    map_tree(e, &mut |x| {
        if let ExprKind::Call(n, _) = &x.kind {
            if !out.contains(n) {
                out.push(n.clone());
            }
        }
    });
}

/// Visits every node of `e` (children first).
fn map_tree(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => {}
        ExprKind::Neg(x) | ExprKind::Sqrt(x) => map_tree(x, f),
        ExprKind::Pow(x, k) => {
            map_tree(x, f);
            map_tree(k, f);
        }
        ExprKind::Sum(ts) => ts.iter().for_each(|(_, t)| map_tree(t, f)),
        ExprKind::Product(fs) => fs.iter().for_each(|(_, t)| map_tree(t, f)),
        ExprKind::Call(_, args) => args.iter().for_each(|a| map_tree(a, f)),
    }
    f(e);
}

/// `e` with every position set to `pos`.
fn at_pos(e: &Expr, pos: usize) -> Expr {
    rebuild(e, &|mut x| {
        x.pos = pos;
        x
    })
}

/// `e` with the variable `v` replaced by `value`.
pub fn substitute(e: &Expr, v: &str, value: &Expr) -> Expr {
    rebuild(e, &|x| match &x.kind {
        ExprKind::Var(n) if n == v => at_pos(value, x.pos),
        _ => x,
    })
}

/// `e` with the free occurrences of the variable `v` replaced by `value`, as `subs` means it:
/// the substitution comes after every construct inside. A `diff` in `v` (or in a variable
/// `value` mentions) is differentiated first, so `subs(diff(E, t), t, 0)` is `E'(0)`; the
/// bound variable of `integrate` and `sum` is not replaced (only the bounds are), and is
/// renamed when `value` mentions it, so that no variable of `value` is captured.
///
/// # Errors
/// The one-line reason when a `diff` to take first cannot be taken exactly.
pub fn substitute_free(e: &Expr, v: &str, value: &Expr) -> Result<Expr, String> {
    let sub = |x: &Expr| substitute_free(x, v, value);
    let boxed = |x: &Expr| sub(x).map(Box::new);
    let mentions = |name: &str| {
        let mut found = false;
        map_tree(value, &mut |x| {
            found |= matches!(&x.kind, ExprKind::Var(n) if n == name);
        });
        found
    };
    let kind = match &e.kind {
        ExprKind::Var(n) if n == v => return Ok(at_pos(value, e.pos)),
        ExprKind::Number(_) | ExprKind::Var(_) => return Ok(e.clone()),
        ExprKind::Neg(x) => ExprKind::Neg(boxed(x)?),
        ExprKind::Sqrt(x) => ExprKind::Sqrt(boxed(x)?),
        ExprKind::Pow(a, b) => ExprKind::Pow(boxed(a)?, boxed(b)?),
        ExprKind::Sum(ts) => ExprKind::Sum(
            ts.iter()
                .map(|(op, t)| Ok((*op, sub(t)?)))
                .collect::<Result<_, String>>()?,
        ),
        ExprKind::Product(fs) => ExprKind::Product(
            fs.iter()
                .map(|(op, f)| Ok((*op, sub(f)?)))
                .collect::<Result<_, String>>()?,
        ),
        ExprKind::Call(name, args) => {
            let var_at = |i: usize| match args.get(i).map(|a| &a.kind) {
                Some(ExprKind::Var(n)) => Some(n.as_str()),
                _ => None,
            };
            // (argument index of the variable, indices of the arguments where it is bound).
            let binder: Option<(usize, &[usize])> = match (name.as_str(), args.len()) {
                ("diff", 2 | 3) => Some((1, &[0, 1])),
                ("integrate", 4) => Some((1, &[0, 1])),
                ("sum", 4) => Some((0, &[0, 3])),
                _ => None,
            };
            match binder.and_then(|(i, bound)| Some((var_at(i)?, bound))) {
                Some((t, _)) if name == "diff" && (t == v || mentions(t)) => {
                    return sub(&derivative_first(e)?);
                }
                Some((t, bound)) if t == v || mentions(t) => {
                    // Only the bounds see the substitution; the bound variable is renamed
                    // apart from `value` (and from `v`) when `value` mentions it.
                    let args = if t == v || !mentions(t) {
                        args.clone()
                    } else {
                        let fresh = fresh_name(t, e, value);
                        let renamed = Expr {
                            kind: ExprKind::Var(fresh),
                            pos: e.pos,
                        };
                        args.iter()
                            .enumerate()
                            .map(|(j, a)| {
                                if bound.contains(&j) {
                                    substitute(a, t, &renamed)
                                } else {
                                    a.clone()
                                }
                            })
                            .collect()
                    };
                    let keep_bound = t == v;
                    ExprKind::Call(
                        name.clone(),
                        args.iter()
                            .enumerate()
                            .map(|(j, a)| {
                                if keep_bound && bound.contains(&j) {
                                    Ok(a.clone())
                                } else {
                                    sub(a)
                                }
                            })
                            .collect::<Result<_, String>>()?,
                    )
                }
                Some((_, _)) if name == "diff" => ExprKind::Call(
                    name.clone(),
                    args.iter()
                        .enumerate()
                        .map(|(j, a)| if j == 1 { Ok(a.clone()) } else { sub(a) })
                        .collect::<Result<_, String>>()?,
                ),
                _ => ExprKind::Call(
                    name.clone(),
                    args.iter().map(sub).collect::<Result<_, String>>()?,
                ),
            }
        }
    };
    Ok(Expr { kind, pos: e.pos })
}

/// A variable name based on `base` that occurs in neither `e` nor `value`.
fn fresh_name(base: &str, e: &Expr, value: &Expr) -> String {
    let mut taken = HashSet::new();
    for tree in [e, value] {
        map_tree(tree, &mut |x| {
            if let ExprKind::Var(n) = &x.kind {
                taken.insert(n.clone());
            }
        });
    }
    (1..)
        .map(|k| format!("{base}{k}"))
        .find(|n| !taken.contains(n))
        .expect("a finite tree leaves some name free")
}

/// The call `diff(E, t[, k])` taken: the derivative as an expression (numerator over
/// denominator, with rational coefficients), positioned at the call.
fn derivative_first(call: &Expr) -> Result<Expr, String> {
    let mut vars = crate::poly::Vars::new();
    let f = call
        .to_ratfun::<Rational>(&mut vars)
        .map_err(|e| format!("the derivative {call} is taken first, and fails: {e}"))?;
    let text = if exactcheck_core::Ring::is_one(f.denominator()) {
        format!("{}", f.numerator().display(&vars))
    } else {
        format!(
            "({})/({})",
            f.numerator().display(&vars),
            f.denominator().display(&vars)
        )
    };
    let parsed = super::parse_expr(&text)
        .map_err(|e| format!("the derivative {call} is taken first, and fails: {e}"))?;
    Ok(at_pos(&parsed, call.pos))
}

/// Rebuilds `e` bottom-up, handing every rebuilt node (its children done) to `f`.
fn rebuild(e: &Expr, f: &dyn Fn(Expr) -> Expr) -> Expr {
    let b = |x: &Expr| Box::new(rebuild(x, f));
    let kind = match &e.kind {
        ExprKind::Number(_) | ExprKind::Var(_) => e.kind.clone(),
        ExprKind::Neg(x) => ExprKind::Neg(b(x)),
        ExprKind::Sqrt(x) => ExprKind::Sqrt(b(x)),
        ExprKind::Pow(x, k) => ExprKind::Pow(b(x), b(k)),
        ExprKind::Sum(ts) => ExprKind::Sum(ts.iter().map(|(o, t)| (*o, rebuild(t, f))).collect()),
        ExprKind::Product(fs) => {
            ExprKind::Product(fs.iter().map(|(o, t)| (*o, rebuild(t, f))).collect())
        }
        ExprKind::Call(n, args) => {
            ExprKind::Call(n.clone(), args.iter().map(|a| rebuild(a, f)).collect())
        }
    };
    f(Expr { kind, pos: e.pos })
}

/// The number of nodes of a tree.
pub fn count_nodes(e: &Expr) -> usize {
    let mut n = 0;
    map_tree(e, &mut |_| n += 1);
    n
}

/// Whether the tree contains `sqrt` (then the radical coefficient field is needed).
pub fn has_sqrt(e: &Expr) -> bool {
    let mut found = false;
    map_tree(e, &mut |x| found |= matches!(x.kind, ExprKind::Sqrt(_)));
    found
}

/// Parses and resolves a formula with the library functions and no definitions (as `prove`
/// reads its sides).
///
/// # Errors
/// As [`Defs::resolve_text`].
pub fn resolve(text: &str) -> R<Val> {
    Defs::default().resolve_text(text)
}

#[cfg(test)]
#[path = "library_tests.rs"]
mod tests;
