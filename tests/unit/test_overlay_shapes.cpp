// Overlay shapes (renderer/scene/OverlayShapes.h): gizmo axes, camera frustum corners, light
// markers, wireframe cones, and the cones tracedCones() says the cone-trace shader marches.
#include "scene/CameraView.h"
#include "scene/OverlayShapes.h"
#include "scene/Scene.h"

#include <shared.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace lit {
namespace {

constexpr float kPi = 3.14159265358979f;

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f) { return glm::length(a - b) < tolerance; }

TEST(OverlayShapes, GizmoAxesPointAlongWorldAxesInTheirColours) {
    const glm::vec3 origin(1.0f, -2.0f, 0.5f);
    const float length = 0.8f;
    const std::vector<OverlayLine> lines = translateGizmoLines(origin, length);
    const std::pair<glm::vec3, glm::vec4> axes[3] = {
        {{1, 0, 0}, kGizmoColorX}, {{0, 1, 0}, kGizmoColorY}, {{0, 0, 1}, kGizmoColorZ}};
    for (const auto& [axis, color] : axes) {
        int shafts = 0, headLines = 0;
        const glm::vec3 tip = origin + axis * length;
        for (const OverlayLine& line : lines) {
            if (line.color != color) continue;
            if (near(line.a, origin) && near(line.b, tip)) {
                ++shafts;
            } else {
                // Arrow head: from the tip back towards the origin, within 20 % of the length.
                ++headLines;
                EXPECT_TRUE(near(line.a, tip)) << "head line does not start at the tip";
                const float back = glm::dot(tip - line.b, axis);
                EXPECT_NEAR(back, 0.2f * length, 1e-4f);
                EXPECT_GT(glm::length(line.b - (tip - axis * back)), 0.0f) << "head line along the axis";
            }
        }
        EXPECT_EQ(shafts, 1) << "axis " << axis.x << axis.y << axis.z;
        EXPECT_EQ(headLines, 4);
    }
    EXPECT_EQ(lines.size(), 3u * 5u);
    // Red is X, green Y, blue Z.
    EXPECT_GT(kGizmoColorX.r, std::max(kGizmoColorX.g, kGizmoColorX.b));
    EXPECT_GT(kGizmoColorY.g, std::max(kGizmoColorY.r, kGizmoColorY.b));
    EXPECT_GT(kGizmoColorZ.b, std::max(kGizmoColorZ.r, kGizmoColorZ.g));
}

TEST(OverlayShapes, FrustumCornersProjectToTheImageCorners) {
    // A rotated, translated camera: the four edge ends must land on the image corners of the
    // view the renderer would build from the same node.
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 1.0f, 3.0f)) *
                            glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
    const float yfov = 0.9f, aspect = 1.6f, length = 2.5f;
    const glm::vec4 color(0.5f, 0.5f, 1.0f, 1.0f);
    const std::vector<OverlayLine> lines = cameraFrustumLines(world, yfov, aspect, length, color);
    const CameraView view = makeCameraView(world, yfov, aspect, 0.1f, 10.0f);
    const glm::vec3 eye(world[3]);
    int edges = 0;
    bool cornerSeen[2][2] = {};
    for (const OverlayLine& line : lines) {
        EXPECT_EQ(line.color, color);
        if (!near(line.a, eye)) continue;
        ++edges;
        const glm::vec4 clip = view.viewProjection() * glm::vec4(line.b, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_NEAR(std::abs(ndc.x), 1.0f, 1e-4f);
        EXPECT_NEAR(std::abs(ndc.y), 1.0f, 1e-4f);
        cornerSeen[ndc.x > 0][ndc.y > 0] = true;
        // `length` metres down the view axis.
        EXPECT_NEAR(glm::dot(line.b - eye, view.forward()), length, 1e-4f);
    }
    EXPECT_EQ(edges, 4);
    EXPECT_TRUE(cornerSeen[0][0] && cornerSeen[0][1] && cornerSeen[1][0] && cornerSeen[1][1]);
    EXPECT_EQ(lines.size(), 4u + 4u + 3u);  // edges, rectangle, up triangle
}

