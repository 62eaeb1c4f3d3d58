#include "reference/AccuracyRegions.h"

#include "scene/Scene.h"

#include <algorithm>

namespace lit::reference {

std::size_t NamedRegion::pixels() const { return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), true)); }

PixelMask indirectOnlyMask(const std::vector<FirstHit>& hits) {
    PixelMask mask(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) mask[i] = hits[i].node >= 0 && hits[i].litBy == 0 && !hits[i].emissive;
    return mask;
}

PixelMask directlyLitMask(const std::vector<FirstHit>& hits) {
    PixelMask mask(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) mask[i] = hits[i].node >= 0 && hits[i].litBy != 0;
    return mask;
}

PixelMask surfaceMask(const std::vector<FirstHit>& hits) {
    PixelMask mask(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) mask[i] = hits[i].node >= 0;
    return mask;
}

PixelMask nodeMask(const Scene& scene, const std::vector<FirstHit>& hits, const std::string& nodeName) {
    PixelMask mask(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const int node = hits[i].node;
        mask[i] = node >= 0 && static_cast<std::size_t>(node) < scene.nodes.size() &&
                  scene.nodes[static_cast<std::size_t>(node)].name == nodeName;
    }
    return mask;
}

PixelMask erodeEdges(const PixelMask& mask, const std::vector<FirstHit>& hits, int width, int height, int radius) {
    PixelMask out(mask.size(), false);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
            if (!mask[i]) continue;
            bool keep = y >= radius && x >= radius && y < height - radius && x < width - radius;
            for (int dy = -radius; dy <= radius && keep; ++dy)
                for (int dx = -radius; dx <= radius && keep; ++dx) {
                    const FirstHit& h = hits[static_cast<std::size_t>((y + dy) * width + x + dx)];
                    keep = h.node == hits[i].node && h.litBy == hits[i].litBy && glm::dot(h.normal, hits[i].normal) > 0.99f;
                }
            out[i] = keep;
        }
    return out;
}

std::vector<NamedRegion> cornellBoxRegions(const Scene& scene, const std::vector<FirstHit>& hits, int width, int height) {
    std::vector<NamedRegion> regions;
    const PixelMask indirect = indirectOnlyMask(hits);
    const auto add = [&](const std::string& name, const std::string& node, auto&& keep) {
        const PixelMask onNode = nodeMask(scene, hits, node);
        if (std::find(onNode.begin(), onNode.end(), true) == onNode.end()) return;
        PixelMask mask(hits.size());
        for (std::size_t i = 0; i < hits.size(); ++i) mask[i] = onNode[i] && indirect[i] && keep(hits[i].position);
        // Two pixels off every edge: the rasterizer's shadow maps move shadow edges by a texel or so.
        regions.push_back({name, erodeEdges(mask, hits, width, height, 2)});
    };
    // The red wall's side of the floor: x < 0 in assets/cornell_box.gltf; the suite's mirrored and
    // colour-swapped variants (tools/make_gi_suite.cpp) put it at x > 0. The side is where the
    // camera sees the red wall (its pixels' mean x), so region names follow the wall colours.
    double redX = 0.0;
    std::size_t redPixels = 0;
    const PixelMask red = nodeMask(scene, hits, "left_wall_red");
    for (std::size_t i = 0; i < hits.size(); ++i)
        if (red[i]) {
            redX += hits[i].position.x;
            ++redPixels;
        }
    const float redSide = redPixels > 0 && redX > 0.0 ? 1.0f : -1.0f;
    add("ceiling", "ceiling", [](const glm::vec3&) { return true; });
    add("shadowed floor by red wall", "floor", [redSide](const glm::vec3& p) { return p.x * redSide > 0.0f; });
    add("shadowed floor by green wall", "floor", [redSide](const glm::vec3& p) { return p.x * redSide < 0.0f; });
    // The blocks are 1.2 m and 0.6 m tall; the spot's outer cone reaches the back wall up to ≈ 1.3 m.
    add("back wall above blocks", "back_wall", [](const glm::vec3& p) { return p.y > 1.3f; });
    return regions;
}

glm::dvec3 maskedMean(const std::vector<float>& rgb, const PixelMask& mask) {
    glm::dvec3 sum(0.0);
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            sum += glm::dvec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
            ++count;
        }
    return count ? sum / static_cast<double>(count) : glm::dvec3(0.0);
}

}  // namespace lit::reference
