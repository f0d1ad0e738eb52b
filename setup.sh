#!/usr/bin/env bash
# One-step set-up for a fresh Debian 12 machine (run as root, or with sudo available):
# installs the missing Debian packages, configures and builds with CMake, then
#   ./setup.sh demo   runs the main job on simulated hardware (the default dolphin scene)
#   ./setup.sh test   runs every test with ctest, then the suite under ASan+UBSan and the
#                     threaded tests under TSan (tools/ci/sanitizers.sh), then each fuzz
#                     target briefly (tools/fuzz/run_fuzzers.sh); docs/reliability.md
set -euo pipefail
cd "$(dirname "$0")"

mode="${1:-}"
case "$mode" in
  demo|test) ;;
  *) echo "usage: $0 demo|test" >&2; exit 2 ;;
esac

# Each phase's wall time, printed as it ends and again as a table when the script exits
# (a failed phase included), so that every run shows what it cost.
t_start=$(date +%s)
phases=()
phase() {  # phase <label> <command...>
  local label="$1" t0 rc=0
  shift
  echo "==== setup: $label"
  t0=$(date +%s)
  "$@" || rc=$?
  phases+=("$(printf '%-34s %6d s  %s' "$label" $(($(date +%s) - t0)) "$([ $rc -eq 0 ] && echo ok || echo "FAILED ($rc)")")")
  echo "==== setup: $label: $(($(date +%s) - t0)) s, exit $rc"
  return $rc
}
failed_tests=()
flaky_tests=()
# shellcheck source=tools/ci/ctest_once_more.bash
source tools/ci/ctest_once_more.bash
summary() {
  [ ${#phases[@]} -gt 0 ] || return 0
  echo "==== setup: phases ($mode)"
  printf '  %s\n' "${phases[@]}"
  printf '  %-34s %6d s\n' total $(($(date +%s) - t_start))
  ctest_name_tests setup
}
trap summary EXIT
quietly() { "$@" >/dev/null; }

mapfile -t wanted < <(grep -v '^\s*#' tools/debian-packages.txt | grep -v '^\s*$')
missing=()
for p in "${wanted[@]}"; do
  [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" == *"install ok installed"* ]] || missing+=("$p")
done
install_missing() {
  echo "setup: installing ${missing[*]}"
  local sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq || return
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
if [ ${#missing[@]} -gt 0 ]; then phase "Debian packages" install_missing; fi

phase "release configure" quietly cmake --preset release

if [ "$mode" = demo ]; then
  # Only what the demo runs: mhd and the plugins (the tests and benchmarks come with `test`).
  phase "release build (mhd and plugins)" cmake --build --preset release --target mhd-runtime
  trap - EXIT
  summary
  exec build/release/tools/mhd/mhd run scenes/dolphin.xml --duration 20 --record build/release/dolphin_run.csv
else
  # MHD_SANITIZERS=0 / MHD_FUZZ_SECONDS=0 skip these (for a quick local run).
  sanitizers=$([ "${MHD_SANITIZERS:-1}" != 0 ] && echo 1 || echo 0)
  fuzz_seconds="${MHD_FUZZ_SECONDS:-20}"
  # The ASan, TSan and fuzzing builds start now, at idle priority (tools/ci/idle_builds.sh):
  # they take what the release build and the tests leave of the cores, and each is waited
  # for just before its tests; their output is printed then.
  idle_dir=build/ci-idle
  idle_steps=()
  [ "$sanitizers" = 1 ] && idle_steps+=(asan tsan)
  [ "$fuzz_seconds" != 0 ] && idle_steps+=(fuzz)
  if [ ${#idle_steps[@]} -gt 0 ]; then
    tools/ci/idle_builds.sh start "$idle_dir" "${idle_steps[@]}"
    trap 'tools/ci/idle_builds.sh stop "$idle_dir"; summary' EXIT
  fi
  phase "release build" cmake --build --preset release
  # A failed test runs once more, alone (tools/ci/ctest_once_more.bash).
  phase "release test" ctest_once_more release build/release "" -j 2 --output-on-failure
  # The sanitizer script prints its own phases and a summary of each.
  if [ "$sanitizers" = 1 ]; then
    phase "asan build (idle priority, waited)" tools/ci/idle_builds.sh wait "$idle_dir" asan
    phase "asan test (ASan+UBSan)" tools/ci/sanitizers.sh test asan
    phase "tsan build (idle priority, waited)" tools/ci/idle_builds.sh wait "$idle_dir" tsan
    phase "tsan test" tools/ci/sanitizers.sh test tsan
  fi
  if [ "$fuzz_seconds" != 0 ]; then
    phase "fuzz build (idle priority, waited)" tools/ci/idle_builds.sh wait "$idle_dir" fuzz
    phase "fuzz (each target $fuzz_seconds s)" tools/fuzz/run_fuzzers.sh --no-build --seconds "$fuzz_seconds"
  fi
fi
