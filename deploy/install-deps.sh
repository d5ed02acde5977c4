#!/usr/bin/env bash
# Installs the Debian 12 packages clearsky builds, tests and runs with, when any is missing.
# Idempotent: does nothing (and needs no network) when everything is present.
# --build-only: only what building the clearsky executable needs (-DCLEARSKY_BUILD_TESTS=OFF: the
# container image's build stage, deploy/container/Containerfile), not the test, benchmark and
# deployment tools.
set -euo pipefail

build_only=false
[ "${1:-}" = "--build-only" ] && build_only=true

# Compiling and linking the executable.
build_packages=(
  build-essential cmake pkg-config
  libcpp-httplib-dev libssl-dev zlib1g-dev nlohmann-json3-dev
  libopenexr-dev libpng-dev libgeographiclib-dev
  libsqlite3-dev libarchive-dev libxxhash-dev
  prometheus-cpp-dev libspdlog-dev libfmt-dev libcli11-dev libnlopt-cxx-dev
  libhowardhinnant-date-dev tzdata
)
packages=(
  "${build_packages[@]}"
  libgtest-dev libgmock-dev libbenchmark-dev
  git clang-format openexr sqlite3 p7zip-full
  wrk curl python3 haproxy
  # systemd-analyze checks deploy/systemd/clearsky.service; graphviz renders the topology of
  # docs/deploy.md (docs/figures/deploy-topology.dot).
  systemd graphviz
  python3-jsonschema
  # The Python client (clients/python, docs/clients.md): numpy for its arrays, OpenImageIO's
  # Python bindings for decoding skydome images in its tests.
  python3-numpy python3-openimageio
  # The broadband irradiance against the pyranometer (docs/building-energy.md) is plotted by
  # tools/broadband/pyranometer_validation.py.
  # The run-time-vs-error plots of docs/performance.md (tools/atlas/plot_atlas.py).
  python3-matplotlib
  # The browser viewer's test (docs/viewer.md) drives Debian's chromium headless.
  chromium
  # The fuzz programs (fuzz/run.sh, docs/fuzzing.md): clang 14 with its sanitizer and libFuzzer
  # runtimes; ccache keeps their rebuilds short.
  clang libclang-rt-14-dev ccache
  # Blender renders a scene lit by a served skydome (docs/renderers.md, CTest BlenderSunShadow).
  blender
)
# kubectl renders deploy/kubernetes (`kubectl kustomize`, CTest KubernetesManifests): Debian's
# kubernetes-client, unless the machine already has a kubectl.
if ! command -v kubectl >/dev/null 2>&1; then
  packages+=(kubernetes-client)
fi
# The OpenAPI linter (docs/openapi.md) runs on node and npm: Debian's, unless the machine
# already has a node with its npm (another distribution's nodejs package ships both).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

if [ "$build_only" = true ]; then
  packages=("${build_packages[@]}")
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi
