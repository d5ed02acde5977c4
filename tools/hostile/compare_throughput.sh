#!/usr/bin/env bash
# Throughput of two clearsky executables, interleaved so that the load of a shared machine hits
# both alike (docs/deployment.md "Measured"): each serves --models preetham,hosek on its own
# port; wrk -t2 -c32 -d8s runs on /v1/radiance and /healthz against one, then the other, ROUNDS
# times. Prints requests/s per run and the mean of each.
# Usage: tools/hostile/compare_throughput.sh BEFORE_EXE AFTER_EXE [ROUNDS=3]
set -euo pipefail
before=$1 after=$2 rounds=${3:-3}
work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

start() {  # name exe port
  mkdir -p "$work/$1"
  "$2" serve --host 127.0.0.1 --port "$3" --db "$work/$1/db.sqlite" --cache-dir "$work/$1/cache" \
    --models preetham,hosek --prebuild-three false >"$work/$1/serve.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do curl -sf "http://127.0.0.1:$3/readyz" >/dev/null 2>&1 && return; sleep 0.2; done
  echo "$1 did not start" >&2; exit 1
}
start before "$before" 18401
start after "$after" 18402

radiance='/v1/radiance?model=preetham&sun_zenith=30&sun_azimuth=0&view_zenith=45&view_azimuth=90'
declare -A sum
for round in $(seq "$rounds"); do
  for path in "$radiance" /healthz; do
    for name in before after; do
      port=18401; [ "$name" = after ] && port=18402
      rps=$(wrk -t2 -c32 -d8s "http://127.0.0.1:$port$path" | awk '/Requests\/sec/ {print $2}')
      key="$name ${path%%\?*}"
      sum[$key]=$(awk -v a="${sum[$key]:-0}" -v b="$rps" 'BEGIN {print a + b}')
      echo "round $round  $key  $rps req/s"
    done
  done
done
for path in /v1/radiance /healthz; do
  b=$(awk -v s="${sum[before $path]}" -v n="$rounds" 'BEGIN {printf "%.0f", s / n}')
  a=$(awk -v s="${sum[after $path]}" -v n="$rounds" 'BEGIN {printf "%.0f", s / n}')
  echo "mean $path: before $b req/s, after $a req/s ($(awk -v a="$a" -v b="$b" 'BEGIN {printf "%+.1f%%", 100 * (a - b) / b}'))"
done
