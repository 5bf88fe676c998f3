#!/usr/bin/env python3
"""dense-product: Fateman's dense product f (f + 1), f = (1 + x1 + ... + xV)^K.

Usage: python dense_product.py TOOL [K=8] [V=4]
  TOOL: flint (fmpq_mpoly, the same coefficient field as exactcheck's Poly<Rational>),
        flint-z (fmpz_mpoly, integer coefficients), sympy (SymPy's sparse ring over QQ),
        symengine (expand of the product)
Prints one JSON line with `seconds` (the product alone; f is built before) and the check
values: terms, coeff_sum (the value at (1, ..., 1)) and max_coeff, both as decimal strings.
Written for exactcheck (bench/scripts/compare.py); the same product is `exactcheck-bench dense-product`.
"""
import sys, time, json

tool = sys.argv[1]
K = int(sys.argv[2]) if len(sys.argv) > 2 else 8
V = int(sys.argv[3]) if len(sys.argv) > 3 else 4
names = [f"x{i + 1}" for i in range(V)]

if tool in ("flint", "flint-z"):
    import flint
    VERSION = "python-flint " + flint.__version__
    ctx_type = flint.fmpq_mpoly_ctx if tool == "flint" else flint.fmpz_mpoly_ctx
    ctx = ctx_type.get(tuple(names), "lex")
    gens = ctx.gens()
    f = ctx.from_dict({(0,) * V: 1})
    for g in gens:
        f = f + g
    f = f ** K
    g = f + 1
    t0, c0 = time.perf_counter(), time.process_time()
    h = f * g
    t1, c1 = time.perf_counter(), time.process_time()
    coeffs = [int(c) if tool == "flint-z" else int(c.p) for c in h.coeffs()]
    if tool == "flint":
        assert all(c.q == 1 for c in h.coeffs())
elif tool == "sympy":
    import sympy as sp
    from sympy.polys.rings import ring
    from sympy.polys.domains import QQ
    VERSION = "SymPy " + sp.__version__
    R, *gens = ring(",".join(names), QQ, "lex")
    f = R.one
    for g in gens:
        f = f + g
    f = f ** K
    g = f + 1
    t0, c0 = time.perf_counter(), time.process_time()
    h = f * g
    t1, c1 = time.perf_counter(), time.process_time()
    coeffs = [int(c) for c in h.values()]
elif tool == "symengine":
    import symengine as se
    VERSION = "SymEngine " + se.__version__
    xs = [se.Symbol(n) for n in names]
    f = se.expand((1 + se.Add(*xs)) ** K)
    g = f + 1
    t0, c0 = time.perf_counter(), time.process_time()
    h = se.expand(f * g)
    t1, c1 = time.perf_counter(), time.process_time()
    # every term of the expanded sum is coefficient * monomial; a number term is its own
    def coeff(term):
        if term.is_Number:
            return int(term)
        if term.is_Mul and term.args[0].is_Number:
            return int(term.args[0])
        return 1
    coeffs = [coeff(term) for term in h.args]
else:
    sys.exit("unknown tool " + tool)

print(json.dumps(dict(tool=tool, version=VERSION, k=K, vars=V, seconds=t1 - t0, cpu_seconds=c1 - c0,
                      terms=len(coeffs), coeff_sum=str(sum(coeffs)), max_coeff=str(max(coeffs)))))
