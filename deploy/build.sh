#!/usr/bin/env bash
# Configures and builds clearsky (Release) into build/. Used by run.sh and test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
# ccache, when present (deploy/install-deps.sh installs it), shares objects between clones and
# build folders: paths relative to the root, the folder not hashed, and the precompiled
# header's defines and timestamps not compared (the header itself is).
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@"
cmake --build build -j "$jobs"
# The browser viewer (docs/viewer.md): its npm packages as package-lock.json pins them (npm ci,
# again only when the lock file changed), bundled into build/viewer, which `clearsky serve`
# serves at / by default.
if command -v npm >/dev/null 2>&1; then
  if [ ! -f viewer/node_modules/.package-lock.json ] ||
     [ viewer/package-lock.json -nt viewer/node_modules/.package-lock.json ]; then
    (cd viewer && npm ci --no-audit --no-fund)
  fi
  node viewer/build.mjs build/viewer
else
  echo "build.sh: npm is missing, no browser viewer (deploy/install-deps.sh installs node and npm)"
fi
