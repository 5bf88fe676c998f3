#!/usr/bin/env bash
# exactcheck side by side with SymPy, SymEngine, python-flint, gmpy2 and numpy on the benchmark
# workloads, in one run: builds exactcheck (release), creates the anchors' virtual environment `.venv-anchors` from
# bench/scripts/anchors/requirements.txt (PyPI; once), then runs bench/scripts/compare.py, which checks that
# every tool gives the same check values and prints the tables of medians and ratios and the
# speed targets. Arguments go to compare.py (e.g. `--quick`, `--only rational-sum,sample-sphere`, `--reps 3`,
# `--markdown table.md`). Takes about half an hour in full (SymPy's slow sizes dominate); not
# part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet -p exactcheck -p exactcheck-bench
venv="${ANCHOR_VENV:-.venv-anchors}"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
"$venv/bin/pip" install --quiet --disable-pip-version-check -r bench/scripts/anchors/requirements.txt
exec "$venv/bin/python" bench/scripts/compare.py --python "$venv/bin/python" "$@"
