// KHR_materials_ior, _specular, _clearcoat and _sheen drawn (label gl): the Blender scene of
// tools/blender/make_material_layers.py (seven spheres under a sun and a point light: a plain red
// dielectric, the same with a smooth and a rough clear coat, a white dielectric with Blender's
// Specular 1 (F0 0.08), one with IOR 2.2 and a specular tint, a clear-coated gold metal, a dark
// blue cloth with a Velvet BSDF that the exporter writes as a sheen), with
// the rasterizer's light per sphere against the reference path tracer's, which evaluates the
// BRDF of docs/MATERIALS.md exactly. Each sphere's mean over its inner pixels (those whose four
// neighbours see the same sphere) is compared, term by term.
#include "GlTestSupport.h"

#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::PathTracer;
using reference::ReferenceScene;
using reference::ReferenceSettings;

constexpr int kWidth = 192, kHeight = 108;  // the Blender camera's 16:9

class MaterialLayers : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        quiet_.setSink(nullptr);
        scene_ = loadGltf(sourceDir() / "tests" / "data" / "blender" / "material_layers" / "material_layers.gltf",
                          quiet_);
        settings_ = smallSettings();
        settings_.output.width = kWidth;
        settings_.output.height = kHeight;
        camera_ = cameraFor(scene_, settings_);
        const ReferenceScene rs(scene_, quiet_);
        const std::vector<FirstHit> hits = reference::traceFirstHits(rs, camera_, kWidth, kHeight);
        // Inner pixels of each sphere: the pixel and its four neighbours hit the same node.
        for (int y = 1; y + 1 < kHeight; ++y)
            for (int x = 1; x + 1 < kWidth; ++x) {
                const int node = hits[static_cast<std::size_t>(y * kWidth + x)].node;
                if (node < 0) continue;
                bool inner = true;
                for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                    inner = inner && hits[static_cast<std::size_t>((y + dy) * kWidth + x + dx)].node == node;
                const std::string& name = scene_.nodes[static_cast<std::size_t>(node)].name;
                if (inner && kSpheres.count(name)) pixels_[name].push_back(static_cast<std::size_t>(y * kWidth + x));
            }
        for (const auto& [name, unused] : kSpheres)
            ASSERT_GT(pixels_[name].size(), 100u) << name << ": the sphere must be in view";
    }

    // Mean luminance of `rgb` (bottom-up rows, 3 floats a pixel) over each sphere's inner pixels.
    std::map<std::string, double> perSphere(const std::vector<float>& rgb) const {
        std::map<std::string, double> out;
        for (const auto& [name, list] : pixels_) {
            double sum = 0.0;
            for (const std::size_t p : list) sum += luminance({rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]});
            out[name] = sum / static_cast<double>(list.size());
        }
        return out;
    }
    // The reference's terms of `scene` from the fixture's camera, sampled at pixel centres as the
    // rasterizer samples.
    reference::ReferenceImage traced(const Scene& scene, int bounces, int samples) {
        return tracedAtPixelCentres(ReferenceScene(scene, quiet_), camera_, kWidth, kHeight, bounces, samples);
    }
    std::vector<float> rasterImage(const Scene& scene, RenderSettings s, View view, int frames = 1) {
        s.debug.view = view;
        return render(scene, s, frames).rgb;
    }
    std::map<std::string, double> raster(const Scene& scene, RenderSettings s, View view, int frames = 1) {
        return perSphere(rasterImage(scene, s, view, frames));
    }

    // Sphere name → what it shows.
    inline static const std::map<std::string, const char*> kSpheres = {
        {"plain", "no extension"},           {"clearcoat", "clear coat 1, roughness 0.05"},
        {"clearcoat_rough", "coat 0.6, roughness 0.35"}, {"specular", "specular colour 2 (F0 0.08)"},
        {"ior", "IOR 2.2, specular colour 0.284"},        {"coated_metal", "gold with a clear coat"},
        {"sheen", "blue cloth, sheen 0.8, roughness 0.5"}};

    Log quiet_;
    Scene scene_;
    RenderSettings settings_;
    CameraView camera_;
    std::map<std::string, std::vector<std::size_t>> pixels_;
};

TEST_F(MaterialLayers, TheExtensionsAreRead) {
    const auto material = [&](const char* name) -> const Material& {
        for (const Material& m : scene_.materials)
            if (m.name == name) return m;
        ADD_FAILURE() << name;
        return scene_.materials.at(0);
    };
    EXPECT_FLOAT_EQ(material("clearcoat").clearcoatFactor, 1.0f);
    EXPECT_NEAR(material("clearcoat_rough").clearcoatRoughness, 0.35f, 1e-6f);
    EXPECT_NEAR(material("specular").specularColorFactor.g, 2.0f, 1e-6f);
    EXPECT_NEAR(material("ior").ior, 2.2f, 1e-6f);
    EXPECT_EQ(material("plain").clearcoatFactor, 0.0f);
    EXPECT_NEAR(material("sheen").sheenColorFactor.g, 0.8f, 1e-6f);
    EXPECT_NEAR(material("sheen").sheenRoughness, 0.5f, 1e-6f);
}

