#!/usr/bin/env bash
# Soak test of the editor: a scripted session (edits, undo/redo, view switches, camera-path
# playback, re-voxelization, shader reloads) under xvfb-run for MINUTES; resident memory is
# sampled every 5 s and GL errors are counted in the editor's log.
#
#   tools/soak.sh MINUTES [WARMUP_SECONDS] [EDITOR]
#
# Passes when RSS grows by less than 5 % from WARMUP_SECONDS (default 120: the warm-up of
# llvmpipe's shader cache, the voxel volumes and ImGui's atlases) to the end, and the log has no
# GL error. Prints the samples and one summary line:
#   soak: 10 min, 120 samples, 20 shader reload lines, 0 GL errors: RSS 212.4 MB at 120 s -> 215.0 MB at end (+1.2 %, ...) -> PASS
# Environment: LIT_SOAK_DIR (scratch and report folder, default build/soak).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
minutes="${1:?usage: tools/soak.sh MINUTES [WARMUP_SECONDS] [EDITOR]}"
warmup="${2:-120}"
editor="${3:-$root/build/editor/lit-editor}"
work="${LIT_SOAK_DIR:-$root/build/soak}"
[ -x "$editor" ] || { echo "soak: no editor at $editor (build lit-editor first)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "soak: needs xvfb-run (apt-get install xvfb)" >&2; exit 77; }

rm -rf "$work" && mkdir -p "$work/shaders" "$work/scene" "$work/state"
cp -r "$root/shaders/." "$work/shaders/"
cp "$root/assets/cornell_box.gltf" "$root/assets/cornell_box.bin" "$work/scene/"

# One block of commands, ~100 frames; repeated far more often than MINUTES need (the session is
# ended by time, not by the script's end).
block() {
    cat <<'BLOCK'
setting voxelResolution 64
select tall_box
set node.translation 0.2 0.3 -0.1
wait 2
set node.rotation 0 25 0
undo
undo
redo
select ceiling_spot
set light.intensity 12
set light.color 1 0.8 0.6
undo
undo
view albedo
wait 2
view normal
wait 2
view voxels
wait 2
view indirect-diffuse
wait 2
view final
setting gi false
wait 2
setting gi true
setting voxelResolution 128
wait 3
setting voxelResolution 64
wait 3
key add
time 2
key add
play
wait 10
pause
key delete 1
key delete 0
select short_box
set material.roughness 0.3
set material.albedo 0.9 0.2 0.2
undo
undo
select -
wait 5
BLOCK
}
script="$work/session.txt"
: > "$script"
for _ in $(seq 1 $((minutes * 60 + 100))); do block >> "$script"; done

log="$work/editor.log"
samples="$work/rss.txt"
pidfile="$work/editor.pid"
: > "$samples"
rm -f "$pidfile"
# The editor writes its own pid through a one-line wrapper: looking it up by name can find
# xvfb-run itself (its command line holds the editor's), which then outlives a TERM and leaves
# the editor running with nobody to stop it.
LIT_SHADER_DIR="$work/shaders" XDG_STATE_HOME="$work/state" \
    xvfb-run -a -s "-screen 0 1280x720x24" \
    bash -c 'echo $$ > "$0"; exec "$@"' "$pidfile" "$editor" "$work/scene/cornell_box.gltf" --size 640x360 --script "$script" \
    > "$log" 2>&1 &
runner=$!

# Stops the editor, lets xvfb-run clean up its X server, and kills what is left after 10 s.
stop_all() {
    [ -n "${pid:-}" ] && kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 1 100); do
        kill -0 "$runner" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$runner" 2>/dev/null; then
        echo "soak: the editor did not stop on TERM within 10 s; killing it" >&2
        [ -n "${pid:-}" ] && kill -KILL "$pid" 2>/dev/null || true
        sleep 1
        kill -TERM "$runner" 2>/dev/null || true
        sleep 1
        kill -KILL "$runner" 2>/dev/null || true
    fi
    wait "$runner" 2>/dev/null || true
}
trap stop_all EXIT

pid=""
for _ in $(seq 1 600); do
    [ -s "$pidfile" ] && pid=$(cat "$pidfile") && break
    kill -0 "$runner" 2>/dev/null || break
    sleep 0.1
done
[ -n "$pid" ] || { echo "soak: the editor did not start within 60 s" >&2; cat "$log" >&2; exit 1; }

start=$(date +%s)
end=$((start + minutes * 60))
reload=0
while [ "$(date +%s)" -lt "$end" ] && kill -0 "$pid" 2>/dev/null; do
    sleep 5
    elapsed=$(( $(date +%s) - start ))
    rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || echo 0)
    echo "$elapsed $rss" >> "$samples"
    # A shader edit every 30 s: the editor reloads changed shader files (checked every 0.5 s).
    if [ $((elapsed / 30)) -gt "$reload" ]; then
        reload=$((elapsed / 30))
        echo "// soak reload $reload" >> "$work/shaders/tonemap.frag.glsl"
    fi
done
alive=1
kill -0 "$pid" 2>/dev/null || alive=0
stop_all
trap - EXIT
[ "$alive" -eq 1 ] || { echo "soak: the editor ended before $minutes min:" >&2; tail -20 "$log" >&2; exit 1; }

gl_errors=$(grep -c "error: GL " "$log" || true)
reloads=$(grep -ci "reloaded" "$log" || true)
result=$(awk -v warmup="$warmup" -v minutes="$minutes" -v errors="$gl_errors" '
    { t[NR] = $1; r[NR] = $2 }
    END {
        base = 0; for (i = 1; i <= NR; ++i) if (t[i] >= warmup) { base = r[i]; bt = t[i]; break }
        last = r[NR]; peak = 0; for (i = 1; i <= NR; ++i) if (t[i] >= warmup && r[i] > peak) peak = r[i]
        if (base == 0) { print "FAIL no sample after the warm-up"; exit }
        growth = (last - base) * 100.0 / base
        verdict = (growth < 5.0 && errors == 0) ? "PASS" : "FAIL"
        printf "%s RSS %.1f MB at %d s -> %.1f MB at end (%+.1f %%, peak %.1f MB), first sample %.1f MB\n",
               verdict, base / 1024, bt, last / 1024, growth, peak / 1024, r[1] / 1024
    }' "$samples")
echo "soak samples (seconds, RSS kB): $work/rss.txt; log: $log"
echo "soak: $minutes min, $(wc -l < "$samples") samples, $reloads shader reload lines, $gl_errors GL errors: ${result#* } -> ${result%% *}"
case "$result" in PASS*) exit 0 ;; *) echo "soak: FAIL" >&2; exit 1 ;; esac
