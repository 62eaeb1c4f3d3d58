#pragma once
// glTF 2.0 import (.gltf and .glb) through tinygltf, into lit::Scene.

#include "io/GltfGuard.h"
#include "scene/Scene.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

namespace lit {

class Log;

// A file that cannot be loaded. The message names the file and the problem ("accessor 3 reads
// past the end of buffer view 1", "not a glTF file", ...).
class SceneLoadError : public std::runtime_error {
public:
    explicit SceneLoadError(const std::string& message) : std::runtime_error(message) {}
};

// Where a load is. Stages come in this order, each reported first with done = 0 and last with
// done == total (also when total is 0), done never decreasing within a stage:
//   "file"    1 step: tinygltf reads the JSON/GLB, the buffers and the encoded images
//   "meshes"  one step per glTF mesh (vertices, indices, tangents)
//   "images"  one step per image decoded
//   "scene"   1 step: materials, textures, lights, cameras, transforms are ready
struct LoadProgress {
    std::string stage;
    int done = 0;
    int total = 0;
};

struct GltfLoadOptions {
    // Called on the thread that called loadGltf (never on a decoding worker), so it may touch
    // that thread's state (an editor's progress bar, a log) without locking. Empty: no reports.
    std::function<void(const LoadProgress&)> progress;
    // Threads that decode images (stb_image): 0 (or less) = std::thread::hardware_concurrency(),
    // 1 = on the calling thread only. The decoded pixels and the warnings do not depend on it.
    int decodeThreads = 0;
    // File size, JSON depth, memory budget, external URIs (io/GltfGuard.h, docs/RELIABILITY.md).
    GltfLimits limits;
};

// Loads a scene. Throws SceneLoadError for files that cannot be used; recoverable problems
// (a missing or undecodable texture, an unsupported extension) become warnings in `log` and the
// texture is replaced by a neutral one (1×1 white; a material that used it as its normal map
// gets normalTexture = -1). The returned scene has world transforms computed.
Scene loadGltf(const std::filesystem::path& path, Log& log, const GltfLoadOptions& options = {});

// What a loaded scene holds, for a one-line report after loading.
struct SceneSummary {
    std::string name;                // file name of scene.sourcePath, else scene.name
    std::size_t nodes = 0, meshes = 0, primitives = 0;
    std::size_t triangles = 0;       // of the meshes (each mesh once, however many nodes use it)
    std::size_t vertices = 0;
    std::size_t materials = 0, textures = 0, images = 0, lights = 0, cameras = 0;
    std::size_t vertexBytes = 0, indexBytes = 0, pixelBytes = 0;  // CPU memory of that data
    std::size_t cpuBytes() const { return vertexBytes + indexBytes + pixelBytes; }
};

SceneSummary summarize(const Scene& scene);
// "sponza.gltf: 103 meshes, 262k triangles, 69 textures, 412 MB" (MB = 10^6 bytes of vertices,
// indices and pixels; counts of 10 000 and more in k, rounded).
std::string toString(const SceneSummary& summary);

}  // namespace lit
