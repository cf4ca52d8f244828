#!/usr/bin/env bash
# bench/loop_mix.py --mca reads llvm-mca's report of the point loop (docs/roofline.md, Sec. 7):
# the cycles an iteration takes in the model must be at least the arithmetic's share of the two
# floating-point ports (one instruction a cycle each), and the busiest port must be named and
# carry at least a quarter of the arithmetic.
# Usage: loop_mix_mca.sh PYTHON OBJECT; exits 77 (skipped) where llvm-mca is not installed.
set -euo pipefail
python=$1 object=$2
command -v llvm-mca >/dev/null || { echo "llvm-mca not installed: skipped"; exit 77; }
out=$("$python" "$(dirname "$0")/../bench/loop_mix.py" "$object" --mca)
echo "$out"
arithmetic=$(awk '/^fp_arithmetic/ {print $3}' <<<"$out")
cycles=$(awk '/^mca_cycles_per_iteration/ {print $3}' <<<"$out")
ports=$(sed -n 's/^mca_port_pressure_per_iteration //p' <<<"$out")
[ -n "$arithmetic" ] && [ -n "$cycles" ] && [ -n "$ports" ] || { echo "missing rows"; exit 1; }
awk -v c="$cycles" -v a="$arithmetic" 'BEGIN { exit !(c >= a / 2 && c < 10 * a) }' \
  || { echo "mca cycles $cycles against $arithmetic arithmetic instructions: implausible"; exit 1; }
grep -q "Port" <<<"$ports" || { echo "no port named: $ports"; exit 1; }
# the busiest port carries at least a quarter of the arithmetic (two FP ports on Intel's cores,
# four FP pipes on AMD's)
busiest=$(sed 's/^[^=]*=\([0-9.]*\).*/\1/' <<<"$ports")
awk -v b="$busiest" -v a="$arithmetic" 'BEGIN { exit !(b >= a / 4) }' \
  || { echo "busiest port $busiest for $arithmetic arithmetic instructions: not the busiest"; exit 1; }
echo "ok: $cycles cycles per iteration for $arithmetic arithmetic instructions; $ports"
