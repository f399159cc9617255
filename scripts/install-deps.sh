#!/usr/bin/env bash
# Installs the Debian packages CG Sandbox needs, if any are missing.
# Quick and silent when everything is present; `apt-get update` first otherwise;
# apt-get directly as root, through sudo otherwise.
# With arguments, those packages instead of the list below (scripts/install-web-deps.sh).
set -euo pipefail

default_packages=(
  cmake ninja-build g++ pkg-config make
  libsdl2-dev libimgui-dev libglm-dev catch2 libstb-dev
  nlohmann-json3-dev libcli11-dev libbenchmark-dev libpolyclipping-dev libtinyobjloader-dev
  libembree-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core xdotool libx11-dev
  clang libclang-rt-14-dev
  optipng pngquant
)
if (($#)); then packages=("$@"); else packages=("${default_packages[@]}"); fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
((${#missing[@]} == 0)) && exit 0

echo "Installing missing packages: ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null; then
  sudo=(sudo)
else
  echo "error: missing packages (${missing[*]}) and not root, and no sudo to install them" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
