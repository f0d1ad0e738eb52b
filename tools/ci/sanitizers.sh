#!/usr/bin/env bash
# The test suite under the sanitizers (docs/reliability/sanitizers.md):
#   tools/ci/sanitizers.sh asan   every test, built with AddressSanitizer + UBSan (preset asan)
#   tools/ci/sanitizers.sh tsan   the tests that start threads, built with ThreadSanitizer
#                                 (preset tsan; only their targets are built)
#   tools/ci/sanitizers.sh [all]  both
#   tools/ci/sanitizers.sh build|test [asan|tsan|all]
#                                 only the configure and build, or only the tests of a
#                                 build made before: CI (setup.sh test) builds both at idle
#                                 priority beside its other phases (tools/ci/idle_builds.sh),
#                                 then tests them
# Any sanitizer report fails its test (the run aborts on the first report) and fails this
# script. A test that fails with no sanitizer report in the output (an assertion on timing,
# which instrumentation slows several times) runs once more, alone with the other
# failures (tools/ci/ctest_once_more.bash); if it then passes it is named as flaky in the
# summary, and otherwise it fails this script. Each phase prints its wall time.
#
# Environment: MHD_CI_JOBS (default 2) build and test jobs; MHD_ASAN_BUILD_DIR and
# MHD_TSAN_BUILD_DIR (default build/asan, build/tsan) to build elsewhere;
# MHD_SAN_CTEST_ARGS extra ctest arguments (e.g. "-R Dolphin" while triaging).
set -uo pipefail
cd "$(dirname "$0")/../.."
root="$PWD"

usage() { echo "usage: $0 [build|test] [asan|tsan|all]" >&2; exit 2; }
step=both
case "${1:-}" in
  build|test) step="$1"; shift ;;
esac
mode="${1:-all}"
case "$mode" in
  asan|tsan|all) ;;
  *) usage ;;
