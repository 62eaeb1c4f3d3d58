#!/usr/bin/env bash
# The camera-flight table: `lit-render --bench-path` down the generated city's street
# (assets/gi/city.gltf, assets/city_street.path.json: 100 m in 10 s) under the editor's GI budget,
# with the near level scrolling (the defaults), the same without anti-aliasing, with the level
# voxelized and lit whole at every move (gi.voxelizeChangesOnly false), without a near level, and
# with GI off (the flicker figure's own floor: resampling the last frame at moving shadow edges),
# with and without anti-aliasing, with GI off and no shadow cascades, and with GI off and one
# 4096² map (edges about as sharp as the cascades', none of them moving). The variants run interleaved, FLIGHT_ROUNDS
# rounds, and each cell is the median over the rounds. Written to docs/tables/flight.md, headed
# by the date, the commit, this machine's GL renderer and CPU; docs/GI.md ("Near levels") and
# docs/PERFORMANCE.md say how to read it.
#
# Usage: tools/flight-table.sh            (from anywhere; needs a built lit-render and python3)
# Environment (all optional):
#   LIT_BUILD_DIR    build directory holding tools/lit-render   (default: <repo>/build)
#   FLIGHT_SIZE      image size WxH                              (default: 320x180)
#   FLIGHT_FPS       frames per second of the path               (default: 5: 51 frames)
#   FLIGHT_ROUNDS    interleaved rounds                          (default: 2)
#   FLIGHT_BUDGET    the GI budget's flags (default: the editor's while the camera moves:
#                    "--gi-update-per-frame 16384 --gi-refine-per-frame 0 --gi-ms-per-frame 25")
#   FLIGHT_OUT       the markdown file written          (default: <repo>/docs/tables/flight.md at
#                    320x180, docs/tables/flight-WxH.md at any other size)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LIT_BUILD_DIR:-$root/build}"
render="$build/tools/lit-render"
size="${FLIGHT_SIZE:-320x180}"
fps="${FLIGHT_FPS:-5}"
rounds="${FLIGHT_ROUNDS:-2}"
budget="${FLIGHT_BUDGET:---gi-update-per-frame 16384 --gi-refine-per-frame 0 --gi-ms-per-frame 25}"
default_out="$root/docs/tables/flight.md"
[ "$size" = 320x180 ] || default_out="$root/docs/tables/flight-$size.md"
out="${FLIGHT_OUT:-$default_out}"
[ -x "$render" ] || { echo "flight-table: build lit-render first ($render)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "flight-table: needs python3 to read the --json results" >&2; exit 1; }

results="$(mktemp -d)"
trap 'rm -rf "$results"' EXIT
variants=(scroll aliased whole none off offaliased flat sharp)
flags_scroll=()
flags_aliased=(--antialiasing off)
flags_offaliased=(--gi off --antialiasing off)
flags_whole=(--set gi.voxelizeChangesOnly=false)
flags_none=(--set gi.nearLevels=0)
flags_off=(--gi off)
flags_flat=(--gi off --set shadows.cascades=0)
flags_sharp=(--gi off --set shadows.cascades=0 --set shadows.mapSize=4096)
for ((round = 1; round <= rounds; ++round)); do
    for v in "${variants[@]}"; do
        declare -n extra="flags_$v"
        # shellcheck disable=SC2086
        "$render" "$root/assets/gi/city.gltf" --path "$root/assets/city_street.path.json" --fps "$fps" --bench-path \
            --size "$size" $budget "${extra[@]}" --json "$results/$v-$round.json" > "$results/$v-$round.txt" 2>&1 ||
            { echo "flight-table: the $v run failed:" >&2; tail -5 "$results/$v-$round.txt" >&2; exit 1; }
        echo "round $round, $v: $(grep -E '^flicker|^frame \(wall' "$results/$v-$round.txt" | tr -s ' ' | tr '\n' ' ')"
    done
done

. "$root/tools/table-stamp.sh"
python3 - "$results" "$out" "$rounds" "$size" "$fps" "$budget" "$(date -u '+%Y-%m-%d %H:%M UTC')" \
    "$(table_commit "$root")" "$(table_cpu)" "$(table_load)" <<'PY'
import json, statistics, sys
results, out, rounds, size, fps, budget, date, commit, cpu, load = sys.argv[1:]
rounds = int(rounds)
names = {"scroll": "near level scrolls (defaults)", "aliased": "near level scrolls, no anti-aliasing",
         "whole": "near level voxelized and lit whole at each move",
         "none": "no near level", "off": "GI off", "offaliased": "GI off, no anti-aliasing",
         "flat": "GI off, one shadow map over the scene (no cascades)",
         "sharp": "GI off, one 4096² shadow map over the scene (no cascades)"}
# The passes of a near level's move frame: the scroll, the voxelization of its slabs (or of the
# whole level) and what follows any voxelization before the spread update.
move_passes = ["near scroll", "near voxelize", "near solid voxels", "near mip lists", "near inject", "near mipmap"]
def med(values):
    return statistics.median(values) if values else 0.0
rows = {}
device = ""
for v in names:
    runs = [json.load(open(f"{results}/{v}-{r}.json")) for r in range(1, rounds + 1)]
    device = runs[0].get("device", device)
    def pass_stat(run, name, key="median"):
        for p in run["passes"]:
            if p["name"] == name and p["framesRan"] > 0:
                return p["gpuMs"][key], p["framesRan"]
        return 0.0, 0
    median_frame = med([r["frameMs"]["median"] for r in runs])
    worst_frame = med([r["frameMs"]["max"] for r in runs])
    move = med([sum(pass_stat(r, n)[0] for n in move_passes) for r in runs])
    scroll = med([pass_stat(r, "near scroll")[0] for r in runs])
    moves = med([pass_stat(r, "near inject")[1] for r in runs])
    lit = med([pass_stat(r, "near voxel irradiance")[1] for r in runs])
    cascades = med([pass_stat(r, "shadow cascades", "mean")[0] for r in runs])
    rows[v] = dict(median=median_frame, worst=worst_frame, move=move, scroll=scroll, moves=moves, lit=lit, cascades=cascades,
                   flicker=med([r["flickerPercent"] for r in runs]), flickerWorst=med([r["flickerWorstPercent"] for r in runs]),
                   frames=runs[0]["frames"])
with open(out, "w") as f:
    w = lambda s="": f.write(s + "\n")
    w("# Camera flight through the city")
    w()
    env = "" if size == "320x180" else f"FLIGHT_SIZE={size} "
    w(f"Generated by `{env}tools/flight-table.sh` on {date}, commit {commit}, {device}, {cpu}, load {load}.")
    w(f"`lit-render assets/gi/city.gltf --path assets/city_street.path.json --fps {fps} --bench-path --size {size} {budget}`:"
      f" 100 m down the street in {rows['scroll']['frames']} frames after a warm-up frame that converges the light;"
      f" each cell the median of {rounds} interleaved rounds. The near level moves every 8 m (an eighth of its 64 m side).")
    w()
    w("| variant | median frame (ms) | worst frame (ms) | worst ÷ median | move frame's GI work (ms) | ÷ median frame | of it the scroll (ms) | moves | frames the level's irradiance ran | shadow cascades, mean a frame (ms) | flicker mean | flicker worst pair |")
    w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for v, name in names.items():
        r = rows[v]
        ratio = r["worst"] / r["median"] if r["median"] > 0 else 0.0
        share = r["move"] / r["median"] if r["median"] > 0 and r["move"] > 0 else 0.0
        movecells = (f"{r['move']:.1f} | {share:.2f} | {r['scroll']:.1f} | {r['moves']:.0f} | {r['lit']:.0f}"
                     if v in ("scroll", "aliased", "whole") else "– | – | – | – | –")
        w(f"| {name} | {r['median']:.1f} | {r['worst']:.1f} | {ratio:.2f} | {movecells} | {r['cascades']:.1f} | {r['flicker']:.2f} % | {r['flickerWorst']:.2f} % |")
    w()
    w("Move frame's GI work: the medians, over the frames they ran in, of the near level's passes that a move runs"
      " before its spread update (scroll, voxelize, solid voxels, mip lists, inject, mipmap), GPU time. Frames the level's"
      " irradiance ran: the spread update reached its last stage (for the scroll, the uncovered slabs' light) in that many"
      " frames; 0: no update after a move completed during the flight. Shadow cascades: the camera's shadow maps"
      " drawn again (at most one a frame), GPU time over every frame. Flicker: `--bench-path`'s figure, the mean"
      " |frame-to-frame change| of pixels whose surface did not move, relative to the mean luminance; each pixel is"
      " compared with the previous frame interpolated where its point was, so sharper shadow edges raise it (the"
      " last two rows: no map moves there, the 4096² map's edges are about as sharp as the cascades'). Anti-aliasing"
      " (docs/ARCHITECTURE.md, \"Anti-aliasing\") is on in every row but the two that say otherwise.")
print(open(out).read())
PY
