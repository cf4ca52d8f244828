#!/usr/bin/env bash
# A horizon that grows by accretion, with and without the horizon-adjusting shift
# (docs/scalar-field.md, "A growing horizon"): the precollapsed wormhole of M = 1 with a shell of
# the massless scalar field, Phi = 0.04 exp(-((r - 10)/2)^2), time symmetric (--id wormhole
# --matter scalar --scalar-amp 0.04 --scalar-r0 10 --scalar-width 2): M_AH grows from 1.034 to
# 1.377 between t ~ 10 and 25 as the shell's inner half falls in. Gauges: the horizon left to
# grow (`free`: no horizon shift) and held at h = 0.6, 1, 1.5, 2 M (`h<h>`: --rahA 0.5 --rah0 h),
# and at h = 1 M with --rahA 1, 2, 5 and 20 (`h1.0-A<A>`).
#   1. gauges/: each gauge on the default grid (sinh, rmax 1000) at N = 400 and 800 to t = 80:
#      M_AH(t), r_AH(t); whether r_AH ends at h, how far it strays from h while M_AH grows, and
#      the final M_AH against the free run's (at both N, so that its difference is seen to fall).
#   2. converge/: H through the accretion (converge's verdict, --fields alpha,chi,K,Phi) to
#      t = 60 for free, h0.6, h1.0 and h2.0: on the sinh grid at N = 200, 300, 400 (M/25 to M/50
#      at the centre) and 400, 600, 800 (to M/100); on 7 nested boxes to rmax 256 at N = 64,
#      128, 256 (M/16 to M/64 on the finest box; every member's hierarchy steps by 0.5 M, the
#      cap of the coarse boxes' step), 128, 256, 512 (0.5, 0.5, 0.25 M: the cap binds in two
#      members, so with the horizon shift the coarse boxes' extrapolated h_AH is a different
#      gauge in the third, which converge warns of) and 256, 512, 1024 (0.5, 0.25, 0.125 M);
#      and at N = 64, 128, 256 with --no-subcycling (every box at the finest box's step).
#   3. cost/: M_AH at t = 60 against cost for the same four gauges: the sinh grid at N = 100 ...
#      1600 (each step sqrt(2)), 7 boxes at N = 48 ... 384; the error against the same gauge's
#      sinh N = 1600 (at most 1e-7 from every other gauge's there), the cost N x RHS evaluations
#      (points x evaluations: each box holds N cells); for each gauge and grid the cheapest run
#      within 1e-3, 1e-4 and 1e-5.
#   4. budget/: the energy through the spheres of areal radius 5 and 30 M (--flux-R 5,30, a row
#      every 0.05) for free and h1.0 at N = 400, 800, 1600 to t = 80: what crossed R = 5 inwards
#      against M_AH's growth, what left through R = 30, and the error of the identity
#      integral of flux = m(0) - m(end) at each sphere, with its order.
# Writes OUT/accretion.txt (the tables), OUT/gauges.dat, OUT/cost.dat, OUT/budget.dat and the figures
# OUT/accretion.png and OUT/cost.png (plots/accretion.py). Kept in out/accretion/ and redone only
# where a command or the binary changed; an interrupted run resumes. About 1.5 minutes on 2 cores.
#
# Usage: bash runs/accretion.sh [OUT]     GBSSN1D_JOBS: runs at once (default: the core count)
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/accretion.sh "$here" out/accretion "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
data=(--id wormhole --matter scalar --scalar-amp 0.04 --scalar-r0 10 --scalar-width 2)
boxes=(--grid boxes --rmax 256 --levels 7)
fields=(--fields alpha,chi,K,Phi)

gauge_flags() { # GAUGE: its flags (free: none)
  case $1 in
  free) ;;
  h*-A*) local h=${1#h} && echo "--rahA ${h#*-A} --rah0 ${h%-A*}" ;;
  h*) echo "--rahA 0.5 --rah0 ${1#h}" ;;
  esac
}
compared=(free h0.6 h1.0 h2.0)

# 1. the gauges on the default grid
for N in 400 800; do
  for g in free h0.6 h1.0 h1.5 h2.0 h1.0-A1 h1.0-A2 h1.0-A5 h1.0-A20; do
    # shellcheck disable=SC2046 # the gauge's flags are words
    lib_run "gauges/N$N/$g" build/gbssn1d evolve "${data[@]}" $(gauge_flags "$g") --N "$N" \
      --tmax 80 --dt-series 0.25 --dt-profiles 80 --out @OUT
  done
done

# 2. convergence through the accretion
for g in "${compared[@]}"; do
  # shellcheck disable=SC2046
  for family in "sinh-N200 200,300,400" "sinh-N400 400,600,800"; do
    lib_run "converge/$g-${family% *}" build/gbssn1d converge "${data[@]}" $(gauge_flags "$g") \
      --N "${family#* }" --tmax 60 "${fields[@]}" --out @OUT
  done
  for family in "boxes-N64 64,128,256" "boxes-N128 128,256,512" "boxes-N256 256,512,1024" \
    "boxes-nosub-N64 64,128,256 --no-subcycling"; do
    read -r name Ns extra <<<"$family"
    # shellcheck disable=SC2046,SC2086 # the gauge's and the family's flags are words
    lib_run "converge/$g-$name" build/gbssn1d converge "${data[@]}" $(gauge_flags "$g") \
      "${boxes[@]}" $extra --N "$Ns" --tmax 60 "${fields[@]}" --out @OUT
  done
done

# 3. M_AH's error against cost
for g in "${compared[@]}"; do
  for N in 100 141 200 283 400 566 800 1131 1600; do
    # shellcheck disable=SC2046
    lib_run "cost/$g/sinh-N$N" build/gbssn1d evolve "${data[@]}" $(gauge_flags "$g") --N "$N" \
      --tmax 60 --dt-series 1 --dt-profiles 60 --out @OUT
  done
  for N in 48 64 96 128 192 256 384; do
    # shellcheck disable=SC2046
    lib_run "cost/$g/boxes-N$N" build/gbssn1d evolve "${data[@]}" $(gauge_flags "$g") \
      "${boxes[@]}" --N "$N" --tmax 60 --dt-series 1 --dt-profiles 60 --out @OUT
  done
done

# 4. the energy budget
for g in free h1.0; do
  for N in 400 800 1600; do
    # shellcheck disable=SC2046
    lib_run "budget/$g/N$N" build/gbssn1d evolve "${data[@]}" $(gauge_flags "$g") --N "$N" \
      --tmax 80 --dt-series 0.05 --dt-profiles 80 --flux-R 5,30 --out @OUT
  done
done
lib_wait
lib_check

# 5. the tables and figures
$py plots/accretion.py "$out" | tee "$out/accretion.txt"
