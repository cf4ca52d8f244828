#!/usr/bin/env python3
"""A horizon that grows by accretion: the runs of runs/accretion.sh read, tabled and drawn.

    /usr/bin/python3 plots/accretion.py OUT

OUT/gauges/N<N>/GAUGE/: each gauge's run to the end at N cells (GAUGE: free, or h<h>[-A<A>],
--rahA and --rah0 from its header). For each: M_AH at t = 0 and at the end, r_AH at the end
against h, and the largest |r_AH - h| while M_AH grows (the rows where M_AH lies between 5% and
95% of its whole growth from t = 0 to the end), and the final M_AH against the free run's.

OUT/converge/GAUGE-FAMILY/: converge studies; their verdicts (convergence.dat's '# verdict:': the
class, H's, the worst quantity), and whether converge warned that the members' hierarchies step
by different dt (its log beside, FAMILY.log).

OUT/cost/GAUGE/GRID-N<N>/: runs to t = 60; M_AH in the last row of a completed run (a run that
stopped has none: its line says so), its cost N x RHS evaluations (from the run's log beside it,
GRID-N<N>.log: 'reached t = ... (S steps, E RHS evaluations)'), its error against the same
gauge's sinh-N<largest>. For each gauge and grid, the cheapest run whose error and the errors of
every finer run of that grid are within 1e-3, 1e-4 and 1e-5 (so a coarse run that lands near
the answer by chance does not count).

OUT/budget/GAUGE/N<N>/: runs to the end with --flux-R 5,30 (m_R5, flux_R5, m_R30, flux_R30, a
row every 0.05): of the shell's energy M_ADM - M_AH(0) (M-ADM from the header), what crossed
R = 5 inwards (-integral of flux_R5 over t: Simpson's rule, the last three intervals by the 3/8
rule when their number is odd) against M_AH's growth, what left through R = 30, what lies between
the horizon and R = 30 at the end (m_R30 - M_AH), and the identity's error at each sphere,
integral - (m(0) - m(end)), with its order between successive N.

Prints the tables; writes OUT/gauges.dat, OUT/cost.dat and OUT/budget.dat (named columns) and draws
OUT/accretion.png (M_AH and r_AH against t) and OUT/cost.png (M_AH's error against cost).
"""
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gbssn1d_data as gd  # noqa: E402

TARGETS = (1e-3, 1e-4, 1e-5)
# the figure's colours tell seven runs apart: the two strengths between 0.5 and 5 are in the table
FIGURE_LEAVES_OUT = ('h1.0-A1', 'h1.0-A2')
REACHED = re.compile(r'reached t = \S+ in \S+ s \((\d+) steps, (\d+) RHS evaluations\)')


def series(path, names):
    """A run's timeseries.dat: its columns `names` by name, its header's parameters, its last
    end line (or what its absence means) and the file's path."""
    ts = os.path.join(path, 'timeseries.dat')
    if not os.path.exists(ts):
        raise gd.DataError('no timeseries.dat (the run did not start)', path)
    text = gd.read_text(ts)
    columns, data = gd.parse_table(text, ts)
    ends = [line for line in text.splitlines() if line.startswith('# end:')]
    return ({name: gd.column(columns, data, name, ts) for name in names}, gd.header_params(text),
            ends[-1][len('# end: '):] if ends else 'no end line (the run was cut short)', ts)


def run(path):
    """{'t', 'r_ah', 'M_ah', 'completed', 'end', 'rahA', 'rah0', 'N'} of a run's timeseries.dat."""
    col, params, end, _ = series(path, ('t', 'r_ah', 'M_ah'))
    return {**col, 'completed': end.startswith('completed'), 'end': end,
            'rahA': float(params.get('rahA', 0)), 'rah0': float(params.get('rah0', 'nan')),
            'N': int(params['N'])}


def evaluations(log):
    """The RHS evaluations a completed run reports in its log, or nan."""
    if not os.path.exists(log):
        return math.nan
    m = REACHED.search(gd.read_text(log))
    return float(m[2]) if m else math.nan


def gauge_row(r, free):
    """The gauge table's numbers of run r (free: the free run's, for the final M_AH)."""
    m, t = r['M_ah'], r['t']
    growth = m[-1] - m[0]
    h = r['rah0'] if r['rahA'] > 0 else math.nan
    during = (m - m[0] > 0.05 * growth) & (m - m[0] < 0.95 * growth)
    stray = float(np.max(np.abs(r['r_ah'][during] - h))) if during.any() else math.nan
    return {'rahA': r['rahA'], 'h': h, 'M0': m[0], 'M_end': m[-1], 'growth': growth / m[0],
            'r_end': r['r_ah'][-1], 'off_end': r['r_ah'][-1] - h, 'stray': stray,
            't_grow': (float(t[during][0]), float(t[during][-1])) if during.any() else None,
            'dM': (m[-1] - free['M_ah'][-1]) / free['M_ah'][-1] if free else math.nan}


