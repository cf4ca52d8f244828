#!/usr/bin/env python3
"""The published study's signature, row by row, and its figures (runs/thesis.sh).

    /usr/bin/python3 plots/thesis.py OUT ROW [ROW ...]

OUT/ROW is one `gbssn1d converge` study (members N<n>/, convergence.dat, scaled_H.dat),
OUT/ROW.cmd the command that made it (runs/lib.sh's record: `--out @OUT` stands for OUT/ROW, a
trailing `# binary ...` names the program's hash) and OUT/ROW.status its exit status. Writes
OUT/mechanisms.dat (one row per study, named columns, words without spaces:
numpy.genfromtxt(f, names=True, dtype=None, encoding=None) reads it), OUT/commands.txt (each
row's command and full verdict), OUT/signature.txt (which rows show each feature of the
published signature) and the figures OUT/fig*.png.

The published signature (the 3D study's Figs. 3.6-3.8), as tested per row on H_L2_R (the L2
norm of H over areal radius 2.5 M <= R <= 12 M: the same place in every gauge):
  finer_above     the finer member's H lies above the coarser one's for at least 5% of the
                  output times of (0, 20] M (the published figures' range), at some pair of
                  neighbouring members
  finer_earlier   the finer pair's first such time is earlier than the coarser pair's
                  ("the 64-point run is contaminated earlier")
  from_2M         the first such time (any pair) lies in [1, 5] M ("errors from about 2 M")
  shrink_first    (stretch rows) the stretch does not converge over the first 20 M (a pairwise
                  order of its RMS H there below 2.5) while the same configuration's shrink to
                  0.6 M at the same spacings does (both orders at least 2.5)
"""
import math
import os
import re
import shlex
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gbssn1d_data as gd  # noqa: E402

WINDOWS = [(0.0, 20.0), (20.0, 100.0)]
NORM = 'H_L2_R'
THRESHOLD = 2.5  # design order 4 minus the verdict's tolerance 1.5
ABOVE_FRACTION = 0.05
LATE_START, EARLY = 1.0, 5.0
FIGURE_RANGE = 20.0  # the published figures' time range


def members(columns):
    return sorted({int(c[len(NORM) + 2:]) for c in columns if c.startswith(NORM + '_N')})


def verdict_line(path):
    """The converge verdict's whole line ('no verdict' if none)."""
    for line in gd.read_text(path).splitlines():
        if line.startswith('# verdict:'):
            return line[len('# verdict:'):].strip()
    return 'no verdict'


def verdict_of(path):
    """The converge verdict's class: the words before the first ':' of its 'verdict:' line."""
    return verdict_line(path).split(':')[0].strip()


def study(out, name):
    path = os.path.join(out, name, 'convergence.dat')
    status_file = os.path.join(out, name + '.status')
    try:
        status = int(gd.read_text(status_file).strip())
    except ValueError:
        raise gd.DataError('not an exit status (runs/thesis.sh writes one)', status_file)
    command = gd.read_text(os.path.join(out, name + '.cmd')).strip()
    command = re.sub(r'\s*# binary \S+$', '', command).replace('@OUT', os.path.join(out, name))
    try:  # as a user would type it: printf %q's escapes (24\,32) undone, quotes only where needed
        command = shlex.join(shlex.split(command))
    except ValueError:
        raise gd.DataError('not a shell command', os.path.join(out, name + '.cmd'))
    params = gd.params_of(gd.read_text(os.path.join(out, name, 'config.toml')).splitlines())
    columns, parsed = gd.parse(gd.read_text(path), path)
    data = parsed[0][1] if parsed else np.zeros((0, len(columns)))
    Ns = members(columns)
    t = gd.column(columns, data, 't', path)
    H = {n: gd.column(columns, data, f'{NORM}_N{n}', path) for n in Ns}
    spacing = {}
    for n in Ns:
        head = gd.header_params(gd.read_text(os.path.join(out, name, f'N{n}', 'timeseries.dat')))
        spacing[n] = float(head['dr-min'])
    s = {'name': name, 'status': status, 'command': command, 'params': params, 'Ns': Ns,
         't': t, 'H': H, 'spacing': spacing, 'verdict': verdict_of(path),
         'verdict_line': verdict_line(path),
         'tend': float(t[-1]) if len(t) else 0.0}
    # orders of the RMS over each window, per pair of neighbouring members
    s['orders'] = []
    for t0, t1 in WINDOWS:
        sel = (t > t0) & (t <= t1)
        row = []
        for a, b in zip(Ns, Ns[1:]):
            if sel.sum() == 0 or t[-1] < t1:
                row.append(math.nan)
                continue
            ea = math.sqrt(np.mean(H[a][sel] ** 2))
            eb = math.sqrt(np.mean(H[b][sel] ** 2))
            row.append(math.log(ea / eb) / math.log(b / a) if ea > 0 and eb > 0 else math.nan)
        s['orders'].append(row)
    # the first time, and the fraction of output times, with the finer member above the coarser
    s['first_above'], s['frac_above'] = [], []
    sel = (t > 0) & (t <= FIGURE_RANGE)
    for a, b in zip(Ns, Ns[1:]):
        above = (t > 0) & (H[b] > H[a])
        s['first_above'].append(float(t[above][0]) if above.any() else math.nan)
        s['frac_above'].append(float((above & sel).sum()) / max(1, int(sel.sum())))
    return s


