#!/usr/bin/env bash
# The thesis mechanism's scaling (study doc Sec. 13.1): the published configuration (7 boxes to
# 128 M, maximal trumpet, stretch to 0.89 M with the rational profile of width 1, the unit
# normal, upwind-gd, quadratic time interpolation with subcycling) with h_AH held between
# searches a fixed time T apart (--ah-interval T, the same hold at every resolution, as a 3D
# code calls its finder every T), against the same runs with one smooth h_AH(t) (the default:
# a search after every step, extrapolated to every RK stage). The excess of H over the smooth
# run's, sqrt(RMS(H_held)^2 - RMS(H_smooth)^2) of H_L2_R over (0, 20] M, is measured along four
# axes, each with everything else held fixed:
#   the hold T = 0.5 ... 16 M           (N = 64, cfl 0.25, A = 0.5)
#   the strength A = 0.25, 0.5, 1       (N = 64, cfl 0.25, T = 1 M)
#   the Courant number 0.25 ... 0.0625  (N = 64 and 128, T = 1 M, A = 0.5)
#   the spacing M/12 ... M/128          (N = 24 ... 256, cfl 0.25, T = 1 M; to M/64 with 4 M)
# and, at the published spacings M/12, M/16, M/24, holds of 1-16 M at cfl 0.25 and 0.5: the
# pairwise orders of the RMS of H, held and smooth.
# Table out/hold-scaling/scaling.dat, fits and the crossing with the smooth run's truncation
# error printed, figure out/hold-scaling/scaling.png (plots/hold_scaling.py).
#
#   bash runs/hold-scaling.sh [OUT]     # default out/hold-scaling; about 2 minutes on 2 cores
#
# GBSSN1D_JOBS=n runs n at once (a positive whole number; default: the core count). A rerun
# keeps every completed run of the same command and redoes the rest; Ctrl-C stops at once.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/hold-scaling.sh "$here" out/hold-scaling "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
start=$(date +%s)

published=(--id maximal-trumpet --grid boxes --levels 7 --rmax 128 --rah0 0.89
           --rah-profile rational --rah-width 1 --rah-normal unit --driver-advection upwind-gd
           --time-interp quadratic --tmax 20 --dt-series 0.25 --dt-profiles 20)
# member NAME N CFL A [T]: a held run (T given) or the smooth reference (no T)
member() {
  local name=$1 N=$2 cfl=$3 A=$4 T=${5:-}
  local hold=()
  [ -z "$T" ] || hold=(--ah-interval "$T")
  lib_run "$name" build/gbssn1d evolve --out @OUT "${published[@]}" --N "$N" --cfl "$cfl" \
    --rahA "$A" "${hold[@]}"
}
rows=()
# pair N CFL A T: the held run and its smooth reference
pair() {
  local N=$1 cfl=$2 A=$3 T=$4
  member "held-N$N-cfl$cfl-A$A-T$T" "$N" "$cfl" "$A" "$T"
  member "smooth-N$N-cfl$cfl-A$A" "$N" "$cfl" "$A"
  rows+=("$N:$cfl:$A:$T")
}
for T in 0.5 1 2 4 8 16; do pair 64 0.25 0.5 $T; done
for A in 0.25 1; do pair 64 0.25 $A 1; done
for N in 64 128; do for cfl in 0.125 0.0625; do pair $N $cfl 0.5 1; done; done
for N in 24 32 48 96 128 192 256; do pair $N 0.25 0.5 1; done
for N in 24 32 48 96 128; do pair $N 0.25 0.5 4; done
# the published spacings (M/12, M/16, M/24) with longer holds, and at cfl 0.5: which hold
# makes the M/16 run lose order against the M/12 one
for N in 24 32 48; do
  for T in 8 16; do pair $N 0.25 0.5 $T; done
  for T in 1 4 8 16; do pair $N 0.5 0.5 $T; done
done
lib_wait
lib_check # no table from a run that did not complete
/usr/bin/python3 plots/hold_scaling.py "$out" "${rows[@]}"
echo "runs/hold-scaling.sh: $(( $(date +%s) - start )) s; table $out/scaling.dat, figure $out/scaling.png"
