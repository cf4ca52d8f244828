#!/usr/bin/env bash
# Runs each plot script on real gbssn1d output and checks that it writes a non-empty PNG.
set -euo pipefail
gbssn1d=$1 py=$2 plots=$3 dir=$4
rm -rf "$dir" && mkdir -p "$dir"
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 100 --rmax 20 --tmax 2 --dt-profiles 1 \
  --out "$dir/run" 2>/dev/null
"$gbssn1d" evolve --id 1log-trumpet --tmax 0 --grid uniform --N 400 --rmax 20 \
  --out "$dir/ref" 2>/dev/null
"$py" "$plots/plot_series.py" "$dir/run/timeseries.dat" -y H_L2_ext --logy -o "$dir/series.png"
"$py" "$plots/plot_series.py" - -y alpha_center -o "$dir/stdin.png" < "$dir/run/timeseries.dat"
"$py" "$plots/plot_profiles.py" "$dir/run/profiles.dat" -y alpha -y beta --times 0,2 -o "$dir/profiles.png"
"$py" "$plots/compare_trumpet.py" "$dir/run/profiles.dat" "$dir/ref/profiles.dat" -o "$dir/cmp.png" >/dev/null
for n in 60 90 120; do
  "$gbssn1d" evolve --id 1log-trumpet --grid uniform --N $n --rmax 20 --tmax 2 --dt-series 0.5 \
    --out "$dir/conv$n" 2>/dev/null
done
"$py" "$plots/constraint_orders.py" "$dir"/conv{60,90,120}/timeseries.dat -o "$dir/orders.png" >/dev/null
# constraint_orders.py pairs rows by time: members written at other --dt-series (0.25, 0.1) give
# the orders of members written at the same one (paired by row index they gave others), and it
# says how many common times it used; members that share no time are refused, naming the files
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 90 --rmax 20 --tmax 2 --dt-series 0.25 \
  --out "$dir/convdt90" 2>/dev/null
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 120 --rmax 20 --tmax 2 --dt-series 0.1 \
  --out "$dir/convdt120" 2>/dev/null
"$py" "$plots/constraint_orders.py" "$dir"/conv{60,90,120}/timeseries.dat --times 0.5,1,1.5,2 \
  > "$dir/orders_same.txt"
"$py" "$plots/constraint_orders.py" "$dir/conv60/timeseries.dat" "$dir/convdt90/timeseries.dat" \
  "$dir/convdt120/timeseries.dat" --times 0.5,1,1.5,2 -o "$dir/orders_mixed.png" \
  > "$dir/orders_mixed.txt"
grep -q "^# rows paired by time: 5 times common to all 3 runs (of 5, 9, 21 rows" "$dir/orders_mixed.txt" \
  || { echo "constraint_orders.py: not 5 common times"; cat "$dir/orders_mixed.txt"; exit 1; }
[ "$(grep -c '^[0-9]' "$dir/orders_same.txt")" -eq 4 ]
diff <(grep -v '^# rows paired' "$dir/orders_same.txt") <(grep -v '^# rows paired' "$dir/orders_mixed.txt") \
  || { echo "constraint_orders.py: other --dt-series gave other orders"; exit 1; }
{ grep '^#' "$dir/conv90/timeseries.dat"; grep -v '^#' "$dir/conv90/timeseries.dat" | sed -n '2p;4p'; } \
  > "$dir/odd_times.dat"   # t = 0.5, 1.5 only
{ grep '^#' "$dir/conv60/timeseries.dat"; grep -v '^#' "$dir/conv60/timeseries.dat" | sed -n '1p;3p;5p'; } \
  > "$dir/even_times.dat"  # t = 0, 1, 2
if "$py" "$plots/constraint_orders.py" "$dir/even_times.dat" "$dir/odd_times.dat" 2>"$dir/err" >/dev/null; then
  echo "constraint_orders.py: members without a common time accepted"; exit 1
fi
grep -q "no times common to all runs" "$dir/err" && grep -q "odd_times.dat" "$dir/err" \
  && grep -q "even_times.dat" "$dir/err"
