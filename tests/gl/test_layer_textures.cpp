// The layers' textures (label gl): the Blender scene of tools/blender/make_layer_textures.py
// (three dark matte planes under a low sun shining towards the camera: "coat" with a
// checker-painted clear coat, "shine" with a checker-painted Specular that Blender bakes into a
// specular colour texture, "cloth", which this test gives a sheen whose colour texture is the
// checker, since Blender 3.4 writes no sheen from a Principled BSDF, and "ridges", whose clear
// coat has a normal map tilting it towards the sun and away by texel). The reference tracer reads
// each texture per hit; the rasterizer stores the texels in the G-buffer and its lighting reads
// them there. Per plane, the texels with the layer and those without must each match the
// reference; without the textures both halves of a plane look alike, so the comparison can fail.
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <string>

#include "GlTestSupport.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/SheenAlbedo.h"
#include "scene/SpecularMeanAlbedo.h"

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::ReferenceScene;

constexpr int kWidth = 160, kHeight = 90;  // the Blender camera's 16:9

class LayerTextures : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        quiet_.setSink([this](const LogMessage& m) {
            if (m.level == LogLevel::Warning) warnings_ += m.text + "\n";
        });
        scene_ =
            loadGltf(sourceDir() / "tests" / "data" / "blender" / "layer_textures" / "layer_textures.gltf", quiet_);
        Material* cloth = material("cloth");
        const Material* coat = material("coat");
        ASSERT_TRUE(cloth && coat);
        // The sheen Blender does not write: white, roughness 0.5, painted by the coat's checker.
        cloth->sheenColorFactor = glm::vec3(1.0f);
        cloth->sheenRoughness = 0.5f;
        cloth->sheenColorTexture.texture = coat->clearcoatTexture.texture;

        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        camera_ = cameraFor(scene_, settings_);
        std::map<int, std::string> planes;
        for (std::size_t i = 0; i < scene_.nodes.size(); ++i)
            if (scene_.nodes[i].name == "coat" || scene_.nodes[i].name == "shine" || scene_.nodes[i].name == "cloth" ||
                scene_.nodes[i].name == "ridges")
                planes[static_cast<int>(i)] = scene_.nodes[i].name;
        ASSERT_EQ(planes.size(), 4u);

        // Regions from the reference's first hits: which plane, and whether its texel has the layer.
        const ReferenceScene rs(scene_, quiet_);
        const std::vector<FirstHit> hits = reference::traceFirstHits(rs, camera_, kWidth, kHeight);
        std::vector<int> region(hits.size(), -1);
        for (std::size_t p = 0; p < hits.size(); ++p) {
            const auto plane = planes.find(hits[p].node);
            if (plane == planes.end()) continue;
            reference::SurfaceHit at;
            const glm::vec3 toHit = hits[p].position - camera_.position;
            if (!rs.intersect({camera_.position, glm::normalize(toHit), 0.0f, INFINITY}, at) || at.node != plane->first)
                continue;
            // "ridges": "on" where the coat leans towards the sun (glTF's −z, Blender's +y).
            const bool layer = plane->second == "coat"    ? at.clearcoat > 0.5f
                               : plane->second == "shine" ? at.dielectricF0.g > 0.02f
                               : plane->second == "cloth" ? at.sheenColor.g > 0.5f
                                                          : at.clearcoatNormal.z < -0.1f;
            const int base = plane->second == "coat"    ? 0
                             : plane->second == "shine" ? 2
                             : plane->second == "cloth" ? 4
                                                        : 6;
            region[p] = base + (layer ? 0 : 1);
        }
        const std::vector<std::vector<std::size_t>> inner =
            innerPixels(region, static_cast<int>(std::size(kRegions)), kWidth, kHeight);
        for (std::size_t r = 0; r < inner.size(); ++r) pixels_[kRegions[r]] = inner[r];
        for (const char* name : kRegions)
            ASSERT_GT(pixels_[name].size(), 30u) << name << ": the region must be in view";
    }

    Material* material(const std::string& name) {
        for (Material& m : scene_.materials)
            if (m.name == name) return &m;
        return nullptr;
    }

    std::map<std::string, glm::dvec3> perRegion(const std::vector<float>& rgb) const {
        std::map<std::string, glm::dvec3> out;
        for (const auto& [name, list] : pixels_) out[name] = meanRgb(rgb, list);
        return out;
    }

    inline static const char* const kRegions[] = {"coat_on",  "coat_off",  "shine_on",  "shine_off",
                                                  "cloth_on", "cloth_off", "ridges_on", "ridges_off"};
    Log quiet_;
    std::string warnings_;
    Scene scene_;
    RenderSettings settings_;
    CameraView camera_;
    std::map<std::string, std::vector<std::size_t>> pixels_;
};

