#!/usr/bin/env python3
"""Plot columns of profiles.dat at chosen times (the nearest block), several runs overlaid.

  plot_profiles.py RUN/profiles.dat -y alpha -y beta --times 0,50,100 --xmax 10 -o out.png
  plot_profiles.py A/profiles.dat B/profiles.dat -x R_areal -y alpha --times 1000 -o lapse.png
"""
import argparse

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
import numpy as np

from gbssn1d_data import (axis_label, column, finish, line_styles, parse, qualitative_colors,
                          read_text, run_label, sequential_colors, style)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+', help="profiles.dat files ('-' for stdin)")
    ap.add_argument('-x', default='r', help='column for the x axis (default r)')
    ap.add_argument('-y', action='append', required=True, help='column(s) to plot')
    ap.add_argument('--times', default='', help='comma-separated times (default: first and last)')
    ap.add_argument('--xmin', type=float)
    ap.add_argument('--xmax', type=float)
    ap.add_argument('--logy', action='store_true')
    ap.add_argument('--logx', action='store_true')
    ap.add_argument('--label', action='append', help='legend label per file')
    ap.add_argument('--title', default='')
    ap.add_argument('-o', '--output', required=True, help='PNG file to write')
    a = ap.parse_args()
    style(plt)
    fig, ax = plt.subplots()
    # Curves are (file, column) series at several times: with one time, a colour per series;
    # with several, a sequential colour per time (darker is later) and a line style per series.
    n_series = len(a.files) * len(a.y)
    series = 0
    for k, path in enumerate(a.files):
        columns, blocks = parse(read_text(path))
        times = np.array([t if t is not None else 0.0 for t, _ in blocks])
        wanted = [float(v) for v in a.times.split(',')] if a.times else sorted({times[0], times[-1]})
        if len(wanted) == 1:
            colors, styles = [None], ['-'] * n_series
            series_colors = qualitative_colors(n_series, 'curves')
        else:
            colors, styles = sequential_colors(len(wanted)), line_styles(n_series, 'runs x columns')
            series_colors = None
        label = a.label[k] if a.label and k < len(a.label) else run_label(path)
        for i, tw in enumerate(wanted):
            t, data = blocks[int(np.argmin(abs(times - tw)))]
            x = column(columns, data, a.x)
            keep = np.ones_like(x, dtype=bool)
            if a.xmin is not None:
                keep &= x >= a.xmin
            if a.xmax is not None:
                keep &= x <= a.xmax
            for j, y in enumerate(a.y):
                v = column(columns, data, y)[keep]
                s = series + j
                ax.plot(x[keep], abs(v) if a.logy else v, ls=styles[s],
                        color=series_colors[s] if series_colors else colors[i],
                        label=f'{label}: {y}, t = {t:g} M')
        series += len(a.y)
    if a.logy:
        ax.set_yscale('log')
    if a.logx:
        ax.set_xscale('log')
    finish(fig, ax, axis_label(a.x), ', '.join(a.y), a.title, a.output)


if __name__ == '__main__':
    main()
