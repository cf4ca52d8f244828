#!/usr/bin/env python3
"""Plot columns of timeseries.dat (or of any output table: horizon.dat, a sweep's
summary.dat) against t or another column, for one or several runs.

  plot_series.py RUN/timeseries.dat [MORE ...] -y H_L2_ext -y M_L2_ext --logy -o out.png
  gbssn1d ... ; cat RUN/timeseries.dat | plot_series.py - -y alpha_center -o lapse.png
  plot_series.py SWEEP/summary.dat -x rah0 -y M_ah_err_max --logy --points -o drift.png

With --logy the absolute values are plotted (the axis says |y|). Axes name the columns in words
with units; the title says what was run and the legend what tells the runs apart, both from
the files' headers (--title and --label take precedence). For r_AH of a run with the horizon
shift on, its target h (rah0) is drawn dotted.
"""
import argparse
import sys

import numpy as np

from gbssn1d_data import (axis_label, column, common_params, finish, header_params, legend_name,
                          line_styles, log_axis_label, parse_table, pyplot, qualitative_colors,
                          read_text, run_description, run_labels, run_script,
                          sequential_colors, several_label, shifted)


def sweep_line(text):
    """A sweep summary's '# sweep over ...' line (it has no run parameters), or ''."""
    return next((l[2:] for l in text.splitlines() if l.startswith('# sweep over')), '')


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
    ap.add_argument('--label', action='append',
                    help='legend label per file (default: the parameters that tell the runs '
                         'apart, from the headers)')
    ap.add_argument('--title', default='',
                    help='title; what was run (from the headers) is written below it, or is '
                         'the title without one')
    ap.add_argument('-o', '--output', required=True, help='PNG file to write')
    a = ap.parse_args()
    texts = [read_text(path) for path in a.files]
    tables = [parse_table(text, path) for path, text in zip(a.files, texts)]
    params_list = [header_params(text) for text in texts]
    shared = common_params(params_list)
    labels = run_labels(a.files, params_list, a.label)
    plt = pyplot()
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
    targets = {}  # the horizon shift's target h: {h: colours of the runs aiming at it}
    for k, (path, (columns, data), params) in enumerate(zip(a.files, tables, params_list)):
        for j, y in enumerate(a.y):
            values = column(columns, data, y, path)
            if not np.isfinite(values).any():
                sys.stderr.write(f'note: {path}: {y} has no finite value; nothing to draw\n')
            color = column_colors[j] if column_colors else colors[k]
            if len(a.y) == 1:
                label = labels[k]
            else:
                label = (f'{labels[k]}: ' if len(a.files) > 1 else '') + legend_name(y, params)
            ax.plot(column(columns, data, a.x, path), abs(values) if a.logy else values, color=color,
                    ls='none' if a.points else styles[j], marker='o' if a.points else None,
                    label=label)
            if y == 'r_ah' and a.x == 't' and shifted(params) and 'rah0' in params:
                targets.setdefault(float(params['rah0']), set()).add(color)
    for h, run_colors in sorted(targets.items()):
        ax.axhline(h, ls=':', lw=1.2, label=f'target h = {h:g} M',
                   color='black' if len(a.files) == 1 else
                   run_colors.pop() if len(run_colors) == 1 else 'dimgray')
    if a.logy:
        ax.set_yscale('log')
        ylabel = log_axis_label(a.y, shared)
    else:
        ylabel = axis_label(a.y[0], shared) if len(a.y) == 1 else several_label(a.y, shared)
    description = run_description(params_list) or sweep_line(texts[0])
    finish(fig, ax, axis_label(a.x, shared), ylabel, a.title, a.output, description)


if __name__ == '__main__':
    run_script(main)