TEST(OverlayShapes, LightMarkers) {
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f)) *
                            glm::rotate(glm::mat4(1.0f), -0.5f * kPi, glm::vec3(1, 0, 0));  // −Z → −Y (down)
    const glm::vec3 origin(0.0f, 2.0f, 0.0f), down(0.0f, -1.0f, 0.0f);
    Light light;
    light.color = glm::vec3(2.0f, 1.0f, 0.5f);

    light.type = LightType::Point;
    std::vector<OverlayLine> lines = lightMarkerLines(light, world, 0.4f);
    EXPECT_EQ(lines.size(), 3u * kOverlayCircleSegments);
    for (const OverlayLine& line : lines) {
        EXPECT_NEAR(glm::length(line.a - origin), 0.2f, 1e-4f);
        EXPECT_TRUE(near(glm::vec3(line.color), glm::vec3(1.0f, 0.5f, 0.25f))) << "the light's hue at full brightness";
    }

    light.type = LightType::Directional;
    lines = lightMarkerLines(light, world, 0.5f);
    int shafts = 0;
    for (const OverlayLine& line : lines) shafts += near(line.a, origin) && near(line.b, origin + down * 0.5f);
    EXPECT_EQ(shafts, 1) << "arrow along the node's -Z";

    light.type = LightType::Spot;
    light.outerConeAngle = 0.4f;
    lines = lightMarkerLines(light, world, 1.0f);
    int sides = 0;
    for (const OverlayLine& line : lines) {
        if (!near(line.a, origin)) {
            // The circle at the cone's end, 1 m down.
            EXPECT_NEAR(glm::dot(line.a - origin, down), 1.0f, 1e-4f);
            continue;
        }
        ++sides;
        EXPECT_NEAR(angleBetween(line.b - origin, down), 0.4f, 1e-4f);
    }
    EXPECT_EQ(sides, 4);
}

TEST(OverlayShapes, ConeLinesStayOnTheConeSurface) {
    const glm::vec3 apex(0.5f, 0.0f, -1.0f), direction = glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f));
    const float aperture = 0.6f, length = 2.0f;
    const std::vector<OverlayLine> lines = coneLines(apex, direction, aperture, length, glm::vec4(1.0f));
    int axis = 0, sides = 0;
    for (const OverlayLine& line : lines) {
        if (near(line.a, apex)) {
            if (angleBetween(line.b - apex, direction) < 1e-3f) {
                ++axis;
                EXPECT_NEAR(glm::length(line.b - apex), length, 1e-4f);
            } else {
                ++sides;
                EXPECT_NEAR(angleBetween(line.b - apex, direction), 0.5f * aperture, 1e-4f);
            }
        } else {
            // Circle points are on the cone's surface too.
            EXPECT_NEAR(angleBetween(line.a - apex, direction), 0.5f * aperture, 1e-4f);
        }
    }
    EXPECT_EQ(axis, 1);
    EXPECT_EQ(sides, 8);
}

// The diffuse cone table (shared.h, read by C++ and cone.glsl): unit directions, one along the
// normal and five at 60° from it 72° apart, weights summing to 1 (= π / π, docs in cone.glsl).
TEST(OverlayShapes, SharedDiffuseConeTable) {
    float weights = 0.0f;
    for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
        EXPECT_NEAR(glm::length(gpu::kDiffuseConeDirections[i]), 1.0f, 1e-6f);
        weights += gpu::kDiffuseConeWeights[i];
    }
    EXPECT_NEAR(weights, 1.0f, 1e-6f);
    EXPECT_EQ(gpu::kDiffuseConeDirections[0], glm::vec3(0, 0, 1));
    for (int i = 1; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
        EXPECT_NEAR(gpu::kDiffuseConeDirections[i].z, 0.5f, 1e-6f);
        const float azimuth = std::atan2(gpu::kDiffuseConeDirections[i].y, gpu::kDiffuseConeDirections[i].x);
        const float expected = 2.0f * kPi * float(i - 1) / 5.0f;
        EXPECT_NEAR(std::remainder(azimuth - expected, 2.0f * kPi), 0.0f, 1e-5f) << "cone " << i;
    }
}

