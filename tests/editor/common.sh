# Shared by the editor test scripts (sourced): failing with a message, skipping (exit 77,
# CTest's SKIP_RETURN_CODE for these tests) when there is no xvfb-run to give the editor an X
# server, and running the editor ($editor, set by the sourcing script) under Xvfb.

fail() {
    echo "FAIL: $*"
    exit 1
}

require_xvfb() {
    if ! command -v xvfb-run >/dev/null 2>&1; then
        echo "SKIP: xvfb-run not found; the editor test needs an X server (Debian: apt-get install xvfb)"
        exit 77
    fi
}

# prepare_run SCENE OUT: skips without xvfb-run, fails without SCENE, and empties the output
# folder OUT (an earlier run's files must not pass for this run's).
prepare_run() {
    require_xvfb
    [ -f "$1" ] || fail "scene $1 not found"
    rm -rf "$2"
    mkdir -p "$2" || fail "cannot create $2"
}

# xvfb_editor ARGS...: runs $editor with ARGS on an Xvfb screen of the size every editor test
# uses, returning its exit status. Every run is bounded: $editor_timeout seconds (default 240;
# a script whose runs take longer sets it, below its CTest TIMEOUT divided by its runs). timeout
# signals its whole process group (xvfb-run, Xvfb and the editor; TERM, then KILL 10 s later),
# so a hung run fails with a message and leaves no process behind. xvfb-run -a picks a free
# display and, when a test running in parallel takes the same one first, tries the next.
xvfb_editor() {
    timeout -k 10 "${editor_timeout:-240}" xvfb-run -a -s "-screen 0 1280x720x24" "$editor" "$@"
    status=$?
    if [ "$status" -eq 124 ] || [ "$status" -eq 137 ]; then
        echo "FAIL: lit-editor $* did not finish within ${editor_timeout:-240} s and was stopped" >&2
    fi
    return "$status"
}

# run_editor ARGS...: the same, failing the test unless lit-editor exits 0.
run_editor() {
    xvfb_editor "$@"
    status=$?
    [ "$status" -eq 0 ] || fail "lit-editor $* exited with status $status"
}
