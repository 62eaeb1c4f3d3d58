#include "passes/ShadowCascades.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace lit {

namespace {

constexpr int kSnapSteps = 16;  // a map moves in steps of 1/16 of its side

}  // namespace

std::vector<float> cascadeSplits(float nearPlane, float farPlane, int count, float lambda) {
    std::vector<float> splits;
    if (count <= 0 || !(farPlane > nearPlane) || !(nearPlane > 0.0f)) return splits;
    const float l = std::clamp(lambda, 0.0f, 1.0f);
    for (int i = 1; i <= count; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(count);
        const float logarithmic = nearPlane * std::pow(farPlane / nearPlane, t);
        const float uniform = nearPlane + (farPlane - nearPlane) * t;
        splits.push_back(l * logarithmic + (1.0f - l) * uniform);
    }
    splits.back() = farPlane;
    return splits;
}

ShadowCascade fitShadowCascade(const glm::vec3& direction, const Aabb& sceneBounds, const CameraView& camera,
                               float sliceNear, float sliceFar, int mapSize) {
    const Aabb bounds = sceneBounds.empty() ? Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : sceneBounds;
    // The basis of the scene-wide map: its origin moves only when the scene's bounds do.
    const glm::mat4 lightView = directionalLightView(direction, bounds);

    // The slice's bounding sphere: its centre on the view axis at z, equidistant from the near and
    // far rectangles' corners, or at the far rectangle when that one alone is wider.
    const float tanX = 1.0f / std::max(std::abs(camera.projection[0][0]), 1e-6f);
    const float tanY = 1.0f / std::max(std::abs(camera.projection[1][1]), 1e-6f);
    const float k2 = tanX * tanX + tanY * tanY;
    const float a = std::max(sliceNear, 0.0f), b = std::max(sliceFar, a + 1e-4f);
    float z = 0.5f * (a + b) * (1.0f + k2);
    float radius;
    if (z >= b) {
        z = b;
        radius = b * std::sqrt(k2);
    } else {
        radius = std::sqrt((b - z) * (b - z) + b * b * k2);
    }
    const glm::vec3 centre = glm::vec3(lightView * glm::vec4(camera.position + camera.forward() * z, 1.0f));

    // Whole texels everywhere: the side is a whole number of texels, the snap step too, so a
    // redrawn map's texels land where the old ones were.
    const int size = std::max(mapSize, 16);
    const float step0 = 2.0f * radius / kSnapSteps;
    const float texel = 2.0f * (radius + step0) / static_cast<float>(size);
    const float step = texel * std::max(1.0f, std::round(step0 / texel));
    const glm::vec2 snapped = glm::round(glm::vec2(centre) / step);
    const glm::vec2 c = snapped * step;
    const float half = 0.5f * texel * static_cast<float>(size);

    float nearZ = std::numeric_limits<float>::lowest(), farZ = std::numeric_limits<float>::max();
    for (int i = 0; i < 8; ++i) {
        const float zi = (lightView * glm::vec4(bounds.corner(i), 1.0f)).z;
        nearZ = std::max(nearZ, zi);  // the light looks down −z: the largest z is nearest it
        farZ = std::min(farZ, zi);
    }
    const float margin = 1e-3f * (nearZ - farZ) + 1e-5f * std::max(bounds.radius(), 1e-3f);
    const float nearDistance = -nearZ - margin;
    // The sphere's far side rounded up to a snap step, so the depth range too changes only by steps.
    const float sphereFar = std::ceil((radius - centre.z) / step) * step;
    const float farDistance = std::max(std::min(sphereFar, -farZ) + margin, nearDistance + 2.0f * margin);

    ShadowCascade cascade;
    cascade.viewProjection =
        glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, nearDistance, farDistance) * lightView;
    cascade.worldTexel = texel;
    cascade.depthRange = farDistance - nearDistance;
    cascade.farDistance = b;
    cascade.snappedCentre = glm::ivec2(snapped);
    return cascade;
}

std::vector<ShadowCascade> fitShadowCascades(const glm::vec3& direction, const Aabb& sceneBounds,
                                             const CameraView& camera, int count, float distance, float lambda,
                                             int mapSize) {
    std::vector<ShadowCascade> cascades;
    if (count <= 0 || sceneBounds.empty()) return cascades;
    // The reach is the scene's diagonal (or less, as asked), not the distance to its farthest corner
    // or the camera's far plane, which change as the camera moves and would redraw every map.
    const float diagonal = 2.0f * sceneBounds.radius();
    const float farPlane = distance > 0.0f ? std::min(distance, diagonal) : diagonal;
    if (!(farPlane > 0.0f)) return cascades;
    // The logarithmic spacing starts at 1/1000 of the reach, not at the camera's near plane, and the
    // first slice at the camera: two front ends that frame the same view with other near planes
    // (the editor, lit-render) get the same maps.
    const float nearPlane = farPlane * 1e-3f;
    float sliceNear = 0.0f;
    for (const float split : cascadeSplits(nearPlane, farPlane, count, lambda)) {
        cascades.push_back(fitShadowCascade(direction, sceneBounds, camera, sliceNear, split, mapSize));
        sliceNear = split;
    }
    return cascades;
}

}  // namespace lit