// The stratified sets (C++ copy of cone_strata.glsl; tests/gl/test_cone_mirror.cpp compares it with
// the shader): over the LIT_CONE_STRATA² sets each region gets LIT_CONE_STRATA² different
// directions, all inside the region (cap θ < 30°; side region i within ±36° of azimuth 72°(i − 1),
// 30° ≤ θ < 90°), and the mean of their cosθ is the region's cosine-weighted mean cosθ (the cells
// are of equal projected solid angle): cap (2/3)(1 − cos³30°)/sin²30° ≈ 0.9346, ring
// (2/3)cos³30°/cos²30° ≈ 0.5774.
TEST(OverlayShapes, StratifiedConeSetsCoverEachRegionOnce) {
    constexpr int sets = LIT_CONE_STRATA * LIT_CONE_STRATA;
    const float degrees = 180.0f / kPi;
    for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
        std::vector<glm::vec3> directions;
        float meanCos = 0.0f;
        for (int k = 0; k < sets; ++k) {
            const glm::vec3 d = stratifiedDiffuseConeDirection(i, k);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
            const float theta = std::acos(std::clamp(d.z, -1.0f, 1.0f)) * degrees;
            if (i == 0) {
                EXPECT_LT(theta, 30.0f) << "set " << k;
            } else {
                EXPECT_GE(theta, 30.0f) << "cone " << i << ", set " << k;
                EXPECT_LT(theta, 90.0f) << "cone " << i << ", set " << k;
                const float azimuth = std::atan2(d.y, d.x) * degrees;
                EXPECT_LE(std::abs(std::remainder(azimuth - 72.0f * float(i - 1), 360.0f)), 36.0f)
                    << "cone " << i << ", set " << k;
            }
            for (const glm::vec3& other : directions)
                EXPECT_GT(glm::length(d - other), 1e-3f) << "cone " << i << ": set " << k << " repeats a cell";
            directions.push_back(d);
            meanCos += d.z / float(sets);
        }
        const float c30 = std::cos(30.0f / degrees);
        const float expected = i == 0 ? (2.0f / 3.0f) * (1.0f - c30 * c30 * c30) / 0.25f : (2.0f / 3.0f) * c30 * c30 * c30 / 0.75f;
        // The cells' medians (midpoint rule in sin²θ over 4 strata) give 0.9347 and 0.5828 (+0.9 %:
        // cosθ = √(1 − sin²θ) is steep near the horizon); bar 1 %. A wrong stratum is off by ≥ 5 %.
        EXPECT_NEAR(meanCos, expected, 0.01f * expected) << "cone " << i;
    }
    // Each 4 × 4 block of texels (anywhere, negative coordinates too) holds every set once.
    for (const glm::ivec2 origin : {glm::ivec2(0, 0), glm::ivec2(5, 9), glm::ivec2(-3, 2)}) {
        std::vector<int> seen(sets, 0);
        for (int y = 0; y < LIT_CONE_STRATA; ++y)
            for (int x = 0; x < LIT_CONE_STRATA; ++x) ++seen[static_cast<std::size_t>(coneSetIndex(origin + glm::ivec2(x, y)))];
        for (int k = 0; k < sets; ++k) EXPECT_EQ(seen[static_cast<std::size_t>(k)], 1) << "set " << k;
    }
}

// coneSamples repeats the march's step geometry: a bounded cone's samples read voxels no wider
// than footprint × height (and never finer than a voxel), an unbounded one's grow as its
// aperture says; the samples are ordered and stop at `upTo`.
TEST(OverlayShapes, ConeSamplesAreBoundedByTheFootprint) {
    const float voxel = 0.025f, side = 3.2f;
    TracedCone cone{{0, 0, 0}, glm::normalize(glm::vec3(1, 0, 1)), kPi / 3.0f, side, 0.15f, false, true};
    cone.footprintPerHeight = 0.33f;
    cone.startHeight = float(LIT_CONE_NORMAL_OFFSET_VOXELS) * voxel;
    cone.heightPerDistance = cone.direction.z;
    const std::vector<ConeSample> bounded = coneSamples(cone, voxel, side, 0.5f, 0.8f);
    ASSERT_GT(bounded.size(), 5u);
    float previous = 0.0f;
    for (const ConeSample& s : bounded) {
        EXPECT_GT(s.tMid, previous);
        EXPECT_LE(s.tMid, 0.8f + s.diameter);
        EXPECT_GE(s.diameter, voxel);
        EXPECT_LE(s.diameter, std::max(voxel, 0.33f * (cone.startHeight + cone.heightPerDistance * s.tMid)) * 1.0001f);
        previous = s.tMid;
    }
    // Near the surface the bounded cone reads single voxels where the 60° cone would read wider ones.
    EXPECT_FLOAT_EQ(bounded.front().diameter, voxel);
    cone.footprintPerHeight = 0.0f;
    const std::vector<ConeSample> free = coneSamples(cone, voxel, side, 0.5f, 0.8f);
    ASSERT_FALSE(free.empty());
    EXPECT_LT(free.size(), bounded.size());  // wider samples, longer steps
    const float widthPerDistance = 2.0f * std::tan(kPi / 6.0f);
    for (const ConeSample& s : free) EXPECT_NEAR(s.diameter, std::max(voxel, widthPerDistance * s.tMid), 1e-5f);
    EXPECT_TRUE(coneSamples(cone, 0.0f, side, 0.5f, 0.8f).empty());
}

