// Files from real tools: photometric light units, a lossless save (animations,
// extras, unknown extensions, no invented tangents), camera animations as paths, the sky model
// on the CPU, the exposure settings, depth ranges for a camera inside a scene, and the Khronos
// glTF-Validator on what Lit saves (when node and the validator are installed).
#include "GltfValidator.h"
#include "TempDir.h"

#include "Log.h"
#include "RenderSettings.h"
#include "animation/SceneCameraPaths.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/LightUnits.h"
#include "scene/Sky.h"
#include "QuietLog.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>

namespace lit {
namespace {

using json = nlohmann::json;
using lit::testing::TempDir;
using lit::testing::readText;

std::filesystem::path blenderDir() { return std::filesystem::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender"; }

// A Log that keeps its messages to itself.
using lit::testing::QuietLog;

json readJson(const std::filesystem::path& file) { return json::parse(readText(file)); }

const json& nodeNamed(const json& doc, const std::string& name) {
    for (const json& node : doc.at("nodes"))
        if (node.value("name", "") == name) return node;
    throw std::runtime_error("no node " + name);
}

TEST(LightUnits, BlenderCandelaBecomeWattsPerSteradianAndSaveBackExactly) {
    QuietLog log;
    const Scene scene = loadGltf(blenderDir() / "point.gltf", log);
    ASSERT_EQ(scene.lights.size(), 1u);
    // Blender's 500 W point light: 500/(4π) W/sr = 39.79 W/sr, written as ×683 = 27 175.7 cd.
    const double candela = readJson(blenderDir() / "point.gltf")["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"];
    EXPECT_NEAR(scene.lights[0].intensity, 500.0 / (4.0 * std::numbers::pi), 1e-3);
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, static_cast<float>(candela / kLumensPerWatt));

    TempDir dir;
    saveGltf(scene, dir / "saved.gltf");
    const double saved = readJson(dir / "saved.gltf")["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"];
    EXPECT_EQ(saved, candela) << "an unedited light keeps the file's number";

    Scene edited = scene;
    edited.lights[0].intensity = 10.0f;  // W/sr
    saveGltf(edited, dir / "edited.gltf");
    const double editedCandela = readJson(dir / "edited.gltf")["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"];
    EXPECT_DOUBLE_EQ(editedCandela, 6830.0);
    QuietLog log2;
    EXPECT_FLOAT_EQ(loadGltf(dir / "edited.gltf", log2).lights[0].intensity, 10.0f);
}

TEST(LightUnits, SunIlluminanceInLuxBecomesIrradiance) {
    QuietLog log;
    const Scene scene = loadGltf(blenderDir() / "sun.gltf", log);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_NEAR(scene.lights[0].intensity, 3.0f, 1e-5f);  // Blender's 3 W/m², exported as 2049 lx
}

// Moving one node and saving keeps what Lit does not edit: Blender's camera animation "fly",
// node extras, extensions Lit does not know (on nodes, materials, texture references and the
// file), and writes no TANGENT for meshes that had none.
TEST(LosslessSave, KeepsAnimationsExtrasAndUnknownExtensions) {
    TempDir dir;
    json doc = readJson(blenderDir() / "point.gltf");
    doc["extensionsUsed"].push_back("EXT_lit_test");
    doc["extensions"]["EXT_lit_test"] = {{"file", 1}};
    doc["extras"] = {{"author", "make_scenes.py"}};
    doc["asset"]["copyright"] = "CC0";
    doc["materials"][0]["extras"] = {{"note", "white"}};
    doc["materials"][0]["extensions"]["EXT_lit_test"] = {{"material", true}};
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
        {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2.0, 2.0}}}}}}};
    doc["extensionsUsed"].push_back("KHR_texture_transform");
    // One tiny PNG texture so the texture reference is valid (1×1 white, embedded).
    doc["images"] = json::array({{{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8/5+hHgAHggJ/PchI7wAAAABJRU5ErkJggg=="}}});
    doc["textures"] = json::array({{{"source", 0}}});
    doc["scenes"][0]["extras"] = {{"scene", "kept"}};
    std::filesystem::copy_file(blenderDir() / "point.bin", dir / "point.bin");
    {
        std::ofstream out(dir / "source.gltf");
        out << doc.dump(1);
    }
    QuietLog log;
    Scene scene = loadGltf(dir / "source.gltf", log);
    ASSERT_EQ(scene.cameraAnimationNames, std::vector<std::string>{"fly"});
    for (Node& node : scene.nodes)
        if (node.name == "box") node.translation.x += 0.5f;
    ++scene.geometryRevision;
    saveGltf(scene, dir / "saved.gltf");

    const json saved = readJson(dir / "saved.gltf");
    ASSERT_EQ(saved.at("animations").size(), 1u);
    EXPECT_EQ(saved["animations"][0]["name"], "fly");
    EXPECT_EQ(saved["animations"][0]["channels"].size(), doc["animations"][0]["channels"].size());
    EXPECT_EQ(nodeNamed(saved, "box")["extras"]["litTest"], "kept by a save");
    EXPECT_EQ(saved["extensions"]["EXT_lit_test"]["file"], 1);
    EXPECT_EQ(saved["extras"]["author"], "make_scenes.py");
    EXPECT_EQ(saved["asset"]["copyright"], "CC0");
    EXPECT_EQ(saved["scenes"][0]["extras"]["scene"], "kept");
    const json& material = saved["materials"][0];
    EXPECT_EQ(material["extras"]["note"], "white");
    EXPECT_EQ(material["extensions"]["EXT_lit_test"]["material"], true);
    EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["scale"],
              json({2.0, 2.0}));
    const json used = saved["extensionsUsed"];
    for (const char* e : {"KHR_lights_punctual", "KHR_texture_transform", "EXT_lit_test"})
        EXPECT_NE(std::find(used.begin(), used.end(), e), used.end()) << e;
    for (const json& mesh : saved["meshes"])
        for (const json& primitive : mesh["primitives"])
            EXPECT_FALSE(primitive["attributes"].contains("TANGENT")) << "the source had no tangents";

    // The saved file loads with the same animation, as the same path.
    QuietLog log2;
    const Scene reloaded = loadGltf(dir / "saved.gltf", log2);
    ASSERT_EQ(reloaded.cameraAnimationNames, std::vector<std::string>{"fly"});
    const CameraPath before = loadCameraPath(scene, "fly");
    const CameraPath after = loadCameraPath(reloaded, "fly");
    ASSERT_EQ(before.keys().size(), after.keys().size());
    for (std::size_t k = 0; k < before.keys().size(); ++k) {
        EXPECT_NEAR(glm::length(before.keys()[k].position - after.keys()[k].position), 0.0f, 1e-5f);
        EXPECT_NEAR(before.keys()[k].time, after.keys()[k].time, 1e-6);
    }
}

TEST(LosslessSave, TangentsFromTheFileAreWrittenBack) {
    TempDir dir;
    QuietLog log;
    Scene scene = loadGltf(blenderDir() / "sun.gltf", log);
    ASSERT_FALSE(scene.meshes.empty());
    scene.meshes[0].primitives[0].fileHasTangents = true;  // as if the file had given them
    saveGltf(scene, dir / "saved.gltf");
    const json saved = readJson(dir / "saved.gltf");
    EXPECT_TRUE(saved["meshes"][0]["primitives"][0]["attributes"].contains("TANGENT"));
    EXPECT_FALSE(saved["meshes"][1]["primitives"][0]["attributes"].contains("TANGENT"));
    QuietLog log2;
    EXPECT_TRUE(loadGltf(dir / "saved.gltf", log2).meshes[0].primitives[0].fileHasTangents);
}

TEST(LosslessSave, TheEditorsPathReplacesTheAnimationOfItsNameOnly) {
    TempDir dir;
    QuietLog log;
    const Scene scene = loadGltf(blenderDir() / "point.gltf", log);
    const CameraPath fly = loadCameraPath(scene, "fly");
    std::vector<CameraKey> keys = fly.keys();
    keys.resize(2);
    const CameraPath shorter(keys);
    GltfSaveOptions options;
    options.cameraPath = &shorter;
    options.cameraPathName = "fly";  // the editor edited "fly" and saves it under its own name
    saveGltf(scene, dir / "saved.gltf", options);
    QuietLog log2;
    const Scene reloaded = loadGltf(dir / "saved.gltf", log2);
    ASSERT_EQ(reloaded.cameraAnimationNames, std::vector<std::string>{"fly"});
    EXPECT_EQ(loadCameraPath(reloaded, "fly").keys().size(), 2u);
}

TEST(SceneCameraPaths, BlenderAnimationStartsAtTheCameraAndUnknownNamesAreListed) {
    QuietLog log;
    const Scene scene = loadGltf(blenderDir() / "point.gltf", log);
    const CameraPath fly = loadCameraPath(scene, "fly");
    ASSERT_GE(fly.keys().size(), 4u);
    EXPECT_NEAR(fly.duration(), 3.0, 1e-3);  // frames 1..73 at 24 fps
    const int node = scene.nodeOfCamera(0);
    ASSERT_GE(node, 0);
    // The file's static pose is the animation's first frame (exported at frame 1).
    EXPECT_LT(glm::length(fly.keys().front().position - glm::vec3(scene.nodes[static_cast<std::size_t>(node)].world[3])), 1e-4f);
    try {
        loadCameraPath(scene, "walk");
        FAIL() << "no error for an unknown animation";
    } catch (const CameraPathError& e) {
        EXPECT_NE(std::string(e.what()).find("'fly'"), std::string::npos) << e.what();
    }
}

TEST(ExposureSettings, StopsAreSavedAndOldLinearExposureIsRead) {
    RenderSettings s;
    s.output.exposureEv = -3.5f;
    s.output.autoExposure = true;
    s.sky.mode = SkyMode::Hdr;
    s.sky.hdrPath = "sky.hdr";
    s.sky.zenith = {0.5f, 0.25f, 1.0f};
    EXPECT_EQ(renderSettingsFromJson(toJson(s)), s);
    EXPECT_FLOAT_EQ(renderSettingsFromJson(R"({"exposure": 4.0})").output.exposureEv, 2.0f);
    EXPECT_FLOAT_EQ(renderSettingsFromJson(R"({"exposure": 4.0, "exposureEv": -1})").output.exposureEv, -1.0f);
    EXPECT_FLOAT_EQ(RenderSettings{}.output.exposureScale(), 1.0f);
    EXPECT_THROW(renderSettingsFromJson(R"({"exposure": 0})"), std::runtime_error);
    EXPECT_THROW(renderSettingsFromJson(R"({"skyZenith": [1, 2]})"), std::runtime_error);
    EXPECT_THROW(renderSettingsFromJson(R"({"skyMode": "purple"})"), std::runtime_error);
}

TEST(Sky, GradientAndAutoMode) {
    Scene bare;
    RenderSettings settings;
    const Sky sky = resolveSky(bare, settings, nullptr);
    EXPECT_EQ(sky.mode, SkyMode::Gradient) << "a scene without lights gets a sky";
    EXPECT_TRUE(hasDefaultSun(bare, settings));
    const auto near = [](glm::vec3 a, std::array<float, 3> b) { return glm::length(a - glm::vec3(b[0], b[1], b[2])) < 1e-5f; };
    EXPECT_TRUE(near(skyRadiance(sky, {0, 1, 0}), settings.sky.zenith));
    EXPECT_TRUE(near(skyRadiance(sky, {1, 0, 0}), settings.sky.horizon));
    EXPECT_TRUE(near(skyRadiance(sky, {0, -1, 0}), settings.sky.ground));
    // The default sun stands at its elevation, not straight up.
    const glm::vec3 sun = defaultSunDirection(settings);
    EXPECT_NEAR(std::asin(-sun.y), settings.sky.sunElevation, 1e-5f);

    Scene lit = bare;
    lit.lights.push_back(Light{});
    Node holder;
    holder.light = 0;
    lit.nodes.push_back(holder);
    EXPECT_EQ(resolveSky(lit, settings, nullptr).mode, SkyMode::None) << "a lit scene keeps a black world";
    EXPECT_FALSE(hasDefaultSun(lit, settings));
    // The CPU function the reference path tracer uses on ray misses: the same sky.
    EXPECT_FALSE(makeSkyFunction(lit, settings)) << "no sky for a lit scene in auto mode";
    const auto function = makeSkyFunction(bare, settings);
    ASSERT_TRUE(function);
    EXPECT_EQ(function({0.3f, 0.5f, -0.2f}), skyRadiance(sky, {0.3f, 0.5f, -0.2f}));
    settings.sky.mode = SkyMode::Hdr;
    EXPECT_EQ(resolveSky(lit, settings, nullptr).mode, SkyMode::Gradient) << "no image: the gradient";
    std::string error;
    settings.sky.hdrPath = "no_such_sky.hdr";
    EXPECT_TRUE(makeSkyFunction(lit, settings, &error));
    EXPECT_NE(error.find("no_such_sky.hdr"), std::string::npos);
}

// An equirectangular .hdr read through stb_image: each texel centre's direction returns that
// texel's value (row 0 straight up, u = 0.5 looking down −Z).
TEST(Sky, EquirectangularImageLookup) {
    TempDir dir;
    constexpr int W = 8, H = 4;
    {
        // Uncompressed RGBE: each value a power of two times 1, 1.5 (exact in RGBE).
        std::ofstream out(dir / "sky.hdr", std::ios::binary);
        out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << H << " +X " << W << "\n";
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const unsigned char e = static_cast<unsigned char>(128 + 1 + (y % 2));  // 2 or 4
                const unsigned char rgbe[4] = {static_cast<unsigned char>(16 * (x + 1)), static_cast<unsigned char>(32 * y + 8),
                                               96, e};
                out.write(reinterpret_cast<const char*>(rgbe), 4);
            }
    }
    const SkyImage image = loadSkyImage(dir / "sky.hdr");
    ASSERT_EQ(image.width, W);
    ASSERT_EQ(image.height, H);
    RenderSettings settings;
    settings.sky.mode = SkyMode::Hdr;
    settings.sky.intensity = 2.0f;
    const Sky sky = resolveSky(Scene{}, settings, &image);
    ASSERT_EQ(sky.mode, SkyMode::Hdr);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float phi = ((static_cast<float>(x) + 0.5f) / W - 0.5f) * 2.0f * std::numbers::pi_v<float>;
            const float theta = (static_cast<float>(y) + 0.5f) / H * std::numbers::pi_v<float>;
            const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            const glm::vec3 expected = 2.0f * image.texels[static_cast<std::size_t>(y * W + x)];
            EXPECT_LT(glm::length(skyRadiance(sky, d) - expected), 1e-4f * glm::length(expected)) << x << "," << y;
        }
    EXPECT_THROW(loadSkyImage(dir / "missing.hdr"), SkyLoadError);
}

