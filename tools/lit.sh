#!/usr/bin/env bash
# Lit's one entry point for people and CI.
#
#   tools/lit.sh editor [SCENE]   install what is missing, build, open the editor (default: Cornell box)
#   tools/lit.sh test             install what is missing, build, run the whole test suite
#   tools/lit.sh test-sanitize    the same with AddressSanitizer + UndefinedBehaviorSanitizer
#   tools/lit.sh build            install what is missing and build
#   tools/lit.sh build-release    build the programs as Release (in build-release/), no tests
#   tools/lit.sh build-types      build Debug, Release and MinSizeRel with the tests (build-<type>/)
#                                 and run each one's CPU tests (RelWithDebInfo is what `test` builds)
#   tools/lit.sh install PREFIX   build Release and install lit-render, lit-editor, shaders, assets
#   tools/lit.sh deps             only install what is missing
#
# Environment: LIT_BUILD_DIR (default build/), LIT_JOBS (default: number of cores).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="${LIT_JOBS:-$(nproc 2>/dev/null || echo 2)}"

# The project's own builds treat warnings as errors (LIT_WERROR); later -D arguments win.
build() {
    local dir="$1"; shift
    cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLIT_WERROR=ON "$@" >/dev/null
    cmake --build "$dir" -j "$jobs"
}

command="${1:-}"
[ $# -gt 0 ] && shift
case "$command" in
    deps)
        "$root/tools/install-deps.sh"
        ;;
    build)
        "$root/tools/install-deps.sh"
        build "${LIT_BUILD_DIR:-$root/build}"
        ;;
    build-release)
        "$root/tools/install-deps.sh"
        build "${LIT_RELEASE_BUILD_DIR:-$root/build-release}" -DCMAKE_BUILD_TYPE=Release -DLIT_BUILD_TESTS=OFF
        ;;
    build-types)
        "$root/tools/install-deps.sh"
        for type in Debug Release MinSizeRel; do
            dir="$root/build-$(echo "$type" | tr '[:upper:]' '[:lower:]')"
            echo "lit: $type in $dir" >&2
            build "$dir" -DCMAKE_BUILD_TYPE="$type"
            (cd "$dir" && ctest -L cpu --output-on-failure -j "$jobs" --timeout 900)
        done
        ;;
    install)
        [ $# -eq 1 ] || { echo "usage: tools/lit.sh install PREFIX" >&2; exit 2; }
        "$root/tools/install-deps.sh"
        dir="${LIT_RELEASE_BUILD_DIR:-$root/build-release}"
        build "$dir" -DCMAKE_BUILD_TYPE=Release -DLIT_BUILD_TESTS=OFF
        cmake --install "$dir" --prefix "$1"
        ;;
    editor)
        "$root/tools/install-deps.sh"
        dir="${LIT_BUILD_DIR:-$root/build}"
        build "$dir"
        if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
            echo "lit: no display (DISPLAY is unset); starting the editor under xvfb-run instead." >&2
            echo "lit: for a visible window run it from a desktop session." >&2
            exec xvfb-run -a -s "-screen 0 1280x720x24" "$dir/editor/lit-editor" "$@"
        fi
        exec "$dir/editor/lit-editor" "$@"
        ;;
    test)
        "$root/tools/install-deps.sh"
        dir="${LIT_BUILD_DIR:-$root/build}"
        build "$dir"
        cd "$dir"
        ctest --output-on-failure -j "$jobs" --timeout 900
        ;;
    test-sanitize)
        "$root/tools/install-deps.sh"
        dir="${LIT_BUILD_DIR:-$root/build-sanitize}"
        build "$dir" -DLIT_SANITIZE=ON
        cd "$dir"
        # llvmpipe and the X libraries keep allocations for the process lifetime: leaks inside
        # them are not ours, so LeakSanitizer is off; ASan and UBSan still stop on any error.
        ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
            ctest --output-on-failure -j "$jobs" --timeout 1800
        ;;
    *)
        sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
        exit 2
        ;;
esac
