#!/usr/bin/env bash
# Every runs/ script that deletes output (rm -rf) makes sure of its binary first: the line that
# checks (or builds) build/gbssn1d comes before the first rm -rf, so a script run without a
# build never deletes earlier results and then fails. (runs/study-helpers.sh and runs/lib.sh are
# sourced by scripts that check; they only define functions.)
set -euo pipefail
src=$1
bad=0
for f in "$src"/runs/*.sh; do
  case "$(basename "$f")" in study-helpers.sh | lib.sh) continue ;; esac
  first_rm=$(grep -n 'rm -rf' "$f" | head -1 | cut -d: -f1 || true)
  [ -n "$first_rm" ] || continue
  check=$(grep -n -E '\[ -x (build/gbssn1d|"\$g") \]|\.ci/build' "$f" | head -1 | cut -d: -f1 || true)
  if [ -z "$check" ] || [ "$check" -gt "$first_rm" ]; then
    echo "$(basename "$f"): deletes at line $first_rm before checking for its binary (${check:-never})"
    bad=1
  fi
done
[ $bad -eq 0 ] && echo "runs/ scripts: each checks its binary before it deletes anything"
exit $bad
