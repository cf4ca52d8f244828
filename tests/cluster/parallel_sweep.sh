#!/usr/bin/env bash
# A sweep run by GNU parallel from its emitted lines alone, started in another folder, then
# --collect: the summary must equal a direct sweep's (wall time aside).
# Usage: parallel_sweep.sh GBSSN1D_EXECUTABLE. Exit 77 (skipped) when parallel is missing.
set -euo pipefail
exe=$1
command -v parallel >/dev/null 2>&1 || { echo "skipped: GNU parallel is not installed"; exit 77; }
tmp=$(mktemp -d /tmp/gbssn1d_parallel.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/elsewhere"
flags=(--sweep rahA=0.25,0.5 --sweep rah0=0.6,1.2 --id 1log-trumpet --grid uniform --N 100
       --rmax 20 --tmax 5 --dt-series 1)
"$exe" sweep -j 2 --out "$tmp/direct" "${flags[@]}" >/dev/null 2>&1
(cd "$tmp" && "$exe" sweep --out queued "${flags[@]}" --emit-tasks tasks.txt >/dev/null 2>&1)
(cd "$tmp/elsewhere" && parallel --will-cite -j 2 <"$tmp/tasks.txt" >/dev/null 2>&1)
"$exe" sweep --out "$tmp/queued" "${flags[@]}" --collect >/dev/null 2>&1
python3 "$(dirname "$0")/same_summary.py" "$tmp/direct" "$tmp/queued"
echo "a 2 x 2 sweep run by GNU parallel: --collect equals the direct sweep"
