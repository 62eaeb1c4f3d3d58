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

// A circle of `radius` metres around `centre` in the plane perpendicular to `axis`, `segments` lines.
std::vector<OverlayLine> circleLines(const glm::vec3& centre, const glm::vec3& axis, float radius, const glm::vec4& color,
                                     int segments = kOverlayCircleSegments);

// One cone the cone-trace pass marches from a pixel.
struct TracedCone {
    glm::vec3 apex{0.0f};       // world (m): the surface point moved √3 voxels along the shading normal
    glm::vec3 direction{0.0f};  // unit world axis
    float aperture = 0.0f;      // full apex angle (rad)
    float length = 0.0f;        // maximum march distance (m): settings.gi.maxTraceDistance × volume side
    float weight = 0.0f;        // diffuse: W_i/π (sums to 1); specular: the sample's normalised weight
    bool specular = false;
    // False for specular samples of rough lobes on diffuse surfaces: the shader marches no cone
    // for them but blends the diffuse cones' radiance in their direction (cone.glsl,
    // specularCanReuseDiffuseCones / radianceFromDiffuseCones).
    bool marched = true;
    // Accurate mode (footprint-bounded cones): the stratified set the diffuse cones come from
    // (cone_strata.glsl, 0..LIT_CONE_STRATA²−1); −1 for the fixed six-cone set and for specular cones.
    int coneSet = -1;
    // Footprint-bounded diffuse cones (traceConeFromSurface): the sampled voxels are at most
    // footprintPerHeight × (startHeight + heightPerDistance · t) wide; footprintPerHeight 0 = unbounded.
    float footprintPerHeight = 0.0f;
    float startHeight = 0.0f;        // m: the apex's height above the surface
    float heightPerDistance = 1.0f;  // n · direction
};

// One step of a cone's march (cone.glsl, LIT_CONE_STEP_GEOMETRY): the sample at distance tMid
// (m) from the apex reads voxels `diameter` metres wide (mip level log2(diameter / voxelSize)).
struct ConeSample {
    float tMid = 0.0f;
    float diameter = 0.0f;
};

// The samples traceConeFromSurface takes along `cone` up to distance `upTo` (m) in an empty
// volume (a real march stops earlier where it turns opaque): the sampled widths, bounded by the
// footprint for bounded cones. `voxelSize` and `volumeSide` (m) as in SurfaceSample,
// `coneStepScale` GiSettings::coneStepScale; none when voxelSize is 0 (no GI).
std::vector<ConeSample> coneSamples(const TracedCone& cone, float voxelSize, float volumeSide, float coneStepScale,
                                    float upTo);

// C++ copies of shaders/include/cone_strata.glsl (the accurate mode's stratified diffuse cone sets),
// checked against the shader by tests/gl/test_cone_mirror.cpp.
// The set low-resolution texel `low` of the reduced trace traces (coneSetIndex).
int coneSetIndex(glm::ivec2 low);
// Tangent-space direction (z = normal) of diffuse cone i (0..5) of set `setIndex`.
glm::vec3 stratifiedDiffuseConeDirection(int i, int setIndex);
// The set whose cones the accurate mode traces for full-resolution GL pixel `glPixel`: that of
// the low-resolution texel the pixel falls in at frame 0 (jitter 0; the indirect scale as
// ConeTracePass::indirectScale); −1 when `settings` trace the fixed six-cone set (no footprint bound).
int coneSetOfPixel(glm::ivec2 glPixel, const RenderSettings& settings);

// The cones shaders/cone_trace.frag.glsl traces for `surface` seen from `cameraPosition` under
// `settings` when both indirect terms are on (the final view): the six diffuse cones
// (cone.glsl traceDiffuse; none when !surface.diffuse; in the accurate mode, coneFootprintPerHeight
// > 0, the pixel's stratified set, coneSetOfPixel, with their footprint bound), then the specular cones (traceSpecular:
// clamp(specularSamples, 1, 8) cones, specularLobeCone: one around the mirror direction, or GGX
// samples with the pixel's sample rotation, samples below the horizon dropped, the mirror
// direction when all are; marched = false where they reuse the diffuse cones). The diffuse table and the constants come
// from shared.h; the sampling functions (tangent frame, Hammersley point, hashes, GGX half vector)
// are C++ copies of cone.glsl's, checked by tests/unit/test_overlay_shapes.cpp. The renderer traces
// with sample pattern 0 every frame, so this does too. Lengths are 0 when surface.volumeSide is
// 0 (the sample comes from a frame without GI).
std::vector<TracedCone> tracedCones(const SurfaceSample& surface, const glm::vec3& cameraPosition,
                                    const RenderSettings& settings);

}  // namespace lit
