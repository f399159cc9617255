#!/usr/bin/env bash
# Installs what the browser build needs (make web, make test-web), once; quick and silent after.
#   1. Debian packages: emscripten (C++ → WebAssembly, offline), node-acorn (emcc's JS tools),
#      chromium + chromium-driver + python3-selenium + python3-pil (the browser test, headless).
#   2. The sources of SDL2 2.26.5 and Dear ImGui 1.86 from Debian's own source packages, into
#      build-web/deps/: libimgui-dev has no core sources, and emscripten's `-sUSE_SDL=2` port
#      downloads at build time. apt-get source reads a private deb-src list under build-web/deps/
#      apt/ (mirroring the system's Debian entry): the system's apt configuration is not touched.
#   3. SDL2 built for wasm with emcmake (static), installed into build-web/deps/sdl2/.
# Measured on the 2-core build machine: packages 34 s, sources 2 s, SDL2 about a minute.
set -euo pipefail
cd "$(dirname "$0")/.."
deps=$PWD/build-web/deps
source "$(dirname "$0")/web-env.sh"

# --- 1. packages ---------------------------------------------------------------------------
"$(dirname "$0")/install-deps.sh" emscripten node-acorn chromium chromium-driver python3-selenium \
  python3-pil cmake ninja-build libglm-dev nlohmann-json3-dev libstb-dev libtinyobjloader-dev \
  fonts-dejavu-core

# --- 2. sources --------------------------------------------------------------------------------
if [[ ! -f $deps/src/SDL2-2.26.5/CMakeLists.txt || ! -f $deps/src/imgui-1.86/imgui.cpp ]]; then
  echo "Fetching the SDL2 and Dear ImGui sources (Debian source packages) into $deps/src"
  apt=$deps/apt
  mkdir -p "$apt/sources" "$apt/lists/partial" "$apt/cache/archives/partial" "$deps/src"
  # The system's Debian mirror, as a deb-src entry of our own.
  uri=$(grep -hoE 'https?://[^ ]*debian/?( |$)' /etc/apt/sources.list /etc/apt/sources.list.d/*.sources \
          /etc/apt/sources.list.d/*.list 2>/dev/null | grep -v security | head -1 | tr -d ' ' || true)
  uri=${uri:-http://deb.debian.org/debian}
  printf 'Types: deb-src\nURIs: %s\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$uri" > "$apt/sources/debian-src.sources"
  opts=(-o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$apt/sources"
        -o Dir::State::Lists="$apt/lists" -o Dir::Cache="$apt/cache" -o APT::Sandbox::User=root)
  apt-get "${opts[@]}" update -qq
  (cd "$deps/src" && apt-get "${opts[@]}" source -qq --download-only libsdl2=2.26.5+dfsg-1 imgui=1.86+ds-1)
  (cd "$deps/src" && tar xzf libsdl2_2.26.5+dfsg.orig.tar.gz && tar xJf imgui_1.86+ds.orig.tar.xz)
fi

# --- 3. SDL2 for wasm --------------------------------------------------------------------------
if [[ ! -f $deps/sdl2/lib/libSDL2.a ]]; then
  echo "Building SDL2 2.26.5 for WebAssembly into $deps/sdl2 (about a minute)"
  rm -rf "$deps/sdl2-build"
  emcmake cmake -S "$deps/src/SDL2-2.26.5" -B "$deps/sdl2-build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$deps/sdl2" \
    -DSDL_SHARED=OFF -DSDL_STATIC=ON -DSDL_TEST=OFF -DSDL_PTHREADS=OFF \
    > "$deps/sdl2-configure.log" 2>&1 || { cat "$deps/sdl2-configure.log" >&2; exit 1; }
  "${build_lock[@]}" cmake --build "$deps/sdl2-build" >/dev/null
  cmake --install "$deps/sdl2-build" >/dev/null
fi

# --- header-only libraries: a folder of symlinks, not /usr/include (which confuses emcc) ---------
mkdir -p "$deps/include"
for h in glm nlohmann stb tiny_obj_loader.h; do
  [[ -e $deps/include/$h ]] || ln -s "/usr/include/$h" "$deps/include/$h"
done
