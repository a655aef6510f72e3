#!/usr/bin/env bash
# Sets up, builds from nothing if needed, and runs every test (CTest + GoogleTest), then the
# sanitizer build's unit tests and a bounded fuzzing run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure --timeout 600 -j "$(nproc)"
# QUICK=1 stops here; the full run (CI) also runs the unit tests under ASan + UBSan and
# fuzzes the scene loader for 30 s.
if [ "${QUICK:-0}" != 1 ]; then
  bash scripts/sanitize.sh
  bash scripts/fuzz.sh 30
fi
