# Sourced by the study scripts of runs/ that keep their results (runs/hold-scaling.sh first):
# what every such script must do the same way, written once.
#
#   lib_jobs NAME                     set $jobs from GBSSN1D_JOBS or exit 2 naming it (for a
#                                     script that makes only scratch output, e.g. runs/claims.sh)
#   lib_init NAME CALLER OUT_DEFAULT [OUT]
#                                     resolve OUT against CALLER (the folder the user ran the
#                                     script from), validate GBSSN1D_JOBS, refuse an OUT that is
#                                     a link, a file, another command's output (config.toml or
#                                     summary.dat at its top) or another script's (OUT/.script
#                                     names the script that made it), take OUT's lock, stop at
#                                     the first Ctrl-C; sets $out, $jobs
#   lib_run NAME CMD...               run CMD (a gbssn1d evolve, converge or sweep whose --out is
#                                     written as @OUT) into $out/NAME unless that folder already
#                                     holds a completed run of the very same command; the new run is
#                                     made in a scratch folder ($out/.new-NAME) and moved into place
#                                     only when it completed, so a finished result is never deleted
#                                     before its replacement succeeded; at most $jobs at once
#                                     (lib_wait waits for all; a sweep, which runs its own -j
#                                     members, counts as one: wait for it before the next); beside
#                                     it NAME.cmd (the command and the binary's hash), NAME.status
#                                     (its exit status), NAME.log. NAME may name a subfolder
#                                     (part/run: $out/part/.new-run, $out/part/run.log, ...)
#   lib_run_any NAME CMD...           as lib_run, for a command of another program that writes into
#                                     the folder @OUT (a plots/ driver that runs gbssn1d itself):
#                                     complete when it exited 0 (marked by a file .lib-complete
#                                     in its folder)
#   lib_check [NAME...]               exit 1 naming each NAME (default: every lib_run so far)
#                                     that holds no completed run (after lib_wait: some run
#                                     failed), so that no table is made from them
#
# A run counts as done when $out/NAME.cmd holds the same command run by the same binary (the
# SHA-256 of CMD's program, and of every other file CMD names: a --config is an input too) and it
# completed: an evolve's timeseries.dat ends with
# "# end: completed", or it stopped by itself (exit 3: it left the physical range, went
# non-finite, lost its horizon: a result, the same on every rerun); a converge study wrote
# convergence.dat with a verdict and exited 0 (converges), 3 (a member stopped), 4 (does not
# converge), 5 (pre-asymptotic) or 6 (not judged: too short, or nothing above the round-off
# floor), each a result; a sweep wrote summary.dat with every member ok, invalid or blew-up (exit
# 0 or 3). An interrupted (exit 128 + n, "interrupted by"),
# failed, other-input or other-binary run is redone on a rerun: an evolve or converge afresh, a
# sweep of the same command resumed in its scratch folder (gbssn1d sweep keeps its finished
# members and reruns the others). The count of members run at once (-j N) is not part of what
# must match: another GBSSN1D_JOBS keeps every completed run.

lib_jobs() { # NAME: $jobs from GBSSN1D_JOBS (default: the core count), or exit 2 naming it
  case "${GBSSN1D_JOBS:-}" in
    '') jobs=$(nproc) ;;
    *[!0-9]* | 0*) echo "$1: GBSSN1D_JOBS = '$GBSSN1D_JOBS' is invalid: it must be a positive whole number (runs at once)" >&2; exit 2 ;;
    *) jobs=$GBSSN1D_JOBS ;;
  esac
  if [ "$jobs" -gt 1024 ]; then
    echo "$1: GBSSN1D_JOBS = $jobs is invalid: at most 1024 runs at once" >&2
    exit 2
  fi
}

