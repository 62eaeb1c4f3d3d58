#!/usr/bin/env bash
# Regenerates the images under screenshots/ that the README shows, from the current build:
# the Cornell box with GI off and on, each lighting term alone, the voxel view, the material
# layers scene and the sun room against their references, and the editor
# (its panels with a selection and a camera path, the voxel slice view, the cone directions view
# in the fast and in the accurate GI mode,
# and the performance overlay), the editor ones driven by a --script run, and Sponza lit by the
# default sun and sky when the shared scenes are there.
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
# lit-render's stills converge: the default (cached) GI mode as the editor shows it once the
# view is left alone, the voxels' irradiance refined with all 16 cone sets.
for view in final direct-diffuse indirect-diffuse direct-specular indirect-specular voxels; do
    "$render" "$scene" --out "$out/cornell_gi_${view}.png" --size "$size" --gi on --voxels 128 --view "$view"
done

# The same view path-traced by Lit's reference (docs/REFERENCE.md): every bounce (the light paths
# of the default GI), one bounce and two; then the Difference view of each GI image against the
# every-bounce reference (blue too dark, white right, red too bright; ±50 % at the ends), for the
# default (cached) mode, the accurate mode and the fast mode (docs/GI.md), all with every bounce.
tmpdir="$(mktemp -d)"
trap 'rm -rf "$tmpdir"' EXIT
spp="${LIT_SCREENSHOT_SPP:-512}"
"$render" "$scene" --reference --bounces all --spp "$spp" --size "$size" --out "$out/cornell_reference_all.png" \
    --hdr "$tmpdir/reference_all.hdr"
"$render" "$scene" --reference --bounces 1 --spp "$spp" --size "$size" --out "$out/cornell_reference_1bounce.png"
"$render" "$scene" --reference --bounces 2 --spp "$spp" --size "$size" --out "$out/cornell_reference_2bounces.png"
"$render" "$scene" --size "$size" --gi on --voxels 128 --compare "$tmpdir/reference_all.hdr" \
    --difference "$out/cornell_gi_difference.png"
"$render" "$scene" --size "$size" --gi on --voxels 128 --gi-mode accurate \
    --out "$out/cornell_gi_accurate.png" --compare "$tmpdir/reference_all.hdr" \
    --difference "$out/cornell_gi_accurate_difference.png"
"$render" "$scene" --size "$size" --gi on --voxels 128 --gi-mode fast \
    --out "$out/cornell_gi_fast.png" --compare "$tmpdir/reference_all.hdr" \
    --difference "$out/cornell_gi_fast_difference.png"

# The material layers scene (tools/blender/make_material_layers.py, docs/MATERIALS.md): plain,
# clear-coated smooth and rough, specular, IOR with a tint, clear-coated gold, sheen; Lit's defaults at
# 128³, the every-bounce reference, and the Difference view of the first against the second.
layers="$root/tests/data/blender/material_layers/material_layers.gltf"
"$render" "$layers" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/material_layers_reference.png" \
    --hdr "$tmpdir/layers_reference.hdr"
"$render" "$layers" --size 640x360 --gi on --voxels 128 --out "$out/material_layers.png" \
    --compare "$tmpdir/layers_reference.hdr" --difference "$out/material_layers_difference.png"

# The glass scene (tools/blender/make_glass.py, docs/MATERIALS.md "Transmission"): a clear pane
# before an orange box and a tinted panel casting a coloured shadow, drawn as thin sheets; Lit's
# defaults at 128³, the every-bounce reference, and the Difference view.
glass="$root/tests/data/blender/glass/glass.gltf"
"$render" "$glass" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/glass_reference.png" \
    --hdr "$tmpdir/glass_reference.hdr"
"$render" "$glass" --size 640x360 --gi on --voxels 128 --out "$out/glass.png" \
    --compare "$tmpdir/glass_reference.hdr" --difference "$out/glass_difference.png"

# The transmission-texture scene (tools/blender/make_transmission_texture.py): a pane whose
# transmission is a black/white checker over a sunlit floor; Lit's defaults at 128³ beside the
# every-bounce reference.
transmission="$root/tests/data/blender/transmission_texture/transmission_texture.gltf"
"$render" "$transmission" --reference --bounces all --spp "$spp" --size 640x360 \
    --out "$out/transmission_texture_reference.png"
"$render" "$transmission" --size 640x360 --gi on --voxels 128 --out "$out/transmission_texture.png"

# The layer-textures scene (tools/blender/make_layer_textures.py): a clear coat and a Specular
# painted with a black/white checker on dark planes under a low sun; Lit's defaults at 128³ beside
# the every-bounce reference.
layers="$root/tests/data/blender/layer_textures/layer_textures.gltf"
"$render" "$layers" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/layer_textures_reference.png"
"$render" "$layers" --size 640x360 --gi on --voxels 128 --out "$out/layer_textures.png"

# The glass-volume scene (tools/blender/make_glass_volume.py): amber glass slabs 5 cm and 20 cm
# thick (KHR_materials_volume) over a sunlit floor; Lit's defaults at 128³ beside the every-bounce
# reference.
volume="$root/tests/data/blender/glass_volume/glass_volume.gltf"
"$render" "$volume" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/glass_volume_reference.png"
"$render" "$volume" --size 640x360 --gi on --voxels 128 --out "$out/glass_volume.png"

# The glass-refraction scene (tools/blender/make_glass_refraction.py): a 30 cm block of clear
# glass before a checkered wall, seen at an angle; Lit's defaults at 128³ beside the every-bounce
# reference.
refraction="$root/tests/data/blender/glass_refraction/glass_refraction.gltf"
"$render" "$refraction" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/glass_refraction_reference.png"
"$render" "$refraction" --size 640x360 --gi on --voxels 128 --out "$out/glass_refraction.png"

