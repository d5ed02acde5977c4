#!/usr/bin/env bash
# The starvation findings at full size (docs/deployment.md "Measuring starvation"), against a
# clearsky executable served bare and behind HAProxy (deploy/haproxy/clearsky.cfg):
#   70 slowloris connections (a header line every 2 s) for 50 s,
#   70 slow readers of a 4096 spectral skydome (4 bytes/s each) for 30 s,
#   200 idle keep-alive connections for 30 s,
#   wrk -t2 with 1,000 and with 4,000 connections on /v1/radiance for 20 s,
# each while /healthz is probed on a new connection every second (answered = 200 within 1 s).
# Prints probes answered/total and their latency per attack and setup. Takes about 6 minutes
# per executable; needs python3, wrk and haproxy (deploy/install-deps.sh).
# Usage: tools/hostile/starvation.sh CLEARSKY_EXE [bare|fronted|both=both]
set -euo pipefail
exe=$(realpath "$1")
setups=${2:-both}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
hostile="$here/hostile_clients.py"
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
ulimit -n "$(ulimit -Hn)"

wait_healthz() {
  for _ in $(seq 150); do curl -sf "http://127.0.0.1:$1/healthz" >/dev/null 2>&1 && return; sleep 0.2; done
  echo "nothing answers on port $1" >&2
  exit 1
}

# Starts clearsky on port $1 (preetham and hosek, as in the findings).
start_server() {
  "$exe" serve --host 127.0.0.1 --port "$1" --db "$work/db-$1.sqlite" --cache-dir "$work/cache" \
    --models preetham,hosek --prebuild-three false >"$work/serve-$1.log" 2>&1 &
  pids+=($!)
  wait_healthz "$1"
}

attacks() {  # port label
  local port=$1 label=$2
  echo "== $label (port $port)"
  python3 "$hostile" --port "$port" --attack slowloris --connections 70 --line-interval 2 --duration 50 --after 5
  python3 "$hostile" --port "$port" --attack slow-readers --connections 70 --duration 30 --after 5
  python3 "$hostile" --port "$port" --attack idle --connections 200 --duration 30 --after 5
  python3 "$hostile" --port "$port" --attack wrk --connections 1000 --duration 20 --after 5
  python3 "$hostile" --port "$port" --attack wrk --connections 4000 --duration 20 --after 5
}

echo "clearsky: $exe"
if [ "$setups" = bare ] || [ "$setups" = both ]; then
  start_server 18501
  attacks 18501 "bare server"
fi
if [ "$setups" = fronted ] || [ "$setups" = both ]; then
  start_server 18502
  CLEARSKY_FRONT=127.0.0.1:18503 CLEARSKY_BACKEND=127.0.0.1:18502 CLEARSKY_MAXCONN=9000 \
    haproxy -db -f "$repo/deploy/haproxy/clearsky.cfg" 2>"$work/haproxy.log" &
  pids+=($!)
  wait_healthz 18503
  attacks 18503 "fronted by HAProxy"
fi
