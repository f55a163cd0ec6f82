#!/usr/bin/env bash
# Fails on any rustdoc warning (broken intra-doc links, unescaped brackets,
# bare URLs, invalid HTML, ...). Builds the library docs twice: plain, as
# `cargo doc` does, and with the KaTeX header of docs/katex-header.html, as
# docs.rs does ([package.metadata.docs.rs] in Cargo.toml). The second build is
# left in target/doc/asperity for reading (formulas need network access to the
# KaTeX CDN to render).
#
# Usage: scripts/check-docs.sh [extra cargo doc arguments, e.g. --open]
# Honours CARGO_TARGET_DIR. Any RUSTDOCFLAGS already set are kept.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

base="${RUSTDOCFLAGS:-}"

echo "== cargo doc --no-deps (plain, -D warnings)"
RUSTDOCFLAGS="$base -D warnings" cargo doc --no-deps --lib

echo "== cargo doc --no-deps (KaTeX header, -D warnings)"
# The header path is relative to the package root, rustdoc's working
# directory under cargo; --no-deps keeps it away from the dependencies, whose
# working directory differs.
RUSTDOCFLAGS="$base -D warnings --html-in-header docs/katex-header.html" \
    cargo doc --no-deps --lib "$@"

echo "docs: OK (no rustdoc warnings)"
