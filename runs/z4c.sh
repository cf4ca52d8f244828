#!/usr/bin/env bash
# Z4c with constraint damping against BSSN (docs/z4c-study.md): the damping's effect over
# 100-1000 M, the box taper, kappa2, resolution, convergence of every data set with and
# without the horizon shift, the study's coarse question asked again with damping, and the
# horizon mass's drift traced to where it is made and removed by the damping near the hole.
#
#   bash runs/z4c.sh damping       # kappa1 = 0 ... 5 everywhere (--kappa1-hole 0) and the default
#                                  # on four set-ups to 1000 M, the boxes with and without their
#                                  # tapered buffer (~2 min)
#   bash runs/z4c.sh kappa2        # kappa2 = -0.5, 0, 1 at kappa1 = 0.5 and 2; eta = 1 (~1 min)
#   bash runs/z4c.sh resolution    # BSSN, Z4c's default and kappa1 = 0.02 alone at M/16-M/32 (~1 min)
#   bash runs/z4c.sh convergence   # converge families, uniform M/8 ... M/24, to 100 M (~5 min)
#   bash runs/z4c.sh fine          # sinh N = 800, 1600, 3200, h = 1.5, to 30 M (~3 min)
#   bash runs/z4c.sh hole          # kappa1-hole = 0 ... 4 on the four set-ups (~1 min)
#   bash runs/z4c.sh trace         # the drift's experiments (Sec. 9); builds a study binary from
#                                  # runs/patches/z4c-trace.patch in out/z4c/trace-build (~4 min)
#
# bash runs/z4c.sh STAGE OUT writes into OUT instead of out/z4c (a relative OUT from where you
# stand).
#
# Tables (plots/z4c_study.py: RMS of H_L2_R and largest |M_AH - M| over t in [100, 1000] M, and
# their ratios to the BSSN run of the same set-up; plots/horizon_study.py for the converge
# families) are printed and kept in out/z4c/*.txt; figures go to out/z4c/*.png.
#
# GBSSN1D_JOBS=n runs n at once (a positive whole number; default: the core count). A rerun keeps
# every completed run of the same command and binary and redoes the rest (runs/lib.sh); a result
# is replaced only by a completed one; Ctrl-C stops at once.
set -euo pipefail
here=$PWD
cd "$(dirname "$0")/.."
stage=${1:-damping}
case $stage in
damping | kappa2 | resolution | convergence | fine | hole | trace) ;;
*)
  echo "runs/z4c.sh: unknown stage '$stage' (damping, kappa2, resolution, convergence, fine, hole, trace)" >&2
  exit 2
  ;;
esac
# shellcheck source=runs/lib.sh
source runs/lib.sh
lib_init runs/z4c.sh "$here" out/z4c "${2:-}"
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
g=build/gbssn1d
long=(--tmax 1000 --dt-series 1 --dt-profiles 10000)
# the four set-ups: the 1+log trumpet on the default sinh grid at M/16 near the horizon (N = 160),
# wormhole and trumpet data on 10 boxes to 2048 M with 64 cells each (finest M/16), wormhole
# data on the sinh grid at M/16
sinh_trumpet=(--id 1log-trumpet --N 160)
boxes_wormhole=(--id wormhole --grid boxes --levels 10 --rmax 2048 --N 64)
boxes_trumpet=(--id 1log-trumpet --grid boxes --levels 10 --rmax 2048 --N 64)
sinh_wormhole=(--id wormhole --N 160)
setups="sinh_trumpet boxes_wormhole boxes_trumpet sinh_wormhole"
kappas="0 0.02 0.05 0.1 0.2 0.3 0.5 0.7 1 1.5 2 3 5"
# kappa1 everywhere: the damping's own study (Sec. 1-4)
uniform=(--kappa1-hole 0)

# run NAME FLAGS...: one evolve into $out/NAME, kept if it completed with this very command and
# binary (runs/lib.sh)
run() {
  local name=$1
  shift
  lib_run "$name" "$g" evolve --out @OUT "$@"
}
table() { $py plots/z4c_study.py table "$@"; }