// Direct light only (GI off, the reference without bounces): the rasterizer's BRDF is exact here,
// so each sphere's diffuse and specular terms must match the reference's within what shadow maps
// and pixel-centre sampling leave.
TEST_F(MaterialLayers, DirectLightMatchesTheReferencePerSphere) {
    RenderSettings s = settings_;
    s.gi.enabled = false;
    const reference::ReferenceImage image = traced(scene_, 0, 64);
    for (const View view : {View::DirectDiffuse, View::DirectSpecular}) {
        const std::map<std::string, double> lit = raster(scene_, s, view);
        const std::map<std::string, double> ref = perSphere(image.viewRgb(view, s));
        for (const auto& [name, what] : kSpheres) {
            std::printf("%-16s %-15s Lit %.5f reference %.5f ratio %.4f  (%s)\n", name.c_str(),
                        std::string(toString(view)).c_str(), lit.at(name), ref.at(name), lit.at(name) / ref.at(name),
                        what);
            if (ref.at(name) > 1e-6)
                EXPECT_NEAR(lit.at(name) / ref.at(name), 1.0, 0.05) << name << " " << toString(view);
            else
                EXPECT_LT(lit.at(name), 1e-6) << name << " " << toString(view) << ": a metal has no diffuse term";
        }
    }

    // The layers must show, or the agreement above proves nothing: against the same scene without
    // the extensions, the coats dim the diffuse term by what they reflect and the rough coat adds
    // its lobe (the smooth coat's highlights of the two point-like lights fall between pixel
    // centres), and F0 0.08 reflects more than 0.04.
    Scene bare = scene_;
    for (Material& m : bare.materials) {
        m.ior = 1.5f;
        m.specularFactor = 1.0f;
        m.specularColorFactor = glm::vec3(1.0f);
        m.clearcoatFactor = 0.0f;
        m.sheenColorFactor = glm::vec3(0.0f);
    }
    const std::map<std::string, double> diffuse = raster(scene_, s, View::DirectDiffuse);
    const std::map<std::string, double> bareDiffuse = raster(bare, s, View::DirectDiffuse);
    const std::map<std::string, double> specular = raster(scene_, s, View::DirectSpecular);
    const std::map<std::string, double> bareSpecular = raster(bare, s, View::DirectSpecular);
    for (const auto& [name, what] : kSpheres)
        std::printf("%-16s without the extensions: diffuse x%.4f, specular x%.4f\n", name.c_str(),
                    diffuse.at(name) / bareDiffuse.at(name), specular.at(name) / bareSpecular.at(name));
    EXPECT_LT(diffuse.at("clearcoat"), 0.97 * bareDiffuse.at("clearcoat"));
    EXPECT_LT(diffuse.at("clearcoat_rough"), 0.98 * bareDiffuse.at("clearcoat_rough"));
    EXPECT_GT(specular.at("clearcoat_rough"), 1.2 * bareSpecular.at("clearcoat_rough"));
    EXPECT_GT(specular.at("specular"), 1.5 * bareSpecular.at("specular")) << "F0 0.08 against 0.04";
    EXPECT_EQ(diffuse.at("plain"), bareDiffuse.at("plain"));
    EXPECT_EQ(specular.at("plain"), bareSpecular.at("plain"));
}

// KHR_materials_ior alone (Blender pairs its IOR with a specular colour that keeps F0 at 0.04):
// IOR 2.2 gives F0 = (1.2/3.2)² = 0.14, in the rasterizer as in the reference.
TEST_F(MaterialLayers, IorAloneSetsTheDielectricsReflectance) {
    Scene scene = scene_;
    for (Material& m : scene.materials)
        if (m.name == "ior") m.specularColorFactor = glm::vec3(1.0f);
    Scene bare = scene;
    for (Material& m : bare.materials)
        if (m.name == "ior") m.ior = 1.5f;
    RenderSettings s = settings_;
    s.gi.enabled = false;
    const double lit = raster(scene, s, View::DirectSpecular).at("ior");
    const double ref = perSphere(traced(scene, 0, 16).viewRgb(View::DirectSpecular, s)).at("ior");
    const double without = raster(bare, s, View::DirectSpecular).at("ior");
    std::printf("IOR 2.2: direct specular Lit %.5f reference %.5f (ratio %.4f); at IOR 1.5 %.5f\n", lit, ref,
                lit / ref, without);
    EXPECT_NEAR(lit / ref, 1.0, 0.05);
    EXPECT_GT(lit, 2.0 * without);
}

