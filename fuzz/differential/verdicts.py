#!/usr/bin/env python3
"""Differential verdict tester for `exactcheck prove`.

Generates identities in exactcheck's formula language together with their meaning as SymPy
expressions, true ones by valid rewrites (expand, factor, fractions combined, trigonometric
expansion, closed forms of sums and integrals computed by SymPy, ...) and false ones by small
perturbations, runs `exactcheck prove` exactly and with `--random 20` on each, and compares the
verdicts with the ground truth: LHS - RHS evaluated with mpmath at 50 digits at random points of
the region the identity speaks about (the relations solved, the domains respected, points where a
square root is not real or a divisor vanishes skipped).

Flagged (each finding is one JSON line in the output file and a line on standard output):

* `proved`/`holds` for an identity that is numerically false;
* `fails` for an identity that is numerically true;
* a counter-example where LHS - RHS evaluates to ~0, or to a value other than the one printed;
* a panic (exit status 101 or "panicked" on standard error), an exit status other than 0, 1, 2;
* exact and `--random` verdicts that contradict each other (proved vs fails, fails vs holds).

Errors (exit 2) are counted by message and listed at the end; they are not findings.

Run with the anchors virtual environment (SymPy + mpmath):

    .venv-anchors/bin/python fuzz/differential/verdicts.py --count 200 --seed 1
"""

import argparse
import collections
import json
import os
import random
import re
import signal
import subprocess
import sys
import time

import mpmath as mp
import sympy as sp

mp.mp.dps = 50

VARS = sp.symbols("x y z t a b u v w")
X, Y, Z, T, A, B, U, V, W = VARS
ALLOWED_NAMES = {"sqrt", "sin", "cos", "tan", "pi"}


class Skip(Exception):
    """The generator produced something outside the language; draw another case."""


class SlowSympy(Exception):
    """SymPy took too long to build or evaluate a case; draw another."""


def _alarm(signum, frame):
    raise SlowSympy()


# ----------------------------------------------------------------------------------------------
# Printing SymPy expressions in exactcheck's language


def ec(expr):
    """SymPy expression -> exactcheck text (explicit `*`, `^`)."""
    if isinstance(expr, (list, tuple)):
        return "[" + ", ".join(ec(e) for e in expr) + "]"
    s = sp.sstr(expr)
    s = s.replace("**", "^")
    names = set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", s))
    allowed = ALLOWED_NAMES | {str(v) for v in VARS} | {"c", "s", "k", "j", "n", "r", "p", "q"}
    bad = names - allowed
    if bad:
        raise Skip("unsupported name(s) %s in %s" % (sorted(bad), s))
    if "zoo" in s or "nan" in s or "oo" in names:
        raise Skip("infinite value")
    return s


def juxtapose(text, rng):
    """Rewrite some `*` as juxtaposition where the language allows it (not before a digit or a
    parenthesis, not inside function names)."""
    out = []
    for i, ch in enumerate(text):
        if (
            ch == "*"
            and 0 < i < len(text) - 1
            and text[i + 1].isalpha()
            and (text[i - 1].isalnum() or text[i - 1] == ")")
            and rng.random() < 0.5
        ):
            out.append(" ")
        else:
            out.append(ch)
    return "".join(out)


# ----------------------------------------------------------------------------------------------
# Random building blocks


def rat(rng, big=False):
    if rng.random() < 0.7:
        return sp.Integer(rng.randint(-9 if not big else -99, 9 if not big else 99))
    return sp.Rational(rng.randint(-9, 9), rng.randint(2, 7))


def nonzero_rat(rng):
    r = rat(rng)
    return r if r != 0 else sp.Integer(rng.choice([1, -1, 2, 3]))


def poly(rng, vs, depth=2):
    """A random polynomial expression, written unexpanded."""
    if depth <= 0 or rng.random() < 0.25:
        if rng.random() < 0.6:
            return rng.choice(vs) * (nonzero_rat(rng) if rng.random() < 0.4 else 1)
        return nonzero_rat(rng)
    kind = rng.random()
    if kind < 0.4:
        return sp.Add(*[poly(rng, vs, depth - 1) for _ in range(rng.randint(2, 3))])
    if kind < 0.8:
        return sp.Mul(*[poly(rng, vs, depth - 1) for _ in range(2)])
    return sp.Pow(sp.Add(poly(rng, vs, depth - 1), poly(rng, vs, 0)), rng.randint(2, 3))


def linear(rng, vs):
    return sp.Add(*[nonzero_rat(rng) * v for v in vs]) + rat(rng)


def sample_real(rng):
    """A random real, as an exact rational: mostly moderate, sometimes small or large."""
    k = rng.random()
    if k < 0.15:
        return sp.Integer(rng.randint(-3, 3))
    if k < 0.3:
        return sp.Rational(rng.randint(-20, 20), rng.randint(1, 9))
    return sp.Rational(rng.randint(-10**6, 10**6), 10**5 + rng.randint(0, 999))


# ----------------------------------------------------------------------------------------------
# Cases


class Case:
    """One identity: the text given to exactcheck and its meaning.

    `L`, `R` are SymPy expressions (or lists of them for vectors); `where` the `--where`
    arguments; `sample(rng)` a point of the region (a dict symbol -> exact value) or None;
    `ok(point)` whether the point lies in the region's domains; `random_ok` whether `--random`
    takes the case; `intended` whether the case was built true."""

    def __init__(self, kind, lhs, rhs, L, R, intended, where=(), sample=None, random_ok=True, angles=()):
        self.kind = kind
        self.lhs = lhs
        self.rhs = rhs
        self.L = L
        self.R = R
        self.intended = intended
        self.where = list(where)
        self.sample = sample
        self.random_ok = random_ok
        self.angles = set(angles)

    def args(self):
        a = ["prove", self.lhs, self.rhs]
        for w in self.where:
            a += ["--where", w]
        return a

    def diff_expr(self):
        if isinstance(self.L, (list, tuple)):
            return [l - r for l, r in zip(self.L, self.R)]
        return [self.L - self.R]


def free_syms(exprs):
    s = set()
    for e in exprs:
        s |= e.free_symbols
    return sorted(s, key=str)


def case_syms(case):
    sides = []
    for side in (case.L, case.R):
        sides += list(side) if isinstance(side, (list, tuple)) else [side]
    return free_syms(sides)


def default_sampler(syms):
    def sample(rng):
        return {v: sample_real(rng) for v in syms}

    return sample


