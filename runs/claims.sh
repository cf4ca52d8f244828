#!/usr/bin/env bash
# The headline numbers of docs/horizon-shift-study.md, rerun (about 2 minutes on 2 cores): each
# claim's number is read from the doc by a pattern, measured afresh with build/gbssn1d, and
# compared; the script fails, naming the claim, the doc's number and the measured one, where
# they disagree. Run it after changing a default, and list the claims rerun in the note.
#
# Usage: bash runs/claims.sh [--doc FILE] [--self-test]
#   --doc FILE   check FILE instead of docs/horizon-shift-study.md (e.g. an edited copy)
#   --self-test  also plant a stale number into a copy of the doc and require that the check
#                of that copy fails (the checker can fail)
# Agreement: a number measured exactly (an error of a deterministic run) must round to the
# doc's number within one unit of its last digit; a cost ratio (CPU times of runs one at a
# time) within 25% of it.
set -euo pipefail
caller=$PWD
cd "$(dirname "$0")/.."
doc=docs/horizon-shift-study.md
self_test=false
while [ $# -gt 0 ]; do
  case "$1" in
    --doc) doc=${2:?--doc needs a file}; [[ $doc = /* ]] || doc=$caller/$doc; shift ;;
    --self-test) self_test=true ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--doc FILE] [--self-test]" >&2; exit 2 ;;
  esac
  shift
done
[ -x build/gbssn1d ] || { echo "claims: build/gbssn1d is missing (bash .ci/build)" >&2; exit 2; }
[ -f "$doc" ] && [ -r "$doc" ] || { echo "claims: --doc $doc: no such readable file" >&2; exit 2; }
py=python3
[ -x /usr/bin/python3 ] && py=/usr/bin/python3
out=out/claims
mkdir -p "$out"

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
rm -rf "$out/uniform-m16"
build/gbssn1d evolve --grid uniform --N 1280 --rmax 80 --tmax 100 --dt-series 0.5 \
  --dt-profiles 100 --out "$out/uniform-m16" 2>"$out/uniform-m16.log"
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

# --- the claims: name | pattern whose group 1 is the doc's number | measured | kind
check() {
  local file=$1
  $py - "$file" "$cost_ratio" "$m16_error" <<'PY'
import math, re, sys
doc = open(sys.argv[1]).read()
cost_ratio, m16_error = float(sys.argv[2]), float(sys.argv[3])
claims = [
    ("boxes' cost at the sinh grid's error (Sec. 6.4 table text)",
     r"boxes need ([0-9.]+)\s+of its CPU time \(standard gauge", cost_ratio, "ratio"),
    ("boxes' cost at the sinh grid's error (summary)",
     r"Boxes reach the sinh grid's error at about ([0-9.]+) times its\s+cost", cost_ratio, "ratio"),
    ("uniform M/16 standard gauge, max |M_AH - M| to 100 M (Sec. 7.2 table, default sigma)",
     r"\| 4, 0\.1 \(default\) \| ([0-9.e+-]+) \|", m16_error, "exact"),
    ("uniform M/16 standard gauge, max |M_AH - M| to 100 M (summary)",
     r"the unshifted run's own truncation error is ([0-9.e+-]+)", m16_error, "exact"),
]
bad = 0
for name, pattern, measured, kind in claims:
    m = re.search(pattern, doc)
    if not m:
        print(f"MISSING  {name}: the doc no longer says it (pattern {pattern!r})")
        bad += 1
        continue
    text = m.group(1).rstrip(".")
    said = float(text)
    if kind == "ratio":
        ok = abs(measured - said) <= 0.25 * said
    else:  # the doc's digits: measured rounded to them, within one unit of the last
        mant = text.split("e")[0]
        digits = len(mant.replace(".", "").lstrip("0"))
        unit = 10 ** (math.floor(math.log10(abs(said))) - digits + 1)
        ok = abs(measured - said) <= 1.0 * unit + 1e-15
    print(f"{'ok      ' if ok else 'STALE   '} {name}: the doc says {text}, measured {measured:.3g}")
    bad += 0 if ok else 1
print(f"claims: {len(claims) - bad} of {len(claims)} agree")
sys.exit(1 if bad else 0)
PY
}
status=0
check "$doc" || status=$?
if $self_test; then
  planted=$(mktemp)
  sed 's/the unshifted run.s own truncation error is [0-9.e+-]*/the unshifted run'"'"'s own truncation error is 4.2e-5/' \
    "$doc" >"$planted"
  if check "$planted" >/dev/null; then
    echo "claims: self-test FAILED: a planted stale number (4.2e-5) was not caught"
    status=1
  else
    echo "claims: self-test: a planted stale number (4.2e-5) is caught"
  fi
  rm -f "$planted"
fi
exit $status
