#pragma once
// The camera's shadow cascades of a directional light (docs/ARCHITECTURE.md, "Shadow cascades"):
// the view frustum is cut into slices at distances from the camera, and each slice gets an
// orthographic map around its bounding sphere. A sphere's size does not change as the camera turns,
// and its centre is snapped to a grid in light space, so a map's texels stay put on the world
// (no shimmer) and a map is drawn again only when its snapped centre moves. Pure math: no GL.

#include <glm/glm.hpp>
#include <vector>

#include "scene/Aabb.h"
#include "scene/CameraView.h"

namespace lit {

struct ShadowCascade {
    glm::mat4 viewProjection{1.0f};  // world → light clip space ([−1, 1]³)
    float worldTexel = 0.0f;         // metres per texel
    float depthRange = 0.0f;         // metres from the near to the far plane
    float farDistance = 0.0f;        // the slice's far end, metres from the camera along its view
    glm::ivec2 snappedCentre{0};     // the centre in snap steps of light space: a new value = a new map
    bool operator==(const ShadowCascade&) const = default;
};

// The far ends of `count` slices of [nearPlane, farPlane]: λ·logarithmic + (1 − λ)·uniform
// (the "practical split scheme", Zhang et al. 2006), the last one `farPlane`.
std::vector<float> cascadeSplits(float nearPlane, float farPlane, int count, float lambda);

// The map of the slice [sliceNear, sliceFar] of `camera`'s frustum (aspect from its projection)
// for a light travelling along `direction`, `mapSize` texels square. It covers the slice's
// bounding sphere in x and y (the centre snapped to 1/16 of the map, the side grown by one step so
// the sphere stays inside), and in depth everything of `sceneBounds` between the light and the
// sphere's far side, so every caster of the slice is in it.
ShadowCascade fitShadowCascade(const glm::vec3& direction, const Aabb& sceneBounds, const CameraView& camera,
                               float sliceNear, float sliceFar, int mapSize);

// Every cascade of one light: `count` slices from the camera out to `distance`, at most (and
// when ≤ 0) the diagonal of `sceneBounds`, split by cascadeSplits from 1/1000 of that reach.
std::vector<ShadowCascade> fitShadowCascades(const glm::vec3& direction, const Aabb& sceneBounds,
                                             const CameraView& camera, int count, float distance, float lambda,
                                             int mapSize);

}  // namespace lit
