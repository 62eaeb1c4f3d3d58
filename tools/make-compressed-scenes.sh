#!/usr/bin/env bash
# Makes the compressed test scenes the way users make them: the Blender-exported point scene
# (tests/data/blender/point.gltf, made by tools/blender/make_scenes.py) compressed by
# glTF-Transform's `draco` and `meshopt` commands with their default settings (meshopt "high":
# quantized attributes, octahedral normals, exponential and quaternion animation filters).
#
#   tools/install-gltf-transform.sh          # once (npm)
#   tools/make-compressed-scenes.sh [OUT_DIR]  # default tests/data/compressed
#
# Writes OUT_DIR/point_draco.glb, OUT_DIR/point_meshopt.glb and OUT_DIR/gltf/point_meshopt.gltf
# with its .bin (a .gltf whose fallback buffer has no URI). tests/unit/test_gltf_compression.cpp
# loads them against point.gltf.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-$root/tests/data/compressed}")"
dir="${LIT_GLTF_TRANSFORM_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lit/gltf-transform}"
tool="$dir/node_modules/.bin/gltf-transform"
[ -x "$tool" ] || { echo "lit: $tool not found; run tools/install-gltf-transform.sh" >&2; exit 1; }
source="$root/tests/data/blender/point.gltf"
mkdir -p "$out/gltf"
"$tool" draco "$source" "$out/point_draco.glb"
"$tool" meshopt "$source" "$out/point_meshopt.glb"
"$tool" meshopt "$source" "$out/gltf/point_meshopt.gltf"
echo "lit: compressed scenes written to $out" >&2