TEST_F(LayerTextures, BlendersImagesAreReadAsTheTextures) {
    const Material* coat = material("coat");
    const Material* shine = material("shine");
    ASSERT_TRUE(coat && shine);
    EXPECT_EQ(coat->clearcoatFactor, 1.0f);
    EXPECT_GE(coat->clearcoatTexture.texture, 0);
    EXPECT_GE(shine->specularColorTexture.texture, 0) << "Blender bakes the Specular input into this texture";
    const Material* ridges = material("ridges");
    ASSERT_TRUE(ridges);
    EXPECT_GE(ridges->clearcoatNormalTexture.texture, 0);
    EXPECT_EQ(ridges->clearcoatNormalTexture.scale, 1.0f);
    EXPECT_EQ(warnings_.find("is not drawn"), std::string::npos) << warnings_;
}

// Direct light only (GI off, the reference without bounces): each plane's texels with the layer
// and without it, against the reference.
TEST_F(LayerTextures, DirectLightMatchesTheReferencePerTexel) {
    const auto [lit, ref] = directLightPerRegion(scene_, settings_, pixels_, quiet_);
    for (const char* name : kRegions) {
        const glm::dvec3 l = lit.at(name), r = ref.at(name);
        std::printf("%-10s Lit (%.4f %.4f %.4f) reference (%.4f %.4f %.4f) ratio %.3f\n", name, l.r, l.g, l.b, r.r, r.g,
                    r.b, l.g / r.g);
        EXPECT_NEAR(l.g / r.g, 1.0, 0.05) << name;
    }
    // Each texture must change its plane by more than the comparison's tolerance, or this test
    // proves nothing: the coat and the shine add a highlight; the sheen, seen at 28° over a dark
    // base, takes more of the base's light than its own lobe gives back.
    for (const char* plane : {"coat", "shine", "cloth", "ridges"}) {
        const std::string on = std::string(plane) + "_on", off = std::string(plane) + "_off";
        const double contrast = ref.at(on).g / ref.at(off).g;
        EXPECT_GT(std::abs(contrast - 1.0), 0.08) << plane << ": the layer must show";
        EXPECT_NEAR(lit.at(on).g / lit.at(off).g, contrast, 0.03) << plane;
    }
}

// A texture under the extension's default factors (no factor of any material away from its
// default) is drawn all the same: the shine with IOR 1.5 and no tint factor.
TEST_F(LayerTextures, ATextureUnderDefaultFactorsIsDrawn) {
    Scene plain = scene_;
    for (Material& m : plain.materials) {
        m.ior = 1.5f;
        m.specularColorFactor = glm::vec3(1.0f);
        m.clearcoatFactor = 0.0f;
        m.sheenColorFactor = glm::vec3(0.0f);
    }
    const auto [lit, ref] = directLightPerRegion(plain, settings_, pixels_, quiet_);
    for (const char* name : {"shine_on", "shine_off"}) {
        std::printf("%-10s default factors: Lit %.4f reference %.4f ratio %.3f\n", name, lit.at(name).g, ref.at(name).g,
                    lit.at(name).g / ref.at(name).g);
        EXPECT_NEAR(lit.at(name).g / ref.at(name).g, 1.0, 0.05) << name;
    }
    EXPECT_GT(ref.at("shine_on").g, 1.5 * ref.at("shine_off").g) << "the texture must show";
}

