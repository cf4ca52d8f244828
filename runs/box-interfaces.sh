#!/usr/bin/env bash
# The refinement interfaces of nested boxes and the tapered buffer (--box-taper F,
# --box-taper-from R; docs/horizon-shift-study.md Sec. 6.6). Every run is made afresh.
#
#   bash runs/box-interfaces.sh wormhole   # 10 boxes to 2048 M, wormhole data, to 1000 M, N = 64, 128
#                                          # against the sinh grid of the same innermost spacing
#   bash runs/box-interfaces.sh published  # wormhole data on the published grid with the boundary out
#                                          # of the way (8 boxes to 256 M), N = 24, 32, 48, to 100 M
#   bash runs/box-interfaces.sh shifted    # the shifted trumpet on the published grid (7 boxes to 128 M):
#                                          # what a taper of the inner boxes costs
#   bash runs/box-interfaces.sh trumpet    # the unshifted trumpet on 9 boxes to 1024 M, N = 48, 64, 96
#   bash runs/box-interfaces.sh widths     # the taper's width in cells, every box, wormhole (10 boxes)
#   bash runs/box-interfaces.sh five       # the suite's five-box trumpet against uniform grids at
#                                          # its finest spacing, untapered and at the defaults
#   bash runs/box-interfaces.sh cells      # the published grid's wormhole run with 2 and 4 times
#                                          # more cells on every box at the same finest spacing
#   bash runs/box-interfaces.sh all
#   (a second argument OUT writes into OUT instead of out/box-interfaces, a relative OUT from
#   where you stand)
#
# Output under out/box-interfaces/, tables on stdout (also in out/box-interfaces/*.txt). The
# boxes run at cfl 0.25, as when the study doc's tables were made (the boxes' default until
# 2026-11-26; the stage values' errors are the same at 0.5 to 2-3 digits, Sec. 11).
# GBSSN1D_JOBS=n runs n runs or studies at once (a positive whole number; default: the core
# count; the CPU times of `cells` are measured one run at a time). A rerun keeps every run that
# completed with the same command and binary and redoes the rest (runs/lib.sh; a kept run's CPU
# time is the one measured when it ran); a result is replaced only by a completed one; Ctrl-C
# stops at once; the tables are made only from completed runs.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
stage=${1:-wormhole}
case $stage in
wormhole | published | shifted | trumpet | widths | five | cells | all) ;;
*)
  echo "usage: runs/box-interfaces.sh wormhole|published|shifted|trumpet|widths|five|cells|all [OUT] (not '$stage')" >&2
  exit 2
  ;;
esac
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/box-interfaces.sh "$here" out/box-interfaces "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3

# the tapers compared: name and flags
tapers=("off:--box-taper 0" "half-all:--box-taper 0.5 --box-taper-from 0"
        "half-from8:--box-taper 0.5 --box-taper-from 8" "default:")

evolve() { # evolve NAME FLAGS...: one run into $out/NAME (runs/lib.sh)
  local name=$1
  shift
  local cfl=() # boxes at 0.25, the sinh grid at its default
  [[ " $* " == *" boxes "* ]] && cfl=(--cfl 0.25)
  lib_run "$name" build/gbssn1d evolve "${cfl[@]}" "$@" --out @OUT
  runs+=("$name")
}
family() { # family NAME "N list" FLAGS...: one converge study (at cfl ${cfl:-0.25})
  local name=$1 Ns=$2
  shift 2
  lib_run "$name" build/gbssn1d converge --N "$Ns" -j 1 --out @OUT --cfl "${cfl:-0.25}" "$@"
  runs+=("$name")
}
runs=()
# every run since the last call completed (else exit 1, no table), then which of them stopped or
# did not converge (their exit status)
finished() {
  lib_wait
  lib_check "${runs[@]}"
  local name status
  for name in "${runs[@]}"; do
    status=$(cat "$out/$name.status")
    [ "$status" = 0 ] ||
      echo "  ($name: exit $status: a run or member stopped (3), the study does not converge (4), is pre-asymptotic (5) or is not judged (6), see $out/$name.log)"
  done
  runs=()
}
# max |M_AH - M| per time window of each run's timeseries.dat; the first run is the reference
windows() { # windows "t0-t1 ..." REFERENCE RUN...
  local w=$1
  shift
  $py - "$w" "$@" <<'PY'
import sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series
wins = [tuple(float(x) for x in w.split('-')) for w in sys.argv[1].split()]
ref = None
print(f"{'run':34s}" + "".join(f"{f'{a:g}-{b:g} M':>12s}" for a, b in wins) + "   max/ref")
for d in sys.argv[2:]:
    s = series(d.rstrip('/') + '/timeseries.dat')
    t, e = s['t'], np.abs(s['M_ah_err'])
    m = [np.nanmax(e[(t >= a) & (t <= b)]) for a, b in wins]
    worst = max(m)
    ref = worst if ref is None else ref
    name = '/'.join(d.rstrip('/').split('/')[-2:]) if d.rstrip('/').split('/')[-1].startswith('N') \
        else d.rstrip('/').split('/')[-1]
    print(f"{name:34s}" + "".join(f"{x:12.2e}" for x in m) + f"   {worst / ref:.2f}")
PY
}

