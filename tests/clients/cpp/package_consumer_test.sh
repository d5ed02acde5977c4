#!/usr/bin/env bash
# The clearsky_client package end to end: installs the component clearsky_client of a built
# tree into a temporary prefix (cmake --install), configures tests/clients/cpp/consumer against
# that prefix alone with find_package(clearsky_client), builds it with the C++ example of
# README.md ("Use it from C++", taken as written) and runs the consumer.
#
#   package_consumer_test.sh BUILD_DIR SOURCE_DIR CXX_COMPILER
set -euo pipefail
build=$1
source=$2
compiler=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --component clearsky_client --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/clearsky/client/client.h"
# The README's first ```cpp block.
awk '/^```cpp$/ {inside = 1; next} inside && /^```$/ {exit} inside' "$source/README.md" \
  >"$work/readme_example.cpp"
grep -q 'clearsky::client::Client' "$work/readme_example.cpp"
cmake -S "$source/tests/clients/cpp/consumer" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DREADME_EXAMPLE="$work/readme_example.cpp" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/consumer"