# runs of other configurations are no convergence test: a wormhole beside trumpets, Z4c beside
# BSSN, refused (exit 2) naming the flag and its values
"$gbssn1d" evolve --id wormhole --grid uniform --N 90 --rmax 20 --tmax 2 --dt-series 0.5 \
  --out "$dir/convworm90" 2>/dev/null
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 90 --rmax 20 --tmax 2 --dt-series 0.5 \
  --formulation z4c --out "$dir/convz4c90" 2>/dev/null
for other in convworm90:'id 1log-trumpet / wormhole' convz4c90:'formulation bssn / z4c'; do
  status=0
  "$py" "$plots/constraint_orders.py" "$dir/conv60/timeseries.dat" "$dir/${other%%:*}/timeseries.dat" \
    "$dir/conv120/timeseries.dat" >/dev/null 2>"$dir/err" || status=$?
  [ $status -eq 2 ] && grep -q "not one configuration at several N: ${other#*:}" "$dir/err" \
    || { echo "constraint_orders.py: ${other%%:*} mixed in (exit $status): $(cat "$dir/err")"; exit 1; }
done
"$py" "$plots/plot_horizons.py" "$dir"/conv{60,90,120}/horizon.dat --label-by N -o "$dir/horizons.png"
# a box run: its composite profiles (with the level column) and horizon.dat read by the same
# scripts; the error-profile script on three box resolutions
for n in 16 24 32; do
  "$gbssn1d" evolve --id 1log-trumpet --grid boxes --levels 4 --rmax 32 --N $n --tmax 2 \
    --dt-profiles 1 --out "$dir/boxes$n" 2>/dev/null
done
"$py" "$plots/plot_profiles.py" "$dir/boxes32/profiles.dat" -y alpha -y level --times 0,2 -o "$dir/boxes_profiles.png"
"$py" "$plots/compare_trumpet.py" "$dir/boxes32/profiles.dat" "$dir/ref/profiles.dat" -o "$dir/boxes_cmp.png" >/dev/null
"$py" "$plots/plot_horizons.py" "$dir"/boxes{16,24,32}/horizon.dat --label-by N -o "$dir/boxes_horizons.png"
"$py" "$plots/error_profiles.py" "$dir"/boxes{16,24,32} -y a --times 1,2 -o "$dir/boxes_error.png" >/dev/null
# Z4c against BSSN (plots/z4c_study.py): a row per run with its ratios to the base, and a figure
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 100 --rmax 20 --tmax 2 --formulation z4c \
  --out "$dir/z4c" 2>/dev/null
"$py" "$plots/z4c_study.py" table "$dir/run" "$dir/z4c" --t0 0 --t1 2 >"$dir/z4c_table.txt"
grep -q '^run bssn 2 .* 1 .* 1 -$' "$dir/z4c_table.txt" && grep -q '^z4c z4c,kappa1=0.02,hole=1 2 ' "$dir/z4c_table.txt" \
  || { echo "z4c_study.py table: rows not as expected"; cat "$dir/z4c_table.txt"; exit 1; }
"$py" "$plots/z4c_study.py" figure "$dir/run" "$dir/z4c" --t0 0 --t1 2 -o "$dir/z4c.png"
# a window past a run's end: no numbers, said, no division by zero; a run that ended at its own
# tmax is not called stopped; an empty or reversed window is refused (exit 2)
"$py" "$plots/z4c_study.py" table "$dir/run" "$dir/z4c" --t0 5 --t1 9 >"$dir/z4c_late.txt"
grep -q '^z4c .* (the run ends at t = 2, before the window does) (no time in the window: no numbers)$' \
  "$dir/z4c_late.txt" || { echo "z4c_study.py table: a window past the end not said"; cat "$dir/z4c_late.txt"; exit 1; }
! grep -q 'stopped' "$dir/z4c_table.txt" || { echo "z4c_study.py: a completed run called stopped"; exit 1; }
for w in "--t0 5 --t1 0" "--t0 2 --t1 2"; do
  status=0
  # shellcheck disable=SC2086
  "$py" "$plots/z4c_study.py" table "$dir/run" "$dir/z4c" $w >/dev/null 2>&1 || status=$?
  [ $status -eq 2 ] || { echo "z4c_study.py table $w: exit $status, expected 2"; exit 1; }
