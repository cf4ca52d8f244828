#!/usr/bin/env python3
"""Tables and figures of the horizon-shift study from `gbssn1d converge` output directories.

  horizon_study.py table STD FAMILY [FAMILY ...] [-y H_L2_R] [--t0 10 --t1 100]
  horizon_study.py figure FAMILY [FAMILY ...] [-y H_L2_R] [--cols 3] -o figure.png
  horizon_study.py threshold FAMILY [FAMILY ...] [--min-order 3.5] [--max-order 6] [--rmax 200]
  horizon_study.py cost STD FAMILY [FAMILY ...] --H-target 1e-5 --M-target 1e-4

Each FAMILY (and STD, the standard gauge at the same resolutions) is a converge directory
with convergence.dat. `table` prints a row per family:
  - rms_N: the RMS over t in [t0, t1] of the norm (-y) of each member; a time average is
    steadier than one time, where a norm can pass near a zero of H;
  - p_rms: the pairwise orders of those averages, p = ln(E_a/E_b)/ln(b/a) (a quantity whose
    exact value is zero, equations document Sec. 15);
  - p_min, p_max: the smallest and largest pairwise order over the output times in [t0, t1];
  - ratio_N: rms_N over the standard family's at the same N (the cost of the gauge in error).
Families whose members stopped early say so (`ended t = ...`).
`threshold` prints, for each family, the coarsest spacing (each member's smallest cell width
from its header, or rmax/N_k with --rmax) from which every three consecutive resolutions converge: both pairwise orders of the
time averages at least --min-order, and every pairwise order at the output times in [t0, t1]
between --min-order - 1 and --max-order (an order far from the design order at some time is a
cancellation, not convergence), for the triple starting at N_k and every finer one.
`cost` prints, for each family, the work (cells x RK4 steps to t1, from each member's N and
time step) needed to reach an RMS of the norm of --H-target and a largest |M_AH - M| over
[t0, t1] of --M-target, found by interpolating log error against log work between the
members (or extrapolating from the finest two at their order, marked '>'), and its ratio to
the standard family's: below 1, the gauge saves resolution.
`figure` draws the norm against t for each family, one panel each, a curve per resolution
(a sequential colormap: darker is finer), labelled with each member's smallest cell width,
under a title that says what the family ran (data, grid, horizon shift, flags).
"""
import argparse
import math
import os
import textwrap

import numpy as np

from gbssn1d_data import (DataError, axis_label, header_params, params_of, parse, read_text,
                          run_description, run_script, sequential_colors, style, save_figure)


def load(directory, key):
    """{N: (t, norm)} of one converge directory."""
    path = os.path.join(directory, 'convergence.dat')
    columns, blocks = parse(read_text(path), path)
    if 't' not in columns:
        raise DataError('no column t', path)
    data = blocks[0][1]
    t = data[:, columns.index('t')]
    out = {}
    for c in columns:
        if c.startswith(key + '_N'):
            out[int(c[len(key) + 2:])] = (t, data[:, columns.index(c)])
    if not out:
        raise DataError(f'no column {key}_N<n>', path)
    return out


def end_times(directory):
    """Final time of each member's timeseries.dat (a member that stopped ends early)."""
    ends = {}
    for name in os.listdir(directory):
        path = os.path.join(directory, name, 'timeseries.dat')
        if name.startswith('N') and os.path.exists(path):
            columns, blocks = parse(read_text(path), path)
            ends[int(name[1:])] = blocks[0][1][-1, columns.index('t')]
    return ends


def spacing_label(directory, N, rmax=None):
    """'M/12': the member's smallest cell width from its header (dr-min: the finest box's
    spacing on boxes, the innermost cell's on the sinh grid), or rmax/N when --rmax is given."""
    if rmax:
        return f'M/{N / rmax:g}'
    head = header_params(read_text(os.path.join(directory, f'N{N}', 'timeseries.dat')))
    M = float(head.get('M', 1.0))
    return f"M/{M / float(head['dr-min']):.3g}"


# the flags that tell the study's horizon-shift configurations apart, as a panel title names them
TITLE_FLAGS = ['rah-profile', 'rah-width', 'rah-normal', 'driver-advection', 'time-interp',
               'ah-every', 'rah-variant', 'ko-sigma', 'cfl']


def family_title(directory):
    """What a family ran, in words: the data, the grid and the horizon shift (from its
    config.toml), then its horizon-shift and numerical flags."""
    path = os.path.join(directory, 'config.toml')
    if not os.path.exists(path):
        return os.path.basename(os.path.normpath(directory))
    p = params_of(read_text(path).splitlines())
    p.pop('N', None)  # the members' N are in the legend
    flags = ', '.join(f'{k} {p[k]}' for k in TITLE_FLAGS if k in p)
    return '\n'.join(textwrap.fill(part, 70) for part in
                     run_description([p]).split('; ') + ([flags] if flags else []))


def rms(t, v, t0, t1):
    sel = (t >= t0) & (t <= t1)
    return math.sqrt(np.mean(v[sel] ** 2)) if sel.any() else float('nan')


