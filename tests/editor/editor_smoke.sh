#!/bin/sh
# editor_smoke.sh EDITOR IMAGE_STATS SCENE OUT.png
# Runs lit-editor under Xvfb in screenshot mode and checks that it exits 0 and writes a 640x360
# PNG that is not blank, both as a whole and in a patch of the viewport that no panel covers.
# Exit 77 (skipped) when xvfb-run is not installed.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
editor_timeout=540  # one run; CTest TIMEOUT 600
require_xvfb
[ -f "$scene" ] || fail "scene $scene not found"

mkdir -p "$(dirname "$out")"
rm -f "$out"
run_editor "$scene" --screenshot "$out" --frames 5 --size 640x360
[ -f "$out" ] || fail "lit-editor exited 0 but wrote no $out"

# Whole image: panels and the rendered scene give plenty of contrast; a blank or single-colour
# window has a standard deviation near 0.
stats=$("$image_stats" "$out") || fail "cannot read $out"
echo "whole image (width height mean stddev): $stats"
set -- $stats
[ "$1" = 640 ] && [ "$2" = 360 ] || fail "expected a 640x360 capture, got $1x$2"
awk -v sd="$4" 'BEGIN { exit !(sd > 10) }' || fail "the capture looks blank (stddev $4)"

# A patch between the stats overlay and the settings column, above the log, which only the
# viewport covers: the blit must have put the rendered scene there (not the dark clear colour).
stats=$("$image_stats" "$out" 290 60 70 180) || fail "cannot read the viewport patch of $out"
echo "viewport patch (width height mean stddev): $stats"
set -- $stats
awk -v mean="$3" 'BEGIN { exit !(mean > 30) }' || fail "the viewport looks empty (mean $3 of 255)"
echo "PASS: $out"
