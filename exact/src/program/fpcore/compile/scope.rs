//! Scopes: `let` and `let*` (slots, and the substitution of bound values into a condition),
//! and the loops `while` and `while*` (see the parent module's documentation).
use super::super::sexpr::{Pos, SExpr};
use super::{list_items, syntax, unsupported, Compiler, Fail, Value};
use crate::program::{Cond, Loop, Node};

impl Compiler {
    /// `(let ([x e] ...) body)` and `(let* ...)`.
    pub(super) fn let_expr(
        &mut self,
        sequential: bool,
        bindings: &SExpr,
        body: &SExpr,
    ) -> Result<Value, Fail> {
        let Some(list) = list_items(bindings) else {
            return Err(syntax(
                bindings.pos(),
                format!(
                    "expected the bindings `([x e] ...)`, found {}",
                    bindings.describe()
                ),
            ));
        };
        let outer = self.env.len();
        let mut slots: Vec<(usize, Node)> = Vec::new();
        let mut pending: Vec<(String, Value)> = Vec::new();
        for binding in list {
            let (name, value) = match list_items(binding) {
                Some([SExpr::Sym(n, _), v]) => (n, v),
                _ => {
                    return Err(syntax(
                        binding.pos(),
                        format!("expected a binding `[x e]`, found {}", binding.describe()),
                    ))
                }
            };
            if !sequential && pending.iter().any(|(n, _)| n == name) {
                return Err(syntax(
                    binding.pos(),
                    format!("`{name}` is bound twice in one `let`"),
                ));
            }
            let bound = match self.expr(value)? {
                Value::Num(n) => {
                    let s = self.slots;
                    self.slots += 1;
                    slots.push((s, n));
                    Value::Num(Node::Slot(s))
                }
                Value::Bool(c) => Value::Bool(c),
            };
            if sequential {
                self.env.push((name.clone(), bound));
            } else {
                pending.push((name.clone(), bound));
            }
        }
        self.env.extend(pending);
        let result = self.expr(body);
        self.env.truncate(outer);
        Ok(match result? {
            Value::Num(n) if slots.is_empty() => Value::Num(n),
            Value::Num(n) => Value::Num(Node::Let(slots, Box::new(n))),
            // A condition has no `let`: substitute the bound values into it.
            Value::Bool(c) => {
                let mut map: Vec<(usize, Node)> = Vec::new();
                for (s, n) in slots {
                    let n = subst_node(&n, &map);
                    map.push((s, n));
                }
                Value::Bool(subst_cond(&c, &map))
            }
        })
    }

    /// `(while cond ([x init update] ...) body)` and `(while* ...)`: every variable gets a fresh
    /// slot; for `while` the initial values are compiled in the outer scope and the variables
    /// bound together, for `while*` each initial value sees the variables before it. The
    /// condition, the updates and the body see all of them ([`Loop`] evaluates the updates in
    /// the matching order).
    pub(super) fn while_expr(
        &mut self,
        sequential: bool,
        args: &[SExpr],
        pos: Pos,
    ) -> Result<Value, Fail> {
        let op = if sequential { "while*" } else { "while" };
        let [cond, bindings, body] = args else {
            return Err(syntax(
                pos,
                format!(
                    "`{op}` takes a condition, the loop variables `([x init update] ...)` and a \
                     body, found {} argument{}",
                    args.len(),
                    if args.len() == 1 { "" } else { "s" }
                ),
            ));
        };
        let Some(list) = list_items(bindings) else {
            return Err(syntax(
                bindings.pos(),
                format!(
                    "expected the loop variables `([x init update] ...)`, found {}",
                    bindings.describe()
                ),
            ));
        };
        let outer = self.env.len();
        let result = self.loop_parts(sequential, op, list, cond, body);
        self.env.truncate(outer);
        let (vars, cond, body) = result?;
        match body {
            Value::Num(body) => Ok(Value::Num(Node::While(Box::new(Loop {
                sequential,
                vars,
                cond,
                body,
            })))),
            Value::Bool(_) => Err(unsupported(format!("`{op}` with a boolean result"))),
        }
    }