wormhole() {
  # the sinh grid with the innermost spacing of the boxes (M/16, M/32) and the same rmax
  common=(--tmax 1000 --dt-series 1 --dt-profiles 1000 --rmax 2048)
  evolve sinh-M16 "${common[@]}" --grid sinh --N 400 --dr-inner 0.0625
  evolve sinh-M32 "${common[@]}" --grid sinh --N 800 --dr-inner 0.0625
  for n in 64 128; do
    for t in "${tapers[@]}"; do
      # shellcheck disable=SC2086
      evolve "boxes10-N$n-${t%%:*}" "${common[@]}" --grid boxes --levels 10 --N $n ${t#*:}
    done
  done
  finished
  {
    echo "== wormhole data, 10 boxes to 2048 M, N = 64 (M/16), max |M_AH - M|; ratio to the sinh grid"
    windows "0-50 50-200 200-500 500-1000 0-1000" "$out/sinh-M16" "$out"/boxes10-N64-*/
    echo "== the same at N = 128 (M/32)"
    windows "0-50 50-200 200-500 500-1000 0-1000" "$out/sinh-M32" "$out"/boxes10-N128-*/
  } | tee "$out/wormhole.txt"
}

published() {
  grid=(--grid boxes --levels 8 --rmax 256 --tmax 100 --dt-series 0.5 --dt-profiles 10)
  for t in "${tapers[@]}" "quarter:--box-taper 0.25 --box-taper-from 0"; do
    # shellcheck disable=SC2086
    family "published-${t%%:*}" 24,32,48 "${grid[@]}" ${t#*:}
  done
  finished
  {
    echo "== wormhole data, 8 boxes to 256 M: RMS H_L2_R over 10-100 M, ratio to no taper"
    $py plots/horizon_study.py table "$out/published-off" "$out"/published-*/ --t0 10 --t1 100
    for n in 24 32 48; do
      echo "== max |M_AH - M| at N = $n (the pulse returns from the box end at 32 M near 60 M)"
      windows "0-50 50-60 60-70 70-100" "$out/published-off/N$n" \
        "$out"/published-{quarter,half-all,half-from8,default}/N$n
    done
  } | tee "$out/published.txt"
}

shifted() {
  grid=(--grid boxes --levels 7 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 10
        --id 1log-trumpet --rahA 0.5)
  for h in 0.89 0.6; do
    for t in "${tapers[@]}"; do
      # shellcheck disable=SC2086
      family "shifted-$h-${t%%:*}" 24,32,48 "${grid[@]}" --rah0 $h ${t#*:}
    done
  done
  finished
  {
    for h in 0.89 0.6; do
      echo "== 1+log trumpet, rah0 $h, 7 boxes to 128 M: RMS H_L2_R over 10-100 M, ratio to no taper"
      $py plots/horizon_study.py table "$out/shifted-$h-off" "$out"/shifted-$h-*/ --t0 10 --t1 100
    done
  } | tee "$out/shifted.txt"
}

trumpet() {
  grid=(--grid boxes --levels 9 --rmax 1024 --id 1log-trumpet --tmax 1000 --dt-series 1
        --dt-profiles 1000 --norm-Rmin 3)
  for t in "${tapers[@]}"; do
    # shellcheck disable=SC2086
    family "trumpet-${t%%:*}" 48,64,96 "${grid[@]}" ${t#*:}
  done
  finished
  for w in "10 1000" "10 500" "500 1000"; do
    set -- $w
    echo "== 1+log trumpet on 9 boxes, RMS H_L2_R over t in [$1, $2] M, ratio to no taper"
    $py plots/horizon_study.py table "$out/trumpet-off" "$out"/trumpet-*/ --t0 "$1" --t1 "$2"
  done | tee "$out/trumpet.txt"
}

widths() {
  common=(--tmax 1000 --dt-series 1 --dt-profiles 1000 --rmax 2048 --grid boxes --levels 10
          --box-taper-from 0)
  for nk in 64:6 64:12 64:24 64:32 128:6 128:12 128:24 128:32 128:48 128:64; do
    n=${nk%:*} k=${nk#*:}
    evolve "widths-N$n-k$k" "${common[@]}" --N "$n" --box-taper "$($py -c "print($k / $n)")"
  done
  finished
  {
    echo "== wormhole data, 10 boxes to 2048 M: taper of k cells on every box, max |M_AH - M|"
    windows "0-1000" "$out/widths-N64-k6" "$out"/widths-N64-*/
    windows "0-1000" "$out/widths-N128-k6" "$out"/widths-N128-*/
  } | tee "$out/widths.txt"
}

five() {
  # the suite's five-box layout (boxes to 64, 32, 16, 8, 4 M; 1+log trumpet; to 30 M; H over
  # 3 M <= R <= 12 M): each run against a uniform grid at its finest spacing (rmax 64 M, 16 N
  # cells), before the taper (--box-taper 0) and with today's defaults, at cfl 0.5
  common=(--id 1log-trumpet --rmax 64 --tmax 30 --dt-series 0.5 --dt-profiles 30 --norm-Rmin 3)
  for n in 64 96 128; do
    for run in uniform off default; do
      case $run in
      uniform) grid=(--grid uniform --N $((16 * n))) ;;
      off) grid=(--grid boxes --levels 5 --N $n --box-taper 0) ;;
      default) grid=(--grid boxes --levels 5 --N $n) ;;
      esac
      lib_run "five-$run-N$n" build/gbssn1d evolve "${common[@]}" "${grid[@]}" --out @OUT
      runs+=("five-$run-N$n")
    done
  done
  finished
  $py - "$out" <<'PY' | tee "$out/five.txt"
import sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series
out = sys.argv[1]
print("== five boxes to 64 M, 1+log trumpet, RMS over 5-30 M of H_L2_R (3 <= R <= 12 M) and of "
      "H_L2_ext (1 <= r <= 10 M), max |M_AH - M|; each against the uniform grid at the finest "
      "spacing")
print(f"{'N':>4s} {'run':8s} {'H_L2_R':>9s} {'/unif':>6s} {'H_L2_ext':>9s} {'/unif':>6s} "
      f"{'M_AH err':>9s} {'/unif':>6s}")
for n in (64, 96, 128):
    rows = {}
    for run in ('uniform', 'off', 'default'):
        s = series(f"{out}/five-{run}-N{n}/timeseries.dat")
        m = s['t'] >= 5
        rows[run] = (np.sqrt(np.mean(s['H_L2_R'][m] ** 2)), np.sqrt(np.mean(s['H_L2_ext'][m] ** 2)),
                     np.max(np.abs(s['M_ah_err'])))
    u = rows['uniform']
    for run in ('uniform', 'off', 'default'):
        r = rows[run]
        print(f"{n:4d} {run:8s} " + " ".join(f"{x:9.2e} {x / y:6.2f}" for x, y in zip(r, u)))
PY
}

cells() {
  # the published grid with wormhole data (8 boxes to 256 M, N = 24, 32, 48) against the same
  # finest spacing with the outer boxes 2 and 4 times finer (7 boxes at 2N, 6 boxes at 4N: box
  # l covers r <= 256/2^l M either way) and a uniform grid at the finest spacing; to 100 M, at
  # the defaults (cfl 0.5, taper from 16 M)
  common=(--grid boxes --rmax 256 --tmax 100 --dt-series 0.5 --dt-profiles 10)
  for lk in 8:1 7:2 6:4; do
    l=${lk%:*} k=${lk#*:}
    cfl=0.5 family "cells-L$l" "$((24 * k)),$((32 * k)),$((48 * k))" "${common[@]}" --levels "$l"
  done
    cfl=0.5 family cells-uniform 3072,4096,6144 --grid uniform --rmax 256 --tmax 100 \
    --dt-series 0.5 --dt-profiles 10
  finished
  {
    echo "== wormhole data to 100 M, finest spacing M/12, M/16, M/24: RMS H_L2_R over 10-100 M"
    for d in L8 L7 L6 uniform; do
      $py plots/horizon_study.py table "$out/cells-$d" "$out/cells-$d/" --t0 10 --t1 100 | tail -n 1
    done
    for n8 in 24 32 48; do
      echo "== max |M_AH - M| at the finest spacing of 8 boxes at N = $n8 (the pulse returns near 60 M)"
      windows "0-50 50-60 60-70 70-100" "$out/cells-uniform/N$((128 * n8))" \
        "$out/cells-L8/N$n8" "$out/cells-L7/N$((2 * n8))" "$out/cells-L6/N$((4 * n8))"
    done
  } | tee "$out/cells.txt"
  # the same question for the cost study's wormhole runs (Sec. 6.4): 9 boxes to 1024 M at
  # N = 64 (finest M/16) against 8 boxes at 128 and 7 at 256 (the same finest spacing) and the
  # sinh grid with innermost M/16, to 1000 M, one run at a time (CPU times)
  # (the CPU time, "user system" in s, is the last line of each run's log; copied beside it
  # into layout-*.time)
  common=(--id wormhole --rmax 1024 --tmax 1000 --dt-series 1 --dt-profiles 1000)
  for lk in 9:64 8:128 7:256 sinh; do
    if [ $lk = sinh ]; then
      name=layout-sinh grid=(--grid sinh --N 400 --dr-inner 0.0625)
    else
      name=layout-L${lk%:*} grid=(--grid boxes --levels "${lk%:*}" --N "${lk#*:}")
    fi
    lib_run "$name" /usr/bin/time -f "%U %S" build/gbssn1d evolve "${common[@]}" "${grid[@]}" \
      --out @OUT --force
    runs+=("$name")
    lib_wait
  done
  finished
  for name in layout-L9 layout-L8 layout-L7 layout-sinh; do
    tail -n 1 "$out/$name.log" >"$out/$name.time"
  done
  $py - "$out" <<'PY' | tee -a "$out/cells.txt"
import sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series
out = sys.argv[1]
print("== wormhole data to 1000 M, rmax 1024 M, finest spacing M/16: RMS H_L2_R over 10-1000 M")
for name in ('layout-L9', 'layout-L8', 'layout-L7', 'layout-sinh'):
    s = series(f"{out}/{name}/timeseries.dat")
    m = s['t'] >= 10
    cpu = sum(float(x) for x in open(f"{out}/{name}.time").read().split())
    print(f"{name:12s} CPU {cpu:5.2f} s  H_L2_R {np.sqrt(np.mean(s['H_L2_R'][m] ** 2)):.2e}  "
          f"max |M_AH - M| {np.max(np.abs(s['M_ah_err'])):.2e}")
PY
}

case $stage in
wormhole) wormhole ;;
published) published ;;
shifted) shifted ;;
trumpet) trumpet ;;
widths) widths ;;
five) five ;;
cells) cells ;;
all) wormhole; published; shifted; trumpet; widths; five; cells ;;
esac
