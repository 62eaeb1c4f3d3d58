#pragma once
// The hardened front of the glTF loader: everything a hostile or broken file could use to crash,
// exhaust or trick tinygltf is checked here before tinygltf (or the scene builder) does the work.
//
//   1. the scene file: a regular file, not empty, at most GltfLimits::maxFileBytes;
//   2. its JSON (the .gltf text or a GLB's JSON chunk), read once by nlohmann's SAX parser with
//      bounded depth and value count, before tinygltf's recursive conversion ever sees it;
//   3. what the JSON says: asset.version major 2, buffer and image URIs inside the scene's folder
//      (absolute paths and file: URIs only with allowExternalUris; other schemes never),
//      the bytes the buffers and images declare against the memory budget;
//   4. the file callbacks tinygltf reads buffers and images through: regular files inside the
//      scene's folder only, size checked before a byte is allocated;
//   5. after parsing: every distinct encoded image kept once (duplicates share it), and the
//      decoded texture and geometry bytes against the memory budget, before decoding.
// Every failure throws SceneLoadError (scene/GltfLoader.h) whose one-line message starts with
// the file's path. The numbers, and why they are what they are: docs/RELIABILITY.md.

#include "scene/SceneMemory.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace tinygltf {
class Model;
struct FsCallbacks;
}  // namespace tinygltf

namespace lit {

struct GltfLimits {
    // The .gltf or .glb file itself. tinygltf holds it in memory whole; 4 GiB is also the most a
    // GLB can hold (its length field is 32 bits, and tinygltf takes the size as an unsigned int).
    std::uint64_t maxFileBytes = (4ull << 30) - 1;
    // JSON nesting. glTF's own schema nests at most 8 levels (a texture transform inside a
    // material's texture info); 64 leaves room for deep `extras` while keeping tinygltf's
    // recursive conversion (a few hundred bytes of stack per level) far from the stack's end.
    int maxJsonDepth = 64;
    // JSON values (numbers, strings, objects, ...). Every value costs at least 2 bytes of text, so
    // the file size alone allows a billion; the parsers (nlohmann DOM + tinygltf::Value) need
    // about 100-200 bytes per value, so 8 M values bound their memory to ~1.5 GB. Real scenes
    // stay far below (Sponza: ~30 k, a 100 k-node city: ~3 M).
    std::uint64_t maxJsonValues = 8'000'000;
    // Everything Lit allocates to show the scene (scene/SceneMemory.h: decoded images, their GL
    // textures with mips, geometry on the CPU and in GL buffers, and what `render` adds), and
    // separately the bytes read for buffers and encoded images. Front ends set it with
    // renderMemoryLimit ($LIT_MAX_RENDER_MB) and name its source for the message.
    std::uint64_t memoryBudgetBytes = kDefaultSceneMemoryLimit;
    std::string memoryBudgetSource = kDefaultSceneMemoryLimitSource;
    // What the front end's render settings add (voxel volumes, ray hits, render targets); zero
    // counts the scene alone.
    RenderFootprint render{};
    // Buffer and image URIs may point outside the scene's folder (absolute paths, "..", file:).
    // Off: a file from the internet cannot read arbitrary files of the user. (Images may still use
    // a relative path that goes up, "../textures/a.png", as Lit's Save As writes: see GltfGuard.cpp.)
    bool allowExternalUris = false;
};

// The scene file read into memory and its JSON located: `json` views into `bytes`.
struct GuardedScene {
    std::vector<unsigned char> bytes;
    bool binary = false;        // GLB container
    std::string_view json;      // the .gltf text or the GLB JSON chunk
    // Images named by a relative path that leaves the scene's folder ("../textures/a.png", as
    // Lit's Save As writes them): canonical paths the file callbacks may read.
    std::vector<std::filesystem::path> externalImages;
    // Absolute paths and file: URIs (read only with GltfLimits::allowExternalUris), keyed by the
    // URI as tinygltf decodes it (%XX, and '+' as a space): the file each one names.
    std::map<std::string, std::filesystem::path> absoluteFiles;
};

// Step 1 without opening the file (a FIFO would block): a path that exists must be a regular
// file within the size limit. A missing path or a folder is left to the loader's messages.
void checkSceneFile(const std::filesystem::path& file, const GltfLimits& limits);

// Steps 1-3 above. `binary`: parse as GLB (decided by the loader from magic and extension).
GuardedScene guardGltfFile(const std::filesystem::path& file, bool binary, const GltfLimits& limits);

// Step 4: file callbacks for tinygltf that read only what `limits` allows for a scene in
// `sceneFolder`. The returned object owns the state the callbacks point to; keep it alive while
// tinygltf loads.
class GuardedFileSystem {
public:
    GuardedFileSystem(const std::filesystem::path& sceneFile, const GltfLimits& limits,
                      std::vector<std::filesystem::path> externalImages = {},
                      std::map<std::string, std::filesystem::path> absoluteFiles = {});
    ~GuardedFileSystem();
    GuardedFileSystem(const GuardedFileSystem&) = delete;
    GuardedFileSystem& operator=(const GuardedFileSystem&) = delete;

    tinygltf::FsCallbacks callbacks();
    // What a callback refused, one line per file ("'../x.bin' is outside the scene's folder").
    const std::vector<std::string>& refusals() const;

    struct State;

private:
    std::unique_ptr<State> state_;
};

// Step 5, part 1: keeps each distinct encoded image once. Feed every image's bytes as tinygltf
// hands them over (`add`); afterwards `canonical(i)` is the first image with the same bytes, and
// `take(i)` moves those bytes out (once, for canonical images).
class ImageDeduplicator {
public:
    void add(int imageIndex, const unsigned char* bytes, std::size_t size);
    int canonical(int imageIndex) const;
    std::vector<unsigned char> take(int imageIndex);
    std::size_t duplicates() const { return duplicates_; }

private:
    struct Entry {
        std::uint64_t hash = 0;
        int sameAs = -1;  // -1: this entry holds the bytes
        std::vector<unsigned char> bytes;
    };
    std::vector<Entry> entries_;  // by image index
    std::unordered_multimap<std::uint64_t, int> byHash_;  // images that hold bytes
    std::size_t duplicates_ = 0;
};

// Step 5, part 2: everything the scene will take once loaded and uploaded (estimateSceneMemory:
// image sizes from their headers, without decoding; the geometry the builder will make;
// limits.render), against limits.memoryBudgetBytes. Throws SceneLoadError with the figures, the
// limit and its source, and the largest image or the primitive count behind them.
void checkMemoryBudget(const std::filesystem::path& file, const tinygltf::Model& model,
                       const ImageDeduplicator& images, const GltfLimits& limits);

}  // namespace lit
