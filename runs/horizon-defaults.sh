#!/usr/bin/env bash
# A new user's first horizon-shift runs, with every default (docs/horizon-shift-study.md,
# Sec. 9): precollapsed wormhole data on the default grid (sinh, N = 400, rmax 1000 M) with
# --rahA 0.5 --rah0 H for H = 0.5, 0.6, 0.89, 1.2, 1.5, 2, to 1000 M. Prints how each ended, the largest
# |r_AH/H - 1| from 100 M on and the largest |M_AH - M| over the run. About 2 minutes on 2 cores;
# every run kept in out/horizon-defaults/ and redone only where its command or the binary
# changed.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/horizon-defaults.sh "$here" out/horizon-defaults "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
for h in 0.5 0.6 0.89 1.2 1.5 2; do
  lib_run "h$h" build/gbssn1d evolve --rahA 0.5 --rah0 "$h" --tmax 1000 --dt-series 1 \
    --dt-profiles 1000 --out @OUT
done
lib_wait
lib_check
for h in 0.5 0.6 0.89 1.2 1.5 2; do
  /usr/bin/python3 - "$out/h$h" "$h" <<'PY'
import math, os, sys
sys.path.insert(0, 'plots')
from gbssn1d_data import parse, read_text
d, h = sys.argv[1], float(sys.argv[2])
text = read_text(os.path.join(d, 'timeseries.dat'))
columns, blocks = parse(text)
data = blocks[0][1]
t, r, M = (data[:, columns.index(c)] for c in ('t', 'r_ah', 'M_ah_err'))
end = [l for l in text.splitlines() if l.startswith('# end:')]
late = abs(r[t >= 100] / h - 1)
eta = [l for l in text.splitlines() if l.startswith('# eta = ')]
print(f"h = {h}: {end[-1][2:] if end else 'no end line'}; {eta[0][2:] if eta else ''}; "
      f"max |r_AH/h - 1| from 100 M {late.max():.2e}; max |M_AH - M| {abs(M[~(M != M)]).max():.2e}")
PY
done
