#!/usr/bin/env bash
# Every C++ source of the repository (src/, tests/, bench/) is as the repository's .clang-format
# formats it: prints the files that are not, and exits 1; exits 77 (ctest: skipped) where
# clang-format is not installed (.ci/install-deps installs it).
# Usage: tests/format.sh [REPO]   (format by hand: clang-format -i FILE...)
set -euo pipefail
repo=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$repo"
command -v clang-format >/dev/null || { echo "clang-format is not installed: skipped"; exit 77; }
mapfile -t files < <(find src tests bench -name '*.cpp' -o -name '*.hpp' | sort)
bad=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "not formatted by .clang-format (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | head -1)):"
  printf '  %s\n' "${bad[@]}"
  echo "format them with: clang-format -i ${bad[*]}"
  exit 1
fi
echo "formatted: ${#files[@]} files"
