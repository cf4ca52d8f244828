"""Reading gbssn1d ASCII output: columns are chosen by the names in the header, never by
position. A file's last '#' line before the data names the columns; in profiles.dat each block
opens with a '# t = <value>' line and blocks are separated by blank lines."""
import itertools
import os
import re
import sys

import numpy as np


class DataError(SystemExit):
    """Input that is not gbssn1d output: a missing file, a folder, a binary file, a line that
    is not what the file's format allows. Its text is one line, '<script>: <file>: <why>';
    run_script() writes it to stderr and exits with status 2, without a traceback (a script not
    run through run_script() still prints the line, as SystemExit, and exits with status 1)."""

    def __init__(self, why, path=None, table_ok=True):
        super().__init__(why)
        self.why, self.path = why, path
        self.table_ok = table_ok  # parse_table() may still read the text as a table of words

    def line(self):
        where = f'{display_name(self.path)}: ' if self.path is not None else ''
        return f'{script_name()}: {where}{self.why}'

    @property
    def code(self):  # what the interpreter prints for an uncaught SystemExit
        return self.line()

    def __str__(self):
        return self.line()


def script_name():
    """The running script's file name, as argparse names it in its messages."""
    return os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else 'python3'


def display_name(path):
    return 'standard input' if path == '-' else str(path)


def run_script(main, *args):
    """Runs a script's main(*args): input that is not gbssn1d output (DataError) ends the
    script with one line '<script>: <file>: <why>' on stderr and exit status 2, no traceback."""
    try:
        return main(*args)
    except DataError as e:
        sys.stdout.flush()
        sys.stderr.write(e.line() + '\n')
        sys.exit(2)


def read_text(path):
    """The text of a path, or of standard input for '-'. A path that cannot be read as text
    (missing, a folder, unreadable, binary) raises DataError naming it."""
    try:
        if path == '-':
            text = sys.stdin.buffer.read().decode('utf-8')
        else:
            with open(path, encoding='utf-8') as f:
                text = f.read()
    except FileNotFoundError:
        raise DataError('no such file', path) from None
    except IsADirectoryError:
        raise DataError('is a folder, not a file', path) from None
    except UnicodeDecodeError:
        raise DataError('not a text file (binary?)', path) from None
    except OSError as e:
        raise DataError(e.strerror or str(e), path) from None
    if '\0' in text:
        raise DataError('not a text file (binary?)', path)
    return text


def parse(text, path=None):
    """Returns (columns, blocks): blocks is a list of (t or None, 2D array). Text that is not
    gbssn1d output raises DataError (naming path, the file the text came from)."""
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
                try:
                    t = float(s.partition('=')[2])
                except ValueError:
                    raise DataError(f"line {k + 1}: '{s}' is not a block's time "
                                    "('# t = <number>')", path, table_ok=False) from None
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
                where = f'{display_name(path)}: ' if path is not None else ''
                sys.stderr.write(f'note: {where}dropped an incomplete last line\n')
                continue
            raise DataError(f'line {k + 1} is not a row of {len(columns or [])} numbers', path)
        rows.append(row)
    close()
    if columns is None or not blocks:
        raise DataError('no gbssn1d data found (no column header or no rows)', path)
    return columns, blocks


def parse_table(text, path=None):
    """(columns, data) of any output file, summary.dat included: parse() for numeric files;
    for a table with words (a sweep's status and reason) the numeric columns as floats and the
    word columns as NaN. Returns the first block only."""
    try:
        columns, blocks = parse(text, path)
        return columns, blocks[0][1]
    except DataError as e:
        if not e.table_ok:  # a malformed file, not a table with words
            raise
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
    columns, data = parse_table(read_text(path), path)
    return {c: data[:, i] for i, c in enumerate(columns)}


def blocks(path):
    """Every block of an output file with its time: a list of (t, table), where table is a numpy
    structured array whose fields are the file's column names (table['r'], table['alpha'], ...).
    profiles.dat has one block per output time, scaled_H.dat one per --scaled-times;
    timeseries.dat and the other one-table files give one block with t = None. The loader the
    README documents for numpy users (numpy.genfromtxt reads a file's blocks as one table)."""
    columns, parsed = parse(read_text(path), path)
    dtype = [(c, float) for c in columns]
    return [(t, np.array([tuple(row) for row in data], dtype=dtype)) for t, data in parsed]


