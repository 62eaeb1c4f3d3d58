#!/usr/bin/env bash
# Re-renders the golden images under tests/golden/ from the current renderer. Run it after an
# intended visual change, LOOK at every changed image (git diff --stat tests/golden; open them),
# and commit them with the change that caused them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${LIT_BUILD_DIR:-$root/build}"
cmake --build "$dir" --target lit_gl_tests -j "$(nproc)"
LIT_UPDATE_GOLDENS=1 "$dir/tests/lit_gl_tests" --gtest_filter='*Golden*'
git -C "$root" status --short tests/golden