def features(s, shrink):
    fa, first = s['frac_above'], s['first_above']
    f = {}
    f['finer_above'] = any(x >= ABOVE_FRACTION for x in fa)
    f['finer_earlier'] = (len(first) > 1 and not math.isnan(first[-1])
                          and (math.isnan(first[-2]) or first[-1] < first[-2]))
    finite = [x for x in first if not math.isnan(x)]
    f['from_2M'] = bool(finite) and LATE_START <= min(finite) <= EARLY and f['finer_above']
    if shrink is not None:
        early = shrink['orders'][0]
        f['shrink_first'] = (any(p < THRESHOLD for p in s['orders'][0])
                             and all(not math.isnan(p) and p >= THRESHOLD for p in early))
    else:
        f['shrink_first'] = None
    return f


def text(x, fmt='{:.2f}'):
    if x is None:
        return '-'
    if isinstance(x, bool):
        return 'yes' if x else 'no'
    if isinstance(x, float) and math.isnan(x):
        return '-'
    return fmt.format(x)


def word(s):
    """A table field without spaces (numpy.genfromtxt splits at whitespace)."""
    return re.sub(r'\s+', '-', s.strip()) or '-'


def spacing_text(dr):
    return f'M/{1 / dr:.3g}'


def mechanism_columns(p):
    """The candidate mechanisms' settings of a study, from its config.toml."""
    return {
        'normal': p.get('rah-normal', '-'),
        'driver': p.get('driver-advection', '-'),
        'cadence': ('box-substage' if p.get('rah-variant') == 'box-substage'
                    else p.get('ah-every', '-')),
        'interp': p.get('time-interp', '-'),
        'profile': (p.get('rah-profile', '-') + ('/' + p['rah-width']
                                                   if p.get('rah-profile') == 'rational' else '')),
        'rmax': p.get('rmax', '-'),
        'ko': p.get('ko-sigma', '-'),
    }


def write_table(out, studies):
    by_name = {s['name']: s for s in studies}
    cols = ['row', 'data', 'h', 'normal', 'driver', 'cadence', 'interp', 'profile', 'rmax', 'ko',
            'spacings', 'p_0_20_a', 'p_0_20_b', 'p_20_100_a', 'p_20_100_b', 't_above_a',
            't_above_b', 'frac_above_a', 'frac_above_b', 'finer_above', 'finer_earlier',
            'from_2M', 'shrink_first', 'tend', 'verdict']
    lines = [
        '# ' + ' '.join(cols),
        '# gbssn1d runs/thesis.sh: the published signature per configuration (plots/thesis.py)',
        f'# norm: {NORM} (areal radius 2.5 M <= R <= 12 M); members N = 24, 32, 48 unless the row '
        'says (spacings: the finest box\'s, coarse to fine)',
        '# p_T0_T1_a, _b: the order of the RMS over t in (T0, T1] M of the norm, at the coarser '
        '(a) and the finer (b) pair of neighbouring members',
        '# t_above_a, _b: the first output time with the finer member\'s norm above the coarser '
        'one\'s; frac_above: the fraction of output times in (0, 20] M so',
        f'# finer_above: frac_above >= {ABOVE_FRACTION} at some pair; finer_earlier: t_above_b < '
        f't_above_a; from_2M: the first such time in [{LATE_START:g}, {EARLY:g}] M; shrink_first: an order over '
        f'(0, 20] M below {THRESHOLD} while the same configuration\'s shrink to 0.6 M has both '
        f'orders there >= {THRESHOLD}',
        '# verdict: gbssn1d converge\'s class (converges | converges until the round-off floor | '
        'pre-asymptotic | does not converge), over every monitored quantity and the whole run',
        '# words have no spaces (a verdict\'s words joined by -); each row\'s command and whole '
        'verdict: commands.txt',
    ]
    commands = ['# gbssn1d runs/thesis.sh: each row of mechanisms.dat, the command that makes it '
                'alone and its whole verdict (tab-separated: row, command, verdict)']
    for s in studies:
        p = s['params']
        h = p.get('rah0', '-') if float(p.get('rahA', '0')) != 0 else 'standard'
        shrink = None
        if h == '0.89':
            shrink = by_name.get(s['name'].replace('h0.89', 'h0.6'))
        s['features'] = features(s, shrink)
        m = mechanism_columns(p)
        o = s['orders']
        f = s['features']
        vals = [s['name'], p.get('id', '-'), h, m['normal'], m['driver'], m['cadence'],
                m['interp'], m['profile'], m['rmax'], m['ko'],
                ','.join(spacing_text(s['spacing'][n]) for n in s['Ns']),
                text(o[0][0]), text(o[0][1]), text(o[1][0]), text(o[1][1]),
                text(s['first_above'][0], '{:g}'), text(s['first_above'][1], '{:g}'),
                text(s['frac_above'][0]), text(s['frac_above'][1]),
                text(f['finer_above']), text(f['finer_earlier']), text(f['from_2M']),
                text(f['shrink_first']), text(s['tend'], '{:g}'), word(s['verdict'])]
        lines.append(' '.join(vals))
        commands.append(f"{s['name']}\t{s['command']}\t{s['verdict_line']}")
    for name, text_lines in (('mechanisms.dat', lines), ('commands.txt', commands)):
        with open(os.path.join(out, name + '.new'), 'w') as fh:
            fh.write('\n'.join(text_lines) + '\n')
        os.replace(os.path.join(out, name + '.new'), os.path.join(out, name))


