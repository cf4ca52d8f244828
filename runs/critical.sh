#!/usr/bin/env bash
# Critical collapse of the massless scalar field (docs/scalar-field.md, "Critical collapse"):
# the time-symmetric Gaussian at the centre, Phi = A exp(-r^2) (--id flat --matter scalar
# --scalar-r0 0 --scalar-width 1), BSSN with 1+log slicing and each shift Akbarian & Choptuik
# ran (--shift gamma-driver and --shift zero), on a sinh grid whose innermost cells resolve the
# echoes (settings below and why).
#   1. Bisection in A between dispersal (no apparent horizon by t = tmax) and collapse (an
#      apparent horizon after t = 0), as far as the resolution allows: it ends when the bracket
#      is below 1e-10 of A, after 45 halvings, or at the first run that stops (exit 3, left the
#      physical range) without a horizon, which is neither answer: that run is named.
#   2. The mass-scaling exponent: runs at A = p* (1 + eps), eps = 10^(-k/4), k = 4 ... 32 (the
#      ones above the bracket), M_AH at the end of each (t = tmax); gamma from the least
#      squares of ln M_AH on ln(A - p*) over the eps in [EPS_LO, EPS_HI] (below), with its
#      standard error, the range used and the points left out (no horizon, stopped).
#   3. The echoing period: the extrema of Phi_center(t) of the dispersing run nearest the
#      threshold, against the central proper time T = int alpha_center dt; T* and Delta fitted
#      to ln(T* - T_k) = c - k Delta/2 (successive extrema are half a period apart: the critical
#      solution changes Phi's sign every half period), with the fit's standard error.
# Writes OUT/critical.txt (the table and the results), OUT/scaling.dat, OUT/echoes.dat and the
# figures OUT/mass-scaling.png and OUT/echoes.png (plots/critical.py). Kept in out/critical/
# and redone only where a command or the binary changed; an interrupted run resumes. About
# 25 minutes on 2 cores (the two shifts' runs side by side).
#
# Usage: bash runs/critical.sh [OUT]     GBSSN1D_JOBS: runs at once (default: the core count)
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/critical.sh "$here" out/critical "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
# The grid: sinh, rmax 40 (the outer boundary 28 M beyond where the outgoing half of the pulse
# is at t = 12), N = 1600 with --dr-inner 0.0016 (the map of N = 400's innermost cell 0.0016:
# innermost cells of 4e-4 at N = 1600), so that a horizon of M_AH ~ 1e-3 spans a few cells.
# The time: tmax 12 (collapse or dispersal is decided by t ~ 7), Phi_center every 0.005.
family=(--id flat --matter scalar --scalar-r0 0 --scalar-width 1 --grid sinh --rmax 40
        --N 1600 --dr-inner 0.0016 --tmax 12 --dt-series 0.005 --dt-profiles 12)
shifts=(gamma-driver zero)
EPS_LO=1e-6
EPS_HI=1e-2

# collapse | disperse | stopped: how the run in $out/NAME ended
verdict() {
  $py - "$out/$1" <<'EOF'
import math, sys
d = sys.argv[1]
found = False
cols = None
for line in open(f"{d}/horizon.dat"):
    if line.startswith("# t "):
        cols = line[2:].split()
    elif not line.startswith("#") and line.strip():
        v = line.split()
        t, r = float(v[cols.index("t")]), float(v[cols.index("r_ah")])
        found = found or (t > 0 and math.isfinite(r))
end = [l for l in open(f"{d}/timeseries.dat") if l.startswith("# end:")]
completed = bool(end) and end[-1].startswith("# end: completed")
print("collapse" if found else ("disperse" if completed else "stopped"))
EOF
}
run_A() { # SHIFT A: the run of amplitude A named by both
  lib_run "$1/A=$2" build/gbssn1d evolve "${family[@]}" --shift "$1" --scalar-amp "$2" --out @OUT
}
half() { $py -c "import sys; print(repr((float(sys.argv[1]) + float(sys.argv[2])) / 2))" "$1" "$2"; }
narrow() { $py -c "import sys; print(int((float(sys.argv[2]) - float(sys.argv[1])) > 1e-10 * float(sys.argv[2])))" "$1" "$2"; }

# 1. the bracket's ends, then both shifts' halvings side by side
declare -A lo hi state mid
for s in "${shifts[@]}"; do
  lo[$s]=0.25 hi[$s]=0.40 state[$s]=bisecting
  run_A "$s" "${lo[$s]}"
  run_A "$s" "${hi[$s]}"
done
lib_wait
lib_check
for s in "${shifts[@]}"; do
  if [ "$(verdict "$s/A=${lo[$s]}")" != disperse ] || [ "$(verdict "$s/A=${hi[$s]}")" != collapse ]; then
    echo "runs/critical.sh: --shift $s: A = ${lo[$s]} must disperse and A = ${hi[$s]} collapse; they do not (see $out/$s)" >&2
    exit 1
  fi
done
for step in $(seq 1 45); do
  active=()
  for s in "${shifts[@]}"; do
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
for s in "${shifts[@]}"; do
  [ "${state[$s]}" != bisecting ] || state[$s]="45 halvings"
done

# 2. the mass-scaling runs above each bracket
for s in "${shifts[@]}"; do
  for A in $($py -c "
import sys
lo, hi = float(sys.argv[1]), float(sys.argv[2])
p = (lo + hi) / 2
for k in range(4, 33):
    A = p * (1 + 10 ** (-k / 4))
    if A > hi:
        print(repr(A))" "${lo[$s]}" "${hi[$s]}"); do
    run_A "$s" "$A"
  done
done
lib_wait
lib_check

# 3. the tables, fits and figures
args=()
for s in "${shifts[@]}"; do args+=("$s" "${lo[$s]}" "${hi[$s]}" "${state[$s]}"); done
$py plots/critical.py "$out" "$EPS_LO" "$EPS_HI" "${args[@]}" | tee "$out/critical.txt"
