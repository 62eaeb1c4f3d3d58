#!/bin/sh
# editor_camera_path.sh EDITOR IMAGE_STATS SCENE OUTDIR
# The camera path as a user builds it: fly to a view and press "+ Key", three times from three
# views (script "key add", the same action). The keys must lie a second apart (0, 1, 2 s, not
# piled up at 0), the playhead must follow each new key, scrubbing ("time T") must show each
# view at its key's time, and play must move the viewport's camera through the three views to
# the last one, with the frames in between rendered. Checked in the frame log, whose rows carry
# the playhead and the camera position. Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
prepare_run "$scene" "$out"
log=$out/frames.csv

# Three views of the Cornell box, metres (its floor is at y 0, the opening faces +Z).
cat >"$out/path.txt" <<SCRIPT
setting gi.enabled false
panel stats off
camera -0.5 1 3 0 1 0
key add
wait 1
camera 0 1.2 2.5 0 1 0
key add
wait 1
camera 0.5 1 3 0 1 0
key add
wait 1
time 0
wait 1
time 1
wait 1
time 2
wait 1
screenshot $out/timeline.png ui
play 0.5
wait play
wait 1
save $out/path.gltf
SCRIPT

xvfb_editor "$scene" --script "$out/path.txt" --size 640x360 --frame-log "$log" >"$out/editor.txt" 2>&1
status=$?
cat "$out/editor.txt"
[ "$status" -eq 0 ] || fail "lit-editor exited with status $status"
[ -f "$log" ] || fail "the script ran but wrote no frame log"
head -1 "$log" | grep -q ',playhead_s,playing,camera_x,camera_y,camera_z,' || fail "unexpected frame log header: $(head -1 "$log")"

# Columns: 1 frame, 2 start_s, ..., 9 rendered, 10 playhead_s, 11 playing, 12-14 camera x y z.
# Frame N runs the script's command N (0-based, one a frame): frames 3, 6 and 9 the three
# "key add", 11, 13 and 15 the three "time", 18 "play".
awk -F, 'NR == 1 || ($1 >= 3 && $1 <= 16)' "$log"
awk -F, '
    function near(a, b, tol) { return (a - b) < tol && (b - a) < tol }
    $1 == 3 && !near($10, 0, 1e-3) { print "after the first + Key the playhead is at " $10 " s, not 0"; bad = 1 }
    $1 == 6 && !near($10, 1, 1e-3) { print "after the second + Key the playhead is at " $10 " s, not 1"; bad = 1 }
    $1 == 9 && !near($10, 2, 1e-3) { print "after the third + Key the playhead is at " $10 " s, not 2"; bad = 1 }
    END { exit bad }' "$log" || fail "+ Key did not move the playhead a second on each time"

# Scrubbing to each key time shows that key's view.
awk -F, '
    function near(a, b, tol) { return (a - b) < tol && (b - a) < tol }
    function expect(row, t, x, y, z) {
        if ($1 == row && !(near($10, t, 1e-3) && near($12, x, 1e-3) && near($13, y, 1e-3) && near($14, z, 1e-3))) {
            print "at " t " s the camera is at (" $12 ", " $13 ", " $14 "), not (" x ", " y ", " z ")"; bad = 1
        }
    }
    { expect(11, 0, -0.5, 1, 3); expect(13, 1, 0, 1.2, 2.5); expect(15, 2, 0.5, 1, 3) }
    END { exit bad }' "$log" || fail "scrubbing does not show the keys' views at their times"

# Play (at half speed, from the start since the playhead is at the end): the playing rows
# advance the playhead from 0 to 2 s; the row nearest each key time has the camera near that
# key's view (within the distance the path covers in the time between); the camera moves and
# the frames render; after the end the camera rests on the last view.
awk -F, '
    function abs(v) { return v < 0 ? -v : v }
    function dist(x, y, z, kx, ky, kz) { return sqrt((x - kx) ^ 2 + (y - ky) ^ 2 + (z - kz) ^ 2) }
    NR > 1 && $1 >= 18 && $11 == 1 {
        playing++
        if ($10 < last - 1e-6) { print "frame " $1 ": the playhead went back from " last " to " $10; bad = 1 }
        last = $10
        if ($9 == 1) rendered++
        if (playing > 1 && (abs($12 - px) > 1e-4 || abs($14 - pz) > 1e-4)) moved++
        px = $12; pz = $14
        for (k = 0; k < 3; k++) if (!(k in best) || abs($10 - k) < abs(best[k] - k)) { best[k] = $10; bx[k] = $12; by[k] = $13; bz[k] = $14 }
    }
    NR > 1 && $1 >= 18 && $11 == 0 && playing > 0 { endx = $12; endy = $13; endz = $14; endt = $10 }
    END {
        kx[0] = -0.5; ky[0] = 1;   kz[0] = 3
        kx[1] = 0;    ky[1] = 1.2; kz[1] = 2.5
        kx[2] = 0.5;  ky[2] = 1;   kz[2] = 3
        printf "play: %d frames playing, %d rendered, %d moved the camera\n", playing, rendered, moved
        if (playing < 4) { print "only " playing " frames played"; exit 1 }
        if (moved < 3) { print "the camera moved in only " moved " played frames"; bad = 1 }
        if (rendered < 3) { print "only " rendered " played frames rendered"; bad = 1 }
        for (k = 0; k < 3; k++) {
            # The views are 0.5-0.7 m apart a second apart: the path moves well under 2 m/s.
            d = dist(bx[k], by[k], bz[k], kx[k], ky[k], kz[k])
            printf "key %d: nearest played frame at %.3f s, camera %.3f m from the key view\n", k, best[k], d
            if (abs(best[k] - k) > 0.3) { print "no played frame within 0.3 s of " k " s"; bad = 1 }
            else if (d > 2 * abs(best[k] - k) + 0.01) { print "key " k ": the camera is " d " m from its view"; bad = 1 }
        }
        if (abs(endt - 2) > 1e-3 || dist(endx, endy, endz, 0.5, 1, 3) > 1e-3) {
            print "after play the playhead is at " endt " s and the camera at (" endx ", " endy ", " endz ")"; bad = 1
        }
        exit bad
    }' "$log" || fail "play did not move the camera through the three views"

stats=$("$image_stats" "$out/timeline.png") || fail "no timeline screenshot"
echo "timeline.png: $stats"
echo "PASS"