def write_signature(out, studies):
    names = {
        'finer_above': 'the finer run\'s H above the coarser one\'s (>= 5% of the times to 20 M)',
        'finer_earlier': 'the finer pair contaminated earlier',
        'from_2M': 'from about 2 M (first time in [1, 5] M)',
        'shrink_first': 'the stretch fails while the shrink converges over the first 20 M',
    }
    lines = []
    for key, what in names.items():
        yes = [s['name'] for s in studies if s['features'].get(key)]
        lines.append(f'{what}: {len(yes)} rows')
        lines += [f'  {n}' for n in yes]
    full = [s['name'] for s in studies
            if s['features']['finer_above'] and s['features']['finer_earlier']
            and s['features']['from_2M'] and s['features']['shrink_first']]
    lines.append(f'every feature at once (stretch rows): {len(full)} rows')
    lines += [f'  {n}' for n in full]
    with open(os.path.join(out, 'signature.txt'), 'w') as fh:
        fh.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))


def resolution_colors(Ns):
    return dict(zip(Ns, gd.sequential_colors(len(Ns))))


def norm_panel(ax, s, tmax=None, title=''):
    colors = resolution_colors(s['Ns'])
    for n in s['Ns']:
        sel = s['t'] > 0
        if tmax is not None:
            sel &= s['t'] <= tmax
        ax.semilogy(s['t'][sel], s['H'][n][sel], color=colors[n],
                    label=f"N = {n} ({spacing_text(s['spacing'][n])})")
    ax.set_xlabel('time t / M')
    ax.set_ylabel('H: L2 norm over 2.5 M <= R <= 12 M')
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)


def box_edges(params, r_max):
    """The outer edges rmax / 2^l (l = 1 ... levels - 1) of a boxes run's fine boxes below
    r_max; none for a single grid."""
    if params.get('grid') != 'boxes':
        return []
    try:
        rmax, levels = float(params['rmax']), int(params['levels'])
    except (KeyError, ValueError):
        return []
    return [rmax / 2 ** l for l in range(1, levels) if rmax / 2 ** l <= r_max]


