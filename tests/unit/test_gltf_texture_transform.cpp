// KHR_texture_transform (label cpu): read from the Blender scene made by
// tools/blender/make_texture_transform.py, its matrix against the UVs Blender baked itself, kept
// on save (validator clean when installed), and malformed fields reported.
#include "GltfValidator.h"
#include "Log.h"
#include "TempDir.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/Scene.h"
#include "scene/TextureTransform.h"
#include "QuietLog.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

namespace lit {
namespace {

namespace fs = std::filesystem;
using lit::testing::readText;
using lit::testing::TempDir;

using lit::testing::QuietLog;

constexpr std::size_t kBaseColor = 0, kEmissive = 3;

fs::path sceneDir() { return fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender" / "texture_transform"; }

const Material& materialNamed(const Scene& scene, const std::string& name) {
    for (const Material& m : scene.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return scene.materials.at(0);
}

// The specification's matrix, T · R · S: a 90° turn takes (1, 0) to (0, −1) (its rotation
// matrix is [[cos, sin], [−sin, cos]]); the offset comes last.
TEST(TextureTransform, MatrixIsTranslationRotationScale) {
    TextureTransform t;
    t.present = true;
    t.scale = {2.0, 3.0};
    t.rotation = std::numbers::pi / 2.0;
    t.offset = {0.5, 0.25};
    const glm::vec2 uv = applyUvTransform(uvTransformRows(t), glm::vec2(1.0f, 0.0f));
    EXPECT_NEAR(uv.x, 0.5f, 1e-6f);   // (2, 0) turned → (0, −2), + offset
    EXPECT_NEAR(uv.y, -1.75f, 1e-6f);
    const glm::vec2 up = applyUvTransform(uvTransformRows(t), glm::vec2(0.0f, 1.0f));
    EXPECT_NEAR(up.x, 3.5f, 1e-6f);  // (0, 3) turned → (3, 0), + offset
    EXPECT_NEAR(up.y, 0.25f, 1e-6f);
    const glm::vec2 same = applyUvTransform(uvTransformRows(TextureTransform{}), glm::vec2(0.3f, 0.7f));
    EXPECT_EQ(same, glm::vec2(0.3f, 0.7f));
}

// Blender's exporter turned each Mapping node into KHR_texture_transform on both references the
// image feeds; the loader reads them.
TEST(TextureTransform, ReadFromBlendersMappingNode) {
    QuietLog log;
    const Scene scene = loadGltf(sceneDir() / "texture_transform.gltf", log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u) << "KHR_texture_transform is read, not warned about";
    const Material& left = materialNamed(scene, "checker_left");
    for (const std::size_t slot : {kBaseColor, kEmissive}) {
        const TextureTransform& t = left.textureTransforms[slot];
        EXPECT_TRUE(t.present);
        EXPECT_EQ(t.scale, glm::dvec2(3.0, 2.0));
        EXPECT_EQ(t.offset, glm::dvec2(0.25, -1.0));  // Blender's V runs the other way: 1 − 2·1
        EXPECT_EQ(t.rotation, 0.0);
        EXPECT_EQ(t.texCoord, -1);
        EXPECT_TRUE(left.textureExtensions[slot].empty()) << "the transform is not also kept as text";
    }
    EXPECT_NEAR(materialNamed(scene, "checker_right").textureTransforms[kBaseColor].rotation,
                30.0 * std::numbers::pi / 180.0, 1e-7);
    EXPECT_FALSE(left.textureTransforms[1].present) << "no metallic-roughness texture, no transform";
}

// Each vertex's UV through the file's transform lands on the UV Blender baked into the mesh of
// the twin scene (the script applies its Mapping node to the UVs): Lit's matrix is the one
// Blender's exporter means, rotation and V flip included.
TEST(TextureTransform, MatrixAgreesWithBlendersBakedUvs) {
    QuietLog log;
    const Scene mapped = loadGltf(sceneDir() / "texture_transform.gltf", log);
    const Scene baked = loadGltf(sceneDir() / "texture_transform_baked.gltf", log);
    ASSERT_EQ(mapped.meshes.size(), baked.meshes.size());
    int compared = 0;
    for (std::size_t m = 0; m < mapped.meshes.size(); ++m) {
        const Primitive& a = mapped.meshes[m].primitives.at(0);
        const Primitive& b = baked.meshes[m].primitives.at(0);
        ASSERT_EQ(a.vertices.size(), b.vertices.size());
        const Material& material = mapped.materials.at(static_cast<std::size_t>(a.material));
        const auto rows = uvTransformRows(material.textureTransforms[kBaseColor]);
        for (std::size_t v = 0; v < a.vertices.size(); ++v) {
            ASSERT_EQ(a.vertices[v].position, b.vertices[v].position);
            const glm::vec2 uv = applyUvTransform(rows, a.vertices[v].uv);
            EXPECT_NEAR(uv.x, b.vertices[v].uv.x, 1e-5f) << material.name << " vertex " << v;
            EXPECT_NEAR(uv.y, b.vertices[v].uv.y, 1e-5f) << material.name << " vertex " << v;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 8);  // two quads
}

// A save writes the transforms back (the file's exact numbers) and declares the extension; an
// edited transform is saved as edited. The validator accepts both files.
TEST(TextureTransform, KeptOnSave) {
    TempDir dir;
    QuietLog log;
    Scene scene = loadGltf(sceneDir() / "texture_transform.gltf", log);
    saveGltf(scene, dir / "saved.gltf");
    const Scene again = loadGltf(dir / "saved.gltf", log);
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        EXPECT_EQ(again.materials[m].textureTransforms, scene.materials[m].textureTransforms) << m;
    const nlohmann::json saved = nlohmann::json::parse(readText(dir / "saved.gltf"));
    EXPECT_NE(saved["extensionsUsed"].dump().find("KHR_texture_transform"), std::string::npos);
    const nlohmann::json source = nlohmann::json::parse(readText(sceneDir() / "texture_transform.gltf"));
    for (std::size_t m = 0; m < 2; ++m)
        for (const char* pointer : {"/pbrMetallicRoughness/baseColorTexture/extensions", "/emissiveTexture/extensions"})
            EXPECT_EQ(saved["materials"][m][nlohmann::json::json_pointer(pointer)],
                      source["materials"][m][nlohmann::json::json_pointer(pointer)])
                << m << pointer;

    // An edit: the right plane's base colour tiled 4 × 1 without rotation or offset; a transform
    // given to a reference that had none (metallic-roughness has no texture: not written).
    Material& right = scene.materials.at(1);
    right.textureTransforms[kBaseColor] = TextureTransform{{0.0, 0.0}, 0.0, {4.0, 1.0}, -1, true};
    right.textureTransforms[1] = TextureTransform{{0.5, 0.0}, 0.0, {1.0, 1.0}, -1, true};
    saveGltf(scene, dir / "edited.gltf");
    const nlohmann::json edited = nlohmann::json::parse(readText(dir / "edited.gltf"));
    EXPECT_EQ(edited["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"],
              nlohmann::json::parse(R"({"KHR_texture_transform": {"scale": [4.0, 1.0]}})"));
    EXPECT_FALSE(edited["materials"][1]["pbrMetallicRoughness"].contains("metallicRoughnessTexture"));
    EXPECT_EQ(loadGltf(dir / "edited.gltf", log).materials.at(1).textureTransforms[kBaseColor],
              right.textureTransforms[kBaseColor]);

    std::string whyNot;
    const fs::path validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    std::string report;
    const int status = lit::testing::runGltfValidator(
        validatorDir, {sceneDir() / "texture_transform.gltf", dir / "saved.gltf", dir / "edited.gltf"}, report,
        dir / "report.txt");
    std::printf("%s", report.c_str());
    EXPECT_NE(report.find("texture_transform.gltf: 0 errors"), std::string::npos) << report;
    EXPECT_EQ(status, 0) << report;
}

// Fields of the wrong shape are warned about and ignored (the rest of the transform is used);
// a texCoord override names a set the mesh lacks, which is drawn with TEXCOORD_0 and warned about.
TEST(TextureTransform, MalformedFieldsAreReported) {
    TempDir dir;
    nlohmann::json doc = nlohmann::json::parse(readText(sceneDir() / "texture_transform.gltf"));
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] =
        nlohmann::json::parse(R"({"offset": [1], "rotation": "a quarter", "scale": [2, 5], "texCoord": 1})");
    std::ofstream(dir / "scene.gltf") << doc.dump();
    fs::copy_file(sceneDir() / "texture_transform.bin", dir / "texture_transform.bin");
    fs::copy_file(sceneDir() / "checker.png", dir / "checker.png");
    Log log;
    std::vector<std::string> warnings;
    log.setSink([&](const LogMessage& m) {
        if (m.level == LogLevel::Warning) warnings.push_back(m.text);
    });
    const Scene scene = loadGltf(dir / "scene.gltf", log);
    const TextureTransform& t = scene.materials.at(0).textureTransforms[kBaseColor];
    EXPECT_EQ(t.offset, glm::dvec2(0.0));
    EXPECT_EQ(t.rotation, 0.0);
    EXPECT_EQ(t.scale, glm::dvec2(2.0, 5.0));
    EXPECT_EQ(t.texCoord, 1);
    std::string all;
    for (const std::string& w : warnings) all += w + "\n";
    EXPECT_NE(all.find("baseColorTexture: its KHR_texture_transform offset is not two numbers; ignored"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("rotation is not a number"), std::string::npos) << all;
    EXPECT_NE(all.find("has no TEXCOORD_1, which its material's baseColorTexture reads; drawn with TEXCOORD_0"),
              std::string::npos)
        << all;
}

}  // namespace
}  // namespace lit