# family NAME "N list" FLAGS...: one converge study into $out/NAME, likewise
family() {
  local name=$1 Ns=$2
  shift 2
  lib_run "$name" "$g" converge --N "$Ns" -j 1 --out @OUT "$@"
}

case $stage in
damping)
  for setup in $setups; do
    declare -n flags=$setup
    run "$setup-bssn" "${flags[@]}" "${long[@]}"
    run "$setup-default" "${flags[@]}" "${long[@]}" --formulation z4c
    for k in $kappas; do
      run "$setup-k$k" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 "$k" "${uniform[@]}"
    done
    # boxes (tapered by default, as BSSN): also without the tapered buffer, and with tapers of
    # 0.1 and 0.25
    if [ "$setup" != "${setup#boxes}" ]; then
      run "$setup-bssn-taper0" "${flags[@]}" "${long[@]}" --box-taper 0
      for k in 0 0.1 1 2; do
        run "$setup-k$k-taper0" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 "$k" \
          "${uniform[@]}" --box-taper 0
      done
      for tp in 0 0.1 0.25; do
        run "$setup-default-taper$tp" "${flags[@]}" "${long[@]}" --formulation z4c --box-taper $tp
      done
      run "$setup-k2-taper0.25" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 2 \
        "${uniform[@]}" --box-taper 0.25
    fi
  done
  lib_wait
  lib_check
  for setup in $setups; do
    echo "== $setup: BSSN, Z4c's default (kappa1 = 0.02, 2/M near the hole), then kappa1 = $kappas everywhere"
    members=("$out/$setup-default")
    for k in $kappas; do members+=("$out/$setup-k$k"); done
    table "$out/$setup-bssn" "${members[@]}" | tee "$out/damping-$setup.txt"
    if [ "$setup" != "${setup#boxes}" ]; then
      echo "== $setup: without the taper (BSSN, Z4c at kappa1 = 0, 0.1, 1, 2 everywhere, Z4c's default), Z4c's default with tapers 0.1 and 0.25, kappa1 = 2 with 0.25"
      table "$out/$setup-bssn" "$out/$setup-bssn-taper0" "$out/$setup"-k{0,0.1,1,2}-taper0 \
        "$out/$setup"-default-taper{0,0.1,0.25} "$out/$setup-k2-taper0.25" | tee "$out/taper-$setup.txt"
    fi
  done
  $py plots/z4c_study.py figure "$out/sinh_trumpet-bssn" "$out"/sinh_trumpet-{default,k0,k0.02,k0.5,k2} \
    -o "$out/damping-sinh_trumpet.png"
  $py plots/z4c_study.py figure "$out/boxes_wormhole-bssn" "$out"/boxes_wormhole-{default,k0,k0.02,k1,k2} \
    -o "$out/damping-boxes_wormhole.png"
  ;;
kappa2)
  for k in 0.5 2; do
    for k2 in -0.5 0 1; do
      run "sinh_trumpet-k$k-kk$k2" "${sinh_trumpet[@]}" "${long[@]}" --formulation z4c --kappa1 $k \
        "${uniform[@]}" --kappa2 $k2
    done
  done
  run "sinh_trumpet-bssn" "${sinh_trumpet[@]}" "${long[@]}"
  # the band of kappa1 where Z4c is worse than BSSN, with the Gamma-driver's eta halved
  run "sinh_trumpet-eta1-bssn" "${sinh_trumpet[@]}" "${long[@]}" --eta 1
  for k in 0.1 0.3 0.5 0.7 1; do
    run "sinh_trumpet-eta1-k$k" "${sinh_trumpet[@]}" "${long[@]}" --eta 1 --formulation z4c \
      --kappa1 $k "${uniform[@]}"
  done
  lib_wait
  lib_check
  { table "$out/sinh_trumpet-bssn" "$out"/sinh_trumpet-k{0.5,2}-kk{-0.5,0,1}
    echo "== eta = 1/M"
    table "$out/sinh_trumpet-eta1-bssn" "$out"/sinh_trumpet-eta1-k{0.1,0.3,0.5,0.7,1}; } | tee "$out/kappa2.txt"
  ;;
