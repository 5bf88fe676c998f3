#!/usr/bin/env bash
# Regenerates the seed corpus fuzz/seeds/<target>/ from the repository: the `prove`
# examples of README.md and docs/prove.md, tests/solve_golden, the claims files of examples/ and tests/claims_file, the FPCore
# suite of tests/regress, a few hand-made elements of the radical field and output paths. Run
# from anywhere; the seeds are small and committed, the corpus the fuzzer grows (fuzz/corpus) is
# not.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf fuzz/seeds
mkdir -p fuzz/seeds/{expr_roundtrip,solve_json,prove,radical,fpcore,claims_file,output_path,printed}

python3 - <<'PY'
import glob, hashlib, os, re, shlex

def put(target, data):
    if isinstance(data, str):
        data = data.encode()
    name = hashlib.sha1(data).hexdigest()[:16]
    with open(f"fuzz/seeds/{target}/{name}", "wb") as f:
        f.write(data)

# `exactcheck prove ...` lines of the README and the prove guide (with their continuation lines).
readme = "".join(open(p).read() for p in ["README.md", "docs/prove.md"]).replace("\\\n", " ")
expressions = set()
for line in readme.splitlines():
    line = line.strip()
    if not line.startswith("exactcheck prove "):
        continue
    try:
        words = shlex.split(line)[2:]
    except ValueError:
        continue
    plain, where, mode = [], [], "e"
    i = 0
    while i < len(words):
        w = words[i]
        if w == "--where" and i + 1 < len(words):
            where.append(words[i + 1]); i += 2; continue
        if w == "--random":
            mode = "r"; i += 2; continue
        if w in ("--json", "--seed"):
            i += 2 if w == "--seed" else 1; continue
        plain.append(w); i += 1
    if not plain:
        continue
    lhs, rhs = plain[0], (plain[1] if len(plain) > 1 else "")
    put("prove", "\n".join([mode, lhs, rhs] + where))
    put("prove", "\n".join(["j", lhs, rhs] + where))
    for e in [lhs, rhs] + [w for r in where for w in re.split(r"[=<>]+", r)]:
        if e.strip():
            expressions.add(e.strip())
# More expressions: every syntax the prove guide lists.
expressions |= {
    "0.1 + 2.5e-3 - 1E+5", "sqrt(2)*sqrt(3) - sqrt(6)", "(x+1)^3", "2x y^2", "-x^2",
    "-(x^2)", "x/3 - 1/(2*3)", "(sqrt(2)+sqrt(3))^2/5", "((a+b)*(a-b))^2", "1e5",
    "sqrt(3 - 2*sqrt(2))", "x^0 + 0^0",
}
for e in sorted(expressions):
    put("expr_roundtrip", e)
put("prove", "e\nsqrt(2)*sqrt(8)\n4")
# Vectors and matrices as printed in LaTeX, with the definitions of their bold names.
for seed in [
    "e\n\\|\\mathbf{u}\\times\\mathbf{v}\\|^2\n\\|\\mathbf{u}\\|^2\\|\\mathbf{v}\\|^2 - (\\mathbf{u}\\cdot\\mathbf{v})^2\ndef u = [u1, u2, u3]\ndef v = [v1, v2, v3]",
    "e\n\\vec{a}\\times(\\vec{b}\\times\\vec{c})\n\\vec{b}(\\vec{a}\\cdot\\vec{c}) - \\vec{c}(\\vec{a}\\cdot\\vec{b})\ndef a = [a1, a2, a3]\ndef b = [b1, b2, b3]\ndef c = [c1, c2, c3]",
    "e\n\\det(\\mathbf{M}^2)\n\\det(\\mathbf{M})^2\ndef M = [[a, b], [c, d]]",
    "e\n\\mathbf{a}\\cdot\\mathbf{b}\\times\\mathbf{c}\n0\ndef a = [1, 2, 3]\ndef b = [x, y, z]\ndef c = [3, 2, 1]",
    "e\n\\lVert\\vec{x}\\rVert\n\\mathbf{y}\\cdot\\mathbf{y}",
    "e\nM^0\n[[1, 0], [0, 1]]\ndef M = [[a, b], [c, d]]",
]:
    put("prove", seed)
