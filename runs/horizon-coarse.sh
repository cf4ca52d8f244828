#!/usr/bin/env bash
# The horizon-adjusting shift at the coarse spacings a 3D code affords near the puncture
# (docs/horizon-shift-study.md). Uniform grids, rmax = 200 M, to t = 100 M; every family is one
# `gbssn1d converge` run; norms are H_L2_R (areal radius 2.5 M <= R <= 12 M: the same place in
# every gauge).
#
#   bash runs/horizon-coarse.sh reproduce   # published form vs defaults, M/8, M/12, M/16 (~2 min)
#   bash runs/horizon-coarse.sh mechanism   # experiments (a)-(e) on the 1+log stretch (~3 min)
#   bash runs/horizon-coarse.sh threshold   # h = 0.5 ... 2, M/8 ... M/32, both forms (~15 min)
#   bash runs/horizon-coarse.sh cost        # work to reach an error, uniform and sinh (~8 min)
#   (a second argument OUT writes into OUT instead of out/horizon-coarse; GBSSN1D_JOBS=n: n at once;
#   a rerun keeps every study that completed with the same command and binary, runs/lib.sh)
#
# Tables are printed (plots/horizon_study.py table: RMS of H_L2_R over t in [10, 100] M per N,
# pairwise orders of those, the range of pairwise orders over time, the ratio to the standard
# gauge at the same N); figures go to out/horizon-coarse/*.png.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
case ${1:-reproduce} in
reproduce | mechanism | threshold | cost) ;;
*)
  echo "usage: $0 reproduce|mechanism|threshold|cost [OUT] (not '$1')" >&2
  exit 2
  ;;
esac
source runs/lib.sh
lib_init runs/horizon-coarse.sh "$here" out/horizon-coarse "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
common=(--rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
grid=(--grid uniform) # the cost stage sets a sinh grid for its sinh families
# the published method: f = r/(1+r^2), the unit normal sqrt(chi/a)
pub_profile=(--rah-profile rational --rah-width 1)
published=("${pub_profile[@]}" --rah-normal unit --driver-advection upwind-gd)

# family NAME "N list" [evolve flags]: one converge study into $out/NAME, kept if it completed
# with this very command and binary (runs/lib.sh), waited for: the tables below read it at once
family() {
  local name=$1 Ns=$2
  shift 2
  lib_run "$name" build/gbssn1d converge --N "$Ns" -j "$jobs" --out @OUT "${common[@]}" "${grid[@]}" "$@"
  lib_wait
  lib_check "$name"
}
table() { $py plots/horizon_study.py table "$@"; }

stage=${1:-reproduce}
case $stage in
reproduce)
  coarse=1600,2400,3200
  for id in 1log-trumpet maximal-trumpet; do
    family "$id-standard" $coarse --id $id
    family "$id-stretch-published" $coarse --id $id --rahA 0.5 --rah0 0.89 "${published[@]}"
    family "$id-shrink-published" $coarse --id $id --rahA 0.5 --rah0 0.6 "${published[@]}"
    family "$id-stretch" $coarse --id $id --rahA 0.5 --rah0 0.89
    family "$id-shrink" $coarse --id $id --rahA 0.5 --rah0 0.6
    echo "== $id: published form, then the defaults"
    table "$out/$id-standard" "$out/$id"-{standard,stretch-published,shrink-published,stretch,shrink}
  done
  $py plots/horizon_study.py figure --cols 5 -o "$out/reproduce.png" \
    "$out"/{1log,maximal}-trumpet-{standard,stretch-published,shrink-published,stretch,shrink}
  ;;
