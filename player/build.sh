#!/usr/bin/env bash
# Bundles the report page's 3D player (src/player.js with three.js) into ONE classic script,
# minified, for pages opened from file:// (no module imports, no fetch, no network at run time).
# Usage: player/build.sh OUT_FILE
# Installs the pinned packages (npm ci, from package-lock.json) only when node_modules is
# missing or was installed from another lock file. Needs node (>= 18) and npm on PATH.
set -euo pipefail
if [ $# -ne 1 ]; then echo "usage: $0 OUT_FILE" >&2; exit 2; fi
out=$1
case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
for tool in node npm; do
  command -v "$tool" >/dev/null || { echo "$0: $tool is not installed (Debian: nodejs npm)" >&2; exit 1; }
done
# node_modules is current when it was installed from this very lock file.
stamp=node_modules/.rattleback-lock.sha256
want=$(sha256sum package-lock.json | cut -d' ' -f1)
if [ ! -x node_modules/.bin/esbuild ] || [ ! -f node_modules/three/package.json ] ||
   [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  npm ci --no-audit --no-fund --loglevel=error
  echo "$want" > "$stamp"
fi
mkdir -p "$(dirname "$out")"
# Written beside the target, then moved into place: a reader never sees half a bundle.
tmp="$out.tmp.$$"
trap 'rm -f "$tmp"' EXIT
node_modules/.bin/esbuild src/player.js --bundle --format=iife --minify --target=es2020 \
  --legal-comments=eof --log-level=warning --outfile="$tmp"
mv "$tmp" "$out"
trap - EXIT
