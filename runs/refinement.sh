#!/usr/bin/env bash
# The horizon shift under refinement (docs/horizon-shift-study.md, Sec. 12), every run in
# out/refinement/<part>/ and summarised by plots/refinement_study.py.
#   bash runs/refinement.sh onset      (~1 min on 2 cores) the published stencil of B's driver
#       term (--driver-advection upwind-gd): when and where a stretch to 1.5M (1+log trumpet,
#       A = 0.5) goes non-finite against N on the sinh grid (N = 800 ... 3200) and on uniform
#       grids (rmax 200, M/16 ... M/64); the fitted slope of log t_onset against log N; the
#       onset predicted by docs/hyperbolicity.py from the fields of the N = 800 (sinh) and M/16
#       (uniform) runs, against the growth rate and radius measured in the sinh runs (the
#       grid-scale part of B, its 6th difference, in the last profiles before the blow-up);
#       the same runs with the default (matched) stencil.
#   bash runs/refinement.sh converge   (~15 min on 2 cores) the defaults for h = 0.5, 0.6, 0.89,
#       1.2, 1.5, 2M and the standard gauge on each data set, sinh N = 400 ... 3200 to 30M and
#       N = 400 ... 6400 to 12M: the RMS over time of H_L2_R and its order between neighbouring
#       resolutions.
#   bash runs/refinement.sh uniform    (~10 min on 2 cores) the same on uniform grids, M/16 ...
#       M/128 (rmax 100M) to 20M.
#   bash runs/refinement.sh published  (~5 min on 2 cores) the study's answer revisited: the
#       published form (unit normal, rational profile w = 1, upwind-gd driver stencil) on uniform
#       grids (rmax 200) at M/8, M/16, M/32, M/64 to 40M, 1+log trumpet stretched to 0.89M and
#       1.5M (A = 0.5), with each suspect switched off: the normal's kink (conformal normal),
#       the driver stencil (matched), both. The RMS over time of H_L2_R and its orders.
#   bash runs/refinement.sh boxes      (~2 min) the published grid (7 boxes, rmax 128M; finest
#       spacing M/16 ... M/64 for N = 32 ... 128) to 40M, 1+log trumpet: the standard gauge,
#       h = 0.89 in the published form, h = 1.5 with the default, unit and conformal normals
#       (the last two with the published profile), each with the upwind-gd and matched stencils.
#   bash runs/refinement.sh [all]      onset, converge, uniform, published and boxes
#   bash runs/refinement.sh PART OUT   into OUT/<part>/ instead of out/refinement/<part>/ (a
#       relative OUT from where you stand)
# IDS="wormhole" bash runs/refinement.sh converge  runs one data set's families of converge or
#       uniform (out/refinement/<part>/<id>/) and makes its table alone, leaving the others'
#       folders as they are.
#
# GBSSN1D_JOBS=n runs n at once (a positive whole number; default: the core count). A rerun
# keeps every run that completed with the same command and binary and redoes the rest
# (runs/lib.sh); a result is replaced only by a completed one; Ctrl-C stops at once; a part's
# table is made only when all its runs completed (a run that goes non-finite is a result).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
all=(onset converge uniform published boxes)
case ${1:-all} in
all) parts=("${all[@]}") ;;
onset | converge | uniform | published | boxes) parts=("$1") ;;
*)
  echo "runs/refinement.sh: unknown part '$1' (onset, converge, uniform, published, boxes, all)" >&2
  exit 2
  ;;
esac
case ${2:-} in
onset | converge | uniform | published | boxes | all)
  echo "runs/refinement.sh: '$2' is a part, not OUT: one part (or all) at a time, then OUT" >&2
  exit 2
  ;;
esac
for id in ${IDS:-}; do
  case $id in
  1log-trumpet | maximal-trumpet | wormhole) ;;
  *)
    echo "runs/refinement.sh: IDS = '$IDS' is invalid: its data sets are 1log-trumpet, maximal-trumpet, wormhole" >&2
    exit 2
    ;;
  esac
done
# shellcheck source=runs/study-helpers.sh
source runs/study-helpers.sh
lib_init runs/refinement.sh "$here" out/refinement "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
py=/usr/bin/python3
# run KIND NAME FLAGS...: evolve_run or uniform_run (runs/study-helpers.sh) of NAME within the
# part's folder ($d = $out/<part>, the run in $d/NAME), named in $names for the part's check
run() {
  local kind=$1 name=$2
  shift 2
  "$kind" "$part/$name" "$@"
  names+=("$part/$name")
}
# the part's runs all completed (else exit 1, no table)
finished() {
  lib_wait
  lib_check "${names[@]}"
}

