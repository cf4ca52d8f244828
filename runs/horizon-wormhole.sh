#!/usr/bin/env bash
# The table of item 2 for wormhole data (docs/horizon-shift-study.md, Sec. 9.1): precollapsed
# wormhole data with every default but the grid (uniform, rmax 200 M, M/8, M/12, M/16, to
# 100 M), the standard gauge and --rahA 0.5 --rah0 h for h = 0.5 ... 2 M. Prints the table of
# plots/horizon_study.py (RMS of H_L2_R over 10-100 M, pairwise orders, ratio to the standard
# gauge). Every family is one converge run, made afresh in out/horizon-wormhole/ (about a
# minute on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
out=out/horizon-wormhole
mkdir -p "$out"
common=(--id wormhole --grid uniform --rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
source runs/study-helpers.sh
family standard
for h in 0.5 0.6 0.89 1.2 1.5 2; do
  family "h$h" --rahA 0.5 --rah0 "$h"
done
$py plots/horizon_study.py table "$out/standard" "$out/standard" "$out"/h*/ --t0 10 --t1 100 | tee "$out/table.txt"
