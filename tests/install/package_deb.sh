#!/usr/bin/env bash
# cpack -G DEB makes the packages of cmake/MhdPackaging.cmake, and each says what it
# needs: mhd's Depends (from dpkg-shlibdeps) name the shared libraries its programs and
# plugins load, its Recommends what its scenes and scripts use; mhd-dev's Depends name
# mhd of the same version and the -dev packages MHDConfig.cmake finds; python3-mhd's
# (given a Python module folder) mhd of the same version and numpy. Their contents sit
# where the installed mhd, and Debian's python3, look.
# Usage: package_deb.sh <cpack> <build dir> <version> <libdir> [<Python module folder under /usr>]
set -euo pipefail
cpack_exe="$1" build="$2" version="$3" libdir="$4" python_dir="${5:-}"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/mhd_package_test.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$cpack_exe" --config "$build/CPackConfig.cmake" -G DEB -B "$scratch" >"$scratch/cpack.log" 2>&1 \
  || { cat "$scratch/cpack.log"; fail "cpack"; }
arch="$(dpkg --print-architecture)"
runtime="$scratch/mhd_${version}_${arch}.deb"
dev="$scratch/mhd-dev_${version}_${arch}.deb"
[ -f "$runtime" ] && [ -f "$dev" ] || { ls "$scratch"; fail "expected mhd_${version}_${arch}.deb and mhd-dev_${version}_${arch}.deb"; }

depends="$(dpkg-deb -f "$runtime" Depends)"
echo "mhd Depends: $depends"
for lib in libc6 libstdc\\+\\+6 libassimp5 libtinyxml2-9 libspdlog1 libfmt9 libbullet; do
  grep -qE "(^|, )$lib" <<<"$depends" || fail "mhd's Depends lacks $lib"
done
# What its scenes and scripts use without linking it: the bunny scenes' mesh
# (glmark2-data) and the installed plot scripts' matplotlib.
recommends="$(dpkg-deb -f "$runtime" Recommends)"
echo "mhd Recommends: $recommends"
for pkg in glmark2-data python3-matplotlib; do
  grep -qE "(^|, )$pkg(,|$)" <<<"$recommends" || fail "mhd's Recommends lacks $pkg"
done
dev_depends="$(dpkg-deb -f "$dev" Depends)"
echo "mhd-dev Depends: $dev_depends"
grep -qF "mhd (= $version)" <<<"$dev_depends" || fail "mhd-dev does not depend on mhd (= $version)"
for pkg in libeigen3-dev libassimp-dev libbullet-dev; do
  grep -qF "$pkg" <<<"$dev_depends" || fail "mhd-dev's Depends lacks $pkg"
done

runtime_files="$(dpkg-deb -c "$runtime")"
dev_files="$(dpkg-deb -c "$dev")"
for f in ./usr/bin/mhd "./usr/$libdir/mhd/plugins-abi6/libmhd_sim_phantom.so" "./usr/$libdir/mhd/libmhd_sim_world.so" \
         ./usr/share/mhd/scenes/scene.xsd \
         ./usr/share/doc/mhd/LICENSE; do
  grep -qF " $f" <<<"$runtime_files" || fail "mhd lacks $f"
done
for f in ./usr/include/mhd/plugin_abi.h "./usr/$libdir/cmake/MHD/MHDConfig.cmake" "./usr/$libdir/pkgconfig/mhd-plugin.pc"; do
  grep -qF " $f" <<<"$dev_files" || fail "mhd-dev lacks $f"
done
if grep -qF "include/mhd" <<<"$runtime_files"; then fail "mhd (runtime) holds headers"; fi

if [ -n "$python_dir" ]; then
  python="$scratch/python3-mhd_${version}_${arch}.deb"
  [ -f "$python" ] || { ls "$scratch"; fail "expected python3-mhd_${version}_${arch}.deb"; }
  python_depends="$(dpkg-deb -f "$python" Depends)"
  echo "python3-mhd Depends: $python_depends"
  for pkg in "mhd (= $version)" python3-numpy; do
    grep -qF "$pkg" <<<"$python_depends" || fail "python3-mhd's Depends lacks $pkg"
  done
  python_files="$(dpkg-deb -c "$python")"
  grep -qF " ./usr/$python_dir/mhd/__init__.py" <<<"$python_files" || fail "python3-mhd lacks $python_dir/mhd/__init__.py"
  grep -qE " \./usr/$python_dir/mhd/_mhd\..*so$" <<<"$python_files" || fail "python3-mhd lacks $python_dir/mhd/_mhd*.so"
  if grep -qF "/mhd/_mhd" <<<"$runtime_files"; then fail "mhd (runtime) holds the Python module"; fi
fi
echo "packages: ok"