done
# the Misner-Sharp mass at areal radii: a row per run and time, the mass M to 1% at t = 0 on
# these coarse grids (the column read, not another: its accuracy is tests/diagnostics'), and a
# time without a profile block refused
"$py" "$plots/z4c_study.py" mass "$dir/run" "$dir/z4c" --times 0,2 >"$dir/z4c_mass.txt"
[ "$(grep -c -E '^(run|z4c) (0|2) ' "$dir/z4c_mass.txt")" = 4 ] ||
  { echo "z4c_study.py mass: rows not as expected"; cat "$dir/z4c_mass.txt"; exit 1; }
"$py" - "$dir/z4c_mass.txt" <<'PY' || { echo "z4c_study.py mass: m_ms - M at t = 0 not within 1% of M"; exit 1; }
import sys
for line in open(sys.argv[1]):
    w = line.split()
    if w[0] in ('run', 'z4c') and w[1] == '0':
        assert all(abs(float(x)) < 1e-2 for x in w[2:]), line
PY
if "$py" "$plots/z4c_study.py" mass "$dir/z4c" --times 7 >/dev/null 2>"$dir/z4c_mass.err"; then
  echo "z4c_study.py mass: a time without a profile block accepted"; exit 1
fi
grep -q "no profile block at t = 7" "$dir/z4c_mass.err" || { echo "z4c_study.py mass: $(cat "$dir/z4c_mass.err")"; exit 1; }
for f in series stdin profiles cmp orders orders_mixed horizons boxes_profiles boxes_cmp boxes_horizons boxes_error z4c; do
  [ -s "$dir/$f.png" ] || { echo "plot $f.png missing or empty"; exit 1; }
  head -c 8 "$dir/$f.png" | grep -q PNG || { echo "$f.png is not a PNG"; exit 1; }
done
# a column that does not exist is an error naming it
if "$py" "$plots/plot_series.py" "$dir/run/timeseries.dat" -y no_such -o "$dir/x.png" 2>"$dir/err"; then
  echo "unknown column accepted"; exit 1
fi
grep -q no_such "$dir/err"
# a file cut mid-line (a killed run) still plots, without its incomplete last line
head -c -40 "$dir/run/profiles.dat" > "$dir/cut_profiles.dat"
grep -v '^# end:' "$dir/run/timeseries.dat" | head -c -25 > "$dir/cut_series.dat"
"$py" "$plots/plot_profiles.py" "$dir/cut_profiles.dat" -y alpha --times 0,2 -o "$dir/cut1.png" 2>"$dir/err"
grep -q "incomplete last line" "$dir/err"
"$py" "$plots/plot_series.py" "$dir/cut_series.dat" -y H_L2_ext --logy -o "$dir/cut2.png" 2>"$dir/err"
grep -q "incomplete last line" "$dir/err"
[ -s "$dir/cut1.png" ] && [ -s "$dir/cut2.png" ]
"$gbssn1d" sweep --out "$dir/loaders_sweep" --sweep rahA=0,0.5 --sweep rah0=0.9,1 --id 1log-trumpet \
  --grid uniform --N 100 --rmax 20 --tmax 1 --dt-series 0.5 >/dev/null 2>&1
# Colours: more runs than the palette tells apart go into panels of up to seven (never refused)
for k in 1 2 3 4 5 6 7 8 9; do ln -s "$dir/run" "$dir/copy$k"; done
"$py" "$plots/plot_horizons.py" "$dir"/copy{1,2,3,4,5,6,7,8,9}/horizon.dat -o "$dir/nine.png"
head -c 8 "$dir/nine.png" | grep -q PNG
# a sweep's summary.dat (words in it) through plot_series, and the sweep map
"$py" "$plots/plot_series.py" "$dir/loaders_sweep/summary.dat" -x rahA -y M_ah_err_max --logy \
  --points -o "$dir/summary_series.png"
head -c 8 "$dir/summary_series.png" | grep -q PNG
"$py" "$plots/plot_sweep.py" "$dir/loaders_sweep/summary.dat" -o "$dir/sweep_map.png"
head -c 8 "$dir/sweep_map.png" | grep -q PNG
if "$py" "$plots/plot_sweep.py" "$dir/loaders_sweep/summary.dat" -x N -o "$dir/x.png" 2>"$dir/err"; then
  echo "an axis that was not swept accepted"; exit 1
