#!/usr/bin/env bash
# The study scripts' shared library (runs/lib.sh) and the scripts built on it, driven through
# hostile settings, interruptions and reruns:
#   - every script that sources it refuses a bad GBSSN1D_JOBS (0, -1, abc, 2000, empty words)
#     with exit 2 and the variable named, before it creates or deletes anything;
#   - a completed run is kept on a rerun; a run cut short, of another command or of another binary
#     is redone; a rerun whose command fails leaves the finished result in place and says which
#     run did not complete (exit 1, no table made from it);
#   - one SIGINT (or TERM) stops the script with exit 130, leaves no gbssn1d running and keeps
#     what completed; the interrupted run is redone on the rerun;
#   - a relative OUT is resolved against the caller's folder; a symlinked OUT and a second writer
#     are refused;
#   - an interrupted script returns only when its programs have stopped; a sweep (here in a
#     subfolder) is kept also with another GBSSN1D_JOBS; a command of another program
#     (lib_run_any) counts when it exited 0;
#   - runs/horizon-robustness.sh (sweeps) and runs/demo.sh (in a stand-in tree) interrupted and
#     run again: exit 130, one line, nothing left running, the completed runs kept, the
#     interrupted sweep resumed, the figures named from where the script was run.
set -euo pipefail
gbssn1d=$1 src=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. each script that sources runs/lib.sh: a bad GBSSN1D_JOBS is refused before anything is made
for script in thesis.sh z4c.sh hold-scaling.sh cfl.sh horizon-defaults.sh outer-boundary.sh \
  horizon-convergence.sh horizon-long.sh horizon-variants.sh wormhole-1000M.sh uniform-m16.sh \
  boundary-reflections.sh driver-split.sh fd-order.sh horizon-width.sh horizon-wormhole.sh \
  horizon-coarse.sh error-constant.sh boxes.sh box-interfaces.sh refinement.sh demo.sh \
  horizon-experiments.sh horizon-robustness.sh critical.sh accretion.sh; do
  for jobs in 0 -1 abc 2000 "1 2" 07; do
    target=$dir/jobs-$script
    # the argument a script takes before OUT (a stage, a part, a tmax)
    case $script in
    z4c.sh) stage=(damping) ;;
    horizon-coarse.sh) stage=(reproduce) ;;
    boxes.sh) stage=(thesis) ;;
    box-interfaces.sh) stage=(wormhole) ;;
    refinement.sh) stage=(onset) ;;
    horizon-robustness.sh) stage=(1) ;;
    error-constant.sh) stage=(table) ;;
    *) stage=() ;;
    esac
    status=0
    (cd "$dir" && GBSSN1D_JOBS="$jobs" bash "$src/runs/$script" "${stage[@]}" "$target" >"$dir/jobs.out" 2>&1) ||
      status=$?
    [ $status -eq 2 ] || fail "$script with GBSSN1D_JOBS='$jobs': exit $status, expected 2 ($(cat "$dir/jobs.out"))"
    grep -q "GBSSN1D_JOBS" "$dir/jobs.out" || fail "$script: the message does not name GBSSN1D_JOBS"
    [ ! -e "$target" ] || fail "$script with GBSSN1D_JOBS='$jobs' made $target"
  done
done
for jobs in 0 abc; do
  status=0
  GBSSN1D_JOBS="$jobs" bash "$src/runs/claims.sh" >"$dir/jobs.out" 2>&1 || status=$?
  [ $status -eq 2 ] && grep -q GBSSN1D_JOBS "$dir/jobs.out" || fail "claims.sh with GBSSN1D_JOBS='$jobs': exit $status"
done
echo "a bad GBSSN1D_JOBS: refused by every script (exit 2), nothing made"
# an unknown stage, part or mode: refused before anything is made (horizon-coarse.sh made OUT
# and its lock first)
for script in z4c.sh horizon-coarse.sh boxes.sh box-interfaces.sh refinement.sh error-constant.sh; do
  target=$dir/stage-$script
  status=0
  (cd "$dir" && bash "$src/runs/$script" bogus "$target" >"$dir/stage.out" 2>&1) || status=$?
  [ $status -eq 2 ] && grep -q bogus "$dir/stage.out" || fail "$script bogus: exit $status ($(cat "$dir/stage.out"))"
  [ ! -e "$target" ] || fail "$script bogus made $target"
