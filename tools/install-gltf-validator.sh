#!/usr/bin/env bash
# Installs the Khronos glTF-Validator (npm package "gltf-validator") for the test that validates
# the files Lit saves (tests/cli/validate_saved_gltf.cmake). Needs node and npm; nothing is
# fetched at build or test time: without this install the test skips with a message.
#
#   tools/install-gltf-validator.sh            # into ${XDG_CACHE_HOME:-~/.cache}/lit/gltf-validator
#   LIT_GLTF_VALIDATOR_DIR=/some/dir tools/install-gltf-validator.sh
set -euo pipefail

dir="${LIT_GLTF_VALIDATOR_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lit/gltf-validator}"
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    echo "lit: node and npm are needed (Debian: apt-get install nodejs npm)" >&2
    exit 1
fi
mkdir -p "$dir"
# The package is published only as 2.0.0-dev.* pre-releases; pin the one the tests were run with.
npm install --prefix "$dir" --no-audit --no-fund gltf-validator@2.0.0-dev.3.10
echo "lit: gltf-validator installed in $dir/node_modules/gltf-validator"
