#!/usr/bin/env bash
# plots/thesis.py on small real converge studies: mechanisms.dat has one row per study whose
# fields parse and match what an independent reading of convergence.dat gives (orders, the first
# time the finer member lies above, the verdict's class), the signature's features follow their
# stated rules, the figures are PNGs; plots/horizon_study.py labels spacings from the members'
# headers; and runs/thesis.sh refuses a folder another run holds.
set -euo pipefail
gbssn1d=$1 py=$2 src=$3 dir=$4
rm -rf "$dir" && mkdir -p "$dir"
# row NAME FLAGS...: a converge study as runs/thesis.sh makes one (its .cmd and .status beside)
row() {
  local name=$1
  shift
  local cmd=("$gbssn1d" converge --N 24,32,48 -j 2 --out "$dir/$name" --id maximal-trumpet
             --grid boxes --levels 5 --rmax 32 --tmax 24 --dt-series 0.25 --scaled-times 20
             --cfl 0.25 "$@")
  printf '%q ' "${cmd[@]}" >"$dir/$name.cmd"
  local status=0
  "${cmd[@]}" >"$dir/$name.log" 2>&1 || status=$?
  echo "$status" >"$dir/$name.status"
}
# each box its own h_AH: the finer runs lie above the coarser ones from the start (a known
# failure); the shrink with the defaults converges
row maximal-h0.89-thesis --rahA 0.5 --rah0 0.89 --rah-variant box-substage
row maximal-h0.6-thesis --rahA 0.5 --rah0 0.6
row maximal-h0.89-defaults --rahA 0.5 --rah0 0.89
row maximal-h0.6-defaults --rahA 0.5 --rah0 0.6
row maximal-standard-thesis
"$py" "$src/plots/thesis.py" "$dir" maximal-h0.89-thesis maximal-h0.6-thesis \
  maximal-h0.89-defaults maximal-h0.6-defaults maximal-standard-thesis >"$dir/thesis.out"
PYTHONPATH="$src/plots" "$py" - "$dir" <<'PY'
import math
import shlex
import sys

import numpy as np
from gbssn1d_data import parse, read_text

d = sys.argv[1]
lines = open(f"{d}/mechanisms.dat").read().splitlines()
cols = lines[0][1:].split()
rows = [dict(zip(cols, l.split())) for l in lines if not l.startswith('#')]
# the README's one-line loading reads it, every row and column
table = np.genfromtxt(f"{d}/mechanisms.dat", names=True, dtype=None, encoding=None)
assert list(table.dtype.names) == cols, (table.dtype.names, cols)
assert [str(x) for x in table['row']] == [r['row'] for r in rows]
assert [str(x) for x in table['verdict']] == [r['verdict'] for r in rows]
commands = {l.split('\t')[0]: l.split('\t')[1:] for l in open(f"{d}/commands.txt").read().splitlines()
            if not l.startswith('#')}
assert [r['row'] for r in rows] == ['maximal-h0.89-thesis', 'maximal-h0.6-thesis',
                                    'maximal-h0.89-defaults', 'maximal-h0.6-defaults',
                                    'maximal-standard-thesis'], [r['row'] for r in rows]
for l in lines:
    if not l.startswith('#'):
        assert len(l.split()) == len(cols), l
for r in rows:
    name = r['row']
    columns, blocks = parse(read_text(f"{d}/{name}/convergence.dat"))
    data = blocks[0][1]
    t = data[:, columns.index('t')]
    H = {n: data[:, columns.index(f'H_L2_R_N{n}')] for n in (24, 32, 48)}
    # the orders of the RMS over (0, 20] M, recomputed here
    sel = (t > 0) & (t <= 20)
    for key, (a, b) in zip(('p_0_20_a', 'p_0_20_b'), ((24, 32), (32, 48))):
        p = math.log(np.sqrt(np.mean(H[a][sel] ** 2)) / np.sqrt(np.mean(H[b][sel] ** 2))) \
            / math.log(b / a)
        assert abs(float(r[key]) - p) < 0.006, (name, key, r[key], p)
    # the first time the finer member lies above the coarser one
    for key, (a, b) in zip(('t_above_a', 't_above_b'), ((24, 32), (32, 48))):
        above = (t > 0) & (H[b] > H[a])
        expect = f'{t[above][0]:g}' if above.any() else '-'
        assert r[key] == expect, (name, key, r[key], expect)
    # the verdict: the class words of convergence.dat's verdict line
    verdict = next(l for l in open(f"{d}/{name}/convergence.dat") if l.startswith('# verdict:'))
    assert verdict[len('# verdict:'):].strip().startswith(r['verdict'].replace('-', ' ')), \
        (verdict, r['verdict'])
    assert r['verdict'] in ('converges', 'converges-until-the-round-off-floor', 'pre-asymptotic',
                            'does-not-converge'), r['verdict']
    command, whole = commands[name]
    assert shlex.split(command)[1] == 'converge' and f'--out {d}/{name}' in command, command
    assert whole == verdict[len('# verdict:'):].strip(), (whole, verdict)
    assert r['spacings'] == 'M/12,M/16,M/24', r['spacings']