fi
grep -q "not a swept column" "$dir/err"
# a third swept column: refused without --where, naming it; with it, the chosen members' map
"$gbssn1d" sweep --out "$dir/sweep3" --sweep rahA=0,0.5 --sweep rah0=0.9,1 --sweep N=60,80 \
  --id 1log-trumpet --grid uniform --rmax 20 --tmax 0.5 --dt-series 0.5 >/dev/null 2>&1
if "$py" "$plots/plot_sweep.py" "$dir/sweep3/summary.dat" -o "$dir/x.png" 2>"$dir/err"; then
  echo "a third swept column drawn without --where"; exit 1
fi
grep -q "the sweep varies N too (60, 80)" "$dir/err"
"$py" "$plots/plot_sweep.py" "$dir/sweep3/summary.dat" --where N=80 -o "$dir/sweep3.png"
head -c 8 "$dir/sweep3.png" | grep -q PNG
# a sweep over one flag: curves against it (its docstring's promise); -x and -y the same: refused
"$gbssn1d" sweep --out "$dir/sweep1" --sweep rahA=0,0.25,0.5 --id 1log-trumpet --grid uniform \
  --rmax 20 --N 64 --tmax 0.5 --dt-series 0.5 >/dev/null 2>&1
"$py" "$plots/plot_sweep.py" "$dir/sweep1/summary.dat" -o "$dir/sweep1.png"
head -c 8 "$dir/sweep1.png" | grep -q PNG || { echo "plot_sweep.py: no curves for one swept flag"; exit 1; }
status=0
"$py" "$plots/plot_sweep.py" "$dir/sweep3/summary.dat" -x rahA -y rahA --where N=80 -o "$dir/x.png" \
  2>"$dir/err" || status=$?
[ $status -ne 0 ] && grep -q "both name rahA" "$dir/err" || { echo "plot_sweep.py: -x = -y drawn"; exit 1; }
# ... and ordered curves (resolutions, times) darken monotonically along the sequential map
PYTHONPATH="$plots" "$py" - <<'PY'
import numpy as np
from gbssn1d_data import QUALITATIVE, qualitative_colors, sequential_colors
lum = [0.2126 * r + 0.7152 * g + 0.0722 * b for r, g, b, _ in sequential_colors(5)]
assert all(x > y for x, y in zip(lum, lum[1:])), f"sequential colours not darkening: {lum}"
assert len(set(qualitative_colors(7, 'runs'))) == 7 == len(QUALITATIVE)
PY
echo "plot scripts: every figure written, colour rules hold"
# One-line loading: numpy.genfromtxt(file, names=True) reads every output file, the column
# names from its first line, and gives the numbers gbssn1d_data.parse reads
"$gbssn1d" converge --N 40,60,80 --out "$dir/loaders_converge" --id 1log-trumpet --grid uniform \
  --rmax 20 --tmax 1 --dt-series 0.5 >/dev/null 2>&1 || { s=$?; [ $s -eq 6 ]; } # 6: 3 times, too short to judge
PYTHONPATH="$plots" "$py" - "$dir" <<'PY'
import sys
import numpy as np
from gbssn1d_data import parse, read_text
d = sys.argv[1]
files = [f"{d}/run/timeseries.dat", f"{d}/run/profiles.dat", f"{d}/run/horizon.dat",
         f"{d}/boxes32/profiles.dat", f"{d}/loaders_converge/convergence.dat",
         f"{d}/loaders_converge/scaled_H.dat", f"{d}/loaders_sweep/summary.dat"]
for f in files:
    a = np.genfromtxt(f, names=True, dtype=None, encoding=None)
    if 'summary' in f:  # its status and reason columns are words
        columns = open(f).readline()[1:].split()
        assert list(a.dtype.names) == columns, (f, a.dtype.names, columns)
        assert list(a['status']) == ['ok'] * 4, a['status']
        assert list(a['rahA']) == [0, 0, 0.5, 0.5], a['rahA']
        continue
    columns, blocks = parse(read_text(f))
    assert list(a.dtype.names) == columns, (f, a.dtype.names, columns)
    rows = np.concatenate([b for _, b in blocks])
    assert len(a) == len(rows), (f, len(a), len(rows))
    for k, c in enumerate(columns):
        assert np.allclose(a[c], rows[:, k], equal_nan=True, rtol=0, atol=0), (f, c)
