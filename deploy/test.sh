#!/usr/bin/env bash
# Installs what is missing, checks the formatting, builds (warnings are errors), and runs the
# whole test suite with CTest, then the unit tests again under AddressSanitizer +
# UndefinedBehaviorSanitizer (clang) and the fuzz programs' smoke run in that same build.
set -euo pipefail
cd "$(dirname "$0")/.."
deploy/install-deps.sh

# Every tracked C++ source as clang-format (the repo's .clang-format) writes it; a file that
# differs fails the run before any build time is spent. Fix with: clang-format -i FILE
git ls-files -z '*.cpp' '*.h' | xargs -0 clang-format --dry-run --Werror

if [ "${CI:-}" = "true" ] && [ ! -d ../shared/data/kider2014 ]; then
  echo "test.sh: CI=true and ../shared/data/kider2014 is missing" >&2
  exit 1
fi

jobs=$(nproc)
deploy/build.sh
(cd build && ctest --output-on-failure -j "$jobs" --timeout 1200)

# The sanitizer run: one clang tree (fuzz/run.sh configures it; ccache when present) with
# AddressSanitizer + UndefinedBehaviorSanitizer (and libFuzzer's coverage hooks) builds the
# unit tests and the fuzz programs (docs/fuzzing.md): the unit tests run there, then the fuzz
# programs' smoke run (every committed seed, then a fixed number of mutations from a fixed
# seed). -O1 with line tables keeps it quick to build and its reports readable. A second
# compiler also checks the code: the Release build above is GCC's.
export CLEARSKY_FUZZ_BUILD_DIR=build-asan
fuzz/run.sh --build
cmake --build build-asan -j "$jobs"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j "$jobs" -L unit --timeout 1200)
fuzz/run.sh --smoke
