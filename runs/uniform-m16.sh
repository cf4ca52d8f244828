#!/usr/bin/env bash
# What limits max|M_AH - M| on the uniform M/16 grid of the study (docs/horizon-shift-study.md,
# Sec. 7.2), every run kept in out/uniform-m16/ and redone only where its command or binary changed (about 1 minute on 2 cores). Wormhole
# data with every default but the grid and the ones named:
#  1. the standard gauge (no horizon shift) at --fd-order 4 and 6 on uniform grids with the
#     boundary at 160 M (out of the way to 50 M) at M/16, M/32, M/64, to 50 M: the largest
#     |M_AH - M| and its order between spacings;
#  2. the shrink to h = 0.6 M (A = 0.5) at --fd-order 4 and 6, boundary at 160 M, at spacings
#     M/12.8 ... M/32 (N = 2048 ... 5120), to 60 M: where its error falls below 1e-4;
#  3. the issue's grid (uniform N = 1280, rmax 80 M, to 100 M) for the standard gauge and
#     h = 0.6, 0.89, 1.2 M at --fd-order 4 and 6 and Kreiss-Oliger strengths 0 ... 0.2: the
#     largest |M_AH - M| over the run, and its signed value at 40, 60, 80, 100 M for the shrink;
#  4. on that grid at --fd-order 6, the shrink with one thing changed at a time: h_AH(t)
#     prescribed from the run's own horizon.dat (no finder feedback), the advection stencil of
#     B's driver, eta = 1/M (also the standard gauge), cfl 0.25, and no chi floor;
#  5. the four gauges of part 3 at the defaults, 20% finer: N = 1536 (M/19.2), rmax 80 M;
#  6. the four gauges of part 3 at the defaults on the trumpet data sets (1log-trumpet,
#     maximal-trumpet), N = 1280, rmax 80 M: max|M_AH - M| over the run and before 55 M (before
#     the outer boundary's influence can reach the horizon).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/uniform-m16.sh "$here" out/uniform-m16 "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
for p in 4 6; do
  for n in 2560 5120 10240; do
    uniform_run "standard-p$p-N$n" --fd-order "$p" --rmax 160 --N "$n" --tmax 50
  done
  for n in 2048 2560 3072 3413 4096 5120; do
    uniform_run "shrink-p$p-N$n" --fd-order "$p" --rmax 160 --N "$n" --tmax 60 --rahA 0.5 --rah0 0.6
  done
  for sigma in 0 0.02 0.05 0.1 0.2; do
    for h in 0 0.6 0.89 1.2; do
      shift_flags=()
      [ "$h" != 0 ] && shift_flags=(--rahA 0.5 --rah0 "$h")
      uniform_run "m16-p$p-ko$sigma-h$h" --fd-order "$p" --ko-sigma "$sigma" --rmax 80 --N 1280 \
        --tmax 100 "${shift_flags[@]}"
    done
  done
done
lib_wait
lib_check
shrink=(--fd-order 6 --rmax 80 --N 1280 --tmax 100 --rahA 0.5 --rah0 0.6)
uniform_run try-open-loop "${shrink[@]}" --rah-hAH-file "$out/m16-p6-ko0.1-h0.6/horizon.dat"
uniform_run try-driver-centred "${shrink[@]}" --driver-advection centred
uniform_run try-driver-full "${shrink[@]}" --driver-advection upwind-full
uniform_run try-eta1-standard --fd-order 6 --rmax 80 --N 1280 --tmax 100 --eta 1
uniform_run try-cfl0.25 "${shrink[@]}" --cfl 0.25
uniform_run try-no-chi-floor "${shrink[@]}" --chi-floor 0
for p in 4 6; do
  for h in 0 0.6 0.89 1.2; do
    shift_flags=()
    [ "$h" != 0 ] && shift_flags=(--rahA 0.5 --rah0 "$h")
    uniform_run "m19-p$p-h$h" --fd-order "$p" --rmax 80 --N 1536 --tmax 100 "${shift_flags[@]}"
    for id in 1log-trumpet maximal-trumpet; do
      uniform_run "$id-p$p-h$h" --id "$id" --fd-order "$p" --rmax 80 --N 1280 --tmax 100 \
        "${shift_flags[@]}"
    done
  done
