#!/usr/bin/env python3
"""Tables and figures of the horizon-shift study from `gbssn1d converge` output directories.

  horizon_study.py table STD FAMILY [FAMILY ...] [-y H_L2_R] [--t0 10 --t1 100]
  horizon_study.py figure FAMILY [FAMILY ...] [-y H_L2_R] [--cols 3] -o figure.png
  horizon_study.py threshold FAMILY [FAMILY ...] [--min-order 3.5] [--rmax 200]

Each FAMILY (and STD, the standard gauge at the same resolutions) is a converge directory
with convergence.dat. `table` prints a row per family:
  - rms_N: the RMS over t in [t0, t1] of the norm (-y) of each member; a time average is
    steadier than one time, where a norm can pass near a zero of H;
  - p_rms: the pairwise orders of those averages, p = ln(E_a/E_b)/ln(b/a) (a quantity whose
    exact value is zero, equations document Sec. 15);
  - p_min, p_max: the smallest and largest pairwise order over the output times in [t0, t1];
  - ratio_N: rms_N over the standard family's at the same N (the cost of the gauge in error).
Families whose members stopped early say so (`ended t = ...`).
`threshold` prints, for each family on a uniform grid of --rmax, the coarsest spacing
rmax/N_k from which every three consecutive resolutions converge: both pairwise orders of the
time averages at least --min-order, for the triple starting at N_k and every finer one.
`figure` draws the norm against t for each family, one panel each, a curve per resolution
(a sequential colormap: darker is finer).
"""
import argparse
import math
import os

import numpy as np

from gbssn1d_data import parse, read_text, style


def load(directory, key):
    """{N: (t, norm)} of one converge directory."""
    columns, blocks = parse(read_text(os.path.join(directory, 'convergence.dat')))
    data = blocks[0][1]
    t = data[:, columns.index('t')]
    out = {}
    for c in columns:
        if c.startswith(key + '_N'):
            out[int(c[len(key) + 2:])] = (t, data[:, columns.index(c)])
    if not out:
        raise SystemExit(f"{directory}: no column {key}_N<n>")
    return out


def end_times(directory):
    """Final time of each member's timeseries.dat (a member that stopped ends early)."""
    ends = {}
    for name in os.listdir(directory):
        path = os.path.join(directory, name, 'timeseries.dat')
        if name.startswith('N') and os.path.exists(path):
            columns, blocks = parse(read_text(path))
            ends[int(name[1:])] = blocks[0][1][-1, columns.index('t')]
    return ends


def rms(t, v, t0, t1):
    sel = (t >= t0) & (t <= t1)
    return math.sqrt(np.mean(v[sel] ** 2)) if sel.any() else float('nan')


def order(a, b, Na, Nb):
    return math.log(a / b) / math.log(Nb / Na) if a > 0 and b > 0 else float('nan')


def table(args):
    std = load(args.std, args.y)
    print(f"# {args.y}: RMS over t in [{args.t0}, {args.t1}] M; orders p = ln(E_a/E_b)/ln(b/a)")
    for d in args.families:
        fam = load(d, args.y)
        Ns = sorted(fam)
        R = [rms(*fam[n], args.t0, args.t1) for n in Ns]
        p = [order(R[k], R[k + 1], Ns[k], Ns[k + 1]) for k in range(len(Ns) - 1)]
        ranges = []
        for k in range(len(Ns) - 1):
            (t, a), (_, b) = fam[Ns[k]], fam[Ns[k + 1]]
            sel = (t >= args.t0) & (t <= args.t1) & (a > 0) & (b > 0)
            q = np.log(a[sel] / b[sel]) / math.log(Ns[k + 1] / Ns[k])
            ranges.append(f"{q.min():.1f}..{q.max():.1f}" if q.size else '--')
        ratio = [rms(*fam[n], args.t0, args.t1) / rms(*std[n], args.t0, args.t1) if n in std
                 else float('nan') for n in Ns]
        ends = end_times(d)
        short = [f"N{n} ended t = {e:g}" for n, e in sorted(ends.items()) if e < args.t1 - 1e-9]
        print(f"{os.path.basename(os.path.normpath(d))}: N {','.join(map(str, Ns))}"
              f" | rms {' '.join(f'{x:.2e}' for x in R)}"
              f" | p_rms {' '.join(f'{x:.2f}' for x in p)}"
              f" | p(t) {' '.join(ranges)}"
              f" | ratio {' '.join(f'{x:.2f}' for x in ratio)}"
              + (f" | {'; '.join(short)}" if short else ''))


def threshold(args):
    print(f"# coarsest spacing from which every 3 consecutive resolutions give p_rms >= "
          f"{args.min_order} ({args.y}, t in [{args.t0}, {args.t1}] M)")
    for d in args.families:
        fam = load(d, args.y)
        Ns = sorted(fam)
        R = [rms(*fam[n], args.t0, args.t1) for n in Ns]
        ends = end_times(d)
        ok = []
        for k in range(len(Ns) - 2):
            finished = all(ends.get(n, args.t1) >= args.t1 - 1e-9 for n in Ns[k:k + 3])
            p = [order(R[j], R[j + 1], Ns[j], Ns[j + 1]) for j in (k, k + 1)]
            ok.append(finished and all(x >= args.min_order for x in p))
        start = None
        for k in range(len(ok) - 1, -1, -1):
            if not ok[k]:
                break
            start = k
        name = os.path.basename(os.path.normpath(d))
        if start is None:
            print(f"{name}: none of N = {','.join(map(str, Ns))}")
        else:
            print(f"{name}: from M/{Ns[start] / args.rmax:g} (N = {Ns[start]})")


def figure(args):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    style(plt)
    n = len(args.families)
    cols = min(args.cols, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows), squeeze=False,
                             sharey=True)
    for ax, d in zip(axes.flat, args.families):
        fam = load(d, args.y)
        Ns = sorted(fam)
        colors = plt.cm.viridis(np.linspace(0.85, 0.0, len(Ns)))
        for color, N in zip(colors, Ns):
            t, v = fam[N]
            ax.semilogy(t, v, color=color, label=f'N = {N}')
        ax.set_title(os.path.basename(os.path.normpath(d)), fontsize=9)
        ax.set_xlabel('t (M)')
        ax.legend(fontsize=7)
    for ax in axes[:, 0]:
        ax.set_ylabel(args.y)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    fig.tight_layout()
    fig.savefig(args.output)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='what', required=True)
    t = sub.add_parser('table')
    t.add_argument('std')
    t.add_argument('families', nargs='+')
    f = sub.add_parser('figure')
    f.add_argument('families', nargs='+')
    f.add_argument('--cols', type=int, default=3)
    f.add_argument('-o', '--output', required=True)
    th = sub.add_parser('threshold')
    th.add_argument('families', nargs='+')
    th.add_argument('--min-order', type=float, default=3.5)
    th.add_argument('--rmax', type=float, default=200.0)
    for p in (t, f, th):
        p.add_argument('-y', default='H_L2_R')
        p.add_argument('--t0', type=float, default=10.0)
        p.add_argument('--t1', type=float, default=100.0)
    a = ap.parse_args()
    {'table': table, 'figure': figure, 'threshold': threshold}[a.what](a)


if __name__ == '__main__':
    main()
