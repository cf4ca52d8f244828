#!/usr/bin/env bash
# The published horizon-adjusting-shift experiments (standard, stretch, shrink) on maximal- and
# 1+log-trumpet data at two resolutions (N = 400, 800 on the same sinh map), to t = 100 M.
# One `gbssn1d sweep` per configuration: output in out/horizon/<config>/N=<N>/, figures in
# out/horizon/*.png. About a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
out=out/horizon
rm -rf "$out" && mkdir -p "$out"
for cfg in runs/horizon-*.toml; do
  # a member that blows up is a result, not a reason to stop: the sweep's summary says so
  build/gbssn1d sweep -j "${GBSSN1D_JOBS:-$(nproc)}" --out "$out/$(basename "$cfg" .toml)" --config "$cfg" \
    --sweep N=400,800 2>>"$out/stderr.log" || true
done
for data in maximal 1log; do
  $py plots/plot_horizons.py $out/horizon-$data-*/N=*/horizon.dat --target \
    --title "r_AH(t), $data-trumpet data" -o $out/r_ah_$data.png
  $py plots/plot_profiles.py $out/horizon-$data-{stretch,shrink}/N=800/profiles.dat \
    -y beta_GD -y beta_H --times 10,100 --xmax 6 --label stretch --label shrink \
    --title "beta_GD and beta_H, $data-trumpet data" -o $out/beta_split_$data.png
done
echo "# run t r_ah M_ah-1 H_L2_ext (final row of each run)"
for d in $out/*/N=*/; do
  awk -v n="$(basename "$(dirname "$d")")-$(basename "$d")" '!/^#/ {row=$0} END {split(row, c, " ");
    printf "%s %g %.5f %.2e %.3e\n", n, c[1], c[10], c[11]-1, c[4]}' "$d/timeseries.dat"
done
ls $out/*.png
