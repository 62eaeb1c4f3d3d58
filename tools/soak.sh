#!/usr/bin/env bash
# Soak test of the editor: a scripted session (edits, undo/redo, view switches, camera-path
# playback, re-voxelization, shader reloads) under xvfb-run for MINUTES; resident memory is
# sampled every 5 s, the editor logs what it holds at the end of every block of the script, and
# GL errors are counted in the editor's log.
#
#   tools/soak.sh MINUTES [WARMUP_SECONDS] [EDITOR]
#
# The script is one block of commands followed by `loop`, so it runs as long as the soak wants on
# any machine (blocks take 2.5 s here on an idle machine, 100 s on a loaded one). Each block ends
# with the `memory` command, which hands the free heap back to the system (as the editor does
# every 5 s) and logs the heap in use, the free heap and the resident size (editor/ProcessMemory.h):
# without the release first, a block end that fell just before the editor's periodic one counted
# up to 65 MB of freed voxel volumes as resident (a one-minute run: 187, 253, 188, 219 MB). Every block ends in the same state (64^3 voxels, final
# view, nothing selected), so block ends compare like with like; samples at arbitrary moments
# would differ by the 128^3 voxel volumes a block allocates and frees.
#
# Passes when, from the first block end after WARMUP_SECONDS (default 120: the bar is less than 5 %
# resident growth "from minute 2 to the end" of a 10-minute soak) to the last block end,
#   - the heap in use grows by less than 5 % (what the process has allocated and not freed: a
#     leak in our code or in the driver's malloc'd objects, llvmpipe's textures among them), and
#   - the resident size grows by less than 5 % (leaks outside malloc too: mappings, JIT code),
# and the log has no GL error. The editor hands freed heap pages back to the system every 5 s
# (ProcessMemory::releaseFreeHeap); without that glibc kept them resident below live blocks and
# RSS climbed by 20-35 MB over the first ~35 blocks while the heap in use stayed flat
# (docs/RELIABILITY.md, "Soak"). Without glibc's figures (another C library) the resident size
# alone is judged; under AddressSanitizer the heap in use alone (its quarantine holds freed
# memory resident for a while by design). At least two block ends after the warm-up are
# needed; a slow machine gets up to 2 minutes more to reach them. Prints the samples' files and
# one summary line:
#   soak: 10 min, 21 blocks, 120 samples, 20 shader reload lines, 0 GL errors: heap in use ... -> PASS
# Environment: LIT_SOAK_DIR (scratch and report folder, default build/soak), LIT_SOAK_SIZE (the
# window, default 640x360; the suite's one-minute run uses 320x180 so that a loaded machine gets
# through the two blocks it needs).
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
setting gi.voxelResolution 64
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
setting gi.enabled false
wait 2
setting gi.enabled true
setting gi.voxelResolution 128
wait 3
setting gi.voxelResolution 64
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
memory
BLOCK
}
script="$work/session.txt"
{ block; echo loop; } > "$script"

log="$work/editor.log"
samples="$work/rss.txt"        # every 5 s: seconds, RSS kB
block_ends="$work/blocks.txt"  # at each block end: seconds, block, heap in use, heap free, RSS (KiB)
pidfile="$work/editor.pid"
: > "$samples"
: > "$block_ends"
rm -f "$pidfile"
# The editor writes its own pid through a one-line wrapper: looking it up by name can find
# xvfb-run itself (its command line holds the editor's), which then outlives a TERM and leaves
# the editor running with nobody to stop it.
# timeout bounds the whole run even if this script is killed before it can stop the editor:
# it signals its process group (xvfb-run, Xvfb and the editor) 4 minutes after the planned end
# (start-up, the 2 minutes a slow machine may get, the stop).
# The editor runs with the default allocator, as users run it. (Until its periodic heap release
# the soak fixed glibc's mmap threshold at 1 MiB: freed 16 MiB voxel volumes raised the dynamic
# threshold, later ones came from the heap, and RSS showed plateaus of +40..60 MB for minutes.)
LIT_SHADER_DIR="$work/shaders" XDG_STATE_HOME="$work/state" \
    timeout -k 10 $((minutes * 60 + 240)) xvfb-run -a -s "-screen 0 1280x720x24" \
    bash -c 'echo $$ > "$0"; exec "$@"' "$pidfile" "$editor" "$work/scene/cornell_box.gltf" --size "${LIT_SOAK_SIZE:-640x360}" --script "$script" \
    > "$log" 2>&1 &
runner=$!