# a file of an earlier version (version line first, the column names on the last header line)
# is read the same
text = open(f"{d}/run/timeseries.dat").read().splitlines()
header_end = max(k for k, l in enumerate(text) if l.startswith('#') and k < len(text) - 1
                 and not text[k + 1].startswith('#'))
legacy = text[1:header_end + 1] + [text[0]] + text[header_end + 1:]
assert legacy[0].startswith('# gbssn1d')
new_cols, new_blocks = parse('\n'.join(text))
old_cols, old_blocks = parse('\n'.join(legacy))
assert new_cols == old_cols and np.array_equal(new_blocks[0][1], old_blocks[0][1])
print(f"numpy.genfromtxt(names=True) reads {len(files)} kinds of output file")
# the README's loader keeps each block's time: profiles.dat at t = 0, 1, 2 (--dt-profiles 1,
# --tmax 2 above) and scaled_H.dat at the study's tmax, each table with the file's names
from gbssn1d_data import blocks
prof = blocks(f"{d}/run/profiles.dat")
assert [t for t, _ in prof] == [0.0, 1.0, 2.0], [t for t, _ in prof]
assert all(p.dtype.names[0] == 'r' and 'alpha' in p.dtype.names for _, p in prof)
assert np.array_equal(np.concatenate([p['alpha'] for _, p in prof]),
                      np.genfromtxt(f"{d}/run/profiles.dat", names=True)['alpha'])
scaled = blocks(f"{d}/loaders_converge/scaled_H.dat")
assert [t for t, _ in scaled] == [1.0] and 'H_N40' in scaled[0][1].dtype.names, scaled[0][1].dtype
assert blocks(f"{d}/run/timeseries.dat")[0][0] is None
print("blocks() gives each block of profiles.dat and scaled_H.dat with its time")
PY
# Input that is not gbssn1d output: a missing file, a folder, a binary file, a profiles.dat whose
# block line is '# t = abc'. Every script says so in one line '<script>: <file>: <why>' on
# stderr, exit status 2, no traceback (they raised FileNotFoundError, IsADirectoryError,
# UnicodeDecodeError, ValueError). Layout: hostile/KIND/{profiles,convergence}.dat and
# hostile/KIND/sinh-upwind-gd-N1200/profiles.dat are each of that kind (hostile/missing is none)
refused() {  # refused FILE COMMAND...: exit 2, one line naming FILE, no traceback
  local file=$1 status=0
  shift
  "$@" >/dev/null 2>"$dir/err" </dev/null || status=$?
  if [ $status -ne 2 ] || [ "$(wc -l <"$dir/err")" -ne 1 ] || grep -q Traceback "$dir/err" \
     || ! grep -qF ": $file: " "$dir/err" || ! grep -q '^[a-z0-9_]*\.py: ' "$dir/err"; then
    echo "not refused in one line naming $file (exit $status): ${*:2}"; cat "$dir/err"; exit 1
  fi
}
h=$dir/hostile
mkdir -p "$h"/{folder,binary,badt}/sinh-upwind-gd-N1200
for f in profiles.dat convergence.dat sinh-upwind-gd-N1200/profiles.dat; do
  mkdir "$h/folder/$f"
  cp /bin/true "$h/binary/$f"
  sed 's/^# t = 1$/# t = abc/' "$dir/run/profiles.dat" >"$h/badt/$f"
  grep -q '^# t = abc$' "$h/badt/$f"
done
# the shared reader on each kind; then each other script on '# t = abc' (the file's name reaches
# the parser) and on one of the others in turn (its main is wrapped)
for kind in missing folder binary badt; do
  f=$h/$kind/profiles.dat
  refused "$f" "$py" "$plots/plot_series.py" "$f" -y alpha -o "$dir/x.png"
  refused "$f" "$py" "$plots/plot_profiles.py" "$f" -y alpha -o "$dir/x.png"
