#!/usr/bin/env bash
# The demonstration: installs what is missing (Debian packages), builds, runs a precollapsed
# wormhole until it has become the stationary 1+log trumpet, evolves the trumpet itself at
# three resolutions, and draws the figures into demo/. After the build, 11 s on 2 idle cores
# (32 s on 2 cores busy with other work; measured on a fresh clone, 2026-11-27).
#
#   bash runs/demo.sh [OUT]    # into OUT instead of demo/ (a relative OUT from where you stand)
#
# GBSSN1D_JOBS=n runs n at once (a positive whole number; default: the core count). A rerun
# keeps every run that completed with the same command and binary and redoes the rest
# (runs/lib.sh); the figures are drawn again; Ctrl-C stops at once.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/demo.sh "$here" demo "${1:-}"
echo "== set-up: Debian packages that are missing (apt-get), then a Release build in build/"
bash .ci/install-deps
echo "== build of the program: the first took 103 s on 2 idle cores (a fresh clone, no compiler"
echo "   cache) and 570 s on 2 cores busy with other work; later ones take seconds; cmake's"
echo "   progress below, and a line every 20 s while it works"
start=$SECONDS
# (without OUT's lock: a sleep left behind would hold it)
(exec 9>&-; while sleep 20; do echo "   ... building, $((SECONDS - start)) s"; done) &
ticker=$!
trap 'kill $ticker 2>/dev/null || true' EXIT
bash .ci/build gbssn1d | grep --line-buffered -E '^\[ *[0-9]+%\]' | sed -u 's/^/   /'
kill $ticker 2>/dev/null || true
wait $ticker 2>/dev/null || true
echo "   built in $((SECONDS - start)) s"
echo "== built: $(build/gbssn1d --version 2>/dev/null || echo build/gbssn1d)"
g=build/gbssn1d
py=/usr/bin/python3
d=$out
# the runs' own last line (how each ended; its log beside it in OUT)
said() { local n; for n in "$@"; do echo "   $n: $(tail -n 1 "$d/$n.log")"; done; }

echo "== wormhole (precollapsed lapse) -> 1+log trumpet, t = 300 M"
lib_run wormhole "$g" evolve --id wormhole --lapse0 precollapsed --grid sinh --N 400 --rmax 600 \
  --dr-inner 0.02 --tmax 300 --dt-series 1 --dt-profiles 5 --out @OUT
lib_run trumpet-reference "$g" evolve --id 1log-trumpet --tmax 0 --grid sinh --N 4000 \
  --dr-inner 0.005 --rmax 200 --out @OUT
lib_wait
lib_check wormhole trumpet-reference
said wormhole
$py plots/plot_profiles.py "$d"/wormhole/profiles.dat -y alpha --times 0,5,10,20,50,300 \
  --xmax 10 --title "lapse: wormhole collapsing onto the trumpet" -o "$d"/lapse_profiles.png
$py plots/plot_series.py "$d"/wormhole/timeseries.dat -y dtalpha_max_ext --logy \
  --title "settling: max |d_t alpha| over 1 M <= r <= 10 M" -o "$d"/settling.png
$py plots/plot_series.py "$d"/wormhole/timeseries.dat -y H_L2_ext -y M_L2_ext --logy \
  --title "constraints: L2 norms of H and M_r over 1 M <= r <= 10 M" -o "$d"/constraints.png
$py plots/compare_trumpet.py "$d"/wormhole/profiles.dat "$d"/trumpet-reference/profiles.dat \
  -o "$d"/alpha_vs_R.png

echo "== stationary 1+log trumpet at three resolutions, t = 20 M"
# rmax 48: the outer boundary cannot reach the norm windows (areal radius <= 12 M) by 20 M
for n in 360 720 1440; do
  lib_run trumpet-N$n "$g" evolve --id 1log-trumpet --grid uniform --N $n --rmax 48 --tmax 20 \
    --dt-series 0.5 --dt-profiles 10 --norm-rmin 1 --norm-rmax 10 --out @OUT
done
lib_wait
lib_check trumpet-N{360,720,1440}
said trumpet-N{360,720,1440}
$py plots/plot_series.py "$d"/trumpet-N{360,720,1440}/timeseries.dat -y H_L2_ext --logy --ordered \
  --label "M/7.5" --label "M/15" --label "M/30" \
  --title "1+log trumpet: H on [1, 10] M at M/7.5, M/15, M/30" \
  -o "$d"/trumpet_H.png
echo "== converge: the 1+log trumpet at N = 720, 1080, 1440 (M/15, M/22.5, M/30)"
lib_run converge "$g" converge --N 720,1080,1440 -j "$jobs" --out @OUT --id 1log-trumpet \
  --grid uniform --rmax 48 --tmax 20 --dt-series 0.5 --norm-rmin 1 --norm-rmax 10
lib_wait
lib_check converge
$py plots/constraint_orders.py "$d"/converge/N{720,1080,1440}/timeseries.dat --times 5,10,20 \
  --title "1+log trumpet: H on [1, 10] M, scaled at 4th order" -o "$d"/trumpet_orders.png

echo "== sweep: horizon shift strength x target radius (1+log trumpet data, t = 40 M)"
lib_run sweep "$g" sweep -j "$jobs" --out @OUT --sweep rahA=0.25,0.5 --sweep rah0=0.6,1.2 \
  --id 1log-trumpet --grid sinh --N 300 --rmax 100 --dr-inner 0.01875 --tmax 40 --dt-series 0.5
lib_wait
lib_check sweep
# the column names (the first line) and the rows
awk 'NR == 1 { print substr($0, 3); next } !/^#/ { print }' "$d"/sweep/summary.dat | column -t
$py plots/plot_horizons.py "$d"/sweep/*/horizon.dat --label-by rahA,rah0 --target \
  --title "sweep: r_AH(t), dotted: the targets h" -o "$d"/sweep_r_ah.png
$py plots/plot_sweep.py "$d"/sweep/summary.dat -o "$d"/sweep_map.png
# from where you stand
echo "figures: $(for f in "$d"/*.png; do realpath -m --relative-to="$here" "$f"; done | tr '\n' ' ')"
