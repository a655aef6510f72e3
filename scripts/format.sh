#!/usr/bin/env bash
# Formats the C++ sources with clang-format (.clang-format: Google style, 100 columns), or with
# --check says which files drift from it and fails (the test command runs that).
set -euo pipefail
cd "$(dirname "$0")/.."
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find app bench fuzz media python render scene sim tasks tests util \
                          -name '*.cpp' -o -name '*.hpp' | sort)
fi
if [ "${1:-}" = "--check" ]; then
  clang-format --dry-run -Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
