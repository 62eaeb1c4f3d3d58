// The glTF extension check (renderer/scene/GltfExtensions.cpp): an extension Lit does not read is
// named in one line, an error when the file requires it and a warning when it only uses it, and
// before tinygltf can fail on the data the extension would have explained.

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "Log.h"
#include "TempDir.h"
#include "scene/GltfLoader.h"

namespace lit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

struct TempDir : lit::testing::TempDir {
    TempDir() : lit::testing::TempDir("lit_extensions") {}
};

// Keeps the warnings for the test to read, writes nothing.
struct RecordingLog : Log {
    RecordingLog() {
        setSink([](const LogMessage&) {});
    }
    std::vector<std::string> warnings() const {
        std::vector<std::string> out;
        for (const LogMessage& m : recent())
            if (m.level == LogLevel::Warning) out.push_back(m.text);
        return out;
    }
    // The warnings that contain `phrase`.
    std::size_t warningsWith(const std::string& phrase) const {
        std::size_t n = 0;
        for (const std::string& w : warnings()) n += w.find(phrase) != std::string::npos;
        return n;
    }
};

void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    ASSERT_TRUE(out.good()) << path;
}

// One triangle with UVs: positions (36 bytes), UVs (24 bytes), uint16 indices (6 bytes).
json triangleDoc(const fs::path& dir) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float uvs[6] = {0, 0, 1, 0, 0, 1};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::vector<std::uint8_t> bin(68, 0);
    std::memcpy(bin.data(), positions, 36);
    std::memcpy(bin.data() + 36, uvs, 24);
    std::memcpy(bin.data() + 60, indices, 6);
    writeBytes(dir / "tri.bin", bin.data(), bin.size());
    return {
        {"asset", {{"version", "2.0"}}},
        {"buffers", json::array({{{"uri", "tri.bin"}, {"byteLength", 68}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                     {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}},
                                     {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 6}}})},
        {"accessors", json::array({{{"bufferView", 0},
                                    {"componentType", 5126},
                                    {"count", 3},
                                    {"type", "VEC3"},
                                    {"min", {0, 0, 0}},
                                    {"max", {1, 1, 0}}},
                                   {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
                                   {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                                                              {"indices", 2}}})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"scene", 0}};
}

fs::path writeScene(const fs::path& dir, const std::string& name, const json& doc) {
    const std::string text = doc.dump();
    writeBytes(dir / name, text.data(), text.size());
    return dir / name;
}

// The message of the SceneLoadError a load throws (a failure when it throws none or another).
std::string loadError(const fs::path& path) {
    RecordingLog log;
    try {
        loadGltf(path, log);
    } catch (const SceneLoadError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected SceneLoadError for " << path;
    return {};
}

TEST(GltfExtensions, ARequiredExtensionLitLacksIsNamedInOneLine) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_anisotropy"};
    doc["extensionsRequired"] = {"KHR_materials_anisotropy"};
    const std::string message = loadError(writeScene(dir.path(), "scene.gltf", doc));
    EXPECT_EQ(message, (dir / "scene.gltf").string() + ": requires KHR_materials_anisotropy, which Lit does not support");
}

TEST(GltfExtensions, EveryMissingRequiredExtensionIsNamed) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    doc["extensionsUsed"] = {"KHR_materials_anisotropy", "EXT_foo", "KHR_mesh_quantization", "EXT_bar"};
    doc["extensionsRequired"] = doc["extensionsUsed"];
    EXPECT_EQ(loadError(writeScene(dir.path(), "scene.gltf", doc)),
              (dir / "scene.gltf").string() +
                  ": requires KHR_materials_anisotropy, EXT_foo and EXT_bar, which Lit does not support");
}

