#!/usr/bin/env bash
# What a user of an installed MHD does, checked end to end (README.md, "Install"):
#   1. cmake --install <build> --prefix <scratch>: the tree holds mhd and the tools, the
#      plugins, scenes with scene.xsd and their meshes, docs, headers, the CMake package
#      and mhd-plugin.pc; the installed mhd names no build-tree RPATH and loads.
#   2. the two out-of-tree examples (examples/out_of_tree_plugins: one C, one C++) are
#      configured with find_package(MHD) against that prefix, built with warnings as
#      errors, and installed into it; the C one is also built with plain cc + pkg-config.
#      A small program (engine_consumer/) links the engine through find_package(MHD).
#   3. the *installed* mhd finds them: `mhd plugins` lists them from its own plugin folder
#      (and never a build tree), and `mhd run` of an installed scene that names them
#      drives both for a second.
# Usage: install_and_plugins.sh <cmake> <build dir> <source dir> <libdir> [<cxx flags> <exe linker flags>]
# The flags are the build's own (a sanitizer's, under tools/ci/sanitizers.sh): a program
# linking the installed static engine must be compiled and linked the way it was.
# The examples are built with Ninja (a package of ours), whose command list shows the flags.
set -euo pipefail
cmake_exe="$1" build="$2" src="$3" libdir="$4" cxx_flags="${5:-}" exe_linker_flags="${6:-}"

scratch="$(mktemp -d "${TMPDIR:-/tmp}/mhd_install_test.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
prefix="$scratch/prefix"
unset MHD_PLUGIN_PATH CMAKE_PREFIX_PATH PKG_CONFIG_PATH
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "---- [${SECONDS} s] $*"; }

step "cmake --install $build --prefix $prefix"
"$cmake_exe" --install "$build" --prefix "$prefix" >"$scratch/install.log" || { cat "$scratch/install.log"; fail "install"; }

plugin_dir="$prefix/$libdir/mhd/plugins-abi6"
for f in bin/mhd bin/mhd-mesh-gen \
         "$libdir/mhd/plugins-abi6/libmhd_sim_phantom.so" "$libdir/mhd/plugins-abi6/libmhd_null_display.so" \
         "$libdir/mhd/libmhd_sim_world.so" \
         share/mhd/scenes/dolphin.xml share/mhd/scenes/scene.xsd share/mhd/scenes/common/materials.xml \
         share/mhd/assets/dolphin.ply share/mhd/plots/force_traces.py \
         share/doc/mhd/README.md share/doc/mhd/LICENSE share/doc/mhd/plugins.md share/doc/mhd/licensing.md \
         include/mhd/plugin_abi.h include/mhd/plugin_params.hpp include/mhd/plugin_sdk.hpp include/mhd/plugin_sdk_params.hpp \
         include/mhd/engine/proxy/god_object.h \
         "$libdir/libmhd_proxy.a" "$libdir/cmake/MHD/MHDConfig.cmake" "$libdir/cmake/MHD/MHDConfigVersion.cmake" \
         "$libdir/cmake/MHD/MhdPlugin.cmake" "$libdir/pkgconfig/mhd-plugin.pc"; do
  [ -f "$prefix/$f" ] || fail "not installed: $f"
done
test_plugins="$(find "$plugin_dir" -name 'libmhd_fi_*' -o -name 'libmhd_good_*' -o -name 'libmhd_bad_*')"
[ -z "$test_plugins" ] || fail "test plugins were installed: $test_plugins"
[ ! -e "$prefix/share/mhd/assets/generated" ] || fail "assets/generated (50 MB of benchmark meshes) was installed"
# The installed program must not reach back into the tree it was built in.
if readelf -d "$prefix/bin/mhd" | grep -E 'R(UN)?PATH' | grep -F "$build"; then fail "bin/mhd has a build-tree RPATH"; fi
if ldd "$prefix/bin/mhd" | grep -F "not found"; then fail "bin/mhd: a shared library is not found"; fi
# The simulated plugins share their world through the installed libmhd_sim_world.so.
# Output is captured before grep reads it: under pipefail, `cmd | grep -q` fails whenever grep's early exit
# kills the writer with SIGPIPE, which depends on timing.
sim_is900_deps="$(ldd "$plugin_dir/libmhd_sim_is900.so")"
grep -qF "$plugin_dir/../libmhd_sim_world.so" <<<"$sim_is900_deps" \
  || fail "libmhd_sim_is900.so does not find the installed libmhd_sim_world.so: $sim_is900_deps"
mhd_version="$("$prefix/bin/mhd" --version)"
grep -q '^mhd ' <<<"$mhd_version" || fail "installed mhd --version: $mhd_version"