def order(a, b, Na, Nb):
    return math.log(a / b) / math.log(Nb / Na) if a > 0 and b > 0 else float('nan')


def table(args):
    std = load(args.std, args.y)
    print(f"# {args.y}: RMS over t in [{args.t0}, {args.t1}] M; orders p = ln(E_a/E_b)/ln(b/a)")
    for d in args.families:
        fam = load(d, args.y)
        Ns = sorted(fam)
        R = [rms(*fam[n], args.t0, args.t1) for n in Ns]
        p = [order(R[k], R[k + 1], Ns[k], Ns[k + 1]) for k in range(len(Ns) - 1)]
        ranges = []
        for k in range(len(Ns) - 1):
            (t, a), (_, b) = fam[Ns[k]], fam[Ns[k + 1]]
            sel = (t >= args.t0) & (t <= args.t1) & (a > 0) & (b > 0)
            q = np.log(a[sel] / b[sel]) / math.log(Ns[k + 1] / Ns[k])
            ranges.append(f"{q.min():.1f}..{q.max():.1f}" if q.size else '--')
        ratio = [rms(*fam[n], args.t0, args.t1) / rms(*std[n], args.t0, args.t1) if n in std
                 else float('nan') for n in Ns]
        ends = end_times(d)
        short = [f"N{n} ended t = {e:g}" for n, e in sorted(ends.items()) if e < args.t1 - 1e-9]
        print(f"{os.path.basename(os.path.normpath(d))}: N {','.join(map(str, Ns))}"
              f" | rms {' '.join(f'{x:.2e}' for x in R)}"
              f" | p_rms {' '.join(f'{x:.2f}' for x in p)}"
              f" | p(t) {' '.join(ranges)}"
              f" | ratio {' '.join(f'{x:.2f}' for x in ratio)}"
              + (f" | {'; '.join(short)}" if short else ''))


def threshold(args):
    print(f"# coarsest spacing from which every 3 consecutive resolutions give p_rms >= "
          f"{args.min_order} ({args.y}, t in [{args.t0}, {args.t1}] M)")
    for d in args.families:
        fam = load(d, args.y)
        Ns = sorted(fam)
        R = [rms(*fam[n], args.t0, args.t1) for n in Ns]
        ends = end_times(d)
        ok = []
        def orders_in_time(j):
            (t, a), (_, b) = fam[Ns[j]], fam[Ns[j + 1]]
            sel = (t >= args.t0) & (t <= args.t1)
            with np.errstate(divide='ignore', invalid='ignore'):
                return np.log(a[sel] / b[sel]) / math.log(Ns[j + 1] / Ns[j])

        for k in range(len(Ns) - 2):
            finished = all(ends.get(n, args.t1) >= args.t1 - 1e-9 for n in Ns[k:k + 3])
            p = [order(R[j], R[j + 1], Ns[j], Ns[j + 1]) for j in (k, k + 1)]
            steady = all(np.all((q >= args.min_order - 1) & (q <= args.max_order)) for q in
                         (orders_in_time(k), orders_in_time(k + 1)))
            ok.append(finished and steady and all(x >= args.min_order for x in p))
        start = None
        for k in range(len(ok) - 1, -1, -1):
            if not ok[k]:
                break
            start = k
        name = os.path.basename(os.path.normpath(d))
        if start is None:
            print(f"{name}: none of N = {','.join(map(str, Ns))}")
        else:
            print(f"{name}: from {spacing_label(d, Ns[start], args.rmax)} (N = {Ns[start]})")


def member_costs(directory, t1):
    """{N: (work, max |M_ah_err| over [t0, t1], ended early)} from each member's files."""
    out = {}
    for name in os.listdir(directory):
        path = os.path.join(directory, name, 'timeseries.dat')
        if not (name.startswith('N') and os.path.exists(path)):
            continue
        text = read_text(path)
        params = {}
        for line in text.splitlines():
            if line.startswith('# ') and ' = ' in line:
                k, v = line[2:].split(' = ', 1)
                params[k.strip()] = v.strip().strip('"')
        columns, blocks = parse(text, path)
        data = blocks[0][1]
        t = data[:, columns.index('t')]
        n = int(name[1:])
        out[n] = (t, data[:, columns.index('M_ah_err')], params)
    return out


def work_of(directory, args):
    """{N: (cells x steps, M_ah error)}: steps from the run's time step (cfl x smallest cell)."""
    import sys
    sys.path.insert(0, os.path.dirname(__file__))
    res = {}
    for n, (t, merr, params) in member_costs(directory, args.t1).items():
        # the header records the run's time step (cfl x smallest cell); t1 may end before tmax
        steps = math.ceil(args.t1 / float(params['dt']) - 1e-9)
        sel = (t >= args.t0) & (t <= args.t1) & np.isfinite(merr)
        m = float(np.max(np.abs(merr[sel]))) if sel.any() else float('nan')
        res[n] = (n * steps, m, t[-1] < args.t1 - 1e-9)
    return res


