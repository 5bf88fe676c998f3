#!/usr/bin/env python3
"""real-roots: all real roots of an integer polynomial, each isolated in an interval of width
at most 2^-53, in SymPy or python-flint. The same polynomials as `exactcheck-bench real-roots`:

  wilkinson n : prod_{j=1..n} (n x - j)
  random d    : c_0..c_d the first d + 1 outputs of SplitMix64 from the state d, read as signed
                64-bit integers; c_d = 0 becomes 1
  mignotte n  : x^n - 2 (10 x - 1)^2

Usage: real_roots.py TOOL FAMILY DEGREE   (TOOL: sympy | flint-real | flint-complex)

Prints one JSON line: {"tool", "version", "family", "degree", "seconds", "real_roots",
"roots": [["lo", "hi"], ...]} with lo, hi exact rationals ("p/q" or "p"), sorted. The timed
region is from the integer coefficients to the final list of intervals.

* sympy: Poly(p).intervals(eps=2^-53) (real root isolation by continued fractions, refined to
  the width), exact rational endpoints.
* flint-real: FLINT's own real-root path, called through ctypes on the libflint that python-flint
  bundles (python-flint exposes no real-root method): `arb_fmpz_poly_real_roots`, which isolates
  the real roots by Vincent-Collins-Akritas (`fmpz_poly_isolate_real_roots`) and refines each
  with `arb_fmpz_poly_refine_root_arb`, at a relative precision of 53 bits plus the bit size of
  the Cauchy root bound (doubled until every enclosure is at most 2^-53 wide); each enclosure is
  read exactly with `arb_get_interval_fmpz_2exp`. One FLINT thread. The timed region is the
  FLINT call alone (the Python that builds the polynomial and reads the enclosures is left out,
  so that the interpreter's overhead does not count against FLINT).
* flint-complex: fmpz_poly(p).complex_roots() with flint.ctx.prec raised (53, 106, 212, ...) until every
  root certified real (imaginary part exactly zero; FLINT's arb_fmpz_poly_complex_roots proves
  realness) has an enclosure of width <= 2^-53; the arb midpoint and radius are dyadic and are
  converted exactly.

Before the timed call each tool solves x^2 - 2 untimed (a warm-up, as `exactcheck-bench real-roots`
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
    start, cpu = time.perf_counter(), time.process_time()
    p = Poly(list(reversed(coeffs)), x)
    ivs = p.intervals(eps=Rational(1, 1 << 53))
    out = [(Fraction(int(a.p), int(a.q)), Fraction(int(b.p), int(b.q))) for (a, b), _ in ivs]
    seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
    return sympy.__version__, seconds, cpu, out


def dyadic(x):
    """An exact arb (a midpoint or a radius) as a Fraction."""
    man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return Fraction(man * (1 << exp)) if exp >= 0 else Fraction(man, 1 << -exp)


def run_flint(coeffs):
    import flint

    start, cpu = time.perf_counter(), time.process_time()
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
    seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
    flint.ctx.prec = 53
    return flint.__version__, seconds, cpu, out


class _FlintReal:
    """ctypes bindings of the few libflint functions the flint-real tool calls."""

    ARB_SIZE = 48  # sizeof(arb_struct): arf_struct (exp, size, two-limb mantissa) + mag_struct

    def __init__(self):
        import ctypes
        import glob
        import os
        import flint

        site = os.path.dirname(os.path.dirname(flint.__file__))
        libs = sorted(glob.glob(os.path.join(site, "python_flint.libs", "libflint*.so*")))
        if not libs:
            raise SystemExit("flint-real: python-flint's bundled libflint was not found")
        lib = ctypes.CDLL(libs[0])
        P, L, I = ctypes.c_void_p, ctypes.c_long, ctypes.c_int
        for name, res, argtypes in [
            ("fmpz_poly_init", None, [P]), ("fmpz_poly_clear", None, [P]),
            ("fmpz_poly_set_str", I, [P, ctypes.c_char_p]),
            ("_arb_vec_init", P, [L]), ("_arb_vec_clear", None, [P, L]),
            ("arb_fmpz_poly_real_roots", L, [P, P, I, L]),
            ("_fmpz_vec_init", P, [L]), ("_fmpz_vec_clear", None, [P, L]),
            ("arb_get_interval_fmpz_2exp", None, [P, P, P, P]),
            ("fmpz_get_str", P, [P, I, P]), ("flint_free", None, [P]),
            ("flint_set_num_threads", None, [I]),
        ]:
            fn = getattr(lib, name)
            fn.restype, fn.argtypes = res, argtypes
        lib.flint_set_num_threads(1)
        self.lib, self.ctypes = lib, ctypes
        self.version = flint.__version__

    def text(self, ptr):
        raw = self.lib.fmpz_get_str(None, 10, ptr)
        value = int(self.ctypes.string_at(raw).decode())
        self.lib.flint_free(raw)
        return value

    def roots(self, coeffs):
        lib, ctypes = self.lib, self.ctypes
        poly = ctypes.create_string_buffer(24)  # fmpz_poly_struct: coeffs, alloc, length
        lib.fmpz_poly_init(poly)
        text = f"{len(coeffs)}  " + " ".join(map(str, coeffs))
        if lib.fmpz_poly_set_str(poly, text.encode()) != 0:
            raise SystemExit("flint-real: fmpz_poly_set_str refused the polynomial")
        deg = len(coeffs) - 1
        # Cauchy's bound 1 + max |c_i / c_d| on the roots' size, in bits
        bound = 1 + max(abs(c) for c in coeffs[:-1]) // abs(coeffs[-1]) + 1
        prec = 53 + bound.bit_length() + 2
        fz = lib._fmpz_vec_init(3)
        a, b, e = (ctypes.c_void_p(fz + 8 * i) for i in range(3))
        wall = cpu = 0.0
        while True:
            vec = lib._arb_vec_init(deg)
            t0, c0 = time.perf_counter(), time.process_time()
            n = lib.arb_fmpz_poly_real_roots(vec, poly, 0, prec)
            wall += time.perf_counter() - t0
            cpu += time.process_time() - c0
            out = []
            for i in range(n):
                lib.arb_get_interval_fmpz_2exp(a, b, e, ctypes.c_void_p(vec + i * self.ARB_SIZE))
                lo, hi, ex = self.text(a), self.text(b), self.text(e)
                scale = Fraction(2) ** ex
                out.append((lo * scale, hi * scale))
            lib._arb_vec_clear(vec, deg)
            if all(hi - lo <= WIDTH for lo, hi in out):
                break
            prec *= 2
        lib._fmpz_vec_clear(fz, 3)
        lib.fmpz_poly_clear(poly)
        out.sort()
        return wall, cpu, out


_FLINT_REAL = None


def run_flint_real(coeffs):
    global _FLINT_REAL
    if _FLINT_REAL is None:
        _FLINT_REAL = _FlintReal()  # loading the library is set-up, outside the timed region
    seconds, cpu, out = _FLINT_REAL.roots(coeffs)
    return _FLINT_REAL.version, seconds, cpu, out


def fmt(q):
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    tool, family, degree = sys.argv[1], sys.argv[2], int(sys.argv[3])
    if degree < 1:
        raise SystemExit("DEGREE must be at least 1")
    coeffs = coefficients(family, degree)
    runs = {"sympy": run_sympy, "flint-complex": run_flint, "flint-real": run_flint_real}
    if tool not in runs:
        raise SystemExit(f"unknown tool {tool!r} (sympy, flint-real, flint-complex)")
    # The warm-up (as `exactcheck-bench real-roots`): the same call on x^2 - 2, untimed, so that the
    # timed call measures the isolation rather than the first execution of its code.
    runs[tool](WARM_UP)
    version, seconds, cpu, roots = runs[tool](coeffs)
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
        "cpu_seconds": cpu,
        "threads": 1,
        "real_roots": len(roots),
        "roots": [[fmt(lo), fmt(hi)] for lo, hi in roots],
    }))


if __name__ == "__main__":
    main()
