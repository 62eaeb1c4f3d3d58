#!/bin/sh
# editor_authoring.sh EDITOR CHECK_SAVED_SCENE IMAGE_STATS SCENE OUTDIR
# The authoring edits through a --script run on the Cornell box: add a box, rotate it with the
# rotate gizmo (snapped to 15°), scale it with the scale gizmo along its own X, move it with the
# translate gizmo (snapped to 1 m), add a point light and parent it to the box (world position
# kept), duplicate the box with its light, make the copy's material unique and edit it, delete a
# node, undo and redo that, save. lit_check_saved_scene then reads the file back and compares
# every edit; a second run reopens the saved file in the editor and saves it as .glb, which must
# hold the same, runs the view commands on a two-node selection (local axes, frame F, orbit
# Alt+drag; they must not fail) and checks that the voxel slice view is rendered for the free
# area between the panels only, not the whole window. GI is off: the test is about editing, and
# llvmpipe frames stay short (about 25 s in all). Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
check=$2
stats=$3
scene=$4
out=$5

. "$(dirname "$0")/common.sh"
editor_timeout=140  # two runs; CTest TIMEOUT 300
prepare_run "$scene" "$out"
saved=$out/authored.gltf
resaved=$out/authored_again.glb
rm -f "$saved" "$out/authored.bin" "$resaved"

# The window is 640x360; the camera looks straight down -Z at the new box, so its gizmo is at
# the window centre (320, 180). Rotate ring radius 80 px: (376.57, 123.43) is on the Z ring at
# 45°; dragging to (263.43, 123.43) sweeps 90° counter-clockwise, +90° about Z (which points at
# the camera). The scale handles are 90 px long: after the rotation the box's own X points up on
# screen, and dragging it from 60 to 150 px up doubles it. The translate drag moves 150 px along
# world X: 0.9 m at this distance with the Cornell box camera's 0.69 rad field of view (0.67 to
# 1.49 m for 0.5 to 1.05 rad), snapped to 1 m. Then the spot light and the tall box, selected
# together, go up 1 m with one drag of the tall box's Y arrow (150 px at 3.3 m: 0.99 m, snapped).
# The duplicate of new_box (1 m wide along X after the turn) goes 1.1 m to the right of the view
# (+X): its own width and a tenth.
cat >"$out/authored.txt" <<SCRIPT
setting gi.enabled false
add box 0 0.3 0
set node.name new_box
camera 0 0.3 3 0 0.3 0
snap 1 15 0.1
gizmo rotate
drag 376.57 123.43 263.43 123.43
gizmo scale
drag 320 120 320 30
gizmo translate
drag 380 180 530 180
add point 0 1.5 0.5
set node.name new_lamp
parent new_box
select new_box
duplicate
material unique
set material.roughness 0.2
select ceiling_spot
select+ tall_box
camera -0.33 0 3 -0.33 0 -0.3
drag 320 170 320 20
select short_box
delete
undo
redo
save $saved
quit
SCRIPT

run_editor "$scene" --script "$out/authored.txt" --size 640x360
[ -f "$saved" ] || fail "the script ran but $saved was not written"

# 9 nodes in the Cornell box - short_box + new_box, new_lamp and their copies = 12.
checks="*.nodes=12 new_box.rotation=0,0,0.7071068,0.7071068 new_box.scale=2,1,1 new_box.translation=1,0.3,0
    new_box.holds=1,0,0 new_box.roughness=0.5 new_lamp.parent=new_box new_lamp.worldPosition=0,1.5,0.5
    new_lamp.holds=0,1,0 new_box.001.translation=2.1,0.3,0 new_box.001.scale=2,1,1 new_box.001.roughness=0.2
    new_box.001.distinctMaterial=1:new_box new_lamp.001.parent=new_box.001 new_lamp.001.worldPosition=1.1,1.5,0.5
    tall_box.translation=-0.33,1,-0.3 ceiling_spot.translation=0,2.9,0"
# shellcheck disable=SC2086
"$check" "$saved" $checks || fail "the saved scene lacks an edit (see above)"

cat >"$out/authored_again.txt" <<SCRIPT
setting gi.enabled false
save $resaved
select new_box
select+ new_lamp
space local
frame
orbit 40 10
wait 1
view voxel-slice
wait 1
screenshot $out/slice.png noui
view final
wait 1
screenshot $out/final.png noui
SCRIPT
run_editor "$saved" --script "$out/authored_again.txt" --size 640x360
# shellcheck disable=SC2086
"$check" "$resaved" $checks || fail "the scene saved after reopening lost an edit (see above)"
# The final view renders the whole 640x360 window; the voxel slice only the area between the
# panels (about 128x215 at this size: the columns take 236 px on the left and 276 on the right).
set -- $("$stats" "$out/final.png")
[ "$1" -eq 640 ] && [ "$2" -eq 360 ] || fail "the final view rendered $1x$2, not the window's 640x360"
set -- $("$stats" "$out/slice.png")
[ "$1" -lt 320 ] && [ "$2" -lt 300 ] || fail "the voxel slice rendered $1x$2: it should fill only the free viewport area"
echo "PASS: every authoring edit found in $saved and $resaved"