// The data of an extension Lit lacks may not be plain glTF: tinygltf must not be the one to
// report it ("accessor[2] invalid bufferView" for indices that live in the extension's data).
TEST(GltfExtensions, TheExtensionIsNamedBeforeTinygltfReadsItsData) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    doc["accessors"][2].erase("bufferView");
    doc["extensionsUsed"] = {"EXT_lit_packed_indices"};
    doc["extensionsRequired"] = {"EXT_lit_packed_indices"};
    EXPECT_EQ(loadError(writeScene(dir.path(), "scene.gltf", doc)),
              (dir / "scene.gltf").string() + ": requires EXT_lit_packed_indices, which Lit does not support");
}

TEST(GltfExtensions, AnExtensionOnlyUsedIsAWarningNamingIt) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    doc["extensionsUsed"] = {"KHR_materials_anisotropy", "KHR_mesh_quantization"};
    RecordingLog log;
    const Scene scene = loadGltf(writeScene(dir.path(), "scene.gltf", doc), log);
    EXPECT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(log.warningsWith("KHR_materials_anisotropy"), 1u);
    EXPECT_EQ(log.warningsWith("scene.gltf: uses KHR_materials_anisotropy, which Lit does not support"), 1u);
    EXPECT_EQ(log.warningsWith("KHR_mesh_quantization"), 0u) << "a supported extension is not reported";
}

TEST(GltfExtensions, RequiredKtx2TexturesAreRefusedByName) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    doc["extensionsUsed"] = {"KHR_texture_basisu"};
    doc["extensionsRequired"] = {"KHR_texture_basisu"};
    doc["images"] = json::array({{{"uri", "wood.ktx2"}, {"mimeType", "image/ktx2"}}});
    doc["textures"] = json::array({{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}});
    const std::string message = loadError(writeScene(dir.path(), "scene.gltf", doc));
    EXPECT_NE(message.find("scene.gltf: requires KHR_texture_basisu, which Lit does not support"), std::string::npos)
        << message;
    EXPECT_NE(message.find("KTX2"), std::string::npos) << message;
}

// An optional KTX2 image: the texture is drawn with its other source (a PNG here), with one
// warning that says so; a texture with only the KTX2 image is counted in that warning.
TEST(GltfExtensions, OptionalKtx2TexturesFallBackToTheirOtherSource) {
    TempDir dir;
    json doc = triangleDoc(dir.path());
    const std::vector<std::uint8_t> red = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    ASSERT_NE(stbi_write_png((dir / "wood.png").c_str(), 2, 2, 4, red.data(), 8), 0);
    const char ktx2[] = "\xABKTX 20\xBB\r\n\x1A\n not a real KTX2 body";
    writeBytes(dir / "wood.ktx2", ktx2, sizeof ktx2);
    doc["extensionsUsed"] = {"KHR_texture_basisu"};
    doc["images"] = json::array({{{"uri", "wood.png"}}, {{"uri", "wood.ktx2"}, {"mimeType", "image/ktx2"}}});
    doc["textures"] = json::array({{{"source", 0}, {"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}},
                                   {{"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}}});
    doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    RecordingLog log;
    const Scene scene = loadGltf(writeScene(dir.path(), "scene.gltf", doc), log);
    ASSERT_EQ(scene.textures.size(), 2u);
    ASSERT_GE(scene.textures[0].image, 0);
    const Image& image = scene.images.at(static_cast<std::size_t>(scene.textures[0].image));
    ASSERT_EQ(image.rgba.size(), 16u);
    EXPECT_EQ(image.rgba[0], 255);  // the PNG's red, decoded
    EXPECT_EQ(image.rgba[1], 0);
    // No other source: drawn without its image (no image, or the loader's neutral 1×1 white).
    if (scene.textures[1].image >= 0) {
        const Image& neutral = scene.images.at(static_cast<std::size_t>(scene.textures[1].image));
        EXPECT_EQ(neutral.width * neutral.height, 1);
        EXPECT_EQ(neutral.rgba, (std::vector<std::uint8_t>{255, 255, 255, 255}));
    }
    EXPECT_EQ(log.warningsWith("scene.gltf: uses KHR_texture_basisu (KTX2 textures), which Lit does not decode; "
                               "textures use their other source (1 texture has none and is drawn without it)"),
              1u);
}

}  // namespace
}  // namespace lit
