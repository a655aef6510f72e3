#!/usr/bin/env bash
# Fuzzes the scene loader and compile() with libFuzzer (clang, ASan + UBSan) for a bounded
# time, starting from the corpus in tests/fuzz-corpus (copied: the run adds inputs to a scratch
# corpus, never to the repository). Usage: scripts/fuzz.sh [seconds, default 60]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  cmake -S . -B build-fuzz "${generator[@]}" -DRATTLEBACK_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ >/dev/null
fi
cmake --build build-fuzz --parallel "$(nproc)" --target loader_fuzz
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp tests/fuzz-corpus/* "$corpus"/
# -timeout: one input taking longer than 10 s is a hang and fails the run, as a crash does.
./build-fuzz/fuzz/loader_fuzz "$corpus" -dict=fuzz/scene.dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="$corpus/" 2>&1 | tail -n 25
status=${PIPESTATUS[0]}
if [ "$status" -ne 0 ]; then
  echo "fuzz: FAILED (status $status); the input that failed:" >&2
  ls "$corpus"/crash-* "$corpus"/timeout-* "$corpus"/oom-* 2>/dev/null | head -3 | while read -r f; do
    echo "--- $f" >&2; head -c 2000 "$f" >&2; echo >&2
    mkdir -p fuzz-failures && cp "$f" fuzz-failures/
  done
  exit 1
fi
echo "fuzz: ${seconds} s, no crashes"
