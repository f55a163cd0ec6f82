#!/usr/bin/env bash
# Memory and undefined-behaviour checks of the C, C++ and Fortran examples
# (RELIABILITY.md, "Memory and undefined behaviour"):
#
#  (a) valgrind memcheck (--leak-check=full, definite and indirect leaks are
#      errors, "still reachable" is not) on every example linked against the
#      shared and against the static library;
#  (b) every example compiled with -fsanitize=address,undefined
#      -fno-omit-frame-pointer -fno-sanitize-recover=all (LeakSanitizer on)
#      and linked against the static library.
#
# A language is skipped, with the reason printed, when its compiler is
# missing; (a) is skipped when valgrind is. Exits non-zero on any error.
#
# Usage: scripts/memcheck.sh [--valgrind-only | --sanitizers-only]
# Environment: CARGO_TARGET_DIR (default target), MEMCHECK_PROFILE (cargo
# profile of the library, default dev: the build `cargo test` already made),
# CC, CXX, FC (compilers, default cc, c++, gfortran), MEMCHECK_JOBS
# (parallel runs, default the number of CPUs).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

mode=${1:-all}
case "$mode" in
  all | --valgrind-only | --sanitizers-only) ;;
  *) echo "usage: $0 [--valgrind-only | --sanitizers-only]" >&2; exit 2 ;;
esac

profile=${MEMCHECK_PROFILE:-dev}
case "$profile" in dev) profile_dir=debug ;; *) profile_dir=$profile ;; esac
target=${CARGO_TARGET_DIR:-$root/target}
lib_dir="$target/$profile_dir"
out="$target/memcheck"
jobs=${MEMCHECK_JOBS:-$(nproc 2>/dev/null || echo 2)}
CC=${CC:-cc}
CXX=${CXX:-c++}
FC=${FC:-gfortran}
# Each entry explained in the file; none is needed on Linux/glibc today.
supp="$root/scripts/memcheck.supp"

