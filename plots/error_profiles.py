#!/usr/bin/env python3
"""The change of a variable since t = 0 of a stationary solution, against r, scaled for an order.

  error_profiles.py DIR [DIR ...] [-y a] [--times 10,50] [--order 4] [--front 10] -o fig.png

Each DIR is a run (or a converge member, e.g. OUT/N24 OUT/N32 OUT/N48) of data that should stay
as they are (the 1+log trumpet with the standard gauge); its profiles.dat must hold t = 0 and
the --times. The error is |y(t) - y(0)| at each r, multiplied by (N / N_first)^order (N from
each run's header), so that at the design order the curves of all runs lie on top of each
other. Prints, for each run and time, the outer boundary's error front: the smallest r beyond
20 M where the error exceeds --front times its median over 5 M <= r <= 20 M. One panel per
time, log scale.
"""
import argparse
import os
import re

import numpy as np

from gbssn1d_data import (DataError, parse, read_text, run_script, save_figure,
                          sequential_colors, style)


def header_value(text, key):
    m = re.search(rf'^# {re.escape(key)} = (\S+)$', text, re.M)
    return float(m.group(1)) if m else None


def block_at(blocks, t):
    for tb, data in blocks:
        if tb is not None and abs(tb - t) < 1e-9 * max(1.0, abs(t)):
            return data
    raise SystemExit(f'no profile block at t = {t}')


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('runs', nargs='+')
    ap.add_argument('-y', default='a')
    ap.add_argument('--times', default='10,50')
    ap.add_argument('--order', type=float, default=4.0)
    ap.add_argument('--front', type=float, default=10.0)
    ap.add_argument('-o', '--output', required=True)
    args = ap.parse_args()
    times = [float(x) for x in args.times.split(',')]
    runs = []
    for d in args.runs:
        path = os.path.join(d, 'profiles.dat')
        text = read_text(path)
        columns, blocks = parse(text, path)
        n = header_value(text, 'N')
        if n is None:
            raise DataError('no N in the header', path)
        runs.append((d, n, columns, blocks))
    n0 = runs[0][1]
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    style(plt)
    fig, axes = plt.subplots(1, len(times), figsize=(5.5 * len(times), 4), squeeze=False,
                             sharey=True)
    colors = sequential_colors(len(runs))
    print(f'# |{args.y}(t) - {args.y}(0)| x (N/{n0:g})^{args.order:g}; front: smallest r > 20 M '
          f'where it exceeds {args.front:g} x its median over [5, 20] M')
    for ax, t in zip(axes[0], times):
        for color, (d, n, columns, blocks) in zip(colors, runs):
            r = block_at(blocks, 0.0)[:, columns.index('r')]
            y0 = block_at(blocks, 0.0)[:, columns.index(args.y)]
            yt = block_at(blocks, t)[:, columns.index(args.y)]
            err = np.abs(yt - y0) * (n / n0) ** args.order
            inner = err[(r >= 5) & (r <= 20)]
            level = args.front * np.median(inner) if inner.size else np.inf
            beyond = r[(r > 20) & (err > level)]
            front = beyond.min() if beyond.size else float('nan')
            print(f'{d}: t = {t:g}: median over [5, 20] M {np.median(inner):.3e}, '
                  f'front at r = {front:.1f} M')
            ax.semilogy(r, np.maximum(err, 1e-300), color=color, label=f'N = {n:g}')
        ax.set_title(f't = {t:g} M', fontsize=10)
        ax.set_xlabel('r / M')
        ax.legend(fontsize=8)
    axes[0][0].set_ylabel(f'|{args.y}(t) - {args.y}(0)| x (N/{n0:g})^{args.order:g}')
    fig.tight_layout()
    save_figure(fig, args.output)


if __name__ == '__main__':
    run_script(main)
