#!/usr/bin/env bash
# The headline numbers of docs/findings.md, docs/horizon-shift-study.md and docs/z4c-study.md, rerun
# (about 4 minutes on 2 cores): each claim's number is read from its document by a pattern, measured afresh with
# build/gbssn1d, and compared; the script fails, naming the claim, the document's number and
# the measured one, where they disagree. Run it after changing a default, and list the claims
# rerun in the note.
#
# Usage: bash runs/claims.sh [--doc FILE] [--findings FILE] [--z4c FILE] [--self-test]
#   --doc FILE     check FILE instead of docs/horizon-shift-study.md (e.g. an edited copy)
#   --findings FILE  check FILE instead of docs/findings.md (--readme FILE: the same, its
#                    name from when these findings stood in README.md)
#   --z4c FILE     check FILE instead of docs/z4c-study.md
#   --self-test  also plant a stale number into a copy of the doc and require that the check
#                of that copy fails (the checker can fail)
# Agreement: a number measured exactly (an error of a deterministic run) must round to the
# doc's number within one unit of its last digit; a cost ratio (CPU times of runs one at a
# time) within 25% of it.
set -euo pipefail
caller=$PWD
cd "$(dirname "$0")/.."
doc=docs/horizon-shift-study.md
readme=docs/findings.md
z4cdoc=docs/z4c-study.md
self_test=false
while [ $# -gt 0 ]; do
  case "$1" in
    --doc) doc=${2:?--doc needs a file}; [[ $doc = /* ]] || doc=$caller/$doc; shift ;;
    --findings|--readme) readme=${2:?$1 needs a file}; [[ $readme = /* ]] || readme=$caller/$readme; shift ;;
    --z4c) z4cdoc=${2:?--z4c needs a file}; [[ $z4cdoc = /* ]] || z4cdoc=$caller/$z4cdoc; shift ;;
    --self-test) self_test=true ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--doc FILE] [--findings FILE] [--z4c FILE] [--self-test]" >&2; exit 2 ;;
  esac
  shift
done
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_jobs runs/claims.sh # a bad GBSSN1D_JOBS is refused before anything is made
export GBSSN1D_JOBS=$jobs
[ -x build/gbssn1d ] || { echo "claims: build/gbssn1d is missing (bash .ci/build)" >&2; exit 2; }
[ -f "$doc" ] && [ -r "$doc" ] || { echo "claims: --doc $doc: no such readable file" >&2; exit 2; }
[ -f "$readme" ] && [ -r "$readme" ] || { echo "claims: --findings $readme: no such readable file" >&2; exit 2; }
[ -f "$z4cdoc" ] && [ -r "$z4cdoc" ] || { echo "claims: --z4c $z4cdoc: no such readable file" >&2; exit 2; }
py=python3
[ -x /usr/bin/python3 ] && py=/usr/bin/python3
# every run through runs/lib.sh: a run of the same command and binary that completed is kept (a
# rebuilt binary redoes them all), one that did not is redone, nothing is deleted before its
# replacement completed, Ctrl-C stops at once; the timings (boxes_cost.py) are measured afresh
lib_init runs/claims.sh "$caller" out/claims
g=build/gbssn1d

# --- the measurements (each once; the claims below read them)
# Sec. 6.4 and the summary: the CPU time boxes (9 levels) need to reach the error of the sinh
# grid with innermost cell M/16, 1+log trumpet to 1000 M, standard gauge
# (in 5 alternating pairs: runs one after the other carried the host's drift, 0.42-0.57 in four
# reruns of 2026-11-27 against 0.40-0.45 paired)
$py plots/boxes_cost.py --out "$out/cost" --tmax 1000 --kinds boxes,sinh --gauges standard \
  --pairs 5 >"$out/cost.txt"
cost_ratio=$(sed -n 's/^standard boxes, 5 alternating pairs .*: \([0-9.]*\) x sinh N = 400$/\1/p' \
  "$out/cost.txt")
# Sec. 7.2 and the summary: the standard gauge's max |M_AH - M| to 100 M on the uniform M/16
# grid (N = 1280, rmax 80 M, wormhole data, defaults otherwise)
lib_run uniform-m16 $g evolve --grid uniform --N 1280 --rmax 80 --tmax 100 --dt-series 0.5 \
  --dt-profiles 100 --out @OUT

# The thesis's mechanism (docs/findings.md's answer, study Sec. 13 and 13.1): the hold-scaling table,
# the published configuration's triples at M/16, M/24, M/32 with h_AH held over each step
# (quadratic, RK4 stage values, no subcycling), the shrink's and the standard gauge's smooth
# runs there, and converge's verdicts with a 1 M hold and with h_AH(t) from a file.
bash runs/hold-scaling.sh "$out/hold-scaling" >"$out/hold-scaling.txt"
published=(--id maximal-trumpet --grid boxes --levels 7 --rmax 128 --rah-profile rational
           --rah-width 1 --rah-normal unit --driver-advection upwind-gd --cfl 0.25
           --dt-series 0.25 --dt-profiles 20)
for N in 32 48 64; do
  for v in step:--ah-every=step:--time-interp=quadratic stages:--ah-every=step:--time-interp=rk-stages \
           nosub:--ah-every=step:--no-subcycling:--time-interp=quadratic \
           shrink:--rah0=0.6:--time-interp=quadratic standard:--rahA=0:--time-interp=quadratic; do
    name=${v%%:*} extra=()
    IFS=: read -r -a words <<<"${v#*:}"
    for w in "${words[@]}"; do extra+=(${w/=/ }); done
    [[ $name == shrink ]] && extra+=(--rahA 0.5)
    [[ $name == standard || $name == shrink ]] || extra+=(--rahA 0.5 --rah0 0.89)
    lib_run "triple-$name-$N" $g evolve "${published[@]}" --tmax 20 --N $N "${extra[@]}" --out @OUT
  done
done
lib_run verdict-held $g converge --N 48,64,96 "${published[@]}" --time-interp quadratic --tmax 100 \
  --rahA 0.5 --rah0 0.89 --ah-interval 1 --out @OUT
lib_run verdict-ref192 $g evolve "${published[@]}" --time-interp quadratic --tmax 100 --rahA 0.5 \
  --rah0 0.89 --N 192 --out @OUT
# Z4c (docs/findings.md's Z4c paragraph, docs/z4c-study.md Sec. 5, 7, 9): the four long-run set-ups with
# BSSN, Z4c's default and kappa1 = 0.02 everywhere; the sinh grid at N = 240, 320; the published
# stretch on uniform grids M/8-M/16 in both formulations
long=(--tmax 1000 --dt-series 1 --dt-profiles 10000)
declare -A setups=([st]="--id 1log-trumpet --N 160" [sw]="--id wormhole --N 160"
  [bt]="--id 1log-trumpet --grid boxes --levels 10 --rmax 2048 --N 64"
  [bw]="--id wormhole --grid boxes --levels 10 --rmax 2048 --N 64"
  [st240]="--id 1log-trumpet --N 240" [st320]="--id 1log-trumpet --N 320"
  [sw240]="--id wormhole --N 240" [sw320]="--id wormhole --N 320")
for s in "${!setups[@]}"; do
  for f in bssn default k0.02; do
    case $f in bssn) extra=() ;; default) extra=(--formulation z4c) ;; k0.02) extra=(--formulation z4c --kappa1-hole 0) ;; esac
    # shellcheck disable=SC2086 # the set-up's words
    lib_run "z4c-$s-$f" $g evolve ${setups[$s]} "${long[@]}" "${extra[@]}" --out @OUT
  done
done
for f in bssn z4c; do
  lib_run "z4c-published-$f" $g converge --N 1600,2400,3200 -j 1 --grid uniform --rmax 200 \
    --tmax 100 --dt-series 1 --dt-profiles 100 --id 1log-trumpet --formulation $f --rahA 0.5 \
    --rah0 0.89 --rah-profile rational --rah-width 1 --rah-normal unit --driver-advection upwind-gd \
    --out @OUT
done
lib_wait
# the file converge follows is the finished reference's horizon.dat (an input: redone with it)
lib_check verdict-ref192
lib_run verdict-file $g converge --N 48,64,96 "${published[@]}" --time-interp quadratic --tmax 100 \
  --rahA 0.5 --rah0 0.89 --rah-hAH-file "$out/verdict-ref192/horizon.dat" --out @OUT
lib_wait
lib_check
m16_error=$($py -c '
import sys
cols = None
worst = 0.0
for line in open(sys.argv[1]):
    if line.startswith("# t "):
        cols = line[2:].split()
    elif line.strip() and not line.startswith("#"):
        v = float(line.split()[cols.index("M_ah_err")])
        worst = max(worst, abs(v))
print(f"{worst:.6e}")' "$out/uniform-m16/timeseries.dat")
measured=$out/measured.txt
$py - "$out" >"$measured" <<'PY'
import math, os, re, sys
import numpy as np
out = sys.argv[1]
def rms(path):
    d = np.genfromtxt(os.path.join(path, 'timeseries.dat'), names=True)
    m = (d['t'] > 0) & (d['t'] <= 20 + 1e-9)
    return float(np.sqrt(np.mean(d['H_L2_R'][m] ** 2)))
def order(a, b, na, nb):
    return math.log(a / b) / math.log(nb / na)
def slope(x, y):
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])
t = np.genfromtxt(os.path.join(out, 'hold-scaling', 'scaling.dat'), names=True)
def rows(**fixed):
    keep = np.ones(len(t), bool)
    for k, v in fixed.items():
        keep &= np.isclose(t[k], v)
    return t[keep]
v = {}
r = rows(N=64, cfl=0.25, rahA=0.5); v['p_T'] = slope(r['T'], r['excess'])
r = rows(N=64, cfl=0.25, T=1); v['p_A'] = slope(r['rahA'], r['excess'])
r = rows(N=64, rahA=0.5, T=1); v['p_cfl64'] = slope(r['cfl'], r['excess'])
r = rows(N=128, rahA=0.5, T=1); v['p_cfl128'] = slope(r['cfl'], r['excess'])
r = rows(cfl=0.25, rahA=0.5, T=1); v['p_dr'] = slope(r['dr_min'], r['excess'])
v['p_dr_smooth'] = slope(r['dr_min'], r['rms_H_smooth'])
def pair(cfl, T, N1, N2, col='rms_H_held'):
    a, b = rows(N=N1, cfl=cfl, rahA=0.5, T=T), rows(N=N2, cfl=cfl, rahA=0.5, T=T)
    return order(a[col][0], b[col][0], N1, N2)
v['hold1_48_64'] = pair(0.25, 1, 48, 64)
v['hold4_32_48'] = pair(0.25, 4, 32, 48)
v['hold8_32_48'] = pair(0.25, 8, 32, 48)
coarse25 = [pair(0.25, T, 24, 32) for T in (1, 4, 8, 16)]
coarse50 = [pair(0.5, T, 24, 32) for T in (1, 4, 8, 16)]
v['coarse25_min'], v['coarse25_max'] = min(coarse25), max(coarse25)
v['coarse50_min'], v['coarse50_max'] = min(coarse50), max(coarse50)
for name in ('step', 'stages', 'nosub'):
    e = [rms(os.path.join(out, f'triple-{name}-{N}')) for N in (32, 48, 64)]
    v[f'{name}_a'], v[f'{name}_b'] = order(e[0], e[1], 32, 48), order(e[1], e[2], 48, 64)
s = [rows(N=N, cfl=0.25, rahA=0.5, T=1)['rms_H_smooth'][0] for N in (32, 48, 64)]
v['smooth_a'], v['smooth_b'] = order(s[0], s[1], 32, 48), order(s[1], s[2], 48, 64)
for k, N in enumerate((32, 48, 64)):
    v[f'shrink_ratio_{N}'] = (rms(os.path.join(out, f'triple-shrink-{N}'))
                              / rms(os.path.join(out, f'triple-standard-{N}')))
for name in ('held', 'file'):
    text = open(os.path.join(out, f'verdict-{name}', 'convergence.dat')).read()
    m = re.search(r'\n# verdict: ([a-z -]+?)(:|$)', text, re.M)
    v[f'verdict_{name}'] = m.group(1).strip() if m else 'none'
    log = open(os.path.join(out, f'verdict-{name}.log')).read()
    m = re.search(r'the lowest over time is (-?[0-9.]+)', log)
    v[f'lowest_{name}'] = float(m.group(1)) if m else float('nan')
def long_run(name):
    d = np.genfromtxt(os.path.join(out, f'z4c-{name}', 'timeseries.dat'), names=True)
    m = (d['t'] >= 100) & (d['t'] <= 1000)
    return float(np.sqrt(np.mean(d['H_L2_R'][m] ** 2))), float(np.max(np.abs(d['M_ah_err'][m])))
for s in ('st', 'sw', 'bt', 'bw', 'st240', 'st320', 'sw240', 'sw320'):
    bH, bM = long_run(f'{s}-bssn')
    for f in ('default', 'k0.02'):
        H, M = long_run(f'{s}-{f}')
        v[f'z4c_{s}_{f}_H'], v[f'z4c_{s}_{f}_M'] = H / bH, M / bM
for s in ('st', 'bt'):
    v[f'z4c_{s}_default_H_inv'] = 1 / v[f'z4c_{s}_default_H']
    v[f'z4c_{s}_default_M_inv'] = 1 / v[f'z4c_{s}_default_M']
for s in ('sw', 'bw'):
    v[f'z4c_{s}_default_H_inv'] = 1 / v[f'z4c_{s}_default_H']
for f in ('bssn', 'z4c'):
    text = open(os.path.join(out, f'z4c-published-{f}', 'convergence.dat')).read()
    cols, rows = None, []
    for line in text.splitlines():
        if line.startswith('# t '):
            cols = line[2:].split()
        elif cols and line.strip() and not line.startswith('#'):
            rows.append([float(x) for x in line.split()])
    a = np.array(rows)
    t = a[:, cols.index('t')]
    sel = (t >= 10) & (t <= 100)
    e = [float(np.sqrt(np.mean(a[sel, cols.index(f'H_L2_R_N{n}')] ** 2))) for n in (1600, 2400, 3200)]
    v[f'published_{f}_b'] = order(e[1], e[2], 2400, 3200)
for k, x in v.items():
    print(k, x if isinstance(x, str) else f'{x:.6g}')
PY

# --- the claims: name | pattern whose group 1 is the doc's number | measured | kind
check() {
  local file=$1 readme_file=$2
  $py - "$file" "$readme_file" "$cost_ratio" "$m16_error" "$measured" "$z4cdoc" <<'PY'
import math, re, sys
def text_of(path):  # white space folded, so that a pattern does not care where a line breaks
    return re.sub(r'\s+', ' ', open(path).read())
doc, readme, z4cdoc = text_of(sys.argv[1]), text_of(sys.argv[2]), text_of(sys.argv[6])
cost_ratio, m16_error = float(sys.argv[3]), float(sys.argv[4])
v = {}
for line in open(sys.argv[5]):
    k, x = line.split(None, 1)
    x = x.strip()
    try:
        v[k] = float(x)
    except ValueError:
        v[k] = x
S, R, Z = 'study', 'findings', 'z4c'
def several(where, names, pattern, *measured):
    """One claim per group of `pattern` (a sentence that states several numbers): the k-th
    measured value against group k, named by the k-th of the ';'-separated `names` after its
    stem (the text before the first ',' of names' first part)."""
    first, *rest = names.split('; ')
    stem = first.rsplit(', ', 1)[0]
    labels = [first] + [f"{stem}, {r}" for r in rest]
    return [(where, labels[k], pattern, m, "exact", k + 1) for k, m in enumerate(measured)]
claims = [
    (S, "boxes' cost at the sinh grid's error (Sec. 6.4 table text)",
     r"boxes need ([0-9.]+) of its CPU time \(standard gauge", cost_ratio, "ratio"),
    (S, "boxes' cost at the sinh grid's error (summary)",
     r"Boxes reach the sinh grid's error at about ([0-9.]+) times its cost", cost_ratio, "ratio"),
    (S, "uniform M/16 standard gauge, max |M_AH - M| to 100 M (Sec. 7.2 table, default sigma)",
     r"\| 4, 0\.1 \(default\) \| ([0-9.e+-]+) \|", m16_error, "exact"),
    (S, "uniform M/16 standard gauge, max |M_AH - M| to 100 M (summary)",
     r"the unshifted run's own truncation error is ([0-9.e+-]+)", m16_error, "exact"),
    # the answer
    *several(R, "the published configuration at M/24-M/32, held a hierarchy step; held 1 M",
          r"\(H's order ([0-9.-]+) with a hold of one hierarchy step, ([0-9.-]+) with 1 M\)",
          v['step_b'], v['hold1_48_64']),
    *several(R, "M/16-M/24, a 4 M hold; an 8 M hold", r"4-8 M holds \(([0-9.-]+), ([0-9.-]+)\)",
          v['hold4_32_48'], v['hold8_32_48']),
    *several(R, "M/12-M/16 with 1-16 M holds at cfl 0.25, lowest; highest",
          r"orders ([0-9.]+)-([0-9.]+) at cfl 0\.25", v['coarse25_min'], v['coarse25_max']),
    *several(R, "M/12-M/16 with 1-16 M holds at cfl 0.5, lowest; highest",
          r"at cfl 0\.25, ([0-9.]+)-([0-9.]+) at cfl 0\.5", v['coarse50_min'], v['coarse50_max']),
    *several(R, "one smooth h_AH(t), M/16-M/24; M/24-M/32", r"\(H ([0-9.]+), ([0-9.]+) at M/16-M/32;",
          v['smooth_a'], v['smooth_b']),
    *several(R, "RK4 stage values, M/16-M/24; M/24-M/32",
          r"fine boundaries \(([0-9.]+), ([0-9.]+)\) or no subcycling", v['stages_a'], v['stages_b']),
    *several(R, "no subcycling, M/16-M/24; M/24-M/32", r"or no subcycling \(([0-9.]+), ([0-9.]+)\)",
          v['nosub_a'], v['nosub_b']),
    (R, "converge's verdict with h_AH(t) from a file", r'`gbssn1d converge` says "([a-z ]+)" at M/24-M/48',
     v['verdict_file'], "words"),
    (R, "converge's verdict with a 1 M hold", r'with a 1 M hold "([a-z ]+)"\)', v['verdict_held'], "words"),
    # Sec. 13 and 13.1
    (S, "Sec. 13.1: the excess against the hold", r"\| hold T \(N = 64, cfl 0\.25, A = 0\.5\) \| [^|]* \| [^|]* \| ([0-9.-]+) \|",
     v['p_T'], "exact"),
    (S, "Sec. 13.1: the excess against A", r"\| strength A \(N = 64, cfl 0\.25, T = 1 M\) \| [^|]* \| [^|]* \| ([0-9.-]+) \|",
     v['p_A'], "exact"),
    (S, "Sec. 13.1: the excess against the Courant number, N = 64",
     r"\| Courant number \(N = 64, T = 1 M\) \| [^|]* \| [^|]* \| ([0-9.-]+) \|", v['p_cfl64'], "exact"),
    (S, "Sec. 13.1: the excess against the Courant number, N = 128",
     r"\| Courant number \(N = 128, T = 1 M\) \| [^|]* \| [^|]* \| ([0-9.-]+) \|", v['p_cfl128'], "exact"),
    (S, "Sec. 13.1: the excess against the spacing at cfl 0.25",
     r"\| spacing at cfl 0\.25 \(T = 1 M\) \| [^|]* \| [^|]* \| ([0-9.-]+) \|", v['p_dr'], "exact"),
    (S, "Sec. 13.1: the smooth run's RMS H against the spacing",
     r"\| the smooth run's RMS H there \| [^|]* \| [^|]* \| ([0-9.-]+) \|", v['p_dr_smooth'], "exact"),
    (S, "Sec. 13.1: converge with h_AH(t) from a file, lowest order over time",
     r"lowest order over time ([0-9.]+), exit 0\)", v['lowest_file'], "exact"),
    *several(S, "Sec. 13: the shrink's smooth error over the standard gauge's, at M/16; at M/24; at M/32",
          r"smooth h_AH: ([0-9.]+), ([0-9.]+) and ([0-9.]+) times the standard gauge's at M/16",
          v['shrink_ratio_32'], v['shrink_ratio_48'], v['shrink_ratio_64']),
    # Z4c: docs/findings.md's paragraph
    *several(R, "Z4c's default on trumpet data, H below BSSN's (sinh); (boxes)",
          r"Z4c's H over 100-1000 M is ([0-9]+)-([0-9]+) times below BSSN's",
          v['z4c_st_default_H_inv'], v['z4c_bt_default_H_inv']),
    *several(R, "Z4c's default on trumpet data, the horizon mass better (sinh); (boxes)",
          r"horizon-mass error ([0-9]+)-([0-9]+) times smaller", v['z4c_st_default_M_inv'],
          v['z4c_bt_default_M_inv']),
    *several(R, "Z4c's default on wormhole data, H below BSSN's (sinh); (boxes)",
          r"on wormhole data H is ([0-9]+) times below BSSN's", v['z4c_sw_default_H_inv']),
    *several(R, "Z4c's default on wormhole data, H below BSSN's (boxes)",
          r"on wormhole data H is ([0-9]+) times below BSSN's", v['z4c_bw_default_H_inv']),
    *several(R, "Z4c's default on wormhole data, the mass error: sinh M/16; sinh M/32; boxes",
          r"the mass error is ([0-9.]+) of BSSN's on the sinh grid at M/16 \(([0-9.]+) times at "
          r"M/32: it converges more slowly\) and ([0-9.]+) times on boxes",
          v['z4c_sw_default_M'], v['z4c_sw320_default_M'], v['z4c_bw_default_M']),
    (R, "Z4c with kappa1 = 0.02 everywhere, the horizon mass drift over BSSN's",
     r"the horizon mass drifted ([0-9.]+) times as far as BSSN's", v['z4c_st_k0.02_M'], "exact"),
    *several(R, "the published stretch on the 1+log trumpet, M/12-M/16, BSSN; Z4c",
          r"BSSN's ([0-9.]+) becomes ([0-9.]+)\)", v['published_bssn_b'], v['published_z4c_b']),
    # Z4c: docs/z4c-study.md Sec. 9 (the default row of the table, kappa1 = 0.02 everywhere)
    *several(Z, "Sec. 9 the default, (a) H; (a) M; (b) H; (b) M; (c) H; (c) M; (d) H; (d) M",
          r"\| \*\*1 \(default\)\*\* \| \*\*([0-9.]+), ([0-9.]+) \([^|]*\| \*\*([0-9.]+), "
          r"([0-9.]+) \([^|]*\| \*\*([0-9.]+), ([0-9.]+) \([^|]*\| \*\*([0-9.]+), ([0-9.]+) \(",
          v['z4c_st_default_H'], v['z4c_st_default_M'], v['z4c_bw_default_H'],
          v['z4c_bw_default_M'], v['z4c_bt_default_H'], v['z4c_bt_default_M'],
          v['z4c_sw_default_H'], v['z4c_sw_default_M']),
    *several(Z, "Sec. 9 kappa1 = 0.02 everywhere, (a) H; (a) M; (b) H; (b) M; (c) H; (c) M; (d) H; (d) M",
          r"\| 0 \(kappa1 = 0\.02 everywhere\) \| ([0-9.]+), ([0-9.]+) \([^|]*\| ([0-9.]+), "
          r"([0-9.]+) \([^|]*\| ([0-9.]+), ([0-9.]+) \([^|]*\| ([0-9.]+), ([0-9.]+) \(",
          v['z4c_st_k0.02_H'], v['z4c_st_k0.02_M'], v['z4c_bw_k0.02_H'], v['z4c_bw_k0.02_M'],
          v['z4c_bt_k0.02_H'], v['z4c_bt_k0.02_M'], v['z4c_sw_k0.02_H'], v['z4c_sw_k0.02_M']),
    # Sec. 5: the default at N = 240, 320
    *several(Z, "Sec. 5 the default, trumpet N = 240 H; M",
          r"\| trumpet, 240 \| [^|]* \| ([0-9.]+), ([0-9.]+) \|", v['z4c_st240_default_H'],
          v['z4c_st240_default_M']),
    *several(Z, "Sec. 5 the default, trumpet N = 320 H; M",
          r"\| trumpet, 320 \| [^|]* \| ([0-9.]+), ([0-9.]+) \|", v['z4c_st320_default_H'],
          v['z4c_st320_default_M']),
    *several(Z, "Sec. 5 the default, wormhole N = 240 H; M",
          r"\| wormhole, 240 \| [^|]* \| ([0-9.]+), ([0-9.]+) \|", v['z4c_sw240_default_H'],
          v['z4c_sw240_default_M']),
    *several(Z, "Sec. 5 the default, wormhole N = 320 H; M",
          r"\| wormhole, 320 \| [^|]* \| ([0-9.]+), ([0-9.]+) \|", v['z4c_sw320_default_H'],
          v['z4c_sw320_default_M']),
    # Sec. 7: the published stretch's order at M/12-M/16
    *several(Z, "Sec. 7 the published stretch M/12-M/16, BSSN; Z4c",
          r"orders 6\.37, \*\*([0-9.]+)\*\*.*?orders 5\.19, \*\*([0-9.]+)\*\*",
          v['published_bssn_b'], v['published_z4c_b']),
]
bad = 0
for where, name, pattern, measured, kind, *group in claims:
    m = re.search(pattern, {S: doc, R: readme, Z: z4cdoc}[where])
    if not m:
        print(f"MISSING  [{where}] {name}: no longer said (pattern {pattern!r})")
        bad += 1
        continue
    text = m.group(group[0] if group else 1).rstrip(".")
    if kind == "words":
        ok = text == measured
        print(f"{'ok      ' if ok else 'STALE   '} [{where}] {name}: says {text!r}, measured {measured!r}")
        bad += 0 if ok else 1
        continue
    said = float(text)
    if kind == "ratio":
        ok = abs(measured - said) <= 0.25 * said
    else:  # the doc's digits: measured rounded to them, within one unit of the last
        mant = text.split("e")[0].lstrip("-")
        decimals = len(mant.split(".")[1]) if "." in mant else 0
        if "e" in text:
            digits = len(mant.replace(".", "").lstrip("0"))
            unit = 10 ** (math.floor(math.log10(abs(said))) - digits + 1)
        else:
            unit = 10 ** (-decimals)
        ok = abs(measured - said) <= 1.0 * unit + 1e-15
    print(f"{'ok      ' if ok else 'STALE   '} [{where}] {name}: says {text}, measured {measured:.3g}")
    bad += 0 if ok else 1
print(f"claims: {len(claims) - bad} of {len(claims)} agree")
sys.exit(1 if bad else 0)
PY
}
status=0
check "$doc" "$readme" || status=$?
if $self_test; then
  planted=$(mktemp)
  sed 's/the unshifted run.s own truncation error is [0-9.e+-]*/the unshifted run'"'"'s own truncation error is 4.2e-5/' \
    "$doc" >"$planted"
  if check "$planted" "$readme" >/dev/null; then
    echo "claims: self-test FAILED: a planted stale number (4.2e-5) was not caught"
    status=1
  else
    echo "claims: self-test: a planted stale number (4.2e-5) is caught"
  fi
  rm -f "$planted"
fi
exit $status
