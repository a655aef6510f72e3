#!/usr/bin/env bash
# Builds the program and the unit tests with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, -O1) into build-asan/ and runs them: any report fails the run. The rendering tests are
# left out (not built here): llvmpipe (OSMesa) is not instrumented, and it JIT-compiles shaders at run time.
set -euo pipefail
cd "$(dirname "$0")/.."
generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
flags="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan "${generator[@]}" -DCMAKE_BUILD_TYPE=None \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DRATTLEBACK_PYTHON=OFF -DRATTLEBACK_STATIC_RUNTIME=OFF >/dev/null
fi
cmake --build build-asan --parallel "$(nproc)" --target rattleback rattleback_tests
# Mesa keeps a few allocations until exit on purpose; those are not ours.
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/lsan.supp:print_suppressions=0"
# intercept_tls_get_addr=0: GCC 12's runtime takes a dynamic TLS block (Mesa's, LLVM's) that
# lands 16 bytes past a page boundary for a pre-2.25 glibc header and records two words of the
# heap as its address and size; LeakSanitizer's tracer then reads them and dies with "Tracer
# caught signal 11" at exit (UsersScenes.TheReadmeExampleRunsAsWritten: 14 of 15 runs here).
# Fixed in LLVM 17; Mudlet/Mudlet#9930 gives the mechanism. The blocks are malloc'd, so what
# they point to is still found through the heap.
export ASAN_OPTIONS="abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# HardCases.OneSimulatedHour is left out here: its 7.2 million steps take ~3 minutes under the
# sanitizers, and the shorter rolling runs go through the same code.
# Only the programs and unit tests are built here: the tests of the install, the package, the
# browser pages, the Python package and the docs run in the main build (scripts/test.sh).
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" \
  -E "OneSimulatedHour|NOT_BUILT|^Install\.|^Report\.|^Python\.|^Docs\."
echo "sanitize: unit tests clean under ASan + UBSan"
