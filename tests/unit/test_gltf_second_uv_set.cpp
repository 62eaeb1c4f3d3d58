// TEXCOORD_1 (label cpu): read from the Blender scene made by tools/blender/make_second_uv_set.py
// (a texture that reads a plane's second UV map through a UV Map node), which set each texture
// reference is drawn with, what is reported when a file names a set Lit does not draw or a mesh
// lacks, and what a save writes back (validator clean when installed).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "GltfValidator.h"
#include "Log.h"
#include "QuietLog.h"
#include "TempDir.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/Scene.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using lit::testing::QuietLog;
using lit::testing::readText;
using lit::testing::TempDir;

constexpr std::size_t kBaseColor = 0, kNormal = 2, kEmissive = 3;

fs::path sceneDir() { return fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender" / "second_uv_set"; }

const Material& materialNamed(const Scene& scene, const std::string& name) {
    for (const Material& m : scene.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return scene.materials.at(0);
}

// The first primitive of the mesh of the node named `nodeName`.
const Primitive& primitiveOf(const Scene& scene, const std::string& nodeName) {
    for (const Node& node : scene.nodes)
        if (node.name == nodeName && node.mesh >= 0)
            return scene.meshes.at(static_cast<std::size_t>(node.mesh)).primitives.at(0);
    ADD_FAILURE() << "no node " << nodeName << " with a mesh";
    return scene.meshes.at(0).primitives.at(0);
}

// Loads `doc` (the Blender scene's JSON, edited) from a temporary copy, collecting the warnings.
Scene loadEdited(const nlohmann::json& doc, const TempDir& dir, std::string& warnings) {
    std::ofstream(dir / "scene.gltf") << doc.dump();
    for (const char* file : {"second_uv_set.bin", "checker.png"})
        fs::copy_file(sceneDir() / file, dir / file, fs::copy_options::overwrite_existing);
    Log log;
    log.setSink([&](const LogMessage& m) {
        if (m.level == LogLevel::Warning) warnings += m.text + "\n";
    });
    return loadGltf(dir / "scene.gltf", log);
}

// Blender wrote TEXCOORD_1 and texCoord 1 for the left plane's checker: read without a warning,
// drawn with the second set, whose UVs are the ones the twin scene holds as its only set.
TEST(SecondUvSet, ReadFromBlendersUvMapNode) {
    QuietLog log;
    const Scene scene = loadGltf(sceneDir() / "second_uv_set.gltf", log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u) << "TEXCOORD_1 is drawn, not warned about";
    const Material& left = materialNamed(scene, "checker_left");
    const Material& right = materialNamed(scene, "checker_right");
    for (const std::size_t slot : {kBaseColor, kEmissive}) {
        EXPECT_EQ(left.textureTexCoord[slot], 1);
        EXPECT_EQ(drawnTexCoord(left, slot), 1);
        EXPECT_EQ(drawnTexCoord(right, slot), 0);
    }
    const Scene baked = loadGltf(sceneDir() / "second_uv_set_baked.gltf", log);
    int compared = 0;
    for (const char* name : {"left", "right"}) {
        const Primitive& a = primitiveOf(scene, name);
        const Primitive& b = primitiveOf(baked, name);
        ASSERT_EQ(a.vertices.size(), b.vertices.size());
        const bool leftPlane = std::string(name) == "left";
        for (std::size_t v = 0; v < a.vertices.size(); ++v) {
            ASSERT_EQ(a.vertices[v].position, b.vertices[v].position);
            // The texture's set in the first scene holds the twin's only set.
            const glm::vec2 read = leftPlane ? a.vertices[v].uv1 : a.vertices[v].uv;
            EXPECT_NEAR(read.x, b.vertices[v].uv.x, 1e-6f) << name << " vertex " << v;
            EXPECT_NEAR(read.y, b.vertices[v].uv.y, 1e-6f) << name << " vertex " << v;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 8);  // two quads
}

// A set the mesh lacks: drawn with TEXCOORD_0 (uv1 holds a copy), said once per primitive. A set
// beyond TEXCOORD_1, directly or through KHR_texture_transform: drawn with TEXCOORD_0, named.
TEST(SecondUvSet, SetsLitCannotDrawAreReported) {
    TempDir dir;
    nlohmann::json doc = nlohmann::json::parse(readText(sceneDir() / "second_uv_set.gltf"));
    for (nlohmann::json& mesh : doc["meshes"]) mesh["primitives"][0]["attributes"].erase("TEXCOORD_1");
    std::string warnings;
    const Scene lacking = loadEdited(doc, dir, warnings);
    EXPECT_NE(warnings.find("has no TEXCOORD_1, which its material's baseColorTexture reads; drawn with TEXCOORD_0"),
              std::string::npos)
        << warnings;
    for (const Mesh& mesh : lacking.meshes)
        for (const Vertex& v : mesh.primitives.at(0).vertices) EXPECT_EQ(v.uv1, v.uv);

    doc = nlohmann::json::parse(readText(sceneDir() / "second_uv_set.gltf"));
    nlohmann::json& left = doc["materials"][0]["name"] == "checker_left" ? doc["materials"][0] : doc["materials"][1];
    left["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 2;
    left["emissiveTexture"]["extensions"]["KHR_texture_transform"] = nlohmann::json::parse(R"({"texCoord": 3})");
    doc["extensionsUsed"] = nlohmann::json::array({"KHR_texture_transform"});
    warnings.clear();
    const Scene beyond = loadEdited(doc, dir, warnings);
    EXPECT_NE(warnings.find("baseColorTexture uses TEXCOORD_2; Lit draws TEXCOORD_0 and TEXCOORD_1 and draws it with "
                            "TEXCOORD_0"),
              std::string::npos)
        << warnings;
    EXPECT_NE(warnings.find("emissiveTexture uses TEXCOORD_3 (KHR_texture_transform texCoord); Lit draws TEXCOORD_0 "
                            "and TEXCOORD_1"),
              std::string::npos)
        << warnings;
    const Material& m = materialNamed(beyond, "checker_left");
    EXPECT_EQ(drawnTexCoord(m, kBaseColor), 0);
    EXPECT_EQ(drawnTexCoord(m, kEmissive), 0);
    EXPECT_EQ(m.textureTexCoord[kBaseColor], 2) << "the file's number is kept for a save";
}

// A KHR_texture_transform texCoord overrides the reference's own, for drawing (and for the
// tangents the loader computes for a normal texture).
TEST(SecondUvSet, TransformOverrideChoosesTheSet) {
    Material m;
    m.textureTexCoord[kNormal] = 0;
    m.textureTransforms[kNormal].present = true;
    m.textureTransforms[kNormal].texCoord = 1;
    EXPECT_EQ(drawnTexCoord(m, kNormal), 1);
    m.textureTexCoord[kBaseColor] = 1;
    m.textureTransforms[kBaseColor].present = true;
    m.textureTransforms[kBaseColor].texCoord = 0;
    EXPECT_EQ(drawnTexCoord(m, kBaseColor), 0);
}

// A save writes TEXCOORD_1 and the texCoord numbers back; the saved file draws the same.
TEST(SecondUvSet, KeptOnSave) {
    TempDir dir;
    QuietLog log;
    const Scene scene = loadGltf(sceneDir() / "second_uv_set.gltf", log);
    saveGltf(scene, dir / "saved.gltf");
    const Scene again = loadGltf(dir / "saved.gltf", log);
    EXPECT_EQ(log.countAtLeast(LogLevel::Warning), 0u);
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        EXPECT_EQ(again.materials[m].textureTexCoord, scene.materials[m].textureTexCoord) << m;
    ASSERT_EQ(again.meshes.size(), scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const auto& a = scene.meshes[m].primitives.at(0).vertices;
        const auto& b = again.meshes[m].primitives.at(0).vertices;
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t v = 0; v < a.size(); ++v) EXPECT_EQ(a[v].uv1, b[v].uv1) << m << " " << v;
    }
    const nlohmann::json saved = nlohmann::json::parse(readText(dir / "saved.gltf"));
    for (const nlohmann::json& mesh : saved["meshes"])
        EXPECT_TRUE(mesh["primitives"][0]["attributes"].contains("TEXCOORD_1")) << mesh.dump();

    std::string whyNot;
    const fs::path validatorDir = lit::testing::findGltfValidator(whyNot);
    if (validatorDir.empty()) GTEST_SKIP() << whyNot;
    std::string report;
    const int status = lit::testing::runGltfValidator(validatorDir, {dir / "saved.gltf"}, report, dir / "report.txt");
    std::printf("%s", report.c_str());
    EXPECT_EQ(status, 0) << report;
}

}  // namespace
}  // namespace lit
