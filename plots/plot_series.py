#!/usr/bin/env python3
"""Plot columns of timeseries.dat (or of any output table: horizon.dat, a sweep's
summary.dat) against t or another column, for one or several runs.

  plot_series.py RUN/timeseries.dat [MORE ...] -y H_L2_ext -y M_L2_ext --logy -o out.png
  gbssn1d ... ; cat RUN/timeseries.dat | plot_series.py - -y alpha_center -o lapse.png
  plot_series.py SWEEP/summary.dat -x rah0 -y M_ah_err_max --logy --points -o drift.png

With --logy the absolute values are plotted (the axis says |y|).
"""
import argparse
import sys

import numpy as np

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

from gbssn1d_data import (axis_label, column, finish, line_styles, parse_table,
                          qualitative_colors, read_text, run_label, sequential_colors, style)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+', help="timeseries.dat files ('-' for stdin)")
    ap.add_argument('-x', default='t', help='column for the x axis (default t)')
    ap.add_argument('-y', action='append', required=True, help='column(s) to plot')
    ap.add_argument('--logy', action='store_true')
    ap.add_argument('--ordered', action='store_true',
                    help='the files form a sequence (resolutions, times): colours from one '
                         'sequential colormap, darker for later files')
    ap.add_argument('--points', action='store_true', help='markers, no lines (tables of runs)')
    ap.add_argument('--label', action='append', help='legend label per file')
    ap.add_argument('--title', default='')
    ap.add_argument('-o', '--output', required=True, help='PNG file to write')
    a = ap.parse_args()
    style(plt)
    fig, ax = plt.subplots()
    # one file: a colour per column; several: a colour per file and a line style per column
    if len(a.files) == 1:
        colors, styles = [None], ['-'] * len(a.y)
        column_colors = qualitative_colors(len(a.y), 'columns')
    else:
        colors = (sequential_colors(len(a.files)) if a.ordered
                  else qualitative_colors(len(a.files), 'runs'))
        styles = line_styles(len(a.y), 'columns')
        column_colors = None
    for k, path in enumerate(a.files):
        columns, data = parse_table(read_text(path))
        label = a.label[k] if a.label and k < len(a.label) else run_label(path)
        for j, y in enumerate(a.y):
            values = column(columns, data, y)
            if not np.isfinite(values).any():
                sys.stderr.write(f'note: {path}: {y} has no finite value; nothing to draw\n')
            color = column_colors[j] if column_colors else colors[k]
            ax.plot(column(columns, data, a.x), abs(values) if a.logy else values, color=color,
                    ls='none' if a.points else styles[j], marker='o' if a.points else None,
                    label=f'{label}: {y}' if len(a.files) > 1 or len(a.y) > 1 else label)
    if a.logy:
        ax.set_yscale('log')
    ylabel = ', '.join(axis_label(y) for y in a.y)
    if a.logy and '|' not in ylabel:
        ylabel = f'|{ylabel}|'
    finish(fig, ax, axis_label(a.x), ylabel, a.title, a.output)


if __name__ == '__main__':
    main()
