#!/usr/bin/env bash
# Fuzzing the glTF loader with libFuzzer (clang's -fsanitize=fuzzer with ASan and UBSan),
# including the decoders of compressed geometry (Draco, meshopt) through the compressed seeds.
# Not part of the normal build; the regression corpus it feeds (tests/fuzz/regressions) is
# replayed by the normal test suite (GltfFuzzCorpus in lit_unit_tests).
#
#   tools/fuzz.sh build               build build-fuzz/fuzz_gltf_loader (clang-14, ~2 min)
#   tools/fuzz.sh run MINUTES [JOBS]  fuzz for MINUTES (default 1 job = one core); new inputs go to
#                                     build-fuzz/corpus, crashes/timeouts/OOMs to build-fuzz/findings
#   tools/fuzz.sh replay FILE...      run the harness once on each FILE (reproduce a finding)
#   tools/fuzz.sh run-decoders MINUTES  fuzz the Draco and meshopt decoders alone
#                                     (build-fuzz/fuzz_gltf_decoders, tests/fuzz/fuzz_gltf_decoders.cpp),
#                                     seeded with the streams of tests/data/compressed; new inputs go
#                                     to build-fuzz/decoder-corpus, findings to build-fuzz/findings
#
# A finding is fixed, then its input is copied to tests/fuzz/regressions/ (named after what it
# found) so the suite replays it for ever. Environment: LIT_FUZZ_DIR (default build-fuzz/),
# CXX_FUZZ (default clang++-14).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${LIT_FUZZ_DIR:-$root/build-fuzz}"
cxx="${CXX_FUZZ:-clang++-14}"
binary="$out/fuzz_gltf_loader"

# WebP textures (EXT_texture_webp) are decoded, and fuzzed, where libwebp is installed, as the
# normal build decides (renderer/CMakeLists.txt).
webp_flags() {
    if pkg-config --exists libwebp 2> /dev/null; then echo "-DLIT_HAS_WEBP=1"; else echo "-DLIT_HAS_WEBP=0"; fi
}
webp_libs() { pkg-config --libs libwebp 2> /dev/null || true; }

build() {
    mkdir -p "$out/obj"
    local flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
                 -fno-sanitize-recover=undefined -DLIT_SOURCE_DIR="\"$root\"" "$(webp_flags)"
                 -I"$root/renderer" -I"$root/shaders/include" -I"$root/tests/fuzz" -isystem /usr/include/stb)
    # The loader's CPU part and what it needs; tinygltf and stb_image compiled in, instrumented.
    local sources=(renderer/scene/GltfLoader.cpp renderer/scene/GltfContainer.cpp renderer/scene/GltfParse.cpp
                   renderer/scene/GltfExtensions.cpp renderer/scene/GltfCompression.cpp renderer/scene/GltfMeshopt.cpp
                   renderer/scene/GltfDraco.cpp
                   renderer/scene/GltfValidate.cpp renderer/scene/GltfImport.cpp renderer/scene/GltfImportMeshes.cpp
                   renderer/scene/GltfImportImages.cpp renderer/scene/GltfImportKept.cpp renderer/scene/GltfKeep.cpp
                   renderer/scene/GltfMaterialLayers.cpp renderer/scene/GltfTextureTransform.cpp
                   renderer/scene/SceneMemory.cpp renderer/gi/VoxelVolume.cpp renderer/gl/Objects.cpp renderer/gl/Capabilities.cpp
                   renderer/io/GltfGuard.cpp renderer/io/GltfFile.cpp
                   renderer/io/AtomicFile.cpp renderer/Log.cpp renderer/scene/Scene.cpp renderer/scene/Tangents.cpp
                   renderer/animation/CameraPathIO.cpp renderer/animation/CameraPath.cpp renderer/scene/CameraView.cpp
                   tests/fuzz/tinygltf_impl.cpp tests/fuzz/fuzz_gltf_loader.cpp)
    local objects=()
    for source in "${sources[@]}"; do
        local object="$out/obj/$(echo "$source" | tr / _).o"
        # Rebuilt when the source or one of the loader's headers changed (tinygltf_impl.cpp, the
        # slowest by far, only when it changed itself).
        local stale=0
        [ ! -f "$object" ] || [ "$root/$source" -nt "$object" ] && stale=1
        if [ "$source" != tests/fuzz/tinygltf_impl.cpp ]; then
            for header in renderer/io/GltfGuard.h renderer/scene/GltfLoader.h renderer/io/GltfFile.h \
                          renderer/scene/GltfImportDetail.h renderer/scene/GltfContainer.h renderer/scene/GltfParse.h \
                          renderer/scene/GltfValidate.h renderer/scene/GltfImport.h renderer/scene/GltfImportMeshes.h \
                          renderer/scene/GltfImportImages.h renderer/scene/GltfImportKept.h renderer/scene/GltfKeep.h \
                          renderer/io/AtomicFile.h renderer/scene/Scene.h renderer/Log.h tests/fuzz/GltfFuzzInput.h \
                          renderer/animation/CameraPathIO.h renderer/animation/CameraPath.h \
                          renderer/scene/GltfExtensions.h renderer/scene/GltfCompression.h renderer/scene/GltfMeshopt.h \
                          renderer/scene/GltfDraco.h renderer/io/LittleEndian.h; do
                [ "$root/$header" -nt "$object" ] && stale=1
            done
        fi
        if [ "$stale" -eq 1 ]; then
            echo "fuzz: compiling $source" >&2
            "$cxx" "${flags[@]}" -c "$root/$source" -o "$object"
        fi
        objects+=("$object")
    done
    # libdraco and libmeshoptimizer as Debian builds them, uninstrumented: ASan checks what the
    # loader does with their output and catches their crashes, not their own reads. libFuzzer
    # mutates the compressed streams the seeds carry (tests/fuzz/seeds/*_draco.glb, *_meshopt.glb).
    # SceneMemory's budget counts the voxel volumes by VoxelVolume's own arithmetic, which links its
    # GL wrappers; libepoxy resolves them, and the harness never calls GL.
    # shellcheck disable=SC2046  # webp_libs: zero or more words
    "$cxx" "${flags[@]}" "${objects[@]}" -o "$binary" -lpthread -ldraco -lmeshoptimizer -lepoxy $(webp_libs)
    echo "fuzz: built $binary" >&2
}

