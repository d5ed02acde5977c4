#!/usr/bin/env bash
# Load test of a running server with wrk (Debian package): 64 connections, 2 threads, 30 s
# each, on /healthz, /v1/radiance for bruneton and hosek (one view, the 40 default
# wavelengths) and a 256-pixel RGB skydome, in one run; prints requests/s and p50/p99 latency
# and the ratio of /v1/radiance to /healthz throughput.
#   tests/bench/load.sh [BASE_URL] [DURATION]   (defaults http://127.0.0.1:8080, 30s)
set -euo pipefail
base=${1:-http://127.0.0.1:8080}
duration=${2:-30s}
query="sun_zenith=40&sun_azimuth=135&view_zenith=50&view_azimuth=200"
declare -A urls=(
  [healthz]="$base/healthz"
  [radiance_bruneton]="$base/v1/radiance?model=bruneton&$query"
  [radiance_hosek]="$base/v1/radiance?model=hosek&$query"
  [skydome256_rgb]="$base/v1/skydome?model=bruneton&sun_zenith=40&sun_azimuth=135&size=256"
)
declare -A rps
printf "%-18s %12s %10s %10s %8s\n" endpoint requests/s p50 p99 errors
for name in healthz radiance_bruneton radiance_hosek skydome256_rgb; do
  url=${urls[$name]}
  code=$(curl -s -o /dev/null -w "%{http_code}" "$url")
  [ "$code" = 200 ] || { echo "$name: HTTP $code for $url" >&2; exit 1; }
  out=$(wrk -t2 -c64 -d"$duration" --latency "$url")
  rps[$name]=$(awk '/Requests\/sec/ {print $2}' <<< "$out")
  p50=$(awk '$1 == "50%" {print $2}' <<< "$out")
  p99=$(awk '$1 == "99%" {print $2}' <<< "$out")
  errors=$(awk '/Non-2xx|Socket errors/ {sub(/^ +/, ""); printf "%s; ", $0}' <<< "$out")
  printf "%-18s %12s %10s %10s %8s\n" "$name" "${rps[$name]}" "$p50" "$p99" "${errors:-0}"
done
for name in radiance_bruneton radiance_hosek; do
  printf "%s / healthz = %.0f%%\n" "$name" "$(echo "100 * ${rps[$name]} / ${rps[healthz]}" | bc -l)"
done
