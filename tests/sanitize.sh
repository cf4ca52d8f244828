#!/usr/bin/env bash
# The suite under AddressSanitizer and UndefinedBehaviorSanitizer (GCC), then the checkpoint and
# config readers fuzzed with the sanitized binary (tests/fuzz/readers_fuzz.py).
#
# Usage: tests/sanitize.sh [--fuzz-seconds S] [--seed N] [--full]
#   Builds into build-sanitize/ (Debug, -O1, -fsanitize=address,undefined,float-cast-overflow,
#   -D_GLIBCXX_ASSERTIONS; CMake option GBSSN1D_SANITIZE; a unity build: 480 s of compiler time
#   instead of 730, 326 s instead of 376 on 2 idle cores, 2026-11-27), runs the doctest cases of the suite
#   (every unit and equation test, the evolutions, the CLI and hostile-input catalogue through
#   the sanitized binary) with every report written to build-sanitize/sanitizer-logs/ and exit
#   status 86, then the readers fuzzer for S seconds (default 60). Fails if any test fails or
#   any report was written, printing the reports.
#   --full  every ctest entry: also the slowest doctest cases (named below) and the entries
#           outside the doctest cases (README examples, plot scripts, cluster routes, the
#           command-line fuzzer, the runs/ inputs): by hand, about 35 minutes on 2 cores.
# The doctest cases ARE the suite's tests of the code; what --full adds runs the same binary
# from scripts, whose sanitizer reports would also land in the log folder.
set -euo pipefail
fuzz_seconds=60
seed=1
full=false
while [ $# -gt 0 ]; do
  case "$1" in
    --fuzz-seconds) fuzz_seconds=${2:?--fuzz-seconds needs a number}; shift ;;
    --seed) seed=${2:?--seed needs a number}; shift ;;
    --full) full=true ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--fuzz-seconds S] [--seed N] [--full]" >&2; exit 2 ;;
  esac
  shift
done
cd "$(dirname "$0")/.."
build=build-sanitize
logs=$PWD/$build/sanitizer-logs
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# shellcheck source=.ci/generator.sh
source .ci/generator.sh
generator_for "$build"
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DGBSSN1D_SANITIZE=ON -DGBSSN1D_BUILD_BENCH=OFF -DCMAKE_UNITY_BUILD=ON \
  "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" 2>&1 | grep -v '^\[' || true