by = {r['row']: r for r in rows}
bad, good = by['maximal-h0.89-thesis'], by['maximal-h0.6-thesis']
# each box its own h_AH: the finer run above the coarser one from the first outputs
assert bad['finer_above'] == 'yes' and float(bad['t_above_a']) < 1.0, bad
assert bad['from_2M'] == 'no', bad  # from the first output, not from about 2 M
assert bad['verdict'] == 'does-not-converge', bad['verdict']
assert good['finer_above'] == 'no', good
# shrink_first: the stretch fails over (0, 20] M while the shrink converges there
stretch_fails = min(float(bad['p_0_20_a']), float(bad['p_0_20_b'])) < 2.5
shrink_converges = min(float(good['p_0_20_a']), float(good['p_0_20_b'])) >= 2.5
assert bad['shrink_first'] == ('yes' if stretch_fails and shrink_converges else 'no'), bad
assert good['shrink_first'] == '-', good  # a shrink row has no shrink to compare
assert by['maximal-h0.89-defaults']['shrink_first'] == 'no'  # the stretch converges early
assert by['maximal-standard-thesis']['h'] == 'standard'
# a figure is drawn where its rows exist, and said to be left out where they do not
assert open(f"{d}/thesis.out").read().count('left out') == 3
print("mechanisms.dat: rows, orders, first times, verdicts and features as recomputed")
PY
for f in fig3.5_scaled_H; do
  [ -s "$dir/$f.png" ] || { echo "$f.png missing"; exit 1; }
done
# horizon_study.py: spacings from the members' headers (boxes: the finest box's)
PYTHONPATH="$src/plots" "$py" - "$dir" <<'PY'
import sys
from horizon_study import spacing_label
d = sys.argv[1]
got = [spacing_label(f"{d}/maximal-h0.6-thesis", n) for n in (24, 32, 48)]
assert got == ['M/12', 'M/16', 'M/24'], got
assert spacing_label(f"{d}/maximal-h0.6-thesis", 24, rmax=200.0) == 'M/0.12'
print("horizon_study.py: spacings M/12, M/16, M/24 from the headers")
PY
"$py" "$src/plots/horizon_study.py" figure -o "$dir/family.png" "$dir/maximal-h0.6-thesis"
head -c 8 "$dir/family.png" | grep -q PNG
# runs/thesis.sh: a second run on a folder whose lock is held is refused at once, nothing run
mkdir -p "$dir/locked"
status=0
flock "$dir/locked/.lock" bash "$src/runs/thesis.sh" "$dir/locked" >"$dir/locked.out" 2>&1 || status=$?
[ $status -eq 1 ] || { echo "runs/thesis.sh on a held folder: exit $status"; cat "$dir/locked.out"; exit 1; }
grep -q "another run is writing" "$dir/locked.out"
[ "$(ls "$dir/locked")" = "" ] || { echo "runs/thesis.sh wrote into a held folder"; exit 1; }
# a row that was never run: one line naming its file, exit 2, no traceback
status=0
"$py" "$src/plots/thesis.py" "$dir" no-such-row >"$dir/bad.out" 2>"$dir/bad.err" || status=$?
[ $status -eq 2 ] && [ "$(wc -l <"$dir/bad.err")" -eq 1 ] && grep -q "no-such-row.status" "$dir/bad.err" \
  && ! grep -q Traceback "$dir/bad.err" || { echo "thesis.py on a missing row: exit $status"; cat "$dir/bad.err"; exit 1; }
# fig3.5 marks the boxes' edges (rmax / 2^l, below the plotted range): where its spikes are
PYTHONPATH="$src/plots" "$py" - <<'PY'
import thesis
assert thesis.box_edges({'grid': 'boxes', 'rmax': '32', 'levels': '5'}, 20.0) == [16.0, 8.0, 4.0, 2.0]
assert thesis.box_edges({'grid': 'sinh', 'rmax': '1000'}, 20.0) == []
print("fig3.5: box edges at 16, 8, 4, 2 M for 5 boxes to 32 M")
PY
echo "thesis: every check passed"
