#!/bin/sh
# editor_missing_scene.sh EDITOR OUT.png
# In screenshot mode a scene that cannot be loaded is fatal: lit-editor must exit non-zero, say
# which file it could not open, and write no screenshot. The scene is loaded before a window is
# opened, so this needs no X server (and cannot pass merely because there is none: the message
# is checked).
set -u
editor=$1
out=$2
missing=/nonexistent/lit-editor-test/missing-scene.gltf

. "$(dirname "$0")/common.sh"

mkdir -p "$(dirname "$out")"
rm -f "$out"
messages=$(timeout -k 5 40 "$editor" "$missing" --screenshot "$out" --frames 1 2>&1)  # CTest TIMEOUT 60
status=$?
echo "$messages"
[ "$status" -ne 0 ] || fail "lit-editor exited 0 for a missing scene"
echo "$messages" | grep -q "missing-scene.gltf" || fail "the error message does not name the scene file"
[ ! -e "$out" ] || fail "lit-editor wrote a screenshot although the scene could not be loaded"
echo "PASS: exit status $status"
