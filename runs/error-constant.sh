#!/usr/bin/env bash
# What sets the error constant of M_AH on wormhole data at M/16 (docs/horizon-shift-study.md,
# Sec. 7.4): uniform grid, rmax 128 M, to 100 M, standard gauge; one switch at a time against
# the defaults, then the resolution near the puncture alone (sinh grids). About 20 s.
#
#   bash runs/error-constant.sh [table]  the table of switches (about 20 s)
#   bash runs/error-constant.sh upwind   --upwind lopsided against biased at M/8 ... M/32 on
#                                        wormhole and trumpet data, and a stretch and a shrink
#                                        (about 2 minutes; out/error-constant-upwind/)
#   bash runs/error-constant.sh MODE OUT writes into OUT instead (a relative OUT from where you
#                                        stand)
#
# Output under out/error-constant/, the table on stdout and in out/error-constant/table.txt.
# A rerun keeps every run that completed with the same command and binary (runs/lib.sh);
# GBSSN1D_JOBS=n runs n at once; Ctrl-C stops.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
mode=${1:-table}
case $mode in
upwind) lib_init runs/error-constant.sh "$here" out/error-constant-upwind "${2:-}" ;;
table) lib_init runs/error-constant.sh "$here" out/error-constant "${2:-}" ;;
*)
  echo "runs/error-constant.sh: unknown mode '$mode' (table or upwind; then OUT)" >&2
  exit 2
  ;;
esac
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
if [ "$mode" = upwind ]; then
  queue() { # queue NAME FLAGS...
    local name=$1
    shift
    lib_run "$name" build/gbssn1d evolve --tmax 100 --dt-series 1 --dt-profiles 100 "$@" --out @OUT
  }
  for up in lopsided biased; do
    for N in 1024 1536 2048 4096; do # M/8, M/12, M/16, M/32 on rmax 128 M
      queue "wormhole-$up-$N" --grid uniform --rmax 128 --N $N --upwind $up
      queue "trumpet-$up-$N" --id 1log-trumpet --grid uniform --rmax 128 --N $N --upwind $up
    done
    for N in 1600 2400 3200; do # M/8, M/12, M/16 on rmax 200 M (Sec. 8's grids)
      for h in 1.2 0.6; do
        queue "shift$h-$up-$N" --id 1log-trumpet --grid uniform --rmax 200 --N $N --rahA 0.5 \
          --rah0 $h --upwind $up
      done
    done
  done
  lib_wait
  lib_check
  $py - "$out" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series
out = sys.argv[1]
print("RMS H_L2_R over 10-100 M and M_AH - M at 100 M: --upwind lopsided | biased (ratio b/l)")
for case, ns in (('wormhole', (1024, 1536, 2048, 4096)), ('trumpet', (1024, 1536, 2048, 4096)),
                 ('shift1.2', (1600, 2400, 3200)), ('shift0.6', (1600, 2400, 3200))):
    for n in ns:
        row = []
        for up in ('lopsided', 'biased'):
            s = series(os.path.join(out, f'{case}-{up}-{n}', 'timeseries.dat'))
            t = s['t']
            h = np.sqrt(np.mean(s['H_L2_R'][t >= 10] ** 2))
            row.append((h, s['M_ah_err'][np.argmin(abs(t - 100))], t[-1]))
        (hl, ml, tl), (hb, mb, tb) = row
        stop = '' if min(tl, tb) >= 100 else f'  (stopped at {tl:g}, {tb:g})'
        print(f"{case:9s} N={n:5d}  H {hl:.2e} | {hb:.2e} ({hb / hl:5.2f})   "
              f"M_AH-M {ml:+.2e} | {mb:+.2e}{stop}")
PY
  exit 0
fi
common=(--tmax 100 --dt-series 1 --dt-profiles 100 --rmax 128)
uniform=(--grid uniform --N 2048)

run() { # run NAME FLAGS...
  local name=$1
  shift
  lib_run "$name" build/gbssn1d evolve "${common[@]}" "$@" --out @OUT
}
run defaults "${uniform[@]}"
run M32 --grid uniform --N 4096
run ko-sigma-0 "${uniform[@]}" --ko-sigma 0
run ko-sigma-0.2 "${uniform[@]}" --ko-sigma 0.2
run chi-floor-1e-6 "${uniform[@]}" --chi-floor 1e-6
run chi-floor-1e-4 "${uniform[@]}" --chi-floor 1e-4
run lapse0-one "${uniform[@]}" --lapse0 one
run cfl-0.25 "${uniform[@]}" --cfl 0.25
run eta-1 "${uniform[@]}" --eta 1
run advective-shift "${uniform[@]}" --advective-shift
run non-advective-lapse "${uniform[@]}" --non-advective-lapse
run delta-advection-centred "${uniform[@]}" --delta-advection centred
run fd-order-6 "${uniform[@]}" --fd-order 6
run upwind-biased "${uniform[@]}" --upwind biased
run M32-upwind-biased --grid uniform --N 4096 --upwind biased
# the spacing near the puncture and the horizon alone: sinh grids, rmax 128 M
run sinh-0.053 --grid sinh --N 300 --dr-inner 0.04
run sinh-0.080 --grid sinh --N 200 --dr-inner 0.04
run sinh-0.020 --grid sinh --N 400 --dr-inner 0.02
lib_wait
lib_check

$py - "$out" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series, parse, read_text
out = sys.argv[1]
print(f"{'run':26s} {'dr at r=0':>10s} {'at 0.85 M':>10s} {'M_AH-M t=0':>11s} {'t=10':>10s} "
      f"{'t=50':>10s} {'t=100':>10s}")
for name in sorted(n for n in os.listdir(out) if not n.startswith('.')):
    d = os.path.join(out, name)
    s = series(os.path.join(d, 'timeseries.dat')) if os.path.isdir(d) else None
    if s is None:
        continue
    t, e = s['t'], s['M_ah_err']
    cols, blocks = parse(read_text(os.path.join(d, 'profiles.dat')))
    r = blocks[0][1][:, cols.index('r')]
    dr, mid = np.diff(r), 0.5 * (r[1:] + r[:-1])
    at = lambda x: e[np.argmin(abs(t - x))]
    print(f"{name:26s} {dr[0]:10.4f} {dr[np.argmin(abs(mid - 0.85))]:10.4f} {at(0):+11.2e} "
          f"{at(10):+10.2e} {at(50):+10.2e} {at(100):+10.2e}")
PY
