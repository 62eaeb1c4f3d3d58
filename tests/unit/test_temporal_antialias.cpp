// TemporalAntialiasPass's jitter: the sequence of offsets and the projection it moves (no GL).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "RenderSettings.h"
#include "passes/TemporalAntialiasPass.h"

namespace lit {
namespace {

TEST(TemporalAntialias, TheCycleStartsAtThePixelCentreAndCoversThePixel) {
    constexpr int kFrames = 8;
    EXPECT_EQ(TemporalAntialiasPass::sampleOffset(0, kFrames), glm::vec2(0.0f));
    EXPECT_EQ(TemporalAntialiasPass::sampleOffset(kFrames, kFrames), glm::vec2(0.0f));  // the cycle repeats
    EXPECT_EQ(TemporalAntialiasPass::sampleOffset(3, kFrames),
              TemporalAntialiasPass::sampleOffset(3 + kFrames, kFrames));
    // Halton (2, 3) minus ½: index 1 is (½, ⅓) − ½, index 2 (¼, ⅔) − ½.
    EXPECT_NEAR(TemporalAntialiasPass::sampleOffset(1, kFrames).x, 0.0f, 1e-6f);
    EXPECT_NEAR(TemporalAntialiasPass::sampleOffset(1, kFrames).y, 1.0f / 3.0f - 0.5f, 1e-6f);
    EXPECT_NEAR(TemporalAntialiasPass::sampleOffset(2, kFrames).x, -0.25f, 1e-6f);
    EXPECT_NEAR(TemporalAntialiasPass::sampleOffset(2, kFrames).y, 2.0f / 3.0f - 0.5f, 1e-6f);
    // Every offset lies in the pixel, the cycle's are all different, and each quadrant of the
    // pixel holds at least one of the eight.
    int quadrants[4] = {0, 0, 0, 0};
    for (std::uint32_t i = 0; i < kFrames; ++i) {
        const glm::vec2 o = TemporalAntialiasPass::sampleOffset(i, kFrames);
        EXPECT_GE(o.x, -0.5f);
        EXPECT_LT(o.x, 0.5f);
        EXPECT_GE(o.y, -0.5f);
        EXPECT_LT(o.y, 0.5f);
        for (std::uint32_t j = 0; j < i; ++j) EXPECT_NE(o, TemporalAntialiasPass::sampleOffset(j, kFrames));
        ++quadrants[(o.x < 0.0f ? 0 : 1) + (o.y < 0.0f ? 0 : 2)];
    }
    for (int q : quadrants) EXPECT_GE(q, 1);
    // One frame: no offset at all.
    EXPECT_EQ(TemporalAntialiasPass::sampleOffset(5, 1), glm::vec2(0.0f));
}

TEST(TemporalAntialias, TheJitterMovesEveryPointByTheOffsetInPixels) {
    constexpr int kWidth = 320, kHeight = 180;
    const glm::vec2 offset(0.25f, -0.375f);
    const glm::mat4 view = glm::lookAt(glm::vec3(1.0f, 2.0f, 5.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projections[2] = {glm::perspective(0.8f, 16.0f / 9.0f, 0.1f, 100.0f),
                                      glm::ortho(-4.0f, 4.0f, -2.25f, 2.25f, 0.1f, 100.0f)};
    for (const glm::mat4& projection : projections) {
        const glm::mat4 moved = TemporalAntialiasPass::jittered(projection, offset, kWidth, kHeight);
        for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(0.7f, -0.3f, 1.2f), glm::vec3(-1.5f, 0.8f, -2.0f)}) {
            const glm::vec4 a = projection * view * glm::vec4(p, 1.0f), b = moved * view * glm::vec4(p, 1.0f);
            const glm::vec2 pixelsA = (glm::vec2(a) / a.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight);
            const glm::vec2 pixelsB = (glm::vec2(b) / b.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight);
            EXPECT_NEAR(pixelsB.x - pixelsA.x, offset.x, 1e-3f);
            EXPECT_NEAR(pixelsB.y - pixelsA.y, offset.y, 1e-3f);
            EXPECT_NEAR(b.z / b.w, a.z / a.w, 1e-6f);  // depth unchanged
        }
    }
}

TEST(TemporalAntialias, OnlyLitViewsAreAntialiased) {
    RenderSettings s;
    EXPECT_TRUE(TemporalAntialiasPass::applies(s));  // on by default
    s.debug.view = View::IndirectDiffuse;
    EXPECT_TRUE(TemporalAntialiasPass::applies(s));
    for (View data : {View::Albedo, View::Normal, View::ShadowMap, View::Voxels, View::VoxelSlice}) {
        s.debug.view = data;
        EXPECT_FALSE(TemporalAntialiasPass::applies(s));
    }
    s.debug.view = View::Final;
    s.output.antialiasingFrames = 1;
    EXPECT_FALSE(TemporalAntialiasPass::applies(s));
    s.output.antialiasingFrames = 8;
    s.output.antialiasing = false;
    EXPECT_FALSE(TemporalAntialiasPass::applies(s));
}

}  // namespace
}  // namespace lit
