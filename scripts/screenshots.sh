#!/usr/bin/env bash
# The README's pictures, made by the project itself: `cgsandbox render --full` (the viewer's own
# drawing code, the whole window at a fixed size) on lesson presets at chosen steps and on an
# exam problem, written as docs/images/<name>.png.
#
#   scripts/screenshots.sh [CGSANDBOX_BINARY] [OUT_DIR]     (make screenshots)
#
# Defaults: build/bin/cgsandbox and docs/images/. Runs under one `xvfb-run -a` when there is no
# display and Xvfb is installed (otherwise `render` draws offscreen through EGL by itself).
# The lessons are this tree's lessons/. Makes the PNGs small with pngquant (a 256-colour
# palette, which a UI screenshot loses nothing visible to) and optipng when they are installed
# (scripts/install-deps.sh installs both; CG_SCREENSHOTS_OPTIMISE=0 skips them). The README's
# captions describe these steps: change both together.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/bin/cgsandbox}
out=${2:-$root/docs/images}
size=1280x800

if [[ ! -x "$bin" ]]; then
  echo "screenshots: no cgsandbox at $bin (build it first: make build)" >&2
  exit 2
fi
if [[ -z "${DISPLAY:-}" && -z "${CG_SCREENSHOTS_XVFB:-}" ]] && command -v xvfb-run >/dev/null; then
  CG_SCREENSHOTS_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$bin" "$out"
fi
mkdir -p "$out"
export CGSANDBOX_LESSONS="$root/lessons"

# shot NAME RENDER-ARGUMENTS…: the viewer at that step, as OUT_DIR/NAME.png.
shot() {
  local name=$1
  shift
  "$bin" render "$@" --full --size "$size" --out "$out/$name.png"
  if [[ "${CG_SCREENSHOTS_OPTIMISE:-1}" != 0 ]]; then
    if command -v pngquant >/dev/null; then
      # Exit 98/99: the palette would be no smaller, or not good enough; keep the original.
      pngquant --quality=70-95 --speed 1 --strip --skip-if-larger --force \
        --output "$out/$name.png" "$out/$name.png" || { rc=$?; ((rc == 98 || rc == 99)); }
    fi
    if command -v optipng >/dev/null; then optipng -quiet -o2 -strip all "$out/$name.png"; fi
  fi
  echo "$out/$name.png"
}

# The README's first picture: Liang-Barsky mid-clip, the top edge just crossed (leaving).
shot liang-barsky --lesson liang-barsky --preset "a segment crossing two edges" --step 5
# The gallery: a 3D lesson, a ray tree, a Bézier construction, exam practice.
shot arcball --lesson arcball --preset "a small closed loop: the ball comes back" --step 11
shot ray-tree --lesson ray-tracer \
  --preset "through the glass ball: refraction in and out (depth 2)" --step 26
shot de-casteljau --lesson de-casteljau --preset "a cubic split in half" --step 3
shot exam liang-barsky --exam 7