# The generated city (make-gi-suite, docs/GI.md "Near level"): a street 640 m of town across, the
# shaded side lit only by bounced light; Lit's defaults at 128³ (with the 64 m near level around
# the camera), the same with one volume around it all, the every-bounce reference, and the
# Difference views against it.
city="$root/assets/gi/city.gltf"
"$render" "$city" --reference --bounces all --spp "$spp" --size 640x360 --out "$out/city_reference.png" \
    --hdr "$tmpdir/city_reference.hdr"
"$render" "$city" --size 640x360 --gi on --voxels 128 --out "$out/city.png" \
    --compare "$tmpdir/city_reference.hdr" --difference "$out/city_difference.png"
"$render" "$city" --size 640x360 --gi on --voxels 128 --view voxel-levels --out "$out/city_voxel_levels.png"
"$render" "$city" --size 640x360 --gi on --voxels 128 --set gi.nearLevelSide=0 --out "$out/city_one_volume.png" \
    --compare "$tmpdir/city_reference.hdr" --difference "$out/city_one_volume_difference.png"

# The sun room (tools/blender/make_sun_room.py, docs/GI.md "The sun room against Cycles"): lit only
# through its window, so nearly everything shown is bounced light; Lit's defaults at 128³, the
# every-bounce reference, and the Difference view. Exposed +3 stops: the room is dim beside the patch.
room="$root/tests/data/blender/sun_room/sun_room.gltf"
"$render" "$room" --reference --bounces all --spp "$spp" --size 480x300 --ev 3 --out "$out/sun_room_reference.png" \
    --hdr "$tmpdir/room_reference.hdr"
"$render" "$room" --size 480x300 --gi on --voxels 128 --ev 3 --out "$out/sun_room.png" \
    --compare "$tmpdir/room_reference.hdr" --difference "$out/sun_room_difference.png"

# The editor. Keys of a camera path in front of the box, seen from further back and to the side
# so the curve and its key frusta show; the tall box selected (outline, gizmo) in the inspector.
# "wait refined" lets the cached mode's update finish (spread over frames under the editor's GI
# time budget: about 10 s at 128³ on llvmpipe) and then its refinement rounds (about a minute), so
# the GI is captured converged and the overlay shows the steady frame, as a user sees them once
# the light has settled.
script="$tmpdir/script.txt"
cat >"$script" <<SCRIPT
camera 0.9 1.0 4.1 0 1 0
time 0
key add
camera 0 1.3 4.4 0 1 0
time 3
key add
camera -1.0 1.1 3.9 0 1 0
time 6
key add
key select 1
camera 2.6 2.4 6.8 0 1 1.5
select tall_box
wait refined
wait 3
screenshot $out/editor.png ui
select -
camera 0 1 3.4 0 1 0
panel hierarchy off
panel inspector off
panel timeline off
panel log off
panel stats off
view voxel-slice
setting debug.voxelChannel albedo
setting debug.voxelMip 1
setting debug.voxelSliceAxis 1
setting debug.voxelSlice 0.2
wait 2
screenshot $out/editor_voxel_slice.png ui
panel stats on
setting debug.voxelMip 0
view cone-directions
setting gi.mode fast
wait 2
pick 520 560
wait 1
screenshot $out/editor_cone_directions.png ui
setting gi.mode accurate
wait 2
pick 520 560
wait 1
screenshot $out/editor_cone_directions_accurate.png ui
setting gi.mode cached
view final
panel settings off
panel camera off
panel stats-details on
wait refined
wait 3
screenshot $out/editor_performance.png ui
quit
SCRIPT
xvfb-run -a -s "-screen 0 1280x720x24" "$build/editor/lit-editor" "$scene" --script "$script" --size 1280x720

# The rotate gizmo in local space on the tall box, turned by a snapped drag on its Y ring, seen
# from the front right; the View menu's current view named in the viewport bar.
cat >"$script" <<SCRIPT
select tall_box
gizmo rotate
space local
snap on
panel stats off
camera 1.2 1.5 2.6 -0.2 0.4 -0.3
wait 3
screenshot $out/editor_rotate_gizmo.png ui
quit
SCRIPT
xvfb-run -a -s "-screen 0 1280x720x24" "$build/editor/lit-editor" "$scene" --script "$script" --size 1280x720
# Sponza (no lights, no camera: Lit's default sun and gradient sky light it, through the GI too)
# from inside the atrium, at its east end 1.7 m above the floor looking down its length, when the
# shared scenes are present (LIT_SCENES_DIR, else ../shared/scenes beside the checkout or the
# worktree folder), looking up at the sky. Every render setting at its default.
sponza=""
for dir in "${LIT_SCENES_DIR:-}" "$root/../shared/scenes" "$root/../../shared/scenes"; do
    if [ -n "$dir" ] && [ -f "$dir/sponza/Sponza.gltf" ]; then sponza="$dir/sponza/Sponza.gltf"; break; fi
done
if [ -n "$sponza" ]; then
    cat >"$script" <<SCRIPT
panel hierarchy off
panel inspector off
panel settings off
panel camera off
panel timeline off
panel log off
panel stats off
camera 5.47 1.7 -0.31 -12.4 7.5 -0.31
wait gi
wait 8
screenshot $out/sponza_sun_sky.png noui
quit
SCRIPT
    xvfb-run -a -s "-screen 0 1280x720x24" "$build/editor/lit-editor" "$sponza" --script "$script" --size 1280x720
else
    echo "Sponza not found (set LIT_SCENES_DIR): screenshots/sponza_sun_sky.png not refreshed" >&2
fi
echo "screenshots written to $out"
