#!/usr/bin/env bash
# Why wormhole shrinks failed with eta = 2/M (docs/horizon-shift-study.md, Sec. 4.3): a
# persistent beta_H imposed on data whose standard gauge is stationary. Every run is kept in
# out/driver-split/, redone where its command or the binary changed (about 1 minute on 2 cores):
# the stationary 1+log trumpet on the
# default grid to 1000 M, the shrink profile (gauss, w = 1 M, A = 0.5, h = 0.6 M) driven open
# loop by a constant h_AH = h + delta (--rah-hAH-file), so that beta_H = A delta f(r) s^r never
# decays, with
#  - the method's split driver (B driven by d_t Delta^r of beta_GD alone) at eta = 2, 1, 0.5/M
#    and delta = 0.02 M, and at eta = 2/M with delta = 0.005 M;
#  - the driver fed by the full shift (--rah-variant driver-full-shift), eta = 2/M, delta = 0.02 M;
#  - delta = 0 (beta_H = 0), eta = 2/M.
# Prints how each run ended and beta_GD, Delta^r and beta_H at r = 0.7 M every 100 M.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/driver-split.sh "$here" out/driver-split "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
for delta in 0 0.005 0.02; do
  $py - "$out/hAH-$delta.dat" "$delta" <<'PY'
import sys
path, delta = sys.argv[1], float(sys.argv[2])
with open(path, 'w') as f:
    f.write('# t r_ah\n')
    for t in range(0, 1001, 10):
        f.write(f'{t} {0.6 + delta!r}\n')
PY
done
common=(--id 1log-trumpet --rahA 0.5 --rah0 0.6 --rah-profile gauss --rah-width 1 --tmax 1000
  --dt-series 5 --dt-profiles 100)
run() { evolve_run "$1" "${common[@]}" "${@:2}"; } # name, then the flags beyond the common ones
for eta in 2 1 0.5; do
  run "split-eta$eta-delta0.02" --eta "$eta" --rah-hAH-file "$out/hAH-0.02.dat"
done
run split-eta2-delta0.005 --eta 2 --rah-hAH-file "$out/hAH-0.005.dat"
run full-eta2-delta0.02 --eta 2 --rah-hAH-file "$out/hAH-0.02.dat" --rah-variant driver-full-shift
run split-eta2-delta0 --eta 2 --rah-hAH-file "$out/hAH-0.dat"
lib_wait
lib_check
$py - "$out" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import parse, read_text
out = sys.argv[1]
names = ['split-eta2-delta0.02', 'split-eta1-delta0.02', 'split-eta0.5-delta0.02',
         'split-eta2-delta0.005', 'full-eta2-delta0.02', 'split-eta2-delta0']
print("# run: how it ended | beta_GD / Delta^r / beta_H at r = 0.7 M, every 100 M")
for name in names:
    text = read_text(os.path.join(out, name, 'timeseries.dat'))
    end = [l[len('# end: '):] for l in text.splitlines() if l.startswith('# end:')]
    columns, blocks = parse(read_text(os.path.join(out, name, 'profiles.dat')))
    cells = []
    for t, d in blocks:
        i = int(np.argmin(np.abs(d[:, 0] - 0.7)))
        v = lambda c: d[i, columns.index(c)]
        cells.append(f"{t:.0f}: {v('beta_GD'):.3f}/{v('Delta_r'):.1f}/{v('beta_H'):.4f}")
    print(f"{name}: {end[0] if end else '?'}")
    print("   " + "  ".join(cells))
PY
