#!/usr/bin/env bash
# make web: the browser build into build-web/site/ (index.html, index.js, index.wasm and
# index.data, the lessons and fonts preloaded into the page's file system). See docs/web.md.
# CG_BUILD_LOCK=FILE: compile while holding that lock (flock), on a machine shared with others.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-web-deps.sh
source scripts/web-env.sh
if [[ ! -f build-web/cmake/build.ninja ]]; then
  emcmake cmake -S sandbox/web -B build-web/cmake -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
"${build_lock[@]}" cmake --build build-web/cmake
