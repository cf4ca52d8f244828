#!/usr/bin/env python3
"""Z4c against BSSN over long runs (docs/z4c-study.md), from gbssn1d run folders.

  z4c_study.py table BASE RUN [RUN ...] [--t0 100 --t1 1000]
  z4c_study.py figure BASE RUN [RUN ...] [--t0 100 --t1 1000] -o figure.png
  z4c_study.py mass RUN [RUN ...] [--times 100,300,500,1000]

BASE and each RUN are folders with timeseries.dat (an evolve --out, or a sweep's member).
`table` prints a row per run:
  - t_end: the run's last time (a run that stopped early says so: its numbers cover less);
  - H_rms: the RMS over t in [t0, t1] of H_L2_R (areal window, the same place in every gauge);
  - M_max: the largest |M_AH - M| over t in [t0, t1];
  - Theta_rms: the RMS of Theta_L2_R (Z4c only; '-' for BSSN);
  - H_ratio, M_ratio: H_rms and M_max over BASE's (below 1: better than BASE).
`figure` draws H_L2_R and |M_AH - M| against t, BASE dashed, one curve per run.
`mass` prints, for each run (BASE is the first), the Misner-Sharp mass m_ms - M (profiles.dat)
at the areal radii 1.6, 2, 3, 10, 30, 100, 300 M (the nearest point of each profile block) at
the --times (default 100, 300, 500, 1000): where the mass a run gains is made and how it spreads.
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
    # how the run ended: '# end: completed at t = T' (its own tmax) or '# end: stopped: ...'
    ends = [line for line in text.splitlines() if line.startswith('# end: ')]
    params['end'] = ends[-1][len('# end: '):] if ends else 'no end line (still running, or cut short)'
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
    if f != 'z4c':
        return f
    return f + f' kappa1={params.get("kappa1")}' + f' hole={params.get("kappa1-hole", 0)}'


MASS_RADII = (1.6, 2.0, 3.0, 10.0, 30.0, 100.0, 300.0)
MASS_TIMES = (100.0, 300.0, 500.0, 1000.0)


def mass(runs, times=MASS_TIMES):
    """m_ms - M at MASS_RADII and `times`, from each run's profiles.dat."""
    print('# run t ' + ' '.join(f'R={R:g}' for R in MASS_RADII) + '  (m_ms - M)')
    for folder in runs:
        path = os.path.join(folder, 'profiles.dat')
        text = read_text(path)
        params = header_params(text)
        M = float(params.get('M', 1.0))
        columns = None
        blocks, t, rows = {}, None, []
        for line in text.splitlines():
            if line.startswith('# t = '):
                if t is not None and rows:
                    blocks[t] = np.array(rows)
                t, rows = float(line.split('=')[1].split()[0]), []
            elif line.startswith('# ') and columns is None and ' m_ms ' in line + ' ':
                columns = line[2:].split()
            elif line.strip() and not line.startswith('#') and t is not None:
                rows.append([float(x) for x in line.split()])
        if t is not None and rows:
            blocks[t] = np.array(rows)
        if columns is None or 'm_ms' not in columns or 'R_areal' not in columns:
            raise DataError('no m_ms or R_areal column', path)
        iR, im = columns.index('R_areal'), columns.index('m_ms')
        name = os.path.basename(os.path.normpath(folder))
        for tq in times:
            if tq not in blocks:
                raise DataError(f'no profile block at t = {tq:g}', path)
            b = blocks[tq]
            values = [b[int(np.argmin(np.abs(b[:, iR] - R))), im] - M for R in MASS_RADII]
            print(f'{name} {tq:g} ' + ' '.join(f'{v:+.2e}' for v in values))


def ratio(x, base):
    """x / base, or '-' where the base is 0 or not a number (no ratio to state)."""
    return f'{x / base:.3g}' if base > 0 and math.isfinite(base) and math.isfinite(x) else '-'


def table(base, runs, t0, t1):
    b = load(base)
    bH, bM, _, _ = summary(b[2], t0, t1)
    print(f'# base: {b[0]} ({describe(b[1])}); window t in [{t0}, {t1}]')
    print('# run formulation t_end H_rms H_ratio M_max M_ratio Theta_rms')
    for name, params, s in [b] + [load(r) for r in runs]:
        H, M, theta, t_end = summary(s, t0, t1)
        notes = ''
        if not params['end'].startswith('completed'):
            notes += f' ({params["end"]})'  # stopped by itself, or no end line
        elif t_end < t1:
            notes += f' (the run ends at t = {t_end:g}, before the window does)'
        if not window(s, t0, t1).any():
            notes += ' (no time in the window: no numbers)'
        elif H == 0.0:  # the norm of an empty window: no point of the outer sheet in it
            notes += ' (H_L2_R = 0: the areal window held no point)'
        th = f'{theta:.3e}' if theta is not None else '-'
        print(f'{name} {describe(params).replace(" ", ",")} {t_end:g} {H:.3e} {ratio(H, bH)} '
              f'{M:.3e} {ratio(M, bM)} {th}{notes}')


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
    ap.add_argument('what', choices=['table', 'figure', 'mass'])
    ap.add_argument('base')
    ap.add_argument('runs', nargs='*')
    ap.add_argument('--t0', type=float, default=100.0)
    ap.add_argument('--t1', type=float, default=1000.0)
    ap.add_argument('-o', '--output')
    ap.add_argument('--times', default='100,300,500,1000',
                    help='mass: the profile times, comma-separated')
    a = ap.parse_args()
    if a.what != 'mass' and not a.runs:
        ap.error(f'{a.what} needs a RUN besides BASE')
    if not (math.isfinite(a.t0) and math.isfinite(a.t1) and a.t0 < a.t1):
        ap.error(f'--t0 {a.t0:g} --t1 {a.t1:g}: the window needs t0 < t1, both finite')
    if a.what == 'mass':
        try:
            times = tuple(float(x) for x in a.times.split(','))
        except ValueError:
            ap.error(f'--times {a.times!r}: not a comma-separated list of numbers')
        mass([a.base] + a.runs, times)
    elif a.what == 'table':
        table(a.base, a.runs, a.t0, a.t1)
    else:
        if not a.output:
            ap.error('figure needs -o FILE.png')
        figure(a.base, a.runs, a.t0, a.t1, a.output)


if __name__ == '__main__':
    run_script(main)
