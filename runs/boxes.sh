#!/usr/bin/env bash
# Box-in-box mesh refinement (docs/horizon-shift-study.md, Sec. 6). Every family is one
# `gbssn1d converge` run; norms are H_L2_R, the areal-radius window norm-Rmin M <= R <= 12 M (the
# same place in every gauge), and a table gives the RMS over time per resolution and the
# pairwise orders of those (plots/horizon_study.py table).
#
#   bash runs/boxes.sh trumpet   # unshifted 1+log trumpet, 9 boxes, rmax 1024, M/12 ... M/24, to 1000 M
#   bash runs/boxes.sh thesis    # the published grid: 7 boxes, rmax 128, M/12, M/16, M/24, to 100 M
#   bash runs/boxes.sh interp    # h = 0.6, 0.89, 1.2, 2: boxes (stage values, quadratic) vs sinh and uniform
#   bash runs/boxes.sh cost      # wall time against H error: uniform, sinh, boxes, standard and stretched
#   bash runs/boxes.sh speed     # the stretched 3-resolution study to 1000 M as one converge -j 2
#   bash runs/boxes.sh order     # --fd-order 6 against 4 on the published grid, 6 boxes and 9 boxes
#   bash runs/boxes.sh taper     # beta_H's outer taper (quartic, step, none) on coarse boxes
#   bash runs/boxes.sh bursts    # wormhole data on boxes: H bursts against where the boxes end
#   (a second argument OUT writes into OUT instead of out/boxes, a relative OUT from where you stand)
#
# Output under out/boxes/: one folder per family, tables on stdout (also in out/boxes/*.txt),
# figures *.png. GBSSN1D_JOBS=n runs n families (or runs) at once (a positive whole number;
# default: the core count). A rerun keeps every family and run that completed with the same
# command and binary and redoes the rest (runs/lib.sh; `cost` and `speed` are measurements of
# this machine: they are kept too, and their times are those of the run in place); a result is
# replaced only by a completed one; Ctrl-C stops at once; tables are made only from completed
# runs.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
stage=${1:-thesis}
case $stage in
trumpet | thesis | interp | cost | speed | order | taper | bursts) ;;
*)
  echo "usage: runs/boxes.sh trumpet|thesis|interp|cost|speed|order|taper|bursts [OUT] (not '$stage')" >&2
  exit 2
  ;;
esac
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/boxes.sh "$here" out/boxes "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3

# The tables of the study doc's Sec. 6 and 7.3 were made at cfl 0.25, the boxes' default until
# 2026-11-26 (their stage-value errors are the same at 0.5, the default since: Sec. 11); the
# quadratic time interpolation's are not. `cost` and `speed` measure the defaults.
cfl=(--cfl 0.25)
family() { # family NAME "N list" [evolve flags]: one converge study into $out/NAME (runs/lib.sh)
  local name=$1 Ns=$2
  shift 2
  lib_run "$name" build/gbssn1d converge --N "$Ns" -j 1 --out @OUT "${cfl[@]}" "$@"
  families+=("$name")
}
families=()
# every family so far completed, then which of them did not converge (their exit status)
finished() {
  lib_wait
  lib_check
  local name status
  for name in "${families[@]}"; do
    status=$(cat "$out/$name.status")
    [ "$status" = 0 ] ||
      echo "  ($name: exit $status: a member stopped (3), the study does not converge (4), is pre-asymptotic (5) or is not judged (6), see $out/$name.log)"
  done
}
table() { $py plots/horizon_study.py table "$@"; }