done
echo "an unknown stage: refused by every script that takes one (exit 2), nothing made"
# critical.sh's resolution (its second argument): refused before anything is made
for N in bogus 0 012 32 100000 ''; do
  target=$dir/critical-N
  status=0
  (cd "$dir" && bash "$src/runs/critical.sh" "$target" "$N" >"$dir/stage.out" 2>&1) || status=$?
  [ $status -eq 2 ] && grep -q "N = " "$dir/stage.out" || fail "critical.sh OUT '$N': exit $status ($(cat "$dir/stage.out"))"
  [ ! -e "$target" ] || fail "critical.sh OUT '$N' made $target"
done
echo "critical.sh with a bad N: refused (exit 2), nothing made"

# 2. a study script of two runs on the library
cat >"$dir/study.sh" <<EOF
#!/usr/bin/env bash
set -euo pipefail
here=\$PWD
source "$src/runs/lib.sh"
lib_init study.sh "\$here" out-default "\${1:-}"
g=$gbssn1d
lib_run a "\$g" evolve --out @OUT --id 1log-trumpet --grid uniform --N 64 --rmax 20 \\
  --tmax "\${TMAX_A:-4}" --dt-series 0.5 --dt-profiles 4
lib_run b "\$g" evolve --out @OUT --id 1log-trumpet --grid uniform --N "\${N_B:-64}" --rmax 20 \\
  --tmax "\${TMAX_B:-4}" --dt-series 0.5 --dt-profiles 1000
lib_wait
lib_check
echo "study.sh: table made"
EOF
out=$dir/work/res
mkdir -p "$dir/work"
(cd "$dir/work" && bash "$dir/study.sh" res >"$dir/s1.out" 2>&1) || fail "first run: $(cat "$dir/s1.out")"
for n in a b; do
  tail -n 1 "$out/$n/timeseries.dat" | grep -q '^# end: completed' || fail "$n not completed"
  [ "$(cat "$out/$n.status")" = 0 ] || fail "$n.status"
done
[ ! -e "$dir/out-default" ] || fail "the relative OUT was not resolved against the caller's folder"
a_sum=$(sha256sum "$out/a/timeseries.dat")
touch -d '2000-01-01' "$out/a.log" "$out/b.log"
(cd "$dir/work" && bash "$dir/study.sh" res >"$dir/s2.out" 2>&1) || fail "rerun: $(cat "$dir/s2.out")"
[ "$(date -r "$out/a.log" +%Y)" = 2000 ] || fail "a completed run was redone"
echo "a rerun keeps what completed"

# a run cut short is redone
head -n -1 "$out/b/timeseries.dat" >"$out/b/t" && mv "$out/b/t" "$out/b/timeseries.dat"
(cd "$dir/work" && bash "$dir/study.sh" res >"$dir/s3.out" 2>&1) || fail "rerun after a cut: $(cat "$dir/s3.out")"
[ "$(date -r "$out/b.log" +%Y)" != 2000 ] || fail "a run cut short was kept as done"
tail -n 1 "$out/b/timeseries.dat" | grep -q '^# end: completed' || fail "b not redone to the end"
[ "$(date -r "$out/a.log" +%Y)" = 2000 ] || fail "a was redone with b"
echo "a run cut short is redone, the others kept"

# another command whose run fails: the finished result stays, the script says so and exits 1
status=0
(cd "$dir/work" && TMAX_A=-1 bash "$dir/study.sh" res >"$dir/s4.out" 2>&1) || status=$?
[ $status -eq 1 ] || fail "a failed run: exit $status, expected 1 ($(cat "$dir/s4.out"))"
grep -q "did not complete (a)" "$dir/s4.out" || fail "the failed run is not named: $(cat "$dir/s4.out")"
! grep -q "table made" "$dir/s4.out" || fail "a table was made from a failed run"
[ "$(sha256sum "$out/a/timeseries.dat")" = "$a_sum" ] || fail "the finished result was deleted or changed"
echo "a failed rerun leaves the finished result in place (exit 1, named)"

