#!/usr/bin/env bash
# Reference runs of two gbssn1d binaries, compared byte for byte: for a change meant to leave
# behaviour as it is (a restructuring), every file either binary writes must be identical.
#
# Usage: tests/reference/same_outputs.sh [--new-keys K1,K2] [--new-args 'ARGS']
#                                         OLD_BINARY NEW_BINARY [WORK_DIR]
#   --new-keys: configuration keys the new binary added (recorded in config.toml and every
#   header); their lines are dropped before comparing, so that the runs they do not change
#   still compare byte for byte. --new-args: flags the new binary's evolve runs get (e.g.
#   '--box-taper 0', the behaviour before a new default), so that the old behaviour is compared.
#   Runs each case below with both binaries (short runs, a few seconds each) and compares every
#   output file (config.toml's first line, the version, excepted); prints one line per case and
#   exits 1 if any file differs, naming it. Cases: the single grid with the horizon shift in
#   each search mode (substage, step, every 3 steps, the midstep-update variant, an open-loop
#   h_AH file), output times between the steps; boxes in each time interpolation with the
#   horizon shift, the box-substage variant, no subcycling; a run stopped at t = 3 with a checkpoint at 2 and
#   resumed to a later tmax; a converge study and a sweep (wall times excepted); a checkpoint of
#   the legacy layout (3 ghosts a side, as written
#   before the finite-difference order became a choice) resumed; each --fd-order; Z4c on the
#   sinh grid (with the horizon shift and the ADM-K lapse), uniform at 6th order with the
#   biased pair, and on boxes; each of the horizon shift's study variants (--rah-variant).
set -euo pipefail
new_keys=""
new_args=()
while [ $# -gt 0 ]; do
  case $1 in
    --new-keys) new_keys=${2:?--new-keys needs a comma-separated list}; shift 2 ;;
    --new-args) read -r -a new_args <<<"${2:?--new-args needs flags}"; shift 2 ;;
    *) break ;;
  esac
done
old=$(realpath "${1:?usage: same_outputs.sh OLD_BINARY NEW_BINARY [WORK_DIR]}")
new=$(realpath "${2:?usage: same_outputs.sh OLD_BINARY NEW_BINARY [WORK_DIR]}")
work=${3:-$(mktemp -d)}
mkdir -p "$work"
work=$(realpath "$work")
here=$(cd "$(dirname "$0")" && pwd)
failed=0

common=(--dt-series 0.3 --dt-profiles 1.7 --rah0 1.0) # wormhole data, as by default
# (the boxes at cfl 0.25, their default until 2026-11-26, so that binaries from before and
# after that compare; --new-args '--box-taper 0' gives the runs before the tapered buffer)
declare -A cases=(
  [sinh-substage]="--N 120 --rahA 0.5"
  [sinh-step]="--N 120 --rahA 0.5 --ah-every step"
  [sinh-every3]="--N 120 --rahA 0.5 --ah-every 3"
  [sinh-midstep]="--N 120 --rahA 0.5 --rah-variant midstep-update --ah-every 2"
  [sinh-plain]="--N 120"
  [uniform-fd6]="--grid uniform --rmax 40 --N 400 --fd-order 6 --rahA 0.5"
  [uniform-fd2-trumpet]="--grid uniform --rmax 40 --N 200 --fd-order 2 --id 1log-trumpet --rahA 0.5"
  [boxes-rk]="--grid boxes --rmax 64 --N 48 --rahA 0.5 --cfl 0.25"
  [boxes-dense]="--grid boxes --rmax 64 --N 48 --rahA 0.5 --time-interp dense --cfl 0.25"
  [boxes-quadratic]="--grid boxes --rmax 64 --N 48 --rahA 0.5 --time-interp quadratic --cfl 0.25"
  [boxes-box-substage]="--grid boxes --rmax 64 --N 48 --rahA 0.5 --rah-variant box-substage --cfl 0.25"
  [boxes-no-subcycling]="--grid boxes --rmax 64 --N 48 --rahA 0.5 --no-subcycling --ah-every step --cfl 0.25"
  [boxes-maximal]="--grid boxes --rmax 32 --N 32 --id maximal-trumpet --cfl 0.25"
  [study-no-shift-derivatives]="--N 120 --rahA 0.5 --rah-variant no-shift-derivatives"
  [study-no-shift-second-derivatives]="--N 120 --rahA 0.5 --rah-variant no-shift-second-derivatives"
  [study-delta-rhs-from-gd]="--N 120 --rahA 0.5 --rah-variant delta-rhs-from-gd"
  [study-driver-full-shift]="--N 120 --rahA 0.5 --rah-variant driver-full-shift"
  [z4c-sinh]="--N 120 --formulation z4c --id 1log-trumpet"
  [z4c-sinh-shift]="--N 120 --formulation z4c --rahA 0.5 --z4c-lapse-adm"
  [z4c-uniform-fd6-biased]="--grid uniform --rmax 40 --N 400 --fd-order 6 --formulation z4c --upwind biased --kappa2 0.5"
  [z4c-boxes]="--grid boxes --rmax 64 --N 48 --formulation z4c --rahA 0.5 --time-interp quadratic --cfl 0.25"
)
# A file as compared: config.toml without its first line (the version); a sweep's summary.dat
# without its wall_s column and its status files without their wall time, and no member's
# console log (the only figures that measure the machine, not the run)
normalised() {
  if [ -n "$new_keys" ]; then
    local pattern
    pattern="^(# )?($(echo "$new_keys" | sed 's/,/|/g')) = "
    normalised_file "$1" | grep -Ev "$pattern"
  else
    normalised_file "$1"
  fi
}
normalised_file() {
  case "$(basename "$1")" in
    config.toml) tail -n +2 "$1" ;;
    summary.dat) python3 -c '
