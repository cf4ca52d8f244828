#!/usr/bin/env bash
# The published horizon-adjusting-shift experiments (standard, stretch, shrink) on maximal- and
# 1+log-trumpet data at two resolutions (N = 400, 800 on the same sinh map), to t = 100 M.
# Output in out/horizon/<config>-N<N>/, figures in out/horizon/*.png. About a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
out=out/horizon
rm -rf "$out" && mkdir -p "$out"
jobs=()
for cfg in runs/horizon-*.toml; do
  name=$(basename "$cfg" .toml)
  for n in 400 800; do
    jobs+=("build/gbssn1d evolve --config $cfg --N $n --out $out/$name-N$n")
  done
done
# a member that blows up is a result, not a reason to stop: its stderr says where and when
printf '%s\n' "${jobs[@]}" | xargs -P "$(nproc)" -I{} bash -c '{} 2>>"$0"' "$out/stderr.log" || true
for data in maximal 1log; do
  $py plots/plot_horizons.py $out/horizon-$data-*-N*/horizon.dat --target \
    --title "r_AH(t), $data-trumpet data" -o $out/r_ah_$data.png
  $py plots/plot_profiles.py $out/horizon-$data-{stretch,shrink}-N800/profiles.dat \
    -y beta_GD -y beta_H --times 10,100 --xmax 6 --label stretch --label shrink \
    --title "beta_GD and beta_H, $data-trumpet data" -o $out/beta_split_$data.png
done
echo "# run t r_ah M_ah-1 H_L2_ext (final row of each run)"
for d in $out/*-N*/; do
  awk -v n="$(basename "$d")" '!/^#/ {row=$0} END {split(row, c, " ");
    printf "%s %g %.5f %.2e %.3e\n", n, c[1], c[10], c[11]-1, c[4]}' "$d/timeseries.dat"
done
ls $out/*.png