def gauges(out):
    """The gauge tables, one per OUT/gauges/N<N>/; the runs of the coarsest, for the figure."""
    top = os.path.join(out, 'gauges')
    sizes = sorted((int(d[1:]) for d in os.listdir(top) if re.fullmatch(r'N\d+', d)))
    if not sizes:
        raise gd.DataError('no folder N<N> of runs', top)
    shown = None
    with open(os.path.join(out, 'gauges.dat'), 'w') as f:
        f.write('# N rahA h M_AH_0 M_AH_end growth r_AH_end r_AH_end_minus_h max_stray dM_rel\n')
        for N in sizes:
            folder = os.path.join(top, f'N{N}')
            runs = {g: run(os.path.join(folder, g)) for g in sorted(os.listdir(folder), key=order)
                    if os.path.isdir(os.path.join(folder, g)) and not g.startswith('.')}
            shown = shown or runs
            free = runs.get('free')
            rows = {g: gauge_row(r, free) for g, r in runs.items()}
            print(f'{"" if N == sizes[0] else chr(10)}1. The gauges (sinh grid, N = {N}): M_AH '
                  'and r_AH')
            print(f'{"gauge":9} {"rahA":>5} {"h":>4} {"M_AH(0)":>11} {"M_AH(end)":>11} '
                  f'{"growth":>7} {"r_AH(end)":>9} {"r_AH-h":>9} {"max|r_AH-h|":>11} '
                  f'{"while M_AH grows":>16} {"M_AH/free-1":>11}')
            for g, w in rows.items():
                grow = f'{w["t_grow"][0]:.1f}-{w["t_grow"][1]:.1f}' if w['t_grow'] else '-'
                print(f'{g:9} {w["rahA"]:5.2g} {w["h"]:4.2g} {w["M0"]:11.8f} {w["M_end"]:11.8f} '
                      f'{100 * w["growth"]:6.2f}% {w["r_end"]:9.5f} {w["off_end"]:9.2e} '
                      f'{w["stray"]:11.4f} {grow:>16} {w["dM"]:11.2e}')
                if not runs[g]['completed']:
                    print(f'  {g}: {runs[g]["end"]}')
                f.write(f'{N} ' + ' '.join(f'{w[k]:.12g}' for k in
                                           ('rahA', 'h', 'M0', 'M_end', 'growth', 'r_end',
                                            'off_end', 'stray', 'dM')) + '\n')
    return shown


def order(gauge):
    """free first, then by h and A."""
    if gauge == 'free':
        return (0, 0.0, 0.0)
    m = re.fullmatch(r'h([\d.]+)(?:-A([\d.]+))?', gauge)
    return (1, float(m[1]), float(m[2] or 0.5)) if m else (2, 0.0, 0.0)


def verdicts(out):
    folder = os.path.join(out, 'converge')
    print('\n2. H through the accretion to t = 60 (converge\'s verdicts)')
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name, 'convergence.dat')
        if name.startswith('.') or not os.path.exists(path):
            continue
        line = next((l for l in gd.read_text(path).splitlines() if l.startswith('# verdict:')),
                    '# verdict: none')
        v = line[len('# verdict: '):]
        worst = re.search(r'the worst: (\S+ at N = [\d, and]+\d)', v)
        log = os.path.join(folder, name + '.log')
        steps = os.path.exists(log) and 'hierarchies step by different dt' in gd.read_text(log)
        print(f'{name:22} {v[:v.index(";")] if ";" in v else v}'
              + (f'; the worst: {worst[1]}' if worst else '')
              + ('; warned: the hierarchies step by different dt' if steps else ''))


def cost_runs(out, gauge):
    """[(grid, N, cost, M_AH or nan, end)] of OUT/cost/GAUGE, by grid and N."""
    folder = os.path.join(out, 'cost', gauge)
    found = []
    for name in os.listdir(folder):
        m = re.fullmatch(r'(\w+)-N(\d+)', name)
        if not m or not os.path.isdir(os.path.join(folder, name)):
            continue
        r = run(os.path.join(folder, name))
        E = evaluations(os.path.join(folder, name + '.log'))
        M = float(r['M_ah'][-1]) if r['completed'] else math.nan
        found.append((m[1], int(m[2]), int(m[2]) * E, M, r['end']))
    return sorted(found)


