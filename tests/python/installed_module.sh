#!/usr/bin/env bash
# The Python module as `cmake --install` puts it: the python component alone, installed
# into a scratch prefix, is what Debian's python3 imports with PYTHONPATH at
# <prefix>/<module dir>, and it judges scenes as `mhd validate` does: a good one passes,
# one with typos is refused.
# Usage: installed_module.sh <cmake> <build dir> <module dir, relative to the prefix> <python3> <plugin dir>
#        <good scene> <bad scene>
set -euo pipefail
cmake_exe="$1" build="$2" module_dir="$3" python="$4" plugin_dir="$5" good="$6" bad="$7"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/mhd_python_install.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

prefix="$scratch/prefix"
"$cmake_exe" --install "$build" --prefix "$prefix" --component python >"$scratch/install.log" \
  || { cat "$scratch/install.log"; fail "cmake --install --component python"; }
installed="$(cd "$prefix" && find . -type f | sort)"
echo "$installed"
grep -qx "./$module_dir/mhd/__init__.py" <<<"$installed" || fail "no $module_dir/mhd/__init__.py"
grep -qE "^\./$module_dir/mhd/_mhd\..*so$" <<<"$installed" || fail "no $module_dir/mhd/_mhd*.so"
[ "$(wc -l <<<"$installed")" -eq 2 ] || fail "the python component holds more than the module"

cd "$scratch"  # nowhere near the build tree's module
out="$(PYTHONPATH="$prefix/$module_dir" MHD_PLUGIN_PATH="$plugin_dir" LD_PRELOAD="${MHD_PYTHON_PRELOAD:-}" \
  "$python" -c '
import sys
import mhd
print(mhd.__file__)
print(len(mhd.validate(sys.argv[1])), len(mhd.validate(sys.argv[2])))
' "$good" "$bad" 2>&1)" || { echo "$out"; fail "import mhd from the prefix"; }
echo "$out"
[ "$(head -1 <<<"$out")" = "$prefix/$module_dir/mhd/__init__.py" ] || fail "mhd was imported from elsewhere"
read -r good_problems bad_problems <<<"$(tail -1 <<<"$out")"
[ "$good_problems" = 0 ] || fail "mhd.validate refused $good"
[ "$bad_problems" -gt 0 ] || fail "mhd.validate passed $bad"
echo "installed module: ok"
