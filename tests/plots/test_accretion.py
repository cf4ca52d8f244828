#!/usr/bin/env python3
"""plots/accretion.py on runs whose answers are known: M_AH(t) growing by a known amount between
known times, r_AH straying from h by a known amount while it grows; M_AH against cost with a
known error per run, a coarse run that lands near the answer by chance, and a run that stopped;
the energy through two spheres whose fluxes integrate to known amounts, with known errors.

    /usr/bin/python3 tests/plots/test_accretion.py PLOTS_DIR WORK_DIR
"""
import contextlib
import io
import math
import os
import re
import shutil
import sys

import numpy as np

plots, work = sys.argv[1], sys.argv[2]
sys.path.insert(0, plots)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import accretion  # noqa: E402
from checks import check, done  # noqa: E402


def write_run(path, t, r_ah, m_ah, rahA, rah0, N, end='completed at t = 80', log=None):
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, 'timeseries.dat'), 'w') as f:
        f.write('# t alpha_center r_ah M_ah\n# gbssn1d 0.1.0\n')
        f.write(f'# N = {N}\n# rahA = {rahA}\n# rah0 = {rah0}\n')
        for row in zip(t, np.ones_like(t), r_ah, m_ah):
            f.write(' '.join(f'{v:.17g}' for v in row) + '\n')
        f.write(f'# end: {end}\n')
    if log is not None:
        with open(path + '.log', 'w') as f:
            f.write(log)


shutil.rmtree(work, ignore_errors=True)
# 1. gauges: M_AH = 1 + 0.4 s(t), s a smooth step from t = 10 to 20; the free horizon's r_AH
# grows as 2 M_AH, the held one's strays from h = 1 by 0.3 sin(pi s) while M_AH grows and by 0.5
# before and after (at t = 5 and 50, which the stray while M_AH grows must not see)
t = np.linspace(0.0, 80.0, 3201)
s = np.clip((t - 10.0) / 10.0, 0.0, 1.0)
s = s * s * (3 - 2 * s)
m = 1.0 + 0.4 * s
for N, dm in ((400, 2e-5), (800, 1e-6)):
    write_run(os.path.join(work, 'gauges', f'N{N}', 'free'), t, 2 * m, m, 0, 1.0, N)
    spikes = 0.5 * (np.exp(-((t - 5) / 0.5) ** 2) + np.exp(-((t - 50) / 0.5) ** 2))
    write_run(os.path.join(work, 'gauges', f'N{N}', 'h1.0'), t,
              1.0 + 0.3 * np.sin(math.pi * s) + spikes, m + dm * s, 0.5, 1.0, N)
# 2. a converge study's verdict and its warning
os.makedirs(os.path.join(work, 'converge', 'free-boxes-N64'))
with open(os.path.join(work, 'converge', 'free-boxes-N64', 'convergence.dat'), 'w') as f:
    f.write('# verdict: does not converge: H converges (its lowest order 3.1: H_L2_R at N = 64 '
            'and 128); the worst: alpha at N = 64, 128 and 256: the order ...\n# t\n0\n')
with open(os.path.join(work, 'converge', 'free-boxes-N64.log'), 'w') as f:
    f.write('gbssn1d converge: warning: the members\' hierarchies step by different dt (...)\n')
# 3. cost: M_AH = 2 + 2e-3 (100/N)^4 on sinh grids, N = 100 ... 1600 with 10 N evaluations; the
# N = 141 run lands within 1e-6 of the answer by chance (its error changes sign there), and on
# boxes (M_AH = 2 + 1e-4 (48/N)^4, 100 N evaluations) the N = 48 run stopped
reached = 'gbssn1d: reached t = 60 in 0.1 s ({} steps, {} RHS evaluations)\n'
for gauge in ('free', 'h1.0'):
    for N in (100, 141, 200, 400, 800, 1600):
        M = 2.0 + (5e-7 if N == 141 else 2e-3 * (100 / N) ** 4)
        write_run(os.path.join(work, 'cost', gauge, f'sinh-N{N}'), t[:3], np.ones(3), np.full(3, M),
                  0.5 if gauge != 'free' else 0, 1.0, N, 'completed at t = 60',
                  reached.format(N, 10 * N))
    for N in (48, 96, 192):
        M = 2.0 + 1e-4 * (48 / N) ** 4
        write_run(os.path.join(work, 'cost', gauge, f'boxes-N{N}'), t[:3], np.ones(3),
                  np.full(3, M), 0, 1.0, N,
                  'stopped: the evolution became non-finite at t = 3, r = 0.5 in chi' if N == 48
                  else 'completed at t = 60',
                  'gbssn1d: error: ...\n' if N == 48 else reached.format(N, 100 * N))

