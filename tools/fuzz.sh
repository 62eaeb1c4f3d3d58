#!/usr/bin/env bash
# Fuzzing the glTF loader with libFuzzer (clang's -fsanitize=fuzzer with ASan and UBSan).
# Not part of the normal build; the regression corpus it feeds (tests/fuzz/regressions) is
# replayed by the normal test suite (GltfFuzzCorpus in lit_unit_tests).
#
#   tools/fuzz.sh build               build build-fuzz/fuzz_gltf_loader (clang-14, ~2 min)
#   tools/fuzz.sh run MINUTES [JOBS]  fuzz for MINUTES (default 1 job = one core); new inputs go to
#                                     build-fuzz/corpus, crashes/timeouts/OOMs to build-fuzz/findings
#   tools/fuzz.sh replay FILE...      run the harness once on each FILE (reproduce a finding)
#
# A finding is fixed, then its input is copied to tests/fuzz/regressions/ (named after what it
# found) so the suite replays it for ever. Environment: LIT_FUZZ_DIR (default build-fuzz/),
# CXX_FUZZ (default clang++-14).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${LIT_FUZZ_DIR:-$root/build-fuzz}"
cxx="${CXX_FUZZ:-clang++-14}"
binary="$out/fuzz_gltf_loader"

build() {
    mkdir -p "$out/obj"
    local flags=(-std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
                 -fno-sanitize-recover=undefined -DLIT_SOURCE_DIR="\"$root\""
                 -I"$root/renderer" -I"$root/shaders/include" -I"$root/tests/fuzz" -isystem /usr/include/stb)
    # The loader's CPU part and what it needs; tinygltf and stb_image compiled in, instrumented.
    local sources=(renderer/scene/GltfLoader.cpp renderer/scene/GltfContainer.cpp renderer/scene/GltfParse.cpp
                   renderer/scene/GltfValidate.cpp renderer/scene/GltfImport.cpp renderer/scene/GltfImportMeshes.cpp
                   renderer/scene/GltfImportImages.cpp renderer/scene/GltfImportKept.cpp renderer/scene/GltfKeep.cpp
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
                          renderer/animation/CameraPathIO.h renderer/animation/CameraPath.h; do
                [ "$root/$header" -nt "$object" ] && stale=1
            done
        fi
        if [ "$stale" -eq 1 ]; then
            echo "fuzz: compiling $source" >&2
            "$cxx" "${flags[@]}" -c "$root/$source" -o "$object"
        fi
        objects+=("$object")
    done
    "$cxx" "${flags[@]}" "${objects[@]}" -o "$binary" -lpthread
    echo "fuzz: built $binary" >&2
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
    *)
        sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
        exit 2
        ;;
esac
