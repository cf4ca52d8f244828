#!/usr/bin/env bash
# Why would a horizon-shifted evolution stop converging? The "shrink" experiment
# (maximal-trumpet data, rah0 = 0.6, rahA = 0.5) at N = 400, 800, 1600 with the method as
# specified and with three implementation inconsistencies a 3D code could plausibly contain:
#   no-shift-derivatives  beta_H added to the shift's value, derivatives taken of beta_GD only
#   no-shift-second-derivatives  ... only the second derivatives (those of the Gamma equation)
#   delta-rhs-from-gd     d_t Delta^r computed with beta_GD for B, reused as Delta^r's own RHS
#   driver-full-shift     B driven by d_t Delta^r of the full shift instead of beta_GD
#   midstep-update        h_AH re-searched in the middle of an RK step (every 8 steps)
# plus a coarse horizon finder (tolerance 5e-6 M, the coarsest every member accepts: 0.001 of
# the N = 1600 member's smallest cell; held for 8 steps).
# Prints H_L2_ext and pairwise orders over time; figures in out/horizon-variants/*.png.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/horizon-variants.sh "$here" out/horizon-variants "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
variants=("consistent:--rah-variant consistent"
          "no-shift-derivatives:--rah-variant no-shift-derivatives"
          "no-shift-second-derivatives:--rah-variant no-shift-second-derivatives"
          "delta-rhs-from-gd:--rah-variant delta-rhs-from-gd"
          "driver-full-shift:--rah-variant driver-full-shift"
          "midstep-update:--rah-variant midstep-update --ah-every 8"
          "coarse-finder:--ah-every 8 --ah-tol 5e-6")
for v in "${variants[@]}"; do
  tag=${v%%:*} flags=${v#*:}
  # one `gbssn1d converge` per variant (members in out/horizon-variants/<tag>/N<n>/); a member
  # that blows up is a result, not a reason to stop: its log ($out/NAME.log) says where and when
  # shellcheck disable=SC2086
  lib_run "$tag" build/gbssn1d converge --N 400,800,1600 -j 1 --out @OUT \
    --config runs/horizon-maximal-shrink.toml $flags --dt-series 1 --dt-profiles 50
done
lib_wait
lib_check
for v in "${variants[@]}"; do
  tag=${v%%:*}
  echo "== $tag"
  $py plots/constraint_orders.py $out/$tag/N{400,800,1600}/timeseries.dat \
    --title "H on [1, 10] M, shrink run: $tag" -o $out/H_orders_$tag.png
  awk '!/^#/ {row=$0} END {split(row, c, " "); printf "   last row: t = %g, r_ah = %.5f\n", c[1], c[10]}' \
    $out/$tag/N1600/timeseries.dat
done
echo "== runs that stopped:"
grep -h -E "non-finite|physical range" "$out"/*.log || echo "none"
