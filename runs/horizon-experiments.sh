#!/usr/bin/env bash
# The published horizon-adjusting-shift experiments (standard, stretch, shrink) on maximal- and
# 1+log-trumpet data at two resolutions (N = 400, 800 on the same sinh map), to t = 100 M.
# One `gbssn1d sweep` per configuration: output in out/horizon/<config>/N=<N>/, figures in
# out/horizon/*.png. About a minute on 2 cores.
#
#   bash runs/horizon-experiments.sh [OUT]   # into OUT instead of out/horizon (a relative OUT
#                                            # from where you stand)
#
# GBSSN1D_JOBS=n runs n members at once (a positive whole number; default: the core count). A
# rerun keeps every sweep that finished with the same command, binary and config, and resumes
# the others (runs/lib.sh); Ctrl-C stops at once; the figures and the table are made only when
# all six finished.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/horizon-experiments.sh "$here" out/horizon "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
for cfg in runs/horizon-*.toml; do
  # a member that blows up is a result, not a reason to stop: the sweep's summary says so (each
  # sweep's messages in OUT/<config>.log)
  lib_run "$(basename "$cfg" .toml)" build/gbssn1d sweep -j "$jobs" --out @OUT --config "$cfg" \
    --sweep N=400,800
  lib_wait
done
lib_check
for data in maximal 1log; do
  $py plots/plot_horizons.py "$out"/horizon-$data-*/N=*/horizon.dat --target \
    --title "r_AH(t), $data-trumpet data" -o "$out"/r_ah_$data.png
  $py plots/plot_profiles.py "$out"/horizon-$data-{stretch,shrink}/N=800/profiles.dat \
    -y beta_GD -y beta_H --times 10,100 --xmax 6 --label stretch --label shrink \
    --title "beta_GD and beta_H, $data-trumpet data" -o "$out"/beta_split_$data.png
done
echo "# run t r_ah M_ah-1 H_L2_ext (final row of each run)"
for cfg in runs/horizon-*.toml; do
  for d in "$out/$(basename "$cfg" .toml)"/N=*/; do
    awk -v n="$(basename "$(dirname "$d")")-$(basename "$d")" '!/^#/ {row=$0} END {split(row, c, " ");
      printf "%s %g %.5f %.2e %.3e\n", n, c[1], c[10], c[11]-1, c[4]}' "$d/timeseries.dat"
  done
done
ls "$out"/*.png
