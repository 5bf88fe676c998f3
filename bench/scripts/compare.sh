#!/usr/bin/env bash
# exactcheck side by side with SymPy, SymEngine, python-flint, gmpy2 and numpy on W1-W4, in one
# run: builds exactcheck (release), creates the anchors' virtual environment `.venv-anchors` from
# scripts/anchors/requirements.txt (PyPI; once), then runs scripts/compare.py, which checks that
# every tool gives the same check values and prints the tables of medians and ratios and the
# speed targets. Arguments go to compare.py (e.g. `--quick`, `--only W2,W3`, `--reps 3`,
# `--markdown table.md`). Takes about half an hour in full (SymPy's slow sizes dominate); not
# part of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
venv="${ANCHOR_VENV:-.venv-anchors}"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
"$venv/bin/pip" install --quiet --disable-pip-version-check -r scripts/anchors/requirements.txt
exec "$venv/bin/python" scripts/compare.py --python "$venv/bin/python" "$@"
