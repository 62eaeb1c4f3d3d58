#!/bin/sh
# editor_gl_error.sh EDITOR SCENE OUTDIR
# A GL error in the editor must reach its log (the log panel, and stderr) in every build type: a
# release editor that did not install the GL debug output would leave its GL errors unseen.
# LIT_TEST_GL_ERROR=1 makes the editor issue one invalid GL call once its context is set up
# (gl::injectGlErrorIfRequested, GL_INVALID_OPERATION); the run must print it as an error line of
# the log and still finish its script normally. Exit 77 (skipped) without xvfb-run.
set -u
editor=$1
scene=$2
out=$3

. "$(dirname "$0")/common.sh"
editor_timeout=100  # one short run; CTest TIMEOUT 120
prepare_run "$scene" "$out"
printf 'setting gi.enabled false\nwait 1\nquit\n' >"$out/gl_error.txt"
messages=$(export LIT_TEST_GL_ERROR=1; xvfb_editor "$scene" --script "$out/gl_error.txt" --size 160x90 2>&1)
status=$?
echo "$messages" | tail -n 8
[ "$status" -eq 0 ] || fail "lit-editor exited with status $status after a GL error (expected it to log it and go on)"
echo "$messages" | grep -q "lit: error: GL error (api" || fail "the injected GL error is not in the editor's log"
echo "PASS: the GL error reached the log"