put("prove", "e\n(x+y)^3\nx^3+3x^2y+3x y^2+y^3\n0 <= x <= 1")
put("prove", "r\nc^4 - s^4\nc^2 - s^2\nc^2 + s^2 = 1")
# Inputs the fuzzer found slow, kept as seeds (a 74th power of a 4-term base that
# took 8.4 s by binary powering, now the power recurrence).
put("prove", b"?m\n+16(t+ 1x^2+y+3x y_x)^74\xec3\xff\x9d\xa1+3N")
# A residual over Q(sqrt) whose square-free factorization for printing swelled its
# coefficients for minutes (the work bound counted each radical coefficient as one word).
put("prove", "e\n(p0^2+p1^2+p2^2+p32^2+p2)^3^2\n(2*p*p01 sqrtp2*p3)^2 + (2*p0*p2 + 2*p2*3*p3)^2 + (22+p^2-p3^2)^2")

for path in sorted(glob.glob("tests/solve_golden/*.json")):
    put("solve_json", open(path, "rb").read())

for path in sorted(glob.glob("examples/*.toml") + glob.glob("tests/claims_file/*")):
    flag = b"j" if path.endswith(".json") else b"t"
    put("claims_file", flag + open(path, "rb").read())

# The FPCore suite, whole and one benchmark per seed.
suite = open("tests/regress/suite.fpcore").read()
put("fpcore", suite)
for part in re.split(r"\n(?=\(FPCore)", suite):
    if part.strip():
        put("fpcore", part)

# Radical elements: a split byte, then (radicand, numerator, denominator) triples.
for seed in [
    bytes([3, 1, 1, 0, 2, 1, 0, 1, 255, 0]),
    bytes([6, 1, 1, 0, 2, 1, 0, 3, 3, 1, 2, 255, 0, 3, 1, 0]),
    bytes([9, 3, 7, 2, 5, 250, 4, 15, 1, 0, 6, 1, 1, 1, 2, 3]),
    bytes([0, 1, 1, 0, 2, 255, 0, 3, 2, 5]),
    bytes([12, 16, 3, 0, 1, 9, 0, 15, 128, 15, 2, 127, 1, 14, 4, 2, 7, 100, 5, 9, 1, 1, 3, 33, 7]),
]:
    put("radical", seed)

# Output paths: plain, hidden, nested, directories, standard output, long and multi-byte names.
for seed in ["out.svg", "./-", "-", "", "out/", "out.svg/.", "a/..", "/dev/stdout",
             "a//b/./c.svg", ".hidden", "x" * 300, "\u00e9" * 120, "a\nb.svg"]:
    put("output_path", seed)
# Printed decimals: an exact value, a newline, a printed decimal (long ones, ties, misprints).
for seed in [
    "1/3\n0." + "3" * 40,
    "1/3\n0.33333333333333333334",
    "1/200\n0.00500000000000001",
    "sqrt(2)\n1.414213562373095",
    "10^19\n10000000000000000000",
    "(2*sqrt(2) + sqrt(6))/3\n1.76",
    "-sqrt(2)/2\n-0.705",
    "101/8\n12.62",
    "1.3\n0033333333333333333303333333323345^63*333",
    "3400^174\n0",
    "sqrt(2)+sqrt(3)-sqrt(5)\n0.910",
    "0\n0.000",
]:
    put("printed", seed)
PY
for t in expr_roundtrip solve_json prove radical fpcore claims_file output_path printed; do
  echo "$t: $(ls fuzz/seeds/$t | wc -l) seeds"
done
