# Sourced by the study scripts of runs/ that keep their results (runs/hold-scaling.sh first):
# what every such script must do the same way, written once.
#
#   lib_init NAME CALLER OUT_DEFAULT [OUT]
#                                     resolve OUT against CALLER (the folder the user ran the
#                                     script from), validate GBSSN1D_JOBS, take
#                                     OUT's lock, stop at the first Ctrl-C; sets $out, $jobs
#   lib_run NAME CMD...               run CMD (a gbssn1d command whose --out is written as @OUT)
#                                     into $out/NAME unless that folder already holds a completed
#                                     run of the very same command; the new run is made in a
#                                     scratch folder and moved into place only when it completed,
#                                     so a finished result is never deleted before its
#                                     replacement succeeded; at most $jobs at once (lib_wait
#                                     waits for all)
#
# A run counts as done when $out/NAME.cmd holds the same command run by the same build/gbssn1d
# (its SHA-256) and its timeseries.dat ends with "# end: completed"; an interrupted, failed,
# other-input or other-binary run is redone on a rerun.

lib_init() {
  local name=$1 caller=$2 default=$3 given=${4:-}
  lib_name=$name
  case "${GBSSN1D_JOBS:-}" in
    '') jobs=$(nproc) ;;
    *[!0-9]* | 0*) echo "$name: GBSSN1D_JOBS = '$GBSSN1D_JOBS' is invalid: it must be a positive whole number (runs at once)" >&2; exit 2 ;;
    *) jobs=$GBSSN1D_JOBS ;;
  esac
  if [ "$jobs" -gt 1024 ]; then
    echo "$name: GBSSN1D_JOBS = $jobs is invalid: at most 1024 runs at once" >&2
    exit 2
  fi
  if [ -n "$given" ]; then
    case "$given" in /*) out=$given ;; *) out=$caller/$given ;; esac
  else
    out=$PWD/$default
  fi
  [ ! -L "$out" ] || { echo "$name: $out is a symbolic link: refused (write into a real folder)" >&2; exit 2; }
  mkdir -p "$out"
  exec 9>"$out/.lock"
  flock -n 9 || { echo "$name: another run is writing $out (lock $out/.lock)" >&2; exit 1; }
  trap lib_interrupted INT TERM
}

lib_interrupted() {
  trap '' INT TERM
  local pids pid
  pids=$(jobs -p)
  # each run's subshell and the gbssn1d it waits for (a signal sent to this script alone, not
  # to the terminal's process group, reaches neither)
  for pid in $pids; do
    pkill -TERM -P "$pid" 2>/dev/null || true
    kill -TERM "$pid" 2>/dev/null || true
  done
  wait 2>/dev/null || true
  echo "$lib_name: interrupted; completed runs in $out are kept, unfinished ones are redone when you run the same command again" >&2
  exit 130
}

lib_done() { # NAME CMDTEXT: whether $out/NAME holds a completed run of CMDTEXT
  local dir=$out/$1
  [ -f "$out/$1.cmd" ] && [ "$(cat "$out/$1.cmd")" = "$2" ] && [ -f "$dir/timeseries.dat" ] &&
    [ ! -L "$dir" ] && tail -n 1 "$dir/timeseries.dat" | grep -q '^# end: completed'
}

lib_run() {
  local name=$1
  shift
  local cmd=() arg
  for arg in "$@"; do
    if [ "$arg" = @OUT ]; then cmd+=("$out/.new-$name"); else cmd+=("$arg"); fi
  done
  # the command and the program it runs: a rebuilt binary redoes every run
  [ -n "${lib_binary:-}" ] || lib_binary=$(sha256sum build/gbssn1d | cut -c1-16)
  local text
  text="$(printf '%q ' "$@")# binary $lib_binary"
  if lib_done "$name" "$text"; then
    return 0
  fi
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  (
    trap - INT TERM
    rm -rf "${out:?}/.new-$name"
    status=0
    "${cmd[@]}" >"$out/$name.log" 2>&1 || status=$?
    if [ $status -eq 0 ] && tail -n 1 "$out/.new-$name/timeseries.dat" | grep -q '^# end: completed'; then
      rm -rf "${out:?}/.old-$name"
      [ ! -e "$out/$name" ] || mv "$out/$name" "$out/.old-$name"
      mv "$out/.new-$name" "$out/$name"
      printf '%s' "$text" >"$out/$name.cmd"
      rm -rf "${out:?}/.old-$name"
    else
      echo "  $name: exit $status, see $out/$name.log (kept in $out/.new-$name; redone on a rerun)" >&2
    fi
  ) &
}

lib_wait() {
  while [ -n "$(jobs -rp)" ]; do wait -n || true; done
}
