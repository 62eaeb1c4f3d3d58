#pragma once
// Turns the scene's punctual lights into the GPU light table: world position and direction
// from their nodes, the KHR_lights_punctual spot parameters, and one shadow-map slot and
// light-space matrix per shadow-casting light.

#include "RenderSettings.h"
#include "scene/Aabb.h"

#include <shared.h>

#include <glm/glm.hpp>

#include <vector>

namespace lit {

struct Scene;
class Log;

struct ShadowView {
    int light = -1;            // index into LightSetup::lights
    int layer = 0;             // layer of the 2D shadow array, or cube index for point lights
    bool cube = false;
    glm::mat4 viewProjection[6];  // 1 for directional/spot, 6 faces (GL cube order) for point
    float nearPlane = 0.0f, farPlane = 0.0f;  // metres (point and spot)
    glm::vec3 position{0.0f};
};

struct LightSetup {
    std::vector<gpu::GpuLight> lights;
    std::vector<ShadowView> shadows2d;    // directional + spot
    std::vector<ShadowView> shadowsCube;  // point
};

// Spot cone factors of the KHR_lights_punctual spec ("Inner and Outer Cone Angles"):
// attenuation = saturate(cos(θ)·scale + offset)², scale = 1/max(0.001, cos(inner) − cos(outer)),
// offset = −cos(outer)·scale.
glm::vec2 spotAngleScaleOffset(float innerConeAngle, float outerConeAngle);

// The cube-face view-projections for a point light at `position`, in GL cube-map face order
// (+X, −X, +Y, −Y, +Z, −Z), with the up vectors GL's cube-map addressing expects.
void cubeFaceViewProjections(const glm::vec3& position, float nearPlane, float farPlane, glm::mat4 out[6]);

LightSetup buildLightSetup(const Scene& scene, const Aabb& sceneBounds, const RenderSettings& settings, Log& log);

}  // namespace lit
