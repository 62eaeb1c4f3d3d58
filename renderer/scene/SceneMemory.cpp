#include "scene/SceneMemory.h"

#include "RenderSettings.h"
#include "gi/RayHitCache.h"
#include "gi/VoxelVolume.h"
#include "scene/Scene.h"
#include "scene/Sheets.h"

#include <shared.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace lit {

namespace {

// Per output pixel: the G-buffer, the lighting terms, the reduced-resolution indirect targets, the
// output and its read-back copies (a 16384² render measured 17.5 GB, 65 bytes a pixel, before the
// G-buffer's motion target and the anti-aliasing history's depth, 12 bytes more).
constexpr std::uint64_t kTargetBytesPerPixel = 80;

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b) {
    return b != 0 && a > std::numeric_limits<std::uint64_t>::max() / b ? std::numeric_limits<std::uint64_t>::max() : a * b;
}

std::uint64_t positive(int n) { return n > 0 ? static_cast<std::uint64_t>(n) : 0; }

}  // namespace

std::uint64_t SceneMemory::total() const {
    std::uint64_t sum = 0;
    for (const std::uint64_t part : {decodedImages, textures, geometry, voxels, rayHits, targets, shadowMaps})
        sum = saturatingAdd(sum, part);
    return sum;
}

std::string SceneMemory::describe() const {
    std::array<std::pair<const char*, std::uint64_t>, 7> parts{{{"textures", textures},
                                                                {"decoded images", decodedImages},
                                                                {"geometry", geometry},
                                                                {"voxel volumes", voxels},
                                                                {"voxel ray hits", rayHits},
                                                                {"render targets", targets},
                                                                {"shadow maps", shadowMaps}}};
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::string text;
    bool first = true;
    for (const auto& [name, bytes] : parts) {
        if (bytes == 0) continue;
        text += (first ? "" : ", ") + std::string(name) + " " + formatBytes(bytes, total());
        first = false;
    }
    return first ? "nothing" : text;
}

RenderFootprint RenderFootprint::of(const RenderSettings& settings) {
    RenderFootprint footprint;
    footprint.width = settings.output.width;
    footprint.height = settings.output.height;
    if (settings.gi.enabled) {
        footprint.voxelResolution = settings.gi.voxelResolution;
        footprint.radianceRgba8 = settings.gi.radianceRgba8;
        footprint.bounceVolumes = settings.gi.bounces != 1;
        footprint.voxelRays = std::min(settings.gi.voxelRays, kMaxVoxelRays);
        footprint.nearLevels = settings.gi.nearLevelCount();
    }
    if (settings.shadows.enabled) {
        footprint.shadowMapSize = std::clamp(settings.shadows.mapSize, 16, 8192);
        footprint.shadowCascades = std::clamp(settings.shadows.cascades, 0, LIT_MAX_SHADOW_CASCADES);
    }
    return footprint;
}

ShadowCasters shadowCastersOf(const Scene& scene) {
    ShadowCasters casters;
    bool anyLight = false;
    for (const Node& node : scene.nodes) {
        if (node.light < 0 || static_cast<std::size_t>(node.light) >= scene.lights.size()) continue;
        anyLight = true;
        const Light& light = scene.lights[static_cast<std::size_t>(node.light)];
        if (!light.castsShadow) continue;
        (light.type == LightType::Point ? casters.cubes : casters.maps2d) += 1;
        if (light.type == LightType::Directional) ++casters.directional;
    }
    if (!anyLight) casters.maps2d = casters.directional = 1;
    casters.sheets = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return drawnAsSheet(m); });
    return casters;
}

std::uint64_t shadowMapBytes(const ShadowCasters& casters, int mapSize, int cascades) {
    const std::uint64_t texels = saturatingMul(positive(mapSize), positive(mapSize));
    const std::uint64_t layers = static_cast<std::uint64_t>(std::clamp(casters.maps2d, 0, LIT_MAX_SHADOW_2D)) +
                                 6u * static_cast<std::uint64_t>(std::clamp(casters.cubes, 0, LIT_MAX_SHADOW_CUBE));
    // Directional lights beyond the 2D array's layers get no map, so no cascades either.
    const int directional = std::min({casters.directional, casters.maps2d, LIT_MAX_SHADOW_2D, LIT_MAX_CASCADED_LIGHTS});
    const std::uint64_t cascadeLayers = static_cast<std::uint64_t>(std::max(directional, 0)) *
                                        static_cast<std::uint64_t>(std::clamp(cascades, 0, LIT_MAX_SHADOW_CASCADES));
    return saturatingAdd(saturatingMul(saturatingMul(texels, layers), casters.sheets ? 4 + 8 : 4),
                         saturatingMul(saturatingMul(texels, cascadeLayers), 4));
}

