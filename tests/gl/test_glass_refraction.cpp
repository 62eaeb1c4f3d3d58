// KHR_materials_volume's refraction (label gl): the Blender scene of
// tools/blender/make_glass_refraction.py (a 0.3 m thick block of clear glass before a wall painted
// with a checker of 0.2 m cells, seen 34° off the block's normal, a black world). The reference
// bends camera rays at the block's faces by Snell's law; the rasterizer reads what lies where
// the view leaves a slab of the block's thickness from the image before the sheets. Through the
// block's front face, the checker Lit shows must be the reference's: per pixel, a small error
// against the error of the same block drawn unbent (η 1), which shows the checker where it lies
// straight behind, about 8 cm off.
#include <cmath>
#include <cstdio>

#include "GlTestSupport.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/Sheets.h"

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::ReferenceScene;

constexpr int kWidth = 320, kHeight = 180;  // the Blender camera's

class GlassRefraction : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        quiet_.setSink(nullptr);
        scene_ =
            loadGltf(sourceDir() / "tests" / "data" / "blender" / "glass_refraction" / "glass_refraction.gltf", quiet_);
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        settings_.gi.enabled = false;
        camera_ = cameraFor(scene_, settings_);
        int block = -1, wall = -1;
        for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
            if (scene_.nodes[i].name == "block") block = static_cast<int>(i);
            if (scene_.nodes[i].name == "wall") wall = static_cast<int>(i);
        }
        ASSERT_TRUE(block >= 0 && wall >= 0);

        // The pixels that see the wall through the block's front face and out of its back face:
        // the reference's camera ray, bent at each face, crosses two faces facing the camera's
        // side (+z in glTF, Blender's −y) and then meets the wall.
        const ReferenceScene rs(scene_, quiet_);
        const std::vector<FirstHit> hits = reference::traceFirstHits(rs, camera_, kWidth, kHeight);
        std::vector<int> region(hits.size(), -1);
        for (std::size_t p = 0; p < hits.size(); ++p) {
            if (hits[p].node != block) continue;
            reference::Ray ray{camera_.position, glm::normalize(hits[p].position - camera_.position), 0.0f, INFINITY};
            reference::SurfaceHit at;
            int crossed = 0;
            bool throughFrontAndBack = true;
            while (rs.intersect(ray, at) && at.node == block && crossed++ < 4) {
                throughFrontAndBack = throughFrontAndBack && std::abs(at.normal.z) > 0.99f;
                const reference::Crossing c = ReferenceScene::cross(at, ray);
                if (c.through == glm::vec3(0.0f)) break;
                ray = c.ray;
            }
            if (at.node == wall && crossed == 2 && throughFrontAndBack) region[p] = 0;
        }
        for (std::size_t p = 0; p < hits.size(); ++p)
            if (hits[p].node == wall) region[p] = 1;
        const std::vector<std::vector<std::size_t>> inner = innerPixels(region, 2, kWidth, kHeight);
        pixels_ = inner[0];
        wallPixels_ = inner[1];
        ASSERT_GT(pixels_.size(), 2000u) << "the wall must be in view through the block";
        reference_ = tracedAtPixelCentres(rs, camera_, kWidth, kHeight, 0, 16).viewRgb(View::Final, settings_);
    }

    // Mean |Lit − reference| over `pixels`, relative to the reference's mean, in luminance.
    double errorAgainstTheReference(const Scene& scene, const std::vector<std::size_t>& pixels) {
        const std::vector<float> lit = render(scene, settings_).rgb;
        const auto luminance = [](const std::vector<float>& rgb, std::size_t p) {
            return 0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2];
        };
        double difference = 0.0, sum = 0.0;
        for (const std::size_t p : pixels) {
            difference += std::abs(luminance(lit, p) - luminance(reference_, p));
            sum += luminance(reference_, p);
        }
        return difference / sum;
    }

    Log quiet_;
    Scene scene_;
    RenderSettings settings_;
    CameraView camera_;
    std::vector<std::size_t> pixels_;      // the wall through the block
    std::vector<std::size_t> wallPixels_;  // the wall in plain view
    std::vector<float> reference_;
};

TEST_F(GlassRefraction, BlendersThickGlassIsARefractingVolume) {
    for (const Material& m : scene_.materials)
        if (m.name == "block") {
            EXPECT_EQ(m.transmission, 1.0f);
            EXPECT_NEAR(m.thickness, 0.3f, 1e-6f);
            EXPECT_EQ(m.attenuationDistance, 0.0f) << "clear: no absorption";
            EXPECT_EQ(refractiveIndexOfVolume(m), 1.5f);
        }
}

// Direct light only (GI off, the reference without bounces).
TEST_F(GlassRefraction, TheCheckerSeenThroughTheBlockIsWhereTheReferenceBendsIt) {
    const double bent = errorAgainstTheReference(scene_, pixels_);
    const double plain = errorAgainstTheReference(scene_, wallPixels_);
    Scene straight = scene_;
    for (Material& m : straight.materials)
        if (m.name == "block") m.ior = 1.0f;
    const double unbent = errorAgainstTheReference(straight, pixels_);
    std::printf(
        "mean |Lit - reference| / mean: through the block (%zu pixels) %.3f bent, %.3f unbent; the wall in "
        "plain view (%zu pixels) %.3f\n",
        pixels_.size(), bent, unbent, wallPixels_.size(), plain);
    EXPECT_LT(bent, 0.25 * unbent) << "the bend must move the checker where the reference shows it";
    EXPECT_LT(bent, 0.12);
}

}  // namespace
}  // namespace lit::test
