#!/usr/bin/env python3
"""r_AH(t) (or another column of horizon.dat / timeseries.dat) for several runs in one PNG,
each labelled by the parameters recorded in its header. More runs than seven colours tell
apart go into panels of up to seven each (sharing their axes).

  plot_horizons.py out/horizon/*/horizon.dat -o r_ah.png [--label-by rah0,rahA,N] [-y r_ah]
"""
import argparse
import math
import sys

import numpy as np

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

from gbssn1d_data import (QUALITATIVE, axis_label, column, parse, qualitative_colors, read_text,
                          style)


def header_params(text):
    params = {}
    for line in text.splitlines():
        if not line.startswith('#'):
            break
        if '=' in line and not line.startswith('# t ='):
            key, value = line[1:].split('=', 1)
            params[key.strip()] = value.strip().strip('"')
    return params


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+')
    ap.add_argument('-y', default='r_ah', help='column to plot (default r_ah)')
    ap.add_argument('--label-by', default='id,rah0,rahA,N', help='header parameters in the labels')
    ap.add_argument('--target', action='store_true', help='draw each run\'s rah0 as a dotted line')
    ap.add_argument('--title', default=None,
                    help='default: the apparent horizon\'s coordinate radius for -y r_ah, '
                         'else the column\'s name')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    style(plt)
    per_panel = len(QUALITATIVE)
    panels = math.ceil(len(a.files) / per_panel)
    cols = min(panels, 2)
    rows = math.ceil(panels / cols)
    fig, axes = plt.subplots(rows, cols, sharex=True, sharey=True, squeeze=False,
                             figsize=(7 if cols == 1 else 11, 4.5 if rows == 1 else 3.2 * rows))
    title = a.title if a.title is not None else (
        'apparent-horizon coordinate radius' if a.y == 'r_ah' else a.y)
    for p in range(panels):
        ax = axes[p // cols][p % cols]
        files = a.files[p * per_panel:(p + 1) * per_panel]
        for color, path in zip(qualitative_colors(len(files), 'runs'), files):
            text = read_text(path)
            params = header_params(text)
            columns, blocks = parse(text)
            data = blocks[0][1]
            label = ', '.join(f'{k}={params.get(k, "?")}' for k in a.label_by.split(','))
            if not np.isfinite(column(columns, data, a.y)).any():
                sys.stderr.write(f'note: {path} has no finite {a.y} (no horizon found); '
                                 f'its legend entry has no curve\n')
            line, = ax.plot(column(columns, data, 't'), column(columns, data, a.y), color=color,
                            label=label)
            if a.target and 'rah0' in params and float(params.get('rahA', 0)) != 0:
                ax.axhline(float(params['rah0']), color=line.get_color(), ls=':', lw=1)
        ax.legend(fontsize=7)
        if p // cols == rows - 1 or panels - p <= cols:
            ax.set_xlabel('t / M')
        if p % cols == 0:
            ax.set_ylabel(axis_label(a.y))
    for p in range(panels, rows * cols):
        axes[p // cols][p % cols].set_visible(False)
    fig.suptitle(title + (f' ({len(a.files)} runs, {panels} panels)' if panels > 1 else ''))
    fig.tight_layout()
    fig.savefig(a.output)


if __name__ == '__main__':
    main()
