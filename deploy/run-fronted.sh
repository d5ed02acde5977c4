#!/usr/bin/env bash
# The fronted deployment (docs/deployment.md "Fronted by HAProxy"): installs what is missing,
# builds Release, starts `clearsky serve` on CLEARSKY_BACKEND (default 127.0.0.1:8081) and
# HAProxy with deploy/haproxy/clearsky.cfg on CLEARSKY_FRONT (default 0.0.0.0:8080), both in
# the foreground; either ending stops the other. Extra arguments go to `clearsky serve`.
set -euo pipefail
cd "$(dirname "$0")/.."
deploy/install-deps.sh
deploy/build.sh
mkdir -p var/cache
export CLEARSKY_FRONT=${CLEARSKY_FRONT:-0.0.0.0:8080}
export CLEARSKY_BACKEND=${CLEARSKY_BACKEND:-127.0.0.1:8081}
export CLEARSKY_MAXCONN=${CLEARSKY_MAXCONN:-8000}
# HAProxy needs about two descriptors per client connection (client and server side).
ulimit -n "$(( $(ulimit -Hn) < 2 * CLEARSKY_MAXCONN + 256 ? $(ulimit -Hn) : 2 * CLEARSKY_MAXCONN + 256 ))"
build/clearsky serve --host "${CLEARSKY_BACKEND%:*}" --port "${CLEARSKY_BACKEND##*:}" \
  --db var/clearsky.db --cache-dir var/cache "$@" &
server=$!
haproxy -db -f deploy/haproxy/clearsky.cfg &
proxy=$!
trap 'kill "$server" "$proxy" 2>/dev/null || true; wait' EXIT INT TERM
wait -n "$server" "$proxy"