esac
[ $# -le 1 ] || usage
jobs="${MHD_CI_JOBS:-2}"
asan_dir="${MHD_ASAN_BUILD_DIR:-build/asan}"
tsan_dir="${MHD_TSAN_BUILD_DIR:-build/tsan}"
read -r -a extra_ctest <<<"${MHD_SAN_CTEST_ARGS:-}"

# ---- what runs under which sanitizer ---------------------------------------------------

# Tests left out under a sanitizer, as ctest -E regexes. Only two sorts belong here, each
# one saying why: tests whose assertion is about real-time timing (a sanitizer makes every
# tick several times slower, so a deadline count measures the sanitizer, not the code;
# the code they run is still checked by the other tests of the same binary), and tests
# that run no MHD code at all, only tools over the build's files (packaging).
asan_exclude=(
  # viewer_server_tests counts the haptic loop's overruns with the OSG viewer drawing
  # against a run without it. Under ASan on the 2-core CI machine it failed on
  # 2026-11-25 (11 overruns against 1 without the viewer); it is a timing comparison,
  # and it runs in the release suite.
  viewer_server_tests
  # Install.DebPackages runs cpack and dpkg-deb over the build's binaries: no MHD code
  # runs, and nobody ships sanitizer builds. It runs in the release suite. (The install
  # test, Install.PrefixAndOutOfTreeBuilds, stays: it runs the installed, instrumented
  # mhd, and builds its engine consumer with this build's sanitizer flags.)
  'Install\.DebPackages'
  # TwoRigSession runs four real-time processes (two tracker servers, two haptic servers
  # at 1 kHz) on the 2-core machine. Instrumented, on 2026-11-29, a base came within
  # 0.239 m of a user (0.56 m and more in every release run), the two recordings then
  # compared on their own clocks. On one clock, on 2026-12-01, it failed 2 of 3
  # instrumented runs: a base 0.472 m from a user (0.475 m asked), and rig 2's user never
  # in contact. On 2026-12-01 again, 7 instrumented runs: 6 passed (a base 0.489-0.571 m
  # from a user, 0.496-0.570 m in 7 release runs), and in 1 the secured samples reached
  # both haptic processes over 0.1 s old all run (3579 of 3596 refused as stale: force
  # faded, bases stopped). The closest pair is a rig's own base and user as the user walks
  # in: in two release recordings the base is then backing away (12 mm in 50 ms) and the user
  # walking into it, so the test's "never within 0.475 m" also asks the simulated user to
  # stop. It runs in the release suite.
  'TwoRigSession\.'
  # The shared-box tests that hold a box pressed from opposite sides (secured or not) to
  # staying put. Instrumented, on 2026-11-30, rig 1's loop overran 10 times and the box
  # slid 62 mm (1-2 mm in the release runs). Judged only while both rigs ran, on
  # 2026-12-01, 1 of 5 instrumented runs still had it slide 59 mm, the rigs' boxes up to
  # 15 mm apart (2.2-3.3 mm and 0.4-0.5 mm in the other 4). They run in the release
  # suite; the other SharedBoxProcess tests (pressed from one side, one rig alone, a
  # replica with no authority) stay here.
  'SharedBoxProcess\.(Secured)?PressedFromOppositeSides'
  # SharedFloorRun.LosingTheOtherRigsDataHoldsTheBaseUntilItIsBack times the base's stop
  # against a 2 s dropout in a real-time `mhd run`. Instrumented, on 2026-11-30, it failed
  # once in a clean CI run (bases 0.435 m apart, 0.45 m asked) and 5 times in 5 with the
  # two cores loaded (5-26 overruns, 11-53 deadlines missed a run); the release build,
  # loaded the same way, passed 3 of 3. It runs in the release suite; the other
  # SharedFloorRun tests, which passed loaded under ASan, stay here.
  'SharedFloorRun\.LosingTheOtherRigsDataHoldsTheBaseUntilItIsBack'
)
tsan_exclude=(
  # DeclaredParams walks every in-tree plugin by loading and unloading it, libmhd_dds.so
  # (which loads libddsc) included; TSan aborts when a library named in a called_from_lib
  # suppression (tsan.supp) is unloaded. The test starts no thread; it runs in the release
  # and ASan suites.
  'DeclaredParams\.'
  # The secured three-process example runs DDS Security (Cyclone's auth, crypto and access
  # control plugins and OpenSSL, all uninstrumented): TSan reports races inside them, one
  # library after another (libdds_security_crypto, _auth, then libcrypto's own locks).
  # The secured tests are not in TSan's set for that reason (dds_security_tests is not a
  # target); this one lives in dds_server_tests. The unsecured DDS server tests stay.
  'ThreeProcessExample\.Secured'
  # The mesh cache's mesh past 2^21 triangles takes about a minute under TSan; the same
  # threads (checksum, face normals, the tree's pieces) run in
  # AMeshLargeEnoughForTwoThreadsLoadsFromTheCacheAsBuilt, which stays.
  'MeshCacheTest\.AMeshPastOneBulletPart'
  # Meshes of 2^21 triangles (a minute or more each under TSan). The two-thread tree
  # build they go through runs in SplitTreeBuild.ASmallMeshBuiltInPiecesPassesTheTreeCheck,
  # which stays.
  'LargeMesh\.'
  'SplitTreeBuild\.AShuffled'
)

# ThreadSanitizer: every test binary whose code starts threads (the haptic server's five
# threads, the DDS listener threads of Cyclone, the viewer's state hand-off), the
# lock-free hand-offs, and the plugin host that those threads drive.
tsan_targets=(
  realtime_tests              # SpscRing, TripleBuffer, Seqlock: producer/consumer threads
  servo_loop_tests            # the openhaptics plugin: HDAPI's servo thread and the haptic tick
  simulation_tests            # SimulatedWorld's seqlock and mutexes, concurrent writers
  sim_world_tests             # the simulated plugins' shared world, advanced from two threads
  plugin_host_tests           # the loader the server threads call into
  haptic_server_tests         # the whole server (haptic, io, planner, display, recorder)
  recording_replay_tests      # the recorder thread, then replay
  dds_tests                   # Cyclone DDS: listeners, the tracker/state plugins, processes
  dds_server_tests            # the server fed over DDS by another process
  viewer_tests                # the viewer's latest-state hand-off (rig_state_test)
  viewer_dds_tests            # the viewer's DDS state source
  mesh_io_tests               # a cache hit: checksum thread, two-thread face normals and tree check
  collision_tests             # a tree built in pieces on two threads
)

# ---- helpers --------------------------------------------------------------------------

summary=()
failed=0
failed_tests=()
flaky_tests=()

now() { date +%s.%N; }
phase() {  # phase <label> <command...>: runs it, prints and records its wall time
  local label="$1"; shift
  local t0 t1 rc
  echo "==== sanitizers: $label"
  t0=$(now)
  "$@"
  rc=$?
  t1=$(now)
  local secs
  secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", b - a }')
  summary+=("$(printf '%-28s %5s s  %s' "$label" "$secs" "$([ $rc -eq 0 ] && echo ok || echo "FAILED ($rc)")")")
  echo "==== sanitizers: $label: ${secs} s, exit $rc"
  [ $rc -eq 0 ] || failed=1
  return $rc
}

join_regex() { local IFS='|'; echo "$*"; }

# What a sanitizer prints when it finds something (LeakSanitizer's report says ERROR too):
# a test whose output holds one gets no second try (ctest_once_more.bash).
sanitizer_report='ERROR: AddressSanitizer|ERROR: LeakSanitizer|WARNING: ThreadSanitizer|runtime error:'
# shellcheck source=tools/ci/ctest_once_more.bash
source "$root/tools/ci/ctest_once_more.bash"

built() {  # built <build dir>: whether a build was configured there, saying so if not
  [ -f "$1/CTestTestfile.cmake" ] && return 0
  echo "sanitizers: no build in $1 (run: $0 build $mode)" >&2
  failed=1
  return 1
}

supp() {  # supp <file>: the suppressions option for a file in tools/ci, if it exists
  [ -f "$root/tools/ci/$1" ] && echo ":suppressions=$root/tools/ci/$1"
}

# ---- AddressSanitizer + UndefinedBehaviorSanitizer ------------------------------------

build_asan() {
  phase "asan configure" cmake --preset asan -B "$asan_dir" >/dev/null || return
  phase "asan build" cmake --build "$asan_dir" -j "$jobs"
}

test_asan() {
  built "$asan_dir" || return
  local exclude=()
  [ ${#asan_exclude[@]} -eq 0 ] || exclude=(-E "$(join_regex "${asan_exclude[@]}")")
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:check_initialization_order=1:strict_init_order=1$(supp asan.supp)"
  export LSAN_OPTIONS="print_suppressions=0$(supp lsan.supp)"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1$(supp ubsan.supp)"
  phase "asan test" ctest_once_more asan "$asan_dir" "$sanitizer_report" \
    -j "$jobs" --output-on-failure --timeout 300 "${exclude[@]}" "${extra_ctest[@]}"
  unset ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS
}

# ---- ThreadSanitizer ------------------------------------------------------------------

build_tsan() {
  phase "tsan configure" cmake --preset tsan -B "$tsan_dir" >/dev/null || return
  phase "tsan build" cmake --build "$tsan_dir" -j "$jobs" --target "${tsan_targets[@]}"
}

test_tsan() {
  built "$tsan_dir" || return
  # Exactly the tests of the binaries built here, by number (their folders also hold
  # tests of binaries that are not, e.g. the `mhd` command's).
  local numbers
  numbers=$(ctest --test-dir "$tsan_dir" --show-only=json-v1 | python3 -c '
import json, os, re, sys
targets, exclude = set(sys.argv[1].split()), re.compile(sys.argv[2] or "(?!)")
tests = json.load(sys.stdin)["tests"]
print(",".join(str(i + 1) for i, t in enumerate(tests)
               if os.path.basename(t.get("command", [""])[0]) in targets and not exclude.search(t["name"])))
' "${tsan_targets[*]}" "$(join_regex "${tsan_exclude[@]}")")
  if [ -z "$numbers" ]; then
    echo "sanitizers: no tsan tests found in $tsan_dir" >&2
    failed=1
    return 1
  fi
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1$(supp tsan.supp)"
  phase "tsan test" ctest_once_more tsan "$tsan_dir" "$sanitizer_report" \
    -j "$jobs" --output-on-failure --timeout 300 -I "0,0,0,$numbers" "${extra_ctest[@]}"
  unset TSAN_OPTIONS
}

t_start=$(now)
run() {  # run asan|tsan: the step asked for
  case "$step" in
    build) "build_$1" ;;
    test) "test_$1" ;;
    both) "build_$1" && "test_$1" ;;
  esac
}
case "$mode" in
  asan) run asan ;;
  tsan) run tsan ;;
  all) run asan; run tsan ;;
esac
total=$(awk -v a="$t_start" -v b="$(now)" 'BEGIN { printf "%.0f", b - a }')

echo "==== sanitizers: summary ($step $mode, $jobs jobs)"
printf '  %s\n' "${summary[@]}"
printf '  %-28s %5s s\n' "total" "$total"
ctest_name_tests sanitizers
if [ $failed -ne 0 ]; then
  echo "==== sanitizers: FAILED" >&2
  exit 1
fi
if [ "$step" = build ]; then echo "==== sanitizers: built"; else echo "==== sanitizers: all clean"; fi