// A clear coat over a normal-mapped base keeps the interpolated normal (KHR_materials_clearcoat):
// the ridges' coat loses its own map and their base gets it instead, so the base's (dim, rough)
// lobe follows the ridges and the coat's highlight stays where a flat coat has it.
TEST_F(LayerTextures, CoatOverANormalMappedBaseKeepsTheInterpolatedNormal) {
    Scene mapped = scene_;
    for (Material& m : mapped.materials)
        if (m.name == "ridges") {
            m.normalTexture = m.clearcoatNormalTexture.texture;
            m.clearcoatNormalTexture = {};
        }
    const auto [lit, ref] = directLightPerRegion(mapped, settings_, pixels_, quiet_);
    const std::map<std::string, glm::dvec3> own = directLightPerRegion(scene_, settings_, pixels_, quiet_).lit;
    for (const char* name : {"ridges_on", "ridges_off"}) {
        std::printf("%-10s base mapped: Lit %.4f reference %.4f ratio %.3f (the coat mapped: %.4f)\n", name,
                    lit.at(name).g, ref.at(name).g, lit.at(name).g / ref.at(name).g, own.at(name).g);
        EXPECT_NEAR(lit.at(name).g / ref.at(name).g, 1.0, 0.05) << name;
    }
    // A coat bent by the base's map would tilt its highlight away as its own map does (the
    // flat coat reflects the low sun towards the camera): the comparison above must tell them apart.
    for (const char* name : {"ridges_on", "ridges_off"}) EXPECT_GT(ref.at(name).g, 3.0 * own.at(name).g) << name;
}

// The voxels take each texel's layers into the one albedo they reflect (voxelize.frag.glsl
// reflectedAlbedo): over a dark base, texels with a layer reflect more of the light from
// everywhere than those without (the white sheen's mean albedo outweighs what it takes from the
// base, though seen at 28° it darkens the plane); without the textures the halves are alike.
TEST_F(LayerTextures, VoxelsReflectEachTexelsLayers) {
    RenderSettings s = settings_;
    s.gi.enabled = true;
    s.gi.voxelResolution = 64;
    s.debug.view = View::Voxels;
    s.debug.voxelChannel = VoxelChannel::Albedo;
    const std::map<std::string, glm::dvec3> with = perRegion(render(scene_, s).rgb);
    Scene untextured = scene_;
    for (Material& m : untextured.materials)
        for (const ExtensionTextureSlot& slot : kExtensionTextureSlots) m.*slot.member = {};
    const std::map<std::string, glm::dvec3> without = perRegion(render(untextured, s).rgb);
    // What each texel reflects (docs/MATERIALS.md, the voxels' albedo): the base's diffuse part
    // plus its specular lobe's mean F0·Ā + F90·B̄; a coat passes 1 − F̄c and adds its own lobe's
    // mean; a sheen leaves 1 − Ē_s of the base and adds Ē_s.
    const auto lobe = [](float f0, float f90, float roughness) {
        const glm::vec2 ab = specularMeanAlbedo(roughness);
        return f0 * ab.x + f90 * ab.y;
    };
    const float dark = 0.05f;
    const float matte = dark + lobe(0.04f, 1.0f, 0.9f);
    const float coatMeanFresnel = 0.04f + 0.96f / 21.0f;
    const float sheenMean = sheenMeanAlbedo(0.5f);
    const float ior = (1.45f - 1.0f) / (1.45f + 1.0f);
    const float shineF0 = ior * ior * material("shine")->specularColorFactor.g;
    const std::map<std::string, std::pair<double, double>> expected = {
        // with the layer, without
        {"coat", {matte * (1.0f - coatMeanFresnel) + lobe(0.04f, 1.0f, 0.25f), matte}},
        {"shine", {dark + lobe(shineF0, 1.0f, 0.3f), dark + lobe(0.0f, 1.0f, 0.3f)}},
        {"cloth", {matte * (1.0f - sheenMean) + sheenMean, matte}}};
    for (const char* plane : {"coat", "shine", "cloth"}) {
        const std::string on = std::string(plane) + "_on", off = std::string(plane) + "_off";
        const auto [expectedOn, expectedOff] = expected.at(plane);
        const double contrast = with.at(on).g / with.at(off).g, control = without.at(on).g / without.at(off).g;
        const double sum = with.at(on).g + with.at(off).g;
        std::printf("%-6s voxel albedo with the layer %.4f (expected %.4f), without %.4f (%.4f); no textures: %.3f\n",
                    plane, with.at(on).g, expectedOn, with.at(off).g, expectedOff, control);
        EXPECT_NEAR(control, 1.0, 0.02) << plane;
        // The view filters the voxels across the checker's edges, which moves each region's mean
        // towards the other's (by about 15 % here) but keeps their sum.
        EXPECT_NEAR(sum / (expectedOn + expectedOff), 1.0, 0.03) << plane;
        EXPECT_GT(contrast, 1.0 + 0.5 * (expectedOn / expectedOff - 1.0)) << plane;
    }
}

}  // namespace
}  // namespace lit::test
