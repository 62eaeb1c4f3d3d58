#pragma once
// One fuzz input through the ordinary glTF loader, shared by the libFuzzer harness
// (fuzz_gltf_loader.cpp, tools/fuzz.sh) and the corpus replay test (tests/unit/test_fuzz_corpus.cpp),
// so that a crasher found by the fuzzer is replayed by the regular build exactly as it was found.
//
// The input is written as scene.gltf (or scene.glb when it starts with the GLB magic) into a
// scratch folder that also holds the companion files the seeds refer to (cornell_box.bin from
// assets/, tests/fuzz/companions/tex.png), then loaded with limits small enough that every input finishes quickly: a 1 MB file,
// a 64 MB memory budget. The expected outcomes are a Scene or a SceneLoadError; anything else
// (another exception, a crash, a sanitizer report) is a finding.

#include "Log.h"
#include "scene/GltfLoader.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace lit::fuzz {

inline GltfLoadOptions fuzzLoadOptions() {
    GltfLoadOptions options;
    options.decodeThreads = 1;                         // deterministic, and one core per fuzzer
    options.limits.maxFileBytes = 1'000'000;           // libFuzzer's -max_len in tools/fuzz.sh is 256 kB
    options.limits.memoryBudgetBytes = 64'000'000;     // keeps every input under ~1 s
    return options;
}

// Copies the companion files into `scratch` (once per process): tests/fuzz/companions/* and the
// Cornell box's buffer from assets/. `sourceDir` is the repository root.
inline void prepareScratch(const std::filesystem::path& scratch, const std::filesystem::path& sourceDir) {
    namespace fs = std::filesystem;
    fs::create_directories(scratch);
    for (const fs::directory_entry& entry : fs::directory_iterator(sourceDir / "tests/fuzz/companions"))
        fs::copy_file(entry.path(), scratch / entry.path().filename(), fs::copy_options::overwrite_existing);
    fs::copy_file(sourceDir / "assets/cornell_box.bin", scratch / "cornell_box.bin", fs::copy_options::overwrite_existing);
}

// Loads `bytes` as a scene in `scratch`. Returns true when it loaded, false for a SceneLoadError;
// other exceptions propagate (a finding).
inline bool loadFuzzInput(const std::uint8_t* bytes, std::size_t size, const std::filesystem::path& scratch) {
    const bool glb = size >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
    const std::filesystem::path file = scratch / (glb ? "scene.glb" : "scene.gltf");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes), static_cast<std::streamsize>(size));
    }
    Log log;
    log.setSink([](const LogMessage&) {});
    try {
        const Scene scene = loadGltf(file, log, fuzzLoadOptions());
        (void)summarize(scene);
        return true;
    } catch (const SceneLoadError&) {
        return false;
    }
}

}  // namespace lit::fuzz
