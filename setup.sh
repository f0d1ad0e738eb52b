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

mapfile -t wanted < <(grep -v '^\s*#' tools/debian-packages.txt | grep -v '^\s*$')
missing=()
for p in "${wanted[@]}"; do
  [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" == *"install ok installed"* ]] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset release >/dev/null

if [ "$mode" = demo ]; then
  # Only what the demo runs: mhd and the plugins (the tests and benchmarks come with `test`).
  cmake --build --preset release --target mhd-runtime
  exec build/release/tools/mhd/mhd run scenes/dolphin.xml --duration 20 --record build/release/dolphin_run.csv
else
  cmake --build --preset release
  ctest --preset release
  # MHD_SANITIZERS=0 / MHD_FUZZ_SECONDS=0 skip these (for a quick local run).
  if [ "${MHD_SANITIZERS:-1}" != 0 ]; then tools/ci/sanitizers.sh all; fi
  if [ "${MHD_FUZZ_SECONDS:-20}" != 0 ]; then tools/fuzz/run_fuzzers.sh --seconds "${MHD_FUZZ_SECONDS:-20}"; fi
fi