// KHR_materials_sheen beyond the exported `sheen` sphere (Blender 3.4 writes a sheen only from a
// Velvet BSDF): a white sheen of roughness 0.6 on the plain red sphere, and a warm sheen of
// roughness 0.3 alone on the `ior` sphere made black. The sheen counts as diffuse light; direct
// and full light per sphere against the reference.
TEST_F(MaterialLayers, SheenMatchesTheReference) {
    Scene scene = scene_;
    for (Material& m : scene.materials) {
        if (m.name == "plain") {
            m.sheenColorFactor = glm::vec3(0.8f);
            m.sheenRoughness = 0.6f;
        } else if (m.name == "ior") {
            m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
            m.sheenColorFactor = glm::vec3(1.0f, 0.5f, 0.25f);
            m.sheenRoughness = 0.3f;
        }
    }
    RenderSettings direct = settings_;
    direct.gi.enabled = false;
    RenderSettings full = settings_;
    full.gi.enabled = true;
    full.gi.voxelResolution = 128;
    const std::map<std::string, double> litDirect = raster(scene, direct, View::DirectDiffuse);
    const std::map<std::string, double> refDirect = perSphere(traced(scene, 0, 64).viewRgb(View::DirectDiffuse, direct));
    const std::map<std::string, double> litFull = raster(scene, full, View::Final);
    const std::map<std::string, double> refFull =
        perSphere(traced(scene, reference::kAllBounces, 256).viewRgb(View::Final, full));
    const std::map<std::string, double> bare = raster(scene_, direct, View::DirectDiffuse);
    for (const char* name : {"plain", "ior"}) {
        std::printf("%-6s sheen: direct diffuse Lit %.5f reference %.5f (ratio %.4f; without the sheen %.5f), final "
                    "Lit %.5f reference %.5f (ratio %.4f)\n",
                    name, litDirect.at(name), refDirect.at(name), litDirect.at(name) / refDirect.at(name),
                    bare.at(name), litFull.at(name), refFull.at(name), litFull.at(name) / refFull.at(name));
        EXPECT_NEAR(litDirect.at(name) / refDirect.at(name), 1.0, 0.05) << name;
        EXPECT_NEAR(litFull.at(name) / refFull.at(name), 1.0, 0.10) << name;
    }
    EXPECT_GT(litDirect.at("ior"), 0.02) << "a sheen on black must show";
    // The voxels reflect the sheen too: the black sphere's voxelized albedo is its sheen's mean.
    RenderSettings voxels = full;
    voxels.debug.view = View::Voxels;
    voxels.debug.voxelChannel = VoxelChannel::Albedo;
    const double sheenVoxels = raster(scene, voxels, View::Voxels).at("ior");
    std::printf("black sphere with a sheen: voxel albedo (display value) %.4f\n", sheenVoxels);
    EXPECT_GT(sheenVoxels, 0.03) << "the voxels of a black sphere with a sheen must not be black (0 without)";
    EXPECT_GT(std::abs(litDirect.at("plain") / bare.at("plain") - 1.0), 0.03) << "the sheen must change the sphere";
}

// Every term at the editor's defaults (GI on, every bounce, converged) against the reference with
// every bounce: each sphere's final image, and its indirect specular term, where the clear coat
// is drawn by the approximation of docs/MATERIALS.md (the smoother lobe, weighted by both).
TEST_F(MaterialLayers, FullLightMatchesTheReferencePerSphere) {
    RenderSettings s = settings_;
    s.gi.enabled = true;
    s.gi.voxelResolution = 128;
    const reference::ReferenceImage image = traced(scene_, reference::kAllBounces, 256);
    std::map<View, std::map<std::string, double>> ratios;
    for (const View view : {View::Final, View::IndirectDiffuse, View::IndirectSpecular}) {
        const std::map<std::string, double> lit = raster(scene_, s, view);
        const std::map<std::string, double> ref = perSphere(image.viewRgb(view, s));
        for (const auto& [name, what] : kSpheres) {
            ratios[view][name] = lit.at(name) / ref.at(name);
            std::printf("%-16s %-17s Lit %.5f reference %.5f ratio %.4f  (%s)\n", name.c_str(),
                        std::string(toString(view)).c_str(), lit.at(name), ref.at(name), ratios[view][name], what);
        }
    }
    // Measured at 128³: final 0.94–0.98 per sphere; L_IS 0.82–0.92, the coated spheres' within
    // 0.98–1.10 of the plain sphere's (drawing the coats' indirect light with the base's weight
    // alone puts the smooth coat at about half).
    for (const auto& [name, what] : kSpheres) {
        EXPECT_NEAR(ratios[View::Final][name], 1.0, 0.10) << name;
        const double specular = ratios[View::IndirectSpecular][name] / ratios[View::IndirectSpecular]["plain"];
        EXPECT_GT(specular, 0.85) << name << ": indirect specular against the plain sphere's";
        EXPECT_LT(specular, 1.2) << name << ": indirect specular against the plain sphere's";
    }
}

}  // namespace
}  // namespace lit::test
