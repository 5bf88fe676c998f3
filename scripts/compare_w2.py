#!/usr/bin/env python3
"""W2 side by side: exactcheck (fast Rational, plain BigRational) against the anchor scripts.

Usage: python3 scripts/compare_w2.py [--reps K] [--anchors DIR] [--python PY] [--skip-plain]

Runs every tool on the same workloads in the same run (eval and tree at N = 100,000, seq at
N = 2,000), K repetitions each (default 3), and prints a Markdown table of median seconds and the
ratio to gmpy2. Every run's check values must agree with the others; a mismatch is an error.
Needs `cargo build --release` first, and a Python with gmpy2 / python-flint for the anchors
(e.g. `python3 -m venv .venv-anchors && .venv-anchors/bin/pip install gmpy2 python-flint`).
"""
import argparse, json, os, statistics, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
p = argparse.ArgumentParser()
p.add_argument("--reps", type=int, default=3)
p.add_argument("--anchors", default=os.path.join(ROOT, "..", "shared", "anchors"))
p.add_argument("--python", default=os.path.join(ROOT, ".venv-anchors", "bin", "python"))
p.add_argument("--skip-plain", action="store_true", help="skip num-rational's BigRational (slow)")
args = p.parse_args()

BIN = os.path.join(ROOT, "target", "release", "exactcheck")
WORK = [("eval", 100000), ("tree", 100000), ("seq", 2000)]
CHECK = ("count_nonneg", "sum_num_digits", "sum_den_digits", "sum_num_mod_p", "sum_den_mod_p")


def run(cmd):
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


tools = [("exactcheck Rational", lambda m, n: [BIN, "bench", "w2", "--mode", m, "--n", str(n), "--json"])]
if not args.skip_plain:
    tools.append(("num-rational BigRational", lambda m, n: [BIN, "bench", "w2", "--mode", m, "--n", str(n), "--scalar", "plain", "--json"]))
for tool in ("gmpy2", "flint", "fraction"):
    tools.append((tool, lambda m, n, t=tool: [args.python, os.path.join(args.anchors, "w2_rational.py"), t, m, str(n)]))

rows = {}
for name, cmd in tools:
    for mode, n in WORK:
        if name in ("fraction", "num-rational BigRational") and mode == "tree":
            reps = 1  # tens of seconds a run
        else:
            reps = args.reps
        times, checks = [], None
        for _ in range(reps):
            r = run(cmd(mode, n))
            times.append(r["seconds"])
            c = tuple(r.get(k) for k in CHECK)
            if checks is not None and c != checks:
                sys.exit(f"{name} {mode}: check values differ between runs")
            checks = c
        rows[(name, mode)] = (statistics.median(times), checks, reps)
        print(f"{name:26} {mode:5} N={n:<6} median {statistics.median(times):.4f} s  {checks}", file=sys.stderr)

for mode, _ in WORK:
    ref = rows[("gmpy2", mode)][1]
    for name, _ in tools:
        if rows[(name, mode)][1] != ref:
            sys.exit(f"{name} {mode}: check values {rows[(name, mode)][1]} differ from gmpy2's {ref}")

print("| tool | eval, N = 100,000 | tree, N = 100,000 | seq, N = 2,000 |")
print("| --- | --- | --- | --- |")
for name, _ in tools:
    cells = []
    for mode, _ in WORK:
        t, _, reps = rows[(name, mode)]
        g = rows[("gmpy2", mode)][0]
        cells.append(f"{t:.3f} s ({t / g:.2f}x)" if t >= 0.1 else f"{t * 1000:.1f} ms ({t / g:.2f}x)")
    print(f"| {name} | " + " | ".join(cells) + " |")