# 3. one SIGINT (and one TERM): exit 130 at once, no gbssn1d left, the rerun completes
for sig in INT TERM; do
  rm -rf "$out/b" "$out/b.cmd"
  (cd "$dir/work" && exec env N_B=3000 TMAX_B=400 bash "$dir/study.sh" res >"$dir/s5.out" 2>&1) &
  pid=$!
  for _ in $(seq 50); do [ -d "$out/.new-b" ] && break; sleep 0.1; done
  sleep 0.5
  kill -s "$sig" "$pid"
  status=0
  wait "$pid" || status=$?
  [ $status -eq 130 ] || fail "SIG$sig: exit $status, expected 130 ($(cat "$dir/s5.out"))"
  grep -q "interrupted" "$dir/s5.out" || fail "SIG$sig: no word of the interruption"
  sleep 0.2
  ! pgrep -f -- "--out $out/.new-b" >/dev/null || fail "SIG$sig: a gbssn1d is still running"
  [ ! -e "$out/b" ] || fail "SIG$sig: an interrupted run was moved into place"
  [ "$(sha256sum "$out/a/timeseries.dat")" = "$a_sum" ] || fail "SIG$sig: a completed run changed"
done
(cd "$dir/work" && bash "$dir/study.sh" res >"$dir/s6.out" 2>&1) || fail "rerun after SIGINT: $(cat "$dir/s6.out")"
tail -n 1 "$out/b/timeseries.dat" | grep -q '^# end: completed' || fail "b not completed after the rerun"
echo "one SIGINT or TERM stops the script (exit 130, nothing left running); the rerun completes"

# 4. the same name asked for twice: one run of the same command; two commands refused
cat >"$dir/dup.sh" <<EOF
#!/usr/bin/env bash
set -euo pipefail
source "$src/runs/lib.sh"
lib_init dup.sh "\$PWD" dup
for _ in 1 2 3; do
  lib_run a $gbssn1d evolve --out @OUT --id 1log-trumpet --grid uniform --N 400 --rmax 20 --tmax 20 \\
    --dt-series 0.5 --dt-profiles 20
done
[ -z "\${SECOND:-}" ] || lib_run a $gbssn1d evolve --out @OUT --id 1log-trumpet --grid uniform \\
  --N 64 --rmax 20 --tmax 1
lib_wait
lib_check
EOF
(cd "$dir" && bash "$dir/dup.sh" >"$dir/d1.out" 2>&1) || fail "the same name thrice: $(cat "$dir/d1.out")"
[ ! -s "$dir/d1.out" ] || fail "the same name thrice: $(cat "$dir/d1.out")"
tail -n 1 "$dir/dup/a/timeseries.dat" | grep -q '^# end: completed' || fail "the same name thrice: not completed"
status=0
(cd "$dir" && SECOND=1 bash "$dir/dup.sh" >"$dir/d2.out" 2>&1) || status=$?
[ $status -eq 2 ] && grep -q "two different commands" "$dir/d2.out" || fail "two commands for one name: exit $status ($(cat "$dir/d2.out"))"
echo "the same name asked for thrice runs once; two commands for one name are refused"

# 5. a file the command names is an input: an edited --config redoes the run
printf 'tmax = 2\n' >"$dir/run.toml"
cat >"$dir/cfg.sh" <<EOF
#!/usr/bin/env bash
set -euo pipefail
source "$src/runs/lib.sh"
lib_init cfg.sh "\$PWD" cfgout
lib_run c $gbssn1d evolve --out @OUT --id 1log-trumpet --grid uniform --N 64 --rmax 20 \\
  --config "$dir/run.toml"
lib_wait
lib_check
EOF
(cd "$dir" && bash "$dir/cfg.sh" >"$dir/c1.out" 2>&1) || fail "a --config run: $(cat "$dir/c1.out")"
touch -d '2000-01-01' "$dir/cfgout/c.log"
(cd "$dir" && bash "$dir/cfg.sh" >"$dir/c2.out" 2>&1) || fail "a --config rerun: $(cat "$dir/c2.out")"
[ "$(date -r "$dir/cfgout/c.log" +%Y)" = 2000 ] || fail "an unchanged --config redid the run"
printf 'tmax = 3\n' >"$dir/run.toml"
(cd "$dir" && bash "$dir/cfg.sh" >"$dir/c3.out" 2>&1) || fail "an edited --config: $(cat "$dir/c3.out")"
[ "$(date -r "$dir/cfgout/c.log" +%Y)" != 2000 ] || fail "an edited --config kept the old run"
grep -q "completed at t = 3" "$dir/cfgout/c/timeseries.dat" || fail "the edited --config's run is not the new one"
echo "an edited --config redoes its run, an unchanged one keeps it"

