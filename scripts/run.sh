#!/usr/bin/env bash
# The main job: set up, build, then write into out/ the default scene's preferred, reversed
# and side-by-side videos and its four still views, the seed body's four still views,
# telemetry, plots and analysis of every shipped scene, the shipped sweeps' tables and heatmaps,
# a bench of the default scene, and the report page out/index.html that shows them all
# (scripts/main-job.sh, which an install carries for an installed program).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh rattleback
bash scripts/main-job.sh out
