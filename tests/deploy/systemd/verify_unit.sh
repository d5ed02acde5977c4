#!/usr/bin/env bash
# deploy/systemd/clearsky.service is a valid unit (docs/deploy.md "systemd"):
# `systemd-analyze verify` says nothing about it (an unknown key is only a warning there, so any
# output fails), its hardening scores an exposure of at most 2.0 (`systemd-analyze security
# --offline`), and the token reaches the server only as a credential file, never on the command
# line. The unit's ExecStart names the installed binary; the copy checked here names the built one.
# Usage: verify_unit.sh UNIT CLEARSKY_EXE. Exit 77 (skipped) without systemd-analyze.
set -euo pipefail
unit=$1
exe=$2
if ! command -v systemd-analyze >/dev/null 2>&1; then
  echo "systemd-analyze is missing (Debian package systemd; deploy/install-deps.sh): skipped"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s|/usr/local/bin/clearsky|$exe|" "$unit" > "$work/clearsky.service"

if grep -E -- '--token[ =]' "$unit"; then
  echo "FAIL: the token is on the command line; use --token-file %d/token"
  exit 1
fi
grep -q -- '--token-file %d/token' "$unit" || { echo "FAIL: no --token-file %d/token"; exit 1; }
grep -q '^LoadCredential=token:' "$unit" || { echo "FAIL: no LoadCredential=token:"; exit 1; }

out=$(cd "$work" && systemd-analyze verify ./clearsky.service 2>&1) || {
  echo "FAIL: systemd-analyze verify:"; echo "$out"; exit 1; }
if [ -n "$out" ]; then
  echo "FAIL: systemd-analyze verify warns:"; echo "$out"; exit 1
fi
echo "systemd-analyze verify: clean"

security=$(cd "$work" && systemd-analyze security --offline=yes ./clearsky.service 2>&1) || true
exposure=$(printf '%s\n' "$security" | sed -n 's/.*Overall exposure level for clearsky.service: \([0-9.]*\).*/\1/p')
echo "systemd-analyze security: exposure ${exposure:-unknown}"
if [ -z "$exposure" ] || awk -v e="$exposure" 'BEGIN { exit !(e > 2.0) }'; then
  printf '%s\n' "$security"
  echo "FAIL: exposure above 2.0"
  exit 1
fi
