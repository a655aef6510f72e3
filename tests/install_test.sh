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

# The Python package too: imported from the prefix, it finds the same assets from its own folder
# (<prefix>/lib/python3/dist-packages/rattleback → <prefix>/share/rattleback).
python_still() {  # PREFIX
  [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import numpy' 2>/dev/null || return 0
  local run
  run=$(mktemp -d "$work/py.XXXX")
  (cd "$run" && PYTHONPATH="$1/lib/python3/dist-packages" /usr/bin/python3 -c "
import rattleback as rb
image = rb.still('$scene', 1.0, size=(320, 180))
assert image.array.shape == (180, 320, 3), image.array.shape
assert rb.__file__.startswith('$1'), rb.__file__
image.save('x.png')")
  [ "$(stat -c %s "$run/x.png")" -gt 1024 ] || { echo "FAIL: Python's still from $1 is blank"; exit 1; }
  echo "ok: the Python package in $1 drew a still"
}

for f in bin/rattleback share/rattleback/fonts.txt share/rattleback/shaders/points.vert \
         lib/python3/dist-packages/rattleback/__init__.py; do
  [ -e "$work/prefix/$f" ] || { echo "FAIL: the install lacks $f"; exit 1; }
done
# The pages' includes written out (cmake/install_docs.cmake): the script, not the include line.
page="$work/prefix/share/doc/rattleback/your-own-body.md"
! grep -q -- '--8<--' "$page" || { echo "FAIL: $page keeps an include line"; exit 1; }
grep -q '^def with_weight' "$page" || { echo "FAIL: $page lacks weighted_body.py's text"; exit 1; }
render_still "$work/prefix"
python_still "$work/prefix"
# The documentation is installed, and the installed --help names where (it named "docs/ in the
# source", which an installed user does not have).
for f in share/doc/rattleback/getting-started.md share/doc/rattleback/images/rattleback-oblique.png \
         share/doc/rattleback/examples/tour.ipynb; do
  [ -e "$work/prefix/$f" ] || { echo "FAIL: the install lacks $f"; exit 1; }
done
help=$("$work/prefix/bin/rattleback" --help)
grep -q "^Documentation: $work/prefix/share/doc/rattleback/ (getting-started.md first)" <<<"$help" ||
  { echo "FAIL: the installed --help does not name the installed documentation: ${help##*$'\n'}"; exit 1; }
echo "ok: the installed --help names $work/prefix/share/doc/rattleback"
# Its messages cite the installed pages too, not the source's docs/ (a CI maintainer's trial).
printf 'body:\n  shape: ellipsoid\ncontact: {model: rolling}\nsimulation: {duration: 1, dt: 0.001}\n' \
  >"$work/no-mass.yaml"
said=$("$work/prefix/bin/rattleback" simulate "$work/no-mass.yaml" -q -o "$work/no-mass.csv" 2>&1 || true)
grep -qF "($work/prefix/share/doc/rattleback/scenes.md has a complete scene)" <<<"$said" ||
  { echo "FAIL: the installed program's message does not cite the installed docs: $said"; exit 1; }
echo "ok: an installed message cites $work/prefix/share/doc/rattleback/scenes.md"
# The shipped scenes and sweeps are installed, and found by their relative names from any folder
# (plain `bench` and `still scenes/rattleback.yaml` failed outside the source tree).
(cd "$(mktemp -d "$work/elsewhere.XXXX")" &&
  "$work/prefix/bin/rattleback" simulate scenes/rattleback.yaml --duration 0.1 -q -o r.csv &&
  "$work/prefix/bin/rattleback" bench --duration 0.05 --rungs 1 --repeats 1 --models rolling \
    --integrators rk4 -q -o b.csv --plot b.png &&
  test -s r.csv && test -s b.csv) || { echo "FAIL: the installed scenes are not found"; exit 1; }
echo "ok: the installed scenes are found from another folder"
# ... and said to be (a course's deleted scene of the same name would run the shipped one in
# silence).
note=$(cd "$(mktemp -d "$work/elsewhere.XXXX")" &&
  "$work/prefix/bin/rattleback" simulate scenes/rattleback.yaml --duration 0.1 -o r.csv 2>&1 >/dev/null)
[ "$note" = "rattleback: note: no scenes/rattleback.yaml in this folder; running the shipped one, $work/prefix/share/rattleback/scenes/rattleback.yaml (./scenes/rattleback.yaml names this folder's only)" ] ||
  { echo "FAIL: an installed scene run from another folder is not said to be: '$note'"; exit 1; }
echo "ok: a shipped scene run in place of a missing one is said to be"
# ... with -q too, and never for ./ (a CI maintainer's trial: a pipeline's deleted scene of a
# shipped one's name ran the shipped one in silence under -q).
quiet=$(cd "$(mktemp -d "$work/elsewhere.XXXX")" &&
  "$work/prefix/bin/rattleback" simulate scenes/rattleback.yaml --duration 0.1 -q -o r.csv 2>&1 >/dev/null)
[ "$quiet" = "$note" ] || { echo "FAIL: -q hides that the shipped scene ran: '$quiet'"; exit 1; }
status=0
here=$(cd "$(mktemp -d "$work/elsewhere.XXXX")" &&
  "$work/prefix/bin/rattleback" simulate ./scenes/rattleback.yaml --duration 0.1 -q -o r.csv 2>&1) ||
  status=$?
[ "$status" = 2 ] && [ "$here" = "./scenes/rattleback.yaml: cannot open the scene file: No such file or directory" ] ||
  { echo "FAIL: ./scenes/rattleback.yaml ran another folder's scene ($status): '$here'"; exit 1; }
echo "ok: -q says it too, and ./ names this folder's scene only"
# A run of an installed scene names the file it ran in its sidecar, so that report replays it in
# 3D from any folder (a new user's trial: the sidecar named ./scenes/rattleback.yaml, which is
# not there, and the page had no player and said nothing).
if [ -e "$work/prefix/share/rattleback/player/rattleback-player.js" ]; then
  rep=$(mktemp -d "$work/report.XXXX")
  (cd "$rep" &&
    "$work/prefix/bin/rattleback" simulate scenes/rattleback.yaml --duration 0.2 -q -o out/rattleback.csv &&
    "$work/prefix/bin/rattleback" report out -q &&
    test -s out/rattleback.player.js && grep -q 'data-run="rattleback"' out/index.html) ||
    { echo "FAIL: report made no player for an installed scene's run"; exit 1; }
  echo "ok: report replays an installed scene's run from another folder"
  # The page names the installed documentation, not the source's docs/ (a CI maintainer's trial).
  grep -q "<code>$work/prefix/share/doc/rattleback/</code> where rattleback is installed" "$rep/out/index.html" ||
    { echo "FAIL: the installed report's page does not name the installed documentation"; exit 1; }
  echo "ok: the installed report's page names the installed documentation"
fi
# The main job is installed beside the shipped scenes (a CI maintainer's trial: an installed user
# had only scripts/run.sh's name). Run here with a stand-in for the program that records each
# call (the real runs take half a minute; run.sh runs the same script in the source tree), from a
# folder with a scenes/ of its own: each call from the installed scenes' folder, naming scenes
# that are there, each output in OUT, and the page made last.
job=$(mktemp -d "$work/job.XXXX")
mkdir -p "$job/scenes" "$job/bin"
printf '#!/bin/sh\necho "$PWD|$*" >>"%s/calls"\n' "$job" >"$job/bin/rattleback"
chmod +x "$job/bin/rattleback"
(cd "$job" && RATTLEBACK=bin/rattleback bash "$work/prefix/share/rattleback/main-job.sh" made >/dev/null) ||
  { echo "FAIL: the installed main-job.sh failed"; exit 1; }
share="$work/prefix/share/rattleback"
while IFS='|' read -r cwd args; do
  [ "$cwd" = "$share" ] || { echo "FAIL: main-job.sh ran rattleback in $cwd, not $share"; exit 1; }
  for a in $args; do
    case "$a" in
      scenes/*|sweeps/*) [ -f "$share/$a" ] || { echo "FAIL: main-job.sh named $a, not installed"; exit 1; } ;;
      /*) [ "${a#"$job/made"}" != "$a" ] || { echo "FAIL: main-job.sh wrote $a outside OUT"; exit 1; } ;;
    esac
  done
done <"$job/calls"
[ "$(tail -n 1 "$job/calls")" = "$share|report $job/made" ] ||
  { echo "FAIL: main-job.sh did not end with the report: $(tail -n 1 "$job/calls")"; exit 1; }
echo "ok: the installed main-job.sh runs $(wc -l <"$job/calls") commands on the installed scenes into OUT"
mv "$work/prefix" "$work/moved"
render_still "$work/moved"
python_still "$work/moved"