def needed(work, err, target):
    """Work at which err reaches target: log-log interpolation between members, or
    extrapolation beyond the finest pair at its observed order ('>' marks it)."""
    pts = sorted((w, e) for w, e in zip(work, err) if e > 0 and math.isfinite(e))
    if not pts:
        return float('nan'), '?'
    for (w1, e1), (w2, e2) in zip(pts, pts[1:]):
        if (e1 - target) * (e2 - target) <= 0 and e1 != e2:
            f = math.log(target / e1) / math.log(e2 / e1)
            return math.exp(math.log(w1) + f * math.log(w2 / w1)), ''
    if pts[0][1] <= target:
        return pts[0][0], '<'
    (w1, e1), (w2, e2) = pts[-2], pts[-1]
    if e2 >= e1:
        return float('nan'), '?'
    f = math.log(target / e1) / math.log(e2 / e1)
    return math.exp(math.log(w1) + f * math.log(w2 / w1)), '>'


def cost(args):
    rows = []
    for d in [args.std] + args.families:
        fam = load(d, args.y)
        wk = work_of(d, args)
        Ns = [n for n in sorted(fam) if n in wk and not wk[n][2]]
        H = [rms(*fam[n], args.t0, args.t1) for n in Ns]
        W = [wk[n][0] for n in Ns]
        Merr = [wk[n][1] for n in Ns]
        wH, fH = needed(W, H, args.H_target)
        wM, fM = needed(W, Merr, args.M_target)
        rows.append((os.path.basename(os.path.normpath(d)), wH, fH, wM, fM, Ns, H, Merr))
    std = rows[0]
    print(f"# work = cells x RK4 steps to t = {args.t1:g} M to reach: rms {args.y} = "
          f"{args.H_target:g} over t in [{args.t0:g}, {args.t1:g}] M; max |M_AH - M| = "
          f"{args.M_target:g}; ratio to {std[0]} (< 1: fewer cells and steps)")
    for name, wH, fH, wM, fM, Ns, H, Merr in rows:
        print(f"{name}: H: {fH}{wH:.3g} (x{wH / std[1]:.2f}) | M_AH: {fM}{wM:.3g} "
              f"(x{wM / std[3]:.2f}) | N {','.join(map(str, Ns))}: H "
              f"{' '.join(f'{x:.1e}' for x in H)}, M_AH err {' '.join(f'{x:.1e}' for x in Merr)}")


def figure(args):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    style(plt)
    n = len(args.families)
    cols = min(args.cols, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows), squeeze=False,
                             sharey=True)
    for ax, d in zip(axes.flat, args.families):
        fam = load(d, args.y)
        Ns = sorted(fam)
        colors = sequential_colors(len(Ns))  # darker is finer
        for color, N in zip(colors, Ns):
            t, v = fam[N]
            ax.semilogy(t, v, color=color, label=f'N = {N} ({spacing_label(d, N, args.rmax)})')
        ax.set_title(family_title(d), fontsize=7)
        ax.set_xlabel(axis_label('t'))
        ax.legend(fontsize=7)
    labels = {'H_L2_R': 'L2 norm of H, 2.5 M <= R <= 12 M', 'H_L2_ext': 'L2 norm of H (coordinate window)',
              'H_L2_int': 'L2 norm of H near the puncture'}
    for ax in axes[:, 0]:
        ax.set_ylabel(labels.get(args.y, args.y), fontsize=9)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    fig.tight_layout()
    save_figure(fig, args.output)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='what', required=True)
    t = sub.add_parser('table')
    t.add_argument('std')
    t.add_argument('families', nargs='+')
    f = sub.add_parser('figure')
    f.add_argument('families', nargs='+')
    f.add_argument('--cols', type=int, default=3)
    f.add_argument('-o', '--output', required=True)
    f.add_argument('--rmax', type=float, default=None,
                   help='outer radius of uniform grids, for the spacing rmax/N in the legend '
                        '(default: each member\'s smallest cell width from its header)')
    th = sub.add_parser('threshold')
    th.add_argument('families', nargs='+')
    th.add_argument('--min-order', type=float, default=3.5)
    th.add_argument('--max-order', type=float, default=6.0,
                    help='largest pairwise order at an output time counted as convergence '
                         '(the design order + 2; 6 for 4th-order runs)')
    th.add_argument('--rmax', type=float, default=None,
                    help='spacing as rmax/N (default: each member\'s smallest cell width)')
    c = sub.add_parser('cost')
    c.add_argument('std')
    c.add_argument('families', nargs='+')
    c.add_argument('--H-target', type=float, default=1e-5)
    c.add_argument('--M-target', type=float, default=1e-4)
    for p in (t, f, th, c):
        p.add_argument('-y', default='H_L2_R')
        p.add_argument('--t0', type=float, default=10.0)
        p.add_argument('--t1', type=float, default=100.0)
    a = ap.parse_args()
    {'table': table, 'figure': figure, 'threshold': threshold, 'cost': cost}[a.what](a)


if __name__ == '__main__':
    run_script(main)
