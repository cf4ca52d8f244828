#!/usr/bin/env python3
"""Error against cost on three kinds of grid: uniform, sinh and nested boxes.

  boxes_cost.py --out DIR [--tmax 1000] [--rmax 1024] [--t0 10] [--bin build/gbssn1d]
                [--kinds boxes,sinh,uniform] [--gauges standard,stretched] [--id 1log-trumpet]
                [--pairs K]

Runs the 1+log trumpet (or --id's data), standard gauge and stretched to h = 0.89 M (A = 0.5), on
  - boxes: 9 levels to rmax, finest spacing 4/N M (N = 32, 48, 64, 96: M/8 ... M/24);
  - sinh: the map with innermost cell M/16 at N = 400 (--dr-inner 0.0625), N = 200 ... 600
    (innermost M/8 ... M/24); N = 400 is the reference;
  - uniform: N = 4096, 6144, 8192 (M/4 ... M/8),
one after the other, each alone on one core, and measures its CPU time (the runs are single
threaded; CPU time does not depend on what else the machine does) and the RMS over
[t0, tmax] of H_L2_R (areal radius 2.5 M ... 12 M). Prints a row per run, then for each
kind and gauge the CPU time needed to reach the reference's error (sinh, N = 400, same gauge),
interpolated between its runs in log-log (or marked '>' beyond them), and its ratio to the
reference's time. Writes DIR/cost.png: CPU time against error, log-log, one curve per kind and
gauge. Every run is made afresh; DIR/<kind>-<gauge>-N<n>/ holds its output.

A shared machine's speed drifts by tens of percent within minutes, and runs one after the other
carry that drift into the ratio. --pairs K measures it again in K alternating pairs: each of
the two runs of a kind whose errors bracket the reference's, against the reference, run after
run; the median of each pair's CPU ratio, interpolated in log-log as above (the drift cancels
within a pair).
"""
import argparse
import math
import os
import resource
import shutil
import subprocess
import time

import numpy as np

from gbssn1d_data import (DataError, line_styles, parse, qualitative_colors, read_text,
                          run_script, style)

KINDS = {
    'boxes': (['--grid', 'boxes', '--levels', '9'], [32, 48, 64, 96]),
    'sinh': (['--grid', 'sinh', '--dr-inner', '0.0625'], [200, 300, 400, 600]),
    'uniform': (['--grid', 'uniform'], [4096, 6144, 8192]),
}
GAUGES = {'standard': [], 'stretched': ['--rahA', '0.5', '--rah0', '0.89']}


def rms_H(path, t0, t1):
    columns, blocks = parse(read_text(path), path)
    missing = [c for c in ('t', 'H_L2_R') if c not in columns]
    if missing:
        raise DataError(f"no column {', '.join(missing)}", path)
    data = blocks[0][1]
    t = data[:, columns.index('t')]
    H = data[:, columns.index('H_L2_R')]
    keep = (t >= t0 - 1e-9) & (t <= t1 + 1e-9)
    return float(np.sqrt(np.mean(H[keep] ** 2))), float(t[-1])


