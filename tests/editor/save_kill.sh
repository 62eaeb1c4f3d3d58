#!/bin/sh
# Never lose work: SIGKILL a saving process at KILLS moments spread evenly over the whole save of
# a large document (.gltf + .bin + settings sidecar, ~7 MB), and an autosave likewise; after each
# kill, do what the next start does (open the document / the autosave recovery) and check that
# the document is the complete old or the complete new version and that no temporary, backup
# or journal is left. Usage: save_kill.sh HELPER OUT_DIR [KILLS]  (lit_save_kill_helper)
helper="$1"
out="$2"
kills="${3:-20}"
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$out" && mkdir -p "$out" || fail "cannot create $out"

# start_and_wait_ready MODE PATH VARIANT: starts the helper; returns when it has built the
# document (the save starts right after "ready"). Sets pid. The helper writes "ready" into a
# FIFO that one blocking read waits on (at most 60 s; building the document takes well under a
# second): no polling loop, whose thousands of forks cost more than the saves themselves, and
# the kill's delay counts from the moment the helper is ready.
start_and_wait_ready() {
    rm -f "$out/ready" && mkfifo "$out/ready" || fail "cannot make the FIFO $out/ready"
    "$helper" "$1" "$2" "$3" > "$out/ready" 2> "$out/helper.err" &
    pid=$!
    # End of file (empty) when the helper exits without saying it.
    line=$(timeout 60 head -n 1 "$out/ready")
    if [ "$line" != ready ]; then
        kill -9 "$pid" 2>/dev/null
        fail "the helper was not ready within 60 s: '$line' $(cat "$out/helper.err")"
    fi
}

# leftovers DIR: temporaries, backups and journals of an interrupted save.
leftovers() { ls -a "$1" | grep -E '\.tmp-|\.old-|\.lit-journal-' ; }

run_kills() {  # MODE (save|autosave)
    mode="$1"
    if [ "$mode" = save ]; then target="$out/doc/grid.gltf"; folder="$out/doc"; else target="$out/auto"; folder="$out/auto"; fi
    # The old version, complete; kept as a pristine copy to restore before every kill.
    rm -rf "$folder" "$out/pristine"
    mkdir -p "$folder"
    timeout -k 5 120 "$helper" "$mode" "$target" 0 > /dev/null || fail "$mode of version 0 failed"
    cp -a "$folder" "$out/pristine"
    # How long the save of the new version takes once the document is built (the helper times
    # it from "ready" to the end of the save and prints "saved in N ms").
    timeout -k 5 120 "$helper" "$mode" "$target" 1 > "$out/timing.txt" 2>&1 ||
        fail "$mode of version 1 failed: $(cat "$out/timing.txt")"
    duration=$(sed -n 's/^saved in \([0-9]*\) ms$/\1/p' "$out/timing.txt")
    [ -n "$duration" ] || fail "the helper did not say how long the $mode took: $(cat "$out/timing.txt")"
    [ "$duration" -gt 0 ] || duration=1
    echo "$mode: a complete save takes $duration ms; killing at $kills points over it"
    old=0; new=0
    k=1
    while [ "$k" -le "$kills" ]; do
        rm -rf "$folder" && cp -a "$out/pristine" "$folder"
        delay_ms=$(( duration * k / (kills + 1) ))
        start_and_wait_ready "$mode" "$target" 1
        sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
        kill -9 "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        if [ "$mode" = save ]; then
            result=$(timeout -k 5 120 "$helper" check "$target") || fail "kill $k at ${delay_ms} ms: the document does not load: $result"
        else
            result=$(timeout -k 5 120 "$helper" recover "$target") || fail "kill $k at ${delay_ms} ms: recovery failed: $result"
        fi
        case "$result" in
            "variant 0") old=$((old + 1)) ;;
            "variant 1") new=$((new + 1)) ;;
            *) fail "kill $k at ${delay_ms} ms: neither the old nor the new version: $result" ;;
        esac
        left=$(leftovers "$folder")
        [ -z "$left" ] || fail "kill $k at ${delay_ms} ms: left behind after the next start: $left"
        if [ "$mode" = save ]; then
            files=$(ls "$folder" | tr '\n' ' ')
            [ "$files" = "grid.bin grid.gltf grid.gltf.lit.json " ] || fail "kill $k: unexpected files after the next start: $files"
        else
            copies=$(ls "$folder" | grep -c '^autosave.*\.glb$')
            [ "$copies" -eq 1 ] || fail "kill $k: $copies autosave copies after the next start: $(ls "$folder")"
        fi
        k=$((k + 1))
    done
    echo "$mode: $kills kills: $old times the complete old version, $new times the complete new one, no leftovers"
}

run_kills save
run_kills autosave
echo "PASS"
