#!/usr/bin/env bash
# Time to first byte, total time, bytes and peak server memory of GET /v1/skydome for 512,
# 2048 and 4096 pixel fisheye images, RGB (half) and spectral (float), against a running
# server: tests/bench/skydome_figures.sh [BASE_URL] [MODEL] [SERVER_PID].
# Peak memory is the server's resident set sampled every 20 ms during the request, minus its
# resident set before it (tables excluded). The first (512) RGB image is also checked with
# OpenEXR's exrheader.
set -euo pipefail
base=${1:-http://127.0.0.1:8080}
model=${2:-bruneton}
pid=${3:-$(pgrep -f "clearsky serve" | head -1)}
sun="sun_zenith=40&sun_azimuth=135"

rss_kb() { awk '/VmRSS/ {print $2}' "/proc/$pid/status"; }

printf "%-9s %-5s %12s %10s %14s %16s\n" channels size ttfb_s total_s bytes peak_extra_MiB
for channels in rgb spectral; do
  for size in 512 2048 4096; do
    before=$(rss_kb)
    peak_file=$(mktemp)
    echo "$before" > "$peak_file"
    ( while kill -0 "$pid" 2>/dev/null; do rss_kb >> "$peak_file"; sleep 0.02; done ) &
    sampler=$!
    url="$base/v1/skydome?model=$model&$sun&projection=fisheye&size=$size&channels=$channels"
    if [ "$channels$size" = rgb512 ]; then
      out=$(mktemp --suffix=.exr)
      timing=$(curl -sS -o "$out" -w "%{http_code} %{time_starttransfer} %{time_total} %{size_download}" "$url")
      exrheader "$out" | grep -E "channels|compression|dataWindow" -A0 >&2 || true
      rm -f "$out"
    else
      timing=$(curl -sS -o /dev/null -w "%{http_code} %{time_starttransfer} %{time_total} %{size_download}" "$url")
    fi
    kill "$sampler" 2>/dev/null || true
    wait "$sampler" 2>/dev/null || true
    peak=$(sort -n "$peak_file" | tail -1)
    rm -f "$peak_file"
    read -r code ttfb total bytes <<< "$timing"
    [ "$code" = 200 ] || { echo "HTTP $code for $url" >&2; exit 1; }
    printf "%-9s %-5s %12s %10s %14s %16.1f\n" "$channels" "$size" "$ttfb" "$total" "$bytes" \
      "$(echo "($peak - $before) / 1024" | bc -l)"
  done
done