# Stops the editor, lets xvfb-run clean up its X server, and kills what is left after 10 s: the
# whole process group of timeout ($runner leads it), which holds xvfb-run, Xvfb and the editor.
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
        kill -TERM -- "-$runner" 2>/dev/null || kill -TERM "$runner" 2>/dev/null || true
        sleep 1
        kill -KILL -- "-$runner" 2>/dev/null || kill -KILL "$runner" 2>/dev/null || true
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
give_up=$((end + 120))
reload=0
next_sample=5
next_block=1
rss_of() { awk '/VmRSS/ {print $2}' "/proc/$1/status" 2>/dev/null || echo 0; }
# Block ends after the warm-up so far (the verdict needs two).
measured() { awk -v w="$warmup" '$1 >= w' "$block_ends" | wc -l; }
while kill -0 "$pid" 2>/dev/null; do
    now=$(date +%s)
    # Until MINUTES are over and two block ends after the warm-up are in, for at most 2 min more.
    if [ "$now" -ge "$give_up" ] || { [ "$now" -ge "$end" ] && [ "$(measured)" -ge 2 ]; }; then break; fi
    sleep 0.5
    elapsed=$(( $(date +%s) - start ))
    # The block's last command logs "memory: heap in use N KiB (...), heap free F KiB, resident R KiB".
    ends=$(grep -c "memory: heap in use" "$log" || true)
    while [ "$next_block" -le "$ends" ]; do
        grep "memory: heap in use" "$log" | sed -n "${next_block}p" |
            sed -E "s/.*heap in use ([0-9]+|unknown).*heap free ([0-9]+|unknown).*resident ([0-9]+) KiB.*/$elapsed $next_block \\1 \\2 \\3/" >> "$block_ends"
        next_block=$((next_block + 1))
    done
    if [ "$elapsed" -ge "$next_sample" ]; then
        echo "$elapsed $(rss_of "$pid")" >> "$samples"
        next_sample=$((next_sample + 5))
    fi
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
result=$(awk -v warmup="$warmup" -v errors="$gl_errors" -v samples="$samples" '
    function mb(kib) { return kib / 1024 }
    function growth(from, to) { return (to - from) * 100.0 / from }
    { t[NR] = $1; b[NR] = $2; use[NR] = $3; free[NR] = $4; rss[NR] = $5 }
    END {
        first = 0; for (i = 1; i <= NR; ++i) if (t[i] >= warmup) { first = i; break }
        if (first == 0 || first == NR) { printf "FAIL only %d block ends, %d after the %d s warm-up: too few to judge\n", NR, first ? NR - first + 1 : 0, warmup; exit }
        peak = 0; while ((getline line < samples) > 0) { split(line, f, " "); if (f[1] >= warmup && f[2] > peak) peak = f[2] }
        rssGrowth = growth(rss[first], rss[NR])
        span = sprintf("block %d (%d s) -> block %d (%d s)", b[first], t[first], b[NR], t[NR])
        if (use[first] == "unknown") {  # no allocator figures (not glibc): resident size alone
            verdict = (rssGrowth < 5.0 && errors == 0) ? "PASS" : "FAIL"
            printf "%s %s: resident %.1f -> %.1f MB (%+.1f %%; no heap figures, judged on resident size); peak of the 5 s samples after the warm-up %.1f MB\n",
                   verdict, span, mb(rss[first]), mb(rss[NR]), rssGrowth, mb(peak)
            exit
        }
        useGrowth = growth(use[first], use[NR])
        sanitizer = free[first] == "unknown"  # AddressSanitizer: no free-heap figure, RSS holds its quarantine
        verdict = (useGrowth < 5.0 && (sanitizer || rssGrowth < 5.0) && errors == 0) ? "PASS" : "FAIL"
        printf "%s %s: heap in use %.1f -> %.1f MB (%+.1f %%), %s %.1f -> %.1f MB (%+.1f %%); free heap %s -> %s MB, peak of the 5 s samples after the warm-up %.1f MB, first block end %.1f MB\n",
               verdict, span, mb(use[first]), mb(use[NR]), useGrowth, sanitizer ? "not judged (AddressSanitizer): resident" : "resident",
               mb(rss[first]), mb(rss[NR]), rssGrowth, sanitizer ? "?" : sprintf("%.1f", mb(free[first])), sanitizer ? "?" : sprintf("%.1f", mb(free[NR])),
               mb(peak), mb(rss[1])
    }' "$block_ends")
echo "soak samples: every 5 s $samples (seconds, RSS KiB), at block ends $block_ends (seconds, block, heap in use, free heap, RSS KiB); log: $log"
echo "soak: $minutes min, $(wc -l < "$block_ends") blocks, $(wc -l < "$samples") samples, $reloads shader reload lines, $gl_errors GL errors: ${result#* } -> ${result%% *}"
case "$result" in PASS*) exit 0 ;; *) echo "soak: FAIL" >&2; exit 1 ;; esac