def perturb(rng, R, syms, angles=()):
    """A small change of RHS: a term added, a coefficient changed or a sign flipped. With angle
    variables the term added is a sine or cosine of one, so that the sides stay trigonometric."""
    k = rng.random()
    if k < 0.4 or not syms:
        term = nonzero_rat(rng)
        for _ in range(rng.randint(0, 2)):
            if angles:
                term *= rng.choice([sp.sin, sp.cos])(rng.choice(list(angles)))
            elif syms:
                term *= rng.choice(syms)
        return R + term
    if k < 0.7:
        terms = sp.Add.make_args(sp.expand(R))
        if len(terms) >= 2:
            i = rng.randrange(len(terms))
            return sp.Add(*[(-t if j == i else t) for j, t in enumerate(terms)])
        return R + 1
    return R * sp.Rational(rng.choice([2, 3, -1, 5]), rng.choice([1, 2, 3]))


def finish(rng, kind, Lexpr_text, L, R, true, where=(), sample=None, random_ok=True, angles=(), rhs_text=None):
    """Make a case true as built or perturb RHS to make a false one."""
    syms = free_syms([L] if not isinstance(L, list) else L)
    if not true:
        if isinstance(R, list):
            i = rng.randrange(len(R))
            R = list(R)
            R[i] = perturb(rng, R[i], syms, angles)
        else:
            R = perturb(rng, R, syms, angles)
        rhs_text = None
    if rhs_text is None:
        rhs_text = ec(R)
    if sample is None:
        sample = default_sampler(free_syms((L if isinstance(L, list) else [L]) + (R if isinstance(R, list) else [R])))
    if rng.random() < 0.3:
        Lexpr_text = juxtapose(Lexpr_text, rng)
    return Case(kind, Lexpr_text, rhs_text, L, R, true, where, sample, random_ok, angles)


# -- generators: each returns a Case


def gen_poly(rng, true):
    vs = rng.sample([X, Y, Z, A, B], rng.randint(1, 3))
    L = poly(rng, vs, 3)
    R = rng.choice([sp.expand, sp.factor, lambda e: sp.horner(sp.expand(e)), lambda e: sp.collect(sp.expand(e), vs[0])])(L)
    return finish(rng, "poly", ec(L), L, R, true)


def gen_fraction(rng, true):
    vs = rng.sample([X, Y, T], rng.randint(1, 2))
    parts = []
    for _ in range(rng.randint(2, 3)):
        num = poly(rng, vs, 1)
        den = poly(rng, vs, 1)
        if sp.expand(den).is_number:
            den = den + vs[0]
        parts.append(num / den)
    L = sp.Add(*parts, evaluate=False)
    if sp.simplify(L) == 0:
        raise Skip("zero")
    rw = rng.choice(["together", "cancel", "apart", "factor"])
    if rw == "together":
        R = sp.together(L)
    elif rw == "cancel":
        R = sp.cancel(L)
    elif rw == "apart":
        R = sp.apart(sp.cancel(L), vs[0])
    else:
        R = sp.factor(sp.cancel(L))
    text = " + ".join("(%s)/(%s)" % (ec(sp.fraction(p)[0]), ec(sp.fraction(p)[1])) for p in parts)
    return finish(rng, "fraction", text, L, R, true)


def angle(rng, avs, const_ok=True):
    a = sp.Integer(0)
    for v in avs:
        if rng.random() < 0.8:
            a += rng.choice([1, 1, 1, 2, 3, -1, -2]) * v
    q = rng.choice([1, 2, 3, 4, 6, 12, 5, 8, 7, 10])
    p = rng.randint(-q, 2 * q)
    if rng.random() < 0.5 or a == 0:
        a += sp.Rational(p, q) * sp.pi
    if a == 0 or (not const_ok and not a.free_symbols):
        a = avs[0]
    return a


def trig_poly(rng, avs, depth=2, tan_ok=True):
    if depth <= 0 or rng.random() < 0.3:
        f = rng.choice([sp.sin, sp.cos, sp.cos, sp.sin] + ([sp.tan] if tan_ok else []))
        e = f(angle(rng, avs))
        if rng.random() < 0.3:
            e = e ** rng.randint(2, 3)
        return e * (nonzero_rat(rng) if rng.random() < 0.3 else 1)
    if rng.random() < 0.5:
        return sp.Add(*[trig_poly(rng, avs, depth - 1, tan_ok) for _ in range(2)])
    return sp.Mul(*[trig_poly(rng, avs, depth - 1, tan_ok) for _ in range(2)])


def gen_trig(rng, true):
    avs = rng.sample([X, Y], rng.randint(1, 2))
    L = trig_poly(rng, avs, 2, tan_ok=rng.random() < 0.3)
    rw = rng.choice(["expand_trig", "TR8", "TR10", "expand_trig"])
    if rw == "expand_trig":
        R = sp.expand(sp.expand_trig(L))
    elif rw == "TR8":
        from sympy.simplify.fu import TR8

        R = TR8(L)
    else:
        from sympy.simplify.fu import TR10

        R = TR10(L)
    if any(isinstance(f, sp.Function) and f.func not in (sp.sin, sp.cos, sp.tan) for f in sp.preorder_traversal(R)):
        raise Skip("other function")
    return finish(rng, "trig", ec(L), L, R, true, angles=avs)


