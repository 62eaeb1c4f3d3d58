#!/usr/bin/env bash
# The sun room against Cycles: a closed room made in Blender (tools/blender/make_sun_room.py),
# lit only by a low sun through one window, so that most pixels are lit by bounced light alone.
# Renders it with Lit's defaults (the editor's converged image), with Lit's defaults and a given
# bounce count, and with Lit's reference path tracer (every bounce), and compares each, and the
# committed Cycles renders, with Cycles' render of the same file (every bounce) over the pixels lit
# only by bounced light (tools/room_accuracy.py explains the columns), renders the room with every
# material Lambertian (Lit's defaults and its reference) against Cycles' Diffuse BSDF render, and
# times the room at 1280×720: GI on against off, and a light edit's update. Writes
# docs/tables/room-accuracy.md, headed by the date, the commit and the machine.
#
# Usage: tools/room-accuracy.sh     (a built lit-render; python3 with numpy: install-deps.sh --scene-tools)
# Environment (all optional):
#   LIT_BUILD_DIR   build directory               (default: <repo>/build)
#   ROOM_SPP        reference samples per pixel   (default: 4096)
#   ROOM_VOXELS     voxel resolution              (default: 128, the renderer's default)
#   ROOM_OUT        the markdown file written     (default: <repo>/docs/tables/room-accuracy.md)
#   ROOM_COST_ROUNDS  interleaved rounds of GI off and on at 1280×720 (default: 3)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LIT_BUILD_DIR:-$root/build}"
render="$build/tools/lit-render"
scene_dir="$root/tests/data/blender/sun_room"
scene="$scene_dir/sun_room.gltf"
out="${ROOM_OUT:-$root/docs/tables/room-accuracy.md}"
spp="${ROOM_SPP:-4096}"
voxels="${ROOM_VOXELS:-128}"
cost_rounds="${ROOM_COST_ROUNDS:-3}"
size=160x100  # the Cycles renders' size (make_sun_room.py)
[ -x "$render" ] || { echo "room-accuracy: $render not found; build it first" >&2; exit 1; }
python="${PYTHON:-python3}"
"$python" -c "import numpy" 2>/dev/null || { echo "room-accuracy: $python needs numpy (tools/install-deps.sh --scene-tools, or set PYTHON)" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
quiet() { "$@" > "$tmp/log" 2>&1 || { cat "$tmp/log" >&2; exit 1; }; }
quiet "$render" "$scene" --size "$size" --gi off --hdr "$tmp/direct.hdr" --out "$tmp/direct.png"
quiet "$render" "$scene" --size "$size" --voxels "$voxels" --hdr "$tmp/lit.hdr" --out "$tmp/lit.png"
quiet "$render" "$scene" --size "$size" --voxels "$voxels" --bounces 2 --hdr "$tmp/lit2.hdr" --out "$tmp/lit2.png"
quiet "$render" "$scene" --size "$size" --voxels "$voxels" --single-frame --hdr "$tmp/lit1f.hdr" --out "$tmp/lit1f.png"
start=$(date +%s)
quiet "$render" "$scene" --size "$size" --reference --bounces all --spp "$spp" --hdr "$tmp/ref.hdr" --out "$tmp/ref.png"
ref_seconds=$(( $(date +%s) - start ))
quiet "$render" "$scene" --size "$size" --reference --bounces all --spp "$spp" --seed 2 --hdr "$tmp/ref2.hdr" --out "$tmp/ref2.png"
# Which surface each pixel sees, for the per-surface tables.
quiet "$render" "$scene" --size "$size" --reference --spp 1 --node-map "$tmp/nodes.txt" --out "$tmp/nodes.png"
# The room with every material Lambertian, as Cycles' Diffuse BSDF render has it: no specular layer
# (KHR_materials_specular factor 0) and no metal (the gold sphere a diffuse gold). Lit's defaults and
# its reference against that render tell the reference's transport from its BRDF, and Lit's diffuse
# transport from what its voxels make of specular light (the metal sphere's reflected sun).
mkdir -p "$tmp/lambert"
cp "$scene_dir"/*.bin "$tmp/lambert/"
"$python" - "$scene" "$tmp/lambert/sun_room.gltf" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
for material in scene.get("materials", []):
    material.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0.0}
    material.setdefault("pbrMetallicRoughness", {})["metallicFactor"] = 0.0
used = scene.setdefault("extensionsUsed", [])
if "KHR_materials_specular" not in used:
    used.append("KHR_materials_specular")
json.dump(scene, open(sys.argv[2], "w"))
PY
lambert="$tmp/lambert/sun_room.gltf"
quiet "$render" "$lambert" --size "$size" --gi off --hdr "$tmp/lambert-direct.hdr" --out "$tmp/lambert-direct.png"
quiet "$render" "$lambert" --size "$size" --voxels "$voxels" --hdr "$tmp/lambert-lit.hdr" --out "$tmp/lambert-lit.png"
quiet "$render" "$lambert" --size "$size" --reference --bounces all --spp "$spp" --hdr "$tmp/lambert-ref.hdr" \
    --out "$tmp/lambert-ref.png"

# The cost at the editor's size, 1280×720: ROOM_COST_ROUNDS interleaved rounds of GI off and the
# defaults, each the single-frame steady state benchmarks time (docs/PERFORMANCE.md, "The GI budget
# in benchmarks"); then a light edit's update, every bounce, against a re-voxelization, all in one
# frame (--bench-gi-updates), with the later bounces' change gathers (the default) and with every
# ray in every bounce; then the editor itself (under xvfb-run, when both are there): a light edit
# in a script, timed from the edit's frame to the frame that completes its update (--frame-log).
cost_size=1280x720
for round in $(seq "$cost_rounds"); do
    quiet "$render" "$scene" --size "$cost_size" --single-frame --gi off --bench 4 --json "$tmp/cost-off-$round.json"
    quiet "$render" "$scene" --size "$cost_size" --single-frame --voxels "$voxels" --bench 4 --json "$tmp/cost-on-$round.json"
done
quiet "$render" "$scene" --size "$cost_size" --single-frame --voxels "$voxels" --bench 1 --bench-gi-updates 3
cp "$tmp/log" "$tmp/edits.txt"
quiet "$render" "$scene" --size "$cost_size" --single-frame --voxels "$voxels" --set gi.laterBounceRayStride=1 \
    --bench 1 --bench-gi-updates 3
cp "$tmp/log" "$tmp/edits-every-ray.txt"
editor="$build/editor/lit-editor"
if [ -x "$editor" ] && command -v xvfb-run > /dev/null; then
    printf 'setting gi.voxelResolution %s\nwait gi\nwait 3\nselect sun\nset light.intensity 3\nwait gi\nwait 2\nquit\n' \
        "$voxels" > "$tmp/edit.lit"
    for round in $(seq "$cost_rounds"); do
        quiet xvfb-run -a -s "-screen 0 1400x900x24" "$editor" "$scene" --script "$tmp/edit.lit" --size "$cost_size" \
            --frame-log "$tmp/editor-$round.csv"
    done
fi
cost_rows="$("$python" - "$tmp" "$cost_rounds" <<'PY'
import csv, json, os, re, sys
tmp, rounds = sys.argv[1], int(sys.argv[2])
for r in range(1, rounds + 1):
    off = json.load(open(f"{tmp}/cost-off-{r}.json"))["frameMs"]["median"]
    on = json.load(open(f"{tmp}/cost-on-{r}.json"))["frameMs"]["median"]
    print(f"| frame, round {r} | {off:.1f} | {on:.1f} | {on / off:.2f} |")
for name, what in (("edits.txt", "later bounces gather their change over 1 ray in 4"),
                   ("edits-every-ray.txt", "every ray in every bounce")):
    for line in open(f"{tmp}/{name}"):
        m = re.match(r"gi-update round (\d+): light edit ([\d.]+) ms .* re-voxelize ([\d.]+) ms", line)
        if m:
            print(f"| light edit, every bounce in one frame, {what}, round {m[1]} (GPU ms; re-voxelization "
                  f"{float(m[3]):.0f}) | | {float(m[2]):.0f} | |")
for r in range(1, rounds + 1):
    path = f"{tmp}/editor-{r}.csv"
    if not os.path.exists(path):
        continue
    rows = list(csv.DictReader(open(path)))
    done = [float(x["gi_update_done"]) for x in rows]
    first = next(i for i, d in enumerate(done) if d >= 1.0)          # the scene's own update
    edit = next(i for i in range(first, len(done)) if done[i] < 1.0)  # the light edit's frame
    end = next(i for i in range(edit, len(done)) if done[i] >= 1.0)   # the frame that completes it
    start = float(rows[edit]["start_s"])
    seconds = float(rows[end]["start_s"]) + float(rows[end]["duration_ms"]) / 1000.0 - start
    renders = sum(int(rows[i]["rendered"]) for i in range(edit, end + 1))
    print(f"| light edit in the editor (every bounce, spread under its time budget), round {r}: {end - edit + 1} "
          f"frames, {renders} of them rendered, from the edit's frame to the one that completes the update "
          f"| | {seconds * 1000.0:.0f} | |")
PY
)"

rows="$("$python" "$root/tools/room_accuracy.py" "$tmp/direct.hdr" "$scene_dir/sun_room_cycles.hdr" --nodes "$tmp/nodes.txt" \
    "Lit, defaults (${voxels}³, converged)=$tmp/lit.hdr" \
    "Lit, one frame's GI (--single-frame)=$tmp/lit1f.hdr" \
    "Lit, two bounces=$tmp/lit2.hdr" \
    "Lit reference, every bounce, ${spp} spp=$tmp/ref.hdr" \
    "Cycles, Diffuse BSDF materials=$scene_dir/sun_room_cycles_diffuse.hdr")"
rows_ref="$("$python" "$root/tools/room_accuracy.py" "$tmp/direct.hdr" "$tmp/ref.hdr" --second-seed "$tmp/ref2.hdr" --nodes "$tmp/nodes.txt" \
    "Lit, defaults (${voxels}³, converged)=$tmp/lit.hdr" \
    "Lit, one frame's GI (--single-frame)=$tmp/lit1f.hdr" \
    "Lit reference, second seed=$tmp/ref2.hdr")"
rows_lambert="$("$python" "$root/tools/room_accuracy.py" "$tmp/lambert-direct.hdr" "$scene_dir/sun_room_cycles_diffuse.hdr" \
    --nodes "$tmp/nodes.txt" \
    "Lit, defaults (${voxels}³, converged)=$tmp/lambert-lit.hdr" \
    "Lit reference, every bounce, ${spp} spp=$tmp/lambert-ref.hdr")"
# Lit's own sampling noise: one frame's GI against the refined still (each voxel's 16 ray sets).
rows_self="$("$python" "$root/tools/room_accuracy.py" "$tmp/direct.hdr" "$tmp/lit.hdr" \
    "Lit, one frame's GI (--single-frame)=$tmp/lit1f.hdr")"

. "$root/tools/table-stamp.sh"
commit="$(table_commit "$root")"
cpu="$(table_cpu)"
cycles="$("$python" -c "import json,sys; d=json.load(open(sys.argv[1])); c=d['cycles']; print(f\"Blender {d['blender']}, Cycles {c['samples']} samples, {c['bounces']}\")" "$scene_dir/sun_room_cycles.json")"
mkdir -p "$(dirname "$out")"
{
    echo "# The sun room against Cycles"
    echo
    echo "Generated by \`tools/room-accuracy.sh\`; rerun it to refresh. What the columns mean: docs/GI.md,"
    echo "\"Accuracy against the reference\" (the sun room), and \`tools/room_accuracy.py\`."
    echo
    echo "- Date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "- Commit: $commit"
    echo "- Machine: $cpu; load average at the end of the run: $(table_load)"
    echo "- Scene: \`tests/data/blender/sun_room\` (tools/blender/make_sun_room.py), ${size/x/×} pixels; truth: $cycles"
    echo "- Lit's reference: $spp spp, every bounce, ${ref_seconds} s"
    echo
    echo "Against Cycles (Principled BSDF materials, as exported), $(echo "$rows" | head -1):"
    echo
    echo "| image | mean ÷ Cycles | RMSE | blotches (7×7 box, level matched) |"
    echo "|---|---:|---:|---:|"
    echo "$rows" | tail -n +2
    echo
    echo "Against Lit's reference (the same BRDF), $(echo "$rows_ref" | head -1):"
    echo
    echo "| image | mean ÷ reference | RMSE | blotches (7×7 box, level matched) | RMSE − the reference's noise |"
    echo "|---|---:|---:|---:|---:|"
    echo "$rows_ref" | tail -n +2
    echo
    echo "Every material Lambertian (the scene with KHR_materials_specular factor 0 and metallic 0, the gold"
    echo "sphere a diffuse gold) against Cycles' Diffuse BSDF render, $(echo "$rows_lambert" | head -1):"
    echo
    echo "| image | mean ÷ Cycles | RMSE | blotches (7×7 box, level matched) |"
    echo "|---|---:|---:|---:|"
    echo "$rows_lambert" | tail -n +2
    echo
    echo "Lit's own sampling noise: against Lit's defaults (converged, every voxel's 16 ray sets), $(echo "$rows_self" | head -1):"
    echo
    echo "| image | mean ÷ Lit converged | RMSE | blotches (7×7 box, level matched) |"
    echo "|---|---:|---:|---:|"
    echo "$rows_self" | tail -n +2
    echo
    echo "The cost at ${cost_size/x/×}, ${voxels}³ (wall ms; GPU ms where it says; on this machine's llvmpipe): the steady frame"
    echo "is the median of 4 frames, GI off and on interleaved per round; a light edit's update runs until its"
    echo "bounces converge; the editor's time is wall time at the editor's default budget (GI ms / frame, GI ms"
    echo "/ idle frame), its frames included:"
    echo
    echo "| what | GI off (ms) | GI on (ms) | on ÷ off |"
    echo "|---|---:|---:|---:|"
    echo "$cost_rows"
} > "$out"
echo "room-accuracy: wrote $out"
