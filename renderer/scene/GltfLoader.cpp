// glTF 2.0 import, the public entry point. A load runs these steps, each in its own file:
//   1. scene/GltfParse: the guard's limits (io/GltfGuard.h), the container (scene/GltfContainer),
//      tinygltf's parse, each image's encoded bytes kept;
//   2. scene/GltfImport: the Scene, every value checked before use (scene/GltfValidate), images
//      decoded in parallel (scene/GltfImportImages), and what Lit does not draw kept for a
//      lossless save (scene/GltfImportKept; written back by scene/GltfWriter.cpp).

#include "scene/GltfLoader.h"

#include "Log.h"
#include "scene/GltfImport.h"
#include "scene/GltfImportDetail.h"
#include "scene/GltfParse.h"

#include <chrono>
#include <cstdio>

namespace lit {

Scene loadGltf(const std::filesystem::path& path, Log& log, const GltfLoadOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (options.progress) options.progress({"file", 0, 1});
    const gltfimport::ParsedGltf parsed = gltfimport::parseGltf(path, log, options);
    if (options.progress) options.progress({"file", 1, 1});
    const gltfimport::GltfSource source{path, parsed.model, parsed.images, parsed.sparseKept, parsed.doc,
                                             parsed.compression, log, options};
    Scene scene = gltfimport::importScene(source);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // The one summary line of a load, for every front end: "loaded Sponza.gltf: 1 mesh, 262k
    // triangles, 69 textures, 297 MB in 3912 ms".
    log.info("loaded " + toString(summarize(scene)) + " in " + std::to_string(static_cast<long long>(ms + 0.5)) +
             " ms");
    return scene;
}

SceneSummary summarize(const Scene& scene) {
    SceneSummary s;
    s.name = !scene.sourcePath.empty() ? scene.sourcePath.filename().string() : scene.name;
    s.nodes = scene.nodes.size();
    s.meshes = scene.meshes.size();
    for (const Mesh& mesh : scene.meshes)
        for (const Primitive& p : mesh.primitives) {
            ++s.primitives;
            s.triangles += p.indices.size() / 3;
            s.vertices += p.vertices.size();
            s.vertexBytes += p.vertices.size() * sizeof(Vertex);
            s.indexBytes += p.indices.size() * sizeof(std::uint32_t);
        }
    s.materials = scene.materials.size();
    s.textures = scene.textures.size();
    s.images = scene.images.size();
    for (const Image& image : scene.images) s.pixelBytes += image.rgba.size();
    s.lights = scene.lights.size();
    s.cameras = scene.cameras.size();
    return s;
}

std::string toString(const SceneSummary& summary) {
    const auto count = [](std::size_t n, const char* one, const char* many) {
        const std::string number = n >= 10000 ? std::to_string((n + 500) / 1000) + "k" : std::to_string(n);
        return number + " " + (n == 1 ? one : many);
    };
    char megabytes[32];
    std::snprintf(megabytes, sizeof megabytes, "%.0f MB", static_cast<double>(summary.cpuBytes()) / 1e6);
    return summary.name + ": " + count(summary.meshes, "mesh", "meshes") + ", " +
           count(summary.triangles, "triangle", "triangles") + ", " + count(summary.textures, "texture", "textures") +
           ", " + megabytes;
}

}  // namespace lit
