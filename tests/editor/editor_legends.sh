#!/bin/sh
# editor_legends.sh EDITOR IMAGE_STATS SCENE OUTDIR
# Every debug view explains itself: at 1280x720 a script shows each view with its legend and
# without, takes both screenshots and logs the layout ("layout": the free viewport area, the
# legend's box and text, the performance overlay's box). Checked: each legend says what its view
# needs said (channels, axis and slice, cone colours, why the specular terms are dark), lies
# inside the free area clear of its centre, and really draws there (the pixels of its box differ
# from the same view without it, the area's centre does not); the performance overlay is two
# lines by default (a few per cent of the free area) and larger with its details on. Then the
# layout file: LIT_EDITOR_LAYOUT keeps the panels' choices from one run to the next, and a
# scripted run without it writes no layout anywhere (HOME pointed into OUTDIR). Exit 77 without
# xvfb-run.
set -u
editor=$1
image_stats=$2
scene=$3
out=$4

. "$(dirname "$0")/common.sh"
editor_timeout=400  # the longest of three runs; CTest TIMEOUT 900
prepare_run "$scene" "$out"
mkdir -p "$out/home"

views="direct-diffuse direct-specular indirect-diffuse indirect-specular albedo normal roughness-metalness shadow-map voxels voxel-slice cone-directions"
script=$out/legends.txt
{
    # The whole GI update in the edit's frame and no refinement after it: the 3D image stays the
    # same while only the legend is toggled, so the pictures with and without it compare.
    echo "setting gi.voxelResolution 64"
    echo "setting output.antialiasing false"  # the legend tests compare screenshots taken frames apart
    echo "setting editor.giUpdateVoxelsPerFrame 0"
    echo "setting editor.giRefineVoxelsPerFrame 0"
    echo "select -"
    echo "wait 2"
    echo "layout"
    echo "panel stats-details on"
    echo "wait 1"
    echo "layout"
    echo "panel stats-details off"
    for view in $views; do
        echo "view $view"
        [ "$view" = cone-directions ] && echo "pick 640 480"
        echo "wait 1"
        echo "screenshot $out/legend_$view.png ui"
        echo "layout"
        echo "panel legend off"
        echo "wait 1"
        echo "screenshot $out/plain_$view.png ui"
        echo "panel legend on"
    done
} >"$script"

# HOME and XDG_CONFIG_HOME point into OUTDIR: a scripted run must write no layout there.
HOME=$out/home XDG_CONFIG_HOME=$out/home/config run_editor "$scene" --script "$script" --size 1280x720 >"$out/log.txt" 2>&1 ||
    { cat "$out/log.txt"; fail "the legends script failed"; }
[ ! -e "$out/home/config" ] && [ ! -e "$out/home/.config" ] || fail "a scripted run wrote into the home folder"
[ ! -e imgui.ini ] || fail "an imgui.ini was written into the working folder"

layouts=$out/layouts.txt
grep "layout: " "$out/log.txt" >"$layouts"
[ "$(wc -l <"$layouts")" -eq $((2 + $(echo $views | wc -w))) ] || { cat "$out/log.txt"; fail "expected a layout line per view"; }

# "layout: area X Y W H; legend X Y W H; stats X Y W H; legend text: ..." -> the numbers.
numbers() { sed -n "${1}p" "$layouts" | sed 's/.*layout: area \([0-9 -]*\); legend \([0-9 -]*\); stats \([0-9 -]*\);.*/\1 \2 \3/'; }

# The compact overlay: two lines, a few per cent of the free area; with details, several times more.
set -- $(numbers 1)
compact=$(awk -v w="${11}" -v h="${12}" -v aw="$3" -v ah="$4" 'BEGIN { printf "%.1f", 100 * w * h / (aw * ah) }')
set -- $(numbers 2)
detailed=$(awk -v w="${11}" -v h="${12}" -v aw="$3" -v ah="$4" 'BEGIN { printf "%.1f", 100 * w * h / (aw * ah) }')
echo "performance overlay: $compact % of the free area by default, $detailed % with details"
awk -v c="$compact" 'BEGIN { exit !(c > 0 && c < 8) }' || fail "the compact overlay covers $compact % of the free area (at most 8 %)"
awk -v c="$compact" -v d="$detailed" 'BEGIN { exit !(d > 3 * c) }' || fail "the details do not show ($detailed % vs $compact %)"

