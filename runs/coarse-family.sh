# Sourced by the coarse-spacing study scripts (runs/horizon-width.sh, fd-order.sh,
# horizon-wormhole.sh): `family NAME FLAGS...` makes one converge family afresh in $out/NAME at
# the uniform spacings M/8, M/12, M/16 (N = 1600, 2400, 3200 with rmax 200 M in ${common[@]}),
# its log in $out/NAME.log; a member that stops is reported, the script goes on.
family() {
  local name=$1
  shift
  rm -rf "${out:?}/$name"
  build/gbssn1d converge --N 1600,2400,3200 -j "$(nproc)" --out "$out/$name" "${common[@]}" "$@" \
    >"$out/$name.log" 2>&1 || echo "  ($name: a member stopped, see $out/$name.log)"
}
