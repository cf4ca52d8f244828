#!/usr/bin/env python3
"""Critical collapse: the runs of runs/critical.sh read, the mass-scaling exponent and the
echoing period fitted, the figures drawn.

    /usr/bin/python3 plots/critical.py OUT EPS_LO EPS_HI SHIFT LO HI STATE [SHIFT LO HI STATE ...]

OUT/SHIFT/A=<A>/ holds each run of amplitude A with that --shift; LO and HI are the bisection's
last dispersing and collapsing amplitudes, STATE how it ended. A run collapsed when horizon.dat
has an apparent horizon after t = 0, dispersed when it completed without one, and stopped
otherwise.

gamma: least squares of ln M_AH on ln(A - p*), p* = (LO + HI)/2, over the collapsed runs with
eps = A/p* - 1 in [EPS_LO, EPS_HI]; its error is the fit's standard error (the periodic wiggle of
period Delta/(2 gamma) in ln(A - p*) about the line included). Twice: with the final M_AH of the
runs that reached tmax (the hole after the field's last accretion), and with M_AH when a horizon
was first found (every collapsed run).

Delta: the dispersing run LO sampled finely (OUT/SHIFT-echo/A=LO): Phi_center(t) and
alpha_center(t); T = int alpha_center dt (the trapezoid rule over the series' rows); the extrema
T_k of Phi_center from the one of largest |Phi_center| (the first at the critical solution's
amplitude; those before it are the implosion) through the last of the consecutive ones above 3/4
of it (after them the field departs from the critical solution and disperses); T* chosen to
minimise the residual of the line ln(T* - T_k) = c - k Delta/2 (successive extrema half a
period apart; T* - T_k within 1/1000 to 10 times the last interval), Delta from its slope; its error half the spread of the exact solutions through
each three consecutive extrema (with fewer than four extrema none is given, with fewer than
three no Delta).

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
    """(verdict, M_AH first found, M_AH at the end or nan): 'collapse', 'disperse' or 'stopped';
    the final M_AH only for a collapse that reached tmax."""
    h = gd.series(os.path.join(path, 'horizon.dat'))
    ts = os.path.join(path, 'timeseries.dat')
    if h is None or not os.path.exists(ts):
        raise gd.DataError('no horizon.dat or timeseries.dat (the run did not complete)', path)
    ends = [l for l in gd.read_text(ts).splitlines() if l.startswith('# end:')]
    completed = bool(ends) and ends[-1].startswith('# end: completed')
    found = (h['t'] > 0) & np.isfinite(h['r_ah'])
    if found.any():
        final = float(h['M_ah'][-1]) if completed and np.isfinite(h['M_ah'][-1]) else math.nan
        return 'collapse', float(h['M_ah'][found][0]), final
    return ('disperse' if completed else 'stopped'), math.nan, math.nan


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


def mass_scaling(runs, p_star, eps_lo, eps_hi, which):
    """The fit with M_AH `which` (2: first found, 3: final) over the window."""
    used, left = [], []
    for run in runs:
        A, verdict, M = run[0], run[1], run[which]
        eps = A / p_star - 1
        # (the window's ends with a margin for the rounding of A = p* (1 + eps))
        if A <= p_star or not (eps_lo * (1 - 1e-6) <= eps <= eps_hi * (1 + 1e-6)):
            continue
        if verdict == 'collapse' and math.isfinite(M) and M > 0:
            used.append((A, eps, M, verdict))
        else:
            left.append((A, eps, M, verdict if verdict != 'collapse' else 'no final M_AH'))
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
    if s is None:
        raise gd.DataError('no timeseries.dat (the run did not complete)', path)
    t, alpha, phi = s['t'], s['alpha_center'], s['Phi_center']
    T = np.concatenate([[0.0], np.cumsum(0.5 * (alpha[1:] + alpha[:-1]) * np.diff(t))])
    found = extrema(T, phi)
    values = np.interp(found, T, np.abs(phi)) if found else np.array([])
    Tk = []
    if found:
        first = int(np.argmax(values))
        for k in range(first, len(found)):
            if values[k] < 0.75 * values[first]:
                break
            Tk.append(found[k])
    result = {'T': T, 'phi': phi, 'Tk': Tk, 'T_star': math.nan, 'Delta': math.nan,
              'error': math.nan, 'triples': []}
    if len(Tk) < 3:
        return result
    for j in range(len(Tk) - 2):  # the exact fit through three consecutive extrema
        T1, T2, T3 = Tk[j:j + 3]
        T_star = (T1 * T3 - T2 * T2) / (T1 + T3 - 2 * T2)
        if T_star > T3:
            result['triples'].append(2 * math.log((T_star - T1) / (T_star - T2)))
    k = np.arange(len(Tk))
    best = None
    # T* - T_last = d/(exp(Delta/2) - 1) for the last interval d: from d/1000 to 10 d holds every
    # Delta from 0.2 to 14 (a wider range lets a nearly flat residual pick an absurd T*)
    last = Tk[-1] - Tk[-2]
    for gap in np.logspace(math.log10(last / 1000), math.log10(10 * last), 4000):
        T_star = Tk[-1] + gap
        y = np.log(T_star - np.asarray(Tk))
        m, c, se = line_fit(k, y)
        r = y - (m * k + c)
        score = float(r @ r)
        if best is None or score < best[0]:
            best = (score, T_star, m, se)
    _, T_star, m, _ = best
    spread = result['triples']
    error = (max(spread) - min(spread)) / 2 if len(Tk) >= 4 and len(spread) >= 2 else math.nan
    result.update(T_star=T_star, Delta=-2 * m, error=error)
    return result


SHIFTS = ['gamma-driver', 'zero']
VERDICTS = ['disperse', 'collapse', 'stopped']
MASSES = {'final': 3, 'first': 2}  # where in a run's (A, verdict, first, final)


def write_tables(out, results):
    with open(os.path.join(out, 'scaling.dat'), 'w') as f:
        f.write('# shift: 0 gamma-driver, 1 zero; verdict: 0 disperse, 1 collapse, 2 stopped; '
                'M_first: M_AH when a horizon was first found, M_final: at tmax\n')
        f.write('# shift A eps verdict M_first M_final\n')
        for r in results:
            for A, verdict, first, final in r['runs']:
                f.write(f'{SHIFTS.index(r["shift"])} {A!r} {A / r["p_star"] - 1:.6e} '
                        f'{VERDICTS.index(verdict)} {first:.10e} {final:.10e}\n')
    with open(os.path.join(out, 'echoes.dat'), 'w') as f:
        f.write('# shift: 0 gamma-driver, 1 zero; T_k: the extrema of Phi_center in central '
                'proper time\n# shift k T_k ln_Tstar_minus_Tk\n')
        for r in results:
            echo = r['echo']
            for k, Tk in enumerate(echo['Tk']):
                ln = math.log(echo['T_star'] - Tk) if echo['T_star'] > Tk else math.nan
                f.write(f'{SHIFTS.index(r["shift"])} {k} {Tk:.10e} {ln:.6e}\n')


def report(r):
    p_star, lo, hi = r['p_star'], r['lo'], r['hi']
    print(f'--shift {r["shift"]}: p* = {p_star!r}, bracket [{lo!r}, {hi!r}] '
          f'(|p - p*|/p* < {(hi - lo) / hi:.2e}); the bisection ended: {r["state"]}')
    for mass, (used, left, gamma, err) in r['fits'].items():
        if used:
            eps = [e for _, e, _, _ in used]
            print(f'  gamma ({mass} M_AH) = {gamma:.4f} +- {err:.4f} from {len(used)} runs, '
                  f'A - p* from {min(eps) * p_star:.3e} to {max(eps) * p_star:.3e} '
                  f'({math.log10(max(eps) / min(eps)):.2f} decades; published {GAMMA}: '
                  f'{100 * (gamma / GAMMA - 1):+.1f}%)')
        else:
            print(f'  gamma ({mass} M_AH): no runs in the window')
        for A, e, _, why in left:
            print(f'    left out: A = {A!r} (eps {e:.2e}): {why}')
    echo = r['echo']
    print(f'  Delta = {echo["Delta"]:.4f} +- {echo["error"]:.4f} from {len(echo["Tk"])} extrema of '
          f'Phi_center in the run A = {r["lo_text"]} (T* = {echo["T_star"]:.8f}; published {DELTA}: '
          f'{100 * (echo["Delta"] / DELTA - 1):+.1f}%); through each three consecutive extrema: '
          + ', '.join(f'{d:.3f}' for d in echo['triples']))


def figures(out, results):
    plt = gd.pyplot()
    fig, ax = plt.subplots()
    for color, r in zip(gd.qualitative_colors(len(results), 'shifts'), results):
        used, _, gamma, err = r['fits']['final']
        p_star = r['p_star']
        first = [(A - p_star, m) for A, v, m, _ in r['runs'] if v == 'collapse' and A > p_star]
        if first:
            ax.loglog(*zip(*first), 'x', color=color, label=f'{r["shift"]}: M_AH first found')
        if used:
            x = np.array([A - p_star for A, *_ in used])
            m = np.array([M for _, _, M, _ in used])
            ax.loglog(x, m, 'o', color=color, label=f'{r["shift"]}: final M_AH (fitted)')
            c = np.mean(np.log(m) - gamma * np.log(x))
            ax.loglog(x, np.exp(c) * x ** gamma, '-', color=color,
                      label=f'gamma = {gamma:.3f} +- {err:.3f}')
    gd.finish(fig, ax, 'A - p*', 'M_AH', f'mass scaling (published gamma = {GAMMA})',
         os.path.join(out, 'mass-scaling.png'))
    fig, ax = plt.subplots()
    for color, r in zip(gd.qualitative_colors(len(results), 'shifts'), results):
        echo = r['echo']
        if not math.isfinite(echo['T_star']):
            continue
        T, phi = echo['T'], echo['phi']
        keep = T < echo['T_star']
        ax.plot(np.log(echo['T_star'] - T[keep]), phi[keep], '-', color=color,
                label=f'{r["shift"]}: Delta = {echo["Delta"]:.3f} +- {echo["error"]:.3f}')
        for Tk in echo['Tk']:
            ax.axvline(math.log(echo['T_star'] - Tk), color=color, lw=0.6, ls=':')
    ax.invert_xaxis()
    gd.finish(fig, ax, 'ln(T* - T), T the central proper time', 'Phi at r = 0',
         f'echoes (dotted: the extrema fitted; published Delta = {DELTA})',
         os.path.join(out, 'echoes.png'))


def main(out, eps_lo, eps_hi, *specs):
    eps_lo, eps_hi = float(eps_lo), float(eps_hi)
    if len(specs) % 4 or not specs:
        sys.stderr.write('usage: critical.py OUT EPS_LO EPS_HI SHIFT LO HI STATE [...]\n')
        sys.exit(2)
    results = []
    for i in range(0, len(specs), 4):
        shift, lo, hi, state = specs[i], float(specs[i + 1]), float(specs[i + 2]), specs[i + 3]
        if shift not in SHIFTS:
            raise SystemExit(f'critical.py: unknown shift {shift!r}')
        runs = runs_of(out, shift)
        p_star = (lo + hi) / 2
        fits = {mass: mass_scaling(runs, p_star, eps_lo, eps_hi, which)
                for mass, which in MASSES.items()}
        results.append({'shift': shift, 'lo': lo, 'hi': hi, 'lo_text': specs[i + 1],
                        'state': state, 'runs': runs,
                        'p_star': p_star, 'fits': fits,
                        'echo': echoes(os.path.join(out, f'{shift}-echo', f'A={specs[i + 1]}'))})
    write_tables(out, results)
    for r in results:
        report(r)
    figures(out, results)


if __name__ == '__main__':
    if len(sys.argv) < 8:
        sys.stderr.write('usage: critical.py OUT EPS_LO EPS_HI SHIFT LO HI STATE [...]\n')
        sys.exit(2)
    gd.run_script(main, *sys.argv[1:])