import sys
col = None
for line in open(sys.argv[1]):
    words = line.split()
    if col is None and line.startswith("#") and "wall_s" in words:
        col = words.index("wall_s") - 1
    elif col is not None and words and not line.startswith("#"):
        del words[col]
        line = " ".join(words) + "\n"
    sys.stdout.write(line)' "$1" ;;
    *.status) cut -d' ' -f1,3- "$1" ;;
    *) cat "$1" ;;
  esac
}
compare() { # compare NAME: every file under old/NAME and new/NAME
  local name=$1 bad=()
  local files
  files=$( (cd "$work/old/$name" && find . -type f; cd "$work/new/$name" && find . -type f) \
             | grep -v '\.lock$' | grep -v '^./logs/.*.log$' | sort -u)
  for f in $files; do
    cmp -s <(normalised "$work/old/$name/$f" 2>/dev/null) \
      <(normalised "$work/new/$name/$f" 2>/dev/null) || bad+=("$f")
  done
  if [ ${#bad[@]} -eq 0 ]; then
    echo "same: $name ($(echo $files | wc -w) files)"
  else
    echo "DIFFERENT: $name: ${bad[*]}"
    failed=1
  fi
}
run_both() { # run_both NAME ARGS...: `evolve ARGS --out work/{old,new}/NAME` with each binary
  local name=$1
  shift
  for side in old new; do
    local exe=$old extra=()
    [ $side = new ] && exe=$new && extra=("${new_args[@]}")
    rm -rf "${work:?}/$side/$name"
    mkdir -p "$work/$side"
    (cd "$work/$side" && "$exe" evolve "$@" "${extra[@]}" --out "$name" >"$name.log" 2>&1) || true
    if [ ! -f "$work/$side/$name/timeseries.dat" ]; then
      echo "DID NOT RUN: $name ($side): $(tail -n 1 "$work/$side/$name.log")"
      failed=1
    fi
  done
}

# the open-loop h_AH file: the horizons of a short run
run_both hAH-source "${common[@]}" --tmax 6 --N 120 --rahA 0.5
run_both sinh-prescribed "${common[@]}" --tmax 6 --N 120 --rahA 0.5 \
  --rah-hAH-file ../old/hAH-source/horizon.dat
for name in "${!cases[@]}"; do
  # shellcheck disable=SC2086
  run_both "$name" "${common[@]}" --tmax 6 ${cases[$name]}
done
# run to t = 3 with a checkpoint at t = 2, then resumed to a later tmax, on a single grid and on boxes
for grid in sinh boxes; do
  extra=(--N 120 --rahA 0.5)
  [ $grid = boxes ] && extra=(--grid boxes --rmax 64 --N 48 --rahA 0.5 --time-interp quadratic --cfl 0.25)
  run_both "resumed-$grid" "${common[@]}" "${extra[@]}" --checkpoint-every 2 --tmax 3
  for side in old new; do
    exe=$old
    [ $side = new ] && exe=$new
    (cd "$work/$side" && "$exe" resume "resumed-$grid" --tmax 6 >>"resumed-$grid.log" 2>&1) || true
  done
done
# a legacy checkpoint (3 ghosts a side), made from the old binary's checkpoint at t = 2; both
# binaries resume the same folder (the old binary's files and the converted checkpoint), as a
# run made by an earlier version is resumed by a later one
run_both legacy "${common[@]}" --N 120 --rahA 0.5 --checkpoint-every 2 --tmax 3
python3 "$here/legacy_checkpoint.py" "$work/old/legacy/checkpoint.bin"
rm -rf "$work/new/legacy"
cp -r "$work/old/legacy" "$work/new/legacy"
for side in old new; do
  exe=$old
  [ $side = new ] && exe=$new
  (cd "$work/$side" && "$exe" resume legacy --tmax 6 >>legacy.log 2>&1) || true
done

# a converge study (its members, convergence.dat with the verdict, scaled_H.dat) and a sweep
# (its members, summary.dat) of each binary
for side in old new; do
  exe=$old
  [ $side = new ] && exe=$new
  rm -rf "${work:?}/$side/converge" "${work:?}/$side/converge-z4c" "${work:?}/$side/sweep"
  (cd "$work/$side" && "$exe" converge --N 40,60,80 --tmax 4 --dt-series 0.5 --rahA 0.5 \
     --rah0 1.0 --out converge >converge.log 2>&1) || true
  (cd "$work/$side" && "$exe" converge --formulation z4c --N 40,60,80 --tmax 4 --dt-series 0.25 \
     --fields K,Theta --out converge-z4c >converge-z4c.log 2>&1) || true
  (cd "$work/$side" && "$exe" sweep --sweep rahA=0,0.5 --sweep rah0=0.8,1.0 --N 40 --tmax 2 \
     --dt-series 0.5 -j 2 --out sweep >sweep.log 2>&1) || true
  for study in converge converge-z4c sweep; do
    [ -d "$work/$side/$study" ] || { echo "DID NOT RUN: $study ($side)"; failed=1; }
  done
done
for name in $(ls "$work/old" | grep -v '\.log$' | sort); do
  compare "$name"
done
[ $failed -eq 0 ] && echo "same outputs: every case" || echo "same outputs: some cases differ (in $work)"
exit $failed
