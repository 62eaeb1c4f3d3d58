#include "scene/OverlayShapes.h"

#include <shared.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gi/ConeProgram.h"
#include "passes/ConeTracePass.h"
#include "scene/RadicalInverse.h"
#include "scene/Scene.h"

namespace lit {

namespace {

constexpr float kPi = 3.14159265358979323846f;

// Rotation and translation of a node's world matrix; the axes are normalised so a scaled node
// gets a marker of the requested size.
struct NodeFrame {
    glm::vec3 origin, x, y, z;
};

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return length > 1e-12f && std::isfinite(length) ? v / length : fallback;
}

NodeFrame frameOf(const glm::mat4& world) {
    return {glm::vec3(world[3]), normalizedOr(glm::vec3(world[0]), {1, 0, 0}),
            normalizedOr(glm::vec3(world[1]), {0, 1, 0}), normalizedOr(glm::vec3(world[2]), {0, 0, 1})};
}

// Any unit vector perpendicular to unit `v`.
glm::vec3 perpendicular(const glm::vec3& v) {
    const glm::vec3 other = std::abs(v.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(v, other));
}

void addCircle(std::vector<OverlayLine>& lines, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v,
               float radius, const glm::vec4& color, int segments = kOverlayCircleSegments) {
    for (int i = 0; i < segments; ++i) {
        const float a0 = 2.0f * kPi * float(i) / float(segments);
        const float a1 = 2.0f * kPi * float(i + 1) / float(segments);
        lines.push_back({centre + radius * (std::cos(a0) * u + std::sin(a0) * v),
                         centre + radius * (std::cos(a1) * u + std::sin(a1) * v), color});
    }
}

// An arrow from `from` to `to` with a head of four lines, `headLength` long and half as wide.
void addArrow(std::vector<OverlayLine>& lines, const glm::vec3& from, const glm::vec3& to, float headLength,
              const glm::vec4& color) {
    lines.push_back({from, to, color});
    const glm::vec3 axis = normalizedOr(to - from, {0, 0, -1});
    const glm::vec3 u = perpendicular(axis), v = glm::cross(axis, u);
    const glm::vec3 base = to - axis * headLength;
    const float r = 0.35f * headLength;
    for (const glm::vec3& side : {u, -u, v, -v}) lines.push_back({to, base + side * r, color});
}

// The light's colour as a marker colour: its hue at full brightness (intensity is not shown).
glm::vec4 markerColor(const glm::vec3& color) {
    const float peak = std::max({color.r, color.g, color.b});
    return peak > 0.0f ? glm::vec4(color / peak, 1.0f) : glm::vec4(1.0f);
}

// ---- C++ copies of cone.glsl / gbuffer.glsl / brdf.glsl functions (same names, same float math) --

glm::vec3 shadingNormal(const glm::vec3& n, const glm::vec3& v) {
    const float nv = glm::dot(n, v);
    return nv < 0.0f ? glm::normalize(n - v * (nv * 1.01f)) : n;
}

glm::mat3 tangentFrame(const glm::vec3& n) {
    const float s = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (s + n.z);
    const float b = n.x * n.y * a;
    const glm::vec3 t(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    const glm::vec3 bt(b, s + n.y * n.y * a, -n.y);
    return glm::mat3(t, bt, n);
}

float fract(float x) { return x - std::floor(x); }

float interleavedGradientNoise(const glm::vec2& pixel) {
    return fract(52.9829189f * fract(glm::dot(pixel, glm::vec2(0.06711056f, 0.00583715f))));
}

std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

glm::vec2 specularSample(int k, int count, const glm::vec2& pixel, int frameIndex) {
    const std::uint32_t px = std::uint32_t(pixel.x), py = std::uint32_t(pixel.y);
    const std::uint32_t hash = pcgHash(px + pcgHash(py + pcgHash(std::uint32_t(frameIndex))));
    const glm::vec2 rotation(float(hash) * 2.3283064365386963e-10f,
                             interleavedGradientNoise(pixel + glm::vec2(float(frameIndex % 64) * 5.588238f)));
    const glm::vec2 u(fract(float(k) / float(count) + rotation.x), fract(radicalInverse(std::uint32_t(k)) + rotation.y));
    return {u.x * float(LIT_SPECULAR_LOBE_SHARE), u.y};
}

glm::vec3 sampleGgxHalfVector(const glm::vec2& u, float alpha) {
    const float a2 = alpha * alpha;
    const float cos2 = (1.0f - u.x) / (1.0f + (a2 - 1.0f) * u.x);
    const float cosTheta = std::sqrt(std::clamp(cos2, 0.0f, 1.0f));
    const float sinTheta = std::sqrt(std::clamp(1.0f - cos2, 0.0f, 1.0f));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

float G_SmithGGXCorrelated(float NdotL, float NdotV, float alpha) {
    const float a2 = alpha * alpha;
    const float lambdaV = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
    const float lambdaL = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
    return 2.0f * NdotL * NdotV / std::max(lambdaV + lambdaL, 1e-7f);
}

float ggxSampleWeight(const glm::vec3& n, const glm::vec3& v, const glm::vec3& h, float alpha, glm::vec3& l) {
    const float VdotH = glm::dot(v, h);
    l = 2.0f * VdotH * h - v;
    const float NdotL = glm::dot(n, l);
    if (VdotH <= 0.0f || NdotL <= 0.0f) return 0.0f;
    const float NdotV = std::max(glm::dot(n, v), 1e-4f);
    const float NdotH = std::max(glm::dot(n, h), 1e-4f);
    return G_SmithGGXCorrelated(NdotL, NdotV, alpha) * VdotH / (NdotH * NdotV);
}

// cone.glsl's specularLobeCone.
float specularLobeCone(int k, int count, const glm::vec3& n, const glm::vec3& v, const glm::mat3& basis, float alpha,
                       const glm::vec2& pixel, int frameIndex, glm::vec3& l) {
    if (count <= 1) {
        l = glm::reflect(-v, n);
        return 1.0f;
    }
    const glm::vec3 h = basis * sampleGgxHalfVector(specularSample(k, count, pixel, frameIndex), alpha);
    return ggxSampleWeight(n, v, h, alpha, l);
}

float alphaFromRoughness(float roughness) {
    const float r = std::clamp(roughness, 0.03f, 1.0f);
    return r * r;
}

// cone.glsl's: the single cone as wide as each of two samples'.
float specularConeAperture(float alpha, int count) {
    const float halfAngle = std::atan(2.0f * alpha / std::sqrt(float(std::max(count, 2))));
    return std::clamp(2.0f * halfAngle, float(LIT_SPECULAR_APERTURE_MIN), float(LIT_SPECULAR_APERTURE_MAX));
}

// cone.glsl's specularCanReuseDiffuseCones: the lobe's halves against the diffuse cones.
bool specularCanReuseDiffuseCones(float alpha, float diffuseAperture) {
    return specularConeAperture(alpha, 2) >= diffuseAperture - float(LIT_CONE_REUSE_TOLERANCE);
}

}  // namespace

std::vector<OverlayLine> cameraFrustumLines(const glm::mat4& world, float yfov, float aspect, float length,
                                            const glm::vec4& color) {
    const NodeFrame f = frameOf(world);
    const float halfHeight = length * std::tan(0.5f * yfov);
    const float halfWidth = halfHeight * aspect;
    const glm::vec3 centre = f.origin - f.z * length;
    const glm::vec3 corners[4] = {centre - f.x * halfWidth - f.y * halfHeight, centre + f.x * halfWidth - f.y * halfHeight,
                                  centre + f.x * halfWidth + f.y * halfHeight, centre - f.x * halfWidth + f.y * halfHeight};
    std::vector<OverlayLine> lines;
    for (int i = 0; i < 4; ++i) {
        lines.push_back({f.origin, corners[i], color});
        lines.push_back({corners[i], corners[(i + 1) % 4], color});
    }
    // "Up" triangle on the top edge (corners 2 and 3), a third of the image width wide.
    const glm::vec3 top = centre + f.y * halfHeight;
    const glm::vec3 apex = top + f.y * (0.6f * halfWidth);
    lines.push_back({top - f.x * (0.35f * halfWidth), apex, color});
    lines.push_back({apex, top + f.x * (0.35f * halfWidth), color});
    lines.push_back({top + f.x * (0.35f * halfWidth), top - f.x * (0.35f * halfWidth), color});
    return lines;
}

std::vector<OverlayLine> lightMarkerLines(const Light& light, const glm::mat4& world, float size) {
    const NodeFrame f = frameOf(world);
    const glm::vec4 color = markerColor(light.color);
    std::vector<OverlayLine> lines;
    switch (light.type) {
        case LightType::Directional: {
            // The arrow, and a small circle at its tail so it reads as a "sun" from the front.
            addArrow(lines, f.origin, f.origin - f.z * size, 0.25f * size, color);
            addCircle(lines, f.origin, f.x, f.y, 0.15f * size, color);
            break;
        }
        case LightType::Point: {
            const float r = 0.5f * size;
            addCircle(lines, f.origin, f.x, f.y, r, color);
            addCircle(lines, f.origin, f.y, f.z, r, color);
            addCircle(lines, f.origin, f.z, f.x, r, color);
            break;
        }
        case LightType::Spot: {
            const float angle = std::clamp(light.outerConeAngle, 0.0f, 0.5f * kPi - 1e-3f);
            const float radius = size * std::tan(angle);
            const glm::vec3 end = f.origin - f.z * size;
            addCircle(lines, end, f.x, f.y, radius, color);
            for (const glm::vec3& side : {f.x, -f.x, f.y, -f.y}) lines.push_back({f.origin, end + side * radius, color});
            break;
        }
    }
    return lines;
}

std::vector<OverlayLine> translateGizmoLines(const glm::vec3& origin, float length) {
    std::vector<OverlayLine> lines;
    const std::pair<glm::vec3, glm::vec4> axes[3] = {
        {{1, 0, 0}, kGizmoColorX}, {{0, 1, 0}, kGizmoColorY}, {{0, 0, 1}, kGizmoColorZ}};
    for (const auto& [axis, color] : axes) addArrow(lines, origin, origin + axis * length, 0.2f * length, color);
    return lines;
}

std::vector<OverlayLine> circleLines(const glm::vec3& centre, const glm::vec3& axis, float radius, const glm::vec4& color,
                                     int segments) {
    const glm::vec3 a = normalizedOr(axis, {0, 0, -1});
    const glm::vec3 u = perpendicular(a), v = glm::cross(a, u);
    std::vector<OverlayLine> lines;
    addCircle(lines, centre, u, v, radius, color, std::max(segments, 3));
    return lines;
}

std::vector<OverlayLine> coneLines(const glm::vec3& apex, const glm::vec3& direction, float apertureRadians,
                                   float length, const glm::vec4& color) {
    const glm::vec3 axis = normalizedOr(direction, {0, 0, -1});
    const glm::vec3 u = perpendicular(axis), v = glm::cross(axis, u);
    const float halfAngle = std::clamp(0.5f * apertureRadians, 0.0f, 0.5f * kPi - 1e-3f);
    const float radius = length * std::tan(halfAngle);
    const glm::vec3 end = apex + axis * length;
    std::vector<OverlayLine> lines;
    lines.push_back({apex, end, color});
    for (int i = 0; i < 8; ++i) {
        const float a = 2.0f * kPi * float(i) / 8.0f;
        lines.push_back({apex, end + radius * (std::cos(a) * u + std::sin(a) * v), color});
    }
    addCircle(lines, end, u, v, radius, color);
    addCircle(lines, apex + axis * (0.5f * length), u, v, 0.5f * radius, color);
    return lines;
}

int coneSetIndex(glm::ivec2 low) {
    constexpr int strata = LIT_CONE_STRATA;
    glm::ivec2 cell(static_cast<int>(static_cast<unsigned>(low.x) % unsigned(strata)),
                    static_cast<int>(static_cast<unsigned>(low.y) % unsigned(strata)));
    if (strata == 4) cell = ((cell & 1) << 1) | (cell >> 1);
    return cell.x + strata * cell.y;
}

glm::vec3 stratifiedDiffuseConeDirection(int i, int setIndex) {
    constexpr int strata = LIT_CONE_STRATA;
    const float n = float(strata);
    if (i == 0) {
        const int a = setIndex % strata, p = setIndex / strata;
        const float sin2 = 0.25f * (float(p) + 0.5f) / n;
        const float phi = 2.0f * kPi * (float(a) + (float(p) + 0.5f) / n) / n;
        const float s = std::sqrt(sin2);
        return {s * std::cos(phi), s * std::sin(phi), std::sqrt(1.0f - sin2)};
    }
    const int cell = (setIndex + (strata + 1) * (i - 1)) % (strata * strata);
    const int a = cell % strata, p = cell / strata;
    const float sin2 = 0.25f + 0.75f * (float(p) + 0.5f) / n;
    const float phi = (72.0f * kPi / 180.0f) * (float(i - 1) + (float(a) + 0.5f) / n - 0.5f);
    const float s = std::sqrt(sin2);
    return {s * std::cos(phi), s * std::sin(phi), std::sqrt(1.0f - sin2)};
}

int coneSetOfPixel(glm::ivec2 glPixel, const RenderSettings& settings) {
    if (!ConeFeatures::of(settings).footprint) return -1;
    // Footprint-bounded cones always take the reduced path (ConeTracePass::reducedPath): texel
    // (pixel − jitter) / scale, as the resolve's fallback computes it; the jitter is 0 at frame 0.
    const int scale = ConeTracePass::indirectScale(settings);
    return coneSetIndex(glm::max(glPixel, glm::ivec2(0)) / scale);
}

std::vector<ConeSample> coneSamples(const TracedCone& cone, float voxelSize, float volumeSide, float coneStepScale,
                                    float upTo) {
    // traceConeFromSurface's LIT_CONE_STEP_GEOMETRY (cone.glsl), without the opacity that ends a real
    // march; kConeStartVoxels = 1, the step scale clamped as VoxelVolume::updateUniforms does.
    std::vector<ConeSample> samples;
    if (voxelSize <= 0.0f) return samples;
    const float stepScale = std::max(coneStepScale, 0.05f);
    const float widthPerDistance = 2.0f * std::tan(0.5f * std::clamp(cone.aperture, 0.0f, float(LIT_CONE_APERTURE_MAX)));
    const float maxLevelVoxelSize = std::max(volumeSide, voxelSize);
    const bool bounded = cone.footprintPerHeight > 0.0f;
    const auto bound = [&](float t) {
        return bounded ? cone.footprintPerHeight * (cone.startHeight + cone.heightPerDistance * t) : 1e30f;
    };
    constexpr int kConeMaxSteps = 1800;  // cone.glsl
    float t = voxelSize;                 // kConeStartVoxels = 1
    const float end = std::min(upTo, cone.length);
    for (int i = 0; i < kConeMaxSteps && t <= end; ++i) {
        const float stepLength = std::max(stepScale * std::max(voxelSize, std::min(widthPerDistance * t, bound(t))),
                                          0.5f * voxelSize);
        const float tMid = t + 0.5f * stepLength;
        const float diameter = std::max(voxelSize, std::min(widthPerDistance * tMid, bound(tMid)));
        samples.push_back({tMid, std::min(diameter, maxLevelVoxelSize)});
        t += stepLength;
    }
    return samples;
}

std::vector<TracedCone> tracedCones(const SurfaceSample& surface, const glm::vec3& cameraPosition,
                                    const RenderSettings& settings) {
    // cone_trace.frag.glsl, main(): view vector, shading normal, cone origin, trace length.
    const glm::vec3 v = normalizedOr(cameraPosition - surface.position, surface.normal);
    const glm::vec3 n = shadingNormal(normalizedOr(surface.normal, {0, 1, 0}), v);
    const glm::vec3 origin = surface.position + n * (float(LIT_CONE_NORMAL_OFFSET_VOXELS) * surface.voxelSize);
    const float maxDistance = settings.gi.maxTraceDistance * surface.volumeSide;

    std::vector<TracedCone> cones;
    const glm::mat3 basis = tangentFrame(n);
    // traceCone clamps the aperture.
    const float diffuseAperture = std::clamp(settings.gi.diffuseConeAperture, 0.0f, float(LIT_CONE_APERTURE_MAX));
    // The accurate mode (indirect_trace.frag.glsl, LIT_CONE_FOOTPRINT): the stratified set of the
    // pixel's low-resolution texel (rotation 0: coneSetRotation), each cone footprint-bounded.
    const int coneSet = coneSetOfPixel(surface.glPixel, settings);
    if (surface.diffuse)
        for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
            const glm::vec3 local =
                coneSet >= 0 ? stratifiedDiffuseConeDirection(i, coneSet) : gpu::kDiffuseConeDirections[i];
            TracedCone cone{origin, glm::normalize(basis * local), diffuseAperture, maxDistance,
                            gpu::kDiffuseConeWeights[i], false, true};
            // traceDiffuseCone / traceDiffuseStratified: start height √3 voxels, rising at n·d = local.z.
            if (coneSet >= 0) {
                cone.coneSet = coneSet;
                cone.footprintPerHeight = settings.gi.footprintPerHeight();
                cone.startHeight = float(LIT_CONE_NORMAL_OFFSET_VOXELS) * surface.voxelSize;
                cone.heightPerDistance = local.z;
            }
            cones.push_back(cone);
        }

    // traceSpecular with the pixel's gl_FragCoord.xy (the pixel centre) and frame index 0.
    const int count = std::clamp(settings.indirect.specularSamples, 1, LIT_SPECULAR_MAX_SAMPLES);
    const float alpha = alphaFromRoughness(surface.roughness);
    const float aperture = specularConeAperture(alpha, count);
    // With the unclamped diffuse aperture the shader gets (traceParams.w).
    const bool marched = !(surface.diffuse && specularCanReuseDiffuseCones(alpha, settings.gi.diffuseConeAperture));
    const glm::vec2 fragCoord = glm::vec2(surface.glPixel) + 0.5f;
    const std::size_t firstSpecular = cones.size();
    float weightSum = 0.0f;
    for (int k = 0; k < count; ++k) {
        glm::vec3 l;
        const float w = specularLobeCone(k, count, n, v, basis, alpha, fragCoord, 0, l);
        if (w <= 0.0f) continue;
        cones.push_back({origin, normalizedOr(l, n), aperture, maxDistance, w, true, marched});
        weightSum += w;
    }
    if (weightSum <= 0.0f) {
        cones.push_back({origin, glm::reflect(-v, n), aperture, maxDistance, 1.0f, true, marched});
        weightSum = 1.0f;
    }
    for (std::size_t i = firstSpecular; i < cones.size(); ++i) cones[i].weight /= weightSum;
    return cones;
}

}  // namespace lit
