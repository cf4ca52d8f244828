#!/usr/bin/env bash
# Z4c with constraint damping against BSSN (docs/z4c-study.md): the damping's effect over
# 100-1000 M, the box taper, kappa2, resolution, convergence of every data set with and
# without the horizon shift, and the study's coarse question asked again with damping.
#
#   bash runs/z4c.sh damping       # kappa1 = 0 ... 5 on four set-ups to 1000 M, the boxes with
#                                  # and without their tapered buffer (~2 min)
#   bash runs/z4c.sh kappa2        # kappa2 = -0.5, 0, 1 at kappa1 = 0.5 and 2; eta = 1 (~1 min)
#   bash runs/z4c.sh resolution    # the damping's effect at M/16, M/24, M/32 (~3 min)
#   bash runs/z4c.sh convergence   # converge families, uniform M/8 ... M/24, to 100 M (~5 min)
#   bash runs/z4c.sh fine          # sinh N = 800, 1600, 3200, h = 1.5, to 30 M (~3 min)
#
# Tables (plots/z4c_study.py: RMS of H_L2_R and largest |M_AH - M| over t in [100, 1000] M, and
# their ratios to the BSSN run of the same set-up; plots/horizon_study.py for the converge
# families) are printed and kept in out/z4c/*.txt; figures go to out/z4c/*.png.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/gbssn1d ] || { bash .ci/install-deps && bash .ci/build >/dev/null; }
py=/usr/bin/python3
out=out/z4c
mkdir -p "$out"
long=(--tmax 1000 --dt-series 1 --dt-profiles 10000)
# the four set-ups: the 1+log trumpet on the default sinh grid at M/16 near the horizon (N = 160),
# wormhole and trumpet data on 10 boxes to 2048 M with 64 cells each (finest M/16), wormhole
# data on the sinh grid at M/16
sinh_trumpet=(--id 1log-trumpet --N 160)
boxes_wormhole=(--id wormhole --grid boxes --levels 10 --rmax 2048 --N 64)
boxes_trumpet=(--id 1log-trumpet --grid boxes --levels 10 --rmax 2048 --N 64)
sinh_wormhole=(--id wormhole --N 160)
kappas="0 0.02 0.05 0.1 0.2 0.3 0.5 0.7 1 1.5 2 3 5"

# run NAME FLAGS...: one evolve into $out/NAME (in the background, at most ${GBSSN1D_JOBS:-$(nproc)} at once),
# kept if it completed with these very inputs (config.toml as `evolve --print-config` writes it
# now: other flags, or defaults changed since, redo it); a run that stops is reported.
run() {
  local name=$1
  shift
  if [ -f "$out/$name/timeseries.dat" ] && tail -1 "$out/$name/timeseries.dat" | grep -q '^# end: ' &&
    cmp -s <(build/gbssn1d evolve --out "$out/$name" "$@" --print-config 2>/dev/null) \
      <(grep -v '^#' "$out/$name/config.toml"); then
    return 0
  fi
  while [ "$(jobs -rp | wc -l)" -ge "${GBSSN1D_JOBS:-$(nproc)}" ]; do wait -n; done
  { rm -rf "${out:?}/$name"
    build/gbssn1d evolve --out "$out/$name" "$@" >"$out/$name.log" 2>&1 ||
      echo "  ($name stopped: $(tail -1 "$out/$name.log"))"; } &
}
table() { $py plots/z4c_study.py table "$@"; }

# family NAME "N list" FLAGS...: one converge run into $out/NAME, kept if complete with these inputs
family() {
  local name=$1 Ns=$2
  shift 2
  if [ -f "$out/$name/convergence.dat" ] && grep -q "^# converge: N = $Ns," "$out/$name/config.toml" &&
    cmp -s <(build/gbssn1d evolve --N "${Ns%%,*}" --out "$out/$name" "$@" --print-config 2>/dev/null) \
      <(grep -v '^#' "$out/$name/config.toml"); then
    return 0
  fi
  rm -rf "${out:?}/$name"
  build/gbssn1d converge --N "$Ns" -j "${GBSSN1D_JOBS:-$(nproc)}" --out "$out/$name" "$@" >"$out/$name.log" 2>&1 ||
    echo "  ($name: a member stopped (exit 3), the study does not converge (4) or is pre-asymptotic (5), see $out/$name.log)"
}