done
lib_wait
lib_check
$py - "$out" <<'PY' | tee "$out/table.txt"
import math, os, sys
import numpy as np
sys.path.insert(0, 'plots')
from gbssn1d_data import series as read_series
out = sys.argv[1]
def series(name):
    return read_series(os.path.join(out, name, 'timeseries.dat'))
def max_err(name):
    s = series(name)
    return None if s is None else float(np.nanmax(np.abs(s['M_ah_err'])))
def fmt(x):
    return "--" if x is None else f"{x:.2e}"
def orders(errs, spacings):
    o = []
    for (e1, h1), (e2, h2) in zip(zip(errs, spacings), zip(errs[1:], spacings[1:])):
        o.append("--" if e1 is None or e2 is None else f"{math.log(e1 / e2) / math.log(h1 / h2):.2f}")
    return " ".join(o)
print("# 1. standard gauge, uniform, rmax 160 M, to 50 M: max|M_AH - M| at M/16, M/32, M/64 (orders)")
for p in (4, 6):
    e = [max_err(f"standard-p{p}-N{n}") for n in (2560, 5120, 10240)]
    print(f"fd-order {p}: {' '.join(fmt(x) for x in e)} ({orders(e, [1/16, 1/32, 1/64])})")
print("# 2. shrink to h = 0.6 M, uniform, rmax 160 M, to 60 M: max|M_AH - M| against spacing")
ns = (2048, 2560, 3072, 3413, 4096, 5120)
print("# spacing " + " ".join(f"M/{n / 160:.1f}" for n in ns))
for p in (4, 6):
    print(f"fd-order {p}: " + " ".join(fmt(max_err(f"shrink-p{p}-N{n}")) for n in ns))
print("# 3. uniform N = 1280, rmax 80 M, to 100 M: max|M_AH - M| over the run")
print("# fd-order ko-sigma standard 0.6 0.89 1.2 | the shrink's M_AH - M at t = 40, 60, 80, 100 M")
for p in (4, 6):
    for sigma in ('0', '0.02', '0.05', '0.1', '0.2'):
        row = [fmt(max_err(f"m16-p{p}-ko{sigma}-h{h}")) for h in ('0', '0.6', '0.89', '1.2')]
        s = series(f"m16-p{p}-ko{sigma}-h0.6")
        signed = "--" if s is None else " ".join(
            f"{s['M_ah_err'][np.argmin(np.abs(s['t'] - t))]:+.1e}" for t in (40, 60, 80, 100))
        print(f"{p} {sigma} {' '.join(row)} | {signed}")
print("# 4. the shrink at --fd-order 6, N = 1280, rmax 80 M, one change at a time: max|M_AH - M|")
for name in ('try-open-loop', 'try-driver-centred', 'try-driver-full', 'try-eta1-standard',
             'try-cfl0.25', 'try-no-chi-floor'):
    s = series(name)
    end = "" if s is None or s['t'][-1] >= 100 else f" (stopped at t = {s['t'][-1]:g})"
    print(f"{name} {fmt(max_err(name))}{end}")
print("# 5. uniform N = 1536 (M/19.2), rmax 80 M, to 100 M, defaults: max|M_AH - M|")
print("# fd-order standard 0.6 0.89 1.2")
for p in (4, 6):
    print(f"{p} " + " ".join(fmt(max_err(f"m19-p{p}-h{h}")) for h in ('0', '0.6', '0.89', '1.2')))
print("# 6. trumpet data, uniform N = 1280, rmax 80 M, to 100 M: max|M_AH - M| (before 55 M)")
print("# data fd-order standard 0.6 0.89 1.2")
def early_late(name):
    s = series(name)
    if s is None:
        return "--"
    e = np.abs(s['M_ah_err'])
    return f"{np.nanmax(e):.2e} ({np.nanmax(e[s['t'] < 55]):.1e})"
for id in ('1log-trumpet', 'maximal-trumpet'):
    for p in (4, 6):
        print(f"{id} {p} " + " ".join(early_late(f"{id}-p{p}-h{h}") for h in ('0', '0.6', '0.89', '1.2')))
PY