lib_init() {
  local name=$1 caller=$2 default=$3 given=${4:-}
  lib_name=$name
  lib_jobs "$name"
  if [ -n "$given" ]; then
    case "$given" in /*) out=$given ;; *) out=$caller/$given ;; esac
  else
    out=$PWD/$default
  fi
  [ ! -L "$out" ] || { echo "$name: $out is a symbolic link: refused (write into a real folder)" >&2; exit 2; }
  if [ -e "$out" ] && [ ! -d "$out" ]; then
    echo "$name: $out exists and is not a folder: refused (give another OUT)" >&2
    exit 2
  fi
  # another command's output (a gbssn1d run, study or sweep: its config.toml or summary.dat at
  # the top), or another script's results: not this script's folder, left as it is
  if [ -e "$out/config.toml" ] || [ -e "$out/summary.dat" ]; then
    echo "$name: $out holds another command's output (a gbssn1d run, study or sweep): refused, left as it is (give another OUT)" >&2
    exit 2
  fi
  if [ -f "$out/.script" ] && [ "$(cat "$out/.script")" != "$name" ]; then
    echo "$name: $out holds the results of $(cat "$out/.script"): refused, left as they are (give another OUT)" >&2
    exit 2
  fi
  mkdir -p "$out"
  exec 9>"$out/.lock"
  flock -n 9 || { echo "$name: another run is writing $out (lock $out/.lock)" >&2; exit 1; }
  [ -f "$out/.script" ] || printf '%s\n' "$name" >"$out/.script"
  trap lib_interrupted INT TERM
}

lib_interrupted() {
  trap '' INT TERM
  local pid
  # each run's subshell (a signal sent to this script alone, not to the terminal's process
  # group, reaches neither it nor its gbssn1d): it passes the signal on to its gbssn1d and
  # returns only when that has ended (a sweep stopping its members takes a moment), so that
  # nothing is left running once this script has exited
  for pid in $(jobs -p); do
    kill -TERM "$pid" 2>/dev/null || true
  done
  wait 2>/dev/null || true
  echo "$lib_name: interrupted; completed runs in $out are kept, unfinished ones are redone (a sweep resumed) when you run the same command again" >&2
  exit 130
}

lib_complete() { # DIR: whether DIR holds a completed evolve, converge or sweep (or lib_run_any)
  if [ -f "$1/.lib-complete" ]; then
    return 0
  elif [ -f "$1/summary.dat" ] && [ -d "$1/logs" ]; then
    # a sweep: every member finished as a result (an interrupted or failed member, or one not
    # run yet, is rerun by the same sweep); the status column named by the header line
    awk '/^#/ { if (!c) for (i = 2; i <= NF; i++) if ($i == "status") c = i - 1; next }
         !c || ($c != "ok" && $c != "invalid" && $c != "blew-up") { bad = 1; exit }
         { rows++ }
         END { exit bad || !rows }' "$1/summary.dat"
  elif [ -f "$1/convergence.dat" ]; then
    grep -q '^# verdict' "$1/convergence.dat" &&
      ! grep -q -E '^# verdict: not judged: (the study was interrupted|.*a write failed)' "$1/convergence.dat"
  else
    [ -f "$1/timeseries.dat" ] && tail -n 1 "$1/timeseries.dat" | grep -q -E '^# end: (completed|stopped: )' &&
      ! tail -n 1 "$1/timeseries.dat" | grep -q '^# end: stopped: interrupted by'
  fi
}

lib_same() { # TEXT1 TEXT2: the same command, whatever its -j (members at once)
  [ "$(lib_sans_jobs "$1")" = "$(lib_sans_jobs "$2")" ]
}
lib_sans_jobs() { # TEXT: TEXT without a `-j N`
  local text=" $1 "
  while [[ $text =~ ^(.*)\ -j\ [^\ ]+\ (.*)$ ]]; do
    text="${BASH_REMATCH[1]} ${BASH_REMATCH[2]}"
  done
  printf '%s' "$text"
}

lib_done() { # NAME CMDTEXT: whether $out/NAME holds a completed run of CMDTEXT
  local dir=$out/$1
  [ -f "$out/$1.cmd" ] && lib_same "$(cat "$out/$1.cmd")" "$2" && [ -d "$dir" ] && [ ! -L "$dir" ] &&
    lib_complete "$dir"
}

declare -A lib_binaries=()

lib_run() {
  local name=$1
  shift
  : "${out:?lib_init first}"
  case /$name/ in
  // | *//* | */./* | */../*) echo "$lib_name: '$name' is not a run's name (a relative path)" >&2; exit 2 ;;
  esac
  # the run's folder, its scratch folder and the one the result it replaces waits in, side by side
  local dir=$out/$name
  local new=${dir%/*}/.new-${dir##*/} old=${dir%/*}/.old-${dir##*/}
  local cmd=() arg
  for arg in "$@"; do
    if [ "$arg" = @OUT ]; then cmd+=("$new"); else cmd+=("$arg"); fi
  done
  # the command and the program it runs (its first word naming a file by a path, after an
  # `env VAR=value ...`): a rebuilt binary redoes every run
  local program="" sweep=no any=${lib_any:-no}
  for arg in "$@"; do
    if [ -n "$program" ]; then
      [ "$arg" != sweep ] || sweep=yes
      break
    fi
    case $arg in */*) [ -f "$arg" ] && program=$arg ;; esac
  done
  [ -n "$program" ] || { echo "$lib_name: $name: no program file in the command ($*)" >&2; exit 2; }
  [ -n "${lib_binaries[$program]:-}" ] || lib_binaries[$program]=$(sha256sum "$program" | cut -c1-16)
  local text
  text="$(printf '%q ' "$@")# binary ${lib_binaries[$program]}"
  # and every other file the command names (a --config, an h_AH file): an edited file redoes
  # the run
  for arg in "$@"; do
    [ "$arg" != "$program" ] && [ -f "$arg" ] && text+=" # file $arg $(sha256sum "$arg" | cut -c1-16)"
  done
  # a name asked for again in the same script: the same command runs once (a second run of it
  # beside the first would write into the same scratch folder); another command is refused
  if [ -n "${lib_texts[$name]:-}" ]; then
    [ "${lib_texts[$name]}" = "$text" ] && return 0
    echo "$lib_name: $name: asked for with two different commands" >&2
    exit 2
  fi
  lib_texts[$name]=$text
  lib_names+=("$name")
  if lib_done "$name" "$text"; then
    return 0
  fi
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  (
    # a signal (lib_interrupted's TERM, or the terminal's Ctrl-C) is passed on to the program,
    # which stops as an interrupted run does, and waited for; nothing is moved into place then
    stopping="" child="" grandchildren=""
    trap 'stopping=yes; lib_stop_child' INT TERM
    # an unfinished sweep of the same command is resumed where it stopped; anything else afresh
    if [ $sweep = no ] || [ ! -f "$new.cmd" ] || ! lib_same "$(cat "$new.cmd")" "$text"; then
      rm -rf "$new" "$new.cmd"
    fi
    mkdir -p "${dir%/*}"
    [ $sweep = no ] || printf '%s' "$text" >"$new.cmd"
    [ -z "$stopping" ] || exit 130
    "${cmd[@]}" >"$dir.log" 2>&1 &
    child=$!
    [ -z "$stopping" ] || lib_stop_child
    status=0
    wait "$child" || status=$?
    # (a wait cut short by the signal: the program is still stopping)
    while [ -n "$(jobs -rp)" ]; do status=0; wait "$child" || status=$?; done
    if [ -n "$stopping" ]; then
      for pid in $grandchildren; do
        while kill -0 "$pid" 2>/dev/null; do sleep 0.05; done
      done
      exit 130
    fi
    case $status in 0 | 3 | 4 | 5 | 6) ;; *) status_ok=no ;; esac
    if [ "$any" = yes ]; then
      rm -f "$new/.lib-complete"
      [ "$status" != 0 ] || [ ! -d "$new" ] || [ -L "$new" ] || : >"$new/.lib-complete"
    fi
    if [ "${status_ok:-yes}" = yes ] && { [ $status -le 3 ] || [ -f "$new/convergence.dat" ]; } &&
      lib_complete "$new"; then
      rm -rf "$old"
      [ ! -e "$dir" ] || mv "$dir" "$old"
      mv "$new" "$dir"
      printf '%s' "$text" >"$dir.cmd"
      echo "$status" >"$dir.status"
      rm -rf "$old" "$new.cmd"
    else
      local again="redone on a rerun"
      [ $sweep = no ] || again="resumed by a rerun"
      echo "  $name: exit $status, see $dir.log (kept in $new; $again)" >&2
    fi
  ) &
}

# (in a run's subshell) TERM to its program and to that program's own children: a wrapper such
# as /usr/bin/time passes no signal on; they are waited for before the subshell ends
lib_stop_child() {
  [ -n "$child" ] || return 0
  local pid
  grandchildren+=" $(pgrep -P "$child" || true)"
  kill -TERM "$child" 2>/dev/null || true
  for pid in $grandchildren; do kill -TERM "$pid" 2>/dev/null || true; done
}

lib_run_any() {
  local lib_any=yes
  lib_run "$@"
}

lib_names=()
declare -A lib_texts=()
lib_check() {
  local name missing=()
  [ $# -gt 0 ] || set -- "${lib_names[@]}"
  for name in "$@"; do
    # completed, and by the command this script asked for (a finished result of another
    # command kept in place does not count)
    lib_done "$name" "${lib_texts[$name]:-}" || missing+=("$name")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "$lib_name: ${#missing[@]} run(s) did not complete (${missing[*]}); the tables are not made: see their logs in $out, then run the same command again" >&2
    exit 1
  fi
}

lib_wait() {
  while [ -n "$(jobs -rp)" ]; do wait -n || true; done
}