# 6. a symlinked OUT and a second writer are refused
ln -s "$out" "$dir/work/link"
status=0
(cd "$dir/work" && bash "$dir/study.sh" link >"$dir/s7.out" 2>&1) || status=$?
[ $status -eq 2 ] && grep -q "symbolic link" "$dir/s7.out" || fail "a symlinked OUT: exit $status ($(cat "$dir/s7.out"))"
exec 8>"$out/.lock"
flock -n 8
status=0
(cd "$dir/work" && bash "$dir/study.sh" res >"$dir/s8.out" 2>&1) || status=$?
exec 8>&-
[ $status -eq 1 ] && grep -q "another run is writing" "$dir/s8.out" || fail "a second writer: exit $status ($(cat "$dir/s8.out"))"
echo "a symlinked OUT and a second writer are refused"

# 7. an interrupted script returns only when its programs have stopped: one that takes a second
# to stop (as a sweep stopping its members) is not left running
printf '%s\n' '#!/usr/bin/env bash' 'mkdir -p "$2"' "trap 'sleep 1; exit 143' TERM" 'sleep 60 &' 'wait' \
  >"$dir/slowstop"
chmod +x "$dir/slowstop"
cat >"$dir/slow.sh" <<EOF_SLOW
#!/usr/bin/env bash
set -euo pipefail
source "$src/runs/lib.sh"
lib_init slow.sh "\$PWD" slowout
lib_run s "$dir/slowstop" --out @OUT
lib_wait
EOF_SLOW
(cd "$dir" && exec bash "$dir/slow.sh" >"$dir/w1.out" 2>&1) &
pid=$!
for _ in $(seq 50); do [ -d "$dir/slowout/.new-s" ] && break; sleep 0.1; done
sleep 0.2
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[ $status -eq 130 ] || fail "a slow stop: exit $status, expected 130 ($(cat "$dir/w1.out"))"
! pgrep -f -- "$dir/slowstop" >/dev/null || fail "the script ended before its program had stopped"
echo "an interrupted script returns only when its programs have stopped"

# a sweep into a subfolder (NAME part/s) is kept, also with another GBSSN1D_JOBS (its -j); a
# command of another program (lib_run_any) is complete when it exited 0
printf '%s\n' '#!/usr/bin/env bash' 'mkdir -p "$2" && echo measured >"$2/m.txt" && exit "${FAIL:-0}"' \
  >"$dir/measure"
chmod +x "$dir/measure"
cat >"$dir/sub.sh" <<EOF_SUB
#!/usr/bin/env bash
set -euo pipefail
source "$src/runs/lib.sh"
lib_init sub.sh "\$PWD" subout
lib_run part/s $gbssn1d sweep -j "\$jobs" --out @OUT --sweep N=32,48 --id 1log-trumpet \\
  --grid uniform --rmax 20 --tmax 2 --dt-series 0.5 --dt-profiles 2
lib_run_any m "$dir/measure" --out @OUT
lib_wait
lib_check
EOF_SUB
sub=$dir/subout
(cd "$dir" && GBSSN1D_JOBS=1 bash "$dir/sub.sh" >"$dir/u1.out" 2>&1) || fail "a sweep in a subfolder: $(cat "$dir/u1.out")"
[ -f "$sub/part/s/summary.dat" ] && [ -f "$sub/part/s.cmd" ] && [ -f "$sub/part/s.log" ] &&
  [ ! -e "$sub/part/.new-s" ] && [ ! -e "$sub/.new-part" ] || fail "the sweep is not in place in $sub/part"
[ -f "$sub/m/m.txt" ] && [ -f "$sub/m/.lib-complete" ] || fail "lib_run_any's folder is not in place"
touch -d '2000-01-01' "$sub/part/s.log" "$sub/m.log"
(cd "$dir" && GBSSN1D_JOBS=2 bash "$dir/sub.sh" >"$dir/u2.out" 2>&1) || fail "its rerun: $(cat "$dir/u2.out")"
[ "$(date -r "$sub/part/s.log" +%Y)" = 2000 ] || fail "another GBSSN1D_JOBS redid a completed sweep"
[ "$(date -r "$sub/m.log" +%Y)" = 2000 ] || fail "a completed lib_run_any was redone"
# a sweep in place whose summary lists a member not run (missing) is not complete: redone
sed -i '0,/^32 ok /s//32 missing /' "$sub/part/s/summary.dat"
grep -q '^32 missing ' "$sub/part/s/summary.dat" || fail "no row of N = 32 in $sub/part/s/summary.dat"
(cd "$dir" && bash "$dir/sub.sh" >"$dir/u4.out" 2>&1) || fail "a rerun of an incomplete sweep: $(cat "$dir/u4.out")"
[ "$(date -r "$sub/part/s.log" +%Y)" != 2000 ] && ! grep -q ' missing ' "$sub/part/s/summary.dat" ||
  fail "a sweep with a member missing was kept as complete"
