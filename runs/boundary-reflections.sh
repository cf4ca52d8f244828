#!/usr/bin/env bash
# The outer boundary's reflections and the taper of beta_H (docs/horizon-shift-study.md,
# Sec. 7.1), every run kept in out/boundary-reflections/ and redone only where its command or binary changed (about 2 minutes on 2 cores):
#  1. the reflected amplitude at the horizon: the default wormhole (standard gauge) on uniform
#     grids with the boundary at 50, 100, 200 M, at spacings M/8 and M/16, to 150 M, against a
#     reference at the same spacing with the boundary at 400 M (beyond the light cone): the
#     largest difference of the lapse at the puncture and of M_AH once the boundary's influence
#     can have reached the horizon, and before;
#  2. the criterion of uniform N = 1280, rmax 80 M to 100 M: max|M_AH - M| for the standard
#     gauge and h = 0.6, 0.89, 1.2 M (A = 0.5), at --fd-order 4 and 6, with beta_H tapered to 0
#     before the boundary (the default, --rah-rcut = rmax/2) and not (--rah-rcut 1e9), and with
#     the boundary at 160 M (N = 2560, the same spacing) as the reference.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/boundary-reflections.sh "$here" out/boundary-reflections "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
for per_M in 8 16; do
  for rmax in 50 100 200 400; do
    uniform_run "reflect-M$per_M-rmax$rmax" --rmax "$rmax" --N "$((rmax * per_M))" --tmax 150
  done
done
for p in 4 6; do
  for h in 0 0.6 0.89 1.2; do
    shift_flags=()
    [ "$h" != 0 ] && shift_flags=(--rahA 0.5 --rah0 "$h")
    uniform_run "p$p-h$h-taper" --fd-order "$p" --rmax 80 --N 1280 --tmax 100 "${shift_flags[@]}"
    uniform_run "p$p-h$h-far" --fd-order "$p" --rmax 160 --N 2560 --tmax 100 "${shift_flags[@]}"
    [ "$h" != 0 ] && uniform_run "p$p-h$h-notaper" --fd-order "$p" --rmax 80 --N 1280 --tmax 100 \
      "${shift_flags[@]}" --rah-rcut 1e9
  done
done
lib_wait
lib_check
$py - "$out" <<'PY' | tee "$out/table.txt"
import os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series as read_series
out = sys.argv[1]
def series(name):
    return read_series(os.path.join(out, name, 'timeseries.dat'))
print("# 1. reflected amplitude at the horizon: largest |difference| to the rmax 400 M run")
print("# spacing rmax t_b max|d alpha_center| max|d M_AH| (t >= t_b) max|d M_AH| (t < t_b)"
      " (t_b = (rmax - 2)/sqrt 2: the boundary's influence reaches the horizon)")
for per_M in (8, 16):
    ref = series(f"reflect-M{per_M}-rmax400")
    for rmax in (50, 100, 200):
        s = series(f"reflect-M{per_M}-rmax{rmax}")
        n = min(len(s['t']), len(ref['t']))
        t = s['t'][:n]
        # the boundary's influence reaches the horizon (r ~ 2 M) after (rmax - 2) / sqrt(2) at
        # the gauge speed; the collapse's outgoing pulse comes back after twice that
        t_return = (rmax - 2.0) / np.sqrt(2.0)
        late, early = t >= t_return, t < t_return
        da = np.abs(s['alpha_center'][:n] - ref['alpha_center'][:n])
        dm = np.abs(s['M_ah'][:n] - ref['M_ah'][:n])
        fmt = lambda a, sel: f"{np.nanmax(a[sel]):.2e}" if sel.any() else "--"
        print(f"M/{per_M} {rmax} {t_return:.0f} {fmt(da, late)} {fmt(dm, late)} {fmt(dm, early)}")
print("# 2. uniform N = 1280, rmax 80 M, to 100 M: max|M_AH - M| over 0 <= t <= 100 M")
print("# fd_order h tapered(default) untapered boundary_at_160M")
for p in (4, 6):
    for h in ('0', '0.6', '0.89', '1.2'):
        def m(name):
            s = series(name)
            return "--" if s is None else f"{np.nanmax(np.abs(s['M_ah_err'])):.2e}"
        label = 'standard' if h == '0' else h
        print(f"{p} {label} {m(f'p{p}-h{h}-taper')} {m(f'p{p}-h{h}-notaper')} {m(f'p{p}-h{h}-far')}")
PY