case $stage in
trumpet)
  # 9 boxes to rmax 1024: finest box r <= 4 M with spacing 4/N M (N = 48: M/12)
  common=(--grid boxes --id 1log-trumpet --tmax 1000 --dt-series 1 --dt-profiles 1000 --norm-Rmin 3)
  boxes=("${common[@]}" --levels 9 --rmax 1024)
  family trumpet-1000M 48,64,96 "${boxes[@]}"
  family trumpet-1000M-fine 64,96,128 "${boxes[@]}"
  for ko in 0 0.05 0.2; do
    family "trumpet-1000M-ko$ko" 48,64,96 "${boxes[@]}" --ko-sigma $ko
  done
  # the same boxes inside a tenth box to 2048 M: the outer boundary's influence cannot reach
  # R = 12 M before about 1440 M
  family trumpet-1000M-rmax2048 48,64,96 "${common[@]}" --levels 10 --rmax 2048
  finished
  for w in "10 1000" "10 500" "500 1000"; do
    set -- $w
    echo "== 1+log trumpet on 9 boxes, t in [$1, $2] M"
    table "$out/trumpet-1000M" "$out"/trumpet-1000M*/ --t0 "$1" --t1 "$2"
  done | tee "$out/trumpet.txt"
  $py plots/horizon_study.py figure --cols 2 -o "$out/trumpet.png" "$out"/trumpet-1000M*/
  ;;
thesis)
  # 7 boxes to 128 M with 48, 64 and 96 points across each box (N = 24, 32, 48 cells on r >= 0):
  # finest spacing M/12, M/16, M/24, with this project's numerics (RK4 stage values at the fine
  # boundaries, h_AH at every substage); the published configuration itself, with every
  # mechanism switched on and off, is runs/thesis.sh
  boxes=(--grid boxes --levels 7 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 10)
  published=(--rah-profile rational --rah-width 1 --rah-normal unit --driver-advection upwind-gd)
  for id in 1log-trumpet maximal-trumpet; do
    family "thesis-$id-standard" 24,32,48 "${boxes[@]}" --id $id
    family "thesis-$id-stretch" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.89
    family "thesis-$id-stretch-published" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.89 \
      "${published[@]}"
    family "thesis-$id-shrink" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.6
    family "thesis-$id-shrink-published" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.6 \
      "${published[@]}"
    # h_AH found by the box holding the horizon at its own substages, the other boxes using its
    # latest value (hypothesis 2 of the study), and h_AH held over each step of the hierarchy
    family "thesis-$id-stretch-box-substage" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.89 \
      --rah-variant box-substage
    family "thesis-$id-shrink-box-substage" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.6 \
      --rah-variant box-substage
    family "thesis-$id-stretch-held" 24,32,48 "${boxes[@]}" --id $id --rahA 0.5 --rah0 0.89 \
      --ah-every step
  done
  finished
  for id in 1log-trumpet maximal-trumpet; do
    echo "== $id on the published grid (7 boxes, rmax 128), t in [10, 100] M"
    table "$out/thesis-$id-standard" "$out/thesis-$id"-*/ --t0 10 --t1 100
  done | tee "$out/thesis.txt"
  $py plots/horizon_study.py figure --cols 5 -o "$out/thesis.png" "$out"/thesis-*-trumpet-*/
  # the unshifted test of the published grid: the change of the conformal metric a since t = 0,
  # scaled for 4th order, at 10 M and 50 M, and the outer boundary's error front
  $py plots/error_profiles.py "$out"/thesis-1log-trumpet-standard/N{24,32,48} -y a --times 10,50 \
    -o "$out/thesis-metric-error.png" | tee -a "$out/thesis.txt"
  ;;
