#!/usr/bin/env bash
# Critical collapse of the massless scalar field (docs/scalar-field.md, "Critical collapse"):
# the time-symmetric Gaussian at the centre, Phi = A exp(-r^2) (--id flat --matter scalar
# --scalar-r0 0 --scalar-width 1), BSSN with 1+log slicing and each shift Akbarian & Choptuik
# ran (--shift gamma-driver and --shift zero), on nested boxes whose finest resolve the echoes
# (settings below and why).
#   1. Bisection in A from [0.30, 0.31] between dispersal (no apparent horizon by t = tmax) and
#      collapse (an apparent horizon after t = 0), as far as the resolution allows: it ends when
#      the bracket is below 1e-10 of A, after 45 halvings, or at the first run that stops (exit
#      3, left the physical range) without a horizon, which is neither answer: that run is
#      named. (A wider bracket is no use: from A ~ 0.32 to 0.35 the runs stop near the centre
#      before a horizon is found, docs/scalar-field.md.) A shift whose bracket does not hold
#      (A = 0.30 must disperse, 0.31 collapse) is reported and left out.
#   2. The mass-scaling exponent: runs at A = p* (1 + eps), eps = 10^(-k/4), k = 8 ... 32 (the
#      ones above the bracket); gamma from the least squares of ln M_AH on ln(A - p*) over the
#      eps in [EPS_LO, EPS_HI] (below), with its standard error, the range used and the points
#      left out, twice: with M_AH at the end of the runs that reached t = tmax, and with M_AH
#      when a horizon was first found (every collapsed run, also those that stopped after it).
#   3. The echoing period: the dispersing run nearest the threshold again to t = 8 with
#      Phi_center every 0.0005 (the last echoes are 1e-3 apart in the central proper time T =
#      int alpha_center dt); the extrema of Phi_center from the largest (the first at the
#      critical solution's amplitude) through the last above 3/4 of it; T* and Delta fitted to
#      ln(T* - T_k) = c - k Delta/2 (successive extrema are half a period apart: the critical
#      solution changes Phi's sign every half period), its error the spread of the exact fits
#      through each three consecutive extrema.
# Writes OUT/critical.txt (the table and the results), OUT/scaling.dat, OUT/echoes.dat and the
# figures OUT/mass-scaling.png and OUT/echoes.png (plots/critical.py). Kept in out/critical/
# and redone only where a command or the binary changed; an interrupted run resumes. About
# 15 minutes on 2 cores (the two shifts' runs side by side, 7 s each).
#
# Usage: bash runs/critical.sh [OUT] [N]   GBSSN1D_JOBS: runs at once (default: the core count)
#   N: cells per box (default 128); 256 halves every spacing (the resolution's check: about 4
#   times the cost), and its results default to out/critical-N256.
set -euo pipefail
here=$PWD
N=128
[ $# -lt 2 ] || N=$2
case $N in
'' | *[!0-9]* | 0*) echo "runs/critical.sh: N = '$N' is invalid: it must be a whole number of cells per box, e.g. 128 or 256" >&2; exit 2 ;;
esac
if [ "$N" -lt 64 ] || [ "$N" -gt 4096 ]; then
  echo "runs/critical.sh: N = $N is invalid: 64 to 4096 cells per box" >&2
  exit 2
fi
default=out/critical
[ "$N" = 128 ] || default=out/critical-N$N
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/critical.sh "$here" "$default" "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
# The grid: 13 nested boxes of 128 cells to rmax 32 (Berger-Oliger subcycling: each box steps
# at its own spacing), spacings 0.25 M on the outermost down to 6.1e-5 on the finest (r <=
# 0.0078): a horizon of M_AH = 2e-4 spans 6 of its cells, and each run takes 7 s where a sinh
# grid of the same innermost cell takes minutes (every cell steps at the smallest cell's step).
# The outer boundary lies 20 beyond where the outgoing half of the pulse is at t = 12. The time:
# tmax 12 (collapse or dispersal is decided by t ~ 7), Phi_center every 0.005.
grid=(--id flat --matter scalar --scalar-r0 0 --scalar-width 1 --grid boxes --rmax 32 --N "$N"
      --levels 13)
family=("${grid[@]}" --tmax 12 --dt-series 0.005 --dt-profiles 12)
shifts=(gamma-driver zero)
EPS_LO=1e-6
EPS_HI=1e-2

