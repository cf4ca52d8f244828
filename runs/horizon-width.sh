#!/usr/bin/env bash
# The profile width of large stretches (docs/horizon-shift-study.md, Sec. 8): 1+log trumpet,
# A = 0.5, uniform grids, rmax 200 M, M/8, M/12, M/16, to 100 M; the standard gauge, and each h
# with the rational profile at several widths (the default w = 3 max(h, M) among them). Every
# family is one converge run, kept in out/horizon-width/ and redone only where its command or binary changed.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
source runs/study-helpers.sh
lib_init runs/horizon-width.sh "$here" out/horizon-width "${1:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
common=(--grid uniform --rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
family standard --id 1log-trumpet
for hw in 0.89:3 0.89:2.67 1.2:3 1.2:3.6 1.5:3 1.5:4.5 2:3 2:4 2:6; do
  family "h${hw%%:*}-w${hw#*:}" --id 1log-trumpet --rahA 0.5 --rah0 "${hw%%:*}" --rah-profile rational --rah-width "${hw#*:}"
done
family h2-default --id 1log-trumpet --rahA 0.5 --rah0 2
family maximal-standard --id maximal-trumpet
family maximal-h2-default --id maximal-trumpet --rahA 0.5 --rah0 2
lib_wait
lib_check
{
  $py plots/horizon_study.py table "$out/standard" "$out"/h*/ --t0 10 --t1 100
  $py plots/horizon_study.py table "$out/maximal-standard" "$out/maximal-h2-default" --t0 10 --t1 100
} | tee "$out/table.txt"