interp)
  # the same finest spacing M/12, M/16, M/24 on: 7 boxes (stage values, dense output, quadratic
  # in time as BAM and Carpet), the sinh grid (innermost cell) and uniform grids, rmax 128
  boxes=(--grid boxes --levels 7)
  common=(--id 1log-trumpet --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 100)
  for h in std 0.6 0.89 1.2 2; do
    # stretches with w = 3 M, the auto width when this comparison was made (docs Sec. 6.3, 8)
    shift_flags=()
    [ $h = std ] || shift_flags=(--rahA 0.5 --rah0 $h)
    case $h in 0.89 | 1.2 | 2) shift_flags+=(--rah-profile rational --rah-width 3) ;; esac
    family "interp-h$h-boxes-stages" 24,32,48 "${common[@]}" "${boxes[@]}" "${shift_flags[@]}"
    family "interp-h$h-boxes-quadratic" 24,32,48 "${common[@]}" "${boxes[@]}" "${shift_flags[@]}" \
      --time-interp quadratic
    family "interp-h$h-boxes-held" 24,32,48 "${common[@]}" "${boxes[@]}" "${shift_flags[@]}" \
      --time-interp quadratic --ah-every step
    family "interp-h$h-sinh" 384,512,768 "${common[@]}" --grid sinh --dr-inner 0.08 "${shift_flags[@]}"
    family "interp-h$h-uniform" 1536,2048,3072 "${common[@]}" --grid uniform "${shift_flags[@]}"
  done
  # h = 2 lies on the edge of the published grid's finest box (r <= 2 M): the same finest
  # spacings with 6 boxes (finest r <= 4 M, N = 48, 64, 96)
  six=(--grid boxes --levels 6)
  w3=(--rah-profile rational --rah-width 3)
  family interp-hstd-boxes6-stages 48,64,96 "${common[@]}" "${six[@]}"
  family interp-hstd-boxes6-quadratic 48,64,96 "${common[@]}" "${six[@]}" --time-interp quadratic
  family interp-h2-boxes6-stages 48,64,96 "${common[@]}" "${six[@]}" --rahA 0.5 --rah0 2 "${w3[@]}"
  family interp-h2-boxes6-dense 48,64,96 "${common[@]}" "${six[@]}" --rahA 0.5 --rah0 2 \
    "${w3[@]}" --time-interp dense
  family interp-h2-boxes6-quadratic 48,64,96 "${common[@]}" "${six[@]}" --rahA 0.5 --rah0 2 \
    "${w3[@]}" --time-interp quadratic
  family interp-h2-boxes6-quadratic-nosub 48,64,96 "${common[@]}" "${six[@]}" --rahA 0.5 \
    --rah0 2 "${w3[@]}" --time-interp quadratic --no-subcycling
  family interp-hstd-boxes6-quadratic-nosub 48,64,96 "${common[@]}" "${six[@]}" \
    --time-interp quadratic --no-subcycling
  finished
  for h in 0.6 0.89 1.2 2; do
    echo "== h = $h M (A = 0.5): ratio to the standard gauge on the same grid kind"
    for kind in boxes-stages boxes-quadratic boxes-held sinh uniform; do
      table "$out/interp-hstd-$kind" "$out/interp-h$h-$kind" --t0 10 --t1 100
    done
  done | tee "$out/interp.txt"
  {
    echo "== h = 2 M on 6 boxes (finest r <= 4 M), M/12 ... M/24"
    for kind in stages dense quadratic quadratic-nosub; do
      std=$kind
      [ $kind = dense ] && std=stages
      table "$out/interp-hstd-boxes6-$std" "$out/interp-h2-boxes6-$kind" --t0 10 --t1 100
    done
    echo "== the standard gauge on each grid kind"
    for kind in boxes-stages boxes-quadratic sinh uniform boxes6-stages boxes6-quadratic; do
      table "$out/interp-hstd-$kind" "$out/interp-hstd-$kind" --t0 10 --t1 100
    done
  } | tee -a "$out/interp.txt"
  $py plots/horizon_study.py figure --cols 4 -o "$out/interp.png" "$out"/interp-h1.2-boxes-*/ \
    "$out"/interp-h1.2-sinh "$out"/interp-h2-boxes6-*/
  ;;
cost)
  # wall time (one core, each member alone) against the RMS of H_L2_R over [10, 1000] M; each
  # measurement alone, its table (printed into its log) kept in $out/cost.txt
  lib_run_any cost $py plots/boxes_cost.py --out @OUT --tmax 1000 --bin build/gbssn1d
  lib_wait
  # and on wormhole data (standard gauge; boxes and the sinh grid)
  lib_run_any cost-wormhole $py plots/boxes_cost.py --out @OUT --tmax 1000 --id wormhole \
    --kinds boxes,sinh --gauges standard --bin build/gbssn1d
  lib_wait
  lib_check
  tee "$out/cost.txt" <"$out/cost.log"
  tee "$out/cost-wormhole.txt" <"$out/cost-wormhole.log"
  ;;
