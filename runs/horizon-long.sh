#!/usr/bin/env bash
# Thousands of M: the published experiments (maximal-trumpet data) to t = 1000 M at
# N = 400, 800, 1600 (one sinh map: --dr-inner 0.02 of the configuration) with the outer boundary at 1600 M, so
# that nothing from it reaches the exterior region [1, 10] M before the end. Prints H_L2_ext
# and its pairwise orders over time; figures in out/horizon-long/*.png. About 15 minutes on
# 2 cores.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/horizon-long.sh "$here" out/horizon-long "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
for cfg in standard stretch shrink; do
  # one `gbssn1d converge` per configuration (members in out/horizon-long/<cfg>/N<n>/); a
  # member that blows up is a result, not a reason to stop: its log ($out/NAME.log) says where and when
  lib_run "$cfg" build/gbssn1d converge --N 400,800,1600 -j 1 --out @OUT \
    --config "runs/horizon-maximal-$cfg.toml" --rmax 1600 --tmax 1000 --dt-series 5 \
    --dt-profiles 500
done
lib_wait
lib_check
for cfg in standard stretch shrink; do
  echo "== $cfg"
  $py plots/constraint_orders.py $out/$cfg/N{400,800,1600}/timeseries.dat \
    --times 10,50,100,200,400,600,800,1000 --title "H on [1, 10] M to 1000 M: $cfg" \
    -o $out/H_orders_$cfg.png
  awk '!/^#/ {row=$0} END {split(row, c, " "); printf "   N=1600 at t = %g: r_ah = %.5f, M_ah - 1 = %.2e\n", c[1], c[10], c[11]-1}' \
    $out/$cfg/N1600/timeseries.dat
done