def run(args, kind, gauge, n):
    flags, _ = KINDS[kind]
    out = os.path.join(args.out, f'{kind}-{gauge}-N{n}')
    shutil.rmtree(out, ignore_errors=True)
    cmd = [args.bin, 'evolve', '--id', args.id, '--rmax', str(args.rmax), '--N', str(n),
           '--tmax', str(args.tmax), '--dt-series', '1', '--dt-profiles', str(args.tmax),
           '--out', out] + flags + GAUGES[gauge]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(cmd, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    H, t_end = rms_H(os.path.join(out, 'timeseries.dat'), args.t0, args.tmax)
    status = 'ok' if done.returncode == 0 else f'exit {done.returncode}'
    return dict(kind=kind, gauge=gauge, N=n, cpu=cpu, wall=wall, H=H, t_end=t_end, status=status)


def needed(rows, target):
    """CPU time at which the error reaches target, by log-log interpolation between runs."""
    pts = sorted((r['cpu'], r['H']) for r in rows if r['status'] == 'ok')
    for (c0, e0), (c1, e1) in zip(pts, pts[1:]):
        if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
            s = math.log(target / e0) / math.log(e1 / e0)
            return '', math.exp(math.log(c0) + s * math.log(c1 / c0))
    if pts and pts[0][1] <= target:
        return '<', pts[0][0]
    if len(pts) >= 2:  # beyond the finest: extrapolate the last pair
        (c0, e0), (c1, e1) = pts[-2], pts[-1]
        s = math.log(target / e0) / math.log(e1 / e0)
        return '>', math.exp(math.log(c0) + s * math.log(c1 / c0))
    return '?', float('nan')


def paired_ratio(args, rows, kind, gauge, target, k):
    """The CPU ratio of `kind` to the reference at the reference's error, from k alternating
    pairs of each bracketing run and the reference (medians of the pairs' ratios)."""
    pts = sorted((r['H'], r['N']) for r in rows if r['kind'] == kind and r['gauge'] == gauge
                 and r['status'] == 'ok')
    bracket = [(a, b) for a, b in zip(pts, pts[1:]) if (a[0] - target) * (b[0] - target) <= 0]
    if not bracket or bracket[0][0][0] == bracket[0][1][0]:
        return None
    (e0, n0), (e1, n1) = bracket[0]
    medians = []
    for n in (n0, n1):
        ratios = [run(args, kind, gauge, n)['cpu'] / run(args, 'sinh', gauge, 400)['cpu']
                  for _ in range(k)]
        medians.append(float(np.median(ratios)))
    s = math.log(target / e0) / math.log(e1 / e0)
    return math.exp(math.log(medians[0]) + s * math.log(medians[1] / medians[0])), (n0, n1), medians


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--out', required=True)
    ap.add_argument('--tmax', type=float, default=1000.0)
    ap.add_argument('--rmax', type=float, default=1024.0)
    ap.add_argument('--t0', type=float, default=10.0)
    ap.add_argument('--bin', default='build/gbssn1d')
    ap.add_argument('--kinds', default='boxes,sinh,uniform')
    ap.add_argument('--gauges', default='standard,stretched')
    ap.add_argument('--id', default='1log-trumpet',
                    help='initial data: 1log-trumpet (default), wormhole or maximal-trumpet')
    ap.add_argument('--pairs', type=int, default=0,
                    help='also measure each ratio in this many alternating pairs (0: not)')
    args = ap.parse_args()
    if args.pairs < 0:
        raise DataError('must be 0 or more (--pairs)', str(args.pairs))
    if shutil.which(args.bin) is None or os.path.isdir(args.bin):
        raise DataError('no such program (--bin: the gbssn1d executable)', args.bin)
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        raise DataError('is not a folder (--out)', args.out)
    os.makedirs(args.out, exist_ok=True)
    kinds = args.kinds.split(',')
    gauges = args.gauges.split(',')
    rows = []
    print(f'# {args.id} data to {args.tmax:g} M, rmax {args.rmax:g} M; H = RMS of H_L2_R over '
          f't in [{args.t0:g}, {args.tmax:g}] M; cpu and wall in seconds, one run at a time')
    print('kind gauge N cpu_s wall_s H status')
    for gauge in gauges:
        for kind in kinds:
            for n in KINDS[kind][1]:
                r = run(args, kind, gauge, n)
                rows.append(r)
                print(f"{kind} {gauge} {n} {r['cpu']:.2f} {r['wall']:.2f} {r['H']:.3e} "
                      f"{r['status'] if r['status'] != 'ok' else 'ok'}"
                      f"{'' if r['t_end'] >= args.tmax - 1e-6 else ' (ended t = %g)' % r['t_end']}",
                      flush=True)
    print('# CPU time to reach the error of sinh N = 400 (innermost M/16), same gauge')
    for gauge in gauges:
        ref = [r for r in rows if r['kind'] == 'sinh' and r['gauge'] == gauge and r['N'] == 400]
        if not ref:
            continue
        target, ref_cpu = ref[0]['H'], ref[0]['cpu']
        for kind in kinds:
            mark, cpu = needed([r for r in rows if r['kind'] == kind and r['gauge'] == gauge],
                               target)
            print(f'{gauge} {kind}: H = {target:.3e} at cpu {mark}{cpu:.3g} s '
                  f'({cpu / ref_cpu:.2f} x sinh N = 400)')
        for kind in kinds:
            paired = paired_ratio(args, rows, kind, gauge, target, args.pairs) \
                if args.pairs > 0 and kind != 'sinh' else None
            if paired:
                ratio, ns, medians = paired
                print(f'{gauge} {kind}, {args.pairs} alternating pairs of N = {ns[0]}, {ns[1]} '
                      f'with sinh N = 400 (medians {medians[0]:.2f}, {medians[1]:.2f}): '
                      f'{ratio:.2f} x sinh N = 400', flush=True)

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    style(plt)
    fig, ax = plt.subplots()
    colors = qualitative_colors(len(kinds), 'grid kinds')
    styles = line_styles(len(GAUGES), 'gauges')
    for color, kind in zip(colors, kinds):
        for ls, gauge in zip(styles, GAUGES):
            pts = sorted((r['cpu'], r['H']) for r in rows
                         if r['kind'] == kind and r['gauge'] == gauge and r['status'] == 'ok')
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], ls, marker='o', color=color,
                          label=f'{kind}, {gauge}')
    ax.set_xlabel('CPU time (s)')
    ax.set_ylabel('RMS over t of ||H||_2 over 2.5 M <= R <= 12 M (1/M^2)')
    ax.set_title(f'{args.id} data to {args.tmax:g} M: error against cost')
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, 'cost.png'))


if __name__ == '__main__':
    run_script(main)
