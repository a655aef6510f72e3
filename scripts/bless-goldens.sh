#!/usr/bin/env bash
# Re-blesses the project's golden stills: `rattleback snapshot tests/golden/suite.yaml --update`
# writes each case's golden that differs (or is missing) and leaves the others alone. Look at the
# new images (and `git diff --stat`) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh rattleback
./build/app/rattleback snapshot tests/golden/suite.yaml --update
