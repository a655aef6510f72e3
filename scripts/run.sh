#!/usr/bin/env bash
# The main job: set up, build, and simulate the default scenes into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh rattleback
mkdir -p out
for scene in rattleback seed-preferred seed-reversed; do
  echo "== $scene"
  ./build/app/rattleback analyze "scenes/$scene.yaml" > "out/$scene-analysis.txt"
  ./build/app/rattleback simulate "scenes/$scene.yaml" -o "out/$scene.csv"
done
echo
echo "Written to out/:"
ls -1 out | sed 's/^/  out\//'
