#!/usr/bin/env bash
# Installs what is missing, checks the formatting, builds (warnings are errors), and runs the
# whole test suite with CTest, then the unit tests again under AddressSanitizer +
# UndefinedBehaviorSanitizer.
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

# Sanitizer build of the unit tests (no benchmarks, no accuracy tests), kept apart from the
# Release tree; -O1 with line tables keeps it quick to build and its reports readable.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCLEARSKY_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCLEARSKY_BUILD_BENCHMARKS=OFF -DCLEARSKY_BUILD_ACCURACY_TESTS=OFF
cmake --build build-asan -j "$jobs"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j "$jobs" -L unit --timeout 1200)

# The fuzz programs' smoke run (fuzz/run.sh, docs/fuzzing.md), after the suite: a clang build
# of their own (ccache), every committed seed, then 10 s of mutation per program.
if command -v clang++ >/dev/null 2>&1; then
  fuzz/run.sh --smoke
fi
