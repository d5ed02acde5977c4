#!/usr/bin/env bash
# The scale-out benchmark (docs/deploy.md "Scale-out on one host"): a writer and N query
# replicas behind HAProxy on loopback; throughput and memory for N = 1, 2, 3, then one replica
# killed and a rolling restart under load, counting failed requests. Not part of the test suite
# (minutes, and it loads the machine); CTest ScaleOutSmoke runs `--smoke`.
# Usage: deploy/scale_out.sh [CLEARSKY_EXE] [scale_out.py options, e.g. --replicas 1,2,3 --json]
set -euo pipefail
cd "$(dirname "$0")/.."
exe=build/clearsky
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then exe=$1; shift; fi
exec python3 tools/scale_out/scale_out.py --binary "$exe" "$@"
