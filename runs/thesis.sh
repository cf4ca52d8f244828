#!/usr/bin/env bash
# The published 3D study's configuration in one dimension, its figures, and every candidate
# mechanism of its loss of convergence switched on and off (study doc, opening and Sec. 13).
#
#   bash runs/thesis.sh [OUT]      # everything below into OUT (default out/thesis/, a relative
#                                  # OUT from where you stand; about a minute on 2 cores)
#
# GBSSN1D_JOBS=n runs n studies at once (a positive whole number; default: the core count). A
# rerun keeps every completed study of the same command and binary and redoes the rest
# (runs/lib.sh); a finished study is replaced only by a completed one; Ctrl-C stops at once.
#
# The published configuration ("thesis" in the tables): nested boxes as the 48- and 64-point
# boxes of the 3D code (7 boxes, outer boundary 128 M, N = 24 and 32 cells on r >= 0, plus
# N = 48 for three-level orders: finest spacing M/12, M/16, M/24), maximally sliced trumpet
# data, 1+log slicing and the Gamma-driver (eta = 2/M), beta_H with the published rational
# profile of width 1 M, the unit normal s^r = sqrt(chi/a), B's driver term upwinded with
# beta_GD alone, quadratic time interpolation of the fine boxes' boundaries (three coarse time
# levels, as Carpet and BAM), cfl 0.25, and h_AH found after every step of the hierarchy and
# held over the next (what a horizon finder called between steps gives), rahA = 0.5,
# rah0 = 0.89 (stretch) and 0.6 (shrink), to 100 M (the first 20 M are the published figures'
# range). 1+log trumpet data beside it.
#
# Each configuration is one `gbssn1d converge` study into out/thesis/<row>/; the table
# out/thesis/mechanisms.dat (plots/thesis.py) has one row per configuration with the command
# that reproduces it alone; figures out/thesis/fig*.png.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
# shellcheck source=runs/lib.sh
source runs/lib.sh
# GBSSN1D_JOBS checked, OUT resolved against the caller's folder and locked (one writer at a
# time: a second runs/thesis.sh on the same folder is refused, not interleaved)
lib_init runs/thesis.sh "$here" out/thesis "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
start=$(date +%s)

# what every row shares: the time, output cadence, the Richardson-scaled H at 20 M
common=(--tmax 100 --dt-series 0.25 --dt-profiles 20 --scaled-times 20 --cfl 0.25 --grid boxes)
# each candidate mechanism: its published setting ("on") and the project's default ("off")
declare -A on off
on[kink]="--rah-normal unit"; off[kink]="--rah-normal conformal"
on[driver]="--driver-advection upwind-gd"; off[driver]="--driver-advection matched"
on[cadence]="--ah-every step"; off[cadence]="" # the default: every substage, one h_AH(t) for every box
on[interp]="--time-interp quadratic"; off[interp]="--time-interp rk-stages"
on[width]="--rah-profile rational --rah-width 1"; off[width]="--rah-profile auto"
on[boundary]="--levels 7 --rmax 128"; off[boundary]="--levels 9 --rmax 512"
mechanisms=(kink driver cadence interp width boundary)
# Kreiss-Oliger dissipation (sigma 0.1 in both) is the seventh candidate: rows with 0 and 0.3

# the flags of a configuration: each mechanism named in "$1" (space separated) on, the rest off
flags_of() {
  local m f=""
  for m in "${mechanisms[@]}"; do
    if [[ " $1 " == *" $m "* ]]; then f+=" ${on[$m]}"; else f+=" ${off[$m]}"; fi
  done
  echo "$f"
}

rows=()
# row NAME DATA H NS FLAGS...: one converge study (H = std: the standard gauge; NS: members)
row() {
  local name=$1 id=$2 h=$3 Ns=$4
  shift 4
  local shift_flags=()
  [ "$h" = std ] || shift_flags=(--rahA 0.5 --rah0 "$h")
  lib_run "$name" build/gbssn1d converge --N "$Ns" -j 1 --out @OUT --id "$id" \
    "${shift_flags[@]}" "${common[@]}" "$@"
  rows+=("$name")
}

all="${mechanisms[*]}"
# spacings: the published pair and a third (coarse), then one, two and three steps finer
coarse=24,32,48 fine=32,48,64 vfine=48,64,96 vvfine=64,96,128
for id in maximal-trumpet 1log-trumpet; do
  d=${id%%-*} # maximal | 1log
  echo "== $id: the standard gauge, the published configuration, the defaults"
  row "$d-standard-thesis" $id std $coarse $(flags_of "$all")
  row "$d-standard-defaults" $id std $coarse $(flags_of "")
  for h in 0.89 0.6; do
    row "$d-h$h-thesis" $id $h $coarse $(flags_of "$all")
    row "$d-h$h-defaults" $id $h $coarse $(flags_of "")
  done
  echo "== $id: the published configuration refined"
  for h in 0.89 0.6; do
    row "$d-h$h-thesis-fine" $id $h $fine $(flags_of "$all")
    row "$d-h$h-thesis-vfine" $id $h $vfine $(flags_of "$all")
  done
  [ $id = maximal-trumpet ] || continue
  row "$d-standard-thesis-vfine" $id std $vfine $(flags_of "$all")
  row "$d-h0.6-thesis-vvfine" $id 0.6 $vvfine $(flags_of "$all")
  row "$d-h0.89-defaults-vfine" $id 0.89 $vfine $(flags_of "")
  row "$d-h0.6-defaults-vvfine" $id 0.6 $vvfine $(flags_of "")
  echo "== $id: each mechanism alone, and all but one (published spacings, and one step finer)"
  for h in 0.89 0.6; do
    for m in "${mechanisms[@]}"; do
      row "$d-h$h-only-$m" $id $h $coarse $(flags_of "$m")
      row "$d-h$h-all-but-$m" $id $h $coarse $(flags_of "${all/$m/}")
      row "$d-h$h-all-but-$m-fine" $id $h $fine $(flags_of "${all/$m/}")
    done
    row "$d-h$h-only-interp-fine" $id $h $fine $(flags_of interp)
    row "$d-h$h-only-cadence-fine" $id $h $fine $(flags_of cadence)
    row "$d-h$h-thesis-nosubcycling-fine" $id $h $fine $(flags_of "$all") --no-subcycling
    # each box its own latest h_AH, found at its own substages (box-substage)
    row "$d-h$h-thesis-box-substage" $id $h $coarse $(flags_of "${all/cadence/}") --rah-variant box-substage
    row "$d-h$h-only-box-substage" $id $h $coarse $(flags_of "") --rah-variant box-substage
    # dissipation: none, and stronger than the default 0.1
    row "$d-h$h-thesis-ko0" $id $h $coarse $(flags_of "$all") --ko-sigma 0
    row "$d-h$h-thesis-ko0-fine" $id $h $fine $(flags_of "$all") --ko-sigma 0
    row "$d-h$h-thesis-ko0.3" $id $h $coarse $(flags_of "$all") --ko-sigma 0.3
    row "$d-h$h-thesis-ko0.3-fine" $id $h $fine $(flags_of "$all") --ko-sigma 0.3
    row "$d-h$h-only-ko0.3" $id $h $coarse $(flags_of "") --ko-sigma 0.3
  done
  echo "== $id: the search cadence: h_AH held over 2, 4, 8, 16 steps of the hierarchy"
  for h in 0.89 0.6; do
    for n in 2 4 8 16; do
      row "$d-h$h-thesis-every$n" $id $h $coarse $(flags_of "${all/cadence/}") --ah-every $n
    done
    row "$d-h$h-thesis-every16-rk-stages" $id $h $coarse $(flags_of "kink driver width boundary") --ah-every 16
    row "$d-h$h-thesis-every16-nosubcycling" $id $h $coarse $(flags_of "${all/cadence/}") --ah-every 16 --no-subcycling
  done
done

lib_wait
lib_check "${rows[@]}"
$py plots/thesis.py "$out" "${rows[@]}"
echo "runs/thesis.sh: $(( $(date +%s) - start )) s; table $out/mechanisms.dat, figures $out/fig*.png"
