#!/usr/bin/env bash
# The report's 3D player in a real browser: a dev page with two runs and a missing one
# (make_page.py, the bundle built by player/build.sh), checked in headless Chromium with
# software WebGL by check_player.py.
# Usage: player_test.sh [PYTHON_DIR [BUNDLE]]
#   PYTHON_DIR  the build's python folder (default: <repo>/build/python)
#   BUNDLE      a built rattleback-player.js to use (default: build one with player/build.sh)
# Exit status 0 pass, 1 fail, 77 skipped (no Chromium, chromedriver, Selenium, node or npm).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/../../.." && pwd)
python_dir=${1:-$source_dir/build/python}
bundle=${2:-}
if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then
  echo "chromium or chromedriver is not installed; skipped"; exit 77
fi
if ! /usr/bin/python3 -c "import selenium" 2>/dev/null; then
  echo "selenium is not installed (Debian: python3-selenium); skipped"; exit 77
fi
if [ -z "$bundle" ] && ! { command -v node && command -v npm; } >/dev/null; then
  echo "node or npm is not installed (Debian: nodejs npm); skipped"; exit 77
fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
args=("$dir" --python "$python_dir")
if [ -n "$bundle" ]; then args+=(--bundle "$bundle"); fi
/usr/bin/python3 "$source_dir/tests/browser/player/make_page.py" "${args[@]}"
/usr/bin/python3 "$source_dir/tests/browser/player/check_player.py" "$dir"
