#!/usr/bin/env bash
# The default horizon-adjusting shift (rahA = 0.5) on every data set, for targets h from 0.5 M
# to 2 M, and the standard gauge (rahA = 0), to t = 1000 M: on uniform grids of spacing M/8
# and M/16 (rmax = 200 M) and on the default sinh grid (N = 400, dr-inner = 0.02 M,
# rmax = 100 M; there with and without --rah-ramp 20). Prints each sweep's summary.dat: status, t_end, r_ah_final, |r_ah/h - 1|,
# M_ah_err_max = max |M_AH - M|, H_L2_R_max (outer sheet, areal radius 2.5 M <= R <= 12 M).
# Wormhole shrinks are run once more with --eta 1: with the default eta = 2/M the Gamma-driver
# does not settle on wormhole data (docs/horizon-shift-study.md, Sec. 4).
# About 25 minutes on 2 cores.
#
#   bash runs/horizon-robustness.sh [tmax] [OUT]   (default 1000; OUT default
#                                                  out/horizon-robustness, a relative OUT from
#                                                  where you stand)
#
# Each of the four sweeps is one `gbssn1d sweep -j GBSSN1D_JOBS` (a positive whole number;
# default: the core count), run one after the other into OUT/<sweep> (runs/lib.sh): a rerun keeps
# every sweep that finished with the same command and binary; an interrupted one (Ctrl-C stops
# at once) is resumed by the rerun, keeping its finished members; the tables are printed only
# when all four finished.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
tmax=${1:-1000}
if ! [[ $tmax =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || ! awk -v t="$tmax" 'BEGIN { exit !(t > 0) }'; then
  echo "runs/horizon-robustness.sh: tmax = '$tmax' is invalid: it must be a positive number (M)" >&2
  exit 2
fi
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/horizon-robustness.sh "$here" out/horizon-robustness "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build gbssn1d >/dev/null; }
# sweep NAME FLAGS...: one sweep into $out/NAME, waited for (it runs $jobs members at once)
sweep() {
  local name=$1
  shift
  lib_run "$name" build/gbssn1d sweep -j "$jobs" --out @OUT "$@"
  lib_wait
}
axes=(--sweep id=1log-trumpet,maximal-trumpet,wormhole
  --sweep rahA,rah0=0:0.89,0.5:0.5,0.5:0.6,0.5:0.89,0.5:1.2,0.5:1.5,0.5:2.0)
run=(--tmax "$tmax" --dt-series 1 --dt-profiles "$tmax")
sweep uniform "${axes[@]}" "${run[@]}" --sweep N=1600,3200 --grid uniform --rmax 200
sweep default-grid "${axes[@]}" "${run[@]}" --sweep rah-ramp=0,20 --grid sinh --N 400 \
  --dr-inner 0.02 --rmax 100
shrinks=(--id wormhole --eta 1 --sweep rahA,rah0=0:0.89,0.5:0.5,0.5:0.6)
sweep wormhole-eta1-uniform "${shrinks[@]}" "${run[@]}" --sweep N=1600,3200 --grid uniform --rmax 200
sweep wormhole-eta1-default-grid "${shrinks[@]}" "${run[@]}" --sweep rah-ramp=0,20 --grid sinh \
  --N 400 --dr-inner 0.02 --rmax 100
lib_check
for s in uniform default-grid wormhole-eta1-uniform wormhole-eta1-default-grid; do
  echo "== $s (|r_ah/h - 1| at the end; M_ah_err_max = max |M_AH - M|)"
  # columns by name from the header line (the '#' line that names a status column; the other
  # '#' lines describe the sweep); N is a column of the uniform sweep only, rah-ramp of the
  # default-grid sweep only
  awk '/^#/ { if (!hdr && $0 ~ / status /) { n = split(substr($0, 3), names, " "); hdr = 1
                for (i = 1; i <= n; i++) c[names[i]] = i }
              next }
       !printed++ { print "id rahA rah0 N ramp status t_end r_ah_final |r_ah/h-1| M_ah_err_max H_L2_R_max wall_s" }
       { h = $c["rah0"]; r = $c["r_ah_final"]
         id = ("id" in c) ? $(c["id"]) : "wormhole(eta=1)"
         N = ("N" in c) ? $(c["N"]) : 400; ramp = ("rah-ramp" in c) ? $(c["rah-ramp"]) : 0
         printf "%s %s %s %s %s %s %s %.5f %.1e %.1e %.1e %s\n", id, $c["rahA"], h, N, ramp,
                $c["status"], $c["t_end"], r, $c["rahA"] == 0 ? 0 : (r > h ? r / h - 1 : 1 - r / h),
                $c["M_ah_err_max"], $c["H_L2_R_max"], $c["wall_s"] }' \
    "$out/$s/summary.dat" | column -t
done
