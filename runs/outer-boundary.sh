#!/usr/bin/env bash
# The outer boundary's share of the default run's late-time numbers (docs/horizon-shift-study.md,
# Sec. 7): the default wormhole run to t = 500 M with the boundary at 100 M (the old default),
# 1000 M (the default) and 2000 M, and at 1000 M with N = 600 and 800. Prints the largest
# |M_AH - M| over t >= 50 M and the RMS of H_L2_R over 10-100 M and 100-500 M; every run is kept
# in out/outer-boundary/ (or OUT) and redone only where its command or the binary changed.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/outer-boundary.sh "$here" out/outer-boundary "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
cfgs=("100 400" "1000 400" "2000 400" "1000 600" "1000 800")
for cfg in "${cfgs[@]}"; do
  read -r rmax n <<<"$cfg"
  lib_run "rmax$rmax-N$n" build/gbssn1d evolve --rmax "$rmax" --N "$n" --tmax 500 --dt-series 1 \
    --dt-profiles 500 --out @OUT
done
lib_wait
lib_check
for cfg in "${cfgs[@]}"; do
  set -- $cfg
  d="$out/rmax$1-N$2"
  /usr/bin/python3 - "$d" "$1" "$2" <<'PY'
import math, os, sys
sys.path.insert(0, 'plots')
from gbssn1d_data import parse, read_text
d, rmax, n = sys.argv[1:]
columns, blocks = parse(read_text(os.path.join(d, 'timeseries.dat')))
data = blocks[0][1]
t, M, H = (data[:, columns.index(c)] for c in ('t', 'M_ah_err', 'H_L2_R'))
def rms(a, b):
    sel = H[(t >= a) & (t <= b)]
    return math.sqrt((sel ** 2).mean())
late = abs(M[t >= 50])
print(f"rmax {rmax} N {n}: max|M_AH - M| over t >= 50 M {late[~(late != late)].max():.3e}; "
      f"RMS H_L2_R 10-100 M {rms(10, 100):.2e}, 100-500 M {rms(100, 500):.2e}")
PY
done