mechanism)
  coarse=1600,2400,3200
  id=1log-trumpet
  s=(--id $id --rahA 0.5 --rah0 0.89)
  family "$id-standard" $coarse --id $id
  family "$id-stretch-published" $coarse "${s[@]}" "${published[@]}"
  # (a) open loop: h_AH(t) of a fine closed-loop run, the same function at every resolution
  if [ ! -f "$out/fine-stretch-published/horizon.dat" ]; then
    rm -rf "$out/fine-stretch-published"
    build/gbssn1d evolve --rmax 200 --tmax 100 --dt-series 0.25 --dt-profiles 100 "${grid[@]}" \
      --N 6400 "${s[@]}" "${published[@]}" \
      --out "$out/fine-stretch-published" 2>/dev/null
  fi
  family a-open-loop $coarse "${s[@]}" "${published[@]}" \
    --rah-hAH-file "$out/fine-stretch-published/horizon.dat"
  # (b) the normal: kinked at the puncture (unit) or smooth
  family b-smooth-0.01 $coarse "${s[@]}" "${pub_profile[@]}" --driver-advection upwind-gd --rah-normal smooth --rah-chi-smooth 0.01
  family b-smooth-0.1 $coarse "${s[@]}" "${pub_profile[@]}" --driver-advection upwind-gd --rah-normal smooth --rah-chi-smooth 0.1
  family b-smooth-0.3 $coarse "${s[@]}" "${pub_profile[@]}" --driver-advection upwind-gd --rah-normal smooth --rah-chi-smooth 0.3
  family b-conformal $coarse "${s[@]}" "${pub_profile[@]}" --driver-advection upwind-gd --rah-normal conformal
  family b-conformal-A0.2 $coarse --id $id --rahA 0.2 --rah0 0.89 "${pub_profile[@]}" --driver-advection upwind-gd --rah-normal conformal
  # (c) profiles and widths (conformal normal)
  for pw in rational:2 rational:3 rational3:1 gauss:1 gauss:2 gauss3:1; do
    family "c-${pw%%:*}-w${pw#*:}" $coarse "${s[@]}" --rah-normal conformal \
      --rah-profile "${pw%%:*}" --rah-width "${pw#*:}"
  done
  # (d) the advection stencils, published form and h = 2 (where the published form blows up)
  family d-driver-centred $coarse "${s[@]}" "${pub_profile[@]}" --rah-normal unit \
    --driver-advection centred
  family d-driver-upwind-full $coarse "${s[@]}" "${pub_profile[@]}" --rah-normal unit \
    --driver-advection upwind-full
  family d-delta-centred $coarse "${s[@]}" "${published[@]}" --delta-advection centred
  family d-conformal-driver-centred $coarse "${s[@]}" "${pub_profile[@]}" --rah-normal conformal \
    --driver-advection centred
  for adv in upwind-gd upwind-full centred matched; do
    family "d-h2-$adv" $coarse --id $id --rahA 0.5 --rah0 2 "${pub_profile[@]}" --rah-normal unit \
      --driver-advection $adv
  done
  family d-h2-conformal $coarse --id $id --rahA 0.5 --rah0 2 "${pub_profile[@]}" \
    --rah-normal conformal --driver-advection upwind-gd
  # (e) dissipation and time step (published form)
  family e-ko0 $coarse "${s[@]}" "${published[@]}" --ko-sigma 0
  family e-ko0.3 $coarse "${s[@]}" "${published[@]}" --ko-sigma 0.3
  family e-cfl0.5 $coarse "${s[@]}" "${published[@]}" --cfl 0.5
  echo "== 1+log trumpet, stretch to 0.89 M: the mechanism"
  table "$out/$id-standard" "$out/$id-standard" "$out/$id-stretch-published" "$out"/[a-e]-*/
  $py plots/horizon_study.py figure --cols 4 -o "$out/mechanism.png" "$out/$id-stretch-published" \
    "$out"/a-open-loop "$out"/b-smooth-0.01 "$out"/b-conformal "$out"/d-driver-centred \
    "$out"/d-h2-upwind-gd "$out"/d-h2-centred "$out"/d-h2-conformal
  ;;
threshold)
  all=1600,2400,3200,4800,6400
  id=1log-trumpet
  family "t-standard" $all --id $id
  for h in 0.5 0.6 0.89 1.0 1.2 1.5 2.0; do
    family "t-h$h-published" $all --id $id --rahA 0.5 --rah0 $h "${published[@]}"
    family "t-h$h" $all --id $id --rahA 0.5 --rah0 $h
  done
  # maximal-trumpet data: the default method, M/8 ... M/24
  family "tm-standard" 1600,2400,3200,4800 --id maximal-trumpet
  for h in 0.5 0.6 0.89 1.2 2.0; do
    family "tm-h$h" 1600,2400,3200,4800 --id maximal-trumpet --rahA 0.5 --rah0 $h
  done
  echo "== 1+log trumpet, M/8 ... M/32 (N = $all)"
  table "$out/t-standard" "$out"/t-*/ | tee "$out/threshold-table.txt"
  echo "== maximal trumpet, M/8 ... M/24"
  table "$out/tm-standard" "$out"/tm-*/ | tee -a "$out/threshold-table.txt"
  $py plots/horizon_study.py threshold "$out"/t-*/ "$out"/tm-*/ --min-order 3.5
  ;;
cost)
  # uniform: the threshold families; sinh: one map at every N (--dr-inner 0.06 at N = 400), from
  # about M/12 near the horizon at N = 300 to M/33 at N = 800
  bash "$0" threshold >/dev/null # redoes only the families whose inputs changed
  grid=(--grid sinh --dr-inner 0.06)
  family s-standard 300,400,600,800 --id 1log-trumpet
  for h in 0.6 0.89 1.2 2.0; do
    family "s-h$h" 300,400,600,800 --id 1log-trumpet --rahA 0.5 --rah0 $h
  done
  for target in "1e-5 1e-4" "1e-6 1e-5"; do
    set -- $target
    echo "== uniform grids"
    $py plots/horizon_study.py cost "$out/t-standard" "$out"/t-h*[0-9] --H-target $1 --M-target $2
    echo "== sinh grids"
    $py plots/horizon_study.py cost "$out/s-standard" "$out"/s-h*[0-9] --H-target $1 --M-target $2
  done
  ;;
*)
  echo "usage: $0 reproduce|mechanism|threshold|cost" >&2
  exit 2
  ;;
esac