    /// The variables, condition and body of a loop, with the variables left in scope.
    #[allow(clippy::type_complexity)]
    fn loop_parts(
        &mut self,
        sequential: bool,
        op: &str,
        list: &[SExpr],
        cond: &SExpr,
        body: &SExpr,
    ) -> Result<(Vec<(usize, Node, Node)>, Cond, Value), Fail> {
        let mut vars: Vec<(usize, Node, &SExpr)> = Vec::new();
        let mut names: Vec<&str> = Vec::new();
        let mut pending: Vec<(String, Value)> = Vec::new();
        for binding in list {
            let (name, init, update) = match list_items(binding) {
                Some([SExpr::Sym(n, _), i, u]) => (n, i, u),
                _ => {
                    return Err(syntax(
                        binding.pos(),
                        format!(
                            "expected a loop variable `[x init update]`, found {}",
                            binding.describe()
                        ),
                    ))
                }
            };
            if names.contains(&name.as_str()) {
                return Err(syntax(
                    binding.pos(),
                    format!("`{name}` is bound twice in one `{op}`"),
                ));
            }
            names.push(name);
            let init = match self.expr(init)? {
                Value::Num(n) => n,
                Value::Bool(_) => {
                    return Err(unsupported(format!("a boolean loop variable of `{op}`")))
                }
            };
            let s = self.slots;
            self.slots += 1;
            let bound = (name.clone(), Value::Num(Node::Slot(s)));
            if sequential {
                self.env.push(bound);
            } else {
                pending.push(bound);
            }
            vars.push((s, init, update));
        }
        self.env.extend(pending);
        let cond = self.cond(cond)?;
        let mut out = Vec::with_capacity(vars.len());
        for (s, init, update) in vars {
            let update = self.num(update)?;
            out.push((s, init, update));
        }
        let body = self.expr(body)?;
        Ok((out, cond, body))
    }
}

/// `n` with every `Slot(s)` of `map` replaced by its node.
fn subst_node(n: &Node, map: &[(usize, Node)]) -> Node {
    let b = |x: &Node| Box::new(subst_node(x, map));
    match n {
        Node::Slot(s) => map
            .iter()
            .find(|(t, _)| t == s)
            .map_or_else(|| n.clone(), |(_, v)| v.clone()),
        Node::Input(_) | Node::Const(_) => n.clone(),
        Node::Neg(a) => Node::Neg(b(a)),
        Node::Add(x, y) => Node::Add(b(x), b(y)),
        Node::Sub(x, y) => Node::Sub(b(x), b(y)),
        Node::Mul(x, y) => Node::Mul(b(x), b(y)),
        Node::Div(x, y) => Node::Div(b(x), b(y)),
        Node::Chain(x, rest) => Node::Chain(
            b(x),
            rest.iter()
                .map(|(op, y)| (*op, subst_node(y, map)))
                .collect(),
        ),
        Node::Sqrt(a) => Node::Sqrt(b(a)),
        Node::Abs(a) => Node::Abs(b(a)),
        Node::Fma(x, y, z) => Node::Fma(b(x), b(y), b(z)),
        Node::Min(x, y) => Node::Min(b(x), b(y)),
        Node::Max(x, y) => Node::Max(b(x), b(y)),
        Node::Pow(a, k, style) => Node::Pow(b(a), *k, *style),
        Node::Let(bs, body) => Node::Let(
            bs.iter().map(|(s, v)| (*s, subst_node(v, map))).collect(),
            b(body),
        ),
        Node::If(c, x, y) => Node::If(Box::new(subst_cond(c, map)), b(x), b(y)),
        Node::Fun(f, args) => Node::Fun(*f, args.iter().map(|a| subst_node(a, map)).collect()),
        Node::While(l) => Node::While(Box::new(Loop {
            sequential: l.sequential,
            vars: l
                .vars
                .iter()
                .map(|(s, init, update)| (*s, subst_node(init, map), subst_node(update, map)))
                .collect(),
            cond: subst_cond(&l.cond, map),
            body: subst_node(&l.body, map),
        })),
        Node::Precision(f, a) => Node::Precision(*f, b(a)),
        Node::Cast(a) => Node::Cast(b(a)),
    }
}

/// `c` with every `Slot(s)` of `map` replaced by its node.
fn subst_cond(c: &Cond, map: &[(usize, Node)]) -> Cond {
    match c {
        Cond::Bool(v) => Cond::Bool(*v),
        Cond::Cmp(op, x, y) => Cond::Cmp(*op, subst_node(x, map), subst_node(y, map)),
        Cond::And(cs) => Cond::And(cs.iter().map(|c| subst_cond(c, map)).collect()),
        Cond::Or(cs) => Cond::Or(cs.iter().map(|c| subst_cond(c, map)).collect()),
        Cond::Not(c) => Cond::Not(Box::new(subst_cond(c, map))),
    }
}
