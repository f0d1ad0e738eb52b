#!/usr/bin/env bash
# The builds CI tests after the release suite, made beforehand at idle priority:
#   tools/ci/idle_builds.sh start <dir> <step>...   starts them in the background, in order
#   tools/ci/idle_builds.sh wait <dir> <step>       waits for one, prints its output, exits
#                                                   with its exit status
#   tools/ci/idle_builds.sh stop <dir>              ends those still running
# Steps: asan and tsan (tools/ci/sanitizers.sh build), fuzz (tools/fuzz/run_fuzzers.sh
# --build-only). A build under SCHED_IDLE takes only the CPU that other tasks leave: the
# release build leaves little, the release and ASan tests much more (they wait on clocks,
# sockets and other processes). Each step writes <dir>/<step>.log, then <dir>/<step>.rc
# ("<exit status> <seconds>") once it has ended. `run` is the background part of `start`.
set -uo pipefail
cd "$(dirname "$0")/../.."

usage() { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 2 ] || usage
action="$1" dir="$2"
shift 2

command_of() {  # command_of <step>: the step's command line
  case "$1" in
    asan|tsan) echo "tools/ci/sanitizers.sh build $1" ;;
    fuzz) echo "tools/fuzz/run_fuzzers.sh --build-only" ;;
    *) echo "idle_builds.sh: unknown step '$1' (asan, tsan or fuzz)" >&2; return 2 ;;
  esac
}

run_steps() {  # run_steps <step>...: each in turn, its log and exit status in $dir
  local step t0 rc
  for step in "$@"; do
    t0=$(date +%s)
    # shellcheck disable=SC2046 # the command line is split into words on purpose
    $(command_of "$step") >"$dir/$step.log" 2>&1 </dev/null
    rc=$?
    echo "$rc $(($(date +%s) - t0))" >"$dir/$step.rc.part" && mv "$dir/$step.rc.part" "$dir/$step.rc"
  done
}

tree_of() {  # tree_of <pid>: the process and its descendants, parents first
  ps -e -o pid=,ppid= | awk -v root="$1" '
    { parent[$1] = $2; order[NR] = $1 }
    END {
      keep[root] = 1; print root
      do {
        grown = 0
        for (i = 1; i <= NR; i++) {
          p = order[i]
          if (!(p in keep) && (parent[p] in keep)) { keep[p] = 1; print p; grown = 1 }
        }
      } while (grown)
    }'
}

signal_tree() {  # signal_tree <signal>: to the builds' processes; twice, for any just started
  local pid p
  pid=$(cat "$dir/pid" 2>/dev/null) || return 0
  kill -0 "$pid" 2>/dev/null || return 0
  for _ in 1 2; do
    for p in $(tree_of "$pid"); do kill -"$1" "$p" 2>/dev/null; done
  done
}

case "$action" in
  start)
    [ $# -ge 1 ] || usage
    for step in "$@"; do command_of "$step" >/dev/null || exit 2; done
    rm -rf "$dir" && mkdir -p "$dir" || exit 1
    # SCHED_IDLE is inherited by every compiler and linker the builds start (nice 19
    # where the policy is refused). Not under setsid: that would give the builds a
    # scheduler autogroup of their own, which the kernel gives as much of the CPU as the
    # tests' (seen: half each).
    idle=(chrt --idle 0)
    "${idle[@]}" true 2>/dev/null || idle=(nice -n 19)
    "${idle[@]}" "$0" run "$dir" "$@" </dev/null >/dev/null 2>&1 &
    echo $! >"$dir/pid"
    ;;
  run)
    run_steps "$@"
    ;;
  wait)
    [ $# -eq 1 ] || usage
    step="$1"
    command_of "$step" >/dev/null || exit 2
    pid=$(cat "$dir/pid" 2>/dev/null) || { echo "idle_builds.sh: nothing was started in $dir" >&2; exit 1; }
    while [ ! -f "$dir/$step.rc" ]; do
      if ! kill -0 "$pid" 2>/dev/null && [ ! -f "$dir/$step.rc" ]; then
        [ -f "$dir/$step.log" ] && cat "$dir/$step.log"
        echo "idle_builds.sh: the $step build ended with no exit status" >&2
        exit 1
      fi
      sleep 1
    done
    cat "$dir/$step.log"
    read -r rc seconds <"$dir/$step.rc"
    echo "==== idle builds: $step: $seconds s from its start, exit $rc"
    exit "$rc"
    ;;
  stop)
    # Ninja starts each compiler in a process group of its own: the whole tree is signalled.
    signal_tree TERM
    signal_tree CONT
    ;;
  *) usage ;;
esac
