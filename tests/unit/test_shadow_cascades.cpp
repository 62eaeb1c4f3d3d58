// The camera's shadow cascades (renderer/passes/ShadowCascades.cpp): split distances, each map
// covering its frustum slice and every caster towards the light, and maps that stay put while the
// camera moves less than a snap step.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "passes/ShadowCascades.h"

namespace lit {
namespace {

const Aabb kCity{glm::vec3(-320.0f, 0.0f, -320.0f), glm::vec3(320.0f, 60.0f, 320.0f)};
const glm::vec3 kSun = glm::normalize(glm::vec3(0.4f, -0.5f, -0.77f));

CameraView streetCamera(const glm::vec3& position, float yaw, float pitch) {
    FlyCamera fly;
    fly.position = position;
    fly.yaw = yaw;
    fly.pitch = pitch;
    fly.yfov = 0.9f;
    return fly.view(16.0f / 9.0f, 0.1f, 1000.0f);
}

glm::vec3 toNdc(const glm::mat4& viewProjection, const glm::vec3& p) {
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// The corners of the slice [a, b] of the camera's frustum, in world space.
std::vector<glm::vec3> sliceCorners(const CameraView& camera, float a, float b) {
    const float tanX = 1.0f / camera.projection[0][0], tanY = 1.0f / camera.projection[1][1];
    const glm::mat4 world = glm::inverse(camera.view);
    std::vector<glm::vec3> out;
    for (const float d : {a, b})
        for (int i = 0; i < 4; ++i)
            out.push_back(glm::vec3(
                world * glm::vec4((i & 1 ? 1.0f : -1.0f) * tanX * d, (i & 2 ? 1.0f : -1.0f) * tanY * d, -d, 1.0f)));
    return out;
}

TEST(ShadowCascades, SplitsBlendLogarithmicAndUniformSpacing) {
    const std::vector<float> uniform = cascadeSplits(1.0f, 101.0f, 4, 0.0f);
    ASSERT_EQ(uniform.size(), 4u);
    EXPECT_NEAR(uniform[0], 26.0f, 1e-4f);
    EXPECT_NEAR(uniform[2], 76.0f, 1e-4f);
    const std::vector<float> logarithmic = cascadeSplits(1.0f, 10000.0f, 4, 1.0f);
    EXPECT_NEAR(logarithmic[0], 10.0f, 1e-3f);
    EXPECT_NEAR(logarithmic[1], 100.0f, 1e-2f);
    EXPECT_EQ(logarithmic[3], 10000.0f);
    const std::vector<float> practical = cascadeSplits(0.1f, 640.0f, 4, 0.75f);
    for (std::size_t i = 1; i < practical.size(); ++i) EXPECT_GT(practical[i], practical[i - 1]);
    EXPECT_EQ(practical.back(), 640.0f);
    EXPECT_TRUE(cascadeSplits(1.0f, 1.0f, 4, 0.5f).empty());
    EXPECT_TRUE(cascadeSplits(1.0f, 10.0f, 0, 0.5f).empty());
}

TEST(ShadowCascades, EachMapHoldsItsSliceAndEveryCasterTowardsTheLight) {
    for (const float yaw : {0.0f, 0.7f, 2.0f, 4.0f})
        for (const float pitch : {-0.3f, 0.0f, 0.5f}) {
            const CameraView camera = streetCamera({12.0f, 1.7f, 40.0f}, yaw, pitch);
            const std::vector<ShadowCascade> cascades = fitShadowCascades(kSun, kCity, camera, 4, 0.0f, 0.75f, 1024);
            ASSERT_EQ(cascades.size(), 4u);
            float sliceNear = 0.0f;
            for (const ShadowCascade& cascade : cascades) {
                for (const glm::vec3& p : sliceCorners(camera, sliceNear, cascade.farDistance)) {
                    const glm::vec3 ndc = toNdc(cascade.viewProjection, p);
                    EXPECT_LE(std::abs(ndc.x), 1.0f)
                        << "yaw " << yaw << " pitch " << pitch << " slice to " << cascade.farDistance;
                    EXPECT_LE(std::abs(ndc.y), 1.0f);
                    // Inside the scene, a slice point lies between the near and far planes.
                    if (glm::all(glm::greaterThanEqual(p, kCity.min)) && glm::all(glm::lessThanEqual(p, kCity.max))) {
                        EXPECT_LE(ndc.z, 1.0f);
                    }
                }
                for (int i = 0; i < 8; ++i) {
                    const glm::vec3 corner{(i & 1) ? kCity.max.x : kCity.min.x, (i & 2) ? kCity.max.y : kCity.min.y,
                                           (i & 4) ? kCity.max.z : kCity.min.z};
                    EXPECT_GE(toNdc(cascade.viewProjection, corner).z, -1.0f) << "a caster before the near plane";
                }
                EXPECT_GT(cascade.worldTexel, 0.0f);
                sliceNear = cascade.farDistance;
            }
            // Finer near the camera: each map's texels are larger than the one inside it.
            for (std::size_t c = 1; c < cascades.size(); ++c)
                EXPECT_GT(cascades[c].worldTexel, cascades[c - 1].worldTexel);
        }
}

TEST(ShadowCascades, MapsStayPutUnderSmallMovesAndMoveByWholeTexels) {
    const CameraView camera = streetCamera({12.0f, 1.7f, 40.0f}, 0.7f, 0.0f);
    const std::vector<ShadowCascade> before = fitShadowCascades(kSun, kCity, camera, 4, 0.0f, 0.75f, 1024);
    // A move far below the first map's snap step (1/16 of its side) keeps every map.
    const CameraView nudged = streetCamera({12.0f + 0.1f * before[0].worldTexel, 1.7f, 40.0f}, 0.7f, 0.0f);
    const std::vector<ShadowCascade> same = fitShadowCascades(kSun, kCity, nudged, 4, 0.0f, 0.75f, 1024);
    for (std::size_t c = 0; c < before.size(); ++c) EXPECT_EQ(same[c], before[c]) << "cascade " << c;

    // A move of 20 m redraws the first map, by a whole number of texels in x and y, at the same size.
    const CameraView moved = streetCamera({32.0f, 1.7f, 40.0f}, 0.7f, 0.0f);
    const std::vector<ShadowCascade> after = fitShadowCascades(kSun, kCity, moved, 4, 0.0f, 0.75f, 1024);
    EXPECT_NE(after[0].snappedCentre, before[0].snappedCentre);
    EXPECT_FLOAT_EQ(after[0].worldTexel, before[0].worldTexel);
    const glm::vec3 p(5.0f, 3.0f, 7.0f);
    const glm::vec2 texels =
        (glm::vec2(toNdc(after[0].viewProjection, p)) - glm::vec2(toNdc(before[0].viewProjection, p))) * 512.0f;
    EXPECT_NEAR(texels.x, std::round(texels.x), 0.02f);
    EXPECT_NEAR(texels.y, std::round(texels.y), 0.02f);
    EXPECT_GT(std::abs(texels.x) + std::abs(texels.y), 1.0f);
}

TEST(ShadowCascades, SlicesReachTheScenesDiagonalOrTheChosenDistance) {
    const CameraView camera = streetCamera({12.0f, 1.7f, 40.0f}, 0.7f, 0.0f);
    const float diagonal = glm::length(kCity.size());
    const std::vector<ShadowCascade> all = fitShadowCascades(kSun, kCity, camera, 3, 0.0f, 0.75f, 1024);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_FLOAT_EQ(all.back().farDistance, diagonal);
    EXPECT_FLOAT_EQ(fitShadowCascades(kSun, kCity, camera, 3, 1e5f, 0.75f, 1024).back().farDistance, diagonal);
    const std::vector<ShadowCascade> near = fitShadowCascades(kSun, kCity, camera, 2, 50.0f, 0.75f, 1024);
    ASSERT_EQ(near.size(), 2u);
    EXPECT_FLOAT_EQ(near.back().farDistance, 50.0f);
    // The camera's near and far planes play no part.
    CameraView otherPlanes = streetCamera({12.0f, 1.7f, 40.0f}, 0.7f, 0.0f);
    FlyCamera fly;
    fly.position = otherPlanes.position;
    fly.yaw = 0.7f;
    fly.yfov = 0.9f;
    otherPlanes = fly.view(16.0f / 9.0f, 0.01f, 600.0f);
    const std::vector<ShadowCascade> same = fitShadowCascades(kSun, kCity, otherPlanes, 3, 0.0f, 0.75f, 1024);
    for (std::size_t c = 0; c < all.size(); ++c) EXPECT_EQ(same[c], all[c]) << "cascade " << c;
    EXPECT_TRUE(fitShadowCascades(kSun, kCity, camera, 0, 0.0f, 0.75f, 1024).empty());
    EXPECT_TRUE(fitShadowCascades(kSun, Aabb{}, camera, 4, 0.0f, 0.75f, 1024).empty());
}

}  // namespace
}  // namespace lit
