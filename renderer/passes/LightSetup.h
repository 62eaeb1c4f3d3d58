#pragma once
// Turns the scene's punctual lights into the GPU light table: world position and direction
// from their nodes, the KHR_lights_punctual spot parameters, and one shadow-map slot and
// light-space matrix per shadow-casting light.

#include "RenderSettings.h"
#include "scene/Aabb.h"

#include <shared.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
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
    // The directional lights (indices into `lights`) that also get the camera's cascades, in the
    // order of their slots (GpuLight::spotShadow.w).
    std::vector<int> cascaded;
    // The shadow maps also hold what transmissive sheets let through (ShadowPass, lights.glsl); set
    // by the renderer when the scene has sheets.
    bool sheetShadows = false;
};

// The kinds of shadow map a light table uses. The programs that light from it (direct lighting,
// injection) compile out the lookups of a kind no light has (LIT_SHADOWS_CUBE, LIT_SHADOWS_2D in
// lights.glsl; gl::ProgramVariants): llvmpipe ran the point lights' four cube lookups for every
// pixel of a scene lit by a spot light alone, a third of its lighting pass (docs/PERFORMANCE.md,
// "llvmpipe"). The default has both, right for any table.
struct ShadowKinds {
    bool cube = true;     // a point light with a cube shadow map
    bool flat = true;     // a directional or spot light with a 2D one
    bool sheets = false;  // the maps hold transmissive sheets' transmittance (LightSetup::sheetShadows)

    static ShadowKinds of(const LightSetup& setup) {
        const bool cube = !setup.shadowsCube.empty(), flat = !setup.shadows2d.empty();
        return {cube, flat, setup.sheetShadows && (cube || flat)};
    }
    static constexpr std::size_t kVariants = 8;
    std::size_t index() const { return (cube ? 1u : 0u) + (flat ? 2u : 0u) + (sheets ? 4u : 0u); }
    std::string defines() const {
        return std::string("#define LIT_SHADOWS_CUBE ") + (cube ? "1" : "0") + "\n#define LIT_SHADOWS_2D " +
               (flat ? "1" : "0") + "\n#define LIT_SHADOWS_SHEETS " + (sheets ? "1" : "0") + "\n";
    }
    std::string label() const {
        const std::string sheetLabel = sheets ? " (sheets)" : "";
        if (cube && flat) return sheetLabel;
        return (cube ? " (cube shadows)" : (flat ? " (2D shadows)" : " (no shadows)")) + sheetLabel;
    }
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
