#!/usr/bin/env python3
"""The figure of a sweep over the horizon shift's strength A and target h: from the sweep's
summary.dat, three maps over (A, h) with log colour scales and each value written in its cell:
the final horizon's miss |r_AH / h - 1|, the largest |M_AH - M| / M, and the largest H_L2_R
(the L2 norm of the Hamiltonian constraint over the areal-radius window, whose bounds are read
from the members' recorded parameters next to summary.dat). Members that did not finish are
crossed out and named by their status.

  plot_sweep.py out/sweep/summary.dat -o sweep.png [-x rahA] [-y rah0] [--where N=400 ...]

Any two swept columns may be the axes (-x, -y; not the same one twice); a sweep over one flag
gives curves instead: each quantity against that flag (-x, or the one swept column), a member
that did not finish marked by its status.
A map holds one member per cell: a sweep over a third flag (e.g. N) needs --where COLUMN=VALUE
for it, which picks the members of that value (the title says which); without it the script
refuses, naming the column and its values, rather than draw one member per cell unsaid.
"""
import argparse
import glob
import math
import os
import sys

import numpy as np

from gbssn1d_data import (DataError, axis_label, header_params, params_of, pyplot, read_text,
                          run_description, run_script, window, save_figure)


def load(path):
    """(column names, rows of words, the text) of a sweep's summary.dat."""
    text = read_text(path)
    lines = [l for l in text.splitlines() if l.strip()]
    names = lines[0][1:].split() if lines and lines[0].startswith('#') else []
    rows = [l.split() for l in lines if not l.startswith('#')]
    if 'status' not in names or not rows:
        raise DataError('not a sweep summary (no status column or no rows)', path)
    for k, row in enumerate(rows):
        if len(row) != len(names):
            raise DataError(f'row {k + 1} has {len(row)} fields, not the {len(names)} columns',
                            path)
    needed = [c for c in ('M_ah_err_max', 'H_L2_R_max') if c not in names]
    if 'rah0' in names and 'r_ah_final' not in names:
        needed.append('r_ah_final')
    if needed:
        raise DataError(f"not a sweep summary (no column {', '.join(needed)})", path)
    return names, rows, text


def number(word):
    try:
        return float(word)
    except ValueError:
        return math.nan


def member_params(summary):
    """The recorded parameters of the sweep's members (OUT/logs/*.inputs, else the headers of
    OUT/*/timeseries.dat), one dict per member; none for stdin."""
    if summary == '-':
        return []
    out = os.path.dirname(os.path.abspath(summary))
    inputs = sorted(glob.glob(os.path.join(out, 'logs', '*.inputs')))
    if inputs:
        return [params_of(read_text(path).splitlines()) for path in inputs]
    return [header_params(read_text(path))
            for path in sorted(glob.glob(os.path.join(out, '*', 'timeseries.dat')))]


def log_ticks(vmin, vmax):
    """Ticks for a log colour scale from vmin to vmax, spread out enough to be read: the
    decades, then 3, 2, 5, ... times them, each at least a fifth of the scale's length from
    the others (and labelled differently); the ends too where that gives fewer than three."""
    span = math.log10(vmax / vmin)
    ticks = []

    def add(tick):
        if (vmin * (1 - 1e-9) <= tick <= vmax * (1 + 1e-9)
                and all(abs(math.log10(tick / other)) >= span / 5
                        and f'{tick:.1e}' != f'{other:.1e}' for other in ticks)):
            ticks.append(tick)
    for mantissa in (1, 3, 2, 5, 4, 6, 7, 8, 9):
        for exponent in range(math.floor(math.log10(vmin)), math.ceil(math.log10(vmax)) + 1):
            add(mantissa * 10.0 ** exponent)
    if len(ticks) < 3:
        add(vmin)
        add(vmax)
    return sorted(ticks)