# The decoders alone: the harness and the decoders' sources, instrumented; libdraco and
# libmeshoptimizer linked as above.
build_decoders() {
    mkdir -p "$out/obj"
    local flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
                 -fno-sanitize-recover=undefined -I"$root/renderer" -isystem /usr/include/stb)
    "$cxx" "${flags[@]}" "$root/tests/fuzz/fuzz_gltf_decoders.cpp" "$root/renderer/scene/GltfMeshopt.cpp" \
        "$root/renderer/scene/GltfDraco.cpp" "$root/renderer/scene/GltfValidate.cpp" "$out/obj/tests_fuzz_tinygltf_impl.cpp.o" \
        -o "$out/fuzz_gltf_decoders" -lpthread -ldraco -lmeshoptimizer
    echo "fuzz: built $out/fuzz_gltf_decoders" >&2
}

# One seed per compressed stream of the committed Draco and meshopt files, with the header
# fuzz_gltf_decoders.cpp reads (kind, counts) taken from the file's JSON.
decoder_seeds() {
    mkdir -p "$out/decoder-seeds"
    python3 - "$root/tests/data/compressed" "$out/decoder-seeds" <<'PY'
import json, struct, sys, pathlib
source, target = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
def glb(path):
    b = path.read_bytes()
    n = struct.unpack_from('<I', b, 12)[0]
    return json.loads(b[20:20 + n]), b[20 + n + 8:]
doc, binary = glb(source / 'point_draco.glb')
for m, mesh in enumerate(doc['meshes']):
    p = mesh['primitives'][0]
    view = doc['bufferViews'][p['extensions']['KHR_draco_mesh_compression']['bufferView']]
    points = doc['accessors'][p['attributes']['POSITION']]['count']
    faces = doc['accessors'][p['indices']]['count'] // 3
    stream = binary[view.get('byteOffset', 0):view.get('byteOffset', 0) + view['byteLength']]
    (target / f'draco_{m}').write_bytes(struct.pack('<BHH', 0, points, faces) + stream)
doc, binary = glb(source / 'point_meshopt.glb')
modes = {'ATTRIBUTES': 1, 'TRIANGLES': 2, 'INDICES': 3}
filters = {'NONE': 0, 'OCTAHEDRAL': 1, 'QUATERNION': 2, 'EXPONENTIAL': 3}
for v, view in enumerate(doc['bufferViews']):
    e = view.get('extensions', {}).get('EXT_meshopt_compression')
    if not e: continue
    kind = modes[e['mode']]
    stride = (e['byteStride'] // 4 - 1) if kind == 1 else (e['byteStride'] // 4)
    head = kind | (filters[e.get('filter', 'NONE')] << 2) | (stride << 4)
    stream = binary[e.get('byteOffset', 0):e.get('byteOffset', 0) + e['byteLength']]
    (target / f'meshopt_{v}').write_bytes(struct.pack('<BHH', head, e['count'], 0) + stream)
PY
}

command="${1:-}"
[ $# -gt 0 ] && shift
case "$command" in
    build)
        build
        ;;
    run)
        minutes="${1:?usage: tools/fuzz.sh run MINUTES [JOBS]}"
        jobs="${2:-1}"
        build
        mkdir -p "$out/corpus" "$out/findings"
        args=(-dict="$root/tests/fuzz/gltf.dict" -max_total_time=$((minutes * 60)) -timeout=10 -rss_limit_mb=2048
              -max_len=262144 -artifact_prefix="$out/findings/" -print_final_stats=1)
        [ "$jobs" -gt 1 ] && args+=(-jobs="$jobs" -workers="$jobs")
        cd "$out"
        exec "$binary" "${args[@]}" "$out/corpus" "$root/tests/fuzz/seeds" "$root/tests/fuzz/regressions"
        ;;
    replay)
        build
        exec "$binary" -runs=1 "$@"
        ;;
    run-decoders)
        minutes="${1:?usage: tools/fuzz.sh run-decoders MINUTES}"
        build
        build_decoders
        decoder_seeds
        mkdir -p "$out/decoder-corpus" "$out/findings"
        cd "$out"
        exec "$out/fuzz_gltf_decoders" -max_total_time=$((minutes * 60)) -timeout=10 -rss_limit_mb=2048 \
            -max_len=65536 -artifact_prefix="$out/findings/decoders-" -print_final_stats=1 \
            "$out/decoder-corpus" "$out/decoder-seeds"
        ;;
    *)
        sed -n '2,20p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
        exit 2
        ;;
esac
