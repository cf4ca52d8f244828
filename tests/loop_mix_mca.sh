#!/usr/bin/env bash
# bench/loop_mix.py --mca reads llvm-mca's report of the point loop (docs/roofline.md, Sec. 7).
# Checked against llvm-mca run here on the same assembly (--mca-asm) and read independently
# (awk): the cycles per iteration and the busiest resource and its pressure must agree. Checked
# for plausibility: the busiest resource carries at least a quarter of the arithmetic
# instructions (two floating-point ports on Intel's cores, four pipes on AMD's), and the cycles
# are at least that busiest resource's pressure.
# Usage: loop_mix_mca.sh PYTHON OBJECT; exits 77 (skipped) where llvm-mca is not installed.
set -euo pipefail
python=$1 object=$2
command -v llvm-mca >/dev/null || { echo "llvm-mca not installed: skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=$("$python" "$(dirname "$0")/../bench/loop_mix.py" "$object" --mca --mca-asm "$tmp/loop.s")
echo "$out"
arithmetic=$(awk '/^fp_arithmetic/ {print $3}' <<<"$out")
cycles=$(awk '/^mca_cycles_per_iteration/ {print $3}' <<<"$out")
ports=$(sed -n 's/^mca_port_pressure_per_iteration //p' <<<"$out")
[ -n "$arithmetic" ] && [ -n "$cycles" ] && [ -n "$ports" ] || { echo "missing rows"; exit 1; }
busiest_name=${ports%%=*}
busiest=$(sed 's/^[^=]*=\([0-9.]*\).*/\1/' <<<"$ports")

# llvm-mca's own report of the same assembly, read here
llvm-mca -mcpu=native -iterations=300 -timeline=false -instruction-info=false "$tmp/loop.s" \
  >"$tmp/report.txt"
read -r own_cycles own_name own_busiest < <(awk '
  /^Total Cycles:/ { cycles = $3 / 300 }
  /^\[[0-9.]+\] +- / { label = substr($1, 2, length($1) - 2); name[label] = $3 }
  /^Resource pressure per iteration:/ { table = 1; next }
  table == 1 { n = split($0, labels, " "); table = 2; next }
  table == 2 {
    for (k = 1; k <= n; ++k) {
      label = substr(labels[k], 2, length(labels[k]) - 2)
      v = ($k == "-") ? 0 : $k
      if (v > best) { best = v; who = label }
    }
    table = 0
  }
  END {
    unit = (who ~ /\./) ? substr(who, index(who, ".")) : ""
    printf "%.1f %s %.0f\n", cycles, name[who] unit, best
  }' "$tmp/report.txt")
awk -v a="$cycles" -v b="$own_cycles" 'BEGIN { exit !(a - b < 0.11 && b - a < 0.11) }' \
  || { echo "cycles: loop_mix.py $cycles, llvm-mca's report $own_cycles"; exit 1; }
[ "$busiest_name" = "$own_name" ] && [ "$busiest" = "$own_busiest" ] \
  || { echo "busiest: loop_mix.py $busiest_name=$busiest, llvm-mca's report $own_name=$own_busiest"; exit 1; }
awk -v b="$busiest" -v a="$arithmetic" -v c="$cycles" 'BEGIN { exit !(b >= a / 4 && c >= b) }' \
  || { echo "busiest $busiest, cycles $cycles for $arithmetic arithmetic instructions: implausible"; exit 1; }
echo "ok: $cycles cycles per iteration, busiest $busiest_name=$busiest, as llvm-mca's own report"
