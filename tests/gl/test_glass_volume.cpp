// KHR_materials_volume (label gl): the Blender scene of tools/blender/make_glass_volume.py (two
// slabs of the same amber glass, 5 cm and 20 cm thick, 0.8 m over a grey floor under a sun 60°
// high, a black world, seen from above). The reference absorbs along the exact straight path
// inside each slab; the rasterizer's sheets and their shadow maps absorb over the material's
// thickness. Per region they must agree: the floor in each slab's shadow, and each slab seen from
// above over its own shadow (the light crossed the slab twice). Without the medium the floor under
// the thick slab is more than twice as bright in green, so the comparison can fail.
#include <cmath>
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

class GlassVolume : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        quiet_.setSink(nullptr);
        scene_ = loadGltf(sourceDir() / "tests" / "data" / "blender" / "glass_volume" / "glass_volume.gltf", quiet_);
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        camera_ = cameraFor(scene_, settings_);
        int floor = -1;
        for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
            if (scene_.nodes[i].name == "thin_block") thin_ = static_cast<int>(i);
            if (scene_.nodes[i].name == "thick_block") thick_ = static_cast<int>(i);
            if (scene_.nodes[i].name == "floor") floor = static_cast<int>(i);
        }
        ASSERT_TRUE(thin_ >= 0 && thick_ >= 0 && floor >= 0);

        // Regions from the reference's rays: what shadows a floor point, and for a pixel that sees
        // a slab, the floor point behind it (the camera ray followed through the sheets). Only rays
        // that cross a slab through its top and bottom count: those crossing a side face are the
        // slab's edges, where its thickness is not the path's (docs/MATERIALS.md, "Volume").
        const ReferenceScene rs(scene_, quiet_);
        const gpu::GpuLight& sun = rs.punctualLights().at(0);
        // glTF's up is +y.
        const auto topAndBottom = [](const reference::SurfaceHit& hit) { return std::abs(hit.normal.y) > 0.99f; };
        const auto shadowedBy = [&](const glm::vec3& position, const glm::vec3& normal) {
            const reference::PunctualSample ls = reference::samplePunctualLight(sun, position);
            reference::Ray ray{position + normal * 1e-3f, ls.l, 0.0f, INFINITY};
            reference::SurfaceHit entry, exit;
            if (!rs.intersect(ray, entry)) return -1;
            ray.tnear = ReferenceScene::pastHit(entry.t);
            if (!rs.intersect(ray, exit) || exit.node != entry.node) return -2;
            if (!topAndBottom(entry) || !topAndBottom(exit)) return entry.node == thick_ ? -3 : -2;
            return entry.node;
        };
        const std::vector<FirstHit> hits = reference::traceFirstHits(rs, camera_, kWidth, kHeight);
        std::vector<int> region(hits.size(), -1);
        for (std::size_t p = 0; p < hits.size(); ++p) {
            if (hits[p].node == floor) {
                const int by = shadowedBy(hits[p].position, hits[p].normal);
                region[p] = by == -1 ? 0 : by == thin_ ? 1 : by == thick_ ? 2 : by == -3 ? 5 : -1;
            } else if (hits[p].node == thin_ || hits[p].node == thick_) {
                const glm::vec3 origin = camera_.position;
                reference::Ray ray{origin, glm::normalize(hits[p].position - origin), 0.0f, INFINITY};
                reference::SurfaceHit at;
                int crossed = 0;
                bool flat = true;
                while (rs.intersect(ray, at) && at.node != floor && crossed++ < 8) {
                    flat = flat && topAndBottom(at);
                    ray.tnear = ReferenceScene::pastHit(at.t);
                }
                // Both faces of this slab and nothing else on the way; its own shadow behind.
                if (at.node == floor && crossed == 2 && flat && shadowedBy(at.position, at.normal) == hits[p].node)
                    region[p] = hits[p].node == thin_ ? 3 : 4;
            }
        }
        const std::vector<std::vector<std::size_t>> inner =
            innerPixels(region, static_cast<int>(std::size(kRegions)) + 1, kWidth, kHeight);
        for (std::size_t r = 0; r < std::size(kRegions); ++r) pixels_[kRegions[r]] = inner[r];
        for (const char* name : kRegions)
            ASSERT_GT(pixels_[name].size(), 30u) << name << ": the region must be in view";
        // The floor whose sun crossed a side face of the thick slab: a strip a few pixels wide,
        // whole rather than eroded, reported only.
        for (std::size_t p = 0; p < region.size(); ++p)
            if (region[p] == 5) sidePixels_.push_back(p);
    }

    std::map<std::string, glm::dvec3> directLight(const Scene& scene) {
        RenderSettings s = settings_;
        s.gi.enabled = false;
        std::map<std::string, glm::dvec3> out;
        const std::vector<float> rgb = render(scene, s).rgb;
        for (const auto& [name, list] : pixels_) out[name] = meanRgb(rgb, list);
        return out;
    }

    static Material& material(Scene& scene, const char* name) {
        for (Material& m : scene.materials)
            if (m.name == name) return m;
        ADD_FAILURE() << "no material " << name;
        return scene.materials.front();
    }

    inline static const char* const kRegions[] = {"floor_in_sun", "floor_under_thin", "floor_under_thick",
                                                  "thin_over_its_shadow", "thick_over_its_shadow"};
    Log quiet_;
    Scene scene_;
    RenderSettings settings_;
    CameraView camera_;
    int thin_ = -1, thick_ = -1;
    std::map<std::string, std::vector<std::size_t>> pixels_;
    std::vector<std::size_t> sidePixels_;
};

