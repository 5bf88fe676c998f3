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
//! (`M*v`, `M*N`), a square matrix has powers `M^k` (a non-negative integer constant `k`, within
//! the `matrix-power` limit); a product written `\cdot` ([`MulOp::Dot`]) of two vectors is their
//! dot product, one written `\times` ([`MulOp::Cross`]) their cross product; a bold name
//! ([`BOLD`]) is the value of its definition (an undefined one is an error), and `|v|` of a
//! vector its length. Everything else about them goes through the functions:
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
//!
//! The submodules: `matrix` builds the trees of sums, products, matrix products and
//! determinants; `products` resolves products and powers as printed (`\cdot`, `\times`, `M^k`,
//! bold names, `|v|`); `calls` computes the library functions (vectors, matrices, Bernstein and
//! Bezier); `tree` walks and rewrites trees (substitution, positions, sizes).

use super::parse::LIST;
use super::{parse_expr_with_calls, AddOp, Expr, ExprKind, MulOp};
use crate::rational::Rational;
use exactcheck_core::limits;
use std::collections::{HashMap, HashSet};
use std::fmt;

mod calls;
mod matrix;
mod products;
mod tree;

use calls::*;
use matrix::*;
use products::absolute;
pub(crate) use tree::map_tree;
pub(crate) use tree::substitute;
use tree::{at_pos, collect_calls};
pub use tree::{count_nodes, diff_against_relations, has_sqrt, substitute_free};

/// The call the LaTeX reader makes of a bold name (`\mathbf{v}`, `\vec{v}`, `\boldsymbol{v}`,
/// `\bm{v}`): `bold(v)` is the vector or matrix `v` is defined as; an undefined bold name is an
/// error, never a scalar variable.
pub const BOLD: &str = "bold";

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
    names.push(BOLD);
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
        self.dims().to_string()
    }

    /// The shape as a value (to compare, or to name components by).
    pub fn dims(&self) -> Shape {
        match self {
            Val::Scalar(_) => Shape::Scalar,
            Val::Vector(v) => Shape::Vector(v.len()),
            Val::Matrix(rows) => Shape::Matrix(rows.len(), rows[0].len()),
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

/// The shape of a [`Val`]: what an identity between two values compares component by component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// One expression.
    Scalar,
    /// A vector of this many coordinates.
    Vector(usize),
    /// A matrix of this many rows and columns.
    Matrix(usize, usize),
}

impl Shape {
    /// The number of components ([`Val::components`] lists them in this order).
    pub fn len(&self) -> usize {
        match *self {
            Shape::Scalar => 1,
            Shape::Vector(n) => n,
            Shape::Matrix(r, c) => r * c,
        }
    }

    /// Whether the shape has no component (never: a vector or matrix has at least one).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The name of component `k` (0-based, in the order of [`Val::components`]):
    /// `component 2 (y)` of a vector of 2 or 3, `component 5` of a longer one, `entry (1, 2)`
    /// of a matrix (row, column, from 1); empty for a scalar.
    pub fn component(&self, k: usize) -> String {
        match *self {
            Shape::Scalar => String::new(),
            Shape::Vector(2 | 3) => format!("component {} ({})", k + 1, ["x", "y", "z"][k]),
            Shape::Vector(_) => format!("component {}", k + 1),
            Shape::Matrix(_, c) => format!("entry ({}, {})", k / c + 1, k % c + 1),
        }
    }
}

impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Shape::Scalar => f.write_str("a scalar"),
            Shape::Vector(n) => write!(f, "a vector of {n}"),
            Shape::Matrix(r, c) => write!(f, "a {r}x{c} matrix"),
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

/// Whether `s` is a name of the expression syntax (`[A-Za-z_][A-Za-z0-9_]*`): letters, digits
/// and `_`, not starting with a digit.
pub fn is_name(s: &str) -> bool {
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
    /// Further function names kept as calls ([`Defs::with_calls`]).
    calls: Vec<&'static str>,
}

impl Defs {
    /// These definitions, with the functions `names` also accepted and kept as calls (their
    /// arguments resolved to scalars), for a front end that evaluates more functions than the
    /// library does (`regress --formula`: `exp`, `log`, `atan2`, ...).
    pub fn with_calls(mut self, names: &[&'static str]) -> Self {
        self.calls.extend_from_slice(names);
        self
    }

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
            ExprKind::Pow(b, k) => self.power(b, k, pos, stack)?,
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
            ExprKind::Product(factors) => self.product(factors, pos, stack)?,
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
        if name == BOLD {
            return self.bold(args, pos, stack);
        }
        if self.is_defined(name) {
            return self.call_defined(name, args, pos, stack);
        }
        if name == super::ABS && args.len() == 1 {
            let v = self.resolve(&args[0], stack)?;
            return absolute(v, args[0].pos, pos);
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
        if super::FUNCTIONS.contains(&name) || self.calls.contains(&name) {
            // A function of the core language: its arguments resolved, the call kept for the
            // conversion, which checks them. The derivative, integral or sum of a vector or
            // matrix is taken component by component (the body is the first argument of `diff`
            // and `integrate`, the fourth of `sum`).
            let body = match name {
                "diff" | "integrate" => Some(0),
                "sum" => Some(3),
                _ => None,
            };
            let mut resolved = Vec::new();
            let mut componentwise = None;
            for (i, a) in args.iter().enumerate() {
                if Some(i) == body {
                    match self.resolve(a, stack)? {
                        Val::Scalar(x) => resolved.push(x),
                        v => {
                            resolved.push(a.clone());
                            componentwise = Some((i, v));
                        }
                    }
                } else {
                    resolved.push(self.scalar(a, stack, &format!("an argument of {name}"))?);
                }
            }
            let call = |args: Vec<Expr>| Expr {
                kind: ExprKind::Call(name.to_string(), args),
                pos,
            };
            return Ok(match componentwise {
                None => Val::Scalar(call(resolved)),
                Some((i, v)) => v.map(|x| {
                    let mut args = resolved.clone();
                    args[i] = x;
                    call(args)
                }),
            });
        }
        let Some(&(_, arity, variadic)) = LIBRARY.iter().find(|(n, _, _)| *n == name) else {
            let mut names = function_names();
            names.push("sqrt");
            names.extend(super::FUNCTIONS);
            names.extend(self.calls.iter().filter(|n| !super::FUNCTIONS.contains(n)));
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

/// Parses and resolves a formula with the library functions and no definitions (as `prove`
/// reads its sides).
///
/// # Errors
/// As [`Defs::resolve_text`].
pub fn resolve(text: &str) -> R<Val> {
    Defs::default().resolve_text(text)
}

#[cfg(test)]
#[path = "../library_tests.rs"]
mod tests;
