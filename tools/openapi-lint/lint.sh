#!/bin/sh
# Lints the OpenAPI document of the built code with @redocly/cli (docs/openapi.md).
# Usage: lint.sh DUMP_PROGRAM LINT_DIR, where DUMP_PROGRAM prints the document and LINT_DIR
# holds the node_modules that `npm ci` installed from this folder's package-lock.json.
# redocly.yaml extends recommended-strict, so any problem (warning included) fails.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dump=$1
redocly=$2/node_modules/.bin/redocly
if [ ! -x "$redocly" ]; then
  echo "lint.sh: $redocly is missing: build the clearsky_openapi_lint_tools target (npm ci)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$dump" > "$work/openapi.json"
# No telemetry and no update check: the linter works offline.
REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true NO_UPDATE_NOTIFIER=1 \
  "$redocly" lint --config "$here/redocly.yaml" --format=stylish "$work/openapi.json"