start=$(date +%s)
echo "memcheck: building the library (profile $profile)"
cargo build --quiet --lib --profile "$profile"
mkdir -p "$out"
rm -f "$out"/*.log

# The native libraries a static Rust library needs (as tests/common/native.rs).
static_libs=(-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc)
shared_link=(-L"$lib_dir" -lasperity -Wl,-rpath,"$lib_dir" -lm)
static_link=("$lib_dir/libasperity.a" "${static_libs[@]}")
san=(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
# Fortran: the same without UBSan's null check. gfortran 12 flags passing an
# absent OPTIONAL contiguous array on to another OPTIONAL dummy (legal
# Fortran 2008, 12.5.2.12; what every `loc_d(x)` of bindings/fortran does)
# as "load of null pointer": the instrumented expression is the address
# &x(1), which is never read. A 20-line program with no asperity in it
# reproduces it. Everything else of -fsanitize=undefined stays on.
fsan=("${san[@]}" -fno-sanitize=null)

have() { command -v "$1" >/dev/null 2>&1; }
do_valgrind=1
do_san=1
[ "$mode" = --sanitizers-only ] && do_valgrind=0
[ "$mode" = --valgrind-only ] && do_san=0
# A tool that is missing skips its runs; under ASPERITY_REQUIRE_ALL=1 (set by
# .ci/run) it fails the script instead.
missing() {
  echo "memcheck: SKIPPED $1"
  if [ "${ASPERITY_REQUIRE_ALL:-0}" = 1 ]; then
    echo "memcheck: ASPERITY_REQUIRE_ALL=1 forbids skipping" >&2
    exit 1
  fi
}
if [ $do_valgrind = 1 ] && ! have valgrind; then
  missing "valgrind runs: valgrind not found (apt-get install valgrind)"
  do_valgrind=0
fi

# name|binary|args: the runs, collected while building.
runs=()
build_failed=0

build() { # label, command...
  local label=$1
  shift
  if ! "$@" >"$out/$label.build.log" 2>&1; then
    echo "memcheck: FAILED to build $label:"
    cat "$out/$label.build.log"
    build_failed=1
    return 1
  fi
}

# Examples too slow for valgrind in CI: every_function.cpp calls
# asperity_fidelity_advise, which runs the Lennard-Jones reference solution
# (about a second optimised; over five minutes under valgrind on the dev
# profile); tabulated_threads.c runs 8 threads of table lookups (40 s under
# valgrind for each linkage). Both run under the sanitizers, and under
# valgrind with MEMCHECK_VALGRIND_ALL=1 (clean when last run: RELIABILITY.md).
valgrind_skip=" cpp-every_function c-tabulated_threads "

add_runs() { # name, base binary path (without -shared/-static/-asan), args
  local name=$1 bin=$2 args=${3:-}
  if [ $do_valgrind = 1 ] && [ "${MEMCHECK_VALGRIND_ALL:-0}" != 1 ] && [[ $valgrind_skip == *" $name "* ]]; then
    echo "memcheck: SKIPPED valgrind $name (slow: see valgrind_skip; MEMCHECK_VALGRIND_ALL=1 runs it)"
  elif [ $do_valgrind = 1 ]; then
    runs+=("valgrind|$name-shared|$bin-shared|$args")
    runs+=("valgrind|$name-static|$bin-static|$args")
  fi
  if [ $do_san = 1 ]; then
    runs+=("asan|$name-asan|$bin-asan|$args")
  fi
}

build_variants() { # name, compiler, flags-file-var..., sources... (via arrays)
  local name=$1 tool=$2
  shift 2
  local -a src=("$@")
  local bin="$out/$name"
  if [ $do_valgrind = 1 ]; then
    build "$name-shared" "$tool" "${flags[@]}" -g "${src[@]}" -o "$bin-shared" "${shared_link[@]}" || return 0
    build "$name-static" "$tool" "${flags[@]}" -g "${src[@]}" -o "$bin-static" "${static_link[@]}" || return 0
  fi
  if [ $do_san = 1 ]; then
    build "$name-asan" "$tool" "${flags[@]}" -g "${san[@]}" "${src[@]}" -o "$bin-asan" "${static_link[@]}" || return 0
  fi
}

# ---------------------------------------------------------------- C
if have "$CC"; then
  flags=(-std=c99 -Wall -Wextra -Werror -pedantic -I "$root/include")
  for src in examples/c/*.c; do
    name=c-$(basename "$src" .c)
    build_variants "$name" "$CC" "$src" && add_runs "$name" "$out/$name"
  done
else
  missing "C examples: no C compiler ($CC)"
fi

# ---------------------------------------------------------------- C++
if have "$CXX"; then
  flags=(-std=c++17 -Wall -Wextra -Werror -pedantic -I "$root/include" -I "$root/bindings/cpp")
  # Programs: one per file, except name_a.cpp + name_b.cpp (+ ...) which
  # are the translation units of one program `name`.
  declare -A units=()
  for src in examples/cpp/*.cpp; do
    stem=$(basename "$src" .cpp)
    if [[ $stem =~ ^(.+)_[a-z]$ ]]; then prog=${BASH_REMATCH[1]}; else prog=$stem; fi
    units[$prog]="${units[$prog]:-} $src"
  done
  for prog in $(printf '%s\n' "${!units[@]}" | sort); do
    name=cpp-$prog
    # shellcheck disable=SC2086
    build_variants "$name" "$CXX" ${units[$prog]} && add_runs "$name" "$out/$name"
  done
else
  missing "C++ examples: no C++ compiler ($CXX)"
fi

# ---------------------------------------------------------------- Fortran
if have "$FC"; then
  mods="$out/fortran-mod"
  mkdir -p "$mods"
  # As tests/fortran_bindings.rs (vfric.f90 needs -Wno-unused-dummy-argument:
  # its argument list is Abaqus's).
  fflags=(-std=f2008 -Wall -Wextra -Werror -fimplicit-none -Wno-unused-dummy-argument -fcheck=bounds,do,mem,pointer,recursion)
  if build fortran-module "$FC" "${fflags[@]}" -g -J "$mods" -c bindings/fortran/asperity.f90 -o "$out/asperity_f.o" &&
    { [ $do_san = 0 ] || build fortran-module-asan "$FC" "${fflags[@]}" -g "${fsan[@]}" -J "$mods" -c bindings/fortran/asperity.f90 -o "$out/asperity_f_asan.o"; }; then
    for src in examples/fortran/*.f90; do
      stem=$(basename "$src" .f90)
      name=f-$stem
      bin="$out/$name"
      own="$out/fortran-mod-$stem"
      mkdir -p "$own"
      ok=1
      if [ $do_valgrind = 1 ]; then
        build "$name.o" "$FC" "${fflags[@]}" -g -I "$mods" -J "$own" -c "$src" -o "$bin.o" &&
          build "$name-shared" "$FC" "$bin.o" "$out/asperity_f.o" -o "$bin-shared" "${shared_link[@]}" &&
          build "$name-static" "$FC" "$bin.o" "$out/asperity_f.o" -o "$bin-static" "${static_link[@]}" || ok=0
      fi
      if [ $do_san = 1 ] && [ $ok = 1 ]; then
        build "$name-asan.o" "$FC" "${fflags[@]}" -g "${fsan[@]}" -I "$mods" -J "$own" -c "$src" -o "$bin-asan.o" &&
          build "$name-asan" "$FC" "${fsan[@]}" "$bin-asan.o" "$out/asperity_f_asan.o" -o "$bin-asan" "${static_link[@]}" || ok=0
      fi
      [ $ok = 1 ] && add_runs "$name" "$bin"
    done
  fi
else
  missing "Fortran examples: no Fortran compiler ($FC)"
fi

built=$(date +%s)
echo "memcheck: built in $((built - start)) s; ${#runs[@]} runs, $jobs at a time"

# ---------------------------------------------------------------- runs
run_one() { # kind|label|binary|args
  IFS='|' read -r kind label bin args <<<"$1"
  local log="$out/$label.log"
  local -a cmd
  if [ "$kind" = valgrind ]; then
    cmd=(valgrind --tool=memcheck --error-exitcode=1 --leak-check=full
      --errors-for-leak-kinds=definite,indirect --show-leak-kinds=definite,indirect
      --track-origins=yes --suppressions="$supp" --quiet)
  else
    cmd=(env "ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1:strict_init_order=1"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  fi
  local t0=$SECONDS status=0
  # shellcheck disable=SC2086
  "${cmd[@]}" "$bin" $args </dev/null >"$log" 2>&1 || status=$?
  if [ $status = 0 ]; then
    echo "ok    $kind $label ($((SECONDS - t0)) s)"
  else
    echo "FAIL  $kind $label (exit $status, $((SECONDS - t0)) s); log $log:"
    tail -n 60 "$log"
    return 1
  fi
}
export -f run_one
export out supp

failed=0
if [ ${#runs[@]} -gt 0 ]; then
  printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one "$@"' _ {} || failed=1
fi
end=$(date +%s)
echo "memcheck: runs took $((end - built)) s, $((end - start)) s in all"
if [ $failed != 0 ] || [ $build_failed != 0 ]; then
  echo "memcheck: FAILED"
  exit 1
fi
echo "memcheck: all clean"
