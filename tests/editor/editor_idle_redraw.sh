#!/bin/sh
# editor_idle_redraw.sh EDITOR SCENE OUTDIR
# Redraw on demand: once the GI has converged and nothing changes, the editor shows its last 3D
# image again instead of rendering it, so a frame costs the UI alone; while the refinement runs,
# frames advance the GI under its time budget and render the image only now and then. The
# Cornell box at 1280x720 (a render there takes 150 ms and more on llvmpipe) with --frame-log:
# - the frames that refined must have a median duration of at most 50 ms (20 frames a second);
# - after "wait refined", 40 frames in which nothing changes must all reuse the image (rendered
#   0) and their median duration must be at most 33 ms (30 frames a second).
# LIT_REDRAW_ON_DEMAND=false renders every frame instead, which must fail both bars (the check
# that the test can fail). Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
scene=$2
out=$3

. "$(dirname "$0")/common.sh"
prepare_run "$scene" "$out"
log=$out/frames.csv
rm -f "$log"

# 64³ voxels: the update and the refinement converge in a few dozen frames.
cat >"$out/idle.txt" <<SCRIPT
setting gi.voxelResolution 64
setting editor.redrawOnDemand ${LIT_REDRAW_ON_DEMAND:-true}
wait refined
wait 40
quit
SCRIPT

xvfb_editor "$scene" --script "$out/idle.txt" --size 1280x720 --frame-log "$log" >"$out/editor.txt" 2>&1
status=$?
cat "$out/editor.txt"
[ "$status" -eq 0 ] || fail "lit-editor exited with status $status"
[ -f "$log" ] || fail "the script ran but wrote no frame log"
head -1 "$log" | grep -q ',refined_voxels,rendered,' || fail "unexpected frame log header: $(head -1 "$log")"

# Columns: frame,start_s,duration_ms,render_width,render_height,render_scale,camera_moved,refined_voxels,rendered,
# playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done
# The last 40 rows are the frames of "wait 40" (quit ends the loop before its frame).
rows=$(($(wc -l <"$log") - 1))
[ "$rows" -gt 40 ] || fail "only $rows frames in the log"
tail -n 40 "$log" >"$out/idle_frames.csv"
cat "$out/idle_frames.csv"
rendered=$(awk -F, '$9 == 1' "$out/idle_frames.csv" | wc -l)
median=$(cut -d, -f3 "$out/idle_frames.csv" | sort -n | awk '{ v[NR] = $1 } END { printf "%.2f", (v[20] + v[21]) / 2 }')
# For the record: what a frame that renders costs here (the frames before, while the GI converged).
render_median=$(head -n $((rows + 1 - 40)) "$log" | awk -F, 'NR > 1 && $9 == 1 { print $3 }' | sort -n |
    awk '{ v[NR] = $1 } END { if (NR) printf "%.2f", (v[int((NR + 1) / 2)] + v[int(NR / 2) + 1]) / 2; else print "none" }')
echo "idle frames: median $median ms, $rendered of 40 rendered; frames that rendered before: median $render_median ms"
awk -F, 'NR > 1 && $8 > 0 { print $3 }' "$log" | sort -n >"$out/refining_ms.txt"
refining=$(wc -l <"$out/refining_ms.txt")
refine_median=$(awk '{ v[NR] = $1 } END { if (NR) printf "%.2f", (v[int((NR + 1) / 2)] + v[int(NR / 2) + 1]) / 2 }' "$out/refining_ms.txt")
refine_rendered=$(awk -F, 'NR > 1 && $8 > 0 && $9 == 1' "$log" | wc -l)
echo "refining frames: $refining, median $refine_median ms, $refine_rendered of them rendered the image"
[ "$refining" -gt 0 ] || fail "no frame refined the GI"
awk -v m="$refine_median" 'BEGIN { exit !(m <= 50) }' || fail "the refining frames' median is $refine_median ms, over 50 ms"
[ "$rendered" -eq 0 ] || fail "$rendered of the 40 idle frames rendered the 3D image again"
awk -v m="$median" 'BEGIN { exit !(m <= 33) }' || fail "the idle frames' median is $median ms, over 33 ms"
echo "PASS"
