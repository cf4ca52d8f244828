#!/usr/bin/env python3
"""Z4c against BSSN over long runs (docs/z4c-study.md), from gbssn1d run folders.

  z4c_study.py table BASE RUN [RUN ...] [--t0 100 --t1 1000]
  z4c_study.py figure BASE RUN [RUN ...] [--t0 100 --t1 1000] -o figure.png

BASE and each RUN are folders with timeseries.dat (an evolve --out, or a sweep's member).
`table` prints a row per run:
  - t_end: the run's last time (a run that stopped early says so: its numbers cover less);
  - H_rms: the RMS over t in [t0, t1] of H_L2_R (areal window, the same place in every gauge);
  - M_max: the largest |M_AH - M| over t in [t0, t1];
  - Theta_rms: the RMS of Theta_L2_R (Z4c only; '-' for BSSN);
  - H_ratio, M_ratio: H_rms and M_max over BASE's (below 1: better than BASE).
`figure` draws H_L2_R and |M_AH - M| against t, BASE dashed, one curve per run.
"""
import argparse
import math
import os

import numpy as np

from gbssn1d_data import DataError, header_params, parse_table, pyplot, read_text, run_script


def load(folder):
    """(name, params, {column: values}) of a run folder's timeseries.dat."""
    path = os.path.join(folder, 'timeseries.dat')
    text = read_text(path)
    columns, data = parse_table(text, path)
    for c in ('t', 'H_L2_R', 'M_ah_err'):
        if c not in columns:
            raise DataError(f'no column {c}', path)
    if data.size == 0:
        raise DataError('no rows', path)
    params = header_params(text)
    return os.path.basename(os.path.normpath(folder)), params, \
        {c: data[:, i] for i, c in enumerate(columns)}


def window(s, t0, t1):
    return (s['t'] >= t0) & (s['t'] <= t1)


def summary(s, t0, t1):
    w = window(s, t0, t1)
    rms = lambda v: math.sqrt(float(np.mean(v[w] ** 2))) if w.any() else math.nan
    m = float(np.max(np.abs(s['M_ah_err'][w]))) if w.any() else math.nan
    theta = rms(s['Theta_L2_R']) if 'Theta_L2_R' in s else None
    return rms(s['H_L2_R']), m, theta, float(s['t'][-1])


def describe(params):
    f = params.get('formulation', 'bssn')
    return f + (f' kappa1={params.get("kappa1")}' if f == 'z4c' else '')


def table(base, runs, t0, t1):
    b = load(base)
    bH, bM, _, _ = summary(b[2], t0, t1)
    print(f'# base: {b[0]} ({describe(b[1])}); window t in [{t0}, {t1}]')
    print('# run formulation t_end H_rms H_ratio M_max M_ratio Theta_rms')
    for name, params, s in [b] + [load(r) for r in runs]:
        H, M, theta, t_end = summary(s, t0, t1)
        stopped = '' if t_end >= t1 else f' (stopped at t = {t_end:g})'
        if H == 0.0:  # the norm of an empty window: no point of the outer sheet in it
            stopped += ' (H_L2_R = 0: the areal window held no point)'
        th = f'{theta:.3e}' if theta is not None else '-'
        print(f'{name} {describe(params).replace(" ", ",")} {t_end:g} {H:.3e} {H / bH:.3g} '
              f'{M:.3e} {M / bM:.3g} {th}{stopped}')


def figure(base, runs, t0, t1, output):
    loaded = [load(base)] + [load(r) for r in runs]
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for k, (name, params, s) in enumerate(loaded):
        style = '--' if k == 0 else '-'
        label = f'{name} ({describe(params)})'
        axes[0].semilogy(s['t'], np.abs(s['H_L2_R']), style, label=label)
        axes[1].semilogy(s['t'], np.abs(s['M_ah_err']), style, label=label)
    axes[0].set_ylabel('H_L2_R (areal window)')
    axes[1].set_ylabel('|M_AH - M|')
    for ax in axes:
        ax.set_xlabel('t / M')
        ax.axvspan(t0, t1, color='0.9', zorder=0)
    axes[1].legend(fontsize=7)
    fig.suptitle(f'Z4c against BSSN ({loaded[0][0]} dashed); window [{t0}, {t1}] shaded',
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(output)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('what', choices=['table', 'figure'])
    ap.add_argument('base')
    ap.add_argument('runs', nargs='+')
    ap.add_argument('--t0', type=float, default=100.0)
    ap.add_argument('--t1', type=float, default=1000.0)
    ap.add_argument('-o', '--output')
    a = ap.parse_args()
    if a.what == 'table':
        table(a.base, a.runs, a.t0, a.t1)
    else:
        if not a.output:
            ap.error('figure needs -o FILE.png')
        figure(a.base, a.runs, a.t0, a.t1, a.output)


if __name__ == '__main__':
    run_script(main)
