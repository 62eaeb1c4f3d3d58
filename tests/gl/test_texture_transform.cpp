// KHR_texture_transform in pictures (label gl): the Blender scene of
// tools/blender/make_texture_transform.py (two planes seen from above, a red/blue checker placed
// by Mapping nodes that Blender exported as KHR_texture_transform on the base colour and
// emissive textures) against its twin, where the script baked the Mapping into the mesh UVs.
// The rasterizer, the voxelization (the Voxels view of the albedo) and the reference tracer must
// each draw the first like the second, and unlike the first with its transforms removed; a row
// across the left plane (scale 3, offset 0.25) crosses six checker edges.
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

class TextureTransformPictures : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        const auto dir = sourceDir() / "tests" / "data" / "blender" / "texture_transform";
        Log quiet;
        quiet.setSink(nullptr);
        mapped_ = loadGltf(dir / "texture_transform.gltf", quiet);
        baked_ = loadGltf(dir / "texture_transform_baked.gltf", quiet);
        untransformed_ = mapped_;
        for (Material& m : untransformed_.materials) m.textureTransforms = {};
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        // Which pixels see a plane, and which the left one, from the reference's first hits.
        const ReferenceScene rs(mapped_, quiet);
        hits_ = reference::traceFirstHits(rs, cameraFor(mapped_, settings_), kWidth, kHeight);
        for (const FirstHit& h : hits_) onPlane_.push_back(h.node >= 0);
        ASSERT_GT(std::count(onPlane_.begin(), onPlane_.end(), true), kWidth * kHeight / 3);
        for (std::size_t n = 0; n < mapped_.nodes.size(); ++n)
            if (mapped_.nodes[n].name == "left") left_ = static_cast<int>(n);
        ASSERT_GE(left_, 0);
        for (const FirstHit& h : hits_) onLeft_.push_back(h.node == left_);
    }

    std::vector<int> rasterClasses(const Scene& scene, const RenderSettings& settings) {
        return checkerClasses(render(scene, settings).rgb);
    }

    // Checker colour changes along the pixel row through world point (x, 0, z) on the left plane.
    int edgesAlongLeftRow(const std::vector<int>& cls) const {
        const glm::ivec2 p = projectToPixel(cameraFor(mapped_, settings_), glm::vec3(-1.1f, 0.0f, -0.25f), kWidth, kHeight);
        return checkerEdgesAlongRow(cls, onLeft_, p.y, kWidth);
    }

    Scene mapped_, baked_, untransformed_;
    RenderSettings settings_;
    std::vector<FirstHit> hits_;
    std::vector<bool> onPlane_, onLeft_;
    int left_ = -1;
};

TEST_F(TextureTransformPictures, RasterizerDrawsTheMappingAsBlenderBakedIt) {
    const std::vector<int> mapped = rasterClasses(mapped_, settings_);
    const std::vector<int> baked = rasterClasses(baked_, settings_);
    const std::vector<int> untransformed = rasterClasses(untransformed_, settings_);
    const double same = checkerAgreement(mapped, baked, onPlane_),
                 without = checkerAgreement(untransformed, baked, onPlane_);
    std::printf("rasterizer: transformed vs baked %.4f, untransformed vs baked %.4f; left row edges %d (baked %d, "
                "untransformed %d)\n",
                same, without, edgesAlongLeftRow(mapped), edgesAlongLeftRow(baked), edgesAlongLeftRow(untransformed));
    // Only pixels whose centre falls within float rounding of a checker edge may differ.
    EXPECT_GT(same, 0.99);
    EXPECT_LT(without, 0.8) << "the transform must change the picture, or this test proves nothing";
    EXPECT_EQ(edgesAlongLeftRow(mapped), 6);  // u' from 0.25 to 3.25: an edge at every 0.5
    EXPECT_EQ(edgesAlongLeftRow(baked), 6);
    EXPECT_EQ(edgesAlongLeftRow(untransformed), 1);
}

// The voxelized albedo (the Voxels view, 64³ voxels of 6.6 cm against checks of 33 cm and more)
// follows the transform too.
TEST_F(TextureTransformPictures, VoxelizationAppliesTheTransform) {
    RenderSettings s = settings_;
    s.gi.enabled = true;
    s.gi.voxelResolution = 64;
    s.debug.view = View::Voxels;
    s.debug.voxelChannel = VoxelChannel::Albedo;
    const std::vector<int> mapped = rasterClasses(mapped_, s);
    const std::vector<int> baked = rasterClasses(baked_, s);
    const std::vector<int> untransformed = rasterClasses(untransformed_, s);
    const double same = checkerAgreement(mapped, baked, onPlane_),
                 without = checkerAgreement(untransformed, baked, onPlane_);
    std::printf("voxels: transformed vs baked %.4f, untransformed vs baked %.4f\n", same, without);
    EXPECT_GT(same, 0.95);  // voxels along a checker edge average both colours either way
    EXPECT_LT(without, 0.8);
}

// The reference tracer's picture of the transformed scene agrees with the rasterizer's (its
// pixel-area samples blend the colours at checker edges, which count as disagreement).
TEST_F(TextureTransformPictures, ReferenceAgrees) {
    Log quiet;
    quiet.setSink(nullptr);
    ReferenceSettings referenceSettings;
    referenceSettings.bounces = 0;
    const CameraView camera = cameraFor(mapped_, settings_);
    const auto traced = [&](const Scene& scene) {
        const ReferenceScene rs(scene, quiet);
        PathTracer tracer(rs, camera, kWidth, kHeight, referenceSettings);
        tracer.addSamples(4);
        return checkerClasses(tracer.image().viewRgb(View::Final, settings_));
    };
    const std::vector<int> reference = traced(mapped_);
    const std::vector<int> referenceUntransformed = traced(untransformed_);
    const std::vector<int> raster = rasterClasses(mapped_, settings_);
    const double same = checkerAgreement(reference, raster, onPlane_);
    const double without = checkerAgreement(referenceUntransformed, raster, onPlane_);
    std::printf("reference vs rasterizer: transformed %.4f, untransformed reference %.4f; left row edges %d\n", same,
                without, edgesAlongLeftRow(reference));
    EXPECT_GT(same, 0.95);
    EXPECT_LT(without, 0.8);
    EXPECT_EQ(edgesAlongLeftRow(reference), 6);
}

}  // namespace
}  // namespace lit::test