def column(columns, data, name, path=None):
    """The column `name` of a table parsed from `path`; a missing one is bad input (DataError:
    exit status 2 through run_script()) naming the file, among several the one at fault."""
    if name not in columns:
        raise DataError(f"no column '{name}'; its columns are: {' '.join(columns)}", path)
    return data[:, columns.index(name)]


# Seven colours a reader tells apart (also in grey print, by their order of lightness they
# do not need to): one per unordered curve: runs, columns. Ordered curves (resolutions, times)
# take a sequential colormap instead, where darker means later or finer.
QUALITATIVE = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#17becf']
LINESTYLES = ['-', '--', ':', '-.']


def pyplot():
    """matplotlib.pyplot (non-interactive, styled): imported once the input is read, so that
    input that is not gbssn1d output is refused without waiting for matplotlib."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    style(plt)
    return plt


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


# What a column means, in words, with its unit: lengths and times in units of M (written
# 'r / M': the number plotted is r over M), other quantities with their unit in brackets.
# Norms and their windows are composed in describe(); a column not listed keeps its name.
LABELS = {
    # time series and horizon.dat
    't': 't / M', 'alpha_center': 'lapse at the puncture, alpha(r = 0)',
    'r_ah': 'apparent horizon radius r_AH / M', 'R_ah': 'areal horizon radius R_AH / M',
    'M_ah': 'horizon mass M_AH / M', 'M_ah_err': 'horizon mass error (M_AH - M) / M',
    'n_roots': 'number of zeros of Theta_+', 'level': 'box level (0: outermost)',
    'r_root2': 'second zero of Theta_+, r / M', 'R_root2': 'second zero of Theta_+, R / M',
    'r_root3': 'third zero of Theta_+, r / M', 'R_root3': 'third zero of Theta_+, R / M',
    # profiles.dat
    'r': 'coordinate radius r / M', 'R_areal': 'areal radius R / M', 'alpha': 'lapse alpha',
    'beta': 'shift beta^r', 'beta_GD': 'Gamma-driver shift beta_GD',
    'beta_H': 'horizon shift beta_H', 'B': 'Gamma-driver field B^r (1/M)',
    'chi': 'conformal factor chi', 'a': 'conformal metric a', 'b': 'conformal metric b',
    'K': 'mean curvature K (1/M)', 'A_a': 'traceless curvature A_a (1/M)',
    'Delta_r': 'connection function Delta^r (1/M)',
    'H': 'Hamiltonian constraint H (1/M^2)', 'M_r': 'momentum constraint M_r (1/M^2)',
    'G_r': 'Gamma constraint G^r (1/M)', 'Theta_plus': 'outgoing expansion Theta_+ (1/M)',
    # a sweep's summary.dat and parameters
    'rahA': 'rahA (strength A)', 'rah0': 'rah0: target h / M', 'N': 'N (cells)',
    'rmax': 'outer boundary rmax / M', 'M': 'mass M', 't_end': 'last time t_end / M',
    'r_ah_final': 'final horizon radius r_AH / M',
    'R_ah_final': 'final areal horizon radius R_AH / M',
    'M_ah_drift': 'max |M_AH(t) - M_AH(0)| / M', 'M_ah_err_max': 'max |M_AH - M| / M',
    'wall_s': 'wall-clock time (s)',
}
# columns that are never negative (on a log axis they need no |..|)
NON_NEGATIVE = {'t', 'r', 'R_areal', 'r_ah', 'R_ah', 'M_ah', 'alpha', 'alpha_center', 'chi', 'a',
                'b', 'n_roots', 'level', 'r_root2', 'R_root2', 'r_root3', 'R_root3', 'rahA',
                'rah0', 'N', 'rmax', 'M', 't_end', 'r_ah_final', 'R_ah_final', 'M_ah_drift',
                'M_ah_err_max', 'wall_s'}
CONSTRAINTS = {'H': ('Hamiltonian constraint', '||H||_2', '1/M^2'),
               'M': ('momentum constraint', '||M_r||_2', '1/M^2'),
               'G': ('Gamma constraint', '||G^r||_2', '1/M')}
_NORM = re.compile(r'([HMG])_L2(_ext|_R|_int)?(_max)?')


def window(kind, params=None):
    """Where a norm is taken, in words: kind 'ext' (a coordinate-radius window), 'R' (an
    areal-radius window), 'int' (from the puncture out) or '' (the whole grid); with the bounds
    when params (a run's header, header_params) records them."""
    p = params or {}
    if kind == 'ext':
        return (f"{p['norm-rmin']} M ≤ r ≤ {p['norm-rmax']} M"
                if 'norm-rmin' in p and 'norm-rmax' in p else 'the coordinate window')
    if kind == 'R':
        return (f"{p['norm-Rmin']} M ≤ R ≤ {p['norm-Rmax']} M"
                if 'norm-Rmin' in p and 'norm-Rmax' in p else 'the areal window')
    if kind == 'int':
        return f"R ≤ {p['norm-Rint']} M" if 'norm-Rint' in p else 'the interior'
    return 'the whole grid'


def describe(name, params=None):
    """(words, unit) of a column whose meaning is composed: the constraint norms (H_L2,
    H_L2_ext, H_L2_R, H_L2_int, the same for M and G, and a summary's *_max) and d_t alpha;
    None for any other column."""
    m = _NORM.fullmatch(name)
    if m:
        _, symbol, unit = CONSTRAINTS[m[1]]
        where = window({None: '', '_ext': 'ext', '_R': 'R', '_int': 'int'}[m[2]], params)
        return f"{'max ' if m[3] else ''}{symbol} over {where}", unit
    if name == 'dtalpha_max_ext':
        return f"max |d_t alpha| over {window('ext', params)}", '1/M'
    return None


def axis_label(name, params=None):
    """A column name as an axis label: its meaning in words with its unit (lengths and times
    in M); norms name their window, with its bounds when params (a run's header) has them.
    Unknown columns keep their name."""
    composed = describe(name, params)
    if composed:
        return f'{composed[0]} ({composed[1]})'
    return LABELS.get(name, name)


def legend_name(name, params=None):
    """A column's name for a legend entry: the words without the unit (a constraint norm also
    says which constraint)."""
    m = _NORM.fullmatch(name)
    if m:
        return f'{CONSTRAINTS[m[1]][0]} {CONSTRAINTS[m[1]][1]}'
    composed = describe(name, params)
    return composed[0] if composed else re.sub(r' \(.*\)$', '', LABELS.get(name, name))


def log_axis_label(names, params=None):
    """The y label of columns plotted as absolute values on a log axis: one column's label with
    its symbol in |..| where the column can be negative ('Hamiltonian constraint |H| (1/M^2)'),
    or for several columns what they have in common (their legend entries name them)."""
    if len(names) > 1:
        return several_label(names, params)
    name = names[0]
    label = axis_label(name, params)
    if name in NON_NEGATIVE or describe(name):  # norms and maxima of |..| are >= 0
        return label
    if name == 'M_ah_err':
        return 'horizon mass error |M_AH - M| / M'
    body, unit = re.fullmatch(r'(.*?)( \(.+\))?', label).groups()
    words, space, symbol = body.rpartition(' ')
    return f"{words}{space}|{symbol}|{unit or ''}"


def several_label(names, params=None):
    """The y label of several columns in one figure (their legend entries name them): the
    window and unit they share when they are norms over one window, else their labels."""
    composed = [describe(n, params) for n in names]
    if all(composed) and all(_NORM.fullmatch(n) for n in names):
        wheres = {c[0].split(' over ', 1)[1] for c in composed}
        units = {c[1] for c in composed}
        if len(wheres) == 1 and len(units) == 1:
            return f'L2 norm over {wheres.pop()} ({units.pop()})'
    labels = [axis_label(n, params) for n in names]
    joined = ', '.join(labels)
    # one per line when they would run past the axis (two are about 60 characters)
    return ',\n'.join(labels) if len(joined) > 45 else joined


_PARAM = re.compile(r'#?\s*([A-Za-z][\w.-]*)\s*=\s*(.*)$')


def params_of(lines):
    """{key: value} of 'key = value' lines (with or without a leading '#'), values as strings
    without quotes; other lines are skipped."""
    params = {}
    for line in lines:
        m = _PARAM.match(line)
        if m and m[1] != 't':  # '# t = ...' opens a block of profiles.dat
            params[m[1]] = m[2].strip().strip('"')
    return params


def header_params(text):
    """The run's parameters from a file's header (its '# key = value' lines before the first
    row): {'id': '1log-trumpet', 'N': '400', ...}."""
    return params_of(itertools.takewhile(lambda line: line.startswith('#'), text.splitlines()))


# parameters that follow from others or do not change the solution: never in a run's label
NOT_LABELS = {'out', 'force', 'dt', 'steps', 'dr-min', 'checkpoint-every', 'dt-series',
              'dt-profiles', 'tmax', 'M-ADM', 'flux-R'}
# the parameters a label names first, when they tell the runs apart
FIRST_LABELS = ['id', 'lapse0', 'grid', 'levels', 'N', 'rmax', 'dr-inner', 'rahA', 'rah0']


def label_keys(params_list):
    """The fewest parameters that tell the runs apart, taken in the order of FIRST_LABELS
    and then of the header: a parameter that follows from those already taken (the horizon
    shift's width and profile from rahA and rah0) is left out. Empty when the runs do not
    differ or have no headers."""
    keys = [k for k in FIRST_LABELS if any(k in p for p in params_list)]
    for p in params_list:
        keys += [k for k in p if k not in keys and k not in NOT_LABELS]
    chosen = []
    for k in keys:
        groups = {tuple(p.get(c) for c in chosen) for p in params_list}
        split = {tuple(p.get(c) for c in chosen + [k]) for p in params_list}
        if len(split) > len(groups):
            chosen.append(k)
        if len(split) == len(params_list):
            break
    return chosen


# Header keys that may differ between the members of one configuration at several N: N itself
# and what follows from it (the step, its count, the smallest cell), and output-only settings.
PER_RUN_KEYS = frozenset({'N', 'out', 'force', 'tmax', 'dt-series', 'dt-profiles',
                          'checkpoint-every', 'dt', 'steps', 'dr-min', 'rah-hAH-file'})


def require_one_configuration(params_list, paths):
    """Refuses (DataError) runs that are not one configuration at several N: any header
    parameter besides PER_RUN_KEYS that differs between them, or is in one header only, is named
    with its values and the files (an order between a trumpet and a wormhole, or BSSN and Z4c,
    is no order of anything)."""
    if len(params_list) < 2:
        return
    keys = sorted(set().union(*(p.keys() for p in params_list)) - PER_RUN_KEYS)
    differ = []
    for k in keys:
        values = [p.get(k, '(absent)') for p in params_list]
        if len(set(values)) > 1:
            differ.append(f'{k} ' + ' / '.join(values))
    if differ:
        raise DataError('not one configuration at several N: ' + '; '.join(differ[:6])
                        + (f' (and {len(differ) - 6} more)' if len(differ) > 6 else '')
                        + ' (files: ' + ', '.join(display_name(q) for q in paths) + ')',
                        paths[-1])


def common_params(params_list):
    """The parameters all runs share, e.g. the norm windows that name an axis."""
    if not params_list:
        return {}
    return {k: v for k, v in params_list[0].items() if all(p.get(k) == v for p in params_list)}


def shifted(params):
    """Whether a run has the horizon-adjusting shift on (rahA != 0)."""
    try:
        return float(params.get('rahA', 0)) != 0
    except ValueError:
        return False


def sort_key(value):
    """Parameter values in numeric order (0, 0.25, 1, not the folders' 0.25, 0, 1), then words."""
    try:
        return (0, float(value), '')
    except (TypeError, ValueError):
        return (1, 0.0, str(value))


def run_description(params_list):
    """What was run, in words, from the parameters all runs share: the data, the grid and the
    horizon shift, e.g. '1log-trumpet data; sinh grid, N = 400, rmax = 1000 M; horizon shift
    rahA = 0.5, rah0 = 1.2 M'. Empty without headers."""
    p = common_params(params_list)
    if not p:
        return ''
    parts = []
    if 'id' in p:
        lapse = f" ({p['lapse0']} lapse)" if p['id'] == 'wormhole' and 'lapse0' in p else ''
        parts.append(f"{p['id']} data{lapse}")
    grid = []
    if 'grid' in p:
        grid.append(f"{p['levels']} nested boxes" if p['grid'] == 'boxes' and 'levels' in p
                    else f"{p['grid']} grid")
    if 'N' in p:
        grid.append(f"N = {p['N']}" + (' per box' if p.get('grid') == 'boxes' else ''))
    if 'rmax' in p:
        grid.append(f"rmax = {p['rmax']} M")
    if grid:
        parts.append(', '.join(grid))
    if 'rahA' in p and not shifted(p):
        parts.append('no horizon shift')
    elif 'rahA' in p:
        parts.append(f"horizon shift rahA = {p['rahA']}"
                     + (f", rah0 = {p['rah0']} M" if 'rah0' in p else ''))
    elif 'rah0' in p and any(shifted(q) for q in params_list):
        parts.append(f"horizon shift to rah0 = {p['rah0']} M")
    return '; '.join(parts)


def run_labels(paths, params_list, labels=None):
    """Legend labels of runs plotted together: the given labels where there are; else the
    values of the parameters that tell the runs apart (label_keys), e.g. 'rahA = 0.5, rah0 =
    1.2'; a run alone by its horizon shift or its data; else (no headers, more than three
    parameters, or runs that do not differ) by their folder names."""
    keys = label_keys(params_list)
    if len(paths) == 1 and params_list[0]:
        p = params_list[0]
        auto = [f"rahA = {p['rahA']}, rah0 = {p['rah0']}" if shifted(p) and 'rah0' in p
                else f"{p['id']} data" if 'id' in p else run_label(paths[0])]
    elif keys and len(keys) <= 3:
        auto = [', '.join(f"{k} = {p.get(k, '?')}" for k in keys) for p in params_list]
    else:
        auto = [run_label(path) for path in paths]
    labels = labels or []
    return [labels[k] if k < len(labels) else auto[k] for k in range(len(paths))]


def run_label(path):
    """A file's folder name (its run's, without the folders above it), or 'stdin' for '-'."""
    if path == '-':
        return 'stdin'
    return os.path.basename(os.path.dirname(os.path.abspath(path))) or path


def wrap(description, width):
    """A run description in lines of at most width characters, broken at its '; '."""
    lines = []
    for part in description.split('; '):
        if lines and len(lines[-1]) + 2 + len(part) <= width:
            lines[-1] += '; ' + part
        else:
            lines.append(part)
    return '\n'.join(lines)


def set_titles(fig, ax, title, description):
    """A figure's title and, below it in smaller type, what was run (either may be empty)."""
    description = wrap(description, int(12 * ax.get_position().width * fig.get_figwidth()))
    if title and description:
        fig.suptitle(title)
        ax.set_title(description, fontsize=9)
    else:
        ax.set_title(title or description, fontsize=None if title else 10)


def finish(fig, ax, xlabel, ylabel, title, output, description=''):
    """Labels, legend and layout shared by every figure; writes the PNG."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    set_titles(fig, ax, title, description)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, output)


def save_figure(fig, output):
    """Writes the figure; an output path that cannot take it (a missing folder, no permission,
    a name whose extension is no image format) raises DataError naming it, not a traceback."""
    try:
        fig.savefig(output)
    except (OSError, ValueError) as e:
        why = e.strerror if isinstance(e, OSError) and e.strerror else str(e)
        raise DataError(f'cannot write the figure: {why}', output) from None
