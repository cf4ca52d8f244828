#!/usr/bin/env python3
"""The figure of a sweep over the horizon shift's strength A and target h: from the sweep's
summary.dat, three maps over (A, h) with log colour scales and each value written in its cell:
the final horizon's miss |r_AH / h - 1|, the largest |M_AH - M| / M, and the largest H_L2_R.
Members that did not finish are crossed out and named by their status.

  plot_sweep.py out/sweep/summary.dat -o sweep.png [-x rahA] [-y rah0]

Any two swept columns may be the axes (-x, -y); a sweep over one flag gives curves instead.
"""
import argparse
import math
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.colors as mcolors
import matplotlib.pyplot as plt
import numpy as np

from gbssn1d_data import axis_label, read_text, style


def load(path):
    lines = [l for l in read_text(path).splitlines() if l.strip()]
    names = lines[0][1:].split()
    rows = [l.split() for l in lines if not l.startswith('#')]
    if 'status' not in names or not rows:
        raise SystemExit(f'{path} is not a sweep summary (no status column or no rows)')
    return names, rows


def number(word):
    try:
        return float(word)
    except ValueError:
        return math.nan


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('summary')
    ap.add_argument('-x', default='rahA', help='swept column on the x axis (default rahA)')
    ap.add_argument('-y', default='rah0', help='swept column on the y axis (default rah0)')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    names, rows = load(a.summary)
    col = {n: k for k, n in enumerate(names)}
    swept = names[:col['status']]
    for axis in (a.x, a.y):
        if axis not in swept:
            raise SystemExit(f"'{axis}' is not a swept column; swept: {' '.join(swept)}")
    xs = sorted({number(r[col[a.x]]) for r in rows})
    ys = sorted({number(r[col[a.y]]) for r in rows})
    h_of = (lambda r: number(r[col['rah0']])) if 'rah0' in col else None
    quantities = [
        ('|r_AH / h - 1| at the end (A = 0: no target)',
         lambda r: (abs(number(r[col['r_ah_final']]) / h_of(r) - 1)
                    if h_of and ('rahA' not in col or number(r[col['rahA']]) != 0) else math.nan)),
        ('max |M_AH - M| / M', lambda r: number(r[col['M_ah_err_max']])),
        ('max H_L2_R', lambda r: number(r[col['H_L2_R_max']])),
    ]
    if not h_of:
        quantities = quantities[1:]
    style(plt)
    fig, axes = plt.subplots(1, len(quantities), figsize=(4.6 * len(quantities), 4.2),
                             squeeze=False)
    for ax, (title, value) in zip(axes[0], quantities):
        grid = np.full((len(ys), len(xs)), np.nan)
        status = [[None] * len(xs) for _ in ys]
        for r in rows:
            i, j = ys.index(number(r[col[a.y]])), xs.index(number(r[col[a.x]]))
            status[i][j] = r[col['status']]
            if r[col['status']] == 'ok':
                grid[i, j] = value(r)
        finite = grid[np.isfinite(grid) & (grid > 0)]
        norm = (mcolors.LogNorm(vmin=finite.min(), vmax=max(finite.max(), finite.min() * 1.01))
                if finite.size else None)
        image = ax.imshow(np.where(grid > 0, grid, np.nan), origin='lower', aspect='auto',
                          cmap='viridis', norm=norm)
        for i in range(len(ys)):
            for j in range(len(xs)):
                if status[i][j] is None:
                    continue
                if status[i][j] != 'ok':
                    ax.text(j, i, f'x\n{status[i][j]}', ha='center', va='center', color='crimson',
                            fontsize=8)
                elif np.isfinite(grid[i, j]):
                    ax.text(j, i, f'{grid[i, j]:.1e}', ha='center', va='center', fontsize=8,
                            color='white' if norm and grid[i, j] < math.sqrt(
                                norm.vmin * norm.vmax) else 'black')
        ax.set_xticks(range(len(xs)), [f'{x:g}' for x in xs])
        ax.set_yticks(range(len(ys)), [f'{y:g}' for y in ys])
        ax.set_xlabel(axis_label(a.x))
        ax.set_ylabel(axis_label(a.y))
        ax.set_title(title, fontsize=10)
        ax.grid(False)
        if norm:
            fig.colorbar(image, ax=ax, shrink=0.85)
    header = [l for l in read_text(a.summary).splitlines() if l.startswith('# sweep over')]
    fig.suptitle(header[0][2:] if header else a.summary, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.output)
    bad = [r for r in rows if r[col['status']] != 'ok']
    if bad:
        sys.stderr.write(f'note: {len(bad)} member(s) did not finish (crossed out)\n')


if __name__ == '__main__':
    main()
