#!/usr/bin/env bash
# Builds MHD's libFuzzer targets with clang (ASan + UBSan + libFuzzer) and runs each for
# a while: docs/reliability/fuzzing.md.
#
#   tools/fuzz/run_fuzzers.sh [--seconds N] [--build-dir DIR] [--only NAME] [--jobs J]
#                             [--fresh] [--no-build | --build-only]
#
#   --seconds N     run each target for N seconds (default 20)
#   --build-dir DIR build folder (default build/fuzz); the corpora, crash files and logs
#                   go under DIR/fuzz/
#   --only NAME     one target: scene, mesh-header, mesh-cache, replay-csv, dds-sample or
#                   recording (default: all)
#   --jobs J        build jobs, and targets fuzzed at once (default 2)
#   --fresh         start from the seeds only (drop what earlier runs added to the corpus)
#   --no-build      run what is already built
#   --build-only    build, and run nothing (CI builds at idle priority beside other work)
#
# Exits 0 when every target ran its time without a crash, leak, timeout or out-of-memory;
# otherwise 1, after printing the crash file (re-run one with `DIR/tools/fuzz/mhd-fuzz-NAME
# FILE`). Needs Debian's clang and libclang-rt-14-dev (or another clang with libFuzzer).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
seconds=20
build_dir="$repo/build/fuzz"
only=""
jobs=2
fresh=0
build=1
run=1

usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds="${2:?--seconds needs a number}"; shift 2 ;;
    --build-dir) build_dir="${2:?--build-dir needs a folder}"; shift 2 ;;
    --only) only="${2:?--only needs a target name}"; shift 2 ;;
    --jobs|-j) jobs="${2:?--jobs needs a number}"; shift 2 ;;
    --fresh) fresh=1; shift ;;
    --no-build) build=0; shift ;;
    --build-only) run=0; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "run_fuzzers.sh: error: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ "$seconds" =~ ^[0-9]+$ && "$seconds" -gt 0 ]] || { echo "run_fuzzers.sh: error: --seconds must be a positive integer, got '$seconds'" >&2; exit 2; }
