#!/usr/bin/env bash
# Runs runs/wormhole-1000M.toml into out/wormhole-1000M/run (or OUT/run) and compares its lapse
# with the stationary 1+log trumpet (OUT/trumpet-reference); writes out/wormhole-1000M/*.png.
# Builds the program first if build/gbssn1d is missing. A rerun keeps both runs when their
# command, the .toml and the binary are the same (runs/lib.sh); Ctrl-C stops.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/wormhole-1000M.sh "$here" out/wormhole-1000M "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
lib_run run build/gbssn1d evolve --config runs/wormhole-1000M.toml --out @OUT
lib_run trumpet-reference build/gbssn1d evolve --id 1log-trumpet --tmax 0 --grid sinh --N 8000 \
  --dr-inner 0.01 --rmax 200 --out @OUT
lib_wait
lib_check
grep -h "reached t = " "$out/run.log" || true
py=/usr/bin/python3
$py plots/compare_trumpet.py "$out/run/profiles.dat" "$out/trumpet-reference/profiles.dat" \
  -o "$out/alpha_vs_R.png" | tee "$out/trumpet_agreement.txt"
# one unit per axis: d_t alpha (1/M) and H (1/M^2) in separate figures
$py plots/plot_series.py "$out/run/timeseries.dat" -y dtalpha_max_ext --logy \
  --title "settling: max |d_t alpha| over 1 M <= r <= 10 M" -o "$out/settling.png"
$py plots/plot_series.py "$out/run/timeseries.dat" -y H_L2_ext --logy \
  --title "constraint: L2 norm of H over 1 M <= r <= 10 M" -o "$out/constraints.png"
$py plots/plot_series.py "$out/run/timeseries.dat" -y alpha_center -o "$out/alpha_center.png"
tail -n 1 "$out/run/timeseries.dat"
