// KHR_materials_ior, _specular, _sheen, _clearcoat, _transmission and _volume (label cpu): their factors read into the Material,
// their textures named and kept, out-of-range values clamped with a warning, and a save that
// writes edited factors into the file's objects.
#include "Log.h"
#include "TempDir.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace lit {
namespace {

namespace fs = std::filesystem;
using lit::testing::readText;
using lit::testing::TempDir;

// A base file with materials, a texture and geometry: the texture-transform scene.
fs::path baseDir() { return fs::path(LIT_SOURCE_DIR) / "tests" / "data" / "blender" / "texture_transform"; }

struct Loaded {
    Scene scene;
    std::string warnings;
};

// Writes `doc` next to the base file's buffer and image, loads it and collects the warnings.
Loaded loadDoc(const TempDir& dir, const nlohmann::json& doc) {
    std::ofstream(dir / "scene.gltf") << doc.dump();
    for (const char* file : {"texture_transform.bin", "checker.png"})
        if (!fs::exists(dir / file)) fs::copy_file(baseDir() / file, dir / file);
    Log log;
    Loaded out;
    log.setSink([&](const LogMessage& m) {
        if (m.level == LogLevel::Warning) out.warnings += m.text + "\n";
    });
    out.scene = loadGltf(dir / "scene.gltf", log);
    return out;
}

nlohmann::json baseDoc() { return nlohmann::json::parse(readText(baseDir() / "texture_transform.gltf")); }

void addExtension(nlohmann::json& doc, const std::string& name, const nlohmann::json& object, int material = 0) {
    doc["materials"][material]["extensions"][name] = object;
    if (!doc.contains("extensionsUsed")) doc["extensionsUsed"] = nlohmann::json::array();
    doc["extensionsUsed"].push_back(name);
}

TEST(MaterialLayers, FactorsAreRead) {
    TempDir dir;
    nlohmann::json doc = baseDoc();
    addExtension(doc, "KHR_materials_ior", {{"ior", 1.45}});
    addExtension(doc, "KHR_materials_specular",
                 {{"specularFactor", 0.5}, {"specularColorFactor", {2.0, 1.0, 0.5}}});
    addExtension(doc, "KHR_materials_clearcoat", {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.2}});
    addExtension(doc, "KHR_materials_sheen", {{"sheenColorFactor", {0.9, 0.5, 0.1}}, {"sheenRoughnessFactor", 0.4}});
    const Loaded loaded = loadDoc(dir, doc);
    EXPECT_EQ(loaded.warnings.find("which Lit does not support"), std::string::npos) << loaded.warnings;
    const Material& m = loaded.scene.materials.at(0);
    EXPECT_FLOAT_EQ(m.ior, 1.45f);
    EXPECT_FLOAT_EQ(m.specularFactor, 0.5f);
    EXPECT_EQ(m.specularColorFactor, glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_FLOAT_EQ(m.clearcoatFactor, 0.75f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.2f);
    EXPECT_EQ(m.sheenColorFactor, glm::vec3(0.9f, 0.5f, 0.1f));
    EXPECT_FLOAT_EQ(m.sheenRoughness, 0.4f);
    const Material& other = loaded.scene.materials.at(1);
    EXPECT_EQ(other.ior, 1.5f) << "defaults where the file has no extension";
    EXPECT_EQ(other.specularFactor, 1.0f);
    EXPECT_EQ(other.clearcoatFactor, 0.0f);
    EXPECT_EQ(other.sheenColorFactor, glm::vec3(0.0f));
}

TEST(MaterialLayers, TexturesAreReadAndOutOfRangeFactorsClamped) {
    TempDir dir;
    nlohmann::json doc = baseDoc();
    addExtension(doc, "KHR_materials_clearcoat",
                 {{"clearcoatFactor", 2.0},
                  {"clearcoatRoughnessFactor", -1.0},
                  {"clearcoatTexture", {{"index", 0}}},
                  {"clearcoatRoughnessTexture", {{"index", 0}, {"texCoord", 1}}},
                  {"clearcoatNormalTexture", {{"index", 0}, {"scale", 0.5}}}});
    addExtension(doc, "KHR_materials_volume", {{"thicknessFactor", 0.0}, {"thicknessTexture", {{"index", 0}}}});
    addExtension(doc, "KHR_materials_ior", {{"ior", 0.5}});
    addExtension(doc, "KHR_materials_specular",
                 {{"specularColorFactor", {1.0, "red", 1.0}},
                  {"specularTexture", {{"index", 0}}},
                  {"specularColorTexture",
                   {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2.0, 2.0}}}}}}}}});
    addExtension(doc, "KHR_materials_sheen",
                 {{"sheenColorFactor", {2.0, 0.5, 0.5}},
                  {"sheenColorTexture", {{"index", 0}}},
                  {"sheenRoughnessTexture", {{"index", 0}}}});
    const Loaded loaded = loadDoc(dir, doc);
    const Material& m = loaded.scene.materials.at(0);
    EXPECT_EQ(m.clearcoatFactor, 1.0f);
    EXPECT_EQ(m.clearcoatRoughness, 0.0f);
    EXPECT_EQ(m.ior, 1.0f);
    EXPECT_EQ(m.specularColorFactor, glm::vec3(1.0f));
    EXPECT_EQ(m.sheenColorFactor, glm::vec3(1.0f, 0.5f, 0.5f));
    for (const ExtensionTexture* t :
         {&m.clearcoatTexture, &m.clearcoatRoughnessTexture, &m.clearcoatNormalTexture, &m.specularTexture,
          &m.specularColorTexture, &m.sheenColorTexture, &m.sheenRoughnessTexture, &m.thicknessTexture})
        EXPECT_EQ(t->texture, 0);
    EXPECT_EQ(m.clearcoatNormalTexture.scale, 0.5f);
    EXPECT_EQ(m.clearcoatTexture.scale, 1.0f);
    EXPECT_EQ(m.clearcoatRoughnessTexture.texCoord, 1);
    EXPECT_TRUE(m.specularColorTexture.transform.present);
    EXPECT_EQ(m.specularColorTexture.transform.scale, glm::dvec2(2.0, 2.0));
    for (const char* expected :
         {"KHR_materials_clearcoat clearcoatFactor 2.000000 is outside its range; Lit uses 1.000000",
          "KHR_materials_ior ior 0.500000 is below 1",
          "KHR_materials_specular specularColorFactor is not three finite numbers",
          "KHR_materials_sheen sheenColorFactor has a value outside its range; Lit clamps it"})
        EXPECT_NE(loaded.warnings.find(expected), std::string::npos) << expected << "\n" << loaded.warnings;
    for (const char* drawn : {"clearcoatTexture is not drawn", "clearcoatRoughnessTexture is not drawn",
                              "clearcoatNormalTexture is not drawn", "specularTexture is not drawn",
                              "sheenRoughnessTexture is not drawn", "thicknessTexture is not drawn"})
        EXPECT_EQ(loaded.warnings.find(drawn), std::string::npos) << drawn << "\n" << loaded.warnings;
}

