# Shared by the editor test scripts (sourced): failing with a message, and skipping (exit 77,
# CTest's SKIP_RETURN_CODE for these tests) when there is no xvfb-run to give the editor an X
# server.

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
