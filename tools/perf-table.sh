#!/usr/bin/env bash
# The performance tables: `lit-render --bench` on Crytek Sponza at 1280×720 with GI off and with GI
# at 128³, 256³ and 512³ voxels (RGBA8 radiance), the full-frame Cornell box's GI variants
# interleaved, flicker and light edits, printed as they run and written to
# docs/tables/performance.md, headed by the date, the commit, this machine's GL renderer and CPU.
# The whole file is rewritten: it holds measurements only; docs/PERFORMANCE.md says how they are
# taken and how to read them. Optionally also benchmarks the cone-trace shaders of an older
# revision with the same binary in the same run (PERF_COMPARE_REV), for before/after numbers of a
# shader change.
#
# Usage: tools/perf-table.sh            (from anywhere; needs a built lit-render and python3)
# Environment (all optional):
#   LIT_BUILD_DIR     build directory holding tools/lit-render       (default: <repo>/build)
#   PERF_SCENE        the Sponza glTF     (default: <repo>/../shared/scenes/sponza/Sponza.gltf)
#   PERF_SIZE         image size WxH                                  (default: 1280x720)
#   PERF_FRAMES       frames per GI-off run                           (default: 5)
#   PERF_GI_FRAMES    frames per GI-on run; the first also voxelizes  (default: 3)
#   PERF_VOXELS       voxel resolutions for GI on                     (default: "128 256 512")
#   PERF_OUT          the markdown file written                (default: <repo>/docs/tables/performance.md)
#   PERF_COMPARE_REV  a git revision whose version of PERF_COMPARE_FILES is benchmarked as
#                     "before" against the working tree (GI on at the first of PERF_VOXELS): the
#                     same binary, shaders/ copied with just those files from the revision
#   PERF_COMPARE_FILES   default: "shaders/include/cone.glsl shaders/cone_trace.frag.glsl"
#   PERF_COMPARE_SCENES  scenes of the before/after runs (default: the Sponza scene above and the
#                     Cornell box, whose camera sees only interior surfaces)
#   PERF_COMPARE_ROUNDS  before/after pairs, interleaved                (default: 3)
#   PERF_COMPARE_SIZE, PERF_COMPARE_FRAMES   image size and frames of those runs (default: 640x360, 6)
#   PERF_FAST         1 (default): also the GI-cost rows: the full-frame Cornell box
#                     (assets/cornell_inside.still.path.json: inside the box, 70° fov) at PERF_SIZE
#                     and 128³ with GI off and GI on at indirect scale 1, 2 and 4, at 2 with
#                     temporal accumulation, and the fast GI mode's per-pixel cone trace, interleaved
#                     PERF_FAST_ROUNDS times; the flicker figure on assets/cornell_inside.path.json
#                     (PERF_FLICKER_SIZE, temporal accumulation on and off); and a light edit
#                     against a re-voxelization on Sponza at 256³ (--bench-gi-updates). 0: skip them.
#   PERF_FAST_ROUNDS  rounds of the interleaved Cornell runs          (default: 2)
#   PERF_FLICKER_SIZE image size of the flicker runs                  (default: 640x360)
# Besides the pass timings (wall clock, so they grow with other load on a shared machine) each
# before/after run records the process's CPU time (user + sys, with /usr/bin/time): both variants
# do identical work apart from the compared shaders, so the difference in CPU seconds is the
# difference in their cost, and is much less disturbed by other processes than wall time.
# Software rasterizers (llvmpipe) take about a second per 1280×720 GI frame: the defaults keep the
# whole script to a few minutes there (more when the machine is shared).
# A resolution whose volumes would not fit in the free memory, or that Lit's memory budget refuses,
# is skipped with a message.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LIT_BUILD_DIR:-$root/build}"
render="$build/tools/lit-render"
scene="${PERF_SCENE:-$root/../shared/scenes/sponza/Sponza.gltf}"
size="${PERF_SIZE:-1280x720}"
frames="${PERF_FRAMES:-5}"
giFrames="${PERF_GI_FRAMES:-3}"
voxelList="${PERF_VOXELS:-128 256 512}"
out="${PERF_OUT:-$root/docs/tables/performance.md}"
compareRev="${PERF_COMPARE_REV:-}"
compareRounds="${PERF_COMPARE_ROUNDS:-3}"
compareSize="${PERF_COMPARE_SIZE:-640x360}"
compareFrames="${PERF_COMPARE_FRAMES:-6}"
compareFiles="${PERF_COMPARE_FILES:-shaders/include/cone.glsl shaders/cone_trace.frag.glsl}"
compareScenes="${PERF_COMPARE_SCENES:-$scene $root/assets/cornell_box.gltf}"

