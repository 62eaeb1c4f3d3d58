#!/bin/sh
# editor_bad_script.sh EDITOR SCENE OUTDIR
# A script with an unknown command or a bad value must stop lit-editor with status 2 before a
# window opens, naming the file and line; these runs have no X server (DISPLAY unset), so a
# window attempt would fail differently. A command that fails while running (a node without a
# light) must exit 1 naming its line: that part needs xvfb-run and is skipped without it.
set -u
editor=$1
scene=$2
out=$3

. "$(dirname "$0")/common.sh"
editor_timeout=200  # one run under Xvfb after the quick ones; CTest TIMEOUT 300

mkdir -p "$out"

# expect_parse_error NAME LINE WORD: runs script NAME, expects status 2 and "NAME:LINE:" and WORD
# in the message.
expect_parse_error() {
    messages=$(env -u DISPLAY timeout -k 5 60 "$editor" "$scene" --script "$out/$1" --size 64x64 2>&1)
    status=$?
    echo "$messages"
    [ "$status" -eq 2 ] || fail "$1: expected exit status 2, got $status"
    echo "$messages" | grep -q "$1:$2:" || fail "$1: the message does not name line $2"
    echo "$messages" | grep -q "$3" || fail "$1: the message does not mention '$3'"
}

printf '# comment\nselect tall_box\nselec floor\nquit\n' >"$out/unknown_command.txt"
expect_parse_error unknown_command.txt 3 selec

printf 'select tall_box\n\nwait soon\n' >"$out/bad_wait.txt"
expect_parse_error bad_wait.txt 3 soon

printf 'panel inspector on\npanel inspector maybe\n' >"$out/bad_panel.txt"
expect_parse_error bad_panel.txt 2 maybe

printf 'view final\nview nonsense\n' >"$out/bad_view.txt"
expect_parse_error bad_view.txt 2 nonsense

messages=$(env -u DISPLAY timeout -k 5 60 "$editor" "$scene" --script "$out/no_such_script.txt" 2>&1)
status=$?
echo "$messages"
[ "$status" -eq 2 ] || fail "a missing script file: expected exit status 2, got $status"
echo "$messages" | grep -q "no_such_script.txt" || fail "a missing script file: the message does not name it"

if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "PASS (parse errors only; xvfb-run not found, so the run-time error was not tried)"
    exit 0
fi
printf 'setting gi.voxelResolution 64\nsetting gi.enabled false\nselect floor\nset light.color 1 0 0\nquit\n' >"$out/runtime_error.txt"
messages=$(xvfb_editor "$scene" --script "$out/runtime_error.txt" --size 160x90 2>&1)
status=$?
echo "$messages" | tail -n 5
[ "$status" -eq 1 ] || fail "runtime_error.txt: expected exit status 1, got $status"
echo "$messages" | grep -q "runtime_error.txt:4:" || fail "runtime_error.txt: the message does not name line 4"
echo "PASS"
