#!/usr/bin/env bash
# The Python package's checks (issue 31): run.sh [--setup]
#
# Uses the virtual environment $ASPERITY_PYTHON_VENV (default
# ~/.cache/asperity/python-venv, outside the repository). With --setup it
# makes that environment afresh (python3 -m venv) and installs the package
# from this checkout the way a user does, `pip install ./bindings/python`
# (with the `plot` and `test` extras: matplotlib, pytest), which builds the
# extension from source with maturin and cargo. Without --setup it reinstalls
# the package into an existing environment, and a missing one prints
# "SKIPPED: <reason>" and exits 0, or 1 under ASPERITY_REQUIRE_ALL=1 (as
# does a machine without python3 or cargo). Then it runs pytest on
# bindings/python/tests; extra arguments go to pytest.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
pkg=$(cd "$here/.." && pwd)
venv=${ASPERITY_PYTHON_VENV:-$HOME/.cache/asperity/python-venv}

skip() {
  echo "SKIPPED: $1"
  [ "${ASPERITY_REQUIRE_ALL:-0}" = "1" ] && exit 1
  exit 0
}

setup=0
if [ "${1:-}" = "--setup" ]; then
  setup=1
  shift
fi
command -v python3 >/dev/null 2>&1 || skip "no python3 (CPython >= 3.9 with the venv module) to build the Python package"
command -v cargo >/dev/null 2>&1 || skip "no cargo: the Python package builds its extension with a Rust toolchain (https://rustup.rs)"

if [ "$setup" = 1 ]; then
  echo "run.sh: making $venv afresh and installing $pkg[plot,test]"
  rm -rf "$venv"
  python3 -m venv "$venv" || skip "python3 -m venv failed (on Debian: apt-get install python3-venv)"
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check --upgrade pip
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$pkg[plot,test]"
elif [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import pytest, numpy' >/dev/null 2>&1; then
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps "$pkg"
else
  skip "no Python environment at $venv (run bindings/python/tests/run.sh --setup)"
fi

cd "$pkg"
exec "$venv/bin/python" -m pytest -q "$here" "$@"
