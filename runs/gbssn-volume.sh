#!/usr/bin/env bash
# Brown's two volume choices (--gbssn-volume lagrangian | eulerian; docs/gbssn1d-equations.md
# Sec. 18) side by side in the moving-puncture gauge (1+log, Gamma-driver): the 1+log trumpet
# and the wormhole on uniform grids to 40 M at M/8, M/12, M/16 and M/32, without the horizon
# shift and with it (stretch to h = 2 M, shrink to h = 0.6 M, A = 0.5), and a convergence
# study of each choice over the first 3.5 M on the trumpet.
# Prints, for every run, how it ended (completed, or the time it left the physical range),
# the RMS of H_L2_R over 0.5-3.5 M, b's largest value at t = 3.5 (the Eulerian choice lets the
# shift drag the conformal metric: d_t ln(a b^2) = 2 Dbar.beta), and each study's verdict.
# Kept in out/gbssn-volume/ and redone only where a command or the binary changed (about 2
# minutes on 2 cores).
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/lib.sh
lib_init runs/gbssn-volume.sh "$here" out/gbssn-volume "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
common=(--grid uniform --rmax 40 --tmax 40 --dt-series 0.25 --dt-profiles 3.5)
names=()
for vol in lagrangian eulerian; do
  for id in 1log-trumpet wormhole; do
    for gauge in standard h2 h0.6; do
      shift_args=()
      [ $gauge = h2 ] && shift_args=(--rahA 0.5 --rah0 2)
      [ $gauge = h0.6 ] && shift_args=(--rahA 0.5 --rah0 0.6)
      for N in 320 480 640 1280; do
        name=$vol-$id-$gauge-N$N
        names+=("$name")
        lib_run "$name" build/gbssn1d evolve --gbssn-volume $vol --id $id --N $N "${common[@]}" \
          "${shift_args[@]}" --out @OUT
      done
    done
  done
  lib_run "converge-$vol" build/gbssn1d converge --gbssn-volume $vol --id 1log-trumpet \
    --grid uniform --rmax 40 --N 320,480,640 --tmax 3.5 --dt-series 0.125 --out @OUT
done
lib_wait
lib_check
{
  $py - "$out" "${names[@]}" <<'EOF'
import math, sys
out, names = sys.argv[1], sys.argv[2:]
print("# run | end | RMS of H_L2_R over 0.5-3.5 M | max b at t = 3.5")
for name in names:
    ts = f"{out}/{name}/timeseries.dat"
    cols, rows, end = None, [], "?"
    for line in open(ts):
        if line.startswith("# end:"):
            end = line[6:].strip()
        elif line.startswith("# t "):
            cols = line[2:].split()
        elif not line.startswith("#") and line.strip():
            rows.append([float(w) for w in line.split()])
    t, h = cols.index("t"), cols.index("H_L2_R")
    window = [r[h] for r in rows if 0.5 <= r[t] <= 3.5 and math.isfinite(r[h])]
    rms = math.sqrt(sum(v * v for v in window) / len(window)) if window else float("nan")
    b_max, block_t = float("nan"), None
    pcols = None
    for line in open(f"{out}/{name}/profiles.dat"):
        if line.startswith("# r "):
            pcols = line[2:].split()
        elif line.startswith("# t ="):
            block_t = float(line.split("=")[1])
        elif not line.startswith("#") and line.strip() and block_t == 3.5:
            v = float(line.split()[pcols.index("b")])
            b_max = v if math.isnan(b_max) else max(b_max, v)
    print(f"{name} | {end} | {rms:.3e} | {b_max:.4g}")
EOF
  for vol in lagrangian eulerian; do
    echo "# converge-$vol: $(sed -n 's/^# verdict: //p' "$out/converge-$vol/convergence.dat")"
  done
} | tee "$out/table.txt"