resolution)
  for N in 160 240 320; do
    for id in 1log-trumpet wormhole; do
      run "res-$id-N$N-bssn" --id $id --N $N "${long[@]}"
      run "res-$id-N$N-default" --id $id --N $N "${long[@]}" --formulation z4c
      for k in 0.02 0.5 2; do
        run "res-$id-N$N-k$k" --id $id --N $N "${long[@]}" --formulation z4c --kappa1 $k "${uniform[@]}"
      done
    done
  done
  lib_wait
  lib_check
  for id in 1log-trumpet wormhole; do
    for N in 160 240 320; do
      echo "== $id, sinh N = $N: BSSN, Z4c's default, kappa1 = 0.02, 0.5, 2 everywhere"
      table "$out/res-$id-N$N-bssn" "$out/res-$id-N$N"-{default,k0.02,k0.5,k2}
    done | tee "$out/resolution-$id.txt"
  done
  ;;
convergence)
  common=(--grid uniform --rmax 200 --tmax 100 --dt-series 1 --dt-profiles 100)
  published=(--rah-profile rational --rah-width 1 --rah-normal unit --driver-advection upwind-gd)
  for f in bssn z4c; do
    for id in 1log-trumpet maximal-trumpet wormhole; do
      family "$f-$id-standard" 1600,2400,3200,4800 "${common[@]}" --id $id --formulation $f
      family "$f-$id-stretch" 1600,2400,3200,4800 "${common[@]}" --id $id --formulation $f --rahA 0.5 --rah0 0.89
      family "$f-$id-shrink" 1600,2400,3200,4800 "${common[@]}" --id $id --formulation $f --rahA 0.5 --rah0 0.6
      family "$f-$id-stretch-published" 1600,2400,3200 "${common[@]}" --id $id --formulation $f --rahA 0.5 --rah0 0.89 "${published[@]}"
      family "$f-$id-shrink-published" 1600,2400,3200 "${common[@]}" --id $id --formulation $f --rahA 0.5 --rah0 0.6 "${published[@]}"
    done
  done
  # boxes: 6 boxes to 128 M, finest M/12, M/16, M/24, to 50 M (Z4c's damping without the taper)
  family z4c-boxes-1log-trumpet 48,64,96 --id 1log-trumpet --formulation z4c --grid boxes \
    --levels 6 --rmax 128 --tmax 50 --dt-series 0.25 --dt-profiles 50
  lib_wait
  lib_check
  grep -E '^# (verdict|order (H|Theta)_L2_R)' "$out/z4c-boxes-1log-trumpet/convergence.dat"
  for f in bssn z4c; do
    for id in 1log-trumpet maximal-trumpet wormhole; do
      echo "== $f, $id: RMS H_L2_R over [10, 100] M at M/8, M/12, M/16 (M/24); ratio to $f's standard gauge"
      $py plots/horizon_study.py table "$out/$f-$id-standard" "$out/$f-$id"-{standard,stretch,shrink,stretch-published,shrink-published}
    done
  done | tee "$out/convergence.txt"
  ;;
fine)
  for f in bssn z4c; do
    family "$f-fine-h1.5" 800,1600,3200 --id 1log-trumpet --formulation $f --rahA 0.5 --rah0 1.5 \
      --tmax 30 --dt-series 0.5 --dt-profiles 30
  done
  lib_wait
  lib_check
  for f in bssn z4c; do
    echo "== $f: sinh N = 800, 1600, 3200, stretch to 1.5 M, to 30 M"
    grep -E '^# (verdict|order H_L2_R)' "$out/$f-fine-h1.5/convergence.dat"
  done | tee "$out/fine.txt"
  ;;
hole)
  holes="0.5 1 2 4"
  for setup in $setups; do
    declare -n flags=$setup
    run "$setup-bssn" "${flags[@]}" "${long[@]}"
    run "$setup-k0.02" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 0.02 "${uniform[@]}"
    for h in $holes; do
      run "$setup-hole$h" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1-hole "$h"
    done
  done
  lib_wait
  lib_check
  for setup in $setups; do
    echo "== $setup: BSSN, Z4c at kappa1 = 0.02 everywhere, then --kappa1-hole = $holes"
    members=("$out/$setup-k0.02")
    for h in $holes; do members+=("$out/$setup-hole$h"); done
    table "$out/$setup-bssn" "${members[@]}"
  done | tee "$out/hole.txt"
  ;;
