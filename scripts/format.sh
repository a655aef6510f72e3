#!/usr/bin/env bash
# Formats the sources, each language by its formatter, or with --check says which files drift
# and fails (the test Style.SourcesAreFormatted runs that):
#   C++    (*.cpp, *.hpp)  clang-format (Debian's), .clang-format: Google style, 100 columns;
#   JS     (*.js)          prettier, pinned in player/package.json and installed by `npm ci` in
#                          player/ (the build does it), .prettierrc: 110 columns, single quotes;
#   Python (*.py)          black (Debian's), [tool.black] in pyproject.toml: 110 columns.
# A formatter that is missing is an error, not a skip: a check that checked nothing would pass.
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [ "${1:-}" = "--check" ]; then check=1; fi

# Ours only: what git tracks (never node_modules, nor a bundle, which the build writes).
list() {
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files "$@"
  else
    local names=()
    for pattern in "$@"; do names+=(-o -name "$pattern"); done
    find . \( -name node_modules -o -name 'build*' -o -name .git \) -prune \
      -o \( -false "${names[@]}" \) -print | sed 's|^\./||' | sort
  fi
}
mapfile -t cpp < <(list '*.cpp' '*.hpp')
mapfile -t js < <(list '*.js')
mapfile -t py < <(list '*.py')

prettier=player/node_modules/.bin/prettier
missing=()
command -v clang-format >/dev/null || missing+=("clang-format (Debian: clang-format; scripts/setup.sh)")
[ -x "$prettier" ] || missing+=("prettier (run \`npm ci\` in player/, or build: scripts/build.sh)")
command -v black >/dev/null || missing+=("black (Debian: black; scripts/setup.sh)")
if [ ${#missing[@]} -gt 0 ]; then
  for m in "${missing[@]}"; do echo "format.sh: not installed: $m" >&2; done
  exit 1
fi

if [ $check = 0 ]; then
  clang-format -i "${cpp[@]}"
  "$prettier" --log-level warn --write "${js[@]}"
  black --quiet --config pyproject.toml "${py[@]}"
  exit 0
fi
# Every language checked, each drifting file named, before the verdict.
status=0
clang-format --dry-run -Werror "${cpp[@]}" || status=1
"$prettier" --log-level warn --check "${js[@]}" || status=1
black --check --config pyproject.toml "${py[@]}" || status=1
if [ $status != 0 ]; then
  echo "format.sh: sources drift from their formatters (above); \`bash scripts/format.sh\` formats them" >&2
fi
exit $status
