#!/bin/sh
# lit_render_node_animation.sh LIT_RENDER IMAGE_STATS SCENE OUTDIR
# The Blender scene tests/data/blender/animated (tools/blender/make_animated_scene.py) rendered
# with --time at 0 s and 2 s, rasterized and path-traced (--reference), through its own camera at
# 160×100, and along a camera path (--path), rasterized and path-traced. Each object is looked for where its keys put it, by projecting its known position with
# the camera (at (0, 1.5, 6) looking down −Z, vertical field of view 40°, tan 20° = 0.364, aspect
# 1.6): x_px = 80 (1 + x / (d · 0.364 · 1.6)), y_px = 50 (1 − (y − 1.5) / (d · 0.364)), d the depth.
#   the red box, centre y 0.3 m, depth 6 m: x −1.5 m at 0 s → column 45.7; +1.5 m at 2 s → 114.3;
#     rows 72 to 86 (its front face and top). Checked in 6 × 6 squares at columns 43 and 111, rows 75.
#   the blue door: at 0 s a panel at depth 7.5 m from x −2.5 to −1.5 m, y 0 to 2 m (columns 34 to
#     52, rows 41 to 77); at 2 s turned edge-on at column 34 to 39. Checked in the square at
#     columns 42 to 48, rows 52 to 58: blue at 0 s, the white back wall at 2 s.
# The stills at 0 and 2 s render with the GI (re-voxelized for the posed scene); the other runs
# with --gi off, which the positions do not depend on, to keep the test short.
# "red": mean R − mean G over 40 (of 255); "blue": mean B − mean R over 40. Far above the other
# image's numbers there (a few units: grey floor, white wall), far below the objects' (over 100).
set -u
render=$1
image_stats=$2
scene=$3
out=$4

fail() {
    echo "FAIL: $*"
    exit 1
}
[ -f "$scene" ] || fail "scene $scene not found"
rm -rf "$out"
mkdir -p "$out"

# Mean R, G, B of a square (columns 5, 6, 7 of lit_image_stats).
square() { "$image_stats" "$1" "$2" "$3" 6 6 | awk '{ print $5, $6, $7 }'; }
red() { square "$@" | awk '{ printf "%d", $1 - $2 }'; }
blue() { square "$@" | awk '{ printf "%d", $3 - $1 }'; }

check() {
    image=$1
    what=$2
    box_at_left=$3  # 1: the box is at the left square (0 s), 0: at the right one (2 s)
    door_closed=$4
    left=$(red "$image" 43 75)
    right=$(red "$image" 111 75)
    door=$(blue "$image" 42 52)
    echo "$what: box redness left $left right $right, door blueness $door"
    if [ "$box_at_left" -eq 1 ]; then
        [ "$left" -gt 40 ] && [ "$right" -lt 40 ] || fail "$what: the box is not at x -1.5 m (left $left, right $right)"
    else
        [ "$right" -gt 40 ] && [ "$left" -lt 40 ] || fail "$what: the box is not at x +1.5 m (left $left, right $right)"
    fi
    if [ "$door_closed" -eq 1 ]; then
        [ "$door" -gt 40 ] || fail "$what: the closed door is not in front of the back wall (blueness $door)"
    else
        [ "$door" -lt 40 ] || fail "$what: the door has not swung open (blueness $door)"
    fi
}

common="--size 160x100 --camera camera"
for t in 0 2; do
    "$render" "$scene" $common --time $t --out "$out/time_$t.png" >"$out/time_$t.txt" 2>&1 ||
        { cat "$out/time_$t.txt"; fail "lit-render --time $t failed"; }
done
grep -q "node animations: 2 channels on 2 nodes" "$out/time_0.txt" || { cat "$out/time_0.txt"; fail "lit-render did not report the scene's node animations"; }
check "$out/time_0.png" "rasterized at 0 s" 1 1
check "$out/time_2.png" "rasterized at 2 s" 0 0
# Without --time a still shows 0 s.
"$render" "$scene" $common --gi off --out "$out/no_time.png" >"$out/no_time.txt" 2>&1 || fail "lit-render without --time failed"
check "$out/no_time.png" "rasterized without --time" 1 1

# The reference builds from the same posed scene: the objects are where the rasterizer has them.
for t in 0 2; do
    "$render" "$scene" $common --time $t --reference --spp 8 --out "$out/reference_$t.png" >"$out/reference_$t.txt" 2>&1 ||
        { cat "$out/reference_$t.txt"; fail "lit-render --reference --time $t failed"; }
done
check "$out/reference_0.png" "reference at 0 s" 1 1
check "$out/reference_2.png" "reference at 2 s" 0 0
# --path flies a camera path with the node animations on the same clock. The path (the scene
# camera's pose, held from 0 to 1 s) ends before the animations: at 1 frame per second the frames
# are 0, 1 and 2 s, the last past the path's end, and the box crosses as in the stills.
cat >"$out/hold.path.json" <<JSON
{ "version": 1, "keys": [
  { "time": 0, "position": [0, 1.5, 6], "rotation": [0, 0, 0, 1], "yfov": 0.6981317 },
  { "time": 1, "position": [0, 1.5, 6], "rotation": [0, 0, 0, 1], "yfov": 0.6981317 } ] }
JSON
"$render" "$scene" --size 160x100 --gi off --path "$out/hold.path.json" --fps 1 --frames-out "$out/frames" >"$out/path.txt" 2>&1 ||
    { cat "$out/path.txt"; fail "lit-render --path failed"; }
[ -f "$out/frames/frame_00002.png" ] && [ ! -f "$out/frames/frame_00003.png" ] ||
    { ls "$out/frames"; fail "--path did not render the frames at 0, 1 and 2 s"; }
check "$out/frames/frame_00000.png" "path frame at 0 s" 1 1
check "$out/frames/frame_00002.png" "path frame at 2 s" 0 0
# --reference --path: every frame path-traced at its time, the objects where the rasterized path
# has them.
"$render" "$scene" --size 160x100 --gi off --reference --spp 4 --path "$out/hold.path.json" --fps 1 \
    --frames-out "$out/reference_frames" >"$out/reference_path.txt" 2>&1 ||
    { cat "$out/reference_path.txt"; fail "lit-render --reference --path failed"; }
[ -f "$out/reference_frames/frame_00002.png" ] && [ ! -f "$out/reference_frames/frame_00003.png" ] ||
    { ls "$out/reference_frames"; fail "--reference --path did not trace the frames at 0, 1 and 2 s"; }
check "$out/reference_frames/frame_00000.png" "reference path frame at 0 s" 1 1
check "$out/reference_frames/frame_00002.png" "reference path frame at 2 s" 0 0
# --time with --path: one still through the path at that time.
"$render" "$scene" --size 160x100 --gi off --path "$out/hold.path.json" --time 2 --out "$out/path_still.png" >"$out/path_still.txt" 2>&1 ||
    { cat "$out/path_still.txt"; fail "lit-render --path --time failed"; }
check "$out/path_still.png" "path still at 2 s" 0 0
echo "PASS"
