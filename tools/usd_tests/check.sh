#!/bin/sh
# modesplit export --usd, read back with pxr (tools/usd_tests/test_usd_export.py).
#   tools/usd_tests/check.sh BUILD_DIR [--venv]
# --venv (CI): make BUILD_DIR/venv-usd and pip-install usd-core, h5py, numpy
# and pytest into it. Without it, python3 must import pxr, h5py and pytest,
# or the check is skipped (exit 77), which fails when MS_TEST_NO_SKIP=1.
set -eu
build=${1:-build}
root=$(cd "$(dirname "$0")/../.." && pwd)
py=python3
if [ "${2:-}" = --venv ]; then
    venv=$build/venv-usd
    [ -x "$venv/bin/python" ] || python3 -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        usd-core h5py numpy pytest
    py=$venv/bin/python
fi
if ! "$py" -c "import pxr, h5py, numpy, pytest" 2>/dev/null; then
    echo "check-usd: SKIPPED: $py cannot import pxr, h5py, numpy and pytest (use --venv)"
    [ "${MS_TEST_NO_SKIP:-0}" = 1 ] && { echo "check-usd: a skip fails in CI"; exit 1; }
    exit 77
fi
MODESPLIT=$(cd "$build" && pwd)/bin/modesplit PATH="$(dirname "$py"):$PATH" \
    "$py" -m pytest -q -p no:cacheprovider "$root/tools/usd_tests"
