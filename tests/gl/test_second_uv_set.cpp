// TEXCOORD_1 in pictures (label gl): the Blender scene of tools/blender/make_second_uv_set.py (two
// planes seen from above, each with two UV maps; the left plane's red/blue checker reads its
// second map through a UV Map node, which Blender exported as TEXCOORD_1 and texCoord 1) against
// its twin, where each plane keeps only the map its texture reads. The rasterizer, the
// voxelization and the reference tracer must each draw the first like the second, and unlike the
// first read with TEXCOORD_0; a row across the left plane crosses six checker edges on the second
// map and one on the first.
#include <algorithm>
#include <cstdio>

#include "CheckerPictures.h"
#include "GlTestSupport.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::PathTracer;
using reference::ReferenceScene;
using reference::ReferenceSettings;

constexpr int kWidth = 256, kHeight = 128;  // the Blender camera's aspect (2:1)

class SecondUvSetPictures : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        const auto dir = sourceDir() / "tests" / "data" / "blender" / "second_uv_set";
        Log quiet;
        quiet.setSink(nullptr);
        secondSet_ = loadGltf(dir / "second_uv_set.gltf", quiet);
        baked_ = loadGltf(dir / "second_uv_set_baked.gltf", quiet);
        firstSet_ = secondSet_;
        for (Material& m : firstSet_.materials) m.textureTexCoord.fill(0);
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        // Which pixels see the left plane, from the reference's first hits.
        int left = -1;
        for (std::size_t n = 0; n < baked_.nodes.size(); ++n)
            if (baked_.nodes[n].name == "left") left = static_cast<int>(n);
        ASSERT_GE(left, 0);
        const ReferenceScene rs(baked_, quiet);
        hits_ = reference::traceFirstHits(rs, cameraFor(baked_, settings_), kWidth, kHeight);
        for (const FirstHit& h : hits_) onLeft_.push_back(h.node == left);
        ASSERT_GT(std::count(onLeft_.begin(), onLeft_.end(), true), kWidth * kHeight / 6);
    }

    std::vector<int> rasterClasses(const Scene& scene, const RenderSettings& settings) {
        return checkerClasses(render(scene, settings).rgb);
    }

    // Checker colour changes along the pixel row through the left plane's centre.
    int edgesAlongLeftRow(const std::vector<int>& cls) const {
        const glm::ivec2 p =
            projectToPixel(cameraFor(baked_, settings_), glm::vec3(-1.1f, 0.0f, -0.25f), kWidth, kHeight);
        return checkerEdgesAlongRow(cls, onLeft_, p.y, kWidth);
    }

    Scene secondSet_, baked_, firstSet_;
    RenderSettings settings_;
    std::vector<FirstHit> hits_;
    std::vector<bool> onLeft_;
};

TEST_F(SecondUvSetPictures, RasterizerSamplesTheSetTheMaterialNames) {
    const std::vector<int> baked = rasterClasses(baked_, settings_);
    const std::vector<int> second = rasterClasses(secondSet_, settings_);
    const std::vector<int> first = rasterClasses(firstSet_, settings_);
    const double same = checkerAgreement(second, baked, onLeft_), without = checkerAgreement(first, baked, onLeft_);
    std::printf(
        "rasterizer: TEXCOORD_1 vs baked %.4f, TEXCOORD_0 vs baked %.4f; left row edges %d (baked %d, "
        "TEXCOORD_0 %d)\n",
        same, without, edgesAlongLeftRow(second), edgesAlongLeftRow(baked), edgesAlongLeftRow(first));
    EXPECT_GT(same, 0.99);  // only pixels within float rounding of a checker edge may differ
    EXPECT_LT(without, 0.8) << "the UV set must change the picture, or this test proves nothing";
    EXPECT_EQ(edgesAlongLeftRow(second), 6);
    EXPECT_EQ(edgesAlongLeftRow(baked), 6);
    EXPECT_EQ(edgesAlongLeftRow(first), 1);
}

// The voxelized albedo (the Voxels view, 64³) reads the second set too.
TEST_F(SecondUvSetPictures, VoxelizationSamplesTheSetTheMaterialNames) {
    RenderSettings s = settings_;
    s.gi.enabled = true;
    s.gi.voxelResolution = 64;
    s.debug.view = View::Voxels;
    s.debug.voxelChannel = VoxelChannel::Albedo;
    const std::vector<int> baked = rasterClasses(baked_, s);
    const std::vector<int> second = rasterClasses(secondSet_, s);
    const std::vector<int> first = rasterClasses(firstSet_, s);
    const double same = checkerAgreement(second, baked, onLeft_), without = checkerAgreement(first, baked, onLeft_);
    std::printf("voxels: TEXCOORD_1 vs baked %.4f, TEXCOORD_0 vs baked %.4f\n", same, without);
    EXPECT_GT(same, 0.95);  // voxels along a checker edge average both colours either way
    EXPECT_LT(without, 0.8);
}

TEST_F(SecondUvSetPictures, ReferenceSamplesTheSetTheMaterialNames) {
    Log quiet;
    quiet.setSink(nullptr);
    ReferenceSettings referenceSettings;
    referenceSettings.bounces = 0;
    const CameraView camera = cameraFor(baked_, settings_);
    const auto traced = [&](const Scene& scene) {
        const ReferenceScene rs(scene, quiet);
        PathTracer tracer(rs, camera, kWidth, kHeight, referenceSettings);
        tracer.addSamples(4);
        return checkerClasses(tracer.image().viewRgb(View::Final, settings_));
    };
    const std::vector<int> baked = traced(baked_);
    const std::vector<int> second = traced(secondSet_);
    const std::vector<int> first = traced(firstSet_);
    const double same = checkerAgreement(second, baked, onLeft_), without = checkerAgreement(first, baked, onLeft_);
    std::printf("reference: TEXCOORD_1 vs baked %.4f, TEXCOORD_0 vs baked %.4f; left row edges %d\n", same, without,
                edgesAlongLeftRow(second));
    EXPECT_GT(same, 0.95);  // pixel-area samples blend the colours at edges, which count as disagreement
    EXPECT_LT(without, 0.8);
    EXPECT_EQ(edgesAlongLeftRow(second), 6);
}

}  // namespace
}  // namespace lit::test
