#!/usr/bin/env bash
# Installs what is missing, builds Release and starts the server on 127.0.0.1:8080 with its
# SQLite database and table cache under var/. Extra arguments go to `clearsky serve`.
set -euo pipefail
cd "$(dirname "$0")/.."
deploy/install-deps.sh
deploy/build.sh
mkdir -p var/cache
exec build/clearsky serve --host 127.0.0.1 --port 8080 --db var/clearsky.db --cache-dir var/cache "$@"
