#!/usr/bin/env bash
# Installs a build into a temporary prefix and renders a still with the installed program from
# another folder, RATTLEBACK_ASSETS unset: the program must find its assets beside itself
# (<prefix>/bin → <prefix>/share/rattleback). Then moves the prefix and renders again: the
# install is relocatable. Usage: tests/install_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: install_test.sh BUILD_DIR}" && pwd)
scene=$(cd "$(dirname "$0")/.." && pwd)/scenes/rattleback.yaml
unset RATTLEBACK_ASSETS

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null

# A PNG of 320×180 with floor, body and read-outs is ~10–60 kB; a blank or failed frame is not
# written or is far smaller, hence the 1 kB floor.
render_still() {  # PREFIX: renders from a fresh folder and checks the PNG
  local run
  run=$(mktemp -d "$work/run.XXXX")
  (cd "$run" && "$1/bin/rattleback" still "$scene" -o x.png --size 320x180 -q)
  local size magic
  size=$(stat -c %s "$run/x.png")
  magic=$(head -c 8 "$run/x.png" | od -An -tx1 | tr -d ' \n')
  [ "$magic" = 89504e470d0a1a0a ] || { echo "FAIL: $run/x.png is not a PNG ($magic)"; exit 1; }
  [ "$size" -gt 1024 ] || { echo "FAIL: $run/x.png is only $size bytes"; exit 1; }
  echo "ok: $1/bin/rattleback wrote a $size-byte PNG"
}

for f in bin/rattleback share/rattleback/fonts.txt share/rattleback/shaders/points.vert; do
  [ -e "$work/prefix/$f" ] || { echo "FAIL: the install lacks $f"; exit 1; }
done
render_still "$work/prefix"
mv "$work/prefix" "$work/moved"
render_still "$work/moved"