[[ "$jobs" =~ ^[0-9]+$ && "$jobs" -gt 0 ]] || { echo "run_fuzzers.sh: error: --jobs must be a positive integer, got '$jobs'" >&2; exit 2; }
[[ "$build_dir" = /* ]] || build_dir="$PWD/$build_dir"

all_targets=(scene mesh-header mesh-cache replay-csv dds-sample recording)
if [[ -n "$only" ]]; then
  case " ${all_targets[*]} " in
    *" $only "*) targets=("$only") ;;
    *) echo "run_fuzzers.sh: error: unknown target '$only' (expected one of: ${all_targets[*]})" >&2; exit 2 ;;
  esac
else
  targets=("${all_targets[@]}")
fi

# max_len per target: scenes run to ~2.5 kB, mesh seeds to ~1 kB, CSV rows ~60 bytes, a
# DDS sample ~90 bytes.
max_len_of() {
  case "$1" in
    scene) echo 16384 ;;
    mesh-header) echo 8192 ;;
    mesh-cache) echo 4096 ;;
    replay-csv) echo 8192 ;;
    dds-sample) echo 4096 ;;
  esac
}
dict_of() {
  case "$1" in
    scene) echo "$repo/tools/fuzz/dict/scene.dict" ;;
    mesh-header) echo "$repo/tools/fuzz/dict/mesh_header.dict" ;;
    replay-csv) echo "$repo/tools/fuzz/dict/replay_csv.dict" ;;
    dds-sample) echo "" ;;
    mesh-cache) echo "" ;;
  esac
}
# Seed files, one per line: the repository's own data plus tools/fuzz/corpus/<name> and
# tools/fuzz/regressions/<name> (inputs that once crashed, so they stay fixed).
seeds_of() {
  local name="$1"
  case "$name" in
    scene) find "$repo/scenes" "$repo/tests/data" -type f -name '*.xml' ;;
    mesh-header) ;;  # seeds carry a leading format byte: tools/fuzz/corpus/mesh-header
    replay-csv) find "$repo/tests/data" -type f -name '*.csv' -size -64k ;;
    dds-sample) ;;
    mesh-cache) ;;  # seeds carry a leading mode byte: tools/fuzz/corpus/mesh-cache
    recording) find "$repo/tests/data" -type f -name '*.csv' -size -64k ;;
  esac
  for extra in "$repo/tools/fuzz/corpus/$name" "$repo/tools/fuzz/regressions/$name"; do
    [[ -d "$extra" ]] && find "$extra" -type f ! -name 'README*'
  done
  return 0
}

sanitize_flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
if [[ $build -eq 1 ]]; then
  command -v clang++ >/dev/null || { echo "run_fuzzers.sh: error: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
  echo "== configuring $build_dir (clang, ASan+UBSan+libFuzzer, -O1)"
  mkdir -p "$build_dir"
  CC=clang CXX=clang++ cmake -S "$repo" -B "$build_dir" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DCMAKE_C_FLAGS="$sanitize_flags" -DCMAKE_CXX_FLAGS="$sanitize_flags" \
    -DMHD_FUZZ=ON -DMHD_BUILD_TESTS=OFF -DMHD_BUILD_BENCHMARKS=OFF >"$build_dir/fuzz-configure.log" 2>&1 ||
    { cat "$build_dir/fuzz-configure.log" >&2; echo "run_fuzzers.sh: error: configuring failed" >&2; exit 1; }
  build_targets=()
  for t in "${targets[@]}"; do build_targets+=("mhd-fuzz-$t"); done
  echo "== building ${build_targets[*]} (-j$jobs)"
  build_t0=$(date +%s)
  cmake --build "$build_dir" -j "$jobs" --target "${build_targets[@]}"
  echo "== built in $(($(date +%s) - build_t0)) s"
fi
if [[ $run -eq 0 ]]; then
  [[ $build -eq 1 ]] || { echo "run_fuzzers.sh: error: --no-build and --build-only leave nothing to do" >&2; exit 2; }
  exit 0
fi

# The scene fuzzer writes every input to a file in a folder under $TMPDIR: on tmpfs that
# is several times faster than on disk.
if [[ -z "${TMPDIR:-}" && -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$repo/tools/fuzz/lsan.supp:print_suppressions=0}"

work="$build_dir/fuzz"
status=0
summary=()
# The targets run side by side, --jobs at a time (each is one process on one core), so the
# phase takes about targets / jobs times --seconds; each still runs its full time.
launch() {  # launch <target>: seeds its corpus, starts it in the background
  local t="$1" binary corpus artifacts log n_seeds=0 rel dict
  binary="$build_dir/tools/fuzz/mhd-fuzz-$t"
  corpus="$work/corpus/$t"
  artifacts="$work/artifacts/$t"
  log="$work/logs/$t.log"
  [[ $fresh -eq 1 ]] && rm -rf "$corpus"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  rm -f "$work/logs/$t.rc"
  # Seeds under names made from their paths (several folders hold a materials.xml).
  while IFS= read -r seed; do
    [[ -n "$seed" ]] || continue
    rel="${seed#"$repo"/}"
    cp -f "$seed" "$corpus/seed_${rel//\//_}"
    n_seeds=$((n_seeds + 1))
  done < <(seeds_of "$t")
  local args=("$corpus" "-max_total_time=$seconds" -timeout=10 -rss_limit_mb=2048 "-max_len=$(max_len_of "$t")"
              "-artifact_prefix=$artifacts/" -print_final_stats=1)
  dict="$(dict_of "$t")"
  [[ -n "$dict" ]] && args+=("-dict=$dict")
  echo "== fuzzing $t for ${seconds}s ($n_seeds seeds; log $log)"
  { local rc=0; "$binary" "${args[@]}" >"$log" 2>&1 || rc=$?; echo "$rc" >"$work/logs/$t.rc"; } &
}
running=0
for t in "${targets[@]}"; do
  [[ -x "$build_dir/tools/fuzz/mhd-fuzz-$t" ]] || continue
  if [[ $running -ge $jobs ]]; then
    wait -n || true
    running=$((running - 1))
  fi
  launch "$t"
  running=$((running + 1))
done
wait || true

for t in "${targets[@]}"; do
  binary="$build_dir/tools/fuzz/mhd-fuzz-$t"
  if [[ ! -x "$binary" ]]; then
    echo "run_fuzzers.sh: error: $binary was not built" >&2
    status=1
    summary+=("$(printf '%-11s %-9s' "$t" "not-built")")
    continue
  fi
  log="$work/logs/$t.log"
  rc="$(cat "$work/logs/$t.rc" 2>/dev/null || echo 1)"

  # The last value libFuzzer printed for each figure (none when it stopped at once).
  last_of() { { grep -o "$1 [0-9]*" "$log" || true; } | tail -n 1 | sed "s|^$1 ||"; }
  execs="$({ sed -n 's/^stat::number_of_executed_units: *//p' "$log" || true; } | tail -n 1)"
  rate="$(last_of 'exec/s:')"
  cov="$(last_of 'cov:')"
  ft="$(last_of 'ft:')"
  corp="$(last_of 'corp:')"
  if [[ $rc -eq 0 ]]; then
    verdict="ok"
  else
    status=1
    verdict="FAILED($rc)"
    echo "---- $t: libFuzzer exited with $rc; the end of $log:" >&2
    tail -n 60 "$log" >&2
    crash="$({ sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" || true; } | tail -n 1)"
    if [[ -n "$crash" ]]; then
      echo "---- $t: crash file: $crash" >&2
      echo "     reproduce: $binary $crash" >&2
    fi
  fi
  summary+=("$(printf '%-11s %-9s %12s %8s %7s %8s %7s' "$t" "$verdict" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}")")
done

echo
echo "== fuzzing summary (${seconds}s per target)"
printf '%-11s %-9s %12s %8s %7s %8s %7s\n' target result executions exec/s cov ft corpus
for line in "${summary[@]}"; do echo "$line"; done
exit "$status"