done
others=(missing folder binary) i=0
for script in plot_horizons plot_sweep constraint_orders compare_trumpet error_profiles \
              horizon_study refinement_study; do
  for kind in badt "${others[i++ % 3]}"; do
    f=$h/$kind/profiles.dat
    case $script in
      plot_horizons) refused "$f" "$py" "$plots/$script.py" "$f" -o "$dir/x.png" ;;
      plot_sweep) refused "$f" "$py" "$plots/$script.py" "$f" -o "$dir/x.png" ;;
      constraint_orders) refused "$f" "$py" "$plots/$script.py" "$dir/conv60/timeseries.dat" "$f" ;;
      compare_trumpet) refused "$f" "$py" "$plots/$script.py" "$f" "$dir/ref/profiles.dat" ;;
      error_profiles) refused "$f" "$py" "$plots/$script.py" "$dir/boxes16" "$h/$kind" \
                        -o "$dir/x.png" ;;
      horizon_study) refused "$h/$kind/convergence.dat" "$py" "$plots/$script.py" table "$h/$kind" \
                       "$h/$kind" ;;
      refinement_study)
        [ $kind = missing ] && g=$h/missing || g=$h/$kind/sinh-upwind-gd-N1200/profiles.dat
        refused "$g" "$py" "$plots/$script.py" onset "$h/$kind" ;;
    esac
  done
done
for kind in missing folder binary; do # z4c_study.py reads a folder's timeseries.dat
  mkdir -p "$h/z4c-$kind"
  case $kind in folder) mkdir -p "$h/z4c-$kind/timeseries.dat" ;; binary) cp /bin/true "$h/z4c-$kind/timeseries.dat" ;; esac
  refused "$h/z4c-$kind/timeseries.dat" "$py" "$plots/z4c_study.py" table "$dir/run" "$h/z4c-$kind"
done
refused "standard input" bash -c '"$1" "$2/plot_series.py" - -y alpha -o "$3/x.png" </bin/true' \
  _ "$py" "$plots" "$dir"
refused "$h/missing/gbssn1d" "$py" "$plots/boxes_cost.py" --out "$h/cost" --bin "$h/missing/gbssn1d"
refused "$h/folder" "$py" "$plots/boxes_cost.py" --out "$h/cost" --bin "$h/folder"
# an output the figure cannot be written to: a missing folder, an extension that is no image
# format (the data file named by mistake is left as it was): one line naming it, exit 2
refused "$h/missing/x.png" "$py" "$plots/plot_series.py" "$dir/run/timeseries.dat" -y alpha_center \
  -o "$h/missing/x.png"
cp "$dir/run/timeseries.dat" "$h/kept.dat"
refused "$h/kept.dat" "$py" "$plots/plot_series.py" "$dir/run/timeseries.dat" -y alpha_center \
  -o "$h/kept.dat"
cmp -s "$dir/run/timeseries.dat" "$h/kept.dat" || { echo "-o kept.dat overwrote it"; exit 1; }
# a column one of several files lacks (a BSSN run has no Theta_L2_R): the file at fault named,
# exit 2 (it read "no column 'Theta_L2_R'", no file, exit 1)
for script in plot_series.py plot_horizons.py; do
  refused "$dir/run/timeseries.dat" "$py" "$plots/$script" "$dir/z4c/timeseries.dat" \
    "$dir/run/timeseries.dat" -y Theta_L2_R -o "$h/column.png"
done
refused "$dir/run/profiles.dat" "$py" "$plots/plot_profiles.py" "$dir/z4c/profiles.dat" \
  "$dir/run/profiles.dat" -y Theta -o "$h/column.png"
# --times between blocks: the nearest is drawn, and said; a time that is not a number: exit 2
"$py" "$plots/plot_profiles.py" "$dir/run/profiles.dat" -y alpha --times 0.123 -o "$dir/near.png" \
  2>"$dir/err"
grep -q "note: --times 0.123: .* has no block there; the nearest, t = 0, is drawn" "$dir/err" \
  || { echo "plot_profiles.py --times 0.123: no note"; cat "$dir/err"; exit 1; }
status=0
"$py" "$plots/plot_profiles.py" "$dir/run/profiles.dat" -y alpha --times 0,nan -o "$dir/nan.png" \
  2>"$dir/err" || status=$?
[ $status -eq 2 ] && grep -q "\-\-times: 'nan' is not a finite time" "$dir/err" && [ ! -e "$dir/nan.png" ] \
  || { echo "plot_profiles.py --times nan: exit $status"; cat "$dir/err"; exit 1; }
echo "plot scripts: a missing file, a folder, a binary file, '# t = abc', an output that cannot be written: one line each, exit 2"
