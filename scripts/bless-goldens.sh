#!/usr/bin/env bash
# Re-blesses the snapshot goldens: renders every line of tests/golden/stills.txt into
# tests/golden/NAME.png. Look at the new images (and `git diff --stat`) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh rattleback
# Drawn in a scratch folder and copied, so that the folder's output manifest (which every
# command keeps beside what it writes) stays out of tests/golden.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
grep -v '^#' tests/golden/stills.txt | while read -r name args; do
  [ -n "$name" ] || continue
  # shellcheck disable=SC2086
  ./build/app/rattleback still $args -o "$scratch/$name.png" -q
  cp "$scratch/$name.png" "tests/golden/$name.png"
  echo "blessed tests/golden/$name.png"
done
