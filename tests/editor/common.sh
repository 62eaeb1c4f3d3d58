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

# xvfb_editor ARGS...: runs $editor with ARGS on an Xvfb screen of the size every editor test
# uses, returning its exit status.
xvfb_editor() {
    xvfb-run -a -s "-screen 0 1280x720x24" "$editor" "$@"
}

# run_editor ARGS...: the same, failing the test unless lit-editor exits 0.
run_editor() {
    xvfb_editor "$@"
    status=$?
    [ "$status" -eq 0 ] || fail "lit-editor $* exited with status $status"
}
