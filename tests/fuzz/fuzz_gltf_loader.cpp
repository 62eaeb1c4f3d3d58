// libFuzzer harness over the glTF loader's CPU part (parsing, validation, image decoding, scene
// building; no GL). Built only by tools/fuzz.sh (clang, -fsanitize=fuzzer,address,undefined),
// never by the default build. See docs/RELIABILITY.md for the command.

#include "GltfFuzzInput.h"

#include <tiny_gltf.h>

#include <unistd.h>

#include <cstdlib>
#include <string>

// tinygltf_impl.cpp leaves out stb_image_write (TINYGLTF_NO_STB_IMAGE_WRITE: the loader writes
// nothing), but the TinyGLTF constructor in the header still names the default image writer.
namespace tinygltf {
bool WriteImageData(const std::string*, const std::string*, const Image*, bool, std::string*, void*) { return false; }
}  // namespace tinygltf

namespace {
std::filesystem::path scratchFolder() {
    // One folder per process: parallel fuzzing jobs must not share scene.gltf.
    const char* base = std::getenv("LIT_FUZZ_SCRATCH");
    return std::filesystem::path(base && *base ? base : "/tmp") / ("lit-fuzz-" + std::to_string(::getpid()));
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    lit::fuzz::prepareScratch(scratchFolder(), LIT_SOURCE_DIR);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path scratch = scratchFolder();
    lit::fuzz::loadFuzzInput(data, size, scratch);  // any exception but SceneLoadError aborts: a finding
    return 0;
}