[ -x "$build/gbssn1d" ] && [ -x "$build/tests/gbssn1d_tests" ] || { echo "sanitize: build failed" >&2; exit 1; }
rm -rf "$logs"
mkdir -p "$logs"
# Reports go to files (the tests read the binary's stderr); a report ends the process with 86.
# Leak checks included; the standard library's assertions are on (_GLIBCXX_ASSERTIONS).
export ASAN_OPTIONS="log_path=$logs/asan:exitcode=86:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="log_path=$logs/ubsan:print_stacktrace=1:halt_on_error=1:exitcode=86"
status=0
# ctest's -j balances the cases over the cores. Without --full: the doctest cases (-LE script)
# but the slowest under the sanitizers (17-650 s each; the other 195 took 276 s in CI on
# 2026-11-27, 1843e04, on 2 cores shared with the planted-mistake stage): convergence studies
# at several resolutions and study drivers whose code the faster cases run too (the same RHS, transfer and time-interpolation kernels, converge's and sweep's
# member handling, emitted task lines, signals), the resumed progress line's speed (300 s:
# two runs long enough to show a terminal's progress; the resume it exercises runs elsewhere),
# the 10 M trumpet evolution (49 s: the same RHS and stepping as the 1 M runs of the
# other evolution cases; its 4th-order stationarity is checked in the tests stage), and the
# killed converge study rerun to its end (three members to 30 M; a member's resume from its
# checkpoint and samples runs in the faster converge cases), and five evolutions of 39-57 s
# (the wormhole settling onto the trumpet, B's driver stencils compared, the trumpet on four
# boxes, M_AH and r_AH of the trumpet, the held h_AH with quadratic time interpolation): the
# RHS, the finder, the boxes' transfer and time interpolation, and the held h_AH's tracker mode
# all run in faster cases, and the physics these five check is checked in the tests stage; and
# (measured at 17-79 s under the sanitizers) the sweep's periodic progress lines (waiting for
# members long enough to print them; the [k/n] lines run in every sweep case), the converge study
# at the round-off floor (its verdict classes run as unit cases), the dense-output gauge pulse,
# the horizon moving both ways and the trumpet on five boxes (kernels the faster cases run); and
# Z4c's converge study, noise for 1000 M (four runs), the flat-space pulse and the damping's rate
# (102, 298, 70, 75 s under the sanitizers at 66e18bc: Z4c's point loop runs under them in its
# resume case, on a grid and on boxes, its equations in its point-wise case); and a converge
# study interrupted after its first member completed, rerun twice (131 s under the sanitizers at
# 4778d41: three members to 300 M; a completed member's kept records are read and refused in the
# faster "converge rerun after completion" and "samples ... flipped byte" cases); and, so that
# CI keeps under 25 minutes (59, 28 and 24 s under the sanitizers beside the planted mistakes at
# 032a93a, the first the stage's last), the published configuration's two studies with a held
# and a smooth h_AH (the h_AH file and the converge members run in faster cases), every flag's
# run where its row says it acts and the tightened horizon tolerance (the runs' RHS, finder and
# conversions run in the faster cases; the flags' validation under the sanitizers in the bound
# and hostile-input cases); and the energy flux's time integral at three resolutions (its point
# formula and the spheres' sampling run in the faster flux cases).
slow=(
  "converge interrupted after a member completed"
  "a resumed run's progress line counts its speed from the resume"
  "a stretched horizon (0.89 M) converges at coarse spacing"
  "sweep on a cluster: emitted lines run from any folder"
  "converge interrupted: exit 130"
  "beta_H's outer taper on coarse boxes"
  "gauge pulse across refinement boundaries at --fd-order 6"
  "gauge pulse, quadratic time interpolation with buffers"
  "a horizon stretched to 2 M on six boxes"
  "B's driver term under refinement"
  "converge -j runs that many members at once"
  "gauge pulse across refinement boundaries, RK4 stage values"
  "1+log trumpet evolved to t = 10 M stays stationary"
  "converge killed (SIGKILL, no chance to write)"
  "a precollapsed wormhole settles onto the stationary 1+log trumpet"
  "B's driver term: the matched and centred stencils discretise one equation"
  "the 1+log trumpet on four boxes stays stationary at 4th order"
  "during a 1+log trumpet evolution M_AH and r_AH stay where the data put them"
  "a held h_AH with quadratic time interpolation loses convergence under refinement"
  "sweep: progress lines while members run, k of n as they finish, resumed counts"
  "converge: a member at the round-off floor converges until the floor"
  "gauge pulse, RK4 dense output at the stage times"
  "the horizon moves outward in r when h > h_AH and inward when h < h_AH"
  "the 1+log trumpet on five boxes converges at 4th order through refinement boundaries"
  "converge --formulation z4c: 4th order for H, M_r, G^r and Theta"
  "robust stability: random noise around flat data stays bounded for 1000 M"
  "Z4c: a Hamiltonian-constraint violation leaves at the speed of light"
  "Z4c: kappa1 damps the constraints"
  "converge: the published configuration with h_AH held 1 M apart does not converge"
  "every flag acts where its table row says it acts"
  "every flag's tolerance is met"
  "flux_R20 over t is the change of m_R20"
)
for name in "${slow[@]}"; do # a renamed case would otherwise run unnoticed: say so
  pattern=$(sed 's/[][\\.^$*+?(){}|]/\\&/g' <<<"$name")
  ctest --test-dir "$build" -N -R "$pattern" | grep -q "Total Tests: [1-9]" \
    || { echo "sanitize: no test is named '$name' (update tests/sanitize.sh)" >&2; exit 1; }
done
exclude=$(printf '%s\n' "${slow[@]}" | sed 's/[][\\.^$*+?(){}|]/\\&/g' | paste -sd'|')
select=(-LE script -E "$exclude")
$full && select=()
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" "${select[@]}" || status=$?
fuzz_status=0
/usr/bin/env python3 tests/fuzz/readers_fuzz.py --exe "$build/gbssn1d" --seconds "$fuzz_seconds" \
  --seed "$seed" || fuzz_status=$?
reports=$(ls "$logs")
if [ -n "$reports" ]; then
  echo "sanitizer reports:"
  for f in "$logs"/*; do echo "--- $f"; head -n 60 "$f"; done
fi
echo "sanitize: suite exit $status, readers fuzz exit $fuzz_status, $(ls "$logs" | wc -l) reports"
[ $status -eq 0 ] && [ $fuzz_status -eq 0 ] && [ -z "$reports" ]