stage=${1:-damping}
case $stage in
damping)
  for setup in sinh_trumpet boxes_wormhole boxes_trumpet sinh_wormhole; do
    declare -n flags=$setup
    run "$setup-bssn" "${flags[@]}" "${long[@]}"
    for k in $kappas; do
      run "$setup-k$k" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 "$k"
    done
    # boxes: also without the tapered buffer, and Z4c with BSSN's taper
    if [ "$setup" != "${setup#boxes}" ]; then
      run "$setup-bssn-taper0" "${flags[@]}" "${long[@]}" --box-taper 0
      for k in 0 0.1 1 2; do
        run "$setup-k$k-taper0.5" "${flags[@]}" "${long[@]}" --formulation z4c --kappa1 "$k" --box-taper 0.5
      done
    fi
  done
  wait
  for setup in sinh_trumpet boxes_wormhole boxes_trumpet sinh_wormhole; do
    echo "== $setup: BSSN, then Z4c at kappa1 = $kappas"
    members=()
    for k in $kappas; do members+=("$out/$setup-k$k"); done
    table "$out/$setup-bssn" "${members[@]}" | tee "$out/damping-$setup.txt"
    if [ "$setup" != "${setup#boxes}" ]; then
      echo "== $setup: BSSN without the taper, Z4c with BSSN's taper (0.5)"
      table "$out/$setup-bssn" "$out/$setup-bssn-taper0" "$out/$setup"-k{0,0.1,1,2}-taper0.5 |
        tee "$out/taper-$setup.txt"
    fi
  done
  $py plots/z4c_study.py figure "$out/sinh_trumpet-bssn" "$out"/sinh_trumpet-k{0,0.02,0.5,2} \
    -o "$out/damping-sinh_trumpet.png"
  $py plots/z4c_study.py figure "$out/boxes_wormhole-bssn" "$out"/boxes_wormhole-k{0,0.02,1,2} \
    -o "$out/damping-boxes_wormhole.png"
  ;;
kappa2)
  for k in 0.5 2; do
    for k2 in -0.5 0 1; do
      run "sinh_trumpet-k$k-kk$k2" "${sinh_trumpet[@]}" "${long[@]}" --formulation z4c --kappa1 $k --kappa2 $k2
    done
  done
  # the band of kappa1 where Z4c is worse than BSSN, with the Gamma-driver's eta halved
  run "sinh_trumpet-eta1-bssn" "${sinh_trumpet[@]}" "${long[@]}" --eta 1
  for k in 0.1 0.3 0.5 0.7 1; do
    run "sinh_trumpet-eta1-k$k" "${sinh_trumpet[@]}" "${long[@]}" --eta 1 --formulation z4c --kappa1 $k
  done
  wait
  { table "$out/sinh_trumpet-bssn" "$out"/sinh_trumpet-k{0.5,2}-kk{-0.5,0,1}
    echo "== eta = 1/M"
    table "$out/sinh_trumpet-eta1-bssn" "$out"/sinh_trumpet-eta1-k{0.1,0.3,0.5,0.7,1}; } | tee "$out/kappa2.txt"
  ;;
resolution)
  for N in 160 240 320; do
    for id in 1log-trumpet wormhole; do
      run "res-$id-N$N-bssn" --id $id --N $N "${long[@]}"
      for k in 0.02 0.5 2; do
        run "res-$id-N$N-k$k" --id $id --N $N "${long[@]}" --formulation z4c --kappa1 $k
      done
    done
  done
  wait
  for id in 1log-trumpet wormhole; do
    for N in 160 240 320; do
      echo "== $id, sinh N = $N"
      table "$out/res-$id-N$N-bssn" "$out/res-$id-N$N"-k{0.02,0.5,2}
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
  for f in bssn z4c; do
    echo "== $f: sinh N = 800, 1600, 3200, stretch to 1.5 M, to 30 M"
    grep -E '^# (verdict|order H_L2_R)' "$out/$f-fine-h1.5/convergence.dat"
  done | tee "$out/fine.txt"
  ;;
*)
  echo "runs/z4c.sh: unknown stage '$stage' (damping, kappa2, resolution, convergence, fine)" >&2
  exit 2
  ;;
esac