trace)
  # a study binary: this tree's CMakeLists.txt and src/ with runs/patches/z4c-trace.patch, whose
  # switches are read from the environment (TRACE_*); rebuilt when either changes
  tb=$out/trace-build
  key=$( { cat CMakeLists.txt runs/patches/z4c-trace.patch; find src -type f | sort | xargs cat; } | sha256sum | cut -c1-16)
  if [ ! -x "$tb/bin/gbssn1d" ] || [ "$(cat "$tb/key" 2>/dev/null)" != "$key" ]; then
    echo "runs/z4c.sh: building the study binary in $tb (a few minutes)"
    rm -rf "${tb:?}.new"
    mkdir -p "$tb.new/tree"
    cp -r CMakeLists.txt src "$tb.new/tree/"
    (cd "$tb.new/tree" && patch -s -p1 <"$OLDPWD/runs/patches/z4c-trace.patch")
    launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    cmake -S "$tb.new/tree" -B "$tb.new/build" -DCMAKE_BUILD_TYPE=Release -DGBSSN1D_BUILD_TESTS=OFF \
      -DGBSSN1D_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
    cmake --build "$tb.new/build" -j "$jobs" --target gbssn1d >/dev/null
    mkdir -p "$tb.new/bin"
    cp "$tb.new/build/gbssn1d" "$tb.new/bin/gbssn1d"
    echo "$key" >"$tb.new/key"
    rm -rf "${tb:?}"
    mv "$tb.new" "$tb"
  fi
  t=$tb/bin/gbssn1d
  # trace NAME ENV FLAGS...: one run of the study binary with the switches ENV (VAR=value,...)
  trace() {
    local name=$1 envs=$2
    shift 2
    local e=()
    [ -z "$envs" ] || IFS=, read -r -a e <<<"$envs"
    lib_run "trace-$name" env "${e[@]}" "$t" evolve --out @OUT "${sinh_trumpet[@]}" --tmax 1000 \
      --dt-series 1 --dt-profiles 100 "$@"
  }
  trace bssn ""
  trace bssn-frozen TRACE_FROZEN_SHIFT=1
  trace z4c-k0.02 "" --formulation z4c "${uniform[@]}"
  trace z4c-default "" --formulation z4c
  trace z4c-b-no-theta TRACE_B_THETA=0 --formulation z4c "${uniform[@]}"
  for R in 1.6 2 3; do
    trace "z4c-theta-off-R$R" "TRACE_THETA_OFF_R=$R" --formulation z4c "${uniform[@]}"
  done
  for f in 0 3; do
    trace "z4c-ko-theta$f" "TRACE_KO_THETA=$f" --formulation z4c "${uniform[@]}"
  done
  trace z4c-frozen TRACE_FROZEN_SHIFT=1 --formulation z4c "${uniform[@]}"
  trace z4c-lapse-adm "" --formulation z4c "${uniform[@]}" --z4c-lapse-adm
  lib_wait
  lib_check
  {
    echo "== the 1+log trumpet, sinh N = 160: BSSN, then Z4c with kappa1 = 0.02 everywhere and each experiment"
    table "$out/trace-bssn" "$out"/trace-z4c-{k0.02,default,b-no-theta,theta-off-R1.6,theta-off-R2,theta-off-R3,ko-theta0,ko-theta3,lapse-adm}
    echo "== the shift frozen at the trumpet's (BSSN frozen as the base)"
    table "$out/trace-bssn-frozen" "$out/trace-z4c-frozen"
    echo "== the Misner-Sharp mass m_ms - M at areal radii R (profiles)"
    $py plots/z4c_study.py mass "$out/trace-bssn" "$out/trace-z4c-k0.02" "$out/trace-z4c-default"
  } | tee "$out/trace.txt"
  ;;
esac