rm -rf "${sub:?}/m" "$sub/m.cmd"
status=0
(cd "$dir" && FAIL=1 bash "$dir/sub.sh" >"$dir/u3.out" 2>&1) || status=$?
[ $status -eq 1 ] && grep -q "did not complete (m)" "$dir/u3.out" && [ ! -e "$sub/m" ] ||
  fail "a failed lib_run_any: exit $status ($(cat "$dir/u3.out"))"
echo "a sweep in a subfolder is kept, also with another GBSSN1D_JOBS; lib_run_any as documented"

# 8. a sweep-based script (runs/horizon-robustness.sh, to t = 2 M), interrupted in its second
# sweep: exit 130, one line, nothing left running, the finished sweep and members kept; the
# rerun (with another GBSSN1D_JOBS) resumes the interrupted sweep and makes the tables
rob=$dir/work/rob
(cd "$dir/work" && exec env GBSSN1D_JOBS=1 bash "$src/runs/horizon-robustness.sh" 2 rob >"$dir/r1.out" 2>&1) &
pid=$!
for _ in $(seq 1200); do
  [ -f "$rob/uniform.cmd" ] && grep -l -s '^ok ' "$rob/.new-default-grid/logs/"*.status >/dev/null && break
  kill -0 "$pid" 2>/dev/null ||
    fail "horizon-robustness.sh ended before its second sweep had run a member ($(cat "$dir/r1.out"))"
  sleep 0.05
done
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[ $status -eq 130 ] || fail "horizon-robustness.sh interrupted: exit $status ($(cat "$dir/r1.out"))"
[ "$(wc -l <"$dir/r1.out")" -eq 1 ] && grep -q "interrupted.*kept.*run the same command again" "$dir/r1.out" ||
  fail "horizon-robustness.sh interrupted: not one line saying what is kept ($(cat "$dir/r1.out"))"
! pgrep -f -- "$rob/" >/dev/null || fail "horizon-robustness.sh interrupted: a gbssn1d is still running"
[ -f "$rob/uniform/summary.dat" ] && [ ! -e "$rob/default-grid" ] ||
  fail "horizon-robustness.sh interrupted: the finished sweep is gone, or the unfinished one was moved into place"
member=$(grep -l '^ok ' "$rob/.new-default-grid/logs/"*.status | head -n 1)
member=$(basename "$member" .status)
touch -d '2000-01-01' "$rob/uniform.log" "$rob/.new-default-grid/$member/timeseries.dat"
(cd "$dir/work" && GBSSN1D_JOBS=2 bash "$src/runs/horizon-robustness.sh" 2 rob >"$dir/r2.out" 2>&1) ||
  fail "horizon-robustness.sh's rerun: $(cat "$dir/r2.out")"
[ "$(date -r "$rob/uniform.log" +%Y)" = 2000 ] || fail "horizon-robustness.sh's rerun redid a finished sweep"
[ "$(date -r "$rob/default-grid/$member/timeseries.dat" +%Y)" = 2000 ] ||
  fail "horizon-robustness.sh's rerun did not resume the interrupted sweep (its finished member $member was redone)"
[ "$(grep -c '^== ' "$dir/r2.out")" -eq 4 ] || fail "horizon-robustness.sh's rerun: not four tables ($(cat "$dir/r2.out"))"
echo "horizon-robustness.sh: one Ctrl-C stops it (exit 130, nothing left running); the rerun keeps the finished sweep and resumes the other"

# 9. runs/demo.sh in a stand-in tree (no set-up or build; figures drawn by stand-ins that check
# the files they are given), interrupted after its first run, then run again twice
tree=$dir/tree
mkdir -p "$tree/runs" "$tree/.ci" "$tree/build" "$tree/plots"
ln -s "$src/runs/demo.sh" "$tree/runs/demo.sh"
ln -s "$src/runs/lib.sh" "$tree/runs/lib.sh"
ln -s "$gbssn1d" "$tree/build/gbssn1d"
echo 'true' >"$tree/.ci/install-deps"
echo 'echo "[100%] Built target gbssn1d"' >"$tree/.ci/build"
for p in plot_profiles plot_series compare_trumpet constraint_orders plot_horizons plot_sweep; do
  printf '%s\n' 'import os' 'import sys' 'a = sys.argv[1:]' \
    "missing = [f for f in a if f.endswith('.dat') and not os.path.isfile(f)]" \
    "if missing or '-o' not in a:" '    sys.exit(f"{sys.argv[0]}: missing {missing}")' \
    "open(a[a.index('-o') + 1], 'w').close()" >"$tree/plots/$p.py"