# 4. budget: M_ADM = 1.7, M_AH = 1 + 0.4 E(t - 15) with E(x) = (1 + erf(x/2))/2; flux_R5 = -0.4
# E' (what falls in), m_R5 = M_AH + e5 E (an identity's error e5); flux_R30 = 0.3 E'(t - 25), m_R30
# = 1.7 - 0.3 E(t - 25) + e30 E(t - 25); at N = 400 and 800 the errors fall 16-fold (order 4).
# 1601 rows (an even number of intervals) at N = 400, 1602 at N = 800 (odd: the 3/8 rule's end)
E = lambda x: 0.5 * (1 + np.vectorize(math.erf)(x / 2))  # noqa: E731
dE = lambda x: np.exp(-(x / 2) ** 2) / (2 * math.sqrt(math.pi))  # noqa: E731
for N, e5, e30, rows_ in ((400, 1.6e-5, -3.2e-5, 1601), (800, 1e-6, -2e-6, 1602)):
    tb = np.linspace(0.0, 80.0 * (rows_ - 1) / 1600, rows_)
    M_ah = 1 + 0.4 * E(tb - 15)
    cols = (tb, M_ah, M_ah + e5 * E(tb - 15), -0.4 * dE(tb - 15),
            1.7 - 0.3 * E(tb - 25) + e30 * E(tb - 25), 0.3 * dE(tb - 25))
    folder = os.path.join(work, 'budget', 'free', f'N{N}')
    os.makedirs(folder)
    with open(os.path.join(folder, 'timeseries.dat'), 'w') as f:
        f.write(f'# t M_ah m_R5 flux_R5 m_R30 flux_R30\n# N = {N}\n# M-ADM = 1.7\n')
        for row in zip(*cols):
            f.write(' '.join(f'{v:.17g}' for v in row) + '\n')
        f.write('# end: completed at t = 80\n')

printed = io.StringIO()
with contextlib.redirect_stdout(printed):
    accretion.main(work)
text = printed.getvalue()
print(text)

rows = np.loadtxt(os.path.join(work, 'gauges.dat'), ndmin=2)
# N, rahA, h, M0, M_end, growth, r_end, off, stray, dM
held = {int(r[0]): r for r in rows if r[1] > 0}
check(abs(held[400][8] - 0.3) < 1e-4,
      f'the stray while M_AH grows (5% to 95% of its growth): {held[400][8]:.4f} (0.3; 0.5 '
      f'outside those times)')
check(abs(held[400][5] - 0.4) < 1e-4, f'the growth: {held[400][5]:.6f} of 0.4')
check(abs(held[400][9] - 2e-5 / 1.4) < 1e-9 and abs(held[800][9] - 1e-6 / 1.4) < 1e-10,
      f'the final M_AH against the free run\'s, at each N: {held[400][9]:.3e}, {held[800][9]:.3e}')
check(abs(held[400][7]) < 1e-12, 'r_AH ends at h')
check('the worst: alpha at N = 64, 128 and 256; warned: the hierarchies step by different dt'
      in text, 'the verdict line names the worst quantity and the warning')
cost = np.loadtxt(os.path.join(work, 'cost.dat'), ndmin=2)
sinh = cost[(cost[:, 0] == 0) & (cost[:, 1] == 0)]
check(np.allclose(sinh[:, 3], 10 * sinh[:, 2] ** 2), 'cost = N x RHS evaluations')
ref = 2e-3 / 16 ** 4
expected = np.where(sinh[:, 2] == 141, 5e-7, 2e-3 * (100 / sinh[:, 2]) ** 4) - ref
check(np.allclose(sinh[:, 5], np.abs(expected), rtol=1e-5, atol=1e-15),
      'the error against the same gauge\'s finest sinh run')


