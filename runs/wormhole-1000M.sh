#!/usr/bin/env bash
# Runs runs/wormhole-1000M.toml into out/wormhole-1000M and compares its lapse with the
# stationary 1+log trumpet; writes out/wormhole-1000M/*.png. Builds the program first if
# build/gbssn1d is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
out=out/wormhole-1000M
rm -rf "$out" out/trumpet-reference
/usr/bin/time -f "wall %e s" build/gbssn1d evolve --config runs/wormhole-1000M.toml --out "$out"
build/gbssn1d evolve --id 1log-trumpet --tmax 0 --grid sinh --N 8000 --dr-inner 0.01 \
  --rmax 200 --out out/trumpet-reference 2>/dev/null
py=/usr/bin/python3
$py plots/compare_trumpet.py "$out/profiles.dat" out/trumpet-reference/profiles.dat \
  -o "$out/alpha_vs_R.png" | tee "$out/trumpet_agreement.txt"
# one unit per axis: d_t alpha (1/M) and H (1/M^2) in separate figures
$py plots/plot_series.py "$out/timeseries.dat" -y dtalpha_max_ext --logy \
  --title "settling: max |d_t alpha| over 1 M <= r <= 10 M" -o "$out/settling.png"
$py plots/plot_series.py "$out/timeseries.dat" -y H_L2_ext --logy \
  --title "constraint: L2 norm of H over 1 M <= r <= 10 M" -o "$out/constraints.png"
$py plots/plot_series.py "$out/timeseries.dat" -y alpha_center -o "$out/alpha_center.png"
tail -n 1 "$out/timeseries.dat"
