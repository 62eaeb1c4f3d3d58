#!/usr/bin/env bash
# The GI accuracy benchmark: renders the suite (assets/cornell_box.gltf, assets/gi/*.gltf and
# Sponza from ../shared/scenes when it is there) with voxel cone tracing at several voxel
# resolutions and with the reference path tracer, and writes the tables into docs/GI.md between
# the markers "<!-- gi-accuracy:begin -->" and "<!-- gi-accuracy:end -->" (the rest of the file
# is kept). The measuring is done by build/tools/lit-gi-accuracy (tools/gi_accuracy/main.cpp,
# which explains every metric); regions come from renderer/reference/AccuracyRegions.h.
#
# Usage: tools/gi-accuracy.sh             (needs a built lit-gi-accuracy)
# Environment (all optional):
#   LIT_BUILD_DIR   build directory           (default: <repo>/build)
#   GI_VOXELS       voxel resolutions         (default: 64,128,256; add 512 when time allows —
#                   llvmpipe takes minutes per 512³ frame and ~3 GiB of memory)
#   GI_SPP          reference samples/pixel   (default: 256)
#   GI_SIZE         image side in pixels      (default: 128)
#   GI_SCENES       comma-separated subset: cornell_box,sealed_room,thin_walls,glossy_floor,sponza;
#                   the diagnostic Cornell variants cornell_room,cornell_mirrored,cornell_swapped
#                   (assets/gi) run only when named here
#   GI_OUT          the markdown file updated (default: <repo>/docs/GI.md)
#   GI_SHARED       the shared scenes folder  (default: <repo>/../shared/scenes; a git worktree
#                   elsewhere passes the main checkout's, e.g. GI_SHARED=/work/shared/scenes)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LIT_BUILD_DIR:-$root/build}"
tool="$build/tools/lit-gi-accuracy"
out="${GI_OUT:-$root/docs/GI.md}"
[ -x "$tool" ] || { echo "gi-accuracy: $tool not found; build it: cmake --build build --target lit-gi-accuracy" >&2; exit 1; }
[ -f "$out" ] || { echo "gi-accuracy: $out not found" >&2; exit 1; }

args=(--voxels "${GI_VOXELS:-64,128,256}" --spp "${GI_SPP:-256}" --size "${GI_SIZE:-128}")
[ -n "${GI_SCENES:-}" ] && args+=(--scenes "$GI_SCENES")
[ -n "${GI_SHARED:-}" ] && args+=(--shared "$GI_SHARED")
table="$(mktemp)"
trap 'rm -f "$table" "$table.md"' EXIT
"$tool" "${args[@]}" --out "$table"
{
    cat "$table"
    echo
    echo "Run on $(date -u +%Y-%m-%d), $(nproc) CPU cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'))."
} > "$table.md"

# Splice the table between the markers (appended with a heading when the file has none yet).
python3 - "$out" "$table.md" <<'PY'
import sys
path, table = sys.argv[1], open(sys.argv[2]).read().rstrip() + "\n"
text = open(path).read()
begin, end = "<!-- gi-accuracy:begin -->", "<!-- gi-accuracy:end -->"
if begin in text and end in text:
    head, rest = text.split(begin, 1)
    tail = rest.split(end, 1)[1]
    text = head + begin + "\n" + table + end + tail
else:
    text = text.rstrip() + "\n\n## Accuracy against the reference\n\n" + begin + "\n" + table + end + "\n"
tmp = path + ".tmp"
open(tmp, "w").write(text)
import os
os.replace(tmp, path)
PY
echo "wrote the accuracy table to $out"
