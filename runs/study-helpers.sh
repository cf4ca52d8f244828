# Sourced by the study scripts of runs/ (after `cd` to the repository), which then call
# `lib_init runs/NAME.sh "$here" out/NAME "${1:-}"` (runs/lib.sh: GBSSN1D_JOBS checked, OUT
# resolved against the caller's folder and locked, one Ctrl-C stops) and, before reading their
# results, `lib_wait; lib_check`. Every run is kept when it completed with the same command and
# binary, and redone otherwise; none is deleted before its replacement completed.
#
# `family NAME FLAGS...` (runs/horizon-width.sh, fd-order.sh, horizon-wormhole.sh) makes one
# converge family in $out/NAME at the uniform spacings M/8, M/12, M/16 (N = 1600, 2400, 3200
# with rmax 200 M in ${common[@]}), its log in $out/NAME.log.
#
# `evolve_run NAME FLAGS...` makes one `gbssn1d evolve` into $out/NAME, its log in
# $out/NAME.log. `uniform_run NAME FLAGS...` (runs/boundary-reflections.sh, uniform-m16.sh) is
# the same on a uniform grid with a series row every 0.5 M and no profiles. All run in the
# background, at most GBSSN1D_JOBS at once.
# shellcheck source=runs/lib.sh
source runs/lib.sh

family() {
  local name=$1
  shift
  lib_run "$name" build/gbssn1d converge --N 1600,2400,3200 -j 1 --out @OUT "${common[@]}" "$@"
}

evolve_run() {
  local name=$1
  shift
  lib_run "$name" build/gbssn1d evolve --out @OUT "$@"
}

uniform_run() {
  local name=$1
  shift
  evolve_run "$name" --grid uniform --dt-series 0.5 --dt-profiles 1000 "$@"
}