TEST(DepthRange, InsideAStructureTheNearPlaneIsMillimetres) {
    const Aabb atrium{{-15.0f, 0.0f, -7.0f}, {15.0f, 15.0f, 7.0f}};
    const glm::vec2 inside = depthRangeFor({5.0f, 2.0f, 0.0f}, atrium);
    EXPECT_LT(inside.x, 0.01f);
    EXPECT_GT(inside.y, 20.0f);  // reaches the far corner (≈ 25 m)
    const glm::vec2 outside = depthRangeFor({0.0f, 5.0f, 57.0f}, atrium);
    EXPECT_NEAR(outside.x, 25.0f, 0.5f);  // half the 50 m to the box
    EXPECT_GT(outside.y, 64.0f);
}

// The Khronos glTF-Validator accepts what Lit saves: a Blender file round-tripped with an edit,
// as .gltf and .glb, and the Cornell box. Skipped (with the reason) without node or the
// validator (tools/install-gltf-validator.sh).
TEST(GltfValidator, AcceptsSavedFiles) {
    std::string whyNot;
    const auto validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    TempDir dir;
    QuietLog log;
    Scene point = loadGltf(blenderDir() / "point.gltf", log);
    point.nodes[0].translation.y += 0.25f;
    saveGltf(point, dir / "point.gltf");
    saveGltf(point, dir / "point.glb");
    saveGltf(loadGltf(std::filesystem::path(LIT_SOURCE_DIR) / "assets" / "cornell_box.gltf", log), dir / "cornell.gltf");
    std::string report;
    const int status = lit::testing::runGltfValidator(
        validatorDir, {dir / "point.gltf", dir / "point.glb", dir / "cornell.gltf"}, report, dir / "report.txt");
    std::printf("%s", report.c_str());
    EXPECT_EQ(status, 0) << report;
    EXPECT_NE(report.find("point.glb: 0 errors"), std::string::npos) << report;
}

}  // namespace
}  // namespace lit
