#!/usr/bin/env python3
"""W4: all real roots of an integer polynomial, each isolated in an interval of width
at most 2^-53, in SymPy or python-flint. The same polynomials as `exactcheck bench w4`:

  wilkinson n : prod_{j=1..n} (n x - j)
  random d    : c_0..c_d the first d + 1 outputs of SplitMix64 from the state d, read as signed
                64-bit integers; c_d = 0 becomes 1
  mignotte n  : x^n - 2 (10 x - 1)^2

Usage: w4_roots.py TOOL FAMILY DEGREE   (TOOL: sympy | flint)

Prints one JSON line: {"tool", "version", "family", "degree", "seconds", "real_roots",
"roots": [["lo", "hi"], ...]} with lo, hi exact rationals ("p/q" or "p"), sorted. The timed
region is from the integer coefficients to the final list of intervals.

* sympy: Poly(p).intervals(eps=2^-53) (real root isolation by continued fractions, refined to
  the width), exact rational endpoints.
* flint: fmpz_poly(p).complex_roots() with flint.ctx.prec raised (53, 106, 212, ...) until every
  root certified real (imaginary part exactly zero; FLINT's arb_fmpz_poly_complex_roots proves
  realness) has an enclosure of width <= 2^-53; the arb midpoint and radius are dyadic and are
  converted exactly.

Before the timed call each tool solves x^2 - 2 untimed (a warm-up, as `exactcheck bench w4`
does): at a tenth of a millisecond the first execution of the code (cold caches, first-touch page
faults) would otherwise weigh as much as the isolation itself. It is a different polynomial, so
no result cache can serve the timed call.

The script checks the widths itself and exits with status 1 if one is too wide.
"""
import json
import sys
import time
from fractions import Fraction

MASK = (1 << 64) - 1
WARM_UP = [-2, 0, 1]
WIDTH = Fraction(1, 1 << 53)


def splitmix64(state):
    state = (state + 0x9E3779B97F4A7C15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return state, z ^ (z >> 31)


def coefficients(family, n):
    """Integer coefficients from the constant term up."""
    if family == "wilkinson":
        p = [1]
        for j in range(1, n + 1):
            nxt = [0] * (len(p) + 1)
            for i, c in enumerate(p):
                nxt[i] -= c * j
                nxt[i + 1] += c * n
            p = nxt
        return p
    if family == "random":
        state, c = n, []
        for _ in range(n + 1):
            state, z = splitmix64(state)
            c.append(z - (1 << 64) if z >= 1 << 63 else z)
        if c[n] == 0:
            c[n] = 1
        return c
    if family == "mignotte":
        c = [0] * (max(n, 2) + 1)
        c[n] += 1
        c[2] -= 200
        c[1] += 40
        c[0] -= 2
        while c and c[-1] == 0:
            c.pop()
        return c
    raise SystemExit(f"unknown family {family!r} (wilkinson, random, mignotte)")


def run_sympy(coeffs):
    import sympy
    from sympy import Poly, Rational, symbols

    x = symbols("x")
    start = time.perf_counter()
    p = Poly(list(reversed(coeffs)), x)
    ivs = p.intervals(eps=Rational(1, 1 << 53))
    out = [(Fraction(int(a.p), int(a.q)), Fraction(int(b.p), int(b.q))) for (a, b), _ in ivs]
    seconds = time.perf_counter() - start
    return sympy.__version__, seconds, out


def dyadic(x):
    """An exact arb (a midpoint or a radius) as a Fraction."""
    man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return Fraction(man * (1 << exp)) if exp >= 0 else Fraction(man, 1 << -exp)


def run_flint(coeffs):
    import flint

    start = time.perf_counter()
    p = flint.fmpz_poly(coeffs)
    prec = 53
    while True:
        flint.ctx.prec = prec
        roots = p.complex_roots()
        real = [c.real for c, _ in roots if c.imag == 0]
        out = []
        for r in real:
            mid, rad = dyadic(r.mid()), dyadic(r.rad())
            out.append((mid - rad, mid + rad))
        if all(hi - lo <= WIDTH for lo, hi in out):
            break
        prec *= 2
    out.sort()
    seconds = time.perf_counter() - start
    flint.ctx.prec = 53
    return flint.__version__, seconds, out


def fmt(q):
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    tool, family, degree = sys.argv[1], sys.argv[2], int(sys.argv[3])
    if degree < 1:
        raise SystemExit("DEGREE must be at least 1")
    coeffs = coefficients(family, degree)
    runs = {"sympy": run_sympy, "flint": run_flint}
    if tool not in runs:
        raise SystemExit(f"unknown tool {tool!r} (sympy, flint)")
    # The warm-up (as `exactcheck bench w4`): the same call on x^2 - 2, untimed, so that the
    # timed call measures the isolation rather than the first execution of its code.
    runs[tool](WARM_UP)
    version, seconds, roots = runs[tool](coeffs)
    for lo, hi in roots:
        if not (lo <= hi and hi - lo <= WIDTH):
            print(f"interval [{lo}, {hi}] wider than 2^-53", file=sys.stderr)
            sys.exit(1)
    # Sorted, and disjoint as open intervals (SymPy's intervals of a close pair may share an end).
    for (lo0, hi0), (lo1, hi1) in zip(roots, roots[1:]):
        if not (hi0 <= lo1 and (lo0 < hi0 or lo1 < hi1 or hi0 < lo1)):
            print("intervals not sorted and disjoint", file=sys.stderr)
            sys.exit(1)
    print(json.dumps({
        "tool": tool,
        "version": version,
        "family": family,
        "degree": degree,
        "seconds": seconds,
        "real_roots": len(roots),
        "roots": [[fmt(lo), fmt(hi)] for lo, hi in roots],
    }))


if __name__ == "__main__":
    main()