def cheapest(rows, target):
    """The (N, cost) of the coarsest run from which on every finer run's error is within target."""
    best = None
    for k in range(len(rows) - 1, -1, -1):
        if not rows[k][3] <= target:
            break
        best = rows[k][:2]
    return best


def costs(out):
    gauges_ = sorted(g for g in os.listdir(os.path.join(out, 'cost')) if not g.startswith('.'))
    table, refs = {}, {}
    for g in gauges_:
        runs = cost_runs(out, g)
        sinh = [r for r in runs if r[0] == 'sinh']
        if not sinh or not math.isfinite(sinh[-1][3]):
            raise gd.DataError('no completed sinh run to take as the reference',
                               os.path.join(out, 'cost', g))
        refs[g] = sinh[-1]
        table[g] = [(grid, N, c, M, abs(M - refs[g][3]), end) for grid, N, c, M, end in runs
                    if (grid, N) != refs[g][:2]]
    print(f'\n3. M_AH at t = 60 against cost (N x RHS evaluations); the reference: each gauge\'s '
          f'sinh N = {next(iter(refs.values()))[1]}')
    values = [r[3] for r in refs.values()]
    print('references: ' + ', '.join(f'{g} {r[3]:.10f}' for g, r in refs.items())
          + f' (spread {max(values) - min(values):.1e})')
    with open(os.path.join(out, 'cost.dat'), 'w') as f:
        f.write('# gauge_index boxes N cost M_AH error\n')
        for i, g in enumerate(gauges_):
            for grid, N, c, M, err, _ in table[g]:
                f.write(f'{i} {int(grid == "boxes")} {N} {c:.6g} {M:.12g} {err:.6g}\n')
    print(f'{"gauge":8} {"grid":6} ' + ' '.join(f'{"within " + format(t, ".0e"):>22}'
                                                for t in TARGETS))
    for g in gauges_:
        for grid in ('sinh', 'boxes'):
            rows = [(N, c, M, err) for gr, N, c, M, err, _ in table[g] if gr == grid]
            cells = []
            for target in TARGETS:
                best = cheapest([(N, c, M, err) for N, c, M, err in rows], target)
                cells.append(f'N = {best[0]}: {best[1]:.2e}' if best else 'not reached')
            print(f'{g:8} {grid:6} ' + ' '.join(f'{c:>22}' for c in cells))
            for N, c, M, err in rows:
                print(f'    N = {N:5d}  cost {c:9.3e}  M_AH {M:.10f}  error {err:.2e}')
            for gr, N, _, M, _, end in table[g]:
                if gr == grid and not math.isfinite(M):
                    print(f'    N = {N:5d}  {end}')
    return table


def integral(t, y, where):
    """The integral of y over equally spaced times t: Simpson's rule, with Simpson's 3/8 rule over
    the last three intervals when their number is odd."""
    n = len(t) - 1
    if n < 3:
        raise gd.DataError('fewer than four rows to integrate over', where)
    h = (t[-1] - t[0]) / n
    if np.max(np.abs(np.diff(t) - h)) > 1e-6 * h:
        raise gd.DataError('its rows are not equally spaced in t, which the integral needs', where)
    m = n if n % 2 == 0 else n - 3
    total = h / 3 * (y[0] + y[m] + 4 * np.sum(y[1:m:2]) + 2 * np.sum(y[2:m - 1:2])) if m else 0.0
    if m < n:
        total += 3 * h / 8 * (y[m] + 3 * y[m + 1] + 3 * y[m + 2] + y[m + 3])
    return float(total)


def budget_row(path):
    """The budget's numbers of a run with --flux-R 5,30 (NaN where a flux is NaN)."""
    col, params, end, ts = series(path, ('t', 'M_ah', 'm_R5', 'flux_R5', 'm_R30', 'flux_R30'))
    if 'M-ADM' not in params:
        raise gd.DataError('no M-ADM in its header (a run without matter?)', ts)
    t, M = col['t'], col['M_ah']
    flux5, flux30 = integral(t, col['flux_R5'], ts), integral(t, col['flux_R30'], ts)
    return {'N': int(params['N']), 'shell': float(params['M-ADM']) - M[0], 'fell': -flux5,
            'grew': M[-1] - M[0], 'left': flux30, 'between': col['m_R30'][-1] - M[-1],
            'id5': flux5 - (col['m_R5'][0] - col['m_R5'][-1]),
            'id30': flux30 - (col['m_R30'][0] - col['m_R30'][-1]),
            'end': end}


