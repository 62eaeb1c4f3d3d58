#!/bin/sh
# editor_walkthrough.sh EDITOR IMAGE_STATS SCENE OUTDIR
# Walks through every panel and every debug view of lit-editor with a --script run and checks
# the screenshots: each is not blank, each view differs from every other view, and hiding each
# panel changes the window. Also runs the camera path workflow of the timeline (add keys, move
# one, undo, play) and checks that the undo really restored the key. Exit 77 without xvfb-run.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
editor_timeout=840  # one run; CTest TIMEOUT 900
prepare_run "$scene" "$out"

views="final direct-diffuse indirect-diffuse direct-specular indirect-specular albedo normal roughness-metalness shadow-map voxels voxel-slice"
panels="hierarchy inspector settings stats camera log timeline"
script=$out/walkthrough.txt
{
    echo "setting gi.voxelResolution 64"
    echo "select tall_box"
    echo "wait 2"
    echo "screenshot $out/panels_all.png ui"
    for panel in $panels; do
        echo "panel $panel off"
        echo "wait 1"
        echo "screenshot $out/panel_without_$panel.png ui"
        echo "panel $panel on"
    done
    echo "select -"
    for view in $views; do
        echo "view $view"
        echo "wait 1"
        echo "screenshot $out/view_$view.png noui"
    done
    # The voxel slice's other channels and axes.
    for channel in albedo normal opacity; do
        echo "setting debug.voxelChannel $channel"
        echo "wait 1"
        echo "screenshot $out/view_voxel-slice-$channel.png noui"
    done
    echo "setting debug.voxelSliceAxis 1"
    echo "wait 1"
    echo "screenshot $out/view_voxel-slice-y.png noui"
    # Cone directions: pick a pixel on the floor (window pixels, top-left origin).
    echo "view cone-directions"
    echo "wait 1"
    echo "pick 320 330"
    echo "wait 1"
    echo "screenshot $out/view_cone-directions.png noui"
    echo "view final"
    # The timeline: three keys, move one, undo the move, play, screenshot.
    echo "time 0"
    echo "key add"
    echo "time 2"
    echo "key add"
    echo "time 4"
    echo "key add"
    echo "key time 1 3"
    echo "undo"
    echo "key select 1"
    echo "play"
    echo "wait 2"
    echo "screenshot $out/timeline.png ui"
    echo "save $out/with_path.gltf"
} >"$script"

run_editor "$scene" --script "$script" --size 640x360

# Every screenshot exists and is not blank (a single colour has a standard deviation near 0).
for file in "$out"/*.png; do
    stats=$("$image_stats" "$file") || fail "cannot read $file"
    set -- $stats
    echo "$(basename "$file"): mean $3 stddev $4"
    awk -v sd="$4" 'BEGIN { exit !(sd > 2) }' || fail "$(basename "$file") looks blank (stddev $4)"
done
count=$(ls "$out"/*.png | wc -l)
expected=$((1 + 7 + 11 + 4 + 1 + 1))
[ "$count" -eq "$expected" ] || fail "expected $expected screenshots, found $count"

# Different views must give different images; hiding a panel must change the window.
dupes=$(md5sum "$out"/view_*.png | awk '{ print $1 }' | sort | uniq -d)
[ -z "$dupes" ] || fail "two debug views gave identical images: $(md5sum "$out"/view_*.png | grep "$dupes")"
all=$(md5sum <"$out/panels_all.png")
for panel in $panels; do
    [ "$(md5sum <"$out/panel_without_$panel.png")" != "$all" ] || fail "hiding the $panel panel changed nothing"
done

# The saved path has three keys, key 1 back at 2 s after the undo.
grep -q '"camera path"' "$out/with_path.gltf" || fail "the saved scene has no camera path animation"
echo "PASS: $count screenshots, all views distinct"