# What each legend must say (a fixed string from its text).
expect() {
    case $1 in
        direct-diffuse) echo "W/(sr m^2) at +0.0 EV" ;;
        direct-specular | indirect-specular) echo "rough dielectric" ;;
        indirect-diffuse) echo "reflected diffusely" ;;
        albedo) echo "ramp albedo: 0 0.18 0.5 1" ;;
        normal) echo "| +X | -X | +Y" ;;
        roughness-metalness) echo "ramp R: roughness: 0 0.18 0.5 1 | ramp G: metalness" ;;
        shadow-map) echo "depth^32" ;;
        voxels) echo "Mip 0 of" ;;
        voxel-slice) echo "Axis Z, slice 32 of 64" ;;
        cone-directions) echo "diffuse cones" ;;
    esac
}

line=3
for view in $views; do
    text=$(sed -n "${line}p" "$layouts")
    set -- $(numbers $line)
    line=$((line + 1))
    ax=$1 ay=$2 aw=$3 ah=$4 lx=$5 ly=$6 lw=$7 lh=$8
    echo "$view: legend $lx $ly $lw $lh in area $ax $ay $aw $ah"
    want=$(expect "$view")
    case $text in *"$want"*) ;; *) fail "the $view legend does not say '$want': $text" ;; esac
    [ "$lw" -gt 40 ] && [ "$lh" -gt 20 ] || fail "the $view legend was not drawn ($lw x $lh)"
    awk -v ax="$ax" -v ay="$ay" -v aw="$aw" -v ah="$ah" -v lx="$lx" -v ly="$ly" -v lw="$lw" -v lh="$lh" 'BEGIN {
        inside = lx >= ax - 1 && ly >= ay - 1 && lx + lw <= ax + aw + 1 && ly + lh <= ay + ah + 1
        cx = ax + aw / 2; cy = ay + ah / 2
        centre = cx >= lx && cx <= lx + lw && cy >= ly && cy <= ly + lh
        exit !(inside && !centre) }' || fail "the $view legend is outside the free area or covers its centre"
    # Its pixels: the box differs from the view without it; the area's centre is the same.
    set -- $("$image_stats" "$out/legend_$view.png" "$lx" "$ly" "$lw" "$lh")
    with=$3
    set -- $("$image_stats" "$out/plain_$view.png" "$lx" "$ly" "$lw" "$lh")
    without=$3
    awk -v a="$with" -v b="$without" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d > 2) }' ||
        fail "the $view legend's box looks the same with and without it (mean $with vs $without)"
    cx=$((ax + aw / 2 - 10)) cy=$((ay + ah / 2 - 10))
    centre_with=$("$image_stats" "$out/legend_$view.png" "$cx" "$cy" 20 20 | cut -d' ' -f3)
    centre_without=$("$image_stats" "$out/plain_$view.png" "$cx" "$cy" 20 20 | cut -d' ' -f3)
    [ "$centre_with" = "$centre_without" ] || fail "the $view legend changed the area's centre ($centre_with vs $centre_without)"
done

# The layout file keeps the panels' choices from one run to the next.
layout=$out/layout/imgui.ini
printf 'setting gi.enabled false\nwait 1\npanel stats-details on\npanel legend off\nwait 2\n' >"$out/first.txt"
LIT_EDITOR_LAYOUT=$layout run_editor "$scene" --script "$out/first.txt" --size 1280x720 >"$out/first.log" 2>&1 ||
    { cat "$out/first.log"; fail "the first layout run failed"; }
[ -f "$layout" ] || fail "no layout file written to $layout"
grep -q '^panel.stats-details=1$' "$layout" && grep -q '^panel.legend=0$' "$layout" && grep -q '^\[Window\]\[Hierarchy\]$' "$layout" ||
    { cat "$layout"; fail "the layout file lacks the panels' choices or the windows"; }
printf 'setting gi.enabled false\nview albedo\nwait 2\nlayout\n' >"$out/second.txt"
LIT_EDITOR_LAYOUT=$layout run_editor "$scene" --script "$out/second.txt" --size 1280x720 >"$out/second.log" 2>&1 ||
    { cat "$out/second.log"; fail "the second layout run failed"; }
set -- $(grep "layout: " "$out/second.log" | sed 's/.*layout: area \([0-9 -]*\); legend \([0-9 -]*\); stats \([0-9 -]*\);.*/\1 \2 \3/')
[ "$7" -eq 0 ] || fail "the legend hidden in the first run came back in the second"
awk -v w="${11}" -v h="${12}" -v aw="$3" -v ah="$4" -v c="$compact" 'BEGIN { exit !(100 * w * h / (aw * ah) > 3 * c) }' ||
    fail "the overlay's details chosen in the first run were not kept"
echo "PASS: $(echo $views | wc -w) legends checked; overlay $compact % of the free area; layout kept between runs"