if [[ ! -f "$scene" ]]; then
    echo "perf-table: Sponza not found at $scene (set PERF_SCENE); skipped, $out left as it is"
    exit 0
fi
if [[ ! -x "$render" ]]; then
    echo "perf-table: $render not found; build the lit-render target (or set LIT_BUILD_DIR)" >&2
    exit 1
fi
command -v python3 >/dev/null || { echo "perf-table: needs python3 to read the --json results" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo '{"gi": {"radianceRgba8": true}}' >"$work/rgba8.json"
results="$work/results"
mkdir -p "$results"

# run NAME [lit-render flags...]: one benchmark of $benchScene, its summary printed, its JSON kept
# as NAME.json. Each runs the single-frame steady state (the GI update in the first frame, no
# refinement) unless it sets the GI work per frame itself.
benchScene="$scene"
benchSize="$size"
run() {
    local name="$1"
    shift
    echo "== $name: lit-render $(basename "$benchScene") --size $benchSize $*"
    local timer=()
    [[ -x /usr/bin/time ]] && timer=(/usr/bin/time -f "%U %S" -o "$results/$name.cpu")
    local budget=(--single-frame)
    [[ " $* " == *" --gi-update-per-frame "* ]] && budget=()
    "${timer[@]}" "$render" "$benchScene" --size "$benchSize" --json "$results/$name.json" "${budget[@]}" "$@" \
        | grep -v '^wrote '
}

run "gi-off" --bench "$frames" --gi off --culling on
run "gi-off-culling-off" --bench "$frames" --gi off --culling off

availableKiB=$(awk '/MemAvailable/ {print $2}' /proc/meminfo)
for voxels in $voxelList; do
    # Albedo, normal and emission volumes (r32ui) plus RGBA8 radiance with mips: ≈ 4.6 bytes×4 per voxel.
    needKiB=$((voxels * voxels * voxels * 19 / 1024))
    if ((needKiB * 3 / 2 > availableKiB)); then
        echo "== gi-$voxels: skipped: needs about $((needKiB / 1024)) MiB of volumes, $((availableKiB / 1024)) MiB free"
        continue
    fi
    # Lit's own memory budget (LIT_MAX_RENDER_MB) may refuse the scene at this size: its message
    # above says by how much, and the row is left out.
    if ! run "gi-$voxels" --bench "$giFrames" --gi on --voxels "$voxels" --settings "$work/rgba8.json"; then
        echo "== gi-$voxels: skipped: lit-render refused or failed it (its message above)"
        rm -f "$results/gi-$voxels.json" "$results/gi-$voxels.cpu"
    fi
done

fast="${PERF_FAST:-1}"
fastRounds="${PERF_FAST_ROUNDS:-2}"
flickerSize="${PERF_FLICKER_SIZE:-640x360}"
if [[ "$fast" == 1 ]]; then
    # Full-frame Cornell box: every run flies the still path (one untimed warm-up frame that also
    # voxelizes, then 3 timed frames of the same view), variants interleaved round by round.
    benchScene="$root/assets/cornell_box.gltf"
    still="$root/assets/cornell_inside.still.path.json"
    for ((round = 1; round <= fastRounds; ++round)); do
        run "cornell-gi-off-$round" --path "$still" --fps 10 --bench-path --gi off
        for scale in 1 2 4; do
            run "cornell-gi-s$scale-$round" --path "$still" --fps 10 --bench-path --gi on --voxels 128 --indirect-scale "$scale"
        done
        # The per-pixel cone trace: the fast GI mode at scale 1, six cones marched from every pixel
        # every frame (what reduced resolution and the cached mode are measured against).
        run "cornell-gi-fast-s1-$round" --path "$still" --fps 10 --bench-path --gi on --voxels 128 --gi-mode fast \
            --indirect-scale 1
        # ½ scale with temporal accumulation, which traces cone subsets (half the cones per texel).
        run "cornell-gi-s2t-$round" --path "$still" --fps 10 --bench-path --gi on --voxels 128 --indirect-scale 2 \
            --temporal on
    done
    benchSize="$flickerSize"
    for temporal in on off; do
        run "flicker-temporal-$temporal" --path "$root/assets/cornell_inside.path.json" --fps 10 --bench-path --gi on \
            --voxels 128 --temporal "$temporal" | tee "$results/flicker-temporal-$temporal.txt"
    done
    benchScene="$scene"
    benchSize="$size"
    run "gi-updates-256" --bench 1 --gi on --voxels 256 --settings "$work/rgba8.json" --bench-gi-updates 3 \
        | tee "$results/gi-updates-256.txt"
    # The editor's light edit: the cached mode traces the voxel irradiance of 16384 voxels per frame
    # after an edit (editor/EditorState.h), so its edit frame, not the whole update, is what a user waits on.
    run "gi-updates-256-editor" --bench 1 --gi on --voxels 256 --settings "$work/rgba8.json" --bench-gi-updates 3 \
        --gi-update-per-frame 16384 --gi-refine-per-frame 0 | tee "$results/gi-updates-256-editor.txt"
fi

if [[ -n "$compareRev" ]]; then
    # The same binary with the working tree's shaders but the revision's version of the compared
    # files (LIT_SHADER_DIR): only those files differ between "before" and "after".
    mkdir -p "$work/old"
    cp -r "$root/shaders" "$work/old/shaders"
    for file in $compareFiles; do
        git -C "$root" show "$compareRev:$file" >"$work/old/$file"
    done
    abVoxels="${voxelList%% *}"
    benchSize="$compareSize"
    for benchScene in $compareScenes; do
        tag="$(basename "$benchScene" .gltf)"
        for ((round = 1; round <= compareRounds; ++round)); do
            LIT_SHADER_DIR="$work/old/shaders" run "before-$tag-$round" --bench "$compareFrames" --gi on \
                --voxels "$abVoxels" --settings "$work/rgba8.json"
            run "after-$tag-$round" --bench "$compareFrames" --gi on --voxels "$abVoxels" --settings "$work/rgba8.json"
        done
    done
fi

. "$root/tools/table-stamp.sh"
cpu="$(table_cpu)"
commit="$(table_commit "$root")"
python3 - "$results" "$out" "$size" "$cpu" "$(date -u '+%Y-%m-%d %H:%M UTC')" "$compareRev" "$(table_load)" "$compareFiles" "$commit" <<'PY'
import json, os, sys
results, out, size, cpu, date, compare_rev, load, compare_files, commit = sys.argv[1:10]

def load_run(name):
    path = os.path.join(results, name + ".json")
    return json.load(open(path)) if os.path.exists(path) else None

voxel_runs = sorted(int(f[3:-5]) for f in os.listdir(results) if f.startswith("gi-") and f[3:-5].isdigit())
runs = [(n, load_run(n)) for n in ["gi-off", "gi-off-culling-off"] + [f"gi-{v}" for v in voxel_runs]]
runs = [(n, r) for n, r in runs if r]
device = runs[0][1]["device"] if runs else "unknown"
order = ["shadow", "g-buffer", "voxelize", "inject", "mipmap", "lighting", "cone trace", "post"]
seen = {p["name"] for _, r in runs for p in r["passes"]}
passes = [p for p in order if p in seen] + sorted(seen - set(order))

def pass_ms(run, name):
    for p in run["passes"]:
        if p["name"] == name:
            note = "" if p["framesRan"] == run["frames"] else f" ({p['framesRan']}×)"
            return f"{p['gpuMs']['mean']:.1f}{note}"
    return "–"

def label(name, run):
    if name.startswith("gi-off"):
        return "GI off" + (", culling off" if not run["frustumCulling"] else "")
    return f"GI on, {run['voxelResolution']}³"

lines = []
w = lines.append
w("# Performance tables")
w("")
w("Generated by `tools/perf-table.sh` (`lit-render --bench --json` per row); rerun it to refresh. How the numbers")
w("are taken and how to read them: docs/PERFORMANCE.md.")
w("")
w(f"- Date: {date}")
w(f"- Commit: {commit}")
w(f"- GPU (GL renderer): {device}")
w(f"- CPU: {cpu}; load average at the end of the run: {load}")
w("")
w(f"## Crytek Sponza, {size.replace('x', '×')}, default camera, RGBA8 radiance")
w("")
w("| Run | frames | lowest FPS | highest FPS | mean frame (ms) | median frame (ms) | draws | triangles | cull (ms CPU) | "
  + " | ".join(f"{p} (GPU ms)" for p in passes) + " |")
w("|---" * (9 + len(passes)) + "|")
for name, r in runs:
    fm = r["frameMs"]
    w(f"| {label(name, r)} | {r['frames']} | {r['lowestFps']:.2f} | {r['highestFps']:.2f} | {fm['mean']:.1f} | "
      f"{fm['median']:.1f} | {r['drawsSubmitted']} of {r['drawsTotal']} | {r['triangles']} | {r['cullMs']['mean']:.3f} | "
      + " | ".join(pass_ms(r, p) for p in passes) + " |")


tags = sorted({f[len("before-"):-len("-1.json")] for f in os.listdir(results) if f.startswith("before-") and f.endswith("-1.json")})
groups = []
for tag in tags:
    pairs = [(load_run(f"before-{tag}-{i}"), load_run(f"after-{tag}-{i}")) for i in range(1, 100)]
    groups.append((tag, [(b, a) for b, a in pairs if b and a]))
groups = [(t, ab) for t, ab in groups if ab]
if compare_rev and groups:
    def cone(run):
        for p in run["passes"]:
            if p["name"] == "cone trace":
                return p["gpuMs"]["min"]
        return float("nan")
    w("")
    w(f"## Cone trace before/after (same binary and run; `{compare_files}` of `{compare_rev}` vs the working tree)")
    w("")
    def cpu_seconds(name):
        path = os.path.join(results, name + ".cpu")
        try:
            return sum(float(x) for x in open(path).read().split()[-2:])
        except (OSError, ValueError):
            return float("nan")
    ab0 = groups[0][1][0][0]
    w(f"GI on, {ab0['voxelResolution']}³ RGBA8, {ab0['width']}×{ab0['height']}, {ab0['frames']} frames per run, runs "
      "interleaved. Cone trace ms: the lowest of the run's frames (wall clock of the pass, least disturbed by other "
      "load). CPU s: the whole process (load, upload, voxelize, all frames), user + sys; only the cone trace differs.")
    w("")
    w("| Scene | Round | cone trace before (ms) | cone trace after (ms) | speed-up | CPU before (s) | CPU after (s) | CPU saved (s) |")
    w("|---|---|---|---|---|---|---|---|")
    for tag, ab in groups:
        for i, (b, a) in enumerate(ab, 1):
            cb, ca = cpu_seconds(f"before-{tag}-{i}"), cpu_seconds(f"after-{tag}-{i}")
            w(f"| {tag} | {i} | {cone(b):.1f} | {cone(a):.1f} | {cone(b) / cone(a):.2f}× | {cb:.2f} | {ca:.2f} | {cb - ca:.2f} |")
fast_rounds = sorted({int(f[len("cornell-gi-off-"):-len(".json")]) for f in os.listdir(results) if f.startswith("cornell-gi-off-") and f.endswith(".json")})
if fast_rounds:
    def pass_mean(run, name):
        for p in run["passes"]:
            if p["name"] == name:
                return p["gpuMs"]["mean"]
        return 0.0
    def indirect(run):  # GPU ms of the indirect passes: (cone trace, resolve, fallback)
        return tuple(pass_mean(run, p) for p in ("cone trace", "indirect resolve", "indirect fallback"))
    w("")
    w("## Full-frame Cornell box, 128³: GI on against GI off")
    w("")
    first = load_run(f"cornell-gi-off-{fast_rounds[0]}")
    w(f"`assets/cornell_inside.still.path.json` (camera inside the box, 70° vertical fov: every pixel a wall or box), "
      f"{first['width']}×{first['height']}, RGBA16F radiance, the default (cached) GI mode, `--bench-path` (one untimed "
      f"warm-up frame, then {first['frames']} timed frames of the same view), one binary, the variants interleaved in "
      "each round. Frame: mean wall-clock ms. Indirect: the GPU ms of \"cone trace\" + \"indirect resolve\" + "
      "\"indirect fallback\" (the cached mode resolves at scale 1 too, one texel per pixel). Ratios are within one round.")
    w("")
    w("| Round | GI off frame (ms) | GI on frame, scale 1 / 2 / 4 (ms) | GI on ÷ GI off, scale 1 / 2 / 4 | indirect, scale 1 / 2 / 4 (ms) | indirect speed-up vs scale 1, scale 2 / 4 |")
    w("|---|---|---|---|---|---|")
    for rnd in fast_rounds:
        off = load_run(f"cornell-gi-off-{rnd}")
        on = [load_run(f"cornell-gi-s{s}-{rnd}") for s in (1, 2, 4)]
        if not off or not all(on):
            continue
        offMs = off["frameMs"]["mean"]
        frames = [r["frameMs"]["mean"] for r in on]
        ind = [sum(indirect(r)) for r in on]
        w(f"| {rnd} | {offMs:.0f} | {' / '.join(f'{f:.0f}' for f in frames)} | {' / '.join(f'{f / offMs:.2f}×' for f in frames)} | "
          f"{' / '.join(f'{i:.0f}' for i in ind)} | {ind[0] / ind[1]:.2f}× / {ind[0] / ind[2]:.2f}× |")
    temporal_rounds = [(rnd, load_run(f"cornell-gi-off-{rnd}"), load_run(f"cornell-gi-s1-{rnd}"),
                        load_run(f"cornell-gi-s2t-{rnd}")) for rnd in fast_rounds]
    temporal_rounds = [t for t in temporal_rounds if all(t[1:])]
    if temporal_rounds:
        w("")
        w("### Scale 2 with temporal accumulation")
        w("")
        w("`--temporal on`, same rounds; indirect = cone trace + resolve + fallback, its speed-up against scale 1's "
          "indirect.")
        w("")
        w("| Round | frame (ms) | GI on ÷ GI off | indirect (ms): trace + resolve + fallback | indirect speed-up vs scale 1 |")
        w("|---|---|---|---|---|")
        for rnd, off, s1, t in temporal_rounds:
            tr, rs, fb = indirect(t)
            full = sum(indirect(s1))
            w(f"| {rnd} | {t['frameMs']['mean']:.0f} | {t['frameMs']['mean'] / off['frameMs']['mean']:.2f}× | "
              f"{tr + rs + fb:.0f}: {tr:.0f} + {rs:.0f} + {fb:.0f} | {full / (tr + rs + fb):.2f}× |")
    cone_rounds = [(rnd, load_run(f"cornell-gi-fast-s1-{rnd}"), load_run(f"cornell-gi-s2-{rnd}"))
                   for rnd in fast_rounds]
    cone_rounds = [c for c in cone_rounds if all(c[1:])]
    if cone_rounds:
        w("")
        w("### The default against the per-pixel cone trace")
        w("")
        w("The per-pixel cone trace: the fast GI mode (`--gi-mode fast`) at indirect scale 1, six cones marched from "
          "every pixel every frame; same rounds. The default's \"cone trace\" at scale 2 is the cached mode's gather "
          "of the voxels' irradiance for one texel in 2×2; its indirect adds the resolve and fallback.")
        w("")
        w("| Round | per-pixel cone trace, fast mode, scale 1 (ms) | its frame (ms) | default at scale 2: trace (ms) | trace lower by | indirect: trace + resolve + fallback (ms) | indirect lower by |")
        w("|---|---|---|---|---|---|---|")
        for rnd, f1, s2 in cone_rounds:
            cone1 = pass_mean(f1, "cone trace")
            tr, rs, fb = indirect(s2)
            w(f"| {rnd} | {cone1:.0f} | {f1['frameMs']['mean']:.0f} | {tr:.0f} | {cone1 / tr:.1f}× | "
              f"{tr + rs + fb:.0f}: {tr:.0f} + {rs:.0f} + {fb:.0f} | {cone1 / (tr + rs + fb):.1f}× |")
    flick = [(t, load_run(f"flicker-temporal-{t}")) for t in ("on", "off")]
    flick = [(t, r) for t, r in flick if r and "flickerPercent" in r]
    if flick:
        w("")
        w("## Flicker")
        w("")
        r0 = flick[0][1]
        w(f"Flicker on `assets/cornell_inside.path.json` ({r0['width']}×{r0['height']}, 10 fps, {r0['frames']} frames, "
          "indirect scale 2): mean |frame-to-frame change| of pixels whose surface did not move (reprojected, same "
          "point within 1 %), relative to the mean luminance (`lit-render --bench-path`).")
        w("")
        w("| Temporal accumulation | flicker mean | flicker worst frame pair | mean frame (ms) |")
        w("|---|---|---|---|")
        for t, r in flick:
            w(f"| {t} | {r['flickerPercent']:.3f} % | {r['flickerWorstPercent']:.3f} % | {r['frameMs']['mean']:.0f} |")
    updates = []
    for name, how in (("gi-updates-256", "the whole update in one frame, `lit-render --bench 1 --bench-gi-updates 3`"),
                      ("gi-updates-256-editor", "the edit frame as the editor runs it: its default budget of 16384 "
                       "voxels a frame for the update, no refinement, `--gi-update-per-frame 16384 "
                       "--gi-refine-per-frame 0`")):
        upd = os.path.join(results, name + ".txt")
        if os.path.exists(upd):
            rows = [l.strip() for l in open(upd) if l.startswith("gi-update") or l.startswith("GI updates")]
            if rows:
                updates.append((how, rows))
    if updates:
        w("")
        w("## Light edit against a re-voxelization, Sponza 256³")
    for how, rows in updates:
        w("")
        w("Light edit (re-inject + mipmaps, voxels kept, and the GI mode's work that follows it) against a "
          f"re-voxelization, Sponza 256³ RGBA8, interleaved ({how}), GPU ms from the profiler:")
        w("")
        w("```")
        lines.extend(rows)
        w("```")
os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
open(out + ".tmp", "w").write("\n".join(lines) + "\n")
os.replace(out + ".tmp", out)
print(f"wrote {out}")
PY
