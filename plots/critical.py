#!/usr/bin/env python3
"""Critical collapse: the runs of runs/critical.sh read, the mass-scaling exponent and the
echoing period fitted, the figures drawn.

    /usr/bin/python3 plots/critical.py OUT EPS_LO EPS_HI SHIFT LO HI STATE [SHIFT LO HI STATE ...]

OUT/SHIFT/A=<A>/ holds each run of amplitude A with that --shift; LO and HI are the bisection's
last dispersing and collapsing amplitudes, STATE how it ended. A run collapsed when horizon.dat
has an apparent horizon after t = 0 (its mass: the last M_AH found), dispersed when it completed
without one, and stopped otherwise.

gamma: least squares of ln M_AH on ln(A - p*), p* = (LO + HI)/2, over the collapsed runs with
eps = A/p* - 1 in [EPS_LO, EPS_HI]; its error is the fit's standard error (the periodic wiggle of
period Delta/(2 gamma) in ln(A - p*) about the line included).

Delta: the dispersing run LO's Phi_center(t) and alpha_center(t); T = int alpha_center dt (the
trapezoid rule over the series' rows); the extrema T_k of Phi_center while the field is
concentrating (before the largest |Phi_center|, that one included); T* chosen to minimise the
residual of the line ln(T* - T_k) = c - k Delta/2 (successive extrema half a period apart),
Delta from its slope, its error the fit's standard error; with fewer than four extrema no
error is given, with fewer than three no Delta.

Writes OUT/scaling.dat and OUT/echoes.dat (named columns), prints the table and the results,
and draws OUT/mass-scaling.png and OUT/echoes.png.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gbssn1d_data as gd  # noqa: E402

GAMMA, DELTA = 0.374, 3.4453  # Koike, Hara & Adachi 1995; Gundlach 1997


def run_result(path):
    """('collapse', M_AH) | ('disperse', nan) | ('stopped', nan) of the run in `path`."""
    h = gd.series(os.path.join(path, 'horizon.dat'))
    ts = os.path.join(path, 'timeseries.dat')
    if h is None or not os.path.exists(ts):
        raise gd.DataError('no horizon.dat or timeseries.dat (the run did not complete)', path)
    found = (h['t'] > 0) & np.isfinite(h['r_ah'])
    if found.any():
        return 'collapse', float(h['M_ah'][found][-1])
    ends = [l for l in gd.read_text(ts).splitlines() if l.startswith('# end:')]
    return ('disperse' if ends and ends[-1].startswith('# end: completed') else 'stopped'), math.nan


def runs_of(out, shift):
    folder = os.path.join(out, shift)
    if not os.path.isdir(folder):
        raise gd.DataError('no runs', folder)
    found = []
    for name in sorted(os.listdir(folder)):
        if name.startswith('A=') and os.path.isdir(os.path.join(folder, name)):
            found.append((float(name[2:]), *run_result(os.path.join(folder, name))))
    return sorted(found)


def line_fit(x, y):
    """slope, intercept, the slope's standard error (nan for fewer than three points)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    A = np.vstack([x, np.ones_like(x)]).T
    (m, c), *_ = np.linalg.lstsq(A, y, rcond=None)
    if len(x) < 3:
        return float(m), float(c), math.nan
    r = y - (m * x + c)
    se = math.sqrt(float(r @ r) / (len(x) - 2) / float(((x - x.mean()) ** 2).sum()))
    return float(m), float(c), se


def mass_scaling(runs, p_star, eps_lo, eps_hi):
    used, left = [], []
    for A, verdict, M in runs:
        eps = A / p_star - 1
        if A <= p_star or not (eps_lo <= eps <= eps_hi):
            continue
        (used if verdict == 'collapse' else left).append((A, eps, M, verdict))
    if len(used) < 3:
        return used, left, math.nan, math.nan
    m, _, se = line_fit([math.log(A - p_star) for A, *_ in used], [math.log(M) for _, _, M, _ in used])
    return used, left, m, se


def extrema(t, f):
    """Times of the local extrema of f (parabola through each sampled extremum and its
    neighbours)."""
    out = []
    for i in range(1, len(f) - 1):
        if (f[i] - f[i - 1]) * (f[i + 1] - f[i]) < 0:
            a, b, c = f[i - 1], f[i], f[i + 1]
            d = a - 2 * b + c
            shift = 0.5 * (a - c) / d if d != 0 else 0.0
            out.append(t[i] + shift * (t[i + 1] - t[i - 1]) / 2)
    return out


def echoes(path):
    s = gd.series(os.path.join(path, 'timeseries.dat'))
    t, alpha, phi = s['t'], s['alpha_center'], s['Phi_center']
    T = np.concatenate([[0.0], np.cumsum(0.5 * (alpha[1:] + alpha[:-1]) * np.diff(t))])
    peak = int(np.argmax(np.abs(phi)))
    Tk = [x for x in extrema(T[:peak + 2], phi[:peak + 2]) if x <= T[peak] + 1e-12]
    result = {'T': T, 'phi': phi, 'Tk': Tk, 'T_star': math.nan, 'Delta': math.nan,
              'error': math.nan}
    if len(Tk) < 3:
        return result
    k = np.arange(len(Tk))
    best = None
    for gap in np.logspace(-8, 1, 2000):  # T* - T_last
        T_star = Tk[-1] + gap
        y = np.log(T_star - np.asarray(Tk))
        m, c, se = line_fit(k, y)
        r = y - (m * k + c)
        score = float(r @ r)
        if best is None or score < best[0]:
            best = (score, T_star, m, se)
    _, T_star, m, se = best
    result.update(T_star=T_star, Delta=-2 * m, error=2 * se if len(Tk) >= 4 else math.nan)
    return result


