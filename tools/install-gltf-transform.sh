#!/usr/bin/env bash
# Installs glTF-Transform's command line (npm package "@gltf-transform/cli"), which makes the
# compressed test scenes (tools/make-compressed-scenes.sh) and lets the compression tests also
# compress at run time. Needs node and npm; nothing is fetched at build or test time: without
# this install those tests use the committed files and skip the run-time part with a message.
#
#   tools/install-gltf-transform.sh            # into ${XDG_CACHE_HOME:-~/.cache}/lit/gltf-transform
#   LIT_GLTF_TRANSFORM_DIR=/some/dir tools/install-gltf-transform.sh
set -euo pipefail

dir="${LIT_GLTF_TRANSFORM_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lit/gltf-transform}"
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    echo "lit: node and npm are needed (Debian: apt-get install nodejs npm)" >&2
    exit 1
fi
mkdir -p "$dir"
# Pinned: the committed scenes were made with this version.
npm install --prefix "$dir" --no-audit --no-fund @gltf-transform/cli@4.5.1
echo "lit: gltf-transform installed in $dir/node_modules/.bin/gltf-transform"