std::uint64_t textureBytesWithMips(int width, int height) {
    std::uint64_t bytes = 0;
    std::uint64_t w = positive(width), h = positive(height);
    if (w == 0 || h == 0) return 0;
    for (;;) {
        bytes = saturatingAdd(bytes, saturatingMul(saturatingMul(w, h), 4));
        if (w == 1 && h == 1) return bytes;
        w = std::max<std::uint64_t>(1, w / 2);
        h = std::max<std::uint64_t>(1, h / 2);
    }
}

SceneMemory estimateSceneMemory(std::span<const ImageExtent> images, std::uint64_t vertices, std::uint64_t indices,
                                const ShadowCasters& casters, const RenderFootprint& render) {
    SceneMemory memory;
    for (const ImageExtent& image : images) {
        const std::uint64_t pixels = saturatingMul(positive(image.width), positive(image.height));
        memory.decodedImages = saturatingAdd(memory.decodedImages, saturatingMul(pixels, 4));
        if (image.textured) memory.textures = saturatingAdd(memory.textures, textureBytesWithMips(image.width, image.height));
    }
    // The Scene keeps its vertices and indices after GpuScene copied them into GL buffers.
    const std::uint64_t geometry =
        saturatingAdd(saturatingMul(vertices, sizeof(Vertex)), saturatingMul(indices, sizeof(std::uint32_t)));
    memory.geometry = saturatingMul(geometry, 2);
    if (render.voxelResolution > 0) {
        const std::uint64_t volumes = 1u + static_cast<std::uint64_t>(std::max(render.nearLevels, 0));
        memory.voxels = saturatingMul(voxelVolumeBytes(render.voxelResolution, render.radianceRgba8, render.bounceVolumes), volumes);
        // The hit records grow with the occupied voxels, at most every voxel, and the cache
        // allocates none beyond its cap (the passes then march instead).
        if (render.voxelRays > 0) {
            const std::uint64_t side = positive(render.voxelResolution);
            const std::uint64_t everyVoxel =
                saturatingMul(saturatingMul(saturatingMul(side, side), side), 2 * 4 * positive(render.voxelRays));
            memory.rayHits = saturatingMul(std::min<std::uint64_t>(everyVoxel, RayHitCache::kMaxBytes), volumes);
        }
    }
    memory.targets = saturatingMul(saturatingMul(positive(render.width), positive(render.height)), kTargetBytesPerPixel);
    memory.shadowMaps = shadowMapBytes(casters, render.shadowMapSize, render.shadowCascades);
    return memory;
}

SceneMemory estimateSceneMemory(const Scene& scene, const RenderFootprint& render) {
    std::vector<ImageExtent> images(scene.images.size());
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        images[i].width = scene.images[i].width;
        images[i].height = scene.images[i].height;
        images[i].textured = false;
    }
    for (const Texture& texture : scene.textures)
        if (texture.image >= 0 && static_cast<std::size_t>(texture.image) < images.size())
            images[static_cast<std::size_t>(texture.image)].textured = true;
    std::uint64_t vertices = 0, indices = 0;
    for (const Mesh& mesh : scene.meshes)
        for (const Primitive& primitive : mesh.primitives) {
            vertices += primitive.vertices.size();
            indices += primitive.indices.size();
        }
    return estimateSceneMemory(images, vertices, indices, shadowCastersOf(scene), render);
}

MemoryLimit renderMemoryLimit() {
    // Digits only: strtoull would read "-5" as a huge number.
    if (const char* cap = std::getenv("LIT_MAX_RENDER_MB"); cap && *cap >= '0' && *cap <= '9') {
        char* end = nullptr;
        const unsigned long long megabytes = std::strtoull(cap, &end, 10);
        if (end && *end == '\0' && megabytes > 0)
            return {saturatingMul(megabytes, 1'000'000), "LIT_MAX_RENDER_MB"};
    }
    return {kDefaultSceneMemoryLimit, kDefaultSceneMemoryLimitSource};
}

std::optional<std::string> overMemoryLimit(const SceneMemory& memory, const MemoryLimit& limit) {
    if (limit.bytes == 0 || memory.total() <= limit.bytes) return std::nullopt;
    return "scene needs " + formatBytes(memory.total(), memory.total()) + " of memory (" + memory.describe() + "), over the limit of " + formatBytes(limit.bytes, limit.bytes) +
           (limit.source.empty() ? std::string() : " (" + limit.source + ")");
}

std::string formatBytes(std::uint64_t bytes, std::uint64_t unitOf) {
    char text[48];
    const double value = static_cast<double>(bytes);
    if (unitOf >= 1'000'000'000ull)
        std::snprintf(text, sizeof text, "%.1f GB", value / 1e9);
    else if (unitOf >= 1'000'000ull)
        std::snprintf(text, sizeof text, "%.1f MB", value / 1e6);
    else
        std::snprintf(text, sizeof text, "%.1f kB", value / 1e3);
    return text;
}

}  // namespace lit
