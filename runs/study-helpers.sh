# Sourced by the study scripts of runs/, with $out set to their output folder.
#
# `family NAME FLAGS...` (runs/horizon-width.sh, fd-order.sh, horizon-wormhole.sh) makes one
# converge family afresh in $out/NAME at
# the uniform spacings M/8, M/12, M/16 (N = 1600, 2400, 3200 with rmax 200 M in ${common[@]}),
# its log in $out/NAME.log; a member that stops is reported, the script goes on.
family() {
  local name=$1
  shift
  rm -rf "${out:?}/$name"
  build/gbssn1d converge --N 1600,2400,3200 -j "${GBSSN1D_JOBS:-$(nproc)}" --out "$out/$name" "${common[@]}" "$@" \
    >"$out/$name.log" 2>&1 || echo "  ($name: a member stopped (exit 3), the study does not converge (4) or is pre-asymptotic (5), see $out/$name.log)"
}

# `evolve_run NAME FLAGS...` starts one `gbssn1d evolve` in the background, into $out/NAME, its
# log in $out/NAME.log, at most ${GBSSN1D_JOBS:-$(nproc)} at once; a run that stops is reported, the script goes
# on. The caller waits (`wait`) before reading the results. `uniform_run NAME FLAGS...`
# (runs/boundary-reflections.sh, uniform-m16.sh) is the same on a uniform grid with a series
# row every 0.5 M and no profiles.
evolve_run() {
  local name=$1
  shift
  while [ "$(jobs -rp | wc -l)" -ge "${GBSSN1D_JOBS:-$(nproc)}" ]; do wait -n; done
  build/gbssn1d evolve --out "$out/$name" "$@" >"$out/$name.log" 2>&1 ||
    echo "  ($name stopped, see $out/$name.log)" &
}
uniform_run() {
  local name=$1
  shift
  evolve_run "$name" --grid uniform --dt-series 0.5 --dt-profiles 1000 "$@"
}
