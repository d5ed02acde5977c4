#!/usr/bin/env bash
# The clearsky_client package end to end: installs the component clearsky_client of a built
# tree into a temporary prefix (cmake --install), configures tests/clients/cpp/consumer against
# that prefix alone with find_package(clearsky_client), builds it with the C++ example of
# README.md ("Use it from C++", taken as written) and runs the consumer, then the README
# example against a real `clearsky serve` (CLEARSKY_EXE) on a free port: the only change made to
# the example is its address (the README says http://127.0.0.1:8080).
#
#   package_consumer_test.sh BUILD_DIR SOURCE_DIR CXX_COMPILER CLEARSKY_EXE
set -euo pipefail
build=$1
source=$2
compiler=$3
clearsky=$4
work=$(mktemp -d)
server_pid=
cleanup() {
  if [ -n "$server_pid" ]; then kill "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
cmake --install "$build" --component clearsky_client --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/clearsky/client/client.h"
# The README's first ```cpp block.
awk '/^```cpp$/ {inside = 1; next} inside && /^```$/ {exit} inside' "$source/README.md" \
  >"$work/readme_example.cpp"
grep -q 'clearsky::client::Client' "$work/readme_example.cpp"
grep -q 'http://127.0.0.1:8080' "$work/readme_example.cpp"
sed -i "s|http://127.0.0.1:8080|http://127.0.0.1:$port|" "$work/readme_example.cpp"
cmake -S "$source/tests/clients/cpp/consumer" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DREADME_EXAMPLE="$work/readme_example.cpp" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/consumer"

# The README example against a real server: it prints one line per view and exits 0.
"$clearsky" serve --port "$port" --db "$work/db.sqlite" --cache-dir "$work/cache" \
  --models preetham >"$work/serve.log" 2>&1 &
server_pid=$!
for _ in $(seq 600); do
  curl -sf "http://127.0.0.1:$port/readyz" >/dev/null 2>&1 && break
  kill -0 "$server_pid" 2>/dev/null || { cat "$work/serve.log"; exit 1; }
  sleep 0.2
done
"$work/build/readme_example" | tee "$work/readme_example.out"
test "$(grep -c 'W/(m2.sr.nm) at' "$work/readme_example.out")" -eq 2
