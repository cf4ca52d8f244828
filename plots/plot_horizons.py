#!/usr/bin/env python3
"""r_AH(t) (or another column of horizon.dat / timeseries.dat) for several runs in one PNG,
each labelled by the parameters recorded in its header.

  plot_horizons.py out/horizon/*/horizon.dat -o r_ah.png [--label-by rah0,rahA,N] [-y r_ah]
"""
import argparse

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

from gbssn1d_data import column, finish, parse, qualitative_colors, read_text, style


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
    ap.add_argument('--title', default='apparent-horizon coordinate radius')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    style(plt)
    fig, ax = plt.subplots()
    colors = qualitative_colors(len(a.files), 'runs')
    for color, path in zip(colors, a.files):
        text = read_text(path)
        params = header_params(text)
        columns, blocks = parse(text)
        data = blocks[0][1]
        label = ', '.join(f'{k}={params.get(k, "?")}' for k in a.label_by.split(','))
        line, = ax.plot(column(columns, data, 't'), column(columns, data, a.y), color=color,
                        label=label)
        if a.target and 'rah0' in params and float(params.get('rahA', 0)) != 0:
            ax.axhline(float(params['rah0']), color=line.get_color(), ls=':', lw=1)
    finish(fig, ax, 't / M', a.y, a.title, a.output)


if __name__ == '__main__':
    main()
