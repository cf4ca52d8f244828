#!/usr/bin/env python3
"""Compare the lapse of an evolution with the stationary 1+log trumpet as functions of the
areal radius (a coordinate-independent comparison), at the last (or a chosen) time.

  compare_trumpet.py RUN/profiles.dat TRUMPET/profiles.dat [--time T] [-o alpha_vs_R.png]

TRUMPET is a `gbssn1d evolve --id 1log-trumpet --tmax 0` output on a fine grid; its alpha(R)
is interpolated (cubic) at the run's areal radii. Prints max |alpha - alpha_trumpet| in bands
of R and max |d_t alpha| is in the run's timeseries.dat (column dtalpha_max_ext).
"""
import argparse

import numpy as np

from gbssn1d_data import (column, header_params, parse, read_text, run_description, run_script,
                          set_titles, style, save_figure)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('run')
    ap.add_argument('trumpet')
    ap.add_argument('--time', type=float, help='time of the run to compare (default: last)')
    ap.add_argument('--rmin', type=float, default=0.05, help='ignore r below this (puncture)')
    ap.add_argument('-o', '--output', help='PNG of alpha(R) and the difference')
    ap.add_argument('--title', help='default: the lapse at the time compared against the '
                                    'trumpet; what was run is written below it')
    a = ap.parse_args()
    cols_t, blocks_t = parse(read_text(a.trumpet), a.trumpet)
    Rt = column(cols_t, blocks_t[0][1], 'R_areal', a.trumpet)
    at = column(cols_t, blocks_t[0][1], 'alpha', a.trumpet)
    run_text = read_text(a.run)
    cols, blocks = parse(run_text, a.run)
    times = np.array([t for t, _ in blocks])
    t, data = blocks[-1] if a.time is None else blocks[int(np.argmin(abs(times - a.time)))]
    r = column(cols, data, 'r', a.run)
    R = column(cols, data, 'R_areal', a.run)
    alpha = column(cols, data, 'alpha', a.run)
    keep = (r >= a.rmin) & (R >= Rt.min()) & (R <= Rt.max())
    from scipy_free_interp import cubic
    diff = alpha[keep] - cubic(Rt, at, R[keep])
    print(f'# t = {t:g}: alpha(R) of the run minus the 1+log trumpet')
    print('# R_min R_max max_abs_diff')
    for lo, hi in [(R[keep].min(), 2.0), (2.0, 5.0), (5.0, 20.0), (20.0, 50.0)]:
        band = (R[keep] >= lo) & (R[keep] <= hi)
        if band.any():
            print(f'{lo:.4f} {hi:.1f} {abs(diff[band]).max():.3e}')
    if a.output:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        style(plt)
        fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
        # the evolution as every 8th point, the reference drawn over it, so that both show
        ax1.plot(R[keep][::8], alpha[keep][::8], 'o', ms=4, mfc='none', color='tab:blue',
                 label=f'evolution, t = {t:g} M (every 8th point)')
        ax1.plot(Rt, at, '-', color='tab:red', lw=1.2, zorder=3, label='stationary 1+log trumpet')
        ax1.set_ylabel('lapse alpha')
        ax1.legend()
        ax2.semilogy(R[keep], abs(diff), '.', ms=3)
        ax2.set_ylabel('|alpha - alpha_trumpet| at equal R')
        ax2.set_xlabel('areal radius R / M')
        ax2.set_xscale('log')
        title = a.title or f'lapse at t = {t:g} M against the stationary 1+log trumpet'
        set_titles(fig, ax1, title, run_description([header_params(run_text)]))
        fig.tight_layout()
        save_figure(fig, a.output)


if __name__ == '__main__':
    run_script(main)
