#!/usr/bin/env bash
# Does the Hamiltonian constraint converge with the horizon shift? Maximal-trumpet data,
# standard / stretch / shrink, three resolutions N = 400, 800, 1600 on one sinh map, to
# t = 100 M; h_AH found at every RK substage and, as a 3D code does, held between searches
# every 8 steps. Prints H_L2_ext and the pairwise orders over time; figures in
# out/horizon-convergence/*.png. A few minutes on 2 cores.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/horizon-convergence.sh "$here" out/horizon-convergence "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
variants=("standard:--ah-every substage" "stretch:--ah-every substage" "shrink:--ah-every substage"
          "shrink:--ah-every 8" "stretch:--ah-every 8")
tags=()
for v in "${variants[@]}"; do
  cfg=${v%%:*} flags=${v#*:}
  tag="$cfg$(echo "$flags" | tr -d ' -' | sed 's/aheverysubstage//; s/aheverys*/-every/')"
  tags+=("$tag")
  # one `gbssn1d converge` per run (members in out/horizon-convergence/<tag>/N<n>/); a member
  # that blows up is a result, not a reason to stop: its log ($out/NAME.log) says where and when
  # shellcheck disable=SC2086
  lib_run "$tag" build/gbssn1d converge --N 400,800,1600 -j 1 --out @OUT \
    --config "runs/horizon-maximal-$cfg.toml" $flags --dt-series 1 --dt-profiles 100
done
lib_wait
lib_check
for tag in "${tags[@]}"; do
  echo "== $tag"
  $py plots/constraint_orders.py $out/$tag/N{400,800,1600}/timeseries.dat \
    --title "H on [1, 10] M: $tag" -o $out/H_orders_$tag.png
done
