#pragma once
// Line shapes for the viewport overlay (Overlay.h), built on the CPU: camera frusta, light
// markers, the translate gizmo, wireframe cones, and the cones the cone-trace shader traces from
// one pixel (the "cone directions" debug view). Pure functions of their arguments; no GL.

#include "Overlay.h"
#include "RenderSettings.h"

#include <glm/glm.hpp>

#include <vector>

namespace lit {

struct Light;

// Segments per circle of the shapes below: round enough at editor sizes, few lines.
inline constexpr int kOverlayCircleSegments = 32;

// Axis colours of the gizmo (linear RGB, opaque).
inline constexpr glm::vec4 kGizmoColorX{1.0f, 0.15f, 0.15f, 1.0f};
inline constexpr glm::vec4 kGizmoColorY{0.15f, 1.0f, 0.15f, 1.0f};
inline constexpr glm::vec4 kGizmoColorZ{0.2f, 0.35f, 1.0f, 1.0f};

// A camera's view pyramid: apex at the camera, the four edges to the corners of the image
// rectangle at `length` metres down the camera's −Z, that rectangle, and a small triangle above its
// top edge that shows which way is up. `world` is the camera node's world matrix (its scale is
// ignored, as for rendering); `yfov` in radians, `aspect` = width / height.
std::vector<OverlayLine> cameraFrustumLines(const glm::mat4& world, float yfov, float aspect, float length,
                                            const glm::vec4& color);

// A marker for a light held by the node with world matrix `world`, `size` metres across, in the
// light's colour: directional → an arrow along the node's −Z (the direction light travels);
// point → three circles of radius size/2 in the node's XY, YZ and ZX planes; spot → the outer
// cone (half angle outerConeAngle) down −Z, `size` long, with the circle at its end.
std::vector<OverlayLine> lightMarkerLines(const Light& light, const glm::mat4& world, float size);

// The translate gizmo at `origin`: X (red), Y (green), Z (blue) world axes `length` metres long,
// each with an arrow head (four lines from the tip back to a point 20 % down the axis).
std::vector<OverlayLine> translateGizmoLines(const glm::vec3& origin, float length);

// A wireframe cone: apex, unit axis `direction`, full apex angle `apertureRadians`, `length`
// metres along the axis: the axis, eight side lines and the circles at half and full length.
std::vector<OverlayLine> coneLines(const glm::vec3& apex, const glm::vec3& direction, float apertureRadians,
                                   float length, const glm::vec4& color);

// One cone the cone-trace pass marches from a pixel.
struct TracedCone {
    glm::vec3 apex{0.0f};       // world (m): the surface point moved √3 voxels along the shading normal
    glm::vec3 direction{0.0f};  // unit world axis
    float aperture = 0.0f;      // full apex angle (rad)
    float length = 0.0f;        // maximum march distance (m): settings.maxTraceDistance × volume side
    float weight = 0.0f;        // diffuse: W_i/π (sums to 1); specular: the sample's normalised weight
    bool specular = false;
    // False for specular samples of rough lobes on diffuse surfaces: the shader marches no cone
    // for them but blends the diffuse cones' radiance in their direction (cone.glsl,
    // specularCanReuseDiffuseCones / radianceFromDiffuseCones).
    bool marched = true;
};

// The cones shaders/cone_trace.frag.glsl traces for `surface` seen from `cameraPosition` under
// `settings` when both indirect terms are on (the final view): the six diffuse cones
// (cone.glsl traceDiffuse; none when !surface.diffuse), then the specular cones (traceSpecular:
// clamp(specularSamples, 1, 8) GGX samples with the pixel's sample rotation, samples below the
// horizon dropped, the mirror direction when all are; marched = false where they reuse the
// diffuse cones). The diffuse table and the constants come
// from shared.h; the sampling functions (tangent frame, Hammersley point, hashes, GGX half vector)
// are C++ copies of cone.glsl's, checked by tests/unit/test_overlay_shapes.cpp. The renderer traces
// with sample pattern 0 every frame, so this does too. Lengths are 0 when surface.volumeSide is
// 0 (the sample comes from a frame without GI).
std::vector<TracedCone> tracedCones(const SurfaceSample& surface, const glm::vec3& cameraPosition,
                                    const RenderSettings& settings);

}  // namespace lit
