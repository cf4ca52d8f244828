"""Reading gbssn1d ASCII output: columns are chosen by the names in the header, never by
position. A file's last '#' line before the data names the columns; in profiles.dat each block
opens with a '# t = <value>' line and blocks are separated by blank lines."""
import os
import sys

import numpy as np


def read_text(path):
    """The text of a path, or of standard input for '-'."""
    if path == '-':
        return sys.stdin.read()
    with open(path) as f:
        return f.read()


def parse(text):
    """Returns (columns, blocks): blocks is a list of (t or None, 2D array)."""
    columns, blocks = None, []
    t, rows = None, []

    def close():
        nonlocal rows
        if rows:
            blocks.append((t, np.array(rows, dtype=float)))
        rows = []

    lines = text.splitlines()
    last = max((k for k, line in enumerate(lines) if line.strip()), default=-1)
    # The column names are the first line (numpy.genfromtxt(f, names=True) reads them there);
    # files of earlier versions began with the version line and named the columns last.
    # (the version line is the second line then; other tables name their columns last too)
    names_first = (len(lines) > 1 and lines[0].startswith('#')
                   and lines[1].startswith('# gbssn1d'))
    if names_first:
        columns = lines[0][1:].split()
    for k, line in enumerate(lines):
        s = line.strip()
        if not s:
            close()
            continue
        if s.startswith('#'):
            if s.startswith('# t ='):
                close()
                t = float(s.split('=')[1])
            elif (not names_first and rows == [] and not blocks
                  and not s.startswith('# end:')):
                columns = s[1:].split()
            continue
        try:
            row = [float(v) for v in s.split()]
        except ValueError:
            row = None
        if row is None or (columns is not None and len(row) != len(columns)):
            if k == last:  # a file cut mid-line (a killed run): keep what is complete
                sys.stderr.write('note: dropped an incomplete last line\n')
                continue
            raise SystemExit(f'line {k + 1} is not a row of {len(columns or [])} numbers')
        rows.append(row)
    close()
    if columns is None or not blocks:
        raise SystemExit('no gbssn1d data found (no column header or no rows)')
    return columns, blocks


def parse_table(text):
    """(columns, data) of any output file, summary.dat included: parse() for numeric files;
    for a table with words (a sweep's status and reason) the numeric columns as floats and the
    word columns as NaN. Returns the first block only."""
    try:
        columns, blocks = parse(text)
        return columns, blocks[0][1]
    except SystemExit:
        lines = [l for l in text.splitlines() if l.strip()]
        names = lines[0][1:].split() if lines and lines[0].startswith('#') else None
        rows = [l.split() for l in lines if not l.startswith('#')]
        if not names or not rows or any(len(r) != len(names) for r in rows):
            raise

        def number(word):
            try:
                return float(word)
            except ValueError:
                return np.nan
        return names, np.array([[number(w) for w in r] for r in rows], dtype=float)


def series(path):
    """{column name: values} of the first block of an output file (timeseries.dat), or None
    when the file does not exist (a run that stopped before writing it)."""
    if not os.path.exists(path):
        return None
    columns, data = parse_table(read_text(path))
    return {c: data[:, i] for i, c in enumerate(columns)}


def column(columns, data, name):
    if name not in columns:
        raise SystemExit(f"no column '{name}'; columns are: {' '.join(columns)}")
    return data[:, columns.index(name)]


# Seven colours a reader tells apart (also in grey print, by their order of lightness they
# do not need to): one per unordered curve: runs, columns. Ordered curves (resolutions, times)
# take a sequential colormap instead, where darker means later or finer.
QUALITATIVE = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#17becf']
LINESTYLES = ['-', '--', ':', '-.']


def style(plt):
    plt.rcParams.update({'figure.figsize': (7, 4.5), 'axes.grid': True, 'grid.alpha': 0.3,
                         'font.size': 11, 'savefig.dpi': 120,
                         'axes.prop_cycle': plt.cycler(color=QUALITATIVE)})


def qualitative_colors(n, what):
    """n distinct colours for unordered curves; refuses more than a reader can tell apart."""
    if n > len(QUALITATIVE):
        raise SystemExit(f'{n} {what} in one figure: at most {len(QUALITATIVE)} can be told '
                         f'apart by colour; plot fewer, or split them over several figures')
    return QUALITATIVE[:n]


def line_styles(n, what):
    """n distinct line styles (the second way to tell curves apart, after colour)."""
    if n > len(LINESTYLES):
        raise SystemExit(f'{n} {what} in one figure: at most {len(LINESTYLES)} line styles can '
                         f'be told apart; plot fewer, or split them over several figures')
    return LINESTYLES[:n]


def sequential_colors(n):
    """n colours of the sequential viridis map for ordered curves (resolutions, times): light
    (first) to dark (last)."""
    import matplotlib
    cmap = matplotlib.colormaps['viridis']
    return [cmap(x) for x in np.linspace(0.85, 0.0, n)] if n > 1 else [cmap(0.35)]


UNITS = {'t': 't / M', 'r': 'r / M', 'R_areal': 'R / M', 'r_ah': 'r_AH / M', 'R_ah': 'R_AH / M',
         'M_ah': 'M_AH / M', 'M_ah_err': '(M_AH - M) / M', 'rah0': 'h / M', 'r_ah_final': 'r_AH / M',
         'M_ah_drift': 'M_AH drift / M', 'M_ah_err_max': 'max |M_AH - M| / M', 'rahA': 'A',
         'R_ah_final': 'R_AH / M', 't_end': 't_end / M', 'rmax': 'rmax / M', 'M': 'M'}


def run_label(path):
    """A file's legend label: its run's folder name, without the folders above it."""
    if path == '-':
        return 'stdin'
    return os.path.basename(os.path.dirname(os.path.abspath(path))) or path


def axis_label(name):
    """A column name as an axis label, with its unit where it has one (lengths and times in M)."""
    return UNITS.get(name, name)


def finish(fig, ax, xlabel, ylabel, title, output):
    """Labels, legend and layout shared by every figure; writes the PNG."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output)
