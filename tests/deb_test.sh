#!/usr/bin/env bash
# Builds the Debian package of a build with CPack into a temporary folder and checks its
# control fields and contents. Exit 77 (CTest: skipped) without dpkg-shlibdeps (dpkg-dev).
# Usage: tests/deb_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: deb_test.sh BUILD_DIR}" && pwd)
command -v dpkg-shlibdeps >/dev/null || { echo "skip: no dpkg-shlibdeps (install dpkg-dev)"; exit 77; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/rattleback_*.deb)

depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
# libhdf5-103-1 is named by hand: the program opens it when it writes a .h5, and links it not
# (nor the thirty-odd libraries it needs), so dpkg-shlibdeps cannot see it.
if ldd "$build/app/rattleback" | grep -q hdf5; then echo "FAIL: rattleback links HDF5"; exit 1; fi
for needed in libegl1 libegl-mesa0 libavcodec fonts-dejavu-core libhdf5-103-1; do
  grep -q "$needed" <<<"$depends" || { echo "FAIL: Depends lacks $needed"; exit 1; }
done
# OSMesa is opened at run time (the second backend): recommended, not required.
grep -q libosmesa6 <<<"$(dpkg-deb -f "$deb" Recommends)" || { echo "FAIL: Recommends lacks libosmesa6"; exit 1; }
# The Python package needs NumPy (and Debian's python3 it is built for).
grep -q python3-numpy <<<"$(dpkg-deb -f "$deb" Recommends)" || { echo "FAIL: Recommends lacks python3-numpy"; exit 1; }
grep -q "_core.cpython" <<<"$(dpkg-deb -c "$deb")" || { echo "FAIL: the package lacks the Python module"; exit 1; }
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/rattleback ./usr/libexec/rattleback-render ./usr/share/rattleback/fonts.txt ./usr/share/rattleback/shaders/points.frag \
         ./usr/lib/python3/dist-packages/rattleback/__init__.py ./usr/share/rattleback/scenes/rattleback.yaml \
         ./usr/share/rattleback/sweeps/spin-drag.yaml ./usr/share/doc/rattleback/getting-started.md; do
  grep -q " $f\$" <<<"$contents" || { echo "FAIL: the package lacks $f"; exit 1; }
done
echo "ok: $(basename "$deb"), $(stat -c %s "$deb") bytes"
