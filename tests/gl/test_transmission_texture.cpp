// KHR_materials_transmission's transmissionTexture (label gl): the Blender scene of
// tools/blender/make_transmission_texture.py (a flat pane whose Transmission is a black/white
// checker, 1.2 m over a grey floor under a high sun, a black world, seen from above and in front).
// The reference tracer reads the texture per hit; the rasterizer's sheets and their shadow maps
// must agree with it per region: the floor under the pane's clear and opaque quadrants, and the
// pane's clear and opaque quadrants seen from above. Without the texture the whole pane lets the sun through, so the
// comparison can fail.
#include <cstdio>
#include <iterator>
#include <map>
#include <string>

#include "GlTestSupport.h"
#include "reference/PathTracer.h"
#include "reference/PunctualLights.h"
#include "reference/ReferenceScene.h"

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::ReferenceScene;

constexpr int kWidth = 160, kHeight = 90;  // the Blender camera's 16:9

class TransmissionTexture : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        quiet_.setSink(nullptr);
        scene_ = loadGltf(
            sourceDir() / "tests" / "data" / "blender" / "transmission_texture" / "transmission_texture.gltf", quiet_);
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        camera_ = cameraFor(scene_, settings_);
        int pane = -1, floor = -1;
        for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
            if (scene_.nodes[i].name == "pane") pane = static_cast<int>(i);
            if (scene_.nodes[i].name == "floor") floor = static_cast<int>(i);
        }
        ASSERT_TRUE(pane >= 0 && floor >= 0);

        // Regions from the reference's first hits and the texel its shadow rays cross.
        const ReferenceScene rs(scene_, quiet_);
        const std::vector<FirstHit> hits = reference::traceFirstHits(rs, camera_, kWidth, kHeight);
        const gpu::GpuLight& sun = rs.punctualLights().at(0);
        std::vector<int> region(hits.size(), -1);
        for (std::size_t p = 0; p < hits.size(); ++p) {
            if (hits[p].node == pane) {
                // The texel this pixel sees: a shadow-free probe of the material at the hit.
                reference::SurfaceHit at;
                const glm::vec3 origin = camera_.position;
                const glm::vec3 toHit = hits[p].position - origin;
                if (rs.intersect({origin, glm::normalize(toHit), 0.0f, INFINITY}, at) && at.node == pane)
                    region[p] = at.transmission > 0.5f ? 2 : 3;
            } else if (hits[p].node == floor) {
                const reference::PunctualSample ls = reference::samplePunctualLight(sun, hits[p].position);
                reference::SurfaceHit blocker;
                if (rs.intersect({hits[p].position + hits[p].normal * 1e-3f, ls.l, 0.0f, INFINITY}, blocker) &&
                    blocker.node == pane)
                    region[p] = blocker.transmission > 0.5f ? 0 : 1;
            }
        }
        const std::vector<std::vector<std::size_t>> inner =
            innerPixels(region, static_cast<int>(std::size(kRegions)), kWidth, kHeight);
        for (std::size_t r = 0; r < inner.size(); ++r) pixels_[kRegions[r]] = inner[r];
        for (const char* name : kRegions)
            ASSERT_GT(pixels_[name].size(), 30u) << name << ": the region must be in view";
    }

    std::map<std::string, glm::dvec3> perRegion(const std::vector<float>& rgb) const {
        std::map<std::string, glm::dvec3> out;
        for (const auto& [name, list] : pixels_) out[name] = meanRgb(rgb, list);
        return out;
    }

    inline static const char* const kRegions[] = {"floor_under_clear", "floor_under_opaque", "pane_clear",
                                                  "pane_opaque"};
    Log quiet_;
    Scene scene_;
    RenderSettings settings_;
    CameraView camera_;
    std::map<std::string, std::vector<std::size_t>> pixels_;
};

TEST_F(TransmissionTexture, BlendersImageIsReadAsTheTexture) {
    const Material* pane = nullptr;
    for (const Material& m : scene_.materials)
        if (m.name == "pane") pane = &m;
    ASSERT_NE(pane, nullptr);
    EXPECT_EQ(pane->transmission, 1.0f);
    EXPECT_GE(pane->transmissionTexture.texture, 0);
    EXPECT_EQ(drawnTexCoord(pane->transmissionTexture), 0);
}

// Direct light only (GI off, the reference without bounces): the texture picks, per texel, a clear
// sheet or an opaque white surface, in the view and in the shadow maps alike.
TEST_F(TransmissionTexture, DirectLightMatchesTheReferencePerTexel) {
    RenderSettings s = settings_;
    s.gi.enabled = false;
    const auto [lit, ref] = directLightPerRegion(scene_, s, pixels_, quiet_);
    for (const char* name : kRegions) {
        const glm::dvec3 l = lit.at(name), r = ref.at(name);
        std::printf("%-18s Lit (%.4f %.4f %.4f) reference (%.4f %.4f %.4f) ratio %.3f\n", name, l.r, l.g, l.b, r.r, r.g,
                    r.b, l.g / r.g);
    }
    // The floor: the sun through a clear texel against none through an opaque one. The opaque
    // quadrant's floor is black in both (a black world, no bounce), so its bound is absolute.
    EXPECT_NEAR(lit.at("floor_under_clear").g / ref.at("floor_under_clear").g, 1.0, 0.05);
    EXPECT_LT(lit.at("floor_under_opaque").g, 0.02 * lit.at("floor_under_clear").g);
    EXPECT_LT(ref.at("floor_under_opaque").g, 0.02 * ref.at("floor_under_clear").g);
    // The pane from above: its opaque texels are a sunlit white surface, its clear ones pass the
    // floor beneath (lit or shadowed by the checker) dimmed by the sheet.
    EXPECT_NEAR(lit.at("pane_opaque").g / ref.at("pane_opaque").g, 1.0, 0.05);
    EXPECT_NEAR(lit.at("pane_clear").g / ref.at("pane_clear").g, 1.0, 0.10);
    EXPECT_GT(lit.at("pane_opaque").g, 2.0 * lit.at("pane_clear").g);

    Scene untextured = scene_;
    for (Material& m : untextured.materials) m.transmissionTexture = {};
    const std::map<std::string, glm::dvec3> without = perRegion(render(untextured, s).rgb);
    EXPECT_GT(without.at("floor_under_opaque").g, 0.8 * lit.at("floor_under_clear").g)
        << "without the texture the whole pane lets the sun through, or this test proves nothing";
}

}  // namespace
}  // namespace lit::test