def main(out, eps_lo, eps_hi, *specs):
    eps_lo, eps_hi = float(eps_lo), float(eps_hi)
    if len(specs) % 4 or not specs:
        raise SystemExit('usage: critical.py OUT EPS_LO EPS_HI SHIFT LO HI STATE [...]')
    results = []
    for i in range(0, len(specs), 4):
        shift, lo, hi, state = specs[i], float(specs[i + 1]), float(specs[i + 2]), specs[i + 3]
        runs = runs_of(out, shift)
        p_star = (lo + hi) / 2
        used, left, gamma, gamma_err = mass_scaling(runs, p_star, eps_lo, eps_hi)
        echo = echoes(os.path.join(out, shift, f'A={lo!r}'))
        results.append((shift, lo, hi, state, runs, p_star, used, left, gamma, gamma_err, echo))
    with open(os.path.join(out, 'scaling.dat'), 'w') as f:
        f.write('# shift: 0 gamma-driver, 1 zero; verdict: 0 disperse, 1 collapse, 2 stopped\n')
        f.write('# shift A eps verdict M_AH\n')
        for shift, lo, hi, state, runs, p_star, *_ in results:
            for A, verdict, M in runs:
                f.write(f'{["gamma-driver", "zero"].index(shift)} {A!r} {A / p_star - 1:.6e} '
                        f'{["disperse", "collapse", "stopped"].index(verdict)} {M:.10e}\n')
    with open(os.path.join(out, 'echoes.dat'), 'w') as f:
        f.write('# shift: 0 gamma-driver, 1 zero; T_k: the extrema of Phi_center in central '
                'proper time\n# shift k T_k ln_Tstar_minus_Tk\n')
        for shift, *_, echo in results:
            for k, Tk in enumerate(echo['Tk']):
                f.write(f'{["gamma-driver", "zero"].index(shift)} {k} {Tk:.10e} '
                        f'{math.log(echo["T_star"] - Tk) if echo["T_star"] > Tk else math.nan:.6e}\n')
    for shift, lo, hi, state, runs, p_star, used, left, gamma, gamma_err, echo in results:
        print(f'--shift {shift}: p* = {p_star!r}, bracket [{lo!r}, {hi!r}] '
              f'(|p - p*|/p* < {(hi - lo) / hi:.2e}); the bisection ended: {state}')
        if used:
            eps = [e for _, e, _, _ in used]
            print(f'  gamma = {gamma:.4f} +- {gamma_err:.4f} from {len(used)} collapsed runs, '
                  f'A - p* from {min(eps) * p_star:.3e} to {max(eps) * p_star:.3e} '
                  f'({math.log10(max(eps) / min(eps)):.2f} decades; published {GAMMA}, '
                  f'{100 * (gamma / GAMMA - 1):+.1f}%)')
        else:
            print('  gamma: no collapsed runs in the window')
        for A, e, _, verdict in left:
            print(f'  left out of the fit: A = {A!r} (eps {e:.2e}): {verdict}')
        print(f'  Delta = {echo["Delta"]:.4f} +- {echo["error"]:.4f} from {len(echo["Tk"])} '
              f'extrema of Phi_center in the run A = {lo!r} (T* = {echo["T_star"]:.8f}; '
              f'published {DELTA}, {100 * (echo["Delta"] / DELTA - 1):+.1f}%)')
    plt = gd.pyplot()
    fig, ax = plt.subplots()
    for color, (shift, lo, hi, state, runs, p_star, used, left, gamma, gamma_err, echo) in zip(
            gd.qualitative_colors(len(results), 'shifts'), results):
        every = [(A - p_star, M) for A, v, M in runs if v == 'collapse' and A > p_star]
        if every:
            ax.loglog(*zip(*every), 'o', color=color, mfc='none', label=f'{shift}: every collapse')
        if used:
            x = np.array([A - p_star for A, *_ in used])
            ax.loglog(x, [M for _, _, M, _ in used], 'o', color=color, label=f'{shift}: fitted')
            c = np.mean(np.log([M for _, _, M, _ in used]) - gamma * np.log(x))
            ax.loglog(x, np.exp(c) * x ** gamma, '-', color=color,
                      label=f'gamma = {gamma:.3f} +- {gamma_err:.3f}')
    ax.set_xlabel('A - p*')
    ax.set_ylabel('M_AH at t = tmax')
    ax.set_title(f'mass scaling (published gamma = {GAMMA})')
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'mass-scaling.png'))
    fig, ax = plt.subplots()
    for color, (shift, *_, echo) in zip(gd.qualitative_colors(len(results), 'shifts'), results):
        if not math.isfinite(echo['T_star']):
            continue
        T, phi = echo['T'], echo['phi']
        keep = T < echo['T_star']
        ax.plot(np.log(echo['T_star'] - T[keep]), phi[keep], '-', color=color,
                label=f'{shift}: Delta = {echo["Delta"]:.3f} +- {echo["error"]:.3f}')
        for Tk in echo['Tk']:
            ax.axvline(math.log(echo['T_star'] - Tk), color=color, lw=0.6, ls=':')
    ax.invert_xaxis()
    ax.set_xlabel('ln(T* - T), T the central proper time')
    ax.set_ylabel('Phi at r = 0')
    ax.set_title(f'echoes (dotted: the fitted extrema; published Delta = {DELTA})')
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'echoes.png'))


if __name__ == '__main__':
    gd.run_script(main, *sys.argv[1:])
