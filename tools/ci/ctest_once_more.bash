# shellcheck shell=bash
# Sourced by setup.sh and tools/ci/sanitizers.sh: a test run where a failure with no
# report that rules a second try out runs once more, by name, one at a time with the
# run's other failures. The second try is for the host, not the code: on this project's
# CI machines (virtual ones) a real-time thread at SCHED_FIFO, with nothing else running,
# woke 42 ms late once in five minutes, and a test that holds a device's firmware
# watchdog of 30 ms then fails. A test that passes on its second try is named as flaky;
# one that fails again fails the run.
#
# ctest_once_more <label> <build dir> <no-second-try regex> <ctest args...>
#   Runs ctest in <build dir>. Where the tests' output matches the regex (a sanitizer's
#   report; empty: never), nothing runs again. Appends "<label> <test>" to the caller's
#   arrays failed_tests and flaky_tests; returns ctest's last exit status.
# ctest_name_tests <prefix>
#   Prints those arrays, each under a heading, where not empty.

# The names of the tests ctest saw fail in <build dir>, one per line: CI shows only the end
# of the log, and a test phase can end thousands of lines above it.
ctest_failed_in() {
  local log="$1/Testing/Temporary/LastTestsFailed.log"
  [ -f "$log" ] && sed 's/^[0-9]*://' "$log"
}

# ctest_names_regex <name>...: a regex that matches exactly those test names.
ctest_names_regex() {
  local name escaped=()
  for name in "$@"; do escaped+=("$(printf '%s' "$name" | sed 's/[][\\.*^$()+?{}|]/\\&/g')"); done
  local IFS='|'
  echo "^(${escaped[*]})\$"
}

ctest_once_more() {
  local label="$1" dir="$2" no_second_try="$3" rc name
  shift 3
  local log="$dir/Testing/Temporary/ctest_once_more.log"
  # A list left by an earlier run in this folder must not pass for this run's.
  rm -f "$dir/Testing/Temporary/LastTestsFailed.log"
  ctest --test-dir "$dir" --output-log "$log" "$@" && return 0
  rc=$?
  local first=()
  mapfile -t first < <(ctest_failed_in "$dir")
  if { [ -n "$no_second_try" ] && grep -qE "$no_second_try" "$log"; } || [ ${#first[@]} -eq 0 ]; then
    for name in "${first[@]}"; do failed_tests+=("$label $name"); done
    return $rc
  fi
  echo "==== $label: ${#first[@]} test(s) failed; once more, alone:"
  printf '  %s\n' "${first[@]}"
  # By name: ctest's --rerun-failed goes by the numbers of the first run, which a filter
  # (-E, -R) renumbers, so it would run other tests in their place.
  ctest --test-dir "$dir" -R "$(ctest_names_regex "${first[@]}")" --output-on-failure --timeout 300 \
    --output-log "$log.rerun" && {
    for name in "${first[@]}"; do flaky_tests+=("$label $name"); done
    return 0
  }
  rc=$?
  local again=()
  mapfile -t again < <(ctest_failed_in "$dir")
  for name in "${again[@]}"; do failed_tests+=("$label $name"); done
  for name in "${first[@]}"; do
    printf '%s\n' "${again[@]}" | grep -qxF -- "$name" || flaky_tests+=("$label $name")
  done
  return $rc
}

# ctest_name_tests <prefix>: the caller's flaky and failed tests, under headings, if any.
ctest_name_tests() {
  if [ ${#flaky_tests[@]} -gt 0 ]; then
    echo "==== $1: flaky (failed, passed when run again)"
    printf '  %s\n' "${flaky_tests[@]}"
  fi
  if [ ${#failed_tests[@]} -gt 0 ]; then
    echo "==== $1: failed tests"
    printf '  %s\n' "${failed_tests[@]}"
  fi
}