// Unchanged factors keep the file's numbers and fields (textures too); edited ones are written;
// a material given a coat gets the extension, one left at the defaults gets none.
TEST(MaterialLayers, SaveWritesTheFactorsIntoTheFilesObjects) {
    TempDir dir;
    nlohmann::json doc = baseDoc();
    addExtension(doc, "KHR_materials_clearcoat",
                 {{"clearcoatFactor", 0.3}, {"clearcoatTexture", {{"index", 0}}}, {"clearcoatRoughnessFactor", 0.0}});
    addExtension(doc, "KHR_materials_ior", {{"ior", 1.33}});
    Loaded loaded = loadDoc(dir, doc);
    ASSERT_GE(loaded.scene.materials.size(), 2u);
    saveGltf(loaded.scene, dir / "same.gltf");
    const nlohmann::json same = nlohmann::json::parse(readText(dir / "same.gltf"));
    const nlohmann::json& ext = same["materials"][0]["extensions"];
    EXPECT_EQ(ext["KHR_materials_ior"]["ior"].get<double>(), 1.33) << "the file's number, not float(1.33)";
    EXPECT_EQ(ext["KHR_materials_clearcoat"]["clearcoatFactor"].get<double>(), 0.3);
    EXPECT_TRUE(ext["KHR_materials_clearcoat"].contains("clearcoatRoughnessFactor")) << "the file wrote its default";
    EXPECT_EQ(ext["KHR_materials_clearcoat"]["clearcoatTexture"]["index"], 0) << "the texture is kept";
    EXPECT_FALSE(same["materials"][1].contains("extensions")) << same["materials"][1].dump();

    loaded.scene.materials[0].clearcoatFactor = 0.9f;
    loaded.scene.materials[0].ior = 1.5f;
    loaded.scene.materials[1].clearcoatFactor = 0.5f;
    loaded.scene.materials[1].specularColorFactor = glm::vec3(1.0f, 0.5f, 0.25f);
    loaded.scene.materials[1].sheenColorFactor = glm::vec3(0.5f);
    saveGltf(loaded.scene, dir / "edited.gltf");
    const nlohmann::json edited = nlohmann::json::parse(readText(dir / "edited.gltf"));
    const nlohmann::json& first = edited["materials"][0]["extensions"];
    EXPECT_FLOAT_EQ(first["KHR_materials_clearcoat"]["clearcoatFactor"].get<float>(), 0.9f);
    EXPECT_EQ(first["KHR_materials_clearcoat"]["clearcoatTexture"]["index"], 0);
    EXPECT_EQ(first["KHR_materials_ior"]["ior"].get<double>(), 1.5) << "the file had the extension: it stays";
    const nlohmann::json& second = edited["materials"][1]["extensions"];
    EXPECT_FLOAT_EQ(second["KHR_materials_clearcoat"]["clearcoatFactor"].get<float>(), 0.5f);
    EXPECT_FALSE(second["KHR_materials_clearcoat"].contains("clearcoatRoughnessFactor")) << "default, not written";
    EXPECT_FALSE(second["KHR_materials_specular"].contains("specularFactor"));
    EXPECT_FLOAT_EQ(second["KHR_materials_specular"]["specularColorFactor"][1].get<float>(), 0.5f);
    EXPECT_FALSE(second.contains("KHR_materials_ior"));
    EXPECT_FLOAT_EQ(second["KHR_materials_sheen"]["sheenColorFactor"][2].get<float>(), 0.5f);
    EXPECT_FALSE(second["KHR_materials_sheen"].contains("sheenRoughnessFactor")) << "default, not written";
    std::vector<std::string> used = edited["extensionsUsed"].get<std::vector<std::string>>();
    for (const char* name : {"KHR_materials_clearcoat", "KHR_materials_ior", "KHR_materials_specular", "KHR_materials_sheen"})
        EXPECT_EQ(std::count(used.begin(), used.end(), name), 1) << name;

    // What was saved loads back to the same factors.
    Log log;
    const Scene back = loadGltf(dir / "edited.gltf", log);
    EXPECT_EQ(back.materials[1].clearcoatFactor, 0.5f);
    EXPECT_EQ(back.materials[1].specularColorFactor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(back.materials[0].clearcoatFactor, 0.9f);
}

// Transmission and volume: read (the transmission texture with its UV set and transform; the
// volume's numbers, drawn without a warning), an attenuation distance that is no distance refused,
// edits saved.
TEST(MaterialLayers, TransmissionAndVolumeAreReadAndSaved) {
    TempDir dir;
    nlohmann::json doc = baseDoc();
    addExtension(
        doc, "KHR_materials_transmission",
        {{"transmissionFactor", 0.8},
         {"transmissionTexture",
          {{"index", 0}, {"texCoord", 1}, {"extensions", {{"KHR_texture_transform", {{"scale", {2.0, 3.0}}}}}}}}});
    doc["extensionsUsed"].push_back("KHR_texture_transform");
    addExtension(doc, "KHR_materials_volume",
                 {{"thicknessFactor", 0.02}, {"attenuationDistance", 1.5}, {"attenuationColor", {0.9, 0.8, 0.7}}});
    addExtension(doc, "KHR_materials_volume", {{"attenuationDistance", -1.0}}, 1);
    Loaded loaded = loadDoc(dir, doc);
    EXPECT_EQ(loaded.warnings.find("which Lit does not support"), std::string::npos) << loaded.warnings;
    const Material& m = loaded.scene.materials.at(0);
    EXPECT_FLOAT_EQ(m.transmission, 0.8f);
    EXPECT_EQ(m.transmissionTexture.texture, 0);
    EXPECT_EQ(m.transmissionTexture.texCoord, 1);
    EXPECT_TRUE(m.transmissionTexture.transform.present);
    EXPECT_EQ(m.transmissionTexture.transform.scale, glm::dvec2(2.0, 3.0));
    EXPECT_FLOAT_EQ(m.thickness, 0.02f);
    EXPECT_FLOAT_EQ(m.attenuationDistance, 1.5f);
    EXPECT_EQ(m.attenuationColor, glm::vec3(0.9f, 0.8f, 0.7f));
    EXPECT_EQ(loaded.scene.materials.at(1).attenuationDistance, 0.0f) << "infinite";
    EXPECT_EQ(loaded.scene.materials.at(1).transmission, 0.0f);
    EXPECT_EQ(loaded.warnings.find("transmissionTexture is not drawn"), std::string::npos) << loaded.warnings;
    EXPECT_EQ(loaded.warnings.find("KHR_materials_volume:"), std::string::npos) << loaded.warnings;
    for (const char* expected : {"has no TEXCOORD_1, which its material's transmissionTexture reads",
                                 "KHR_materials_volume attenuationDistance -1.000000 is not a positive distance"})
        EXPECT_NE(loaded.warnings.find(expected), std::string::npos) << expected << "\n" << loaded.warnings;

    loaded.scene.materials[0].transmission = 1.0f;
    loaded.scene.materials[1].transmission = 0.5f;
    saveGltf(loaded.scene, dir / "edited.gltf");
    const nlohmann::json edited = nlohmann::json::parse(readText(dir / "edited.gltf"));
    const nlohmann::json& first = edited["materials"][0]["extensions"];
    EXPECT_EQ(first["KHR_materials_transmission"]["transmissionFactor"].get<double>(), 1.0);
    EXPECT_EQ(first["KHR_materials_transmission"]["transmissionTexture"],
              doc["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionTexture"])
        << "the texture reference is kept as the file had it";
    EXPECT_EQ(first["KHR_materials_volume"]["thicknessFactor"].get<double>(), 0.02) << "the file's number";
    EXPECT_EQ(first["KHR_materials_volume"]["attenuationDistance"].get<double>(), 1.5);
    EXPECT_EQ(edited["materials"][1]["extensions"]["KHR_materials_transmission"]["transmissionFactor"].get<double>(), 0.5);
    Log log;
    const Scene back = loadGltf(dir / "edited.gltf", log);
    EXPECT_EQ(back.materials[0].transmission, 1.0f);
    EXPECT_EQ(back.materials[1].transmission, 0.5f);
    EXPECT_FLOAT_EQ(back.materials[0].attenuationColor.z, 0.7f);
    EXPECT_EQ(back.materials[0].transmissionTexture, m.transmissionTexture);
}

// A transmission texture reference that is not one is named and not drawn; one out of range is
// refused like any texture reference.
TEST(MaterialLayers, MalformedTransmissionTextureIsReported) {
    TempDir dir;
    nlohmann::json doc = baseDoc();
    addExtension(doc, "KHR_materials_transmission", {{"transmissionFactor", 1.0}, {"transmissionTexture", "glass"}});
    Loaded loaded = loadDoc(dir, doc);
    EXPECT_NE(loaded.warnings.find("transmissionTexture is not a textureInfo with an integer index; not drawn"),
              std::string::npos)
        << loaded.warnings;
    EXPECT_EQ(loaded.scene.materials.at(0).transmissionTexture.texture, -1);

    doc = baseDoc();
    addExtension(doc, "KHR_materials_transmission",
                 {{"transmissionFactor", 1.0}, {"transmissionTexture", {{"index", 7}}}});
    std::ofstream(dir / "scene.gltf") << doc.dump();
    Log log;
    log.setSink(nullptr);
    try {
        loadGltf(dir / "scene.gltf", log);
        ADD_FAILURE() << "an out-of-range texture index must be refused";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("transmissionTexture refers to texture 7, which is out of range"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lit
