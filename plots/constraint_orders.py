#!/usr/bin/env python3
"""Convergence of a constraint norm over time from runs of one configuration at increasing N.

  constraint_orders.py A/timeseries.dat B/timeseries.dat C/timeseries.dat [-y H_L2_ext]
      [--times 5,10,20,50,100] [-o orders.png]

For a quantity whose exact value is zero the order between resolutions N1 < N2 is
p = ln(E1/E2) / ln(N2/N1) (equations document, Sec. 15); N is read from each file's header.
The runs must be one configuration (every header parameter but N, the output cadence, tmax and
what follows from N the same; otherwise refused, naming the flags and files, exit 2). Rows are
paired by time: the times all runs have (matched within 1e-6 of the smallest output
step), so runs of different --dt-series or tmax compare at the same times; runs that share no
time are refused. Prints how many common times there are, the norms and the pairwise orders at
the chosen times; with -o also draws the norms
against t with the Richardson-scaled finer norms dashed (top: at order --scale they lie on the
coarsest curve) and the pairwise orders against t (bottom). Works on `gbssn1d converge`
output: constraint_orders.py OUT/N*/timeseries.dat.
"""
import argparse
import math

import numpy as np

from gbssn1d_data import (DataError, axis_label, column, common_params, header_params, parse,
                          read_text, require_one_configuration, run_description, run_script,
                          sequential_colors, set_titles, style, save_figure)


def common_rows(runs, paths):
    """The times every run has (within 1e-6 of the smallest output step) and each run's values
    there: runs of other output steps (--dt-series) or lengths are paired by time, not by row.
    Refuses runs that share no time, naming their files."""
    steps = [np.min(np.diff(t)) for t, _ in runs if len(t) > 1]
    positive = [step for step in steps if step > 0]
    scale = min(positive) if positive else max(1.0, max(abs(t[0]) for t, _ in runs if len(t)))
    tol = 1e-6 * scale
    t0 = runs[0][0]
    keep = np.ones(len(t0), dtype=bool)
    picks = []
    for t, _ in runs:
        if len(t) == 0:
            keep[:] = False
            picks.append(np.zeros(len(t0), dtype=int))
            continue
        i = np.clip(np.searchsorted(t, t0), 1, max(len(t) - 1, 1))
        lower = np.clip(i - 1, 0, len(t) - 1)
        upper = np.clip(i, 0, len(t) - 1)
        nearest = np.where(np.abs(t[lower] - t0) <= np.abs(t[upper] - t0), lower, upper)
        keep &= np.abs(t[nearest] - t0) <= tol
        picks.append(nearest)
    if not keep.any():
        raise SystemExit('no times common to all runs (paired within '
                         f'{tol:.3g} of each other): ' + ', '.join(paths))
    return t0[keep], [e[pick[keep]] for (_, e), pick in zip(runs, picks)], tol


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+')
    ap.add_argument('-y', default='H_L2_ext')
    ap.add_argument('--times', default='5,10,20,30,50,75,100')
    ap.add_argument('--scale', type=float, default=4.0,
                    help='also draw each finer norm times (N/N_coarsest)^scale, dashed (0: off)')
    ap.add_argument('--title', default='',
                    help='title; what was run (from the headers) is written below it, or is '
                         'the title without one')
    ap.add_argument('-o', '--output')
    a = ap.parse_args()
    runs, params_list = [], []
    for path in a.files:
        text = read_text(path)
        columns, blocks = parse(text, path)
        params_list.append(header_params(text))
        try:
            n = int(params_list[-1]['N'])
        except (KeyError, ValueError):
            raise DataError('no N (a whole number) in the header', path) from None
        data = blocks[0][1]
        runs.append((n, column(columns, data, 't', path), column(columns, data, a.y, path), path))
    require_one_configuration(params_list, a.files)
    runs.sort(key=lambda run: run[0])
    t, E, tol = common_rows([(run[1], run[2]) for run in runs], [run[3] for run in runs])
    Ns = [run[0] for run in runs]
    orders = [np.log(E[k] / E[k + 1]) / math.log(Ns[k + 1] / Ns[k]) for k in range(len(runs) - 1)]
    print(f'# {a.y} at N = {" ".join(map(str, Ns))} and pairwise orders')
    print(f'# rows paired by time: {len(t)} times common to all {len(runs)} runs (of '
          f'{", ".join(str(len(run[1])) for run in runs)} rows; matched within {tol:.3g})')
    print('# t ' + ' '.join(f'{a.y}_N{n}' for n in Ns) + ' ' +
          ' '.join(f'p_{Ns[k]}_{Ns[k + 1]}' for k in range(len(Ns) - 1)))
    for tw in [float(v) for v in a.times.split(',')]:
        if tw > t[-1] + 1e-9:
            continue  # past the end of the shortest run
        i = int(np.argmin(abs(t - tw)))
        print(f'{t[i]:g} ' + ' '.join(f'{e[i]:.3e}' for e in E) + ' ' +
              ' '.join(f'{o[i]:.2f}' for o in orders))
    if a.output:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        style(plt)
        fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
        colors = sequential_colors(len(Ns))  # darker is finer
        for k, (n, e) in enumerate(zip(Ns, E)):
            line, = ax1.semilogy(t, e, color=colors[k], label=f'N = {n}')
            if a.scale and k > 0:
                ax1.semilogy(t, e * (n / Ns[0]) ** a.scale, ls='--', color=line.get_color(),
                             label=f'N = {n}, times ({n}/{Ns[0]})^{a.scale:g}')
        shared = common_params(params_list)
        ax1.set_ylabel(axis_label(a.y, shared), fontsize=10)
        ax1.legend(fontsize=8)
        set_titles(fig, ax1, a.title, run_description(params_list))
        for k, o in enumerate(orders):
            ax2.plot(t, o, color=colors[k + 1], label=f'p({Ns[k]}, {Ns[k + 1]})')
        design = float(shared.get('fd-order', 4))
        ax2.axhline(design, color='k', ls=':', lw=1,
                    label=f"the scheme's order, {design:g}")
        ax2.set_ylim(0, max(6, design + 2))
        ax2.set_ylabel('convergence order p')
        ax2.set_xlabel('t / M')
        ax2.legend(fontsize=8)
        fig.tight_layout()
        save_figure(fig, a.output)


if __name__ == '__main__':
    run_script(main)
