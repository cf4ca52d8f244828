#!/usr/bin/env bash
# What sets the error constant of M_AH on wormhole data at M/16 (docs/horizon-shift-study.md,
# Sec. 7.4): uniform grid, rmax 128 M, to 100 M, standard gauge; one switch at a time against
# the defaults, then the resolution near the puncture alone (sinh grids). About 20 s.
#
#   bash runs/error-constant.sh
#
# Output under out/error-constant/, the table on stdout and in out/error-constant/table.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
out=out/error-constant
rm -rf "$out" && mkdir -p "$out"
common=(--tmax 100 --dt-series 1 --dt-profiles 100 --rmax 128)
uniform=(--grid uniform --N 2048)

run() { # run NAME FLAGS...
  local name=$1
  shift
  build/gbssn1d evolve "${common[@]}" "$@" --out "$out/$name" >"$out/$name.log" 2>&1 ||
    echo "  ($name stopped: $(tail -n 1 "$out/$name.log"))"
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
# the spacing near the puncture and the horizon alone: sinh grids, rmax 128 M
run sinh-0.053 --grid sinh --N 300 --dr-inner 0.04
run sinh-0.080 --grid sinh --N 200 --dr-inner 0.04
run sinh-0.020 --grid sinh --N 400 --dr-inner 0.02

$py - "$out" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series, parse, read_text
out = sys.argv[1]
print(f"{'run':26s} {'dr at r=0':>10s} {'at 0.85 M':>10s} {'M_AH-M t=0':>11s} {'t=10':>10s} "
      f"{'t=50':>10s} {'t=100':>10s}")
for name in sorted(os.listdir(out)):
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
