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

# xvfb_run SECONDS COMMAND ARGS...: COMMAND under xvfb-run on a 1280x720 screen, stopped after
# SECONDS (as xvfb_editor says), returning COMMAND's exit status or timeout's. The X authority
# file lives in a folder of ours: xvfb-run's own temporary folder now and then fails to be
# removed as a run ends, and xvfb-run then exits 5 in place of the command's status.
xvfb_run() {
    xvfb_limit_s=$1
    shift
    xauth_dir=$(mktemp -d "${TMPDIR:-/tmp}/lit-xauth.XXXXXX") || fail "cannot create a temporary folder"
    : >"$xauth_dir/Xauthority"
    timeout -k 10 "$xvfb_limit_s" xvfb-run -a -f "$xauth_dir/Xauthority" -s "-screen 0 1280x720x24" "$@"
    xvfb_status=$?
    rm -rf "$xauth_dir"
    return "$xvfb_status"
}

# xvfb_editor ARGS...: runs $editor with ARGS on an Xvfb screen of the size every editor test
# uses, returning its exit status. Every run is bounded: $editor_timeout seconds (default 240;
# a script whose runs take longer sets it, below its CTest TIMEOUT divided by its runs). timeout
# signals its whole process group (xvfb-run, Xvfb and the editor; TERM, then KILL 10 s later),
# so a hung run fails with a message and leaves no process behind. xvfb-run -a picks a free
# display and, when a test running in parallel takes the same one first, tries the next.
xvfb_editor() {
    xvfb_run "${editor_timeout:-240}" "$editor" "$@"
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
