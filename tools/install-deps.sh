#!/usr/bin/env bash
# Installs the Debian packages Lit needs that are missing. Works as root on a fresh Debian 12
# (bookworm); as another user it uses sudo when available, else prints the command to run.
#
#   tools/install-deps.sh                 what building, testing and running Lit need
#   tools/install-deps.sh --scene-tools   also Blender and python3-numpy, to remake the Blender
#                                         test scenes (tools/blender/make_scenes.py); Blender's
#                                         glTF exporter imports numpy, and Debian's blender
#                                         package does not depend on it. No test needs these.
set -euo pipefail

packages=(
    build-essential cmake pkg-config          # compiler and build
    libglfw3-dev libglm-dev libimgui-dev      # window, math, editor UI
    libstb-dev libtinygltf-dev nlohmann-json3-dev  # images, glTF, JSON
    libdraco-dev libmeshoptimizer-dev         # compressed glTF geometry (Draco, meshopt)
    libwebp-dev                               # WebP textures (EXT_texture_webp)
    libepoxy-dev libegl-dev libgl-dev         # GL/EGL loading
    libegl-mesa0 libgl1-mesa-dri libglx-mesa0 # Mesa (llvmpipe) for machines without a GPU driver
    libembree-dev libtbb-dev                  # reference path tracer: ray queries, threads
    libgtest-dev                              # tests
    xvfb xauth                                # editor tests without a display
    fonts-dejavu-core                         # editor UI font (falls back to ImGui's own)
)
for arg in "$@"; do
    case "$arg" in
        --scene-tools) packages+=(blender python3-numpy) ;;
        *) echo "usage: tools/install-deps.sh [--scene-tools]" >&2; exit 2 ;;
    esac
done

missing=()
for p in "${packages[@]}"; do
    status="$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)"
    [ "$status" = "install ok installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "lit: installing missing packages: ${missing[*]}" >&2
if ! command -v apt-get >/dev/null 2>&1; then
    echo "lit: apt-get not found. Lit's set-up script supports Debian 12 (and derivatives);" >&2
    echo "lit: install these packages by hand: ${missing[*]}" >&2
    exit 1
fi
if [ "$(id -u)" -eq 0 ]; then
    sudo=()
elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
else
    echo "lit: root rights are needed to install packages. Run as root:" >&2
    echo "    apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
