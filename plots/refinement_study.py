#!/usr/bin/env python3
"""Tables of runs/refinement.sh (docs/horizon-shift-study.md, Sec. 12).

  refinement_study.py onset DIR      onset of the blow-ups against N, the fitted slope of
                                     log t_onset against log N, and the predictions
  refinement_study.py converge DIR   RMS over time of H_L2_R and its orders
"""
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gbssn1d_data as data  # noqa: E402


def end_line(run):
    """(completed, t, r) from the last line of a run's timeseries.dat and its log."""
    log = data.read_text(run + '.log') if os.path.exists(run + '.log') else ''
    m = re.search(r'non-finite at t = ([0-9.e+-]+), r = ([0-9.e+-]+) in (\w+)', log)
    if m:
        return False, float(m.group(1)), float(m.group(2)), m.group(3)
    return 'reached t' in log, None, None, None


def onset(out):
    print('| grid | N | spacing near the puncture | published (upwind-gd) | default (matched) |')
    print('|---|---|---|---|---|')
    fits = {}
    for grid, keys in [('sinh', [800, 1200, 1600, 2400, 3200]), ('uniform', [16, 32, 64])]:
        for key in keys:
            cells = []
            for st in ['upwind-gd', 'matched']:
                name = f'{grid}-{st}-N{key}' if grid == 'sinh' else f'{grid}-{st}-M{key}'
                ok, t, r, var = end_line(os.path.join(out, name))
                cells.append('runs to 6M' if ok else f'non-finite at t = {t:.3g}M, r = {r:.3g}M ({var})'
                             if t is not None else 'failed otherwise')
                if st == 'upwind-gd' and t is not None:
                    n = key if grid == 'sinh' else 200 * key
                    fits.setdefault(grid, []).append((n, t))
            spacing = f'M/{key * 0.05 * 400 / 400 * 1:.0f}' if False else (
                f'M/{key / 400 * 50:.0f}' if grid == 'sinh' else f'M/{key}')
            n = key if grid == 'sinh' else 200 * key
            print(f'| {grid} | {n} | {spacing} | {cells[0]} | {cells[1]} |')
    for grid, pts in fits.items():
        if len(pts) >= 2:
            x = np.log([p[0] for p in pts])
            y = np.log([p[1] for p in pts])
            slope = np.polyfit(x, y, 1)[0]
            print(f'{grid}: slope of log t_onset against log N = {slope:.2f} over N = '
                  f'{", ".join(str(p[0]) for p in pts)} (-1: onset proportional to the spacing)')
    print('\nmeasured in the sinh runs: the largest 6th difference of B (its grid-scale part), '
          'its e-folding rate over the last 0.3 M before the blow-up, and where it sits:')
    for n in [1200, 1600, 2400, 3200]:
        path = os.path.join(out, f'sinh-upwind-gd-N{n}', 'profiles.dat')
        if not os.path.exists(path):
            continue
        columns, blocks = data.parse(data.read_text(path), path)
        amp = []
        for t, d in blocks:
            B = d[:, columns.index('B')]
            d6 = np.abs(np.convolve(B, [1, -6, 15, -20, 15, -6, 1], 'same')) / 64
            d6[:8] = 0  # the origin's parity ghosts and the outer boundary
            d6[-8:] = 0
            if np.all(np.isfinite(d6)):
                amp.append((t, d6.max(), d[d6.argmax(), columns.index('r')]))
        last = [a for a in amp if a[0] >= amp[-1][0] - 0.3 - 1e-9][:-1] or amp[-2:]
        rate = np.polyfit([a[0] for a in last], np.log([a[1] for a in last]), 1)[0]
        print(f'  N = {n}: rate {rate:.3g}/M at r = {last[-1][2]:.3g}M (t = {last[0][0]:.3g} to {last[-1][0]:.3g}M)')
    pred = os.path.join(out, 'predicted.txt')
    if os.path.exists(pred):
        print('\npredicted by docs/hyperbolicity.py (spacing factor, t_onset, radius of the '
              'largest rate, rate):')
        print(data.read_text(pred).rstrip())


def rms_H(run):
    s = data.series(os.path.join(run, 'timeseries.dat'))
    if s is None or len(s['t']) < 2:
        return None
    ok, *_ = end_line(run)
    if not ok:
        return None
    v = s['H_L2_R'][1:]  # t > 0
    return math.sqrt(float(np.mean(v * v)))


def converge(out):
    families = sorted({re.sub(r'-N\d+$|-M\d+$', '', os.path.basename(p))
                       for p in glob.glob(os.path.join(out, '*')) if os.path.isdir(p)})
    print('| family | RMS over time of H_L2_R, coarse to fine | orders | lowest above 10 x floor '
          '| standard gauge (its finest: the floor) |')
    print('|---|---|---|---|---|')
    worst = []
    for fam in families:
        runs = [p for p in glob.glob(os.path.join(out, fam + '-[NM]*')) if os.path.isdir(p)]
        runs.sort(key=lambda p: int(re.findall(r'\d+$', p)[0]))
        vals = [rms_H(r) for r in runs]
        std = re.sub(r'(^|-)h[0-9.]+-', r'\1h0-', fam)
        std_vals = [rms_H(os.path.join(out, std + '-' + os.path.basename(r).split('-')[-1])) for r in runs]
        text = ', '.join('stopped' if v is None else f'{v:.3g}' for v in vals)
        orders = []
        # the resolutions from the names (N or M/spacing): orders for any ratio, not only 2
        res = [int(re.findall(r'\d+$', r)[0]) for r in runs]
        for (a, b, na, nb) in zip(vals, vals[1:], res, res[1:]):
            orders.append('-' if a is None or b is None or b <= 0
                          else f'{math.log(a / b) / math.log(nb / na):.2f}')
        stdtext = ', '.join('-' if v is None else f'{v:.3g}' for v in std_vals)
        # the round-off floor: the standard gauge's value at the family's finest resolution;
        # a pair is judged while its finer member stays above 10 x that floor
        floor = std_vals[-1] if std_vals and std_vals[-1] is not None else 0.0
        judged = [float(o) for o, b in zip(orders, vals[1:]) if o != '-' and b > 10 * floor]
        verdict = f'{min(judged):.2f}' if judged else '-'
        stopped = sum(v is None for v in vals)
        print(f'| {fam} | {text} | {", ".join(orders)} | {verdict} | {stdtext} |')
        if stopped:
            print(f'  ({stopped} member(s) of {fam} stopped)')
        for o in judged:
            worst.append((o, fam))
    if worst:
        low = sorted(worst)[:5]
        print('\nlowest judged orders (finer member above 10 x the floor): '
              + '; '.join(f'{o:.2f} ({f})' for o, f in low))


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ('onset', 'converge'):
        sys.exit(__doc__)
    out = sys.argv[2]
    if not os.path.isdir(out):
        raise data.DataError('no such folder' if not os.path.exists(out)
                             else 'is not a folder (a runs/refinement.sh output folder)', out)
    {'onset': onset, 'converge': converge}[sys.argv[1]](out)


if __name__ == '__main__':
    data.run_script(main)
