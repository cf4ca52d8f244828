#!/usr/bin/env bash
# The table of item 2 for wormhole data (docs/horizon-shift-study.md, Sec. 9.1): precollapsed
# wormhole data with every default but the grid (uniform, rmax 200 M, M/8, M/12, M/16, to
# 100 M), the standard gauge and --rahA 0.5 --rah0 h for h = 0.5 ... 2 M. Prints the table of
# plots/horizon_study.py (RMS of H_L2_R over 10-100 M, pairwise orders, ratio to the standard
# gauge). Every family is one converge run, kept in out/horizon-wormhole/ and redone only where its command or binary changed (about a
# minute on 2 cores).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/horizon-wormhole.sh "$here" out/horizon-wormhole "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
common=(--id wormhole --grid uniform --rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
family standard
for h in 0.5 0.6 0.89 1.2 1.5 2; do
  family "h$h" --rahA 0.5 --rah0 "$h"
done
lib_wait
lib_check
$py plots/horizon_study.py table "$out/standard" "$out/standard" "$out"/h*/ --t0 10 --t1 100 | tee "$out/table.txt"
