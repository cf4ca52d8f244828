#!/usr/bin/env python3
"""Plot columns of profiles.dat at chosen times (the nearest block), several runs overlaid.

  plot_profiles.py RUN/profiles.dat -y alpha -y beta --times 0,50,100 --xmax 10 -o out.png
  plot_profiles.py A/profiles.dat B/profiles.dat -x R_areal -y alpha --times 1000 -o lapse.png
"""
import argparse
import math
import sys

import numpy as np

from gbssn1d_data import (axis_label, column, display_name, finish, header_params, label_keys,
                          legend_name, line_styles, log_axis_label, parse, pyplot,
                          qualitative_colors, read_text, run_description, run_labels, run_script,
                          script_name, sequential_colors, several_label, sort_key)


def requested_times(text):
    """--times as finite numbers; anything else ends the script naming the flag (exit 2)."""
    times = []
    for word in text.split(','):
        try:
            t = float(word)
        except ValueError:
            t = math.nan
        if not math.isfinite(t):
            sys.stderr.write(f"{script_name()}: --times: '{word}' is not a finite time\n")
            sys.exit(2)
        times.append(t)
    return times


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
    ap.add_argument('--label', action='append',
                    help='legend label per file (default: the parameters that tell the runs '
                         'apart, from the headers)')
    ap.add_argument('--title', default='',
                    help='title; what was run (from the headers) is written below it, or is '
                         'the title without one')
    ap.add_argument('-o', '--output', required=True, help='PNG file to write')
    a = ap.parse_args()
    texts = [read_text(path) for path in a.files]
    parsed = [parse(text, path) for path, text in zip(a.files, texts)]
    params_list = [header_params(text) for text in texts]
    labels = run_labels(a.files, params_list, a.label)
    # the runs in the order of the parameters that tell them apart (N = 600, 900, 1200 rather
    # than the folders' N1200, N600, N900), each with its label
    keys = label_keys(params_list)
    order = sorted(range(len(a.files)),
                   key=lambda k: [sort_key(params_list[k].get(key)) for key in keys])
    files, parsed, params_list, labels = ([seq[k] for k in order]
                                         for seq in (a.files, parsed, params_list, labels))
    plt = pyplot()
    fig, ax = plt.subplots()
    # Curves are (file, column) series at several times: with one time, a colour per series;
    # with several, a sequential colour per time (darker is later) and a line style per series.
    n_series = len(a.files) * len(a.y)
    series = 0
    for k, (columns, blocks) in enumerate(parsed):
        times = np.array([t if t is not None else 0.0 for t, _ in blocks])
        wanted = requested_times(a.times) if a.times else sorted({times[0], times[-1]})
        if len(wanted) == 1:
            colors, styles = [None], ['-'] * n_series
            series_colors = qualitative_colors(n_series, 'curves')
        else:
            colors, styles = sequential_colors(len(wanted)), line_styles(n_series, 'runs x columns')
            series_colors = None
        for i, tw in enumerate(wanted):
            t, data = blocks[int(np.argmin(abs(times - tw)))]
            if abs(t - tw) > 1e-9 * max(1.0, abs(tw)):  # said, so that no one reads t = tw
                sys.stderr.write(f'{script_name()}: note: --times {tw:g}: {display_name(files[k])} '
                                 f'has no block there; the nearest, t = {t:g}, is drawn\n')
            x = column(columns, data, a.x, files[k])
            keep = np.ones_like(x, dtype=bool)
            if a.xmin is not None:
                keep &= x >= a.xmin
            if a.xmax is not None:
                keep &= x <= a.xmax
            for j, y in enumerate(a.y):
                v = column(columns, data, y, files[k])[keep]
                s = series + j
                # the legend names what tells the curves apart: the run, the column, the time
                parts = ([labels[k]] if len(a.files) > 1 else []) + (
                    [legend_name(y, params_list[k])] if len(a.y) > 1 else []) + [f't = {t:g} M']
                ax.plot(x[keep], abs(v) if a.logy else v, ls=styles[s],
                        color=series_colors[s] if series_colors else colors[i],
                        label=', '.join(parts))
        series += len(a.y)
    if a.logy:
        ax.set_yscale('log')
        ylabel = log_axis_label(a.y)
    else:
        ylabel = axis_label(a.y[0]) if len(a.y) == 1 else several_label(a.y)
    if a.logx:
        ax.set_xscale('log')
    finish(fig, ax, axis_label(a.x), ylabel, a.title, a.output, run_description(params_list))


if __name__ == '__main__':
    run_script(main)
