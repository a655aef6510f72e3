#!/usr/bin/env bash
# Builds the documentation site (MkDocs, mkdocs.yml) into site/, strictly: a broken link or a
# page missing from the nav fails. Open site/index.html, or `mkdocs serve` to read it live.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v mkdocs >/dev/null || { echo "docs.sh: mkdocs is missing (bash scripts/setup.sh installs it)" >&2; exit 2; }
mkdocs build --strict -q -d site
echo "docs.sh: wrote site/index.html"