TEST_F(GlassVolume, BlendersVolumeAbsorptionIsRead) {
    const Material& thick = material(scene_, "thick_block");
    EXPECT_EQ(thick.transmission, 1.0f);
    EXPECT_NEAR(thick.thickness, 0.2f, 1e-6f);
    EXPECT_NEAR(thick.attenuationDistance, 0.2f, 1e-6f);
    EXPECT_NEAR(thick.attenuationColor.g, 0.5f, 1e-6f);
    EXPECT_NEAR(material(scene_, "thin_block").thickness, 0.05f, 1e-6f);
}

// Direct light only (GI off, the reference without bounces), per channel: the medium's colour
// depends on the path's length, so green and blue fall off at different rates.
TEST_F(GlassVolume, DirectLightMatchesTheReferencePerRegion) {
    RenderSettings s = settings_;
    s.gi.enabled = false;
    const auto [lit, ref] = directLightPerRegion(scene_, s, pixels_, quiet_);
    for (const char* name : kRegions) {
        const glm::dvec3 l = lit.at(name), r = ref.at(name);
        std::printf("%-22s Lit (%.4f %.4f %.4f) reference (%.4f %.4f %.4f) ratio %.3f %.3f %.3f\n", name, l.r, l.g, l.b,
                    r.r, r.g, r.b, l.r / r.r, l.g / r.g, l.b / r.b);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[c] / r[c], 1.0, 0.05) << name << " channel " << c;
    }
    // Where the sun crosses the thick slab's side face, the rasterizer's slab of the thickness is
    // longer than the path (docs/MATERIALS.md, "Volume", Limits): reported, not held to a bar.
    if (!sidePixels_.empty()) {
        const std::vector<float> litRgb = render(scene_, s).rgb;
        const std::vector<float> refRgb =
            tracedAtPixelCentres(ReferenceScene(scene_, quiet_), camera_, kWidth, kHeight, 0, 16)
                .viewRgb(View::Final, s);
        const glm::dvec3 l = meanRgb(litRgb, sidePixels_), r = meanRgb(refRgb, sidePixels_);
        std::printf("floor under the thick slab's side (%zu pixels) Lit/reference %.3f %.3f %.3f\n", sidePixels_.size(),
                    l.r / r.r, l.g / r.g, l.b / r.b);
    }
    // The thick slab leaves less than the thin one, bluer light least of all.
    EXPECT_LT(ref.at("floor_under_thick").b, 0.6 * ref.at("floor_under_thin").b);

    Scene clear = scene_;
    for (Material& m : clear.materials) m.attenuationDistance = 0.0f;
    const std::map<std::string, glm::dvec3> without = directLight(clear);
    EXPECT_GT(without.at("floor_under_thick").g, 1.8 * lit.at("floor_under_thick").g)
        << "without the medium the slab's shadow is clear glass's, or this test proves nothing";
}

// The thickness texture's green channel scales the thickness (a closed form on the rasterizer's
// side: the reference traces the slab's own geometry). A one-texel image of green 0.5 on the
// 20 cm slab draws as the same slab with a thickness of 0.1 m, and its red channel is not read.
TEST_F(GlassVolume, ThicknessTextureScalesTheThicknessByItsGreenChannel) {
    Scene textured = scene_;
    Image image;
    image.name = "half_thickness";
    image.width = image.height = 1;
    image.rgba = {255, 128, 0, 255};
    textured.images.push_back(image);
    Texture texture;
    texture.image = static_cast<int>(textured.images.size()) - 1;
    textured.textures.push_back(texture);
    material(textured, "thick_block").thicknessTexture.texture = static_cast<int>(textured.textures.size()) - 1;
    Scene halved = scene_;
    material(halved, "thick_block").thickness = 0.2f * 128.0f / 255.0f;

    const std::map<std::string, glm::dvec3> full = directLight(scene_), byTexture = directLight(textured),
                                            byFactor = directLight(halved);
    for (const char* name : {"floor_under_thick", "thick_over_its_shadow"}) {
        std::printf("%-22s full %.4f texture %.4f factor %.4f (blue)\n", name, full.at(name).b, byTexture.at(name).b,
                    byFactor.at(name).b);
        EXPECT_NEAR(byTexture.at(name).b / byFactor.at(name).b, 1.0, 0.01) << name;
        EXPECT_GT(byTexture.at(name).b, 1.3 * full.at(name).b) << name << ": the texture must thin the slab";
    }
}

}  // namespace
}  // namespace lit::test