for example in c_frame_counter cpp_contact_log; do
  step "out-of-tree $example: configure, build, install against the prefix"
  "$cmake_exe" -S "$src/examples/out_of_tree_plugins/$example" -B "$scratch/$example" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DMHD_WERROR=ON >"$scratch/$example.log" 2>&1 \
    || { cat "$scratch/$example.log"; fail "configure $example"; }
  "$cmake_exe" --build "$scratch/$example" >>"$scratch/$example.log" 2>&1 || { cat "$scratch/$example.log"; fail "build $example"; }
  if grep -q "warning" "$scratch/$example.log"; then cat "$scratch/$example.log"; fail "$example: warnings"; fi
  # MHD's warnings, as errors, per language: C never gets the C++-only -Wnon-virtual-dtor.
  compile="$(cd "$scratch/$example" && ninja -t commands | grep -E -- ' -c [^ ]+\.(c|cpp)$')" || fail "$example: no compile command"
  grep -q -- "-Wconversion" <<<"$compile" && grep -q -- "-Werror" <<<"$compile" || fail "$example: MHD's warnings not on: $compile"
  case "$example" in
    c_*) ! grep -q -- "-Wnon-virtual-dtor" <<<"$compile" || fail "$example: a C++-only flag for C: $compile" ;;
    *) grep -q -- "-Wnon-virtual-dtor" <<<"$compile" || fail "$example: C++ warnings missing: $compile" ;;
  esac
  "$cmake_exe" --install "$scratch/$example" --prefix "$prefix" >>"$scratch/$example.log" \
    || { cat "$scratch/$example.log"; fail "install $example"; }
  [ -f "$plugin_dir/libmhd_$example.so" ] || fail "$example not installed into $plugin_dir"
done

step "a program on the engine's C++ API: find_package(MHD), MHD::scene_xml"
consumer="$scratch/engine_consumer"
# No optimisation: what this checks is the exported link interface, and -O0 compiles fastest.
"$cmake_exe" -S "$src/tests/install/engine_consumer" -B "$consumer" -G Ninja -DCMAKE_BUILD_TYPE= \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$exe_linker_flags" \
  -DCMAKE_PREFIX_PATH="$prefix" >"$consumer.log" 2>&1 || { cat "$consumer.log"; fail "configure engine_consumer"; }
"$cmake_exe" --build "$consumer" >>"$consumer.log" 2>&1 || { cat "$consumer.log"; fail "build engine_consumer"; }
summary="$("$consumer/scene_summary" "$prefix/share/mhd/scenes/dolphin.xml")" || fail "scene_summary: $summary"
[ "$summary" = "dolphin: 2 objects, 3 plugins" ] || fail "scene_summary of the installed dolphin.xml: '$summary'"

step "C plugin built with cc and pkg-config (no CMake)"
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
[ "$(realpath "$(pkg-config --variable=plugindir mhd-plugin)")" = "$(realpath "$plugin_dir")" ] \
  || fail "pkg-config plugindir is $(pkg-config --variable=plugindir mhd-plugin), not $plugin_dir"
mkdir -p "$scratch/pc"
# shellcheck disable=SC2046  # pkg-config's flags are meant to split
cc $(pkg-config --cflags mhd-plugin) -std=c11 -Wall -Wextra -Wpedantic -Werror -shared -fPIC -fvisibility=hidden \
   "$src/examples/out_of_tree_plugins/c_frame_counter/c_frame_counter.c" -o "$scratch/pc/libmhd_c_frame_counter.so"

cd "$scratch"  # nowhere near a source or build tree
step "installed mhd plugins"
plugins_out="$("$prefix/bin/mhd" plugins --plugin-path "$scratch/pc" 2>&1)" || { echo "$plugins_out"; fail "mhd plugins"; }
echo "$plugins_out"
expect() { grep -qE -- "$1" <<<"$plugins_out" || fail "mhd plugins: no line matching: $1"; }
expect "^  $plugin_dir \\(installed\\)\$"
expect "^display +c_frame_counter +1\\.0\\.0 +$scratch/pc/libmhd_c_frame_counter\\.so\$"
expect "^display +c_frame_counter +1\\.0\\.0 +$plugin_dir/libmhd_c_frame_counter\\.so \\(shadowed by an earlier folder\\)\$"
expect "^display +cpp_contact_log +1\\.0\\.0 +$plugin_dir/libmhd_cpp_contact_log\\.so\$"
expect "^device +sim_phantom +.*$plugin_dir/libmhd_sim_phantom\\.so\$"
if grep -q "build tree" <<<"$plugins_out"; then fail "the installed mhd searches a build tree"; fi

step "installed mhd run: an installed scene driving both plugins"
scene="$prefix/share/mhd/scenes/out_of_tree_check.xml"
sed 's|</plugins>|<plugin kind="display" name="c_frame_counter"/><plugin kind="display" name="cpp_contact_log"><param name="min_force_N" value="0.1"/></plugin></plugins>|' \
  "$prefix/share/mhd/scenes/dolphin.xml" >"$scene"
grep -q cpp_contact_log "$scene" || fail "dolphin.xml has no </plugins> to add the example plugins to"
run_out="$("$prefix/bin/mhd" run "$scene" --duration 1 --quiet --no-cache 2>&1)" || { echo "$run_out"; fail "mhd run"; }
grep -E "^(c_frame_counter|cpp_contact_log): " <<<"$run_out"
grep -qE "^c_frame_counter: [1-9][0-9]* frames$" <<<"$run_out" || { echo "$run_out"; fail "c_frame_counter got no frames"; }
grep -qE "^cpp_contact_log: [1-9][0-9]* frames, [0-9]+ contacts, max force [0-9.]+ N$" <<<"$run_out" \
  || { echo "$run_out"; fail "cpp_contact_log got no frames"; }
echo "install and out-of-tree plugins: ok (${SECONDS} s)"
