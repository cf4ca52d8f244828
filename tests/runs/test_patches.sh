#!/usr/bin/env bash
# runs/z4c.sh trace builds a study binary from runs/patches/z4c-trace.patch. Here: the patch
# applies to today's src/ without fuzz (a hunk that only lands by fuzz may land in code that
# changed under it), and the patched point loops still compile (syntax and templates, no code).
# Usage: test_patches.sh SOURCE_DIR CXX
set -euo pipefail
src=$1 cxx=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$src/src" "$work/src"
patch -s -p1 --fuzz=0 -d "$work" -i "$src/runs/patches/z4c-trace.patch"
for f in rhs_z4c rhs_bssn; do
  "$cxx" -std=c++20 -fsyntax-only -Wall -Wextra -Werror -I"$work/src" -DGBSSN1D_VERSION='"patch"' \
    "$work/src/gbssn/$f.cpp"
done
echo "runs/patches/z4c-trace.patch applies without fuzz and its point loops compile"
