#!/bin/sh
# editor_interactive.sh EDITOR SCENE OUTDIR
# The editor's responsiveness while the camera moves, from a --script run with "interactive on"
# and --frame-log: the frames whose camera moved render at a lowered scale (the target is set
# to 60 FPS, which no frame here meets) and the cached GI mode's refinement waits in them
# (refined_voxels 0), while the still frames before and after the motion refine and the ones
# after it render at full scale again; "wait refined" then lets the refinement finish: its rounds
# trace every occupied voxel 15 times in all, and the frames after it none. Exit 77 (skipped)
# without xvfb-run.
set -u
editor=$1
scene=$2
out=$3

. "$(dirname "$0")/common.sh"
editor_timeout=540  # one run; CTest TIMEOUT 600
prepare_run "$scene" "$out"
log=$out/frames.csv
rm -f "$log"

# 64³: the update is done in a few frames and the refinement (8192 voxels a frame, 15 rounds
# over ~23 000 voxels) runs for ~40 frames after it, longer than this script.
{
    echo "setting gi.voxelResolution 64"
    echo "setting editor.interactiveFpsTarget 60"
    echo "interactive on"
    echo "wait gi"
    echo "wait 3"
    for x in 0.05 0.1 0.15 0.2 0.25 0.3 0.35 0.4; do
        echo "camera $x 1 0.95 $x 1 -1"
    done
    echo "wait 4"
    # Then the refinement's end: every round over every voxel, nothing after it.
    echo "wait refined"
    echo "wait 2"
    echo "quit"
} >"$out/interactive.txt"

xvfb_editor "$scene" --script "$out/interactive.txt" --size 640x360 --frame-log "$log" >"$out/editor.txt" 2>&1
status=$?
cat "$out/editor.txt"
[ "$status" -eq 0 ] || fail "lit-editor exited with status $status"
# "inject 5.3 ms over 23393 occupied voxels": the refinement's rounds each trace all of them.
occupied=$(sed -n 's/.* over \([0-9]*\) occupied voxels.*/\1/p' "$out/editor.txt" | tail -1)
[ -n "$occupied" ] || fail "the editor did not log the occupied voxel count"
[ -f "$log" ] || fail "the script ran but wrote no frame log"
head -1 "$log" | grep -q ',camera_moved,refined_voxels,rendered,' || fail "unexpected frame log header: $(head -1 "$log")"
cat "$log"

# Columns: frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,rendered,
# playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done
awk -F, -v occupied="$occupied" -v rounds=15 'NR > 1 {
    total += $8; lastTwo = prev + $8; prev = $8
    if ($7 == 1) {
        ++moved
        if ($8 != 0) { print "frame " $1 ": the camera moved and the refinement traced " $8 " voxels"; bad = 1 }
        if ($6 < 1) ++lowered
    } else if (moved == 0) {
        if ($8 > 0) ++refinedBefore
    } else {
        # A still frame after the motion began (the camera commands run on consecutive frames).
        if ($8 > 0) ++refinedAfter
        if ($6 == 1) ++fullAfter
    }
}
END {
    if (moved < 6) { print "only " moved " frames with a camera motion in the log"; exit 1 }
    if (refinedBefore == 0) { print "no still frame before the motion refined: the test does not see the refinement"; exit 1 }
    if (lowered == 0) { print "no moving frame rendered at a lowered scale"; exit 1 }
    if (refinedAfter == 0) { print "the refinement did not go on after the motion"; exit 1 }
    if (fullAfter == 0) { print "no full-scale frame after the motion"; exit 1 }
    if (total != rounds * occupied) { print "the refinement traced " total " voxels in all, not " rounds " rounds of " occupied; exit 1 }
    if (lastTwo != 0) { print "the frames after wait refined still refined (" lastTwo " voxels)"; exit 1 }
    if (bad) exit 1
    print "moving frames " moved " (lowered scale in " lowered "), refining still frames before " refinedBefore ", after " refinedAfter
}' "$log" || fail "the refinement or the render scale did not follow the motion"
echo "PASS"
