#!/usr/bin/env bash
# The time step (docs/horizon-shift-study.md, Sec. 11): the largest stable Courant number per
# grid and gauge, and the error against it. For cfl = 0.25 (the default) ... 1, each run to
# 200 M: the sinh grid (N = 400, rmax 1000 M) with wormhole and 1+log-trumpet data, a uniform
# grid (N = 1600, rmax 200 M: M/8) and 9 boxes (N = 64, rmax 1024 M) with trumpet data, and at
# --fd-order 6 (sinh wormhole, uniform trumpet) and 8 (uniform trumpet); the
# standard gauge, the stretch to 2 M and the shrink to 0.6 M (A = 0.5). Prints whether each run
# finished and the RMS of H_L2_R over 10-200 M and the largest |M_AH - M| over 10-200 M.
# Every run is kept in out/cfl/ (or OUT) and redone only where its command or the binary changed
# (about 1 minute on 2 cores).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/cfl.sh "$here" out/cfl "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
cfls="0.25 0.35 0.5 0.6 0.7 0.8 0.9 1"
grids=("sinh-wormhole:--id wormhole" "sinh-trumpet:--id 1log-trumpet"
       "uniform-trumpet:--id 1log-trumpet --grid uniform --rmax 200 --N 1600"
       "boxes-trumpet:--id 1log-trumpet --grid boxes --rmax 1024 --N 64"
       "sinh-wormhole-p6:--id wormhole --fd-order 6"
       "uniform-trumpet-p6:--id 1log-trumpet --grid uniform --rmax 200 --N 1600 --fd-order 6"
       "uniform-trumpet-p8:--id 1log-trumpet --grid uniform --rmax 200 --N 1600 --fd-order 8")
gauges=("standard:" "h2:--rahA 0.5 --rah0 2" "h0.6:--rahA 0.5 --rah0 0.6")
for g in "${grids[@]}"; do
  for s in "${gauges[@]}"; do
    for c in $cfls; do
      name="${g%%:*}-${s%%:*}-cfl$c"
      # shellcheck disable=SC2086
      lib_run "$name" build/gbssn1d evolve ${g#*:} ${s#*:} --cfl "$c" --tmax 200 --dt-series 1 \
        --dt-profiles 1000 --out @OUT
    done
  done
done
lib_wait
lib_check
$py - "$out" "$cfls" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import parse, read_text
out, cfls = sys.argv[1], sys.argv[2].split()
print("# grid-data gauge: per cfl, RMS H_L2_R over 10-200 M / max|M_AH - M| over 10-200 M")
print("# ('x t' = went non-finite or stopped at t)")
names = sorted({n.rsplit('-cfl', 1)[0] for n in os.listdir(out) if '-cfl' in n and not n.startswith('.') and
                os.path.isdir(os.path.join(out, n))})
for base in names:
    cells = []
    for c in cfls:
        d = os.path.join(out, f"{base}-cfl{c}")
        columns, blocks = parse(read_text(os.path.join(d, 'timeseries.dat')))
        data = blocks[0][1]
        t = data[:, columns.index('t')]
        H = data[:, columns.index('H_L2_R')]
        M = np.abs(data[:, columns.index('M_ah_err')])
        if t[-1] < 200 - 1e-9 or not np.all(np.isfinite(H)):
            cells.append(f"{c}: x {t[-1]:.0f}")
            continue
        sel = t >= 10
        cells.append(f"{c}: {np.sqrt(np.mean(H[sel] ** 2)):.2e}/{np.nanmax(M[sel]):.1e}")
    print(f"{base}: " + " | ".join(cells))
PY
