#!/usr/bin/env python3
"""plots/critical.py's fits against data whose answers are known: a discretely self-similar
Phi_center(T) with period Delta about T*, and masses M = c (A - p*)^gamma with a wiggle of
period Delta/(2 gamma) in ln(A - p*); and the runs' verdicts read from output files.

    /usr/bin/python3 tests/plots/test_critical.py PLOTS_DIR WORK_DIR
"""
import math
import os
import shutil
import sys

import numpy as np

plots, work = sys.argv[1], sys.argv[2]
sys.path.insert(0, plots)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import critical  # noqa: E402
from checks import check, done  # noqa: E402


def write_series(path, t, alpha, phi):
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, 'timeseries.dat'), 'w') as f:
        f.write('# t alpha_center Phi_center\n')
        for row in zip(t, alpha, phi):
            f.write(' '.join(f'{v:.17g}' for v in row) + '\n')
        f.write('# end: completed at t = 1\n')


shutil.rmtree(work, ignore_errors=True)
# 1. echoes: T = t (alpha = 1); an implosion, then Phi = 0.6 cos(2 pi ln(T* - T)/Delta) up to
# T* - T = exp(-7), then falling away (the field disperses)
for Delta, T_star in ((3.4453, 1.57), (3.0, 2.0)):
    t = np.linspace(0.0, T_star - math.exp(-9.0), 400001)
    x = np.log(np.maximum(T_star - t, 1e-300))
    echo = 0.6 * np.cos(2 * math.pi * x / Delta + 0.3)
    envelope = np.where(x > -7.0, 1.0, np.exp(-3.0 * (-7.0 - x)))
    implosion = np.where(t < T_star - 1.0, 0.3 * np.cos(t), 0.0)
    phi = np.where(t < T_star - 1.0, implosion, echo * envelope)
    path = os.path.join(work, f'echo-{Delta}')
    write_series(path, t, np.ones_like(t), phi)
    e = critical.echoes(path)
    check(abs(e['Delta'] / Delta - 1) < 0.01,
          f'Delta {Delta}: fitted {e["Delta"]:.4f} from {len(e["Tk"])} extrema (within 1%)')
    check(abs(e['T_star'] - T_star) < 1e-3, f'Delta {Delta}: T* {e["T_star"]:.6f} of {T_star}')
    check(len(e['Tk']) >= 4 and math.isfinite(e['error']) and e['error'] < 0.02 * Delta,
          f'Delta {Delta}: an error bar ({e["error"]:.4f}) from {len(e["Tk"])} extrema')
    check(all(T > T_star - 1.0 for T in e['Tk']), 'the implosion is not counted as an echo')
# too few extrema: no Delta claimed
t = np.linspace(0.0, 1.0, 1001)
write_series(os.path.join(work, 'flat'), t, np.ones_like(t), np.sin(3 * t))
e = critical.echoes(os.path.join(work, 'flat'))
check(math.isnan(e['Delta']), f'one extremum: no Delta ({e["Delta"]})')

# 2. mass scaling: the exponent through a wiggle, and the window
p_star, gamma, Delta = 0.3, 0.374, 3.4453
runs = []
for k in range(4, 33):
    A = p_star * (1 + 10 ** (-k / 4))
    d = A - p_star
    wiggle = 0.05 * math.sin(2 * math.pi * math.log(d) / (Delta / (2 * gamma)))
    M = 0.8 * d ** gamma * math.exp(wiggle)
    runs.append((A, 'collapse', M, M if k % 5 else math.nan))
runs.append((p_star * (1 - 1e-3), 'disperse', math.nan, math.nan))
used, left, g, err = critical.mass_scaling(runs, p_star, 1e-6, 1e-2, 2)
check(abs(g - gamma) < 3 * err + 0.005 and err < 0.02,
      f'gamma from the first masses: {g:.4f} +- {err:.4f} of {gamma}')
check(len(used) == 17 and not left, f'the window holds eps 1e-6 ... 1e-2: {len(used)} runs')
used, left, g, err = critical.mass_scaling(runs, p_star, 1e-6, 1e-2, 3)
check(len(left) == 3 and all(why == 'no final M_AH' for *_, why in left),
      f'runs without a final M_AH are left out and named ({len(left)})')

# 3. a run's verdict from its files
for name, horizon_rows, end, expected in (
        ('collapsed', ['0 nan nan nan', '1 0.1 0.2 0.1', '2 0.12 0.24 0.12'],
         '# end: completed at t = 2', ('collapse', 0.1, 0.12)),
        ('stopped-after', ['0 nan nan nan', '1 0.1 0.2 0.1'],
         '# end: stopped: the evolution became non-finite', ('collapse', 0.1, math.nan)),
        ('dispersed', ['0 nan nan nan', '1 nan nan nan'], '# end: completed at t = 2',
         ('disperse', math.nan, math.nan)),
        ('stopped', ['0 nan nan nan'], '# end: stopped: left the physical range',
         ('stopped', math.nan, math.nan))):
    path = os.path.join(work, name)
    os.makedirs(path)
    with open(os.path.join(path, 'horizon.dat'), 'w') as f:
        f.write('# t r_ah R_ah M_ah\n' + '\n'.join(horizon_rows) + '\n')
    with open(os.path.join(path, 'timeseries.dat'), 'w') as f:
        f.write('# t alpha_center\n0 1\n' + end + '\n')
    got = critical.run_result(path)
    same = got[0] == expected[0] and all(
        (math.isnan(a) and math.isnan(b)) or a == b for a, b in zip(got[1:], expected[1:]))
    check(same, f'{name}: {got}')

shutil.rmtree(work, ignore_errors=True)
done('plots/critical.py')