// cone.glsl must read its table and constants from shared.h, or the debug view would draw
// cones the shader no longer traces.
TEST(OverlayShapes, ConeShaderUsesTheSharedTable) {
    std::ifstream file(std::string(LIT_SOURCE_DIR) + "/shaders/include/cone.glsl");
    ASSERT_TRUE(file) << "cannot read cone.glsl";
    std::stringstream text;
    text << file.rdbuf();
    for (const char* name : {"vec3[](LIT_DIFFUSE_CONE_DIRECTIONS)", "float[](LIT_DIFFUSE_CONE_WEIGHTS)",
                             "= LIT_CONE_NORMAL_OFFSET_VOXELS;", "= LIT_SPECULAR_LOBE_SHARE;",
                             "= LIT_SPECULAR_APERTURE_MIN;", "= LIT_SPECULAR_APERTURE_MAX;"})
        EXPECT_NE(text.str().find(name), std::string::npos) << "cone.glsl no longer uses " << name;
}

SurfaceSample floorSample() {
    SurfaceSample s;
    s.position = glm::vec3(0.2f, 0.0f, -0.3f);
    s.normal = glm::vec3(0.0f, 1.0f, 0.0f);
    s.roughness = 0.0f;
    s.node = 3;
    s.glPixel = glm::ivec2(37, 81);
    s.voxelSize = 0.05f;
    s.volumeSide = 3.2f;
    return s;
}

TEST(OverlayShapes, TracedDiffuseConesFillTheHemisphere) {
    const SurfaceSample s = floorSample();
    RenderSettings settings;
    settings.gi.mode = GiMode::Fast;  // the fixed six-cone set (the other modes: the stratified sets' tests)
    settings.gi.diffuseConeAperture = 0.9f;
    settings.gi.maxTraceDistance = 0.75f;
    const glm::vec3 camera(1.0f, 2.0f, 2.0f);
    const std::vector<TracedCone> cones = tracedCones(s, camera, settings);
    int diffuse = 0;
    float weights = 0.0f;
    const glm::vec3 apex = s.position + s.normal * (1.7320508f * s.voxelSize);
    std::vector<glm::vec3> sides;
    for (const TracedCone& c : cones) {
        EXPECT_TRUE(near(c.apex, apex)) << "apex √3 voxels above the surface";
        EXPECT_NEAR(c.length, 0.75f * 3.2f, 1e-5f);
        EXPECT_NEAR(glm::length(c.direction), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(c.direction, s.normal), 0.0f) << "every cone leaves the surface";
        if (c.specular) continue;
        ++diffuse;
        weights += c.weight;
        EXPECT_FLOAT_EQ(c.aperture, 0.9f);
        const float fromNormal = angleBetween(c.direction, s.normal);
        if (fromNormal < 1e-3f) continue;
        EXPECT_NEAR(fromNormal, kPi / 3.0f, 1e-4f) << "side cones at 60°";
        sides.push_back(c.direction);
    }
    EXPECT_EQ(diffuse, 6);
    EXPECT_NEAR(weights, 1.0f, 1e-5f);
    ASSERT_EQ(sides.size(), 5u);
    // Neighbouring side cones are 72° apart in azimuth around the normal: each has two
    // neighbours at the chord angle between two 60°-tilted directions 72° apart.
    const float neighbour = std::acos(0.25f + 0.75f * std::cos(2.0f * kPi / 5.0f));
    for (std::size_t i = 0; i < sides.size(); ++i) {
        int neighbours = 0;
        for (std::size_t j = 0; j < sides.size(); ++j)
            if (i != j && std::abs(angleBetween(sides[i], sides[j]) - neighbour) < 1e-3f) ++neighbours;
        EXPECT_EQ(neighbours, 2) << "side cone " << i;
    }
}