def cheapest(prefix):
    line = next(l for l in text.splitlines() if l.startswith(prefix))
    return re.findall(r'N = (\d+): (\S+)|(not reached)', line)


# within 1e-3: from N = 141 (5e-7, and every finer run within it); within 1e-4: N = 141 lands
# within it by chance but N = 200 (1.25e-4) does not, so from N = 400 (7.8e-6), also within 1e-5
got = cheapest('free     sinh')
check(got == [('141', '1.99e+05', ''), ('400', '1.60e+06', ''), ('400', '1.60e+06', '')],
      f'the cheapest sinh runs within 1e-3, 1e-4, 1e-5: {got}')
# boxes: N = 48 stopped, so nothing coarser than N = 96 counts; 96 (6.2e-6) is within 1e-5
got = cheapest('h1.0     boxes')
check(got == [('96', '9.22e+05', '')] * 3, f'a stopped coarse run is not counted: {got}')
stopped = [l for l in text.splitlines() if 'stopped: the evolution became non-finite' in l]
check(len(stopped) == 2, f'the stopped boxes run is named, once per gauge ({len(stopped)})')
budget = np.loadtxt(os.path.join(work, 'budget.dat'), ndmin=2)
# gauge_index N shell fell grew left between id5 id30
b400, b800 = budget[0], budget[1]
check(abs(b400[2] - 0.7) < 1e-12 and abs(b400[3] - 0.4) < 1e-8 and abs(b400[5] - 0.3) < 1e-8,
      f'the shell 0.7, what fell in 0.4 and what left 0.3: {b400[2]:.9f}, {b400[3]:.9f}, '
      f'{b400[5]:.9f}')
check(abs(b400[4] - 0.4) < 1e-12, f'M_AH grew by 0.4: {b400[4]:.12f}')
check(abs(b400[7] - 1.6e-5) < 1e-9 and abs(b800[7] - 1e-6) < 1e-9, f'the error at R = 5: '
      f'{b400[7]:.3e}, {b800[7]:.3e} (1.6e-5, 1e-6; Simpson with the 3/8 end at N = 800)')
check(abs(b400[8] + 3.2e-5) < 1e-9 and abs(b400[6] + 3.2e-5) < 1e-9,
      f'the error at R = 30 and what lies between at the end: {b400[8]:.3e}, {b400[6]:.3e}')
line = next(l for l in text.splitlines() if l.startswith('free     800'))
check(line.split()[8] == '4.00' and line.split()[10] == '4.00',
      f'the identity\'s orders between N = 400 and 800: {line}')
# the rule itself: exact for cubics with an even and an odd number of intervals (Simpson, then
# Simpson with the 3/8 rule's end), and rows not equally spaced are refused
for n in (4, 5, 7):
    tc = np.linspace(0.0, 2.0, n + 1)
    got = accretion.integral(tc, tc ** 3 - tc, 'cubic')
    check(abs(got - 2.0) < 1e-13, f'the integral of t^3 - t over [0, 2] with {n} intervals: {got}')
try:
    accretion.integral(np.array([0.0, 1.0, 2.5, 3.0, 4.0]), np.ones(5), 'uneven')
    check(False, 'rows not equally spaced are refused')
except accretion.gd.DataError as e:
    check('not equally spaced' in str(e), f'rows not equally spaced are refused: {e}')
check(os.path.exists(os.path.join(work, 'accretion.png'))
      and os.path.exists(os.path.join(work, 'cost.png')), 'both figures drawn')

# a study folder from before the budget: its table says so, the others and the figures stand
shutil.rmtree(os.path.join(work, 'budget'))
os.remove(os.path.join(work, 'accretion.png'))
printed = io.StringIO()
with contextlib.redirect_stdout(printed):
    accretion.main(work)
check('4. The energy budget: no folder' in printed.getvalue()
      and os.path.exists(os.path.join(work, 'accretion.png')),
      'without budget/ the table says so and the figures are drawn')

done('plots/accretion.py')