# collapse | disperse | stopped: how the run in $out/NAME ended (plots/critical.py's reading)
verdict() {
  $py -c 'import sys; sys.path.insert(0, "plots"); import critical; print(critical.run_result(sys.argv[1])[0])' "$out/$1"
}
run_A() { # SHIFT A: the run of amplitude A named by both
  lib_run "$1/A=$2" build/gbssn1d evolve "${family[@]}" --shift "$1" --scalar-amp "$2" --out @OUT
}
half() { $py -c "import sys; print(repr((float(sys.argv[1]) + float(sys.argv[2])) / 2))" "$1" "$2"; }
narrow() { $py -c "import sys; print(int((float(sys.argv[2]) - float(sys.argv[1])) > 1e-10 * float(sys.argv[2])))" "$1" "$2"; }

# 1. the bracket's ends, then both shifts' halvings side by side
declare -A lo hi state mid
for s in "${shifts[@]}"; do
  lo[$s]=0.30 hi[$s]=0.31 state[$s]=bisecting
  run_A "$s" "${lo[$s]}"
  run_A "$s" "${hi[$s]}"
done
lib_wait
lib_check
studied=()
for s in "${shifts[@]}"; do
  if [ "$(verdict "$s/A=${lo[$s]}")" != disperse ] || [ "$(verdict "$s/A=${hi[$s]}")" != collapse ]; then
    state[$s]="no bracket: A = ${lo[$s]} $(verdict "$s/A=${lo[$s]}")s, A = ${hi[$s]} $(verdict "$s/A=${hi[$s]}")s"
    echo "runs/critical.sh: --shift $s: A = ${lo[$s]} must disperse and A = ${hi[$s]} collapse; ${state[$s]} (see $out/$s): left out" >&2
  else
    studied+=("$s")
  fi
done
[ ${#studied[@]} -gt 0 ] || { echo "runs/critical.sh: no shift has a bracket" >&2; exit 1; }
for step in $(seq 1 45); do
  active=()
  for s in "${studied[@]}"; do
    [ "${state[$s]}" = bisecting ] || continue
    if [ "$(narrow "${lo[$s]}" "${hi[$s]}")" = 0 ]; then state[$s]="bracket below 1e-10"; continue; fi
    mid[$s]=$(half "${lo[$s]}" "${hi[$s]}")
    run_A "$s" "${mid[$s]}"
    active+=("$s")
  done
  [ ${#active[@]} -gt 0 ] || break
  lib_wait
  lib_check
  for s in "${active[@]}"; do
    case $(verdict "$s/A=${mid[$s]}") in
    collapse) hi[$s]=${mid[$s]} ;;
    disperse) lo[$s]=${mid[$s]} ;;
    stopped) state[$s]="stopped at A = ${mid[$s]} (the resolution's limit; $out/$s/A=${mid[$s]}.log)" ;;
    esac
  done
done
for s in "${studied[@]}"; do
  [ "${state[$s]}" != bisecting ] || state[$s]="45 halvings"
done

# 2. the mass-scaling runs above each bracket
for s in "${studied[@]}"; do
  for A in $($py -c "
import sys
lo, hi = float(sys.argv[1]), float(sys.argv[2])
p = (lo + hi) / 2
for k in range(8, 33):
    A = p * (1 + 10 ** (-k / 4))
    if A > hi:
        print(repr(A))" "${lo[$s]}" "${hi[$s]}"); do
    run_A "$s" "$A"
  done
done
lib_wait
lib_check

# 3. the echoes: the dispersing run nearest the threshold, sampled finely
for s in "${studied[@]}"; do
  lib_run "$s-echo/A=${lo[$s]}" build/gbssn1d evolve "${grid[@]}" --tmax 8 --dt-series 0.0005 \
    --dt-profiles 12 --shift "$s" --scalar-amp "${lo[$s]}" --out @OUT
done
lib_wait
lib_check

# 4. the tables, fits and figures
args=()
for s in "${studied[@]}"; do args+=("$s" "${lo[$s]}" "${hi[$s]}" "${state[$s]}"); done
: >"$out/critical.txt"
for s in "${shifts[@]}"; do
  [[ " ${studied[*]} " == *" $s "* ]] || echo "--shift $s: ${state[$s]}" | tee -a "$out/critical.txt"
done
$py plots/critical.py "$out" "$EPS_LO" "$EPS_HI" "${args[@]}" | tee -a "$out/critical.txt"
