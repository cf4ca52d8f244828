# Sourced by .ci/build, tests/mistakes.sh and tests/sanitize.sh: `generator_for DIR` sets the
# array `generator` to the CMake generator flags for the build folder DIR. Ninja where it is
# installed: its check that a target is up to date costs about 0.1 s of CPU where make's costs
# 3.6 s (gbssn1d's 150 objects, measured 2026-12-07), and each planted mistake's rebuild of one
# file is mostly that check. A folder already made with another generator keeps it (CMake
# refuses to switch a folder's generator).
generator_for() {
  generator=()
  if command -v ninja >/dev/null && { [ ! -f "$1/CMakeCache.txt" ] \
       || grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$1/CMakeCache.txt"; }; then
    generator=(-G Ninja)
  fi
}
