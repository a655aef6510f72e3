#!/usr/bin/env bash
# Fuzzes the scene loader and compile(), then the snapshot suite reader and the mesh reader, with
# libFuzzer (clang, ASan + UBSan) for a bounded time each (each reader a third of it, at least
# 10 s), starting from the corpora in tests/fuzz-corpus, tests/fuzz-corpus-snapshot and
# tests/fuzz-corpus-mesh (copied: the run adds inputs to a scratch corpus, never to the
# repository). Usage: scripts/fuzz.sh [seconds, default 60]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  cmake -S . -B build-fuzz "${generator[@]}" -DRATTLEBACK_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ >/dev/null
fi
cmake --build build-fuzz --parallel "$(nproc)" --target loader_fuzz snapshot_fuzz mesh_fuzz

# fuzz TARGET CORPUS SECONDS [libFuzzer options…]
fuzz() {
  local target=$1 source=$2 time=$3
  shift 3
  local corpus
  corpus=$(mktemp -d)
  cp "$source"/* "$corpus"/
  # -timeout: one input taking longer than 10 s is a hang and fails the run, as a crash does.
  set +e
  "./build-fuzz/fuzz/$target" "$corpus" "$@" -max_total_time="$time" -timeout=10 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$corpus/" 2>&1 | tail -n 25
  local status=${PIPESTATUS[0]}
  set -e
  if [ "$status" -ne 0 ]; then
    echo "fuzz: $target FAILED (status $status); the input that failed:" >&2
    ls "$corpus"/crash-* "$corpus"/timeout-* "$corpus"/oom-* 2>/dev/null | head -3 | while read -r f; do
      echo "--- $f" >&2; head -c 2000 "$f" >&2; echo >&2
      mkdir -p fuzz-failures && cp "$f" fuzz-failures/
    done
    rm -rf "$corpus"
    exit 1
  fi
  rm -rf "$corpus"
  echo "fuzz: $target ${time} s, no crashes"
}

fuzz loader_fuzz tests/fuzz-corpus "$seconds" -dict=fuzz/scene.dict
fuzz snapshot_fuzz tests/fuzz-corpus-snapshot "$(( seconds / 3 > 10 ? seconds / 3 : 10 ))"
fuzz mesh_fuzz tests/fuzz-corpus-mesh "$(( seconds / 3 > 10 ? seconds / 3 : 10 ))"