def figures(out, studies, plt):
    by = {s['name']: s for s in studies}

    def have(*names):
        missing = [n for n in names if n not in by]
        if missing:
            print(f"a figure left out: no row {', '.join(missing)}")
        return not missing

    # Figs. 3.2-3.4: the horizon's coordinate radius
    if have(*[f'maximal-{h}-{kind}' for h in ('standard', 'h0.89', 'h0.6')
              for kind in ('thesis', 'defaults')]):
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
        for ax, kind in zip(axes, ['thesis', 'defaults']):
            for name, label, color in [('standard', 'standard gauge', gd.QUALITATIVE[0]),
                                       ('h0.89', 'stretch to 0.89 M', gd.QUALITATIVE[1]),
                                       ('h0.6', 'shrink to 0.6 M', gd.QUALITATIVE[2])]:
                s = by[f'maximal-{name}-{kind}']
                for n, ls in zip(s['Ns'], gd.LINESTYLES):
                    ts = gd.blocks(os.path.join(out, s['name'], f'N{n}', 'timeseries.dat'))[0][1]
                    ax.plot(ts['t'], ts['r_ah'], color=color, ls=ls,
                            label=f"{label}, {spacing_text(s['spacing'][n])}")
            ax.set_xlabel('time t / M')
            ax.set_ylabel('apparent horizon radius r_AH / M')
            ax.set_title('published configuration' if kind == 'thesis'
                         else 'gbssn1d defaults (same boxes)', fontsize=9)
            ax.legend(fontsize=6, ncol=2)
        fig.suptitle('Figs. 3.2-3.4: horizon radius, maximal trumpet, 7 boxes to 128 M, A = 0.5',
                     fontsize=10)
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        fig.savefig(os.path.join(out, 'fig3.2-3.4_horizon.png'), dpi=110)
        plt.close(fig)

    # Fig. 3.5: H along the axis at 20 M, the finer resolutions scaled for 4th order
    names = ['maximal-standard-thesis', 'maximal-h0.89-thesis', 'maximal-h0.89-defaults']
    if have(*names):
        fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
        for ax, name, title in zip(axes, names, ['standard gauge, published configuration',
                                                 'stretch to 0.89 M, published configuration',
                                                 'stretch to 0.89 M, gbssn1d defaults']):
            s = by[name]
            t, tab = gd.blocks(os.path.join(out, name, 'scaled_H.dat'))[0]
            colors = resolution_colors(s['Ns'])
            for k, n in enumerate(s['Ns']):
                col = f'H_N{n}' if k == 0 else f'H_N{n}_scaled'
                lab = (f"{spacing_text(s['spacing'][n])}" if k == 0 else
                       f"{spacing_text(s['spacing'][n])} x ({n}/{s['Ns'][0]})^4")
                ax.plot(tab['r'], tab[col], color=colors[n], label=lab)
            # the boxes' outer edges (rmax / 2^l), where the interpolated boundary values make
            # the spikes: marked, so that they are not read as the horizon's or the gauge's
            edges = box_edges(s['params'], float(np.max(tab['r'])))
            for k, e in enumerate(edges):
                ax.axvline(e, color='0.6', ls=':', lw=0.8,
                           label='box edges' if k == 0 else None)
            ax.set_xlabel('coordinate radius r / M')
            ax.set_ylabel('Hamiltonian constraint H (scaled)')
            ax.set_title(f'{title}, t = {t:g} M', fontsize=9)
            ax.legend(fontsize=7)
        fig.suptitle('Fig. 3.5: H at 20 M scaled for 4th order (curves on one another: 4th order)',
                     fontsize=10)
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        fig.savefig(os.path.join(out, 'fig3.5_scaled_H.png'), dpi=110)
        plt.close(fig)

    # Fig. 3.6: standard gauge and the shrink; Figs. 3.7, 3.8: the stretch, and its first 20 M
    for fig_name, cases in [
            ('fig3.6_standard_shrink.png',
             [('maximal-standard-thesis', 'standard gauge, published configuration', None),
              ('maximal-h0.6-thesis', 'shrink to 0.6 M, published configuration', None),
              ('maximal-h0.6-thesis-vfine', 'shrink to 0.6 M, published configuration, '
               'two steps finer', None)]),
            ('fig3.7-3.8_stretch.png',
             [('maximal-h0.89-thesis', 'stretch to 0.89 M, published configuration', 20.0),
              ('maximal-h0.89-thesis-fine', 'the same one step finer', 20.0),
              ('maximal-h0.89-all-but-cadence-fine', 'one step finer, h_AH at every substage',
               20.0)])]:
        if not have(*[c[0] for c in cases]):
            continue
        fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
        for ax, (name, title, tmax) in zip(axes, cases):
            o = by[name]['orders'][0]
            norm_panel(ax, by[name], tmax,
                       f"{title}\nH's orders over (0, 20] M: {text(o[0])}, {text(o[1])}\n"
                       f"verdict over all quantities: {by[name]['verdict']}")
        fig.suptitle('maximal trumpet, 7 boxes to 128 M, A = 0.5', fontsize=10)
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        fig.savefig(os.path.join(out, fig_name), dpi=110)
        plt.close(fig)


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    out, names = argv[1], argv[2:]
    studies = [study(out, n) for n in names]
    write_table(out, studies)
    write_signature(out, studies)
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    gd.style(plt)
    figures(out, studies, plt)


if __name__ == '__main__':
    gd.run_script(main, sys.argv)