for part in "${parts[@]}"; do
  d=$out/$part
  names=()
  case $part in
  onset)
    stretch=(--id 1log-trumpet --rahA 0.5 --rah0 1.5 --dt-series 0.05)
    for st in upwind-gd matched; do
      for n in 800 1200 1600 2400 3200; do
        # fields every 0.1 M of the published stencil's runs: the measured growth rate
        dtp=1000
        [ "$st" = upwind-gd ] && dtp=0.1
        run evolve_run "sinh-$st-N$n" "${stretch[@]}" --N "$n" --tmax 6 --dt-profiles "$dtp" \
          --driver-advection "$st"
      done
      for m in 16 32 64; do
        run evolve_run "uniform-$st-M$m" "${stretch[@]}" --grid uniform --rmax 200 --N $((200 * m)) \
          --tmax 6 --dt-profiles 1000 --driver-advection "$st"
      done
    done
    # the backgrounds of the predictions: fields every 0.25 M of runs that do not blow up
    run evolve_run background-sinh "${stretch[@]}" --N 800 --tmax 6 --dt-profiles 0.25 \
      --driver-advection upwind-gd
    run evolve_run background-uniform "${stretch[@]}" --grid uniform --rmax 200 --N 3200 --tmax 6 \
      --dt-profiles 0.25 --driver-advection upwind-gd
    finished
    {
      echo "# sinh: N = 800 x 1/factor; uniform: M/16 x 1/factor"
      echo "# sinh"
      $py docs/hyperbolicity.py --profiles "$d/background-sinh/profiles.dat" \
        --spacing-factor 0.6667 0.5 0.3333 0.25
      echo "# uniform"
      $py docs/hyperbolicity.py --profiles "$d/background-uniform/profiles.dat" \
        --spacing-factor 0.5 0.25
    } >"$d/predicted.txt"
    # the continuum speeds on the same fields (real? eigenvectors complete?)
    $py docs/hyperbolicity.py --profiles "$d/background-sinh/profiles.dat" --continuum \
      >"$d/continuum.txt"
    $py plots/refinement_study.py onset "$d" | tee "$d/table.txt"
    ;;
  converge | uniform)
    # ${IDS:-...}: the data sets to (re)run; each has its own folder out/refinement/<part>/<id>
    ids=${IDS:-1log-trumpet maximal-trumpet wormhole}
    for id in $ids; do
      for h in 0 0.5 0.6 0.89 1.2 1.5 2; do
        g=()
        [ "$h" != 0 ] && g=(--rahA 0.5 --rah0 "$h")
        if [ "$part" = converge ]; then
          for n in 400 800 1600 3200; do
            run evolve_run "$id/h$h-sinh-N$n" --id "$id" "${g[@]}" --N "$n" --tmax 30 \
              --dt-series 0.25 --dt-profiles 1000
          done
          for n in 400 800 1600 3200 6400; do
            run evolve_run "$id/h$h-sinh12-N$n" --id "$id" "${g[@]}" --N "$n" --tmax 12 \
              --dt-series 0.25 --dt-profiles 1000
          done
        else
          for m in 16 32 64 128; do
            run evolve_run "$id/h$h-uniform-M$m" --id "$id" "${g[@]}" --grid uniform --rmax 100 \
              --N $((100 * m)) --tmax 20 --dt-series 0.25 --dt-profiles 1000
          done
        fi
      done
    done
    finished
    for id in $ids; do
      echo "## $id"
      $py plots/refinement_study.py converge "$d/$id"
    done | tee "$d/table.txt"
    ;;
  published)
    for h in 0.89 1.5; do
      for v in published:unit:upwind-gd no-kink:conformal:upwind-gd matched:unit:matched \
        neither:conformal:matched; do
        IFS=: read -r name normal stencil <<<"$v"
        for m in 8 16 32 64; do
          run uniform_run "h$h-$name-M$m" --id 1log-trumpet --rahA 0.5 --rah0 "$h" --rmax 200 \
            --N $((200 * m)) --tmax 40 --rah-profile rational --rah-width 1 --rah-normal "$normal" \
            --driver-advection "$stencil"
        done
      done
    done
    finished
    $py plots/refinement_study.py converge "$d" | tee "$d/table.txt"
    ;;
  boxes)
    grid=(--id 1log-trumpet --grid boxes --levels 7 --rmax 128 --tmax 40 --dt-series 0.25
      --dt-profiles 1000)
    pub=(--rah-profile rational --rah-width 1)
    for n in 32 48 64 96 128; do
      run evolve_run "h0-std-N$n" "${grid[@]}" --N "$n"
      for st in upwind-gd matched; do
        run evolve_run "h0.89-unit-$st-N$n" "${grid[@]}" --N "$n" --rahA 0.5 --rah0 0.89 "${pub[@]}" \
          --rah-normal unit --driver-advection "$st"
        run evolve_run "h1.5-default-$st-N$n" "${grid[@]}" --N "$n" --rahA 0.5 --rah0 1.5 \
          --driver-advection "$st"
        for normal in unit conformal; do
          run evolve_run "h1.5-$normal-$st-N$n" "${grid[@]}" --N "$n" --rahA 0.5 --rah0 1.5 "${pub[@]}" \
            --rah-normal "$normal" --driver-advection "$st"
        done
      done
    done
    finished
    $py plots/refinement_study.py converge "$d" | tee "$d/table.txt"
    ;;
  esac
done
