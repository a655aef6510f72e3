#!/usr/bin/env bash
# Re-blesses the snapshot goldens: renders every line of tests/golden/stills.txt into
# tests/golden/NAME.png. Look at the new images (and `git diff --stat`) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh rattleback
grep -v '^#' tests/golden/stills.txt | while read -r name args; do
  [ -n "$name" ] || continue
  # shellcheck disable=SC2086
  ./build/app/rattleback still $args -o "tests/golden/$name.png" -q
  echo "blessed tests/golden/$name.png"
done
