#!/bin/sh
# editor_node_animation.sh EDITOR IMAGE_STATS SCENE OUTDIR
# The timeline plays the scene's node animations: tests/data/blender/animated (a red box that
# slides from x −1.5 m to +1.5 m in 2 s, a door that swings open) has no camera path, so the
# timeline's clock is the animations' own. A script scrubs to 0 s and 2 s ("time T") and
# captures the viewport each time, looking from the scene camera's place (0, 1.5, 6) at
# (0, 1.5, 0): the box's red must be in the left half of the picture's lower band at 0 s and in
# the right half at 2 s. Then "play" must run to the animations' end (2 s) and stop, and a save
# there must write the nodes' rest transforms (the box at x −1.5 m), not the pose at 2 s. Last,
# with the GI on, scrubbing to 1 s must re-voxelize for the moved geometry (the log's
# "re-voxelized ... (geometry changed)"), as a gizmo move does.
# Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
prepare_run "$scene" "$out"
log=$out/frames.csv

cat >"$out/animation.txt" <<SCRIPT
setting gi.enabled false
camera 0 1.5 6 0 1.5 0
time 0
wait 2
screenshot $out/time_0.png noui
time 2
wait 2
screenshot $out/time_2.png noui
time 0
play 1
wait play
wait 1
save $out/saved.gltf
setting gi.voxelResolution 64
setting gi.enabled true
wait gi
time 1
wait gi
screenshot $out/time_1_gi.png noui
SCRIPT

xvfb_editor "$scene" --script "$out/animation.txt" --size 640x360 --frame-log "$log" >"$out/editor.txt" 2>&1
status=$?
cat "$out/editor.txt"
[ "$status" -eq 0 ] || fail "lit-editor exited with status $status"
[ -f "$out/time_0.png" ] && [ -f "$out/time_2.png" ] || fail "the script ran but did not write both screenshots"

# Redness (mean R − mean G) of the left and right thirds of the lower band of a capture.
redness() {
    size=$("$image_stats" "$1") || fail "cannot read $1"
    w=$(echo "$size" | awk '{ print $1 }')
    h=$(echo "$size" | awk '{ print $2 }')
    y=$((h * 55 / 100))
    bh=$((h * 40 / 100))
    left=$("$image_stats" "$1" $((w * 20 / 100)) $y $((w * 28 / 100)) $bh | awk '{ printf "%.1f", $5 - $6 }')
    right=$("$image_stats" "$1" $((w * 52 / 100)) $y $((w * 28 / 100)) $bh | awk '{ printf "%.1f", $5 - $6 }')
    echo "$left $right"
}
at0=$(redness "$out/time_0.png")
at2=$(redness "$out/time_2.png")
echo "redness left/right at 0 s: $at0; at 2 s: $at2"
echo "$at0" | awk '{ exit !($1 > $2 + 3) }' || fail "at 0 s the red box is not on the left (redness left/right $at0)"
echo "$at2" | awk '{ exit !($2 > $1 + 3) }' || fail "at 2 s the red box is not on the right (redness left/right $at2)"

# A move voxelizes its changed boxes ("re-voxelized 2 changed boxes (N voxels) of 64³ ...").
grep -Eq "re-voxelized (.* of )?64³ \(geometry changed\)" "$out/editor.txt" ||
    fail "scrubbing the animation with the GI on did not re-voxelize for the moved geometry"

# Play from 0 s at 1x: the playhead goes through the animation (at least one frame while playing:
# a loaded machine may render few) and stops at its end, 2 s.
[ -f "$log" ] || fail "no frame log"
awk -F, 'NR > 1 && $11 == 1 { playing++ } END { exit !(playing >= 1) }' "$log" ||
    fail "play did not play the node animations (no playing frames in the log)"
# The row after the last playing one: the playhead rests at 2 s.
stopped=$(awk -F, 'NR > 1 && $11 == 1 { seen = 1; next } seen && !done { print $10, $11; done = 1 }' "$log")
echo "$stopped" | awk '{ exit !($1 > 1.999 && $1 < 2.001 && $2 == 0) }' ||
    fail "playback did not stop at the animations' end, 2 s (first row after playing: playhead, playing = $stopped)"

# The save at 2 s keeps the rest pose: the box's translation is its file's, x −1.5 m.
[ -f "$out/saved.gltf" ] || fail "the save wrote nothing"
if command -v python3 >/dev/null 2>&1; then
    python3 - "$out/saved.gltf" <<'PY' || fail "the saved scene does not hold the box's rest transform"
import json, sys
nodes = {n.get("name"): n for n in json.load(open(sys.argv[1]))["nodes"]}
t = nodes["box"].get("translation", [0, 0, 0])
print("saved box translation", t)
sys.exit(0 if abs(t[0] + 1.5) < 1e-6 and abs(t[1] - 0.3) < 1e-6 else 1)
PY
fi
echo "PASS"
