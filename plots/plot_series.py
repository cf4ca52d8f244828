#!/usr/bin/env python3
"""Plot columns of timeseries.dat against t, for one or several runs.

  plot_series.py RUN/timeseries.dat [MORE ...] -y H_L2_ext -y M_L2_ext --logy -o out.png
  gbssn1d ... ; cat RUN/timeseries.dat | plot_series.py - -y alpha_center -o lapse.png
"""
import argparse

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

from gbssn1d_data import axis_label, column, finish, parse, read_text, run_label, style


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+', help="timeseries.dat files ('-' for stdin)")
    ap.add_argument('-x', default='t', help='column for the x axis (default t)')
    ap.add_argument('-y', action='append', required=True, help='column(s) to plot')
    ap.add_argument('--logy', action='store_true')
    ap.add_argument('--label', action='append', help='legend label per file')
    ap.add_argument('--title', default='')
    ap.add_argument('-o', '--output', required=True, help='PNG file to write')
    a = ap.parse_args()
    style(plt)
    fig, ax = plt.subplots()
    for k, path in enumerate(a.files):
        columns, blocks = parse(read_text(path))
        data = blocks[0][1]
        label = a.label[k] if a.label and k < len(a.label) else run_label(path)
        for y in a.y:
            values = column(columns, data, y)
            ax.plot(column(columns, data, a.x), abs(values) if a.logy else values,
                    label=f'{label}: {y}' if len(a.files) > 1 or len(a.y) > 1 else label)
    if a.logy:
        ax.set_yscale('log')
    finish(fig, ax, axis_label(a.x), ', '.join(a.y), a.title, a.output)


if __name__ == '__main__':
    main()
