#!/usr/bin/env bash
# The finite-difference order (docs/horizon-shift-study.md, Sec. 10): for --fd-order 2, 4, 6
# and 8, the 1+log trumpet on uniform grids, rmax 200 M, at M/8, M/12, M/16 to 100 M, in the
# standard gauge, stretched to h = 2 M and shrunk to h = 0.6 M (A = 0.5, default profiles).
# Prints, per order, the table of plots/horizon_study.py (RMS of H_L2_R over 10-100 M, its
# pairwise orders, the ratio to the same order's standard gauge) and the coarse threshold (pairwise
# orders at least p - 1/2, and at every output time between p - 3/2 and p + 2).
# Every family is one converge run, kept in out/fd-order/ and redone only where its command or binary changed (about 2 minutes on 2 cores).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/fd-order.sh "$here" out/fd-order "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
common=(--id 1log-trumpet --grid uniform --rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
for p in 2 4 6 8; do
  family "p$p-standard" --fd-order "$p" --order "$p"
  family "p$p-h2" --fd-order "$p" --order "$p" --rahA 0.5 --rah0 2
  family "p$p-h0.6" --fd-order "$p" --order "$p" --rahA 0.5 --rah0 0.6
done
lib_wait
lib_check
{
  for p in 2 4 6 8; do
    echo "# --fd-order $p"
    $py plots/horizon_study.py table "$out/p$p-standard" "$out/p$p-standard" "$out/p$p-h2" \
      "$out/p$p-h0.6" --t0 10 --t1 100
    $py plots/horizon_study.py threshold "$out/p$p-standard" "$out/p$p-h2" "$out/p$p-h0.6" \
      --min-order "$((p - 1)).5" --max-order "$((p + 2))" --rmax 200
  done
} | tee "$out/table.txt"
