#!/usr/bin/env python3
"""r_AH(t) (or another column of horizon.dat / timeseries.dat) for several runs in one PNG,
each labelled by the parameters recorded in its header (--label-by; those that are the same in
every run go into the title instead).

  plot_horizons.py out/horizon/*/horizon.dat -o r_ah.png [--label-by rah0,rahA,N] [-y r_ah]

Up to seven runs share one panel, a colour each. More runs are split into panels by the value
of the first --label-by parameter that differs between them (a panel per rahA for --label-by
rahA,rah0), with a colour per value of the second (the same colour means the same value in
every panel: one legend for the figure) and line styles for any further ones. Runs that this
does not fit go into panels of up to seven in the order of their parameters, coloured from one
sequential map (darker: later). Curves that coincide are drawn in different line styles and
named in a note. --target draws each shifted run's target radius rah0 as a dotted line.
"""
import argparse
import textwrap
import math
import sys

import numpy as np

from gbssn1d_data import (LINESTYLES, QUALITATIVE, axis_label, column, header_params,
                          label_keys, parse, pyplot, read_text, run_description, run_label,
                          run_script, sequential_colors, shifted, sort_key, save_figure)


def phrase(key, value):
    return f'{key} = {value}'


def load(paths, y):
    runs = []
    for path in paths:
        text = read_text(path)
        columns, blocks = parse(text, path)
        data = blocks[0][1]
        values = column(columns, data, y, path)
        found = np.isfinite(values).any()
        if not found:
            sys.stderr.write(f'note: {path} has no finite {y} (no horizon found); '
                             f'its legend entry has no curve\n')
        runs.append({'path': path, 'params': header_params(text), 'found': found,
                     't': column(columns, data, 't', path), 'y': values})
    return runs


def layout(runs, keys):
    """How the runs are drawn: a list of panels (title, runs) and, per run, 'color', 'ls' and
    'label' set; returns (panels, figure legend handles or None)."""
    import matplotlib.lines as mlines
    per_panel = len(QUALITATIVE)
    if len(runs) <= per_panel:  # one panel, a colour per run
        for run, color in zip(runs, QUALITATIVE):
            run.update(color=color, ls='-', label=', '.join(
                phrase(k, run['params'].get(k, '?')) for k in keys) or run_label(run['path']))
        return [('', runs)], None
    values = {k: sorted({r['params'].get(k) for r in runs}, key=sort_key) for k in keys}
    if len(keys) >= 2 and len(values[keys[1]]) <= per_panel:
        styles = sorted({tuple(r['params'].get(k) for k in keys[2:]) for r in runs},
                        key=lambda v: [sort_key(x) for x in v])
        if len(styles) <= len(LINESTYLES):
            panel_key, color_key, rest = keys[0], keys[1], keys[2:]
            colors = dict(zip(values[color_key], QUALITATIVE))
            handles = []
            for v in values[color_key]:
                handles.append(mlines.Line2D([], [], color=colors[v], label=phrase(color_key, v)))
            for s, ls in zip(styles, LINESTYLES):
                if rest:
                    handles.append(mlines.Line2D([], [], color='gray', ls=ls, label=', '.join(
                        phrase(k, x) for k, x in zip(rest, s))))
            panels = []
            for v in values[panel_key]:
                members = [r for r in runs if r['params'].get(panel_key) == v]
                for r in members:
                    p = r['params']
                    r.update(color=colors[p.get(color_key)],
                             ls=LINESTYLES[styles.index(tuple(p.get(k) for k in rest))],
                             label=phrase(color_key, p.get(color_key)))
                title = phrase(panel_key, v)
                if panel_key == 'rahA' and not shifted({'rahA': v}):
                    title += ' (no horizon shift)'
                panels.append((title, members))
            return panels, handles
    # anything else: panels of up to seven, one sequential colour map over all the runs
    colors = sequential_colors(len(runs))
    for run, color in zip(runs, colors):
        run.update(color=color, ls='-', label=', '.join(
            phrase(k, run['params'].get(k, '?')) for k in keys) or run_label(run['path']))
    return [('', runs[k:k + per_panel]) for k in range(0, len(runs), per_panel)], None


