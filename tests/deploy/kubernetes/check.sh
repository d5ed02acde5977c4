#!/usr/bin/env bash
# deploy/kubernetes (docs/deploy.md "Kubernetes"): the example overlay renders with
# `kubectl kustomize`, every document matches the Kubernetes API schema of its kind
# (tools/kubernetes-validate, offline), and the topology rules of topology.js hold.
# Usage: check.sh REPO_DIR NODE_MODULES_DIR. Exit 77 (skipped) without kubectl (kustomize >= 4).
set -euo pipefail
repo=$1
modules=$2
if ! command -v kubectl >/dev/null 2>&1; then
  echo "kubectl is missing (Debian package kubernetes-client; deploy/install-deps.sh): skipped"
  exit 77
fi
# The overlay uses labels:, replicas: and inline patches: (kustomize 4 and later; Debian 12's
# kubernetes-client 1.20 embeds kustomize 2).
if ! kubectl version --client 2>/dev/null | grep -q 'Kustomize Version: v[4-9]'; then
  echo "kubectl embeds a kustomize older than v4: skipped"
  exit 77
fi
if [ ! -d "$modules/kubernetes-models" ]; then
  echo "check.sh: $modules/kubernetes-models is missing: build clearsky_kubernetes_validate_tools (npm ci)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
kubectl kustomize "$repo/deploy/kubernetes/overlays/example" > "$work/example.yaml"
echo "rendered: $(grep -c '^kind:' "$work/example.yaml") documents"
NODE_PATH=$modules node "$repo/tools/kubernetes-validate/validate.js" "$work/example.yaml"
NODE_PATH=$modules node "$repo/tests/deploy/kubernetes/topology.js" "$work/example.yaml"
