#!/bin/sh
# editor_script_round_trip.sh EDITOR CHECK_SAVED_SCENE SCENE OUTDIR
# Edits a scene through a --script run (select, set, undo, redo, save), then checks the saved
# glTF for every edit with lit_check_saved_scene: the undone edits must be gone and the redone
# ones there. A second run opens the saved file, edits it again and saves it as .glb, which is
# checked too (the first edits survived the reopen). Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
check=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
editor_timeout=280  # two runs; CTest TIMEOUT 600
prepare_run "$scene" "$out"
saved=$out/round_trip.gltf
resaved=$out/round_trip_again.glb
rm -f "$saved" "$out/round_trip.bin" "$resaved"

cat >"$out/round_trip.txt" <<SCRIPT
# A 64^3 volume keeps each llvmpipe frame around a second.
setting gi.voxelResolution 64
select tall_box
set material.roughness 0.25
set material.roughness 0.75
undo
set node.translation -0.3 0.1 -0.3
select left_wall_red
set material.metalness 0.5
select ceiling_spot
set light.color 1 0.5 0.25
set light.intensity 10
undo
redo
save $saved
quit
SCRIPT

run_editor "$scene" --script "$out/round_trip.txt" --size 640x360
[ -f "$saved" ] || fail "the script ran but $saved was not written"

# roughness: 0.75 was undone; intensity: 10 was undone and redone; the white material is shared
# by floor and tall_box, so the floor shows the edit too.
"$check" "$saved" tall_box.roughness=0.25 floor.roughness=0.25 tall_box.translation=-0.3,0.1,-0.3 \
    left_wall_red.metalness=0.5 left_wall_red.roughness=0.9 ceiling_spot.light.color=1,0.5,0.25 \
    ceiling_spot.light.intensity=10 || fail "the saved scene lacks an edit (see above)"

cat >"$out/round_trip_again.txt" <<SCRIPT
setting gi.voxelResolution 64
select short_box
set node.scale 1 2 1
save $resaved
SCRIPT
run_editor "$saved" --script "$out/round_trip_again.txt" --size 640x360
"$check" "$resaved" short_box.scale=1,2,1 tall_box.roughness=0.25 tall_box.translation=-0.3,0.1,-0.3 \
    ceiling_spot.light.color=1,0.5,0.25 ceiling_spot.light.intensity=10 ||
    fail "the scene saved after reopening lost an edit (see above)"
echo "PASS: every edit found in $saved and $resaved"