def gen_trig_const(rng, true):
    """Identities between constants: cos/sin/tan of rational multiples of pi, nested radicals."""
    k = rng.random()
    if k < 0.5:
        q = rng.choice([5, 7, 8, 9, 10, 12, 15, 16, 24])
        p1, p2 = rng.randint(1, 2 * q), rng.randint(1, 2 * q)
        a1, a2 = sp.pi * sp.Rational(p1, q), sp.pi * sp.Rational(p2, q)
        pick = rng.choice(["prod", "double", "square", "sum"])
        if pick == "prod":
            L = sp.cos(a1) * sp.cos(a2)
            R = (sp.cos(a1 - a2) + sp.cos(a1 + a2)) / 2
            lt = "cos(%s)*cos(%s)" % (ec(a1), ec(a2))
        elif pick == "double":
            L = sp.cos(2 * a1)
            R = 2 * sp.cos(a1) ** 2 - 1
            lt = "cos(%s)" % ec(2 * a1)
        elif pick == "square":
            L = sp.sin(a1) ** 2 + sp.cos(a2) ** 2
            R = 1 - sp.cos(a1) ** 2 + sp.cos(a2) ** 2
            lt = "sin(%s)^2 + cos(%s)^2" % (ec(a1), ec(a2))
        else:
            n = rng.choice([5, 7, 9])
            L = sp.Add(*[sp.cos(2 * sp.pi * j / n) for j in range(1, (n - 1) // 2 + 1)])
            R = sp.Rational(-1, 2)
            lt = " + ".join("cos(%s)" % ec(2 * sp.pi * j / n) for j in range(1, (n - 1) // 2 + 1))
        if rng.random() < 0.5:
            x = rng.choice([X, T])
            L, R = x * L, x * R
            lt = "%s*(%s)" % (x, lt)
        return finish(rng, "trig_const", lt, L, R, true)
    # nested radicals: sqrt((p + q sqrt(r))^2) = |p + q sqrt(r)|, products of conjugates
    p, q, r = rng.randint(-5, 5), rng.randint(1, 4), rng.choice([2, 3, 5, 6, 7])
    inner = sp.expand((p + q * sp.sqrt(r)) ** 2)
    pick = rng.random()
    if pick < 0.4:
        L = sp.sqrt(inner, evaluate=False)
        R = abs(p + q * sp.sqrt(r))
        lt = "sqrt(%s)" % ec(inner)
        rt = ec(sp.nsimplify(R))
    else:
        a, b = rng.randint(2, 9), rng.randint(1, 3)
        r2 = rng.choice([2, 3, 5])
        if a * a - b * b * r2 < 0:
            a = b * 3
        L = sp.sqrt(a + b * sp.sqrt(r2)) * sp.sqrt(a - b * sp.sqrt(r2))
        R = sp.sqrt(a * a - b * b * r2)
        lt = "sqrt(%d + %d*sqrt(%d))*sqrt(%d - %d*sqrt(%d))" % (a, b, r2, a, b, r2)
        rt = ec(R)
    if rng.random() < 0.4:
        lt = "x*(%s) + y" % lt
        L, R = X * L + Y, X * R + Y
        rt = None
    return finish(rng, "radical", lt, L, R, true, rhs_text=rt)


def gen_diff(rng, true):
    vs = [T] + rng.sample([X, A], rng.randint(0, 1))
    k = rng.random()
    if k < 0.35:
        E = poly(rng, vs, 2) / (poly(rng, vs, 1) + T)
    elif k < 0.6:
        E = trig_poly(rng, [T], 1, tan_ok=False) * poly(rng, vs, 1)
    elif k < 0.85:
        E = sp.sqrt(sp.expand(poly(rng, vs, 1) ** 2 + rng.randint(1, 4))) * poly(rng, vs, 1)
    else:
        E = poly(rng, vs, 3)
    order = rng.choice([1, 1, 1, 2])
    D = sp.diff(E, T, order)
    R = rng.choice([lambda e: e, sp.together, sp.cancel])(D)
    lt = "diff(%s, t)" % ec(E) if order == 1 else "diff(%s, t, %d)" % (ec(E), order)
    return finish(rng, "diff", lt, D, R, true)


def gen_integrate(rng, true):
    vs = rng.sample([X, A], rng.randint(0, 2))
    if rng.random() < 0.6:
        E = poly(rng, [T] + vs, 2)
        bounds = [rng.choice([sp.Integer(0), sp.Integer(1), sp.Rational(-1, 2), X, A + 1, X * X, 2 * X])
                  for _ in range(2)]
    else:
        E = trig_poly(rng, [T], 1, tan_ok=False) * rng.choice([1, T, T * T, sp.Integer(2), A])
        bounds = [rng.choice([sp.Integer(0), sp.pi, sp.pi / 2, sp.pi / 3, 2 * sp.pi, X, sp.pi / 4, -sp.pi / 6, X + sp.pi / 3])
                  for _ in range(2)]
    I = sp.integrate(E, (T, bounds[0], bounds[1]))
    R = sp.expand(I)
    lt = "integrate(%s, t, %s, %s)" % (ec(E), ec(bounds[0]), ec(bounds[1]))
    angles = [X] if any(b.has(sp.pi) for b in bounds) or E.has(sp.sin, sp.cos) else []
    return finish(rng, "integrate", lt, I, R, true, angles=angles)


def gen_sum(rng, true):
    k = sp.Symbol("k")
    n = rng.randint(0, 8)
    lo = rng.randint(-2, 2)
    pick = rng.random()
    if pick < 0.4:
        E = poly(rng, [k, X], 2)
    elif pick < 0.7:
        E = sp.binomial(n, k) * X ** k * (1 - X) ** (n - k)
        lo = 0
    else:
        E = sp.binomial(n, k) * k ** rng.randint(0, 2) * X ** k
    S = sp.summation(E, (k, lo, n))
    R = rng.choice([sp.expand, sp.factor])(S)
    body = ec(E).replace("binomial(%d, k)" % n, "binomial(%d, k)" % n)
    lt = "sum(k, %d, %d, %s)" % (lo, n, body)
    if rng.random() < 0.3:
        lt = "%s + binomial(%d, %d) - factorial(%d)/(factorial(%d)*factorial(%d))" % (lt, n + 2, 2, n + 2, 2, n)
    return finish(rng, "sum", lt, S, R, true)


def gen_det(rng, true):
    m = rng.choice([2, 2, 3])
    vs = rng.sample([X, Y, A, B, U, V], 3)
    M = sp.Matrix(m, m, lambda i, j: poly(rng, vs, 1) if rng.random() < 0.7 else rat(rng))
    pick = rng.random()
    if pick < 0.6:
        L = M.det(method="berkowitz")
        R = rng.choice([sp.expand, sp.factor])(L)
        lt = "det(%s)" % ec(M.tolist())
    else:
        N = sp.Matrix(m, m, lambda i, j: rat(rng) if rng.random() < 0.5 else rng.choice(vs))
        L = (M * N).det(method="berkowitz")
        R = sp.expand(M.det(method="berkowitz") * N.det(method="berkowitz"))
        lt = "det(%s*%s)" % (ec(M.tolist()), ec(N.tolist()))
    return finish(rng, "det", lt, L, R, true)


def gen_vector(rng, true):
    vs = rng.sample([X, Y, A, B, U, V], 3)
    n = rng.choice([2, 3])
    p = [poly(rng, vs, 1) for _ in range(n)]
    q = [poly(rng, vs, 1) for _ in range(n)]
    pick = rng.random()
    if pick < 0.3:
        L = sum(a * b for a, b in zip(p, q))
        lt = "dot(%s, %s)" % (ec(p), ec(q))
    elif pick < 0.5:
        L = sum(a * a for a in p)
        lt = "norm2(%s)" % ec(p)
    elif pick < 0.8:
        if n == 3:
            L = list(sp.Matrix(p).cross(sp.Matrix(q)))
        else:
            L = p[0] * q[1] - p[1] * q[0]
        lt = "cross(%s, %s)" % (ec(p), ec(q))
    else:
        i = rng.randint(1, n)
        L = p[i - 1] + sp.expand(q[0]).subs(vs[0], vs[1] ** 2)
        lt = "at(%s, %d) + subs(%s, %s, %s^2)" % (ec(p), i, ec(q[0]), vs[0], vs[1])
    R = [sp.expand(e) for e in L] if isinstance(L, list) else sp.expand(L)
    return finish(rng, "vector", lt, L, R, true)


def gen_where_power(rng, true):
    """A relation x^2 = r with r not a square; RHS is LHS reduced modulo it."""
    r = rng.choice([2, 3, 5, 7, sp.Rational(1, 2), sp.Rational(5, 4)])
    vs = [X] + rng.sample([Y, A], rng.randint(0, 1))
    L = poly(rng, vs, 3)
    R = sp.rem(sp.expand(L), X ** 2 - r, X)
    roots = [sp.sqrt(r), -sp.sqrt(r)]

    others = [v for v in vs if v != X]

    def sample(rg):
        p = {v: sample_real(rg) for v in others}
        p[X] = rg.choice(roots)
        return p

    return finish(rng, "where_power", ec(L), L, R, true, where=["x^2 = %s" % ec(r)], sample=sample, random_ok=False)


def gen_where_circle(rng, true):
    c, s = sp.symbols("c s")
    L = poly(rng, [c, s, X], 2) * (c ** 2 + s ** 2) ** rng.randint(1, 2) + poly(rng, [c, s], 2)
    R = sp.expand(L.subs(c ** 2 + s ** 2, 1).subs(s ** 2, 1 - c ** 2))
    R = sp.expand(L).subs(s ** 2, 1 - c ** 2)
    R = sp.expand(sp.expand(R).subs(s ** 2, 1 - c ** 2))

    def sample(rg):
        th = sample_real(rg)
        return {c: sp.cos(th), s: sp.sin(th), X: sample_real(rg)}

    return finish(rng, "where_circle", ec(L), L, R, true, where=["c^2 + s^2 = 1"], sample=sample, random_ok=True)


def gen_where_subst(rng, true):
    """A relation y = P(x): RHS has y replaced."""
    P = poly(rng, [X], 2)
    L = poly(rng, [X, Y], 2)
    R = sp.expand(L.subs(Y, P))

    def sample(rg):
        x = sample_real(rg)
        return {X: x, Y: P.subs(X, x)}

    return finish(rng, "where_subst", ec(L), L, R, true, where=["y = %s" % ec(P)], sample=sample, random_ok=False)


def gen_hypothesis(rng, true):
    """w*X = w*P with w != 0: X = P."""
    P = poly(rng, [X, Y], 2)
    Q = sp.Symbol("u")

    def sample(rg):
        p = {X: sample_real(rg), Y: sample_real(rg), W: sample_real(rg) or sp.Integer(1)}
        p[Q] = P.subs(p)
        return p

    return finish(rng, "hypothesis", "u", Q, P, true, where=["w*u = w*(%s)" % ec(P), "w != 0"], sample=sample, random_ok=False)


def gen_domain(rng, true):
    """Square roots whose branch needs a domain: sqrt((x + c)^2) = x + c for x >= -c, and
    products of roots of non-negative variables."""
    c = rng.randint(-3, 3)
    pick = rng.random()
    if pick < 0.4:
        inner = sp.expand((X + c) ** 2 * rng.choice([1, 4, Y ** 2]))
        L = sp.sqrt(inner)
        R = (X + c) * (2 if inner.has(4) and not inner.has(Y) else 1)
        if inner.has(Y):
            R = (X + c) * Y
        lo = -c
        where = ["x >= %d" % lo] + (["y > 0"] if inner.has(Y) else [])
        lt = "sqrt(%s)" % ec(inner)

        def ok(p):
            return p[X] >= lo and (Y not in p or p[Y] > 0)

    elif pick < 0.7:
        L = sp.sqrt(X) * sp.sqrt(Y)
        R = sp.sqrt(sp.expand(X * Y))
        where = ["x >= 0", "y >= 0"]
        lt = "sqrt(x)*sqrt(y)"

        def ok(p):
            return p[X] >= 0 and p[Y] >= 0

    else:
        e = rng.choice([1, 3])
        inner = sp.expand(1 + X ** 2)
        L = sp.Pow(inner, sp.Rational(e, 2))
        R = inner ** ((e - 1) // 2) * sp.sqrt(inner)
        where = []
        lt = "(%s)^(%d/2)" % (ec(inner), e)

        def ok(p):
            return True

    def sample(rg):
        for _ in range(50):
            p = {X: sample_real(rg), Y: abs(sample_real(rg))}
            if ok(p):
                return p
        return None

    return finish(rng, "domain", lt, L, R, true, where=where, sample=sample, random_ok=False)


def gen_sqrt_expr(rng, true):
    """sqrt(E)^2 = E and derivatives of roots, defined where E >= 0."""
    E = sp.expand(poly(rng, [X, Y], 1) ** 2 + poly(rng, [X], 1) ** 2 + rng.randint(0, 2))
    pick = rng.random()
    if pick < 0.5:
        L = sp.sqrt(E) ** 2 * X + sp.sqrt(E) * (X - X)
        lt = "sqrt(%s)^2*x" % ec(E)
        R = E * X
    else:
        L = sp.diff(sp.sqrt(E), X)
        lt = "diff(sqrt(%s), x)" % ec(E)
        R = sp.diff(E, X) / (2 * sp.sqrt(E))
    return finish(rng, "sqrt_expr", lt, L, R, true, random_ok=False)


def gen_pole(rng, true):
    """Fractions with cancelling factors, and differences that vanish at the small rationals a
    counter-example search tries first (poles and zeros at 0, 1, -1, 1/2, 2, ...)."""
    small = [0, 1, -1, sp.Rational(1, 2), 2, sp.Rational(-1, 2), -2, sp.Rational(1, 3), 3]
    zs = rng.sample(small, rng.randint(1, 5))
    ps = rng.sample(small, rng.randint(1, 3))
    x = rng.choice([X, T])
    Z = sp.Mul(*[(x - r) for r in zs])
    P = sp.Mul(*[(x - r) for r in ps])
    base = poly(rng, [x], 2)
    pick = rng.random()
    if pick < 0.5:
        # (base * P) / P = base, written with the divisor expanded
        L = sp.expand(base * P) / sp.expand(P)
        lt = "(%s)/(%s)" % (ec(sp.expand(base * P)), ec(sp.expand(P)))
        R = base
        if not true:
            R = base + Z / sp.expand(P) * nonzero_rat(rng)
            return finish(rng, "pole", lt, L, R, True, rhs_text=ec(R))
        return finish(rng, "pole", lt, L, R, True)
    # base + Z/P vs base: false, LHS - RHS = Z/P vanishes at the zeros, is undefined at the poles
    L = base + Z / P
    lt = ec(base) + " + (" + ec(sp.expand(Z)) + ")/(" + ec(sp.expand(P)) + ")"
    R = base if not true else sp.cancel(L)
    return finish(rng, "pole", lt, L, R, True, rhs_text=ec(R))


def gen_syntax(rng, true):
    """One polynomial written in the language's other spellings: decimals and scientific
    notation for fractions, degrees, x^(1/2) for roots, negative exponents, juxtaposition."""
    vs = rng.sample([X, Y, A], 2)
    c1, c2 = sp.Rational(rng.randint(-99, 99), rng.choice([2, 4, 5, 8, 10, 20, 25, 100])), rng.randint(1, 5)
    dec = str(float(c1)) if rng.random() < 0.5 else "%se%d" % (str(float(c1 * 10)), -1)
    deg = rng.choice([30, 45, 60, 90, 120, 135, 150, 180, 270])
    pieces = [
        (dec + " " + str(vs[0]), c1 * vs[0]),
        ("%s^-%d" % (vs[1], c2), vs[1] ** -c2),
        ("cos(%d°)" % deg, sp.cos(sp.pi * deg / 180)),
        ("%s^(1/2)" % vs[0], sp.sqrt(vs[0])),
        ("(%s + 1)(%s - 1)" % (vs[0], vs[0]), (vs[0] + 1) * (vs[0] - 1)),
        ("2^3^%d" % c2, sp.Integer(2) ** (3 ** c2)),
        ("%s^2 %s" % (vs[0], vs[1]), vs[0] ** 2 * vs[1]),
        ("-%s^2" % vs[1], -vs[1] ** 2),
        ("2 sqrt(2) %s" % vs[1], 2 * sp.sqrt(2) * vs[1]),
        ("1E+1*%s" % vs[0], 10 * vs[0]),
    ]
    chosen = rng.sample(pieces, rng.randint(2, 4))
    lt = " + ".join("(%s)" % t for t, _ in chosen)
    L = sp.Add(*[e for _, e in chosen])
    R = sp.expand(L)
    where = ["%s > 0" % vs[0]] if L.has(sp.sqrt(vs[0])) else []

    def sample(rg):
        p = {v: sample_real(rg) for v in vs}
        if where:
            p[vs[0]] = abs(p[vs[0]]) + sp.Rational(1, 7)
        return p

    return finish(rng, "syntax", lt, L, R, true, where=where, sample=sample, random_ok=not where)


def gen_tan(rng, true):
    """tan: double angle, addition, shifts by pi/4, and constants such as tan(pi/12)."""
    pick = rng.random()
    a = angle(rng, [X], const_ok=False)
    b = angle(rng, [Y] if rng.random() < 0.5 else [X, Y])
    if pick < 0.3:
        L = sp.tan(2 * a)
        R = 2 * sp.tan(a) / (1 - sp.tan(a) ** 2)
    elif pick < 0.6:
        L = sp.tan(a + b)
        R = (sp.tan(a) + sp.tan(b)) / (1 - sp.tan(a) * sp.tan(b))
    elif pick < 0.8:
        L = sp.tan(a) * sp.cos(a) ** 2
        R = sp.sin(a) * sp.cos(a)
    else:
        q = rng.choice([5, 8, 10, 12, 16, 7])
        p = rng.randint(1, q - 1)
        L = sp.tan(sp.pi * p / q) * X
        R = sp.sin(sp.pi * p / q) / sp.cos(sp.pi * p / q) * X
    return finish(rng, "tan", ec(L), L, R, true, angles=[X, Y])


def gen_diff_trig(rng, true):
    """Derivatives of trigonometric expressions (tan included) and subs at a point."""
    pick = rng.random()
    if pick < 0.4:
        E = trig_poly(rng, [X], 2, tan_ok=True)
        L = sp.diff(E, X)
        lt = "diff(%s, x)" % ec(E)
        R = rng.choice([lambda e: e, lambda e: sp.expand(sp.expand_trig(e))])(L)
        return finish(rng, "diff_trig", lt, L, R, true, angles=[X])
    E = poly(rng, [T, X], 2) / (poly(rng, [T], 1) + T + rng.choice([5, 7, 11]))
    c = rng.choice([0, 1, 2, sp.Rational(1, 2), X])
    L = sp.diff(E, T).subs(T, c)
    lt = "subs(diff(%s, t), t, %s)" % (ec(E), ec(c))
    R = sp.cancel(L)
    return finish(rng, "diff_subs", lt, L, R, true)


def gen_sum_frac(rng, true):
    """Sums of fractions and of binomials with a variable, closed forms from SymPy."""
    k = sp.Symbol("k")
    n = rng.randint(1, 7)
    pick = rng.random()
    if pick < 0.4:
        E = 1 / ((k + X) * (k + X + 1))
        S = sp.together(sp.summation(sp.apart(E, k), (k, 1, n)))
        R = sp.cancel(S)
        body = "1/((k + x)(k + x + 1))"
    elif pick < 0.7:
        E = sp.binomial(n, k) * (-1) ** k / (k + 1)
        S = sp.summation(E, (k, 0, n))
        R = sp.Rational(1, n + 1)
        body = "binomial(%d, k)*(-1)^k/(k + 1)" % n
    else:
        j = sp.Symbol("j")
        E = sp.Sum(k * j * X, (j, 1, k))
        S = sp.summation(sp.summation(k * j * X, (j, 1, k)), (k, 1, n))
        R = sp.expand(S)
        body = "sum(j, 1, k, k*j*x)"
    lt = "sum(k, %d, %d, %s)" % (0 if pick >= 0.4 and pick < 0.7 else 1, n, body)
    return finish(rng, "sum_frac", lt, S, R, true)


def gen_const_trig_products(rng, true):
    """Classical constant products and sums of cosines and tangents of rational multiples of pi."""
    n = rng.choice([5, 7, 9, 11])
    pick = rng.random()
    if pick < 0.35:
        # prod_{k=1}^{(n-1)/2} cos(k pi / n) = 1/2^((n-1)/2)
        m = (n - 1) // 2
        L = sp.Mul(*[sp.cos(sp.pi * j / n) for j in range(1, m + 1)])
        R = sp.Rational(1, 2 ** m)
        lt = "*".join("cos(%s)" % ec(sp.pi * j / n) for j in range(1, m + 1))
    elif pick < 0.6:
        # prod tan(k pi/n), k = 1..(n-1)/2, = sqrt(n)
        m = (n - 1) // 2
        L = sp.Mul(*[sp.tan(sp.pi * j / n) for j in range(1, m + 1)])
        R = sp.sqrt(n)
        lt = "*".join("tan(%s)" % ec(sp.pi * j / n) for j in range(1, m + 1))
    else:
        q = rng.choice([7, 9, 11, 13, 14, 15, 18, 20, 24])
        p = rng.randint(1, 2 * q - 1)
        a = sp.pi * sp.Rational(p, q)
        L = sp.sin(a) ** 2
        R = (1 - sp.cos(2 * a)) / 2
        lt = "sin(%s)^2" % ec(a)
    if rng.random() < 0.5:
        L, R, lt = L * Y + X, R * Y + X, "(%s)*y + x" % lt
        return finish(rng, "const_trig", lt, L, R, true)
    return finish(rng, "const_trig", lt, L, R, true)


def gen_where_frac(rng, true):
    """A relation with a fraction, m = P/Q: its denominator becomes a hypothesis."""
    m = sp.Symbol("u")
    P = poly(rng, [X, Y], 1)
    Q = poly(rng, [X], 1) + X
    L = poly(rng, [m, X], 2)
    R = sp.cancel(L.subs(m, P / Q))

    def sample(rg):
        p = {X: sample_real(rg), Y: sample_real(rg)}
        q = Q.subs(p)
        if q == 0:
            return None
        p[m] = P.subs(p) / q
        return p

    return finish(rng, "where_frac", ec(L), L, R, true, where=["u = (%s)/(%s)" % (ec(P), ec(Q))], sample=sample, random_ok=False)


def gen_random_const_frac(rng, true):
    """Fractions with radicals and cosines of pi/q in divisors: rationalized denominators."""
    c = rng.choice([sp.sqrt(2), sp.sqrt(3), sp.sqrt(5), sp.cos(sp.pi / 5), sp.sqrt(2 + sp.sqrt(2)), sp.cos(sp.pi / 7)])
    a = rng.randint(1, 4)
    L = 1 / (X + a * c)
    if c.is_Pow:
        R = (X - a * c) / sp.expand((X + a * c) * (X - a * c))
    else:
        R = sp.Integer(1) / (X + a * c)
        R = X / (X ** 2 + a * c * X) if rng.random() < 0.5 else R
    lt = "1/(x + %s)" % ec(a * c)
    return finish(rng, "const_frac", lt, L, R, true)


def gen_sqrt_branch(rng, true):
    """Roots whose branch decides the identity: sqrt((x - c)^2) = c - x where x <= c, nested
    roots sqrt(x + 2 sqrt(x) + 1) = sqrt(x) + 1, the relation y^2 = x with y >= 0."""
    c = rng.randint(-3, 3)
    pick = rng.random()
    if pick < 0.4:
        L = sp.sqrt(sp.expand((X - c) ** 2))
        R = c - X
        where = ["x <= %d" % c]
        lt = "sqrt(%s)" % ec(sp.expand((X - c) ** 2))

        def ok(p):
            return p[X] <= c

    elif pick < 0.7:
        k = rng.randint(1, 3)
        L = sp.sqrt(X + 2 * k * sp.sqrt(X) + k * k)
        R = sp.sqrt(X) + k
        where = []
        lt = "sqrt(x + %d*sqrt(x) + %d)" % (2 * k, k * k)

        def ok(p):
            return p[X] >= 0

    else:
        # with y^2 = x and y >= 0, sqrt(x) = y
        L, R, lt = sp.sqrt(X), Y, "sqrt(x)"
        where = ["y^2 = x", "y >= 0"]

        def sample(rg):
            y = abs(sample_real(rg))
            return {X: y * y, Y: y}

        return finish(rng, "sqrt_branch", lt, L, R, true, where=where, sample=sample, random_ok=False)

    def sample(rg):
        for _ in range(50):
            p = {X: sample_real(rg)}
            if ok(p):
                return p
        return None

    return finish(rng, "sqrt_branch", lt, L, R, true, where=where, sample=sample, random_ok=False)


def gen_mixed(rng, true):
    """Constructs combined: rotation matrices, trigonometric sums and fractions, derivatives of
    tangents with constant shifts, integrals with fractional coefficients, sums of derivatives."""
    pick = rng.randrange(6)
    if pick == 0:
        a, b = angle(rng, [X], const_ok=False), angle(rng, [Y])

        def rot(t):
            return [[sp.cos(t), -sp.sin(t)], [sp.sin(t), sp.cos(t)]]

        L = (sp.Matrix(rot(a)) * sp.Matrix(rot(b))).tolist()
        R = rot(a + b)
        lt = "%s*%s" % (ec(rot(a)), ec(rot(b)))
        L = [e for row in L for e in row]
        R = [e for row in R for e in row]
        if not true:
            i = rng.randrange(4)
            R[i] = R[i] + nonzero_rat(rng) * sp.sin(X)
        rt = "[[%s, %s], [%s, %s]]" % tuple(ec(e) for e in R)
        return Case("mixed", lt, rt, L, R, true, sample=default_sampler([X, Y]), angles=[X, Y])
    if pick == 1:
        n = rng.randint(1, 4)
        k = sp.Symbol("k")
        E = rng.choice([sp.sin, sp.cos])(k * X + sp.pi * sp.Rational(rng.randint(0, 5), rng.choice([3, 4, 5, 6])))
        L = sp.Add(*[E.subs(k, j) for j in range(1, n + 1)])
        R = sp.expand(sp.expand_trig(L))
        return finish(rng, "mixed", "sum(k, 1, %d, %s)" % (n, ec(E)), L, R, true, angles=[X])
    if pick == 2:
        E = sp.tan(X + sp.pi * sp.Rational(rng.randint(1, 6), rng.choice([5, 7, 8, 12])))
        L = sp.diff(E, X)
        R = 1 + E ** 2
        return finish(rng, "mixed", "diff(%s, x)" % ec(E), L, R, true, angles=[X])
    if pick == 3:
        E = poly(rng, [T], 2) / (A ** 2 + 1) + T * X / (A - 3)
        lo, hi = rng.choice([0, 1, -2]), rng.choice([X, A, 2 * X + 1, sp.Rational(1, 3)])
        I = sp.integrate(E, (T, lo, hi))
        R = sp.together(I) if rng.random() < 0.5 else sp.cancel(I)
        return finish(rng, "mixed", "integrate(%s, t, %s, %s)" % (ec(E), ec(lo), ec(hi)), I, R, true)
    if pick == 4:
        k = sp.Symbol("k")
        n = rng.randint(1, 4)
        E = (X + k) ** rng.randint(2, 4)
        L = sp.Add(*[sp.diff(E.subs(k, j), X) for j in range(0, n + 1)])
        R = sp.expand(L)
        return finish(rng, "mixed", "sum(k, 0, %d, diff(%s, x))" % (n, ec(E)), L, R, true)
    # trig fraction with a constant angle
    a = angle(rng, [X], const_ok=False)
    L = (sp.sin(a) + nonzero_rat(rng)) / (sp.cos(a) + rng.choice([2, 3, -3]))
    R = sp.expand_trig(L)
    return finish(rng, "mixed", ec(L), L, R, true, angles=[X])


GENERATORS = {
    "poly": gen_poly,
    "fraction": gen_fraction,
    "trig": gen_trig,
    "trig_const": gen_trig_const,
    "diff": gen_diff,
    "integrate": gen_integrate,
    "sum": gen_sum,
    "det": gen_det,
    "vector": gen_vector,
    "where_power": gen_where_power,
    "where_circle": gen_where_circle,
    "where_subst": gen_where_subst,
    "hypothesis": gen_hypothesis,
    "domain": gen_domain,
    "sqrt_expr": gen_sqrt_expr,
    "pole": gen_pole,
    "syntax": gen_syntax,
    "tan": gen_tan,
    "diff_trig": gen_diff_trig,
    "sum_frac": gen_sum_frac,
    "const_trig": gen_const_trig_products,
    "where_frac": gen_where_frac,
    "const_frac": gen_random_const_frac,
    "sqrt_branch": gen_sqrt_branch,
    "mixed": gen_mixed,
}


# ----------------------------------------------------------------------------------------------
# Ground truth


def numeric(expr, point):
    """The value of `expr` at `point` as an mpmath complex at 50 digits, or None (a pole, or a
    square root that is not real)."""
    try:
        e = expr.subs(point)
        v = sp.N(e, 50)
        if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            return None
        c = complex(v)  # raises for non-numbers
        re_, im_ = v.as_real_imag()
        re_ = mp.mpf(str(sp.N(re_, 50)))
        im_ = mp.mpf(str(sp.N(im_, 50)))
        return mp.mpc(re_, im_) if c is not None else None
    except (TypeError, ValueError, ZeroDivisionError, AttributeError):
        return None


def is_real_point(case, point):
    """Every square root and every side is real and finite at the point."""
    for side in (case.L, case.R):
        for e in side if isinstance(side, (list, tuple)) else [side]:
            val = numeric(e, point)
            if val is None or abs(val.imag) > mp.mpf(10) ** -30 * max(1, abs(val.real)):
                return False
            # a root of a negative number that cancels still makes the point outside the domain
            for p in sp.preorder_traversal(e):
                if isinstance(p, sp.Pow) and p.exp.is_Rational and not p.exp.is_Integer:
                    b = numeric(p.base, point)
                    if b is None or b.real < -mp.mpf(10) ** -40:
                        return False
                if isinstance(p, sp.Pow) and p.exp.is_negative:
                    b = numeric(p.base, point)
                    if b is None or abs(b) < mp.mpf(10) ** -40:
                        return False
    return True


def scale_of(case, point):
    m = mp.mpf(1)
    for side in (case.L, case.R):
        for e in side if isinstance(side, (list, tuple)) else [side]:
            v = numeric(e, point)
            if v is not None:
                m = max(m, abs(v))
    return m


def residual_at(case, point):
    vals = [numeric(d, point) for d in case.diff_expr()]
    if any(v is None for v in vals):
        return None
    return max(abs(v) for v in vals) / scale_of(case, point)


def truth(case, rng, points=6):
    """'true' (zero at every sampled point), 'false' (non-zero at one) or None (no point)."""
    seen = 0
    for _ in range(points * 4):
        p = case.sample(rng)
        if p is None or not is_real_point(case, p):
            continue
        r = residual_at(case, p)
        if r is None:
            continue
        seen += 1
        if r > mp.mpf(10) ** -25:
            return "false", p, r
        if seen >= points:
            break
    if seen == 0:
        return None, None, None
    return "true", None, None


# ----------------------------------------------------------------------------------------------
# Running exactcheck


def run(binary, args, timeout):
    t0 = time.time()
    try:
        pr = subprocess.run([binary] + args + ["--json", "--timeout", str(timeout)], capture_output=True,
                            text=True, timeout=timeout + 20)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "code": None, "stdout": "", "stderr": "", "secs": time.time() - t0}
    out = {"code": pr.returncode, "stdout": pr.stdout, "stderr": pr.stderr, "secs": time.time() - t0}
    try:
        out["json"] = json.loads(pr.stdout) if pr.stdout.strip() else None
    except json.JSONDecodeError:
        out["json"] = None
    out["verdict"] = out["json"]["verdict"] if out["json"] else ("error" if pr.returncode == 2 else "?")
    return out


def parse_value(text):
    if text is None:
        return None
    if "≈" in text:
        text = text.split("≈")[1]
    try:
        return sp.N(sp.sympify(text.strip().replace("^", "**"), locals={str(v): v for v in VARS}), 50)
    except (sp.SympifyError, TypeError, SyntaxError, ValueError):
        return None


def point_of(case, js):
    """The counter-example of a `fails` verdict as a SymPy point, or None when it has no point."""
    pt = js.get("point")
    if not pt:
        return None
    names = {str(s): s for s in case_syms(case)}
    res = {}
    circ = {}
    for k, val in pt.items():
        m = re.fullmatch(r"(cos|sin)\((\w+)\)", k)
        v = parse_value(val)
        if m:
            circ.setdefault(m.group(2), {})[m.group(1)] = v
            continue
        if k in names and v is not None:
            res[names[k]] = sp.nsimplify(v) if not v.is_Rational else v
            try:
                res[names[k]] = sp.sympify(val.replace("^", "**"))
            except sp.SympifyError:
                pass
    for name, cs in circ.items():
        if name in names and "cos" in cs and "sin" in cs:
            res[names[name]] = sp.atan2(cs["sin"], cs["cos"])
    return res


def judge(case, tr, ex, rd):
    """The findings of one case."""
    found = []
    for mode, r in (("exact", ex), ("random", rd)):
        if r is None:
            continue
        if r.get("status") == "timeout":
            found.append((mode, "timeout", "no answer within the time limit"))
            continue
        if r["code"] not in (0, 1, 2):
            found.append((mode, "exit-status", "exit status %s: %s" % (r["code"], r["stderr"].strip()[-300:])))
        if "panicked" in r["stderr"]:
            found.append((mode, "panic", r["stderr"].strip()[-300:]))
        v = r["verdict"]
        if v in ("proved", "holds") and tr == "false":
            found.append((mode, "wrong-proved", "%s for a numerically false identity" % v))
        if v == "fails" and tr == "true":
            found.append((mode, "wrong-fails", "fails for a numerically true identity: %s" % r["json"].get("evidence", "")[:300]))
        if v in ("proved", "holds", "fails", "undecided") and r["code"] != (0 if v in ("proved", "holds") else 1):
            found.append((mode, "exit-status", "%s with exit status %s" % (v, r["code"])))
        if v == "fails" and mode == "exact" and r["json"]:
            pt = point_of(case, r["json"])
            if pt:
                missing = [s for s in case_syms(case) if s not in pt]
                if missing:
                    found.append((mode, "counter-example", "point lacks %s" % missing))
                elif is_real_point(case, pt):
                    res = residual_at(case, pt)
                    vals = [numeric(d, pt) for d in case.diff_expr()]
                    printed = parse_value(r["json"].get("value"))
                    if res is not None and res < mp.mpf(10) ** -25:
                        found.append((mode, "counter-example", "LHS - RHS ~ 0 at the printed point %s" % pt))
                    elif printed is not None and vals and all(v is not None for v in vals):
                        pv = complex(printed)
                        if not any(abs(complex(v) - pv) <= 1e-8 * max(1, abs(pv)) for v in vals):
                            found.append((mode, "counter-example", "printed value %s but LHS - RHS = %s at %s" % (
                                r["json"].get("value"), [mp.nstr(v.real, 12) for v in vals], pt)))
                else:
                    found.append((mode, "counter-example", "the point %s is a pole or outside the roots' domain" % pt))
    if ex and rd and ex.get("verdict") and rd.get("verdict"):
        a, b = ex["verdict"], rd["verdict"]
        if (a == "proved" and b == "fails") or (a == "fails" and b == "holds"):
            found.append(("both", "exact-vs-random", "exact %s, random %s" % (a, b)))
    return found


def shell_quote(a):
    return "'" + a.replace("'", "'\\''") + "'" if re.search(r"[^\w./=-]", a) else a


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exactcheck", default=os.path.join(os.path.dirname(__file__), "..", "..", "target", "release", "exactcheck"))
    ap.add_argument("--count", type=int, default=100, help="cases to generate")
    ap.add_argument("--seed", type=int, default=None, help="seed of the generator (default: fresh)")
    ap.add_argument("--kinds", default=",".join(GENERATORS), help="comma-separated generators: " + ", ".join(GENERATORS))
    ap.add_argument("--timeout", type=int, default=20, help="seconds per exactcheck run")
    ap.add_argument("--sympy-seconds", type=int, default=15, help="seconds SymPy may spend on one case")
    ap.add_argument("--no-random", action="store_true", help="skip the --random runs")
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "..", "target", "differential-findings.jsonl"),
                    help="findings, one JSON object a line, appended (default target/differential-findings.jsonl)")
    ap.add_argument("--verbose", action="store_true", help="print every case")
    opts = ap.parse_args()
    signal.signal(signal.SIGALRM, _alarm)
    seed = opts.seed if opts.seed is not None else random.SystemRandom().randrange(2**32)
    print("seed %d" % seed, flush=True)
    rng = random.Random(seed)
    kinds = [k.strip() for k in opts.kinds.split(",") if k.strip()]
    for k in kinds:
        if k not in GENERATORS:
            sys.exit("unknown kind %s (known: %s)" % (k, ", ".join(GENERATORS)))
    stats = collections.Counter()
    errors = collections.Counter()
    findings = 0
    with open(opts.out, "a") as out:
        n = 0
        while n < opts.count:
            kind = kinds[n % len(kinds)]
            intended = rng.random() < 0.6
            signal.alarm(opts.sympy_seconds)
            try:
                case = GENERATORS[kind](rng, intended)
                tr, fpt, fres = truth(case, rng)
            except Skip:
                stats["skipped"] += 1
                continue
            except SlowSympy:
                stats["skipped: slow sympy"] += 1
                continue
            except (sp.PolynomialError, NotImplementedError, ValueError, TypeError, ZeroDivisionError) as e:
                stats["skipped:" + type(e).__name__] += 1
                continue
            finally:
                signal.alarm(0)
            n += 1
            if tr is None:
                stats["no-point"] += 1
            elif (tr == "true") != intended:
                stats["generator-intent-differs"] += 1
            ex = run(opts.exactcheck, case.args(), opts.timeout)
            rd = None
            if case.random_ok and not opts.no_random:
                rd = run(opts.exactcheck, case.args() + ["--random", "20"], opts.timeout)
            stats["%s exact %s" % (kind, ex.get("verdict"))] += 1
            if rd:
                stats["%s random %s" % (kind, rd.get("verdict"))] += 1
            for r in (ex, rd):
                if r and r.get("verdict") == "error":
                    msg = re.sub(r"\d+", "N", r["stderr"].strip().splitlines()[-1] if r["stderr"].strip() else "")
                    errors[msg[:160]] += 1
            signal.alarm(opts.sympy_seconds)
            try:
                found = judge(case, tr, ex, rd)
            except SlowSympy:
                stats["judge: slow sympy"] += 1
                found = []
            finally:
                signal.alarm(0)
            cmd = "exactcheck " + " ".join(shell_quote(a) for a in case.args())
            if opts.verbose:
                print("[%s] truth=%s exact=%s random=%s  %s" % (kind, tr, ex.get("verdict"), rd and rd.get("verdict"), cmd), flush=True)
            for mode, what, detail in found:
                findings += 1
                rec = {"seed": seed, "case": n, "kind": kind, "mode": mode, "finding": what, "detail": detail,
                       "command": cmd, "truth": tr, "exact": ex.get("verdict"), "random": rd and rd.get("verdict"),
                       "exact_stdout": ex.get("stdout", "")[:2000], "exact_stderr": ex.get("stderr", "")[:500]}
                if fpt:
                    rec["false_at"] = {str(k): str(v) for k, v in fpt.items()}
                out.write(json.dumps(rec) + "\n")
                out.flush()
                print("FINDING %s %s [%s]: %s\n    %s" % (what, mode, kind, detail[:300], cmd), flush=True)
    print("\n%d cases, %d findings" % (opts.count, findings))
    for k, c in sorted(stats.items()):
        print("  %-40s %d" % (k, c))
    if errors:
        print("errors (exit 2), by message:")
        for m, c in errors.most_common(30):
            print("  %4d  %s" % (c, m))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
