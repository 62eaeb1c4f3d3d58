#!/bin/sh
# editor_real_input.sh EDITOR SCENE OUTDIR
# The timeline and Escape with a real mouse and keyboard (xdotool's XTEST events into the Xvfb
# server), as a user meets them, not through script commands:
#   - "+ Key" clicked three times: the playhead goes 0, 1, 2 s (keys a second apart);
#   - key 1's diamond dragged 48 px right (half a second on the ruler): key 1 at about 1.5 s;
#   - File menu opened, Escape: the menu closes (the next click on "+ Key" adds a fourth key at
#     3 s; an open menu would swallow it) and the selection stays;
#   - Escape again with nothing open: the selection is cleared (the keys reach the editor);
#   - Ctrl+Z twice: the fourth key goes, then the drag is undone (key 1 back at 1 s).
# Read from the frame log (playhead, selected node per frame). The pixel positions are those of
# the default layout at 1280x720 with the DejaVu Sans UI font (the screenshot after_ui.png shows
# them). Exit 77 (skipped) without xvfb-run, xdotool or that font.
set -u
editor=$1
scene=$2
out=$3

. "$(dirname "$0")/common.sh"
require_xvfb
command -v xdotool >/dev/null 2>&1 || { echo "SKIP: xdotool not found (Debian: apt-get install xdotool)"; exit 77; }
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || { echo "SKIP: DejaVu Sans missing: the UI's layout differs"; exit 77; }
prepare_run "$scene" "$out"
log=$out/frames.csv

# The script holds the editor in "wait" while the input arrives, then reads the keys back.
cat >"$out/input.txt" <<SCRIPT
setting gi.enabled false
panel stats off
select tall_box
screenshot $out/ready.png noui
wait 20s
screenshot $out/after_ui.png ui
key select 1
key select 2
SCRIPT

cat >"$out/drive.sh" <<'DRIVE'
#!/bin/sh
# Inside xvfb-run: the editor in the background, then the input once its first capture is written.
editor=$1; scene=$2; out=$3
"$editor" "$scene" --script "$out/input.txt" --size 1280x720 --frame-log "$out/frames.csv" >"$out/editor.txt" 2>&1 &
pid=$!
i=0
while [ ! -f "$out/ready.png" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i + 1)); done
sleep 0.5
click() { xdotool mousemove "$1" "$2"; sleep 0.2; xdotool click 1; sleep 0.5; }
# Keys are held 0.3 s and spaced out: the editor sees which keys went down once a frame
# (ImGuiLayer latches a short press for one frame), so two presses of a key within one frame,
# which a render of half a second on llvmpipe can span, count as one.
tap() { xdotool keydown "$1"; sleep 0.3; xdotool keyup "$1"; sleep 0.4; }
undo() { xdotool keydown ctrl; sleep 0.2; tap z; xdotool keyup ctrl; sleep 0.4; }
plus_key() { click 687 603; }
plus_key; plus_key; plus_key
# Key 1 sits at x 694 on the ruler (0..3 s over x 598..887); drag it 48 px right.
xdotool mousemove 694 695; sleep 0.3; xdotool mousedown 1; sleep 0.3
for x in 700 710 720 730 740 742; do xdotool mousemove "$x" 695; sleep 0.2; done
sleep 0.3; xdotool mouseup 1; sleep 0.5
click 22 10               # File menu
tap Escape
plus_key                  # reaches the button only if the menu closed
xdotool mousemove 640 300; sleep 0.2
tap Escape
undo
undo
wait "$pid"
DRIVE

xvfb_run 280 sh "$out/drive.sh" "$editor" "$scene" "$out"
status=$?
cat "$out/editor.txt"
[ "$status" -eq 0 ] || fail "lit-editor (or the input around it) exited with status $status"
[ -f "$log" ] || fail "no frame log"
head -1 "$log" | grep -q ',playhead_s,playing,camera_x,camera_y,camera_z,selected_node,gi_only,gi_update_done$' || fail "unexpected frame log header: $(head -1 "$log")"

# Columns: 1 frame, ..., 10 playhead_s, 11 playing, 12-14 camera, 15 selected_node. The rows
# where the playhead changes:
awk -F, 'NR > 1 && $10 != prev { print "frame " $1 ": playhead " $10 " s, selected node " $15; prev = $10 }' "$log"
tall_box=5  # the Cornell box's sixth node

awk -F, -v box="$tall_box" '
    function near(a, b, tol) { return (a - b) < tol && (b - a) < tol }
    NR == 1 { next }
    # The three "+ Key" clicks: the playhead steps to exactly 1 and 2 s, in that order.
    near($10, 1, 1e-4) && !seen2 { seen1 = 1 }
    near($10, 2, 1e-4) && seen1 && !seen3 { seen2 = 1 }
    # The drag: the playhead follows key 1 to about 1.5 s.
    seen2 && !seen3 && $10 > 1.35 && $10 < 1.65 { dragged = $10 }
    # The fourth key at 3 s, after the menu was closed with Escape: still selected then.
    near($10, 3, 1e-4) && !seen3 { seen3 = 1; selectedAtFourth = $15 }
    { last = $15; lastPlayhead = $10; beforeLastPlayhead = previousPlayhead; previousPlayhead = $10 }
    END {
        bad = 0
        if (!seen1 || !seen2) { print "+ Key did not move the playhead to 1 s and then 2 s"; bad = 1 }
        if (!dragged) { print "dragging key 1 half a second right did not move it to about 1.5 s"; bad = 1 }
        if (!seen3) { print "the click on + Key after Escape closed the menu added no key at 3 s"; bad = 1 }
        else if (selectedAtFourth != box) { print "Escape on the open menu changed the selection to " selectedAtFourth; bad = 1 }
        if (last != -1) { print "Escape with nothing open left node " last " selected"; bad = 1 }
        # The last two frames: "key select 1" then "key select 2", after the two undos.
        if (!near(beforeLastPlayhead, 1, 1e-4)) { print "after undoing the drag key 1 is at " beforeLastPlayhead " s, not 1"; bad = 1 }
        if (!near(lastPlayhead, 2, 1e-4)) { print "key 2 is at " lastPlayhead " s, not 2"; bad = 1 }
        exit bad
    }' "$log" || fail "the timeline or Escape did not answer the mouse and keyboard as expected"
echo "PASS"
