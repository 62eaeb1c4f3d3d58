#!/usr/bin/env bash
# Regenerates the images under screenshots/ that the README shows, from the current build:
# the Cornell box with GI off and on, each lighting term alone, the voxel view, and the editor.
# Usage: tools/make-screenshots.sh [SIZE] (default 512x512; the editor is captured at 1280x720)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LIT_BUILD_DIR:-$root/build}"
size="${1:-512x512}"
out="$root/screenshots"
scene="$root/assets/cornell_box.gltf"
render="$build/tools/lit-render"
mkdir -p "$out"

"$render" "$scene" --out "$out/cornell_gi_off.png" --size "$size" --gi off
for view in final direct-diffuse indirect-diffuse direct-specular indirect-specular voxels; do
    "$render" "$scene" --out "$out/cornell_gi_${view}.png" --size "$size" --gi on --voxels 128 --view "$view"
done
xvfb-run -a -s "-screen 0 1280x720x24" "$build/editor/lit-editor" "$scene" \
    --screenshot "$out/editor.png" --frames 10 --size 1280x720
echo "screenshots written to $out"
