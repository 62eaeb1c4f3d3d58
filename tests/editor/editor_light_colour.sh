#!/bin/sh
# editor_light_colour.sh EDITOR IMAGE_STATS SCENE OUTDIR
# Makes the Cornell box's white light red through a --script run and checks that the viewport
# (screenshots without UI) changed the right way: green and blue fall, red stays and dominates.
# Each capture waits for the GI update to finish (wait gi: the cached mode spreads the bounce and
# the voxel irradiance over frames), so the indirect light is the edited light's too.
# Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
editor_timeout=540  # one run; CTest TIMEOUT 600
prepare_run "$scene" "$out"
before=$out/light_white.png
after=$out/light_red.png
rm -f "$before" "$after"

cat >"$out/light_colour.txt" <<SCRIPT
setting gi.voxelResolution 64
select ceiling_spot
wait gi
screenshot $before noui
set light.color 1 0 0
wait gi
screenshot $after noui
SCRIPT

run_editor "$scene" --script "$out/light_colour.txt" --size 640x360
[ -f "$before" ] && [ -f "$after" ] || fail "the script ran but did not write both screenshots"

# Columns: width height mean stddev meanR meanG meanB.
stats_before=$("$image_stats" "$before") || fail "cannot read $before"
stats_after=$("$image_stats" "$after") || fail "cannot read $after"
echo "white light: $stats_before"
echo "red light:   $stats_after"
set -- $stats_before
[ "$1" = 640 ] && [ "$2" = 360 ] || fail "expected a 640x360 viewport capture, got $1x$2"
r0=$5 g0=$6 b0=$7
set -- $stats_after
r1=$5 g1=$6 b1=$7
# The scene is lit only by this light (no emissive surfaces, no ambient term), so under a pure red
# light green and blue can only come from tone-mapping noise: they must at least halve, while
# red (white walls reflect all of it) must stay within a fifth of what it was and dominate.
awk -v r0="$r0" -v g0="$g0" -v b0="$b0" -v r1="$r1" -v g1="$g1" -v b1="$b1" 'BEGIN {
    if (!(r0 > 20)) { print "the white-light render is too dark to judge (mean red " r0 ")"; exit 1 }
    if (!(g1 < 0.5 * g0 && b1 < 0.5 * b0)) { print "green/blue did not fall: " g0 "," b0 " -> " g1 "," b1; exit 1 }
    if (!(r1 > 0.8 * r0)) { print "red fell from " r0 " to " r1; exit 1 }
    if (!(r1 > 2 * g1 && r1 > 2 * b1)) { print "red does not dominate: " r1 " vs " g1 ", " b1; exit 1 }
}' || fail "the light colour edit did not change the render as expected"
echo "PASS: mean RGB ($r0, $g0, $b0) -> ($r1, $g1, $b1)"
