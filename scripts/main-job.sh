#!/usr/bin/env bash
# The main job's runs, into OUT (default out): the default scene's preferred, reversed and
# side-by-side videos and its four still views, the tap experiment's two videos, the printable
# mesh body's video and still, the seed body's four still views, telemetry,
# plots and analysis of every shipped scene, the shipped sweeps' tables and heatmaps, a bench of
# the default scene, and the report page OUT/index.html that shows them all.
#
# scripts/run.sh runs it after building; an install carries it as
# <prefix>/share/rattleback/main-job.sh, beside the shipped scenes it runs, for the same page
# from an installed program: bash /usr/share/rattleback/main-job.sh out
#
# Usage: bash main-job.sh [OUT]   ($RATTLEBACK names the program to run, when not the one
#                                  beside: build/app/rattleback, or <prefix>/bin/rattleback)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ -f "$here/run.sh" ] && [ -d "$here/../scenes" ]; then
  data="$here/.."                           # the source tree: scripts/ beside scenes/
  beside="$here/../build/app/rattleback"
else
  data="$here"                              # installed: <prefix>/share/rattleback
  beside="$here/../../bin/rattleback"
fi
rb="${RATTLEBACK:-$beside}"
if [ ! -x "$rb" ]; then
  rb="$(command -v rattleback || true)"
  if [ -z "$rb" ]; then
    echo "main-job.sh: no rattleback beside ($beside) nor on PATH; set RATTLEBACK=PROGRAM" >&2
    exit 2
  fi
fi
rb="$(cd "$(dirname "$rb")" && pwd)/$(basename "$rb")"
mkdir -p "${1:-out}"
out="$(cd "${1:-out}" && pwd)"
# The shipped scenes by their names (scenes/…, sweeps/…) from their own folder, never a folder
# of the caller's that happens to hold a scenes/ of its own.
cd "$data"

echo "== videos of scenes/rattleback.yaml (spun both ways)"
"$rb" render scenes/rattleback.yaml --both -o "$out/rattleback.mp4"

echo "== the tap experiment: at rest, tapped on one end and pressed on a side, it spins opposite ways"
for scene in tap-end tap-side; do
  "$rb" render "scenes/$scene.yaml" -o "$out/$scene.mp4" -q
done

echo "== a printable body that reverses both ways: spun 8 rad/s clockwise and counter-clockwise"
"$rb" render scenes/both-ways.yaml --both -o "$out/both-ways.mp4" -q

echo "== a printable rattleback: the default body exported as STL, read back as a mesh body, rolling on its fitted bottom"
"$rb" render scenes/printed.yaml -o "$out/printed.mp4" -q

echo "== stills"
# Posters for the report page: each video's first frame (spun -5 it reverses, +5 it does not,
# as render --both above named them).
"$rb" still scenes/rattleback.yaml --spin -5 -o "$out/rattleback-reversed.png" -q
"$rb" still scenes/rattleback.yaml --spin 5 -o "$out/rattleback-preferred.png" -q
for view in oblique above front side; do
  "$rb" still scenes/rattleback.yaml --view "$view" --t 1.0 -o "$out/rattleback-$view.png" -q
  "$rb" still scenes/seed-flip-ccw.yaml --view "$view" -o "$out/seed-$view.png" -q
done
"$rb" still scenes/printed.yaml --t 0.5 -o "$out/printed-oblique.png" -q

echo "== telemetry and analysis"
# The scenes side by side (the seed's two, with their checks, take most of it); any failure fails
# the job.
pids=()
# Background jobs of a script start with SIGINT ignored (POSIX), and rattleback keeps it so: the
# terminal's Ctrl-C stops this script, which stops them (SIGTERM: each keeps its old output).
trap 'kill -TERM "${pids[@]}" 2>/dev/null; wait; exit 130' INT
for scene in seed-flip-cw seed-flip-ccw rattleback kane-levinson kane-levinson-long tap-end tap-side both-ways printed; do
  (
    "$rb" analyze "scenes/$scene.yaml" -o "$out/$scene-analysis.txt"
    "$rb" analyze "scenes/$scene.yaml" --json -o "$out/$scene-analysis.json"
    "$rb" simulate "scenes/$scene.yaml" -o "$out/$scene.csv" --plot "$out" --check -q
  ) &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done
trap - INT

echo "== sweeps on every core: reversal time against spin and drag, and against the dents"
"$rb" sweep sweeps/spin-drag.yaml -o "$out/spin-drag.csv" --plot "$out/spin-drag.png" -q
"$rb" sweep sweeps/dents.yaml -o "$out/dents.csv" --plot "$out/dents.png" -q

echo "== bench of the default scene (speed against error, 3 s runs)"
"$rb" bench scenes/rattleback.yaml -q -o "$out/bench.csv" --plot "$out/bench.png" --repeats 1 --rungs 4

echo "== the report page"
"$rb" report "$out"

echo
echo "Written to $out/:"
ls -1 "$out" | sed "s|^|  $out/|"