def coinciding(members):
    """Groups (lists of runs, the first drawn solid) of runs whose curves are identical."""
    groups = []
    for run in members:
        for group in groups:
            first = group[0]
            if (len(first['t']) == len(run['t']) and np.array_equal(first['t'], run['t'])
                    and np.array_equal(first['y'], run['y'], equal_nan=True)):
                group.append(run)
                break
        else:
            groups.append([run])
    return [g for g in groups if len(g) > 1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('files', nargs='+')
    ap.add_argument('-y', default='r_ah', help='column to plot (default r_ah)')
    ap.add_argument('--label-by', default='id,rah0,rahA,N',
                    help='header parameters in the labels; the first that differs between the '
                         'runs groups them into panels when they do not fit in one')
    ap.add_argument('--target', action='store_true', help='draw each run\'s rah0 as a dotted line')
    ap.add_argument('--title', default=None,
                    help='default: the apparent horizon\'s coordinate radius for -y r_ah, '
                         'else the column\'s name; what was run is written below it')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    runs = load(a.files, a.y)
    plt = pyplot()
    import matplotlib.lines as mlines
    wanted = a.label_by.split(',')
    params_list = [r['params'] for r in runs]
    keys = [k for k in wanted if len({p.get(k) for p in params_list}) > 1]
    if not keys and len(runs) > 1:  # the chosen parameters do not tell the runs apart
        keys = label_keys(params_list)[:3]
    runs.sort(key=lambda r: [sort_key(r['params'].get(k)) for k in keys])
    panels, handles = layout(runs, keys)
    n = len(panels)
    cols = 1 if n == 1 else 2 if n in (2, 4) else 3
    rows = math.ceil(n / cols)
    size = (7 if cols == 1 else 5.2 * cols, 4.5 if rows == 1 else 3.4 * rows)
    fig, axes = plt.subplots(rows, cols, sharex=True, sharey=True, squeeze=False, figsize=size)
    for p, (panel_title, members) in enumerate(panels):
        ax = axes[p // cols][p % cols]
        # coinciding curves: the later ones dashed, dotted, ... over the first, and a note
        same = coinciding(members)
        for group in same:
            for k, run in enumerate(group[1:]):
                run['ls'] = LINESTYLES[1 + k % (len(LINESTYLES) - 1)]
        targets = {}
        for run in members:
            label = run['label'] + ('' if run['found'] else ' (no horizon found)')
            ax.plot(run['t'], run['y'], color=run['color'], ls=run['ls'], label=label,
                    lw=1.6 if run['ls'] == '-' else 2.0)
            if a.target and 'rah0' in run['params'] and shifted(run['params']):
                targets.setdefault(float(run['params']['rah0']), set()).add(run['color'])
        target_colors = set()
        for h, colors in targets.items():
            color = colors.pop() if len(colors) == 1 else 'dimgray'
            target_colors.add(color)
            ax.axhline(h, color=color, ls=':', lw=1.2)
        notes = [f'identical curves: {", ".join(r["label"] for r in group)}' for group in same]
        if notes:
            ax.text(0.98, 0.03, '\n'.join(notes), transform=ax.transAxes, ha='right',
                    va='bottom', fontsize=7, color='dimgray')
        if panel_title:
            ax.set_title(panel_title, fontsize=10)
        if handles is None:
            # drawn in its run's colour: so is the legend's entry when there is one colour
            extra = ([mlines.Line2D([], [], ls=':', label='target h = rah0',
                                    color=(next(iter(target_colors))
                                           if len(target_colors) == 1 else 'dimgray'))]
                     if targets else [])
            ax.legend(handles=ax.get_legend_handles_labels()[0] + extra, fontsize=7)
        ax.tick_params(labelbottom=True)  # also above an empty slot and in shared columns
        if p + cols >= n:  # the lowest panel of its column
            ax.set_xlabel('t / M')
        if p % cols == 0:
            ax.set_ylabel(axis_label(a.y))
    for p in range(n, rows * cols):
        axes[p // cols][p % cols].set_visible(False)
    title = a.title if a.title is not None else (
        'apparent-horizon coordinate radius' if a.y == 'r_ah' else a.y)
    description = run_description(params_list)
    if handles is not None:
        if a.target:
            handles.append(mlines.Line2D([], [], color='dimgray', ls=':',
                                         label="target h = rah0 (in its run's colour)"))
        legend = fig.legend(handles=handles, loc='center right', fontsize=8)
    # the description wrapped to the figure's width (about 10 characters an inch at 11 pt)
    wrapped = textwrap.fill(description, width=int(fig.get_figwidth() * 10)) if description else ''
    fig.suptitle(title + (f' ({len(runs)} runs)' if n > 1 else '')
                 + (f'\n{wrapped}' if wrapped else ''), fontsize=11)
    fig.tight_layout()
    if handles is not None:  # make room for the figure's legend on the right
        fig.canvas.draw()
        width = legend.get_window_extent().width / fig.bbox.width
        fig.tight_layout(rect=(0, 0, 1 - width - 0.01, 1))
    save_figure(fig, a.output)


if __name__ == '__main__':
    run_script(main)
