#!/usr/bin/env bash
# The FEniCSx checks (issue 32): examples/fe/run.sh [--setup]
#
# The host is Debian's python3-dolfinx (FEniCSx 0.5.2, PETSc, Open MPI) in
# the system interpreter /usr/bin/python3. This project's Python package is
# installed into a virtual environment made with --system-site-packages
# ($ASPERITY_FE_VENV, default ~/.cache/asperity/fe-venv, outside the
# repository), so both import. With --setup the environment is made afresh
# and the package installed from this checkout with pip; without it the
# package is reinstalled into an existing environment. A machine without
# dolfinx or the environment prints "SKIPPED: <reason>" and exits 0, or 1
# under ASPERITY_REQUIRE_ALL=1. .ci/run installs the Debian packages first.
#
# Then both models run serially and on 2 MPI ranks, their JSON goes to
# $ASPERITY_FE_OUT (default target/fe) and check.py asserts the figures:
# c/a within 3 % of Cattaneo-Mindlin at the finest of three meshes, Newton
# converged to 1e-10 in at most 8 solves per load step, the energy balance,
# and the same results on 1 and 2 ranks.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
venv=${ASPERITY_FE_VENV:-$HOME/.cache/asperity/fe-venv}
out=${ASPERITY_FE_OUT:-$root/target/fe}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One thread per rank: the two ranks share the machine's cores.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

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
[ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import dolfinx' >/dev/null 2>&1 ||
  skip "no dolfinx in /usr/bin/python3 (apt-get install -y --no-install-recommends python3-dolfinx)"
command -v mpirun >/dev/null 2>&1 || skip "no mpirun (apt-get install -y openmpi-bin)"
command -v cargo >/dev/null 2>&1 || skip "no cargo: the Python package builds its extension with a Rust toolchain"

if [ "$setup" = 1 ]; then
  echo "run.sh: making $venv afresh (system site packages) and installing $root/bindings/python"
  rm -rf "$venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$root/bindings/python"
elif [ -x "$venv/bin/python" ]; then
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps "$root/bindings/python"
else
  skip "no environment at $venv (run examples/fe/run.sh --setup)"
fi
py="$venv/bin/python"
"$py" -c 'import asperity, dolfinx' || skip "asperity and dolfinx do not import together in $venv"

mkdir -p "$out"
cd "$here"
run() { # run NAME RANKS SCRIPT ARGS...
  local name=$1 ranks=$2
  shift 2
  echo "run.sh: $name on $ranks rank(s)"
  local t0=$SECONDS
  set +e
  if [ "$ranks" = 1 ]; then
    timeout 600 "$py" "$@" --json >"$out/$name.json" 2>"$out/$name.log"
  else
    timeout 600 mpirun -np "$ranks" "$py" "$@" --json >"$out/$name.json" 2>"$out/$name.log"
  fi
  local rc=$?
  set -e
  echo "run.sh:   $((SECONDS - t0)) s"
  if [ $rc != 0 ]; then
    tail -20 "$out/$name.log"
    echo "run.sh: $name failed (exit $rc)"
    exit 1
  fi
}
run cattaneo_mindlin_1 1 cattaneo_mindlin.py --meshes 8,16,32 --compare-tangents
run cattaneo_mindlin_2 2 cattaneo_mindlin.py --meshes 8,16,32
run energy_homogenised_1 1 energy_law.py --law homogenised
run energy_homogenised_2 2 energy_law.py --law homogenised
run energy_maxwell_slip_1 1 energy_law.py --law maxwell_slip
run energy_maxwell_slip_2 2 energy_law.py --law maxwell_slip
"$py" check.py "$out"
