#!/usr/bin/env bash
# Install asperity for C, C++ and Fortran host codes:
#
#   scripts/install.sh --prefix /usr/local
#
# builds the library in release mode and installs
#   PREFIX/include/asperity.h, asperity.hpp       C and C++ headers
#   PREFIX/lib/libasperity.so.MAJOR.MINOR.PATCH   shared library, soname libasperity.so.ABI,
#   PREFIX/lib/libasperity.so.ABI, .so            and the two usual links
#   PREFIX/lib/libasperity.a                      static library
#   PREFIX/lib/pkgconfig/asperity.pc              pkg-config (static: pkg-config --static)
#   PREFIX/lib/cmake/asperity/                    CMake package: find_package(asperity) gives
#                                                 asperity::asperity (shared) and
#                                                 asperity::asperity_static
#   PREFIX/share/asperity/fortran/asperity.f90    Fortran module source (compile it with
#                                                 your compiler: .mod files are compiler-specific)
#
# ABI is the ABI version: MAJOR for MAJOR >= 1, and 0.MINOR for 0.x (semver: a
# 0.x minor release may break), e.g. libasperity.so.0.2 for 0.2.0 (build.rs).
#
# Options:
#   --prefix DIR       installation prefix (default /usr/local)
#   --libdir NAME      library directory under the prefix (default lib)
#   --profile NAME     Cargo profile whose artifacts are installed (default release)
#   --target-dir DIR   Cargo target directory (default: $CARGO_TARGET_DIR or ./target)
#   --no-build         install artifacts already built with that profile
#   --destdir DIR      staging root prepended to every installed path (packagers)
#
# Linux only (ELF sonames); other systems: link target/release/ directly.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
prefix=/usr/local
libdir_name=lib
profile=release
target_dir="${CARGO_TARGET_DIR:-$root/target}"
build=1
destdir=""

while [ $# -gt 0 ]; do
  case "$1" in
    --prefix) prefix="$2"; shift 2 ;;
    --libdir) libdir_name="$2"; shift 2 ;;
    --profile) profile="$2"; shift 2 ;;
    --target-dir) target_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --destdir) destdir="$2"; shift 2 ;;
    -h|--help) sed -n '2,/^# Linux only/p' "$0"; exit 0 ;;
    *) echo "install.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done

case "$(uname -s)" in
  Linux) ;;
  *) echo "install.sh: only Linux is supported (ELF soname); found $(uname -s)" >&2; exit 1 ;;
esac
case "$prefix" in
  /*) ;;
  *) echo "install.sh: --prefix must be an absolute path, got '$prefix'" >&2; exit 2 ;;
esac

version="$(sed -n 's/^version = "\(.*\)"/\1/p' "$root/Cargo.toml" | head -n1)"
major="${version%%.*}"
rest="${version#*.}"
minor="${rest%%.*}"
if [ -z "$version" ] || [ -z "$major" ] || [ -z "$minor" ]; then
  echo "install.sh: cannot read the version from Cargo.toml" >&2
  exit 1
fi
# The ABI version (the soname's suffix): MAJOR, or 0.MINOR before 1.0.
if [ "$major" = 0 ]; then abi="0.$minor"; else abi="$major"; fi

if [ "$build" = 1 ]; then
  (cd "$root" && cargo build --lib --profile "$profile" --target-dir "$target_dir")
fi
case "$profile" in
  dev|test) artifacts="$target_dir/debug" ;;
  bench) artifacts="$target_dir/release" ;;
  *) artifacts="$target_dir/$profile" ;;
esac
for f in libasperity.so libasperity.a; do
  if [ ! -f "$artifacts/$f" ]; then
    echo "install.sh: $artifacts/$f not found (build with --profile $profile, or drop --no-build)" >&2
    exit 1
  fi
done
soname="$(readelf -d "$artifacts/libasperity.so" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')"
if [ -n "$soname" ] && [ "$soname" != "libasperity.so.$abi" ]; then
  echo "install.sh: built soname '$soname' differs from libasperity.so.$abi" >&2
  exit 1
fi

inc="$destdir$prefix/include"
lib="$destdir$prefix/$libdir_name"
share="$destdir$prefix/share/asperity"
cmake_dir="$lib/cmake/asperity"
install -d "$inc" "$lib/pkgconfig" "$cmake_dir" "$share/fortran"

install -m 644 "$root/include/asperity.h" "$inc/asperity.h"
[ -f "$root/bindings/cpp/asperity.hpp" ] && install -m 644 "$root/bindings/cpp/asperity.hpp" "$inc/asperity.hpp"
[ -f "$root/bindings/fortran/asperity.f90" ] && install -m 644 "$root/bindings/fortran/asperity.f90" "$share/fortran/asperity.f90"

real="libasperity.so.$version"
install -m 755 "$artifacts/libasperity.so" "$lib/$real"
ln -sf "$real" "$lib/libasperity.so.$abi"
ln -sf "libasperity.so.$abi" "$lib/libasperity.so"
install -m 644 "$artifacts/libasperity.a" "$lib/libasperity.a"

subst() {
  sed -e "s|@PREFIX@|$prefix|g" -e "s|@LIBDIR@|$libdir_name|g" \
      -e "s|@VERSION@|$version|g" -e "s|@MAJOR@|$major|g" -e "s|@MINOR@|$minor|g" \
      -e "s|@ABI@|$abi|g" "$1"
}
subst "$root/packaging/asperity.pc.in" > "$lib/pkgconfig/asperity.pc"
subst "$root/packaging/asperityConfig.cmake.in" > "$cmake_dir/asperityConfig.cmake"
subst "$root/packaging/asperityConfigVersion.cmake.in" > "$cmake_dir/asperityConfigVersion.cmake"
chmod 644 "$lib/pkgconfig/asperity.pc" "$cmake_dir"/*.cmake

echo "installed asperity $version into $destdir$prefix"