order)
  # --fd-order 6 against 4, each order's own standard gauge as the reference: the published
  # grid (7 boxes, rmax 128, M/12, M/16, M/24, to 100 M), h = 2 M on 6 boxes (finest r <= 4 M),
  # and the unshifted and stretched trumpet on 9 boxes to 1000 M (rmax 1024)
  seven=(--grid boxes --levels 7 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 100)
  six=(--grid boxes --levels 6 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 100)
  nine=(--grid boxes --levels 9 --rmax 1024 --tmax 1000 --dt-series 1 --dt-profiles 1000)
  for p in 4 6; do
    for id in 1log-trumpet maximal-trumpet; do
      family "order-p$p-$id-standard" 24,32,48 "${seven[@]}" --id $id --fd-order $p
      family "order-p$p-$id-stretch" 24,32,48 "${seven[@]}" --id $id --fd-order $p --rahA 0.5 --rah0 0.89
      family "order-p$p-$id-shrink" 24,32,48 "${seven[@]}" --id $id --fd-order $p --rahA 0.5 --rah0 0.6
    done
    family "order-p$p-six-standard" 48,64,96 "${six[@]}" --id 1log-trumpet --fd-order $p
    family "order-p$p-six-h2" 48,64,96 "${six[@]}" --id 1log-trumpet --fd-order $p --rahA 0.5 --rah0 2
    family "order-p$p-nine-standard" 48,64,96 "${nine[@]}" --id 1log-trumpet --fd-order $p --norm-Rmin 3
    family "order-p$p-nine-stretch" 48,64,96 "${nine[@]}" --id 1log-trumpet --fd-order $p --norm-Rmin 3 \
      --rahA 0.5 --rah0 0.89
  done
  finished
  for p in 4 6; do
    for id in 1log-trumpet maximal-trumpet; do
      echo "== --fd-order $p, $id on the published grid (7 boxes, rmax 128), t in [10, 100] M"
      table "$out/order-p$p-$id-standard" "$out/order-p$p-$id"-*/ --t0 10 --t1 100
    done
    echo "== --fd-order $p, h = 2 M on 6 boxes, t in [10, 100] M"
    table "$out/order-p$p-six-standard" "$out/order-p$p-six"-*/ --t0 10 --t1 100
    echo "== --fd-order $p, the trumpet on 9 boxes, t in [10, 1000] M"
    table "$out/order-p$p-nine-standard" "$out/order-p$p-nine"-*/ --t0 10 --t1 1000
  done | tee "$out/order.txt"
  ;;
taper)
  # beta_H's outer taper where coarse boxes sample it: h = 2 M on 6 boxes to rmax 128 (the taper
  # on boxes 1 and 2, spacing 0.67 ... 2.7 M) and the published grid's stretch and shrink, with
  # the quartic taper (default), the C-infinity step, and none (--rah-rcut 1e9), against each
  # grid's standard gauge
  six=(--grid boxes --levels 6 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 100 --id 1log-trumpet)
  seven=(--grid boxes --levels 7 --rmax 128 --tmax 100 --dt-series 0.5 --dt-profiles 100 --id 1log-trumpet)
  family taper-six-standard 48,64,96 "${six[@]}"
  family taper-seven-standard 24,32,48 "${seven[@]}"
  family taper-six-h2-none 48,64,96 "${six[@]}" --rahA 0.5 --rah0 2 --rah-rcut 1e9
  family taper-seven-h0.89-none 24,32,48 "${seven[@]}" --rahA 0.5 --rah0 0.89 --rah-rcut 1e9
  family taper-seven-h0.6-none 24,32,48 "${seven[@]}" --rahA 0.5 --rah0 0.6 --rah-rcut 1e9
  for taper in quartic step; do
    for rcut in 48 64 80; do
      family "taper-six-h2-$taper-rcut$rcut" 48,64,96 "${six[@]}" --rahA 0.5 --rah0 2 \
        --rah-taper $taper --rah-rcut $rcut
    done
    family "taper-seven-h0.89-$taper" 24,32,48 "${seven[@]}" --rahA 0.5 --rah0 0.89 --rah-taper $taper
    family "taper-seven-h0.6-$taper" 24,32,48 "${seven[@]}" --rahA 0.5 --rah0 0.6 --rah-taper $taper
  done
  finished
  {
    echo "== h = 2 M on 6 boxes (rmax 128), t in [10, 100] M"
    table "$out/taper-six-standard" "$out"/taper-six-h2-*/ --t0 10 --t1 100
    echo "== the published grid (7 boxes, rmax 128), rcut 64, t in [10, 100] M"
    table "$out/taper-seven-standard" "$out"/taper-seven-h*/ --t0 10 --t1 100
  } | tee "$out/taper.txt"
  ;;
