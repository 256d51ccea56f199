#!/usr/bin/env bash
# Installs NumPy and SciPy into target/scipy-venv (once) and runs the splprep baseline.
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/scipy-venv
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import scipy" 2>/dev/null; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet numpy scipy
fi
exec "$venv/bin/python" benches/scipy/splprep_compare.py
