#!/usr/bin/env bash
# The snapshot report in a real browser: a suite whose scene's tilt then changes by 0.1° and a
# case with no golden, `rattleback snapshot` failing on it (exit 1), and the report checked from
# disk in headless Chromium by check_snapshot_report.py. Usage: snapshot_report_test.sh
# RATTLEBACK_BINARY [SCREENSHOT.png]
set -euo pipefail
rb=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cp "$source_dir/scenes/rattleback.yaml" "$dir/mine.yaml"
cat > "$dir/suite.yaml" <<'SUITE'
size: 320x180
cases:
  - {name: rocking, scene: mine.yaml, t: 1.5, view: above}
SUITE
"$rb" snapshot "$dir/suite.yaml" --update -q
echo "  - {name: brand-new, scene: mine.yaml, view: side}" >> "$dir/suite.yaml"
sed -i 's/tilt: \[0.5, 0.5\]/tilt: [0.6, 0.5]/' "$dir/mine.yaml"
grep -q 'tilt: \[0.6, 0.5\]' "$dir/mine.yaml"
status=0
"$rb" snapshot "$dir/suite.yaml" -q || status=$?
if [ "$status" -ne 1 ]; then echo "FAIL: snapshot exited $status, not 1"; exit 1; fi
page="$dir/snapshot-report/index.html"
test -s "$page"
# From disk: classic markup only, relative images, nothing the file:// origin refuses.
if grep -qE 'type="module"|fetch\(|src="(/|https?:)' "$page"; then
  echo "FAIL: the report uses modules, fetch or absolute images"; exit 1
fi
/usr/bin/python3 "$source_dir/tests/browser/check_snapshot_report.py" "$dir/snapshot-report" \
  rocking brand-new "${2:-}"