def power_of_ten(value, _=None):
    """2e-06 as 2x10^-6 (in mathtext)."""
    mantissa, exponent = f'{value:.1e}'.split('e')
    mantissa = f'{float(mantissa):g}'
    power = f'10^{{{int(exponent)}}}'
    return f'${power}$' if mantissa == '1' else rf'${mantissa}\times{power}$'


def curves(a, names, rows, text, x):
    """A sweep over one flag: each quantity against it, members that did not finish marked."""
    col = {n: k for k, n in enumerate(names)}
    members = member_params(a.summary)
    windows = {window('R', p) for p in members}
    areal = windows.pop() if len(windows) == 1 else window('R')
    quantities = [('largest |M_AH - M| / M over the run', 'M_ah_err_max'),
                  (f'largest L2 norm of H over {areal} (1/M^2)', 'H_L2_R_max')]
    plt = pyplot()
    fig, axes = plt.subplots(1, len(quantities), figsize=(4.8 * len(quantities), 4.0),
                             squeeze=False)
    ok = sorted((number(r[col[x]]), r) for r in rows if r[col['status']] == 'ok')
    bad = [r for r in rows if r[col['status']] != 'ok']
    for ax, (label, column_name) in zip(axes[0], quantities):
        xs = [v for v, _ in ok]
        ys = [number(r[col[column_name]]) for _, r in ok]
        ax.plot(xs, ys, 'o-')
        positive = [y for y in ys if y > 0]
        if positive:
            ax.set_yscale('log')
        for r in bad:
            ax.axvline(number(r[col[x]]), color='crimson', ls=':')
            ax.text(number(r[col[x]]), 0.95, f"x {r[col['status']]}", color='crimson',
                    fontsize=8, rotation=90, va='top', transform=ax.get_xaxis_transform())
        ax.set_xlabel(axis_label(x))
        ax.set_ylabel(label, fontsize=9)
    header = [l for l in text.splitlines() if l.startswith('# sweep over')]
    ran = run_description(members)
    fig.suptitle((header[0][2:] if header else a.summary) + (f'\n{ran}' if ran else ''),
                 fontsize=10)
    fig.tight_layout()
    save_figure(fig, a.output)
    if bad:
        sys.stderr.write(f'note: {len(bad)} member(s) did not finish (marked)\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('summary')
    ap.add_argument('-x', default='rahA', help='swept column on the x axis (default rahA)')
    ap.add_argument('-y', default='rah0', help='swept column on the y axis (default rah0)')
    ap.add_argument('--where', action='append', default=[], metavar='COLUMN=VALUE',
                    help='keep the members with this value of a third swept column (repeatable)')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    names, rows, text = load(a.summary)
    col = {n: k for k, n in enumerate(names)}
    swept = names[:col['status']]
    if len(swept) == 1:
        if a.x not in swept and a.x != ap.get_default('x'):
            raise SystemExit(f"'{a.x}' is not a swept column; swept: {swept[0]}")
        return curves(a, names, rows, text, swept[0])
    if a.x == a.y:
        raise SystemExit(f"-x and -y both name {a.x}: a map needs two swept columns "
                         f"(swept: {' '.join(swept)})")
    for axis in (a.x, a.y):
        if axis not in swept:
            raise SystemExit(f"'{axis}' is not a swept column; swept: {' '.join(swept)}")
    chosen = {}
    for item in a.where:
        name, _, value = item.partition('=')
        if name not in swept or name in (a.x, a.y):
            raise SystemExit(f"--where {item}: '{name}' is not a swept column besides the axes; "
                             f"swept: {' '.join(swept)}")
        if not value or math.isnan(number(value)):
            raise SystemExit(f"--where {item}: the value is not a number")
        chosen[name] = number(value)
    for name in swept:
        values = sorted({number(r[col[name]]) for r in rows})
        if name not in (a.x, a.y) and len(values) > 1 and name not in chosen:
            raise SystemExit(
                f"the sweep varies {name} too ({', '.join(f'{v:g}' for v in values)}): a map "
                f"over {a.x} and {a.y} holds one member per cell; pick one with "
                f"--where {name}=VALUE")
    rows = [r for r in rows if all(number(r[col[n]]) == v for n, v in chosen.items())]
    if not rows:
        raise SystemExit(f"no member has {', '.join(a.where)}")
    cells = [(r[col[a.x]], r[col[a.y]]) for r in rows]
    if len(set(cells)) != len(cells):
        raise SystemExit(f"two members share a cell of {a.x} and {a.y}: not a map")
    xs = sorted({number(r[col[a.x]]) for r in rows})
    ys = sorted({number(r[col[a.y]]) for r in rows})
    h_of = (lambda r: number(r[col['rah0']])) if 'rah0' in col else None

    def unshifted(r):  # rahA = 0: the shift is off, its rah0 is no target
        return 'rahA' in col and number(r[col['rahA']]) == 0

    members = member_params(a.summary)
    windows = {window('R', p) for p in members}
    areal = windows.pop() if len(windows) == 1 else window('R')
    # (panel title, colour bar label, value of a member's row, what the cell of a finished
    # member says instead of a value, if anything)
    quantities = [
        ('horizon radius at the end:\nmiss of the target h', 'relative miss |r_AH / h - 1|',
         lambda r: (abs(number(r[col['r_ah_final']]) / h_of(r) - 1)
                    if h_of and not unshifted(r) else math.nan),
         lambda r: 'no target\n(A = 0)' if unshifted(r) else ''),
        ('horizon mass M_AH:\nlargest error over the run', 'relative error max |M_AH - M| / M',
         lambda r: number(r[col['M_ah_err_max']]), None),
        (f'Hamiltonian constraint over {areal}:\nlargest L2 norm over the run',
         'max ||H||_2 (1/M^2)', lambda r: number(r[col['H_L2_R_max']]), None),
    ]
    if not h_of:
        quantities = quantities[1:]
    plt = pyplot()
    import matplotlib.colors as mcolors
    import matplotlib.ticker as mticker
    fig, axes = plt.subplots(1, len(quantities), figsize=(4.6 * len(quantities), 4.2),
                             squeeze=False)
    for ax, (title, bar_label, value, note) in zip(axes[0], quantities):
        grid = np.full((len(ys), len(xs)), np.nan)
        status = [[None] * len(xs) for _ in ys]
        notes = [[''] * len(xs) for _ in ys]
        for r in rows:
            i, j = ys.index(number(r[col[a.y]])), xs.index(number(r[col[a.x]]))
            status[i][j] = r[col['status']]
            if r[col['status']] == 'ok':
                grid[i, j] = value(r)
                notes[i][j] = note(r) if note else ''
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
                elif notes[i][j]:
                    ax.text(j, i, notes[i][j], ha='center', va='center', fontsize=8,
                            color='dimgray')
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
            bar = fig.colorbar(image, ax=ax, shrink=0.85)
            bar.set_ticks(log_ticks(norm.vmin, norm.vmax))
            bar.ax.yaxis.set_major_formatter(mticker.FuncFormatter(power_of_ten))
            bar.ax.yaxis.set_minor_formatter(mticker.NullFormatter())
            bar.ax.tick_params(labelsize=9)
            bar.set_label(bar_label, fontsize=9)
    header = [l for l in text.splitlines() if l.startswith('# sweep over')]
    ran = run_description(members)
    ends = {p.get('tmax') for p in members}
    if ran and len(ends) == 1 and None not in ends:
        ran += f'; to t = {ends.pop()} M'
    picked = ', '.join(f'{n} = {v:g}' for n, v in chosen.items())
    fig.suptitle((header[0][2:] if header else a.summary) + (f' (members with {picked})'
                                                              if picked else '')
                 + (f'\n{ran}' if ran else ''), fontsize=10)
    fig.tight_layout()
    save_figure(fig, a.output)
    bad = [r for r in rows if r[col['status']] != 'ok']
    if bad:
        sys.stderr.write(f'note: {len(bad)} member(s) did not finish (crossed out)\n')


if __name__ == '__main__':
    run_script(main)