done
dout=$dir/work/dout
(cd "$dir/work" && exec env GBSSN1D_JOBS=1 bash "$tree/runs/demo.sh" dout >"$dir/m1.out" 2>&1) &
pid=$!
for _ in $(seq 1000); do
  [ -f "$dout/wormhole.cmd" ] && break
  kill -0 "$pid" 2>/dev/null || fail "demo.sh ended before its first run had completed ($(cat "$dir/m1.out"))"
  sleep 0.02
done
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[ $status -eq 130 ] || fail "demo.sh interrupted: exit $status ($(cat "$dir/m1.out"))"
tail -n 1 "$dir/m1.out" | grep -q "interrupted.*kept.*run the same command again" && ! grep -q "kept in" "$dir/m1.out" ||
  fail "demo.sh interrupted: its last line does not say what is kept ($(cat "$dir/m1.out"))"
! pgrep -f -- "$dout/" >/dev/null || fail "demo.sh interrupted: a gbssn1d is still running"
[ -f "$dout/wormhole/timeseries.dat" ] || fail "demo.sh interrupted: the completed wormhole run is gone"
touch -d '2000-01-01' "$dout/wormhole.log"
(cd "$dir/work" && GBSSN1D_JOBS=1 bash "$tree/runs/demo.sh" dout >"$dir/m2.out" 2>&1) || fail "demo.sh's rerun: $(cat "$dir/m2.out")"
[ "$(date -r "$dout/wormhole.log" +%Y)" = 2000 ] || fail "demo.sh's rerun redid the completed wormhole run"
figures=$(sed -n 's/^figures: //p' "$dir/m2.out")
[ "$(echo "$figures" | wc -w)" -eq 8 ] || fail "demo.sh: not 8 figures ($figures)"
for f in $figures; do
  case $f in dout/*) ;; *) fail "demo.sh: $f is not named from where it was run" ;; esac
  [ -f "$dir/work/$f" ] || fail "demo.sh: $f does not exist"
done
touch -d '2000-01-01' "$dout"/*.log
(cd "$dir/work" && bash "$tree/runs/demo.sh" dout >"$dir/m3.out" 2>&1) || fail "demo.sh's third run: $(cat "$dir/m3.out")"
for f in "$dout"/*.log; do
  [ "$(date -r "$f" +%Y)" = 2000 ] || fail "demo.sh's third run redid $f"
done
echo "demo.sh: one Ctrl-C stops it (exit 130, nothing left running, its completed runs kept); a rerun redoes none of them"
# 10. an OUT that is a file, another command's output or another script's results: refused with
# exit 2 naming it, left byte for byte (mkdir failed with exit 1 on a file; a run's folder was
# written into)
printf 'notes\n' >"$dir/work/afile"
"$gbssn1d" evolve --id 1log-trumpet --grid uniform --N 32 --rmax 8 --tmax 0.5 --out "$dir/work/arun" 2>/dev/null
mkdir -p "$dir/work/other" && printf 'runs/other.sh\n' >"$dir/work/other/.script"
for target in afile arun other; do
  before=$(cd "$dir/work" && find "$target" -type f -exec sha256sum {} + | sort)
  status=0
  (cd "$dir/work" && bash "$dir/study.sh" "$target" >"$dir/s9.out" 2>&1) || status=$?
  [ $status -eq 2 ] && grep -q "$target" "$dir/s9.out" || fail "OUT $target: exit $status ($(cat "$dir/s9.out"))"
  [ "$(cd "$dir/work" && find "$target" -type f -exec sha256sum {} + | sort)" = "$before" ] || fail "OUT $target was changed"
done
grep -q "holds the results of runs/other.sh" "$dir/s9.out" || fail "another script's OUT: $(cat "$dir/s9.out")"
echo "an OUT that is a file, another command's run or another script's results is refused"
echo "runs/lib.sh: every case as documented"
