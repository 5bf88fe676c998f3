#!/usr/bin/env python3
"""exactcheck's real algebraic numbers side by side with python-flint's qqbar and SymPy's
minimal_polynomial.

Usage: python3 bench/scripts/compare_algebraic.py [--reps K] [--python PY]

Two workloads (python-flint 0.9 has no qqbar type, so FLINT takes part through
fmpz_poly.cos_minpoly in the first only): (cos) the minimal polynomials of cos(2 pi / n) for n = 1..60; (sum) the polynomial
of sqrt(2 + sqrt(2)) + sqrt(2 - sqrt(2)) + sqrt(3 + sqrt(3)) + sqrt(5 + sqrt(5)). exactcheck runs
as `target/release/examples/algebraic_minpoly` (build it with
`cargo build --release -p exactcheck-bench --example algebraic_minpoly`); the Python tools run in
the anchors' virtual environment (`.venv-anchors`, see bench/scripts/compare.sh; it needs
python-flint and sympy). The tools alternate run by run (K runs each); every run reports CPU time
(exactcheck: the child's user + system time from getrusage; Python: time.process_time in the
child) and wall time, and the table shows the medians.

Checks (a disagreement exits 1): the cos polynomials must equal FLINT's and SymPy's minimal
polynomials up to sign; for the sum, SymPy's minimal polynomial must equal exactcheck's
defining polynomial up to sign (exactcheck factors every result over Z and keeps the minimal
polynomial, see the algebraic module) and the values must agree to 28 significant characters.
"""
import argparse, json, os, resource, statistics, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "target", "release", "examples", "algebraic_minpoly")

p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("--reps", type=int, default=5)
p.add_argument("--python", default=os.path.join(ROOT, ".venv-anchors", "bin", "python"))
args = p.parse_args()

# The Python side of one run: prints one JSON line {"cpu", "wall", "polys" | "poly"}.
# python-flint 0.9 has no qqbar type: its anchor is fmpz_poly.cos_minpoly (FLINT's minimal
# polynomial of 2 cos(2 pi / n)) for the cosines, and the sum is SymPy's alone.
PY = r"""
import json, sys, time
which, tool = sys.argv[1], sys.argv[2]
c0, w0 = time.process_time(), time.perf_counter()
if tool == "flint":
    from flint import fmpz_poly
    two_x = fmpz_poly([0, 2])
    out = {"polys": [[str(c) for c in fmpz_poly.cos_minpoly(n)(two_x).coeffs()] for n in range(1, 61)]}
else:
    import sympy
    x = sympy.Symbol("x")
    if which == "cos":
        ps = [sympy.Poly(sympy.minimal_polynomial(sympy.cos(2 * sympy.pi / n), x), x) for n in range(1, 61)]
        out = {"polys": [[str(c) for c in reversed(m.all_coeffs())] for m in ps]}
    else:
        s = sympy.sqrt
        v = s(2 + s(2)) + s(2 - s(2)) + s(3 + s(3)) + s(5 + s(5))
        m = sympy.Poly(sympy.minimal_polynomial(v, x), x)
        out = {"poly": [str(c) for c in reversed(m.all_coeffs())], "decimal": str(sympy.N(v, 40))}
out["cpu"] = time.process_time() - c0
out["wall"] = time.perf_counter() - w0
print(json.dumps(out))
"""


def fail(msg):
    print("compare_algebraic: " + msg, file=sys.stderr)
    sys.exit(1)


if not os.access(BIN, os.X_OK):
    fail(f"{BIN} is missing: cargo build --release -p exactcheck-bench --example algebraic_minpoly")
if not os.access(args.python, os.X_OK):
    fail(f"{args.python} is missing: create the venv (bench/scripts/compare.sh) with python-flint and sympy")


def run_exactcheck(which):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    out = subprocess.run([BIN, which], check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - w0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = json.loads(out)
    r["cpu"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    r["wall"] = wall
    return r


def run_python(which, tool):
    out = subprocess.run([args.python, "-c", PY, which, tool], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def ints(cs):
    from fractions import Fraction
    fr = [Fraction(c) for c in cs]
    assert all(f.denominator == 1 for f in fr)
    return [int(f) for f in fr]


def primitive(a):
    from math import gcd
    g = 0
    for c in a:
        g = gcd(g, c)
    return [c // g for c in a] if g else a


def same_up_to_sign(a, b):
    a, b = primitive(a), primitive(b)
    return a == b or a == [-c for c in b]


def check(which, results):
    ex = results["exactcheck"][0]
    if which == "cos":
        for tool in ["flint", "sympy"]:
            for n, (a, b) in enumerate(zip(ex["polys"], results[tool][0]["polys"]), start=1):
                if not same_up_to_sign(ints(a), ints(b)):
                    fail(f"cos(2 pi/{n}): exactcheck {a} != {tool} {b}")
    else:
        # The minimal polynomials must agree, and the values to 28 characters.
        a, b = ints(ex["poly"]), ints(results["sympy"][0]["poly"])
        if not same_up_to_sign(a, b):
            fail(f"sum: exactcheck's minimal polynomial (degree {len(a) - 1}) != SymPy's (degree {len(b) - 1})")
        if ex["decimal"][:28] != results["sympy"][0]["decimal"][:28]:
            fail(f"sum: values differ: {ex['decimal']} vs {results['sympy'][0]['decimal']}")


rows = []
for which in ["cos", "sum"]:
    tools = ["exactcheck", "flint", "sympy"] if which == "cos" else ["exactcheck", "sympy"]
    results = {t: [] for t in tools}
    for rep in range(args.reps):
        # alternate the order run by run
        order = tools[rep % len(tools):] + tools[:rep % len(tools)]
        for tool in order:
            if tool == "exactcheck":
                results[tool].append(run_exactcheck(which))
            else:
                results[tool].append(run_python(which, tool))
    check(which, results)
    for tool, runs in results.items():
        rows.append((which, tool, statistics.median(r["cpu"] for r in runs),
                     statistics.median(r["wall"] for r in runs), len(runs)))

print(f"{'workload':10} {'tool':11} {'CPU s (median)':>15} {'wall s (median)':>16} runs")
for which, tool, cpu, wall, n in rows:
    print(f"{which:10} {tool:11} {cpu:15.4f} {wall:16.4f} {n:4}")
