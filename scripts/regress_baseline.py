#!/usr/bin/env python3
"""Python baseline for the exact side of `exactcheck regress`: one formula, evaluated exactly.

Usage: python3 scripts/regress_baseline.py [--n N] [--seed S] [--reps K] [--tools LIST] [--json]

Evaluates the throughput formula of docs/regress.md

    F(x, y, z, w) = ((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y

exactly on N samples (default 100,000) of four doubles uniform in [-1, 1], with
`fractions.Fraction` and, when it is importable, `gmpy2.mpq` (LIST: fraction,gmpy2; the default
is every one available). Each double enters exactly (`Fraction(x)`, `mpq(x)`: the binary value,
not its decimal), as on exactcheck's exact side. The timed region is the conversion of the inputs
and the evaluation, K repetitions (default 1), the median reported; drawing the inputs and the
check values are outside it.

The inputs are the ones exactcheck draws: sample i is four `uniform(-1, 1)` draws of the
workspace generator's stream `Rng::for_sample(seed, i)` (xoshiro256** seeded by SplitMix64,
core/src/rng.rs, re-implemented below and checked against its known answers), i.e.
`sample_inputs(UniformBox::cube(4, -1.0, 1.0), seed, i)`. So a Rust run on the same seed and N can
compare its check values with these:
  sum_num_mod_p, sum_den_mod_p: the sums over the samples of the numerator and the (positive)
      denominator of F in lowest terms, each reduced mod p = 2^61 - 1 (into [0, p));
  fsum: the correctly rounded sum of the correctly rounded doubles of the exact values (math.fsum
      over num / den, which Python rounds correctly for integers);
  first: the first sample's inputs, shortest round-trip decimals.
Prints one line per tool (or, with --json, one JSON object per line) and exits with an error if
the tools' check values differ. gmpy2: `python3 -m venv .venv-anchors &&
.venv-anchors/bin/pip install gmpy2`, then run the script with `.venv-anchors/bin/python`.
"""
import argparse, json, math, platform, statistics, sys, time

p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
p.add_argument("--n", type=int, default=100_000, help="number of samples (default 100000)")
p.add_argument("--seed", type=int, default=1, help="generator seed, as regress --seed (default 1)")
p.add_argument("--reps", type=int, default=1, help="timed repetitions, median reported (default 1)")
p.add_argument("--tools", default=None, help="comma-separated: fraction,gmpy2 (default: all available)")
p.add_argument("--json", action="store_true", help="one JSON object per tool and line")
args = p.parse_args()
if args.n < 1 or args.reps < 1 or not 0 <= args.seed < 2**64:
    sys.exit("--n and --reps must be positive and --seed in [0, 2^64)")

# --- the workspace generator (core/src/rng.rs), bit for bit --------------------------------------
M64 = (1 << 64) - 1


def splitmix64(state):
    """One SplitMix64 step: (new state, output)."""
    state = (state + 0x9E3779B97F4A7C15) & M64
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
    return state, z ^ (z >> 31)


def rotl(x, k):
    return ((x << k) | (x >> (64 - k))) & M64


class Rng:
    """xoshiro256** seeded through SplitMix64, as exactcheck_core::rng::Rng."""

    def __init__(self, seed=None, state=None):
        if state is None:
            s, out = seed, []
            for _ in range(4):
                s, o = splitmix64(s)
                out.append(o)
            state = out
        self.s = list(state) if any(state) else Rng(0).s

    @staticmethod
    def for_sample(seed, index):
        _, a = splitmix64(seed)
        _, b = splitmix64(index ^ 0xD1B54A32D192ED03)
        return Rng(a ^ rotl(b, 17))

    def next_u64(self):
        s = self.s
        result = (rotl((s[1] * 5) & M64, 7) * 9) & M64
        t = (s[1] << 17) & M64
        s[2] ^= s[0]
        s[3] ^= s[1]
        s[1] ^= s[2]
        s[0] ^= s[3]
        s[2] ^= t
        s[3] = rotl(s[3], 45)
        return result

    def next_f64(self):
        return float(self.next_u64() >> 11) * (1.0 / float(1 << 53))

    def uniform(self, lo, hi):
        t = self.next_f64()
        x = lo * (1.0 - t) + hi * t
        if math.isnan(x):
            return lo
        return min(max(x, min(lo, hi)), max(lo, hi))