bursts)
  # precollapsed wormhole data, standard gauge, 8 boxes, N = 96, to 1000 M, with the boxes ending
  # at rmax/2^l for rmax = 1000 and 1400 M: when do H_L2_R's bursts reach the window, against
  # t = (1/sqrt 2 + 1) R_b, the time for the collapse's pulse to reach a box's end R_b at the
  # lapse's speed sqrt 2 and come back at speed 1
  # (and, as the reference with the outer boundary out of the way to 1000 M, the rmax 1000 boxes
  # inside a ninth box to 2000 M)
  # (a run that stops by itself is a result too)
  for rl in 1000:8 1400:8 2000:9; do
    rmax=${rl%:*}
    lib_run "bursts-rmax$rmax" build/gbssn1d evolve --grid boxes --levels "${rl#*:}" --N 96 \
      --rmax $rmax --tmax 1000 "${cfl[@]}" --dt-series 1 --dt-profiles 1000 --out @OUT
  done
  lib_wait
  lib_check
  $py - "$out" <<'PY' | tee "$out/bursts.txt"
import math, os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series
out = sys.argv[1]
for rmax in (1000, 1400, 2000):
    s = series(os.path.join(out, f'bursts-rmax{rmax}', 'timeseries.dat'))
    t, H, dM = s['t'], s['H_L2_R'], np.abs(s['M_ah_err'])
    # local maxima of H (over +-40 M) above 1e-4 from 100 M on
    peaks = [i for i in range(len(t)) if t[i] >= 100 and H[i] > 1e-4
             and H[i] == H[max(0, i - 40):i + 41].max()]
    ends = [rmax / 2 ** l for l in range(1, 9 if rmax == 2000 else 8)]
    print(f"rmax {rmax}: boxes end at " + ", ".join(f"{r:g}" for r in ends) + " M")
    print("  predicted returns (1/sqrt 2 + 1) R_b: "
          + ", ".join(f"{(1 / math.sqrt(2) + 1) * r:.0f}" for r in ends if (1 / math.sqrt(2) + 1) * r <= 1000))
    print("  H_L2_R bursts (t, H): " + ", ".join(f"{t[i]:.0f} {H[i]:.1e}" for i in peaks))
    print(f"  max |M_AH - M| over 0-100 M {dM[t < 100].max():.1e}, over 100-1000 M {dM[t >= 100].max():.1e}")
PY
  ;;
speed)
  # the stretched study on 9 boxes to rmax 1024, finest M/8, M/12, M/16, to 1000 M
  # (the wall time is the last line of its log: that of the run in place)
  lib_run speed /usr/bin/time -f "wall %e s" build/gbssn1d converge --N 32,48,64 -j 2 --out @OUT \
    --grid boxes --levels 9 --rmax 1024 --id 1log-trumpet --rahA 0.5 --rah0 0.89 --tmax 1000 \
    --dt-series 1 --dt-profiles 1000
  lib_wait
  lib_check
  tail -n 1 "$out/speed.log"
  ;;
esac