def budget(out):
    top = os.path.join(out, 'budget')
    if not os.path.isdir(top):  # a folder from before the budget was part of the study
        print(f'\n4. The energy budget: no folder {top} (rerun runs/accretion.sh to make it)')
        return
    print('\n4. The energy budget (sinh grid, --flux-R 5,30): of the shell\'s energy M_ADM - '
          'M_AH(0), what crossed R = 5 inwards (against M_AH\'s growth), what left through R = 30 '
          'and what lies between the horizon and R = 30 at the end; the identity\'s error '
          'integral of flux - (m(0) - m(end)) at each sphere, with its order')
    print(f'{"gauge":6} {"N":>5} {"shell":>10} {"fell in":>10} {"M_AH grew":>10} {"left":>10} '
          f'{"between":>9} {"error R=5":>10} {"order":>5} {"error R=30":>10} {"order":>5}')
    with open(os.path.join(out, 'budget.dat'), 'w') as f:
        f.write('# gauge_index N shell fell grew left between id5 id30\n')
        gauges_ = sorted((g for g in os.listdir(top) if not g.startswith('.')), key=order)
        for i, g in enumerate(gauges_):
            folder = os.path.join(top, g)
            rows = sorted((budget_row(os.path.join(folder, d)) for d in os.listdir(folder)
                           if re.fullmatch(r'N\d+', d)), key=lambda w: w['N'])
            for k, w in enumerate(rows):
                orders = ['', '']
                if k > 0:
                    for j, key in enumerate(('id5', 'id30')):
                        coarse, fine = abs(rows[k - 1][key]), abs(w[key])
                        if coarse > 0 and fine > 0:  # (an exact zero has no order)
                            fitted = math.log(coarse / fine) / math.log(w["N"] / rows[k - 1]["N"])
                            orders[j] = f"{fitted:.2f}"
                print(f'{g:6} {w["N"]:5d} {w["shell"]:10.7f} {w["fell"]:10.7f} {w["grew"]:10.7f} '
                      f'{w["left"]:10.7f} {w["between"]:9.2e} {w["id5"]:10.2e} {orders[0]:>5} '
                      f'{w["id30"]:10.2e} {orders[1]:>5}')
                if not w['end'].startswith('completed'):
                    print(f'  {g} N = {w["N"]}: {w["end"]}')
                f.write(f'{i} {w["N"]} ' + ' '.join(f'{w[key]:.12g}' for key in
                                                    ('shell', 'fell', 'grew', 'left', 'between',
                                                     'id5', 'id30')) + '\n')


def figures(out, runs, table):
    plt = gd.pyplot()
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 7))
    shown = {g: r for g, r in runs.items() if g not in FIGURE_LEAVES_OUT}
    for color, (g, r) in zip(gd.qualitative_colors(len(shown), 'gauges'), shown.items()):
        top.plot(r['t'], r['M_ah'], color=color, label=g)
        bottom.plot(r['t'], r['r_ah'], color=color, label=g)
        if r['rahA'] > 0:
            bottom.axhline(r['rah0'], color=color, lw=0.6, ls=':')
    top.set_ylabel('M_AH (M)')
    bottom.set_ylabel('r_AH (M); dotted: h')
    bottom.set_xlabel('t (M)')
    top.set_title('accretion of a scalar shell: the horizon left to grow and held')
    top.legend(fontsize=8)
    fig.tight_layout()
    gd.save_figure(fig, os.path.join(out, 'accretion.png'))
    fig, ax = plt.subplots()
    for color, g in zip(gd.qualitative_colors(len(table), 'gauges'), table):
        for grid, style in (('sinh', '-o'), ('boxes', '--s')):
            pts = [(c, err) for gr, _, c, _, err, _ in table[g]
                   if gr == grid and math.isfinite(err) and err > 0]
            if pts:
                ax.loglog(*zip(*pts), style, color=color, ms=3, label=f'{g}, {grid}')
    gd.finish(fig, ax, 'cost: N x RHS evaluations', '|M_AH - M_AH(sinh, finest)| at t = 60',
              "M_AH's error against cost", os.path.join(out, 'cost.png'))


def main(out):
    runs = gauges(out)
    verdicts(out)
    table = costs(out)
    budget(out)
    figures(out, runs, table)


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.stderr.write('usage: accretion.py OUT\n')
        sys.exit(2)
    gd.run_script(main, sys.argv[1])