# The known answers pinned by core/src/rng.rs's tests.
assert splitmix64(0)[1] == 0xE220A8397B1DCDAF and splitmix64(splitmix64(0)[0])[1] == 0x6E789E6AA1B965F4
_r = Rng(state=[1, 2, 3, 4])
assert [_r.next_u64() for _ in range(4)] == [11520, 0, 1509978240, 1215971899390074240]


def sample(seed, i):
    r = Rng.for_sample(seed, i)
    return tuple(r.uniform(-1.0, 1.0) for _ in range(4))


# --- the formula -------------------------------------------------------------------------------
# F = ((x + y) * (z - w) - x * z / (y + 2)) * (w + 1) + x*y, in the order written:
#   x + y, z - w, (x+y)*(z-w), x*z, y + 2, x*z/(y+2), difference, w + 1, product, x*y, sum:
#   11 operations (6 additions/subtractions, 4 multiplications, 1 division; one count calls it
#   "a 10-operation formula"). y + 2 >= 1 on [-1, 1]: no sample is outside the domain.
def make_f(two, one):
    def f(x, y, z, w):
        return ((x + y) * (z - w) - x * z / (y + two)) * (w + one) + x * y
    return f


def tools():
    from fractions import Fraction
    yield "fraction", "CPython " + platform.python_version() + " fractions", Fraction, lambda q: (q.numerator, q.denominator)
    try:
        import gmpy2
    except ImportError:
        print("gmpy2 is not importable: fraction only", file=sys.stderr)
        return
    yield "gmpy2", "gmpy2 " + gmpy2.version() + " (" + gmpy2.mp_version() + ")", gmpy2.mpq, lambda q: (int(q.numerator), int(q.denominator))


P = (1 << 61) - 1
wanted = None if args.tools is None else set(args.tools.split(","))
if wanted is not None and not wanted <= {"fraction", "gmpy2"}:
    sys.exit(f"--tools: unknown tool(s) {sorted(wanted - {'fraction', 'gmpy2'})}; known: fraction, gmpy2")
inputs = [sample(args.seed, i) for i in range(args.n)]

rows = []
for name, version, Q, parts in tools():
    if wanted is not None and name not in wanted:
        continue
    f = make_f(Q(2), Q(1))
    times, cpu_times = [], []
    for _ in range(args.reps):
        t0, c0 = time.perf_counter(), time.process_time()
        results = [f(Q(x), Q(y), Q(z), Q(w)) for (x, y, z, w) in inputs]
        times.append(time.perf_counter() - t0)
        cpu_times.append(time.process_time() - c0)
    nd = [parts(r) for r in results]
    check = {
        "sum_num_mod_p": sum(n % P for n, _ in nd) % P,
        "sum_den_mod_p": sum(d % P for _, d in nd) % P,
        "fsum": repr(math.fsum(n / d for n, d in nd)),
        "first": "[" + ", ".join(repr(v) for v in inputs[0]) + "]",
    }
    secs = statistics.median(times)
    row = {"tool": name, "version": version, "n": args.n, "seed": args.seed, "reps": args.reps,
           "seconds": secs, "cpu_seconds": statistics.median(cpu_times),
           "samples_per_second": args.n / secs, **check}
    rows.append(row)
    if args.json:
        print(json.dumps(row))
    else:
        print(f"{name:8} {version}: {args.n} samples in {secs:.3f} s = {args.n / secs:,.0f} samples/s, "
              f"{row['cpu_seconds']:.3f} s CPU; "
              f"sum_num_mod_p {check['sum_num_mod_p']}, sum_den_mod_p {check['sum_den_mod_p']}, "
              f"fsum {check['fsum']}, first {check['first']}")

if not rows:
    sys.exit("no tool ran (is --tools naming one that is importable?)")
keys = ("sum_num_mod_p", "sum_den_mod_p", "fsum", "first")
for r in rows[1:]:
    if any(r[k] != rows[0][k] for k in keys):
        sys.exit(f"check values of {r['tool']} differ from {rows[0]['tool']}'s")
