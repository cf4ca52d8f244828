#!/usr/bin/env python3
"""The held h_AH's excess of H along each axis, with fits and the crossing (runs/hold-scaling.sh).

    /usr/bin/python3 plots/hold_scaling.py OUT N:CFL:A:T [N:CFL:A:T ...]

For each N:CFL:A:T, OUT/held-N<N>-cfl<CFL>-A<A>-T<T>/ is the published configuration with h_AH
held T apart (--ah-interval T) and OUT/smooth-N<N>-cfl<CFL>-A<A>/ the same with one smooth
h_AH(t). Both RMS values are of H_L2_R over the output times in (0, 20] M; the excess is
sqrt(RMS_held^2 - RMS_smooth^2) (0 where the held run is not above the smooth one).

Writes OUT/scaling.dat (named columns, numbers only: numpy.genfromtxt(..., names=True) reads
it), prints the table, the power-law fits along each axis (everything else held fixed) and the
spacing at which the excess overtakes the smooth run's truncation error, and draws
OUT/scaling.png.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gbssn1d_data as gd  # noqa: E402

WINDOW = (0.0, 20.0)
NORM = 'H_L2_R'


def rms_of(path):
    s = gd.series(os.path.join(path, 'timeseries.dat'))
    if s is None:
        raise gd.DataError('no timeseries.dat (the run did not complete)', path)
    if NORM not in s:
        raise gd.DataError(f"no column '{NORM}'", os.path.join(path, 'timeseries.dat'))
    t, h = s['t'], s[NORM]
    inside = (t > WINDOW[0]) & (t <= WINDOW[1] + 1e-9)
    if inside.sum() < 10:
        raise gd.DataError(f'fewer than 10 output times in {WINDOW}', path)
    if not np.all(np.isfinite(h[inside])):
        raise gd.DataError(f'{NORM} is not finite in {WINDOW}', path)
    return float(np.sqrt(np.mean(h[inside] ** 2)))


def slope(x, y):
    """The least-squares exponent p of y ~ x^p, or nan for fewer than two positive points."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    keep = (x > 0) & (y > 0)
    if keep.sum() < 2:
        return math.nan
    return float(np.polyfit(np.log(x[keep]), np.log(y[keep]), 1)[0])


def main(out, *specs):
    if not specs:
        raise SystemExit('usage: hold_scaling.py OUT N:CFL:A:T [N:CFL:A:T ...]')
    rows = []
    for spec in specs:
        try:
            N, cfl, A, T = spec.split(':')
            values = (int(N), float(cfl), float(A), float(T))
        except ValueError:
            raise gd.DataError('not N:CFL:A:T', spec) from None
        held = rms_of(os.path.join(out, f'held-N{N}-cfl{cfl}-A{A}-T{T}'))
        smooth = rms_of(os.path.join(out, f'smooth-N{N}-cfl{cfl}-A{A}'))
        excess = math.sqrt(max(held * held - smooth * smooth, 0.0))
        rows.append(values + (held, smooth, excess))
    rows = sorted(set(rows))
    columns = ['N', 'dr_min', 'cfl', 'rahA', 'T', 'rms_H_held', 'rms_H_smooth', 'excess']
    table = os.path.join(out, 'scaling.dat')
    with open(table, 'w') as f:
        f.write('# ' + ' '.join(columns) + '\n')
        f.write(f'# excess = sqrt(rms_H_held^2 - rms_H_smooth^2), RMS of {NORM} over t in '
                f'({WINDOW[0]:g}, {WINDOW[1]:g}] M; dr_min = 1/(N/2) M (7 boxes, rmax 128 M)\n')
        for N, cfl, A, T, held, smooth, excess in rows:
            f.write(f'{N} {2.0 / N:.6g} {cfl:g} {A:g} {T:g} {held:.6e} {smooth:.6e} '
                    f'{excess:.6e}\n')
    print(f'{"N":>4} {"dr_min":>8} {"cfl":>7} {"A":>5} {"T":>4} {"RMS H held":>11} '
          f'{"RMS H smooth":>12} {"excess":>10}')
    for N, cfl, A, T, held, smooth, excess in rows:
        print(f'{N:4d} M/{N // 2:<6d} {cfl:7g} {A:5g} {T:4g} {held:11.3e} {smooth:12.3e} '
              f'{excess:10.3e}')

    def axis(vary, fixed):
        """(x, excess, smooth) of the rows whose other values equal `fixed`."""
        index = {'N': 0, 'cfl': 1, 'A': 2, 'T': 3}
        pts = [r for r in rows
               if all(r[index[k]] == v for k, v in fixed.items())]
        pts.sort(key=lambda r: r[index[vary]])
        return ([r[index[vary]] for r in pts], [r[6] for r in pts], [r[5] for r in pts])

    print('\nexponents p of excess ~ x^p, everything else held fixed:')
    fits = {}
    for label, vary, fixed, x_of in [
            ('hold T (N = 64, cfl 0.25, A = 0.5)', 'T', {'N': 64, 'cfl': 0.25, 'A': 0.5}, None),
            ('strength A (N = 64, cfl 0.25, T = 1)', 'A', {'N': 64, 'cfl': 0.25, 'T': 1.0}, None),
            ('cfl at N = 64 (T = 1, A = 0.5)', 'cfl', {'N': 64, 'A': 0.5, 'T': 1.0}, None),
            ('cfl at N = 128 (T = 1, A = 0.5)', 'cfl', {'N': 128, 'A': 0.5, 'T': 1.0}, None),
            ('spacing dr at cfl 0.25 (T = 1, A = 0.5)', 'N', {'cfl': 0.25, 'A': 0.5, 'T': 1.0},
             lambda n: 2.0 / n),
            ('spacing dr at cfl 0.25 (T = 4, A = 0.5)', 'N', {'cfl': 0.25, 'A': 0.5, 'T': 4.0},
             lambda n: 2.0 / n)]:
        x, e, s = axis(vary, fixed)
        if len(x) < 2:
            continue
        xs = [x_of(v) for v in x] if x_of else x
        fits[label] = (xs, e, s)
        print(f'  {label}: p = {slope(xs, e):.2f} over {", ".join(f"{v:g}" for v in x)} '
              f'({", ".join(f"{v:.2e}" for v in e)})')
        if vary == 'N':
            print(f'    the smooth run\'s RMS H there: p = {slope(xs, s):.2f} '
                  f'({", ".join(f"{v:.2e}" for v in s)})')
