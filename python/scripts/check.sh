#!/usr/bin/env bash
# The Python package's checks, as .ci/run runs them: a fresh virtualenv, numpy, scipy, pytest
# and hypothesis from PyPI, the wheel built by `pip install ./python` (maturin from PyPI; the
# Rust build goes to $CARGO_TARGET_DIR when it is set), then the package's tests, its doctests
# and SciPy's own test file (python/tests/scipy_suite.py). Prints SKIPPED and exits 0 where
# Python, venv or PyPI cannot be had; any test failure exits 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if ! command -v python3 >/dev/null; then
    echo "SKIPPED: no python3; the Python package was not built or tested"
    exit 0
fi
if ! python3 -m venv "$work/venv" >/dev/null 2>&1; then
    echo "SKIPPED: python3 has no working venv module; the Python package was not built or tested"
    exit 0
fi
py=$work/venv/bin/python
if ! timeout 300 "$py" -m pip install -q numpy scipy pytest hypothesis >"$work/pip.log" 2>&1; then
    tail -5 "$work/pip.log"
    echo "SKIPPED: numpy, scipy, pytest and hypothesis could not be installed from PyPI; the Python package was not tested"
    exit 0
fi
"$py" -m pip install -q "$root/python" >"$work/build.log" 2>&1 || {
    tail -40 "$work/build.log"
    echo "pip install ./python failed" >&2
    exit 1
}
# From a folder outside python/, whose nyquist/ would shadow the installed package.
cd "$work"
"$py" -m pytest -q -p no:cacheprovider "$root/python/tests"
"$py" -m pytest -q -p no:cacheprovider --doctest-modules --pyargs nyquist
"$py" "$root/python/tests/scipy_suite.py" --tb=line
