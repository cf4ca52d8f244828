#!/usr/bin/env bash
# A running converge study holds every member's folder until it ends: once a fast member has
# finished, `evolve --force --out STUDY/N<n>` and `resume STUDY/N<n>` are refused (exit 2, the
# holder named) and the member's files stay as the study wrote them; after the study ends the
# folder is free again.
set -euo pipefail
gbssn1d=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }
study=$dir/study
# N = 32 and 64 finish in a moment, N = 3200 takes seconds (-j 3: all three at once)
"$gbssn1d" converge --N 32,64,3200 -j 3 --id 1log-trumpet --grid uniform --rmax 20 --tmax 40 \
  --dt-series 0.5 --dt-profiles 40 --checkpoint-every 10 --out "$study" >"$dir/study.log" 2>&1 &
pid=$!
for _ in $(seq 200); do
  tail -n 1 "$study/N32/timeseries.dat" 2>/dev/null | grep -q '^# end: completed' && break
  sleep 0.05
done
tail -n 1 "$study/N32/timeseries.dat" | grep -q '^# end: completed' || fail "N = 32 did not finish"
kill -0 "$pid" 2>/dev/null || fail "the study ended before the test could try its member (make N = 3200 slower)"
before=$(sha256sum "$study/N32/timeseries.dat")
status=0
"$gbssn1d" evolve --force --id wormhole --grid uniform --N 16 --rmax 20 --tmax 1 --out "$study/N32" \
  >"$dir/evolve.out" 2>&1 || status=$?
[ $status -eq 2 ] || fail "evolve --force on a finished member of a running study: exit $status ($(cat "$dir/evolve.out"))"
grep -q "is being written by another gbssn1d process" "$dir/evolve.out" || fail "$(cat "$dir/evolve.out")"
status=0
"$gbssn1d" resume "$study/N32" --tmax 50 >"$dir/resume.out" 2>&1 || status=$?
[ $status -eq 2 ] || fail "resume of a finished member of a running study: exit $status ($(cat "$dir/resume.out"))"
status=0
wait "$pid" || status=$?
# its verdict does not matter here (such coarse members do not converge: exit 4)
case $status in 0 | 4 | 5) ;; *) fail "the study: exit $status: $(tail -3 "$dir/study.log")" ;; esac
[ "$(sha256sum "$study/N32/timeseries.dat")" = "$before" ] || fail "the member's files changed"
# the study ended: its member folder is free (a resume of it runs)
"$gbssn1d" resume "$study/N32" --tmax 41 >"$dir/resume2.out" 2>&1 || fail "resume after the study: $(cat "$dir/resume2.out")"
echo "a running study's finished member is refused to evolve --force and resume, and free after"
