#!/usr/bin/env bash
# The report page in a real browser: a short run of the default scene (both spins, stills,
# plots, analysis, a tiny bench) into a scratch folder, `rattleback report` over it, and the page
# checked in headless Chromium by check_report.py. Usage: report_test.sh RATTLEBACK_BINARY
set -euo pipefail
rb=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$source_dir"
scene=scenes/rattleback.yaml
# 2 s at 25 fps and speed 1: 50 frames, 2.00 s of video.
"$rb" render "$scene" --both --duration 2 --size 320x180 -q -o "$dir/rattleback.mp4"
"$rb" still "$scene" --spin -5 --size 320x180 -q -o "$dir/rattleback-reversed.png"
for view in oblique above; do "$rb" still "$scene" --view "$view" --t 1 --size 320x180 -q -o "$dir/rattleback-$view.png"; done
# 3 s of telemetry: the averaged theory's forecast first reversal (2.12 s) falls within it.
"$rb" simulate "$scene" --duration 3 -o "$dir/rattleback.csv" --plot "$dir" -q
"$rb" analyze "$scene" > "$dir/rattleback-analysis.txt"
"$rb" analyze "$scene" --json > "$dir/rattleback-analysis.json"
"$rb" bench "$scene" --duration 0.5 --rungs 1 --repeats 1 --models rolling --integrators rk4 -q \
  -o "$dir/bench.csv" --plot "$dir/bench.png"
# A scene named with a space and '#': its links must be percent-encoded, or the browser reads
# "my top #1-energy.png" as "my top " and a fragment, and its video, plots, still and player's
# data fail to load (console errors, images that do not decode). 3 s of telemetry as above: the
# player's play-then-pause check on a 2 s run reached its end.
odd="$dir/scenes/my top #1.yaml"
mkdir -p "$dir/scenes" && cp "$scene" "$odd"
"$rb" simulate "$odd" --duration 3 -o "$dir/my top #1.csv" --plot "$dir" -q
"$rb" still "$odd" --t 1 --size 320x180 -q -o "$dir/my top #1-oblique.png"
"$rb" render "$odd" --duration 2 --size 320x180 -q -o "$dir/my top #1.mp4"
# A body drawn as triangles (video.surface: triangles): its player draws them too, where the
# default scene's draws points (check_report.py's surfaces). 3 s, as above: check_player.py
# plays every player on the page for a second from a tenth of its run.
"$rb" simulate scenes/printed.yaml --duration 3 -o "$dir/printed.csv" -q
"$rb" report "$dir" -q
test -s "$dir/index.html"
# Relative paths only: the page must not name the folder it was made in.
if grep -q "$dir" "$dir/index.html"; then echo "FAIL: index.html holds absolute paths"; exit 1; fi
# RATTLEBACK_SCREENSHOTS=DIR keeps the classroom layout's screenshots there, to look at.
/usr/bin/python3 "$source_dir/tests/browser/check_report.py" "$dir" 2.0 ${RATTLEBACK_SCREENSHOTS:+"$RATTLEBACK_SCREENSHOTS"}
# The 3D player of the run simulate left, when the build bundled one (node and npm).
if [ -f "$dir/rattleback-player.js" ]; then
  grep -q 'class="rb-player" data-run="rattleback"' "$dir/index.html" ||
    { echo "FAIL: the page has no player for the scene with telemetry"; exit 1; }
  grep -q 'data-forecast="{' "$dir/index.html" ||
    { echo "FAIL: the player has no data-forecast from the scene's analysis"; exit 1; }
  /usr/bin/python3 "$source_dir/tests/browser/player/check_player.py" "$dir"
else
  echo "note: no player bundle (the build had no node/npm); the player is not checked"
fi