TEST(OverlayShapes, MirrorSpecularConeIsTheReflectedViewRay) {
    const SurfaceSample s = floorSample();
    RenderSettings settings;
    const glm::vec3 camera(1.0f, 2.0f, 2.0f);
    const glm::vec3 mirror = glm::reflect(glm::normalize(s.position - camera), s.normal);
    for (int samples : {1, 2, 4, 8}) {
        settings.indirect.specularSamples = samples;
        int specular = 0;
        float weights = 0.0f;
        for (const TracedCone& c : tracedCones(s, camera, settings)) {
            if (!c.specular) continue;
            ++specular;
            weights += c.weight;
            // Roughness 0 is clamped to 0.03 (α ≈ 0.001): the samples stay within a few mrad.
            EXPECT_LT(angleBetween(c.direction, mirror), 0.01f) << samples << " samples";
            EXPECT_FLOAT_EQ(c.aperture, 0.02f) << "the narrowest specular cone";
        }
        EXPECT_EQ(specular, samples);
        EXPECT_NEAR(weights, 1.0f, 1e-5f);
    }
}

TEST(OverlayShapes, RoughSpecularConesSpreadAroundTheMirrorDirection) {
    SurfaceSample s = floorSample();
    s.roughness = 0.6f;
    RenderSettings settings;
    settings.indirect.specularSamples = 8;
    const glm::vec3 camera(1.0f, 2.0f, 2.0f);
    const glm::vec3 mirror = glm::reflect(glm::normalize(s.position - camera), s.normal);
    const float alpha = 0.36f;
    const float aperture = std::min(2.0f * std::atan(2.0f * alpha / std::sqrt(8.0f)), 1.0471976f);
    float largest = 0.0f;
    int specular = 0;
    for (const TracedCone& c : tracedCones(s, camera, settings)) {
        if (!c.specular) continue;
        ++specular;
        EXPECT_NEAR(c.aperture, aperture, 1e-5f);
        EXPECT_GT(glm::dot(c.direction, s.normal), 0.0f);
        largest = std::max(largest, angleBetween(c.direction, mirror));
    }
    EXPECT_GE(specular, 1);
    EXPECT_GT(largest, 0.05f) << "rough samples are not all at the mirror direction";
    // Another pixel rotates the samples (per-pixel Cranley-Patterson rotation).
    SurfaceSample other = s;
    other.glPixel += glm::ivec2(1, 0);
    const std::vector<TracedCone> a = tracedCones(s, camera, settings), b = tracedCones(other, camera, settings);
    bool differs = a.size() != b.size();
    for (std::size_t i = 0; !differs && i < a.size(); ++i) differs = !near(a[i].direction, b[i].direction, 1e-6f);
    EXPECT_TRUE(differs);
}

TEST(OverlayShapes, RoughSpecularOnDiffuseSurfacesReusesTheDiffuseCones) {
    SurfaceSample s = floorSample();
    s.roughness = 1.0f;  // 2 samples: the specular cones clamp to 60°, as wide as the diffuse ones
    RenderSettings settings;
    settings.indirect.specularSamples = 2;
    const glm::vec3 camera(1.0f, 2.0f, 2.0f);
    int diffuse = 0, specular = 0;
    for (const TracedCone& c : tracedCones(s, camera, settings)) {
        diffuse += !c.specular;
        specular += c.specular;
        EXPECT_EQ(c.marched, !c.specular) << "rough specular is blended from the diffuse cones, not marched";
    }
    EXPECT_EQ(diffuse, 6);
    EXPECT_GE(specular, 1);
    // A metal (no diffuse albedo) traces no diffuse cones and marches its specular ones.
    s.diffuse = false;
    diffuse = 0;
    for (const TracedCone& c : tracedCones(s, camera, settings)) {
        diffuse += !c.specular;
        EXPECT_TRUE(c.marched);
    }
    EXPECT_EQ(diffuse, 0);
    // Diffuse cones wider than the widest specular cone (60°): the specular cones are marched.
    s.diffuse = true;
    settings.gi.diffuseConeAperture = 1.2f;
    for (const TracedCone& c : tracedCones(s, camera, settings)) EXPECT_TRUE(c.marched);
}

TEST(OverlayShapes, ConesWithoutGiHaveNoLength) {
    SurfaceSample s = floorSample();
    s.voxelSize = 0.0f;
    s.volumeSide = 0.0f;
    for (const TracedCone& c : tracedCones(s, glm::vec3(0, 2, 2), RenderSettings{})) {
        EXPECT_EQ(c.length, 0.0f);
        EXPECT_TRUE(near(c.apex, s.position));
    }
}

}  // namespace
}  // namespace lit