#where the excess overtakes the smooth run's truncation error: the first spacing
#(coarse to fine) at which excess >= smooth
            cross = [(n, ee, ss) for n, ee, ss in zip(x, e, s) if ee >= ss]
            if cross:
                n, ee, ss = cross[0]
                print(f'    the excess reaches the smooth run\'s error first at N = {n} '
                      f'(M/{n // 2}): {ee:.2e} >= {ss:.2e}')
            else:
                print('    the excess stays below the smooth run\'s error at every N measured')

    print('\nthe published spacings: pairwise orders of the RMS of H over (0, 20] M '
          '(below 2.5: the pair does not converge at the design order 4)')
    for cfl in sorted({r[1] for r in rows}):
        for T in sorted({r[3] for r in rows}):
            pts = sorted((r for r in rows if r[0] in (24, 32, 48) and r[1] == cfl
                          and r[2] == 0.5 and r[3] == T), key=lambda r: r[0])
            if len(pts) < 2:
                continue
            def orders(k):
                return ', '.join(f'{math.log(a[k] / b[k]) / math.log(b[0] / a[0]):.2f}'
                                 for a, b in zip(pts, pts[1:]))
            spacings = ', '.join(f'M/{r[0] // 2}' for r in pts)
            print(f'  cfl {cfl:g}, T = {T:g} M ({spacings}): held {orders(4)}; '
                  f'smooth {orders(5)}')

    plt = gd.pyplot()
    fig, axes = plt.subplots(1, 4, figsize=(14, 3.8))
#each panel with the model's slope (study doc Sec. 13.1: excess ~ A T^(1/2) cfl^2 dr^0)
    panels = [('hold T (N = 64, cfl 0.25, A = 0.5)', 'hold T / M', 0.5),
              ('strength A (N = 64, cfl 0.25, T = 1)', 'A', 1.0),
              ('cfl at N = 64 (T = 1, A = 0.5)', 'Courant number (N = 64 and 128)', 2.0),
              ('spacing dr at cfl 0.25 (T = 1, A = 0.5)', 'finest spacing / M', 0.0)]
    for ax, (label, xlabel, model) in zip(axes, panels):
        if label not in fits:
            continue
        xs, e, s = fits[label]
        ax.loglog(xs, e, 'o-', color=gd.QUALITATIVE[0], label='excess (held)')
        middle = len(xs) // 2
        guide = [e[middle] * (x / xs[middle]) ** model for x in xs]
        ax.loglog(xs, guide, ':', color='0.4', label=f'model: slope {model:g}')
        if label.startswith('cfl'):
            xs2, e2, _ = fits.get('cfl at N = 128 (T = 1, A = 0.5)', ([], [], []))
            if xs2:
                ax.loglog(xs2, e2, 's--', color=gd.QUALITATIVE[0], label='excess, N = 128')
        if label.startswith('spacing'):
            ax.loglog(xs, s, 'o-', color=gd.QUALITATIVE[1], label='smooth run (truncation)')
            xs4, e4, _ = fits.get('spacing dr at cfl 0.25 (T = 4, A = 0.5)', ([], [], []))
            if xs4:
                ax.loglog(xs4, e4, 's--', color=gd.QUALITATIVE[2], label='excess, T = 4 M')
        ax.set_xticks(xs)
        ax.set_xticklabels([f'{x:g}' if x >= 0.01 else f'{x:.2g}' for x in xs], fontsize=7,
                           rotation=45)
        ax.minorticks_off()
        ax.set_xlabel(xlabel)
        ax.set_title(f'p = {slope(xs, e):.2f}', fontsize=9)
        ax.legend(fontsize=7)
    axes[0].set_ylabel(f'RMS of {NORM} over (0, 20] M')
    fig.suptitle('h_AH held T apart, quadratic time interpolation on subcycled boxes: '
                 'the excess of H over one smooth h_AH(t)', fontsize=10)
    fig.tight_layout()
    gd.save_figure(fig, os.path.join(out, 'scaling.png'))


if __name__ == '__main__':
    gd.run_script(main, *sys.argv[1:2], *sys.argv[2:])
