#!/usr/bin/env bash
# The GNU parallel path of docs/commands.md "rattleback sweep": `sweep --emit parallel --shards 3 | parallel`, then
# `sweep merge`; the merged table must equal the in-process one in every column but wall_s.
# Usage: tests/sweep_parallel_test.sh RATTLEBACK. Exit 77 (skipped) without GNU parallel.
set -euo pipefail
rb=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
command -v parallel >/dev/null 2>&1 || { echo "skipped: GNU parallel missing"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/sweep.yaml" <<YAML
base: $root/scenes/rattleback.yaml
vary:
  initial.spin: {from: -6, to: 6, count: 4}
  body.dents.scale: [0.4, 0.45]
duration: 3.0
YAML
"$rb" sweep "$work/sweep.yaml" --emit parallel --shards 3 -o "$work/t.csv" > "$work/commands"
[ "$(wc -l < "$work/commands")" = 3 ]
parallel --will-cite -j 2 < "$work/commands"
"$rb" sweep merge -q "$work/t.csv" "$work"/t.shard-*-of-3.csv
"$rb" sweep "$work/sweep.yaml" -q -o "$work/in-process.csv"
strip() { sed 's/,[^,]*$//' "$1"; }
diff <(strip "$work/t.csv") <(strip "$work/in-process.csv")
[ "$(wc -l < "$work/t.csv")" = 9 ]
echo "GNU parallel: 3 shards merged equal the in-process table (8 rows)"
